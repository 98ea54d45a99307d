// SPDX-License-Identifier: MIT OR Apache-2.0
//! A live read-only word of a register file ([`crate::bus::wb_front`]): a W-bit status
//! value of the block behind the file, widened to 32 bits (zero- or sign-extended) and
//! placed at bit `lsb`, read as it stands (no latching). Several cells at one offset with
//! disjoint bits make one word (`IDENT_P` = `P_MIN` | `P_MAX` << 16). Model: the live
//! registers of [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `adr` from the file; `value` (W); `rdata` (32) the placed word when `adr` is the
//! register's offset, else 0. Combinational.
//!
//! The value is widened by shifting its bits in at the top and shifting down by a constant
//! (a cast would be emitted as a mask of another width, which Verilator flags), one bit at
//! a time through a copy (a bit select would be invalid Verilog on a 1-bit port).

use golden::bus::regmap::{Register, ADDR_BITS};
use rust_hdl::prelude::*;

/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// A live W-bit word (1 ≤ W ≤ 32).
#[derive(LogicBlock)]
pub struct ReadCell<const W: usize> {
    /// Addressed word, from the file.
    pub adr: Signal<In, Bits<ADDR_BITS>>,
    /// The live value.
    pub value: Signal<In, Bits<W>>,
    /// The placed value at this offset, else 0.
    pub rdata: Signal<Out, Bits<32>>,
    t: Signal<Local, Bits<W>>,
    x: Signal<Local, Bits<32>>,
    offset: Constant<Bits<ADDR_BITS>>,
    w_one: Constant<Bits<W>>,
    w_zero: Constant<Bits<W>>,
    z32: Constant<Bits<32>>,
    msb32: Constant<Bits<32>>,
    /// Bits 31..W when signed, else 0.
    sext: Constant<Bits<32>>,
    /// Bit W − 1: the sign.
    sign: Constant<Bits<32>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    /// 32 − W.
    sh_down: Constant<Bits<SHIFT_BITS>>,
    sh_lsb: Constant<Bits<SHIFT_BITS>>,
}

impl<const W: usize> ReadCell<W> {
    /// The cell of `reg` with its W bits at bit `lsb` of the word (`signed`: sign-extended,
    /// at bit 0 only). Panics on a field that does not fit the 32-bit word.
    pub fn build(reg: &Register, lsb: u32, signed: bool) -> Self {
        assert!((1..=32).contains(&W), "W = {W}: 1..=32");
        assert!(
            W as u32 + lsb <= 32,
            "{}: {W} bits at bit {lsb} exceed the word",
            reg.name
        );
        assert!(!signed || lsb == 0, "a signed value starts at bit 0");
        let k = |v: u64| -> Constant<Bits<32>> { Constant::new(v.into()) };
        let sh = |v: u32| -> Constant<Bits<SHIFT_BITS>> { Constant::new(u64::from(v).into()) };
        let sext = if signed && W < 32 {
            0xFFFF_FFFF & !((1u64 << W) - 1)
        } else {
            0
        };
        Self {
            adr: Default::default(),
            value: Default::default(),
            rdata: Default::default(),
            t: Default::default(),
            x: Default::default(),
            offset: Constant::new(u64::from(reg.offset).into()),
            w_one: Constant::new(1.into()),
            w_zero: Constant::new(0.into()),
            z32: k(0),
            msb32: k(1 << 31),
            sext: k(sext),
            sign: k(1 << (W - 1)),
            sh_one: sh(1),
            sh_down: sh(32 - W as u32),
            sh_lsb: sh(lsb),
        }
    }

    /// `reg` as the value, zero-extended.
    pub fn new(reg: &Register) -> Self {
        Self::build(reg, 0, false)
    }

    /// `reg`'s field `field`: the value zero-extended and placed at the field's LSB (the
    /// field must be W bits wide).
    pub fn field(reg: &Register, field: &str) -> Self {
        let f = reg.field(field);
        assert_eq!(
            f.width as usize, W,
            "{}.{field} is {} bits",
            reg.name, f.width
        );
        Self::build(reg, f.lsb, false)
    }

    /// `reg` as the value, sign-extended from W bits.
    pub fn signed(reg: &Register) -> Self {
        Self::build(reg, 0, true)
    }
}

impl<const W: usize> Logic for ReadCell<W> {
    #[hdl_gen]
    fn update(&mut self) {
        self.x.next = self.z32.val();
        self.t.next = self.value.val();
        for _i in 0..W {
            self.x.next = self.x.val() >> self.sh_one.val();
            if (self.t.val() & self.w_one.val()) != self.w_zero.val() {
                self.x.next = self.x.val() | self.msb32.val();
            }
            self.t.next = self.t.val() >> self.sh_one.val();
        }
        self.x.next = self.x.val() >> self.sh_down.val();
        if (self.x.val() & self.sign.val()) != self.z32.val() {
            self.x.next = self.x.val() | self.sext.val();
        }
        self.rdata.next = self.z32.val();
        if self.adr.val() == self.offset.val() {
            self.rdata.next = self.x.val() << self.sh_lsb.val();
        }
    }
}
