// SPDX-License-Identifier: MIT OR Apache-2.0
//! A LO/HI register pair of a register file ([`crate::bus::wb_front`]) for a value wider
//! than a word (the S-bit speeds): the value sign-extended to 64 bits; LO reads bits 31:0
//! live and, at the same edge, latches bits 63:32 into the HI shadow, which HI reads. A
//! reader that reads LO then HI gets one coherent 64-bit value. Model: the shadow pairs of
//! [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `clock`, `reset` (synchronous, shadow to 0); `adr`, `rd` from the file; `value`
//! (S, two's complement); `rdata` (32) the LO or HI word at their offsets, else 0.
//!
//! The value is sign-extended by shifting its bits in at the top and shifting down by a
//! constant (a cast would be emitted as a mask of another width, which Verilator flags).

use golden::bus::regmap::{Register, ADDR_BITS};
use rust_hdl::prelude::*;

/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// A LO/HI pair of an S-bit two's complement value (2 ≤ S ≤ 64).
#[derive(LogicBlock)]
pub struct ShadowCell<const S: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Addressed word, from the file.
    pub adr: Signal<In, Bits<ADDR_BITS>>,
    /// A read request, from the file.
    pub rd: Signal<In, Bit>,
    /// The value, two's complement.
    pub value: Signal<In, Bits<S>>,
    /// LO or HI at their offsets, else 0.
    pub rdata: Signal<Out, Bits<32>>,
    hi: DFF<Bits<32>>,
    x: Signal<Local, Bits<64>>,
    a_lo: Constant<Bits<ADDR_BITS>>,
    a_hi: Constant<Bits<ADDR_BITS>>,
    z32: Constant<Bits<32>>,
    z64: Constant<Bits<64>>,
    msb64: Constant<Bits<64>>,
    /// Bits 63..S: the sign extension.
    sext: Constant<Bits<64>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    /// 64 − S.
    sh_s: Constant<Bits<SHIFT_BITS>>,
}

impl<const S: usize> ShadowCell<S> {
    /// The pair `lo`, `hi`.
    pub fn new(lo: &Register, hi: &Register) -> Self {
        assert!((2..=64).contains(&S), "S = {S}: 2..=64");
        assert_ne!(lo.offset, hi.offset);
        let sh = |v: usize| -> Constant<Bits<SHIFT_BITS>> { Constant::new((v as u64).into()) };
        let sext = if S == 64 { 0 } else { !((1u64 << S) - 1) };
        Self {
            clock: Default::default(),
            reset: Default::default(),
            adr: Default::default(),
            rd: Default::default(),
            value: Default::default(),
            rdata: Default::default(),
            hi: Default::default(),
            x: Default::default(),
            a_lo: Constant::new(u64::from(lo.offset).into()),
            a_hi: Constant::new(u64::from(hi.offset).into()),
            z32: Constant::new(0.into()),
            z64: Constant::new(0.into()),
            msb64: Constant::new((1u64 << 63).into()),
            sext: Constant::new(sext.into()),
            sh_one: sh(1),
            sh_s: sh(64 - S),
        }
    }
}

impl<const S: usize> Logic for ShadowCell<S> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, hi);
        // Shift the bits in at the top, then move them down and fill bits 63..S with the
        // sign (now bit 63).
        self.x.next = self.z64.val();
        for i in 0..S {
            self.x.next = self.x.val() >> self.sh_one.val();
            if self.value.val().get_bit(i) {
                self.x.next = self.x.val() | self.msb64.val();
            }
        }
        if (self.x.val() & self.msb64.val()) != self.z64.val() {
            self.x.next = (self.x.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x.next = self.x.val() >> self.sh_s.val();
        }
        self.rdata.next = self.z32.val();
        if self.adr.val() == self.a_lo.val() {
            self.rdata.next = self.x.val().get_bits::<32>(0);
            if self.rd.val() {
                self.hi.d.next = self.x.val().get_bits::<32>(32);
            }
        }
        if self.adr.val() == self.a_hi.val() {
            self.rdata.next = self.hi.q.val();
        }
        if self.reset.val() {
            self.hi.d.next = self.z32.val();
        }
    }
}
