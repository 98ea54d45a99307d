// SPDX-License-Identifier: MIT OR Apache-2.0
//! Mode scaling of a speed (combinational): a signed speed in decoder steps per dt to
//! lines per dt (units of ω_lim). Bit-true model: [`golden::top::core::mode_scale`].
//!
//! In x1 a step is a line (shift 0, the value passes). In x2 and x4 there are 2 and 4 steps
//! per line (shift 1, 2): the magnitude is divided by 2^shift, rounded to nearest with ties
//! away from zero, and the sign put back, so forward and reverse speeds stay mirror images
//! and zero stays 0. Error: ½ LSB more than the input's
//! ([`golden::top::core::mode_scale_error_lsb`]).
//!
//! Ports: `value[S-1:0]` (two's complement, magnitude below 2^(S−1)), `shift[1:0]` (0, 1,
//! 2; 3 acts as 2), `scaled[S-1:0]`. No register: the core registers the result.

use rust_hdl::prelude::*;

/// Divides a signed speed by 1, 2 or 4 with rounding of the magnitude.
#[derive(LogicBlock)]
pub struct ModeScale<const S: usize> {
    /// Speed in steps per dt, two's complement.
    pub value: Signal<In, Bits<S>>,
    /// log2 of the steps per line.
    pub shift: Signal<In, Bits<2>>,
    /// Speed in lines per dt, two's complement.
    pub scaled: Signal<Out, Bits<S>>,
    negative: Signal<Local, Bit>,
    magnitude: Signal<Local, Bits<S>>,
    rounded: Signal<Local, Bits<S>>,
    zero: Constant<Bits<S>>,
    one: Constant<Bits<S>>,
    two: Constant<Bits<S>>,
    sign_mask: Constant<Bits<S>>,
    sh_zero: Constant<Bits<2>>,
    sh_one: Constant<Bits<2>>,
    by_one: Constant<Bits<8>>,
    by_two: Constant<Bits<8>>,
}

impl<const S: usize> Default for ModeScale<S> {
    fn default() -> Self {
        assert!((4..=64).contains(&S), "ModeScale: S outside 4..=64");
        Self {
            value: Default::default(),
            shift: Default::default(),
            scaled: Default::default(),
            negative: Default::default(),
            magnitude: Default::default(),
            rounded: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            two: Constant::new(2.into()),
            sign_mask: Constant::new(Bits::<S>::default().replace_bit(S - 1, true)),
            sh_zero: Constant::new(0.into()),
            sh_one: Constant::new(1.into()),
            by_one: Constant::new(1.into()),
            by_two: Constant::new(2.into()),
        }
    }
}

impl<const S: usize> Logic for ModeScale<S> {
    #[hdl_gen]
    fn update(&mut self) {
        self.negative.next = (self.value.val() & self.sign_mask.val()) != self.zero.val();
        self.magnitude.next = self.value.val();
        if self.negative.val() {
            self.magnitude.next = self.zero.val() - self.value.val();
        }
        self.rounded.next = self.magnitude.val();
        if self.shift.val() == self.sh_one.val() {
            self.rounded.next = (self.magnitude.val() + self.one.val()) >> self.by_one.val();
        } else if self.shift.val() != self.sh_zero.val() {
            self.rounded.next = (self.magnitude.val() + self.two.val()) >> self.by_two.val();
        }
        self.scaled.next = self.rounded.val();
        if self.negative.val() {
            self.scaled.next = self.zero.val() - self.rounded.val();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::verilator_lint;

    fn scale(v: i64, shift: u64) -> i64 {
        let mut uut = ModeScale::<12>::default();
        uut.connect_all();
        uut.value.next = ((v as u64) & 0xfff).into();
        uut.shift.next = shift.into();
        assert!(simulate(&mut uut, 10));
        let raw = uut.scaled.val().to_u64();
        ((raw << 52) as i64) >> 52
    }

    #[test]
    fn hand_worked_values() {
        // 5/2 = 2.5 → 3 (tie away from zero); 5/4 = 1.25 → 1; 6/4 = 1.5 → 2; 7/4 → 2.
        assert_eq!(scale(5, 1), 3);
        assert_eq!(scale(-5, 1), -3);
        assert_eq!(scale(5, 2), 1);
        assert_eq!(scale(6, 2), 2);
        assert_eq!(scale(-7, 2), -2);
        assert_eq!(scale(-7, 3), -2);
        assert_eq!(scale(-7, 0), -7);
        assert_eq!(scale(1, 2), 0);
        assert_eq!(scale(-1, 2), 0);
    }

    #[test]
    fn equals_golden_on_every_12_bit_value() {
        for v in -2047i64..=2047 {
            for s in 0..4u64 {
                let want = golden::top::core::mode_scale(v, (s as u32).min(2));
                assert_eq!(scale(v, s), want, "v = {v}, shift = {s}");
            }
        }
    }

    #[test]
    fn synthesises_and_lints() {
        let mut uut = ModeScale::<41>::default();
        uut.connect_all();
        let v = generate_verilog(&uut);
        yosys_validate("encspeed_mode_scale", &v).unwrap();
        verilator_lint("top", &v);
    }
}
