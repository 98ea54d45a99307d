// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::TwoCycleAdder`: a W-bit adder whose carry chain is cut in two by
//! a register, so that no path of the iCE40 carries more than about W/2 bits in one clock
//! cycle (a 49-bit chain alone takes 10.5 ns of the 10 ns a 100 MHz cycle has).
//!
//! At each rising edge the block registers the sum of the low L = ⌈W/2⌉ bits of its
//! operands and `carry_in` (with the carry out of them) and the high W − L bits of both
//! operands; in the following cycle it adds the high bits with the registered carry. Its
//! output is therefore a + b + carry_in (mod 2^W) of the inputs at the last edge: a
//! pipelined adder of latency one, which is all [`TwoCycleAdderModel`] states.

/// Width of the low, registered part of a `w`-bit adder: ⌈w/2⌉.
pub const fn low_bits(w: u32) -> u32 {
    w.div_ceil(2)
}

/// The sum the block outputs, from the inputs at the last edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TwoCycleAdderModel {
    w: u32,
    sum: u128,
}

impl TwoCycleAdderModel {
    /// A `w`-bit adder (4..=127) after power-up: the registers hold 0, so the sum is 0.
    pub fn new(w: u32) -> TwoCycleAdderModel {
        assert!(
            (4..=127).contains(&w),
            "TwoCycleAdder supports W in 4..=127"
        );
        TwoCycleAdderModel { w, sum: 0 }
    }

    /// A rising edge with inputs `a`, `b` (< 2^w) and `carry_in`; the sum after it.
    pub fn edge(&mut self, a: u128, b: u128, carry_in: bool) -> u128 {
        self.sum = (a + b + u128::from(carry_in)) & ((1u128 << self.w) - 1);
        self.sum
    }

    /// The sum after the last edge.
    pub fn sum(&self) -> u128 {
        self.sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The register split does not show: every input at W = 5 gives the wrapped sum.
    #[test]
    fn the_sum_wraps_at_w_bits() {
        let mut m = TwoCycleAdderModel::new(5);
        assert_eq!(m.sum(), 0);
        assert_eq!(m.edge(31, 0, true), 0);
        assert_eq!(m.edge(17, 14, false), 31);
        assert_eq!(m.edge(17, 14, true), 0);
        assert_eq!(low_bits(5), 3);
        assert_eq!(low_bits(49), 25);
    }
}
