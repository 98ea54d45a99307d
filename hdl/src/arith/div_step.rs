// SPDX-License-Identifier: MIT OR Apache-2.0
//! One step of restoring radix-2 division at W bits, combinational: the arithmetic
//! `SeqDivider` and `EccMtSpeed` repeat once per quotient bit, each with its own schedule
//! and registers (`SpeedCalc` and `BaselineSpeeds` take non-restoring steps over two cycles
//! on a `TwoCycleAdder`: the same quotient bits). Bit-true model:
//! [`golden::arith::div_step::div_step`].
//!
//! With partial remainder `rem` (R) and the bit `bit_in` (b) brought down, the trial value
//! 2R + b has W + 1 bits: its top bit is R's most significant bit (the carry), its low W
//! bits are `shifted`. `fits` = carry | shifted ≥ den is the quotient bit, and `next_rem` is
//! shifted − den if it fits, else shifted. Under the dividers' invariant R < den,
//! 2R + b − den < den fits W bits, so the W-bit wrapping difference is exact (rust-hdl
//! cannot size a W + 1-bit signal from a const generic). shifted ≥ den is the borrow of
//! that one subtraction, read off the top bits of the operands and the difference: one
//! subtractor, no comparator.
//!
//! Ports: `rem`, `den` (W), `bit_in` in (not `bit`: a SystemVerilog keyword); `next_rem` (W), `fits` out. W: 2..=128.

use rust_hdl::prelude::*;

/// Width of the shift-amount constant.
const SHIFT_BITS: usize = 8;

/// One restoring division step at W bits.
#[derive(LogicBlock)]
pub struct DivStep<const W: usize> {
    /// Partial remainder R.
    pub rem: Signal<In, Bits<W>>,
    /// The numerator bit brought down.
    pub bit_in: Signal<In, Bit>,
    /// Denominator.
    pub den: Signal<In, Bits<W>>,
    /// The next partial remainder.
    pub next_rem: Signal<Out, Bits<W>>,
    /// 2R + b ≥ den: the quotient bit.
    pub fits: Signal<Out, Bit>,
    shifted: Signal<Local, Bits<W>>,
    diff: Signal<Local, Bits<W>>,
    shifted_msb: Signal<Local, Bit>,
    den_msb: Signal<Local, Bit>,
    borrow: Signal<Local, Bit>,
    l_fits: Signal<Local, Bit>,
    zero: Constant<Bits<W>>,
    one: Constant<Bits<W>>,
    msb: Constant<Bits<W>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
}

impl<const W: usize> Default for DivStep<W> {
    fn default() -> Self {
        assert!((2..=128).contains(&W), "DivStep supports W in 2..=128");
        Self {
            rem: Default::default(),
            bit_in: Default::default(),
            den: Default::default(),
            next_rem: Default::default(),
            fits: Default::default(),
            shifted: Default::default(),
            diff: Default::default(),
            shifted_msb: Default::default(),
            den_msb: Default::default(),
            borrow: Default::default(),
            l_fits: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            // W can exceed 64: build 2^(W−1) bit by bit rather than from a u64.
            msb: Constant::new(Bits::<W>::default().replace_bit(W - 1, true)),
            sh_one: Constant::new(1.into()),
        }
    }
}

impl<const W: usize> Logic for DivStep<W> {
    #[hdl_gen]
    fn update(&mut self) {
        self.shifted.next = self.rem.val() << self.sh_one.val();
        if self.bit_in.val() {
            self.shifted.next = (self.rem.val() << self.sh_one.val()) | self.one.val();
        }
        self.diff.next = self.shifted.val() - self.den.val();
        self.shifted_msb.next = (self.shifted.val() & self.msb.val()) != self.zero.val();
        self.den_msb.next = (self.den.val() & self.msb.val()) != self.zero.val();
        self.borrow.next = ((!self.shifted_msb.val()) & self.den_msb.val())
            | ((!(self.shifted_msb.val() ^ self.den_msb.val()))
                & ((self.diff.val() & self.msb.val()) != self.zero.val()));
        self.l_fits.next =
            ((self.rem.val() & self.msb.val()) != self.zero.val()) | (!self.borrow.val());
        self.next_rem.next = self.shifted.val();
        if self.l_fits.val() {
            self.next_rem.next = self.diff.val();
        }
        self.fits.next = self.l_fits.val();
    }
}
