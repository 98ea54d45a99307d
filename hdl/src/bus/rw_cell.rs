// SPDX-License-Identifier: MIT OR Apache-2.0
//! A read-write register of a register file ([`crate::bus::wb_front`]): 32 bits stored with
//! the bits outside the register's RW fields held at 0 (synthesis removes those flops), so
//! read-back needs no widening. A write stores `(old & !lanes) | ones` masked to the RW
//! fields. Model: the RW registers of [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `clock`, `reset` (synchronous, to 0); `adr`, `wr`, `lanes`, `ones` from the
//! file; `rdata` (32) the stored word when `adr` is the register's offset, else 0; `q` (W)
//! the stored word's low W bits, a register (the RW fields must lie in them).

use golden::bus::regmap::{Access, Register, ADDR_BITS};
use rust_hdl::prelude::*;

/// A read-write register whose fields lie in bits W−1..0.
#[derive(LogicBlock)]
pub struct RwCell<const W: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Addressed word, from the file.
    pub adr: Signal<In, Bits<ADDR_BITS>>,
    /// A write request, from the file.
    pub wr: Signal<In, Bit>,
    /// Written byte lanes, from the file.
    pub lanes: Signal<In, Bits<32>>,
    /// Bits written 1, from the file.
    pub ones: Signal<In, Bits<32>>,
    /// The stored word at this offset, else 0.
    pub rdata: Signal<Out, Bits<32>>,
    /// The stored fields.
    pub q: Signal<Out, Bits<W>>,
    word: DFF<Bits<32>>,
    offset: Constant<Bits<ADDR_BITS>>,
    mask: Constant<Bits<32>>,
    z32: Constant<Bits<32>>,
}

impl<const W: usize> RwCell<W> {
    /// The cell of `reg`'s RW fields; panics if one lies at or above bit W.
    pub fn new(reg: &Register) -> Self {
        let mask = reg.mask_of(Access::Rw);
        assert!((1..=32).contains(&W), "W = {W}: 1..=32");
        assert!(
            mask != 0 && (W == 32 || mask >> W == 0),
            "{}: RW bits {mask:#x} outside bits {}..0",
            reg.name,
            W - 1
        );
        Self {
            clock: Default::default(),
            reset: Default::default(),
            adr: Default::default(),
            wr: Default::default(),
            lanes: Default::default(),
            ones: Default::default(),
            rdata: Default::default(),
            q: Default::default(),
            word: Default::default(),
            offset: Constant::new(u64::from(reg.offset).into()),
            mask: Constant::new(u64::from(mask).into()),
            z32: Constant::new(0.into()),
        }
    }
}

impl<const W: usize> Logic for RwCell<W> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, word);
        self.rdata.next = self.z32.val();
        if self.adr.val() == self.offset.val() {
            self.rdata.next = self.word.q.val();
            if self.wr.val() {
                self.word.d.next =
                    ((self.word.q.val() & (!self.lanes.val())) | self.ones.val()) & self.mask.val();
            }
        }
        if self.reset.val() {
            self.word.d.next = self.z32.val();
        }
        self.q.next = self.word.q.val().get_bits::<W>(0);
    }
}
