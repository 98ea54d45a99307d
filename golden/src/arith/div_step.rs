// SPDX-License-Identifier: MIT OR Apache-2.0
//! One step of restoring radix-2 division at W bits (the block `hdl::DivStep`, used by
//! `SeqDivider` and `EccMtSpeed`; `hdl::SpeedCalc` and `hdl::BaselineSpeeds` take
//! non-restoring steps over two cycles, with the same quotient bits): with partial
//! remainder R and the bit b brought down, the trial value 2R + b has W + 1 bits; its top
//! bit is R's most significant bit (the carry) and its low W
//! bits are `shifted`. The quotient bit is `fits` = carry or shifted ≥ den, and the next
//! remainder is shifted − den (W-bit wrapping, exact when R < den) if it fits, else
//! shifted. Over the dividers' invariant R < den this is the long division of
//! [`crate::estimator::speed_calc::long_division`] and of
//! [`crate::arith::seq_divider::SeqDividerModel`], one bit per step.

/// The step at `w` bits (1..=127): `(next_rem, fits)` for remainder `rem`, the bit `bit`
/// and the denominator `den` (`rem`, `den` < 2^w).
pub fn div_step(rem: u128, bit: bool, den: u128, w: u32) -> (u128, bool) {
    assert!((1..=127).contains(&w), "w = {w}");
    let mask = (1u128 << w) - 1;
    assert!(rem <= mask && den <= mask, "operands wider than {w} bits");
    let carry = rem >> (w - 1) == 1;
    let shifted = ((rem << 1) | u128::from(bit)) & mask;
    let fits = carry || shifted >= den;
    let next = if fits {
        shifted.wrapping_sub(den) & mask
    } else {
        shifted
    };
    (next, fits)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Under R < den the steps are the schoolbook long division: 100 / 7 at 8 bits, one
    /// numerator bit at a time from the top, gives quotient 14 and remainder 2.
    #[test]
    fn steps_are_long_division_by_hand() {
        let (num, den, w) = (100u128, 7u128, 8);
        let (mut rem, mut quo) = (0u128, 0u128);
        for k in (0..w).rev() {
            let (r, q) = div_step(rem, (num >> k) & 1 == 1, den, w);
            rem = r;
            quo = 2 * quo + u128::from(q);
        }
        assert_eq!((quo, rem), (14, 2));
    }

    /// The carry: a remainder with its top bit set always fits, and the wrapped
    /// difference is the true 2R + b − den.
    #[test]
    fn the_carry_fits_and_the_difference_wraps_exactly() {
        // w = 4: R = 9 (1001), b = 1, den = 12: 2R + b = 19 ≥ 12, next 7.
        assert_eq!(div_step(9, true, 12, 4), (7, true));
        // R = 5, b = 0, den = 12: 10 < 12.
        assert_eq!(div_step(5, false, 12, 4), (10, false));
    }
}
