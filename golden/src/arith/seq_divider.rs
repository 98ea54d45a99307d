// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of the sequential divider `hdl::SeqDivider<W>` (unsigned restoring radix-2
//! division, one quotient bit per clock), and the fixed-point helpers its callers use.
//!
//! # Behaviour (shared with the HDL block)
//!
//! * `start` is sampled at a rising edge. When the divider is idle (`busy` low), the edge
//!   loads `numerator` and `denominator` and raises `busy`. A `start` while busy is ignored
//!   (not queued), and `numerator`/`denominator` are only read at an accepted start.
//! * The next W edges each produce one quotient bit, most significant first. The W-th of them
//!   writes `quotient`, `remainder` and `div_by_zero`, lowers `busy` and raises `done` for
//!   one cycle.
//! * Latency ([`latency_cycles`]): a start sampled at edge k gives `done` high after edge
//!   k + W (in the model's convention, the outputs of the step W steps after the step whose
//!   inputs carried the start). `busy` is high after edges k … k + W − 1. The cycle in which
//!   `done` is high is already idle, so a start in that cycle is accepted: one division every
//!   W + 1 cycles at most.
//! * `quotient`, `remainder` and `div_by_zero` are registers held until the next result
//!   (or a reset).
//! * Division by zero: `quotient` = 2^W − 1 (all ones), `remainder` = numerator,
//!   `div_by_zero` high. This is what the restoring recurrence computes by itself when the
//!   denominator is 0; the flag tells it apart from a real all-ones quotient.
//! * Reset (synchronous, active high, wins over `start`): `busy`, `done`, `quotient`,
//!   `remainder`, `div_by_zero` become 0; a division in progress is abandoned without `done`.
//!   Power-up values are the same as after reset.
//!
//! # Fixed point
//!
//! The divider is an integer divider. To get F fractional bits, the caller passes
//! `num << F` as the numerator: the quotient is then ⌊num·2^F / den⌋. The caller must make
//! sure `num << F` fits in W bits ([`shifted_numerator`] and [`fixed_quotient`] check it and
//! report [`Overflow`] instead of truncating). With a non-zero denominator the quotient never
//! exceeds the numerator, so a numerator that fits gives a quotient that fits.

use std::fmt;

/// Largest width the model (and the HDL block) supports.
pub const MAX_WIDTH: u32 = 64;
/// Smallest width the model (and the HDL block) supports.
pub const MIN_WIDTH: u32 = 2;

/// Clock edges from the edge that accepts `start` to the edge after which `done` is high:
/// exactly `width` (one quotient bit per edge).
pub const fn latency_cycles(width: u32) -> u32 {
    width
}

/// All ones in `width` bits.
pub const fn mask(width: u32) -> u64 {
    u64::MAX >> (64 - width)
}

/// Inputs of the divider during one clock cycle (sampled at its rising edge).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DividerInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Start a division (accepted only when idle).
    pub start: bool,
    /// Dividend, W bits; read only at an accepted start.
    pub numerator: u64,
    /// Divisor, W bits; read only at an accepted start.
    pub denominator: u64,
}

/// Outputs of the divider after a rising clock edge (all registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DividerOutputs {
    /// A division is in progress (a start now would be ignored).
    pub busy: bool,
    /// One-cycle strobe: `quotient`, `remainder`, `div_by_zero` were just written.
    pub done: bool,
    /// ⌊numerator / denominator⌋, or all ones when the denominator was 0.
    pub quotient: u64,
    /// numerator mod denominator, or the numerator when the denominator was 0.
    pub remainder: u64,
    /// The last result came from a zero denominator.
    pub div_by_zero: bool,
}

/// The result the divider gives for one division (the rule, from Rust's `/` and `%`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Division {
    /// Quotient (all ones in `width` bits when dividing by zero).
    pub quotient: u64,
    /// Remainder (the numerator when dividing by zero).
    pub remainder: u64,
    /// The denominator was zero.
    pub div_by_zero: bool,
}

/// The documented result of `numerator / denominator` in `width` bits, including the
/// division-by-zero rule. Panics if an operand does not fit `width` bits or `width` is out of
/// [`MIN_WIDTH`]..=[`MAX_WIDTH`].
pub fn divide(numerator: u64, denominator: u64, width: u32) -> Division {
    check_width(width);
    check_operand("numerator", numerator, width);
    check_operand("denominator", denominator, width);
    match (
        numerator.checked_div(denominator),
        numerator.checked_rem(denominator),
    ) {
        (Some(quotient), Some(remainder)) => Division {
            quotient,
            remainder,
            div_by_zero: false,
        },
        _ => Division {
            quotient: mask(width),
            remainder: numerator,
            div_by_zero: true,
        },
    }
}

fn check_width(width: u32) {
    assert!(
        (MIN_WIDTH..=MAX_WIDTH).contains(&width),
        "divider width {width} outside {MIN_WIDTH}..={MAX_WIDTH}"
    );
}

fn check_operand(name: &str, value: u64, width: u32) {
    assert!(
        value <= mask(width),
        "{name} {value:#x} does not fit {width} bits"
    );
}

/// Why a fixed-point division cannot be done by a W-bit divider.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Overflow {
    /// `num · 2^frac_bits` needs `bits_needed` bits, more than the divider's `width`.
    Numerator {
        /// Bits needed by the shifted numerator.
        bits_needed: u32,
        /// Width of the divider.
        width: u32,
    },
    /// The denominator is zero: the quotient is unbounded (the hardware would saturate).
    ZeroDenominator,
}

