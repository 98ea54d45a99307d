// SPDX-License-Identifier: MIT OR Apache-2.0
//! The read-data register of a register file ([`crate::bus::wb_front`]): `wb_dat_o` ← the
//! OR of the cells' words (`cells`; the offsets are distinct, so the OR is the
//! multiplexer, and an unmapped offset reads 0) at the edge of a read request, 0 at any
//! other edge, so `wb_dat_o` is valid with `wb_ack_o` and 0 otherwise. Model: the read data
//! of [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `clock`, `reset` (synchronous, to 0); `rd` from the front end; `cells` (32);
//! `wb_dat_o` (32), a register.

use rust_hdl::prelude::*;

/// The registered read data of a Wishbone slave.
#[derive(LogicBlock)]
pub struct ReadData {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// A read request this cycle, from the front end.
    pub rd: Signal<In, Bit>,
    /// The OR of the cells' words.
    pub cells: Signal<In, Bits<32>>,
    /// Wishbone: read data.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    dat: DFF<Bits<32>>,
    z32: Constant<Bits<32>>,
}

impl Default for ReadData {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            rd: Default::default(),
            cells: Default::default(),
            wb_dat_o: Default::default(),
            dat: Default::default(),
            z32: Constant::new(0.into()),
        }
    }
}

impl Logic for ReadData {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, dat);
        self.dat.d.next = self.z32.val();
        if self.rd.val() & (!self.reset.val()) {
            self.dat.d.next = self.cells.val();
        }
        self.wb_dat_o.next = self.dat.q.val();
    }
}
