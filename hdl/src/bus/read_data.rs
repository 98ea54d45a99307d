// SPDX-License-Identifier: MIT OR Apache-2.0
//! The read data of a register file ([`crate::bus::wb_front`]), in two register stages so
//! that the read multiplexer of some 30 words meets a 10 ns cycle on an iCE40:
//! - at the edge of a read request (edge k), each of the [`READ_GROUPS`] group registers
//!   takes the OR of its group's cells' words (`group0` … `group7`; the offsets are
//!   distinct, so the OR is the multiplexer, and an unmapped offset reads 0); 0 at any
//!   other edge;
//! - at edge k + 1, `wb_dat_o` takes the OR of the group registers (0 unless a read was
//!   executed at edge k).
//!
//! So `wb_dat_o` is the word as it stood before edge k, valid with `wb_ack_o` (high after
//! edge k + 1) and 0 otherwise. The window decides which cells form a group: the words of
//! one 16-byte block of its map (they share the offset's bits 7:4, so that the group's
//! address decode is one term and its OR of four gated words one LUT level). Model: the read data of
//! [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `clock`, `reset` (synchronous, to 0); `rd` from the front end; `group0` …
//! `group7` (32 each); `wb_dat_o` (32), a register.

use rust_hdl::prelude::*;

/// Number of read groups (the `group*` inputs).
pub const READ_GROUPS: usize = 8;

/// The two-stage registered read data of a Wishbone slave.
#[derive(LogicBlock)]
pub struct ReadData {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// A read request this cycle, from the front end.
    pub rd: Signal<In, Bit>,
    /// The OR of group 0's words.
    pub group0: Signal<In, Bits<32>>,
    /// The OR of group 1's words.
    pub group1: Signal<In, Bits<32>>,
    /// The OR of group 2's words.
    pub group2: Signal<In, Bits<32>>,
    /// The OR of group 3's words.
    pub group3: Signal<In, Bits<32>>,
    /// The OR of group 4's words.
    pub group4: Signal<In, Bits<32>>,
    /// The OR of group 5's words.
    pub group5: Signal<In, Bits<32>>,
    /// The OR of group 6's words.
    pub group6: Signal<In, Bits<32>>,
    /// The OR of group 7's words.
    pub group7: Signal<In, Bits<32>>,
    /// Wishbone: read data.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    part0: DFF<Bits<32>>,
    part1: DFF<Bits<32>>,
    part2: DFF<Bits<32>>,
    part3: DFF<Bits<32>>,
    part4: DFF<Bits<32>>,
    part5: DFF<Bits<32>>,
    part6: DFF<Bits<32>>,
    part7: DFF<Bits<32>>,
    dat: DFF<Bits<32>>,
    z32: Constant<Bits<32>>,
}

impl Default for ReadData {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            rd: Default::default(),
            group0: Default::default(),
            group1: Default::default(),
            group2: Default::default(),
            group3: Default::default(),
            group4: Default::default(),
            group5: Default::default(),
            group6: Default::default(),
            group7: Default::default(),
            wb_dat_o: Default::default(),
            part0: Default::default(),
            part1: Default::default(),
            part2: Default::default(),
            part3: Default::default(),
            part4: Default::default(),
            part5: Default::default(),
            part6: Default::default(),
            part7: Default::default(),
            dat: Default::default(),
            z32: Constant::new(0.into()),
        }
    }
}

impl Logic for ReadData {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, part0, part1, part2, part3, part4, part5, part6, part7, dat);
        self.part0.d.next = self.z32.val();
        self.part1.d.next = self.z32.val();
        self.part2.d.next = self.z32.val();
        self.part3.d.next = self.z32.val();
        self.part4.d.next = self.z32.val();
        self.part5.d.next = self.z32.val();
        self.part6.d.next = self.z32.val();
        self.part7.d.next = self.z32.val();
        if self.rd.val() & (!self.reset.val()) {
            self.part0.d.next = self.group0.val();
            self.part1.d.next = self.group1.val();
            self.part2.d.next = self.group2.val();
            self.part3.d.next = self.group3.val();
            self.part4.d.next = self.group4.val();
            self.part5.d.next = self.group5.val();
            self.part6.d.next = self.group6.val();
            self.part7.d.next = self.group7.val();
        }
        self.dat.d.next = self.part0.q.val()
            | self.part1.q.val()
            | self.part2.q.val()
            | self.part3.q.val()
            | self.part4.q.val()
            | self.part5.q.val()
            | self.part6.q.val()
            | self.part7.q.val();
        if self.reset.val() {
            self.dat.d.next = self.z32.val();
        }
        self.wb_dat_o.next = self.dat.q.val();
    }
}
