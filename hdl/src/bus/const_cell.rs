// SPDX-License-Identifier: MIT OR Apache-2.0
//! A constant register of a register file ([`crate::bus::wb_front`]): the register map's
//! reset value, read-only (identification, version, generation parameters). Model: the
//! constant registers of [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `adr` from the file; `rdata` (32) the value when `adr` is the register's offset,
//! else 0. Combinational.

use golden::bus::regmap::{Register, ADDR_BITS};
use rust_hdl::prelude::*;

/// A constant register.
#[derive(LogicBlock)]
pub struct ConstCell {
    /// Addressed word, from the file.
    pub adr: Signal<In, Bits<ADDR_BITS>>,
    /// The value at this offset, else 0.
    pub rdata: Signal<Out, Bits<32>>,
    offset: Constant<Bits<ADDR_BITS>>,
    value: Constant<Bits<32>>,
    z32: Constant<Bits<32>>,
}

impl ConstCell {
    /// The cell of `reg`, whose reset value is its constant.
    pub fn new(reg: &Register) -> Self {
        let value = reg
            .reset
            .unwrap_or_else(|| panic!("{} has no constant value", reg.name));
        Self {
            adr: Default::default(),
            rdata: Default::default(),
            offset: Constant::new(u64::from(reg.offset).into()),
            value: Constant::new(u64::from(value).into()),
            z32: Constant::new(0.into()),
        }
    }
}

impl Logic for ConstCell {
    #[hdl_gen]
    fn update(&mut self) {
        self.rdata.next = self.z32.val();
        if self.adr.val() == self.offset.val() {
            self.rdata.next = self.value.val();
        }
    }
}