impl fmt::Display for Overflow {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Overflow::Numerator { bits_needed, width } => write!(
                f,
                "the shifted numerator needs {bits_needed} bits, the divider has {width}"
            ),
            Overflow::ZeroDenominator => write!(f, "division by zero"),
        }
    }
}

impl std::error::Error for Overflow {}

/// `num << frac_bits`, the numerator to pass to a `width`-bit divider for `frac_bits`
/// fractional bits of quotient; [`Overflow::Numerator`] if it does not fit `width` bits.
/// Panics if `width` is out of [`MIN_WIDTH`]..=[`MAX_WIDTH`].
pub fn shifted_numerator(num: u64, frac_bits: u32, width: u32) -> Result<u64, Overflow> {
    check_width(width);
    if num == 0 {
        return Ok(0);
    }
    let bits_needed = (64 - num.leading_zeros()).saturating_add(frac_bits);
    if bits_needed > width {
        return Err(Overflow::Numerator { bits_needed, width });
    }
    // bits_needed <= width <= 64, so the shift loses nothing.
    Ok(num << frac_bits)
}

/// ⌊num · 2^frac_bits / den⌋ exactly, as a `width`-bit divider computes it when given
/// [`shifted_numerator`]`(num, frac_bits, width)`: an error instead of a truncated or
/// saturated value when the shifted numerator does not fit or `den` is zero. `den` must fit
/// `width` bits (panics otherwise).
pub fn fixed_quotient(num: u64, den: u64, frac_bits: u32, width: u32) -> Result<u64, Overflow> {
    let n = shifted_numerator(num, frac_bits, width)?;
    check_operand("denominator", den, width);
    n.checked_div(den).ok_or(Overflow::ZeroDenominator)
}

/// Cycle-by-cycle model of `hdl::SeqDivider<W>`: the same registers and the same restoring
/// recurrence, one quotient bit per [`SeqDividerModel::step`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SeqDividerModel {
    width: u32,
    /// Partial remainder.
    rem: u64,
    /// Numerator bits still to bring down (high end), quotient bits so far (low end).
    quo: u64,
    /// Denominator sampled at start.
    den: u64,
    /// Steps left after the current one (W − 1 … 0).
    count: u32,
    out: DividerOutputs,
}

impl SeqDividerModel {
    /// A `width`-bit divider in its power-up state (equal to the state after reset).
    /// Panics if `width` is out of [`MIN_WIDTH`]..=[`MAX_WIDTH`].
    pub fn new(width: u32) -> SeqDividerModel {
        check_width(width);
        SeqDividerModel {
            width,
            rem: 0,
            quo: 0,
            den: 0,
            count: 0,
            out: DividerOutputs::default(),
        }
    }

    /// Width W of the operands and results.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Outputs after the last edge.
    pub fn outputs(&self) -> DividerOutputs {
        self.out
    }

    /// One rising clock edge with `inp` applied; returns the outputs after the edge.
    /// Panics if `numerator` or `denominator` does not fit W bits (the ports are W wide).
    pub fn step(&mut self, inp: DividerInputs) -> DividerOutputs {
        let w = self.width;
        let m = mask(w);
        check_operand("numerator", inp.numerator, w);
        check_operand("denominator", inp.denominator, w);
        // Combinational values before the edge, from the registers.
        let carry = (self.rem >> (w - 1)) & 1 == 1;
        let shifted = ((self.rem << 1) & m) | ((self.quo >> (w - 1)) & 1);
        // shifted + carry·2^W ≥ den; the difference then fits W bits, so a W-bit wrapping
        // subtraction gives it exactly.
        let fits = carry || shifted >= self.den;
        let next_rem = if fits {
            shifted.wrapping_sub(self.den) & m
        } else {
            shifted
        };
        let next_quo = ((self.quo << 1) & m) | u64::from(fits);
        let last_step = self.count == 0;

        let mut out = DividerOutputs {
            done: false,
            ..self.out
        };
        if self.out.busy {
            self.rem = next_rem;
            self.quo = next_quo;
            self.count = self.count.wrapping_sub(1) & 63;
            if last_step {
                out.busy = false;
                out.done = true;
                out.quotient = next_quo;
                out.remainder = next_rem;
                out.div_by_zero = self.den == 0;
            }
        } else if inp.start {
            self.rem = 0;
            self.quo = inp.numerator;
            self.den = inp.denominator;
            self.count = w - 1;
            out.busy = true;
        }
        if inp.reset {
            out = DividerOutputs::default();
        }
        self.out = out;
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn masks() {
        assert_eq!(mask(8), 0xff);
        assert_eq!(mask(64), u64::MAX);
    }

    #[test]
    fn one_division_by_hand() {
        // 13 / 4 in 4 bits: quotient 3, remainder 1, done 4 edges after the start.
        let mut m = SeqDividerModel::new(4);
        let start = DividerInputs {
            start: true,
            numerator: 13,
            denominator: 4,
            ..Default::default()
        };
        assert!(m.step(start).busy);
        for _ in 0..3 {
            let o = m.step(DividerInputs::default());
            assert!(o.busy && !o.done);
        }
        let o = m.step(DividerInputs::default());
        assert_eq!(
            o,
            DividerOutputs {
                busy: false,
                done: true,
                quotient: 3,
                remainder: 1,
                div_by_zero: false
            }
        );
    }
}
