// SPDX-License-Identifier: MIT OR Apache-2.0
//! A write-1 pulse of a register file ([`crate::bus::wb_front`]): `pulse` is high for the
//! one cycle after a write to the register's offset with a 1 in any bit of `mask` (a W1P
//! field such as `ECC_CTRL.IDENT_ARM`, or the W1C fault bits of `STATUS`, whose clear the
//! file does not hold but passes on). Model: the pulses of
//! [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `clock`, `reset` (synchronous, to 0); `adr`, `wr`, `ones` from the file; `pulse`,
//! a register.

use golden::bus::regmap::{Register, ADDR_BITS};
use rust_hdl::prelude::*;

/// A one-cycle pulse on a write of 1 to some bits of a register.
#[derive(LogicBlock)]
pub struct PulseCell {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Addressed word, from the file.
    pub adr: Signal<In, Bits<ADDR_BITS>>,
    /// A write request, from the file.
    pub wr: Signal<In, Bit>,
    /// Bits written 1, from the file.
    pub ones: Signal<In, Bits<32>>,
    /// One cycle after the write.
    pub pulse: Signal<Out, Bit>,
    fired: DFF<Bit>,
    offset: Constant<Bits<ADDR_BITS>>,
    mask: Constant<Bits<32>>,
    z32: Constant<Bits<32>>,
}

impl PulseCell {
    /// The pulse of a write of 1 to the bits `mask` of `reg` (a mask of its fields).
    pub fn new(reg: &Register, mask: u32) -> Self {
        assert!(
            mask != 0 && mask & !reg.defined_mask() == 0,
            "{}: mask {mask:#x} is not a set of its fields",
            reg.name
        );
        Self {
            clock: Default::default(),
            reset: Default::default(),
            adr: Default::default(),
            wr: Default::default(),
            ones: Default::default(),
            pulse: Default::default(),
            fired: Default::default(),
            offset: Constant::new(u64::from(reg.offset).into()),
            mask: Constant::new(u64::from(mask).into()),
            z32: Constant::new(0.into()),
        }
    }
}

impl Logic for PulseCell {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, fired);
        self.fired.d.next = self.wr.val()
            & (self.adr.val() == self.offset.val())
            & ((self.ones.val() & self.mask.val()) != self.z32.val());
        if self.reset.val() {
            self.fired.d.next = false;
        }
        self.pulse.next = self.fired.q.val();
    }
}
