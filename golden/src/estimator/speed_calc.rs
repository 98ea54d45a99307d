// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of the speed calculator `hdl::SpeedCalc`: Rairán's n1, n2 and n3 from the
//! registers Nep1 and Ndt1, as signed fixed-point numbers, computed by a sequential
//! divider.
//!
//! # Values
//!
//! With Nep = Nep1 and Ndt = Ndt1 (N-bit unsigned), in units of ω_lim (Rairán 2013):
//!
//! | output | exact value | source |
//! |---|---|---|
//! | n1 | Nep / Ndt | eq. (5) |
//! | n2 | (Nep − 1) / Ndt if Nep ≥ 2·Ndt (n1 ≥ 2), else Nep / (Ndt + 1) | eq. (6) |
//! | n3 | 2·Nep·(Nep − 1) / (Ndt·(2·Nep − 1)) if Nep ≥ 2·Ndt, else 2·Nep / (2·Ndt + 1) | eq. (11) |
//!
//! [`n1_ratio`], [`n2_ratio`] and [`n3_ratio`] give these as exact fractions of integers.
//!
//! # Format
//!
//! Each output is a signed two's-complement fixed-point number Q(N).F: N integer bits,
//! F = `speed_frac_bits` fractional bits and a sign bit, [`speed_bits`]`(N, F)` = N + F + 1
//! bits in all. The real value is `raw · 2^−F` ω_lim. With Ndt ≥ 1 every value is at most
//! Nep ≤ 2^N − 1, so the magnitude always fits (no saturation is ever needed).
//!
//! # Rounding rule
//!
//! The magnitude is the exact value rounded to the nearest multiple of 2^−F, ties away from
//! zero (up): `⌊value·2^F + ½⌋`, computed in integers only ([`round_ratio`]). The sign is
//! applied afterwards: `raw = −magnitude` when `negative` is 1. Forward and reverse speeds
//! are therefore exact mirror images, and zero is always 0 (never a negative zero or −1).
//! The error of each output against the exact value is at most ½ LSB = 2^−(F+1) ω_lim
//! ([`speed_lsb_error`]); relative to a speed n it is at most 2^−(F+1)/n.
//!
//! # Mode scaling
//!
//! The values above are in decoder steps per dt. The calculator outputs them in lines per
//! dt, the unit of every speed port: each signed value v is [`mode_scale`]d by the `shift`
//! latched with its request (0 in x1, 1 in x2, 2 in x4), i.e. its magnitude divided by
//! 2^shift, rounded to nearest with ties away from zero, and the sign put back. The
//! hardware does this second rounding in the same adder as the first (`hdl::SpeedCalc`'s
//! docs give the identity); the model applies the two roundings one after the other, as
//! written here, so a match checks that identity on every result. In x1 nothing changes.
//!
//! # Special inputs
//!
//! * Nep = 0 (no pulse seen): all three are 0.
//! * Ndt = 0 never comes from the core (Ndt1 is 1 after reset and is written only with a
//!   non-zero Cdt). The calculator defines it anyway: with Nep ≥ 1 the speed is faster than
//!   anything measurable and all three outputs saturate to ±(2^(N+F) − 1), the largest
//!   magnitude of the format; with Nep = 0 they are 0.
//!
//! # Timing (shared with the HDL block)
//!
//! * `start` is sampled at a rising edge (reset low). It latches `nep`, `ndt`, `negative`
//!   and `shift` into a one-deep request register and marks the request pending. A start
//!   while a computation runs is latched the same way (a newer start replaces an older
//!   request that has not begun): the calculator always ends up computing the values of
//!   the **last** start.
//! * At the first edge at which the calculator is idle and a request is pending, it takes the
//!   request and begins. [`latency_cycles`]`(N, F)` = 6·(N + F + 1) + 10 edges after the start
//!   edge (for a start while idle), the three outputs change together and `valid` is high for
//!   one cycle. The outputs are registers, held until the next `valid`.
//! * The request carries a `position` (the core's span end, [`POSITION_BITS`] bits) beside
//!   Nep1 and Ndt1: with the speeds the calculator publishes the position, Nep1 and Ndt1 of
//!   the request they were computed from (`tag`), so a user can tell which stretch of disc a
//!   speed belongs to whatever the rate of requests. `have_speeds` is high from the first
//!   `valid` after reset on.
//! * `busy` is high while a computation runs or a request is pending; it is low in the
//!   `valid` cycle unless another request is waiting. A request that was pending when a
//!   computation ends begins at the edge after `valid`, so back-to-back results are
//!   [`latency_cycles`] edges apart.
//! * `reset` (synchronous, active high) wins over `start`: the outputs (speeds, tag and
//!   `have_speeds`) become 0, `valid` and `busy` 0, and a computation in progress or pending
//!   is abandoned.
//!
//! # Updates that are never lost
//!
//! In the core, any three consecutive `update` strobes span at least dt + 1 cycles (after a
//! restart the next write is the tick dt later; a tick can be followed by a restart one
//! cycle later). With L = [`latency_cycles`], if dt ≥ 2·L − 1 ([`min_lossless_dt`]) every
//! update gets its own `valid` with its own values, the second of two close updates at most
//! 2·L − 1 cycles after its strobe. Below that, an update can be replaced by a newer one
//! before it begins (it is never computed from mixed inputs, and the newest is always
//! computed). Both the bound and its tightness are tested.

use crate::arith::latest_request::LatestRequest;
use crate::params::POSITION_BITS;
use std::fmt;

/// Narrowest counter width N (bits), as [`crate::params::MIN_COUNTER_BITS`].
pub const MIN_COUNTER_BITS: u32 = crate::params::MIN_COUNTER_BITS;
/// Widest counter width N (bits), as [`crate::params::MAX_COUNTER_BITS`].
pub const MAX_COUNTER_BITS: u32 = crate::params::MAX_COUNTER_BITS;
/// Fewest fractional bits F of the speed outputs.
pub const MIN_FRAC_BITS: u32 = 0;
/// Most fractional bits F of the speed outputs (keeps N + F + 1 ≤ 57 bits).
pub const MAX_FRAC_BITS: u32 = 24;

/// Width of each speed output: N integer bits, F fractional bits and a sign bit.
pub const fn speed_bits(counter_bits: u32, frac_bits: u32) -> u32 {
    counter_bits + frac_bits + 1
}

/// Width of the products 2·Nep·(Nep − 1) and Ndt·(2·Nep − 1), and of the divider's
/// denominator and partial remainder: 2·N + 1.
pub const fn product_bits(counter_bits: u32) -> u32 {
    2 * counter_bits + 1
}

/// Clock edges from the edge that samples a `start` (calculator idle) to the edge after
/// which `valid` is high: 6·(N + F + 1) + 10 (one edge to take the request, then per
/// division a set-up and N + F + 1 quotient bits, each two edges because the hardware's
/// wide additions are split over two cycles to meet its clock, then three edges for the
/// last rounding and the publication: 1 + 3·(2 + 2·(N + F + 1)) + 3). The publication's
/// third edge writes the output registers the user reads, so no second rank of output
/// registers follows the calculator in the core.
pub const fn latency_cycles(counter_bits: u32, frac_bits: u32) -> u32 {
    6 * speed_bits(counter_bits, frac_bits) + 10
}

/// Shortest dt (clock cycles) at which no `update` of the core is ever replaced before it is
/// computed: 2·L − 1 with L = [`latency_cycles`] (see the module docs).
pub const fn min_lossless_dt(counter_bits: u32, frac_bits: u32) -> u32 {
    2 * latency_cycles(counter_bits, frac_bits) - 1
}

/// Largest error of a speed output against its exact value, in units of ω_lim: half an
/// LSB, 2^−(F+1). Add it to the Rairán and clock terms of an accuracy budget (relative to a
/// speed n, it is `speed_lsb_error(F) / n`).
pub fn speed_lsb_error(frac_bits: u32) -> f64 {
    (-f64::from(frac_bits) - 1.0).exp2()
}

/// A format the calculator cannot be built for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FormatError {
    /// N outside [`MIN_COUNTER_BITS`]..=[`MAX_COUNTER_BITS`].
    CounterBits(u32),
    /// F outside [`MIN_FRAC_BITS`]..=[`MAX_FRAC_BITS`].
    FracBits(u32),
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FormatError::CounterBits(n) => write!(
                f,
                "counter_bits = {n}: must be {MIN_COUNTER_BITS}..={MAX_COUNTER_BITS}"
            ),
            FormatError::FracBits(b) => write!(
                f,
                "speed_frac_bits = {b}: must be {MIN_FRAC_BITS}..={MAX_FRAC_BITS}"
            ),
        }
    }
}

impl std::error::Error for FormatError {}

/// A validated pair (N, F): counter width and fractional bits of the speed outputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpeedFormat {
    counter_bits: u32,
    frac_bits: u32,
}

impl SpeedFormat {
    /// The format Q(`counter_bits`).`frac_bits`, or the reason it is refused.
    pub fn new(counter_bits: u32, frac_bits: u32) -> Result<SpeedFormat, FormatError> {
        if !(MIN_COUNTER_BITS..=MAX_COUNTER_BITS).contains(&counter_bits) {
            return Err(FormatError::CounterBits(counter_bits));
        }
        if !(MIN_FRAC_BITS..=MAX_FRAC_BITS).contains(&frac_bits) {
            return Err(FormatError::FracBits(frac_bits));
        }
        Ok(SpeedFormat {
            counter_bits,
            frac_bits,
        })
    }

    /// N: width of `nep` and `ndt`.
    pub fn counter_bits(&self) -> u32 {
        self.counter_bits
    }

    /// F: fractional bits of the outputs.
    pub fn frac_bits(&self) -> u32 {
        self.frac_bits
    }

    /// [`speed_bits`] of this format.
    pub fn speed_bits(&self) -> u32 {
        speed_bits(self.counter_bits, self.frac_bits)
    }

    /// [`latency_cycles`] of this format.
    pub fn latency_cycles(&self) -> u32 {
        latency_cycles(self.counter_bits, self.frac_bits)
    }

    /// Largest output magnitude, 2^(N+F) − 1 (the saturation value for Ndt = 0).
    pub fn max_magnitude(&self) -> i64 {
        (1i64 << (self.counter_bits + self.frac_bits)) - 1
    }

    /// Largest counter value, 2^N − 1.
    pub fn counter_max(&self) -> u64 {
        (1u64 << self.counter_bits) - 1
    }

    /// `value` (a speed output) as the raw two's-complement bits of the port.
    pub fn to_raw(&self, value: i64) -> u64 {
        (value as u64) & ((1u64 << self.speed_bits()) - 1)
    }

    /// The raw bits of a speed port as a signed value (sign-extended).
    pub fn from_raw(&self, raw: u64) -> i64 {
        let shift = 64 - self.speed_bits();
        ((raw << shift) as i64) >> shift
    }

    /// A speed output in units of ω_lim.
    pub fn to_f64(&self, value: i64) -> f64 {
        value as f64 * (-f64::from(self.frac_bits)).exp2()
    }
}

/// An exact non-negative fraction num / den.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ratio {
    /// Numerator.
    pub num: u128,
    /// Denominator (0 only for Ndt = 0).
    pub den: u128,
}

/// Nep ≥ 2·Ndt, i.e. n1 ≥ 2: the high-speed branch of eq. (6) and eq. (11).
pub fn high_speed(nep: u64, ndt: u64) -> bool {
    u128::from(nep) >= 2 * u128::from(ndt)
}

/// n1 = Nep / Ndt, eq. (5).
pub fn n1_ratio(nep: u64, ndt: u64) -> Ratio {
    Ratio {
        num: nep.into(),
        den: ndt.into(),
    }
}

/// n2, eq. (6): (Nep − 1)/Ndt when Nep ≥ 2·Ndt, else Nep/(Ndt + 1). (Nep = Ndt = 0 takes
/// the second form.)
pub fn n2_ratio(nep: u64, ndt: u64) -> Ratio {
    let high = high_speed(nep, ndt) && nep >= 1;
    let (nep, ndt) = (u128::from(nep), u128::from(ndt));
    if high {
        Ratio {
            num: nep - 1,
            den: ndt,
        }
    } else {
        Ratio {
            num: nep,
            den: ndt + 1,
        }
    }
}

/// n3, eq. (11): 2·Nep·(Nep − 1)/(Ndt·(2·Nep − 1)) when Nep ≥ 2·Ndt, else 2·Nep/(2·Ndt + 1).
pub fn n3_ratio(nep: u64, ndt: u64) -> Ratio {
    let high = high_speed(nep, ndt) && nep >= 1;
    let (nep, ndt) = (u128::from(nep), u128::from(ndt));
    if high {
        Ratio {
            num: 2 * nep * (nep - 1),
            den: ndt * (2 * nep - 1),
        }
    } else {
        Ratio {
            num: 2 * nep,
            den: 2 * ndt + 1,
        }
    }
}

/// ⌊num·2^F/den + ½⌋: `r` rounded to the nearest multiple of 2^−F, ties up, as a count of
/// 2^−F. Panics if the denominator is 0.
pub fn round_ratio(r: Ratio, frac_bits: u32) -> u128 {
    assert!(r.den != 0, "round_ratio: zero denominator");
    (2 * (r.num << frac_bits) + r.den) / (2 * r.den)
}

/// The three outputs of one computation (values, not raw bits).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Speeds {
    /// `speed_n1`, in units of 2^−F ω_lim.
    pub n1: i64,
    /// `speed_n2`, in units of 2^−F ω_lim.
    pub n2: i64,
    /// `speed_n3`, in units of 2^−F ω_lim.
    pub n3: i64,
}

/// What the calculator outputs for `nep`, `ndt` and `negative` (see the module docs for the
/// rule). Panics if `nep` or `ndt` does not fit N bits.
pub fn speeds(format: SpeedFormat, nep: u64, ndt: u64, negative: bool) -> Speeds {
    let max = format.counter_max();
    assert!(
        nep <= max && ndt <= max,
        "nep = {nep} or ndt = {ndt} does not fit {} bits",
        format.counter_bits()
    );
    let f = format.frac_bits();
    let magnitude = |r: Ratio| -> i64 {
        if nep == 0 {
            0
        } else if ndt == 0 {
            format.max_magnitude()
        } else {
            let m = round_ratio(r, f);
            assert!(m <= format.max_magnitude() as u128, "value out of range");
            m as i64
        }
    };
    let sign = |m: i64| if negative { -m } else { m };
    Speeds {
        n1: sign(magnitude(n1_ratio(nep, ndt))),
        n2: sign(magnitude(n2_ratio(nep, ndt))),
        n3: sign(magnitude(n3_ratio(nep, ndt))),
    }
}

/// A speed in steps per dt (2^−F units) as a speed in lines per dt: the magnitude divided
/// by 2^s, rounded to nearest with ties away from zero, then the sign.
pub fn mode_scale(v: i64, shift: u32) -> i64 {
    if shift == 0 {
        return v;
    }
    let m = (v.unsigned_abs() + (1u64 << (shift - 1))) >> shift;
    if v < 0 {
        -(m as i64)
    } else {
        m as i64
    }
}

/// Largest error of a scaled Rairán speed against its exact value, in LSB (2^−F ω_lim):
/// the calculator's ½ LSB of steps per dt is ½/2^s LSB after the scaling, and the scaling
/// rounds once more (½ LSB) when s > 0.
pub fn mode_scale_error_lsb(shift: u32) -> f64 {
    if shift == 0 {
        0.5
    } else {
        0.5 + 0.5 / f64::from(1u32 << shift)
    }
}

/// The hardware's division algorithm on integers: ⌊num·2^frac_bits/den⌋ by restoring long
/// division that starts from the partial remainder `num >> int_bits`, brings down the low
/// `int_bits` bits of `num` and then `frac_bits` zero bits, one quotient bit per step
/// (int_bits + frac_bits steps). The partial remainder stays below `den`, so it needs only
/// the denominator's width (plus one bit for the trial subtraction); `num·2^frac_bits` is
/// never formed. Returns `None` when the precondition `num >> int_bits < den` fails (the
/// quotient would not fit int_bits + frac_bits bits).
pub fn long_division(num: u128, den: u128, int_bits: u32, frac_bits: u32) -> Option<u128> {
    let mut rem = num >> int_bits;
    if rem >= den {
        return None;
    }
    let low = num & ((1u128 << int_bits) - 1);
    let mut quo = 0u128;
    for k in (0..int_bits + frac_bits).rev() {
        // Bit brought down: bit k − frac_bits of `low`, zero once they are used up.
        let b = if k >= frac_bits {
            (low >> (k - frac_bits)) & 1
        } else {
            0
        };
        let trial = 2 * rem + b;
        let fits = trial >= den;
        rem = if fits { trial - den } else { trial };
        quo = 2 * quo + u128::from(fits);
    }
    Some(quo)
}

/// Inputs of the calculator during one clock cycle (sampled at its rising edge).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SpeedCalcInputs {
    /// Synchronous active-high reset (wins over `start`).
    pub reset: bool,
    /// Request a computation (the core's `update` strobe).
    pub start: bool,
    /// Nep1, N bits; latched at a start.
    pub nep: u64,
    /// Ndt1, N bits; latched at a start.
    pub ndt: u64,
    /// Direction, 1 = reverse; latched at a start.
    pub negative: bool,
    /// log2 of the decoder steps per line (0 = x1, 1 = x2, 2 = x4; 3 acts as 2); latched
    /// at a start. The speeds are [`mode_scale`]d by it.
    pub shift: u32,
    /// Position carried with the request ([`POSITION_BITS`] bits); latched at a start.
    pub position: u64,
}

/// What a request was made from, published with its speeds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RequestTag {
    /// The request's `position`.
    pub position: u64,
    /// The request's Nep1.
    pub nep: u64,
    /// The request's Ndt1.
    pub ndt: u64,
}

/// Outputs of the calculator after a rising clock edge (all from registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SpeedCalcOutputs {
    /// A computation runs or a request is pending.
    pub busy: bool,
    /// One-cycle strobe: the three speeds were just written.
    pub valid: bool,
    /// The speeds (held).
    pub speeds: Speeds,
    /// The request the speeds were computed from (held, written with them).
    pub tag: RequestTag,
    /// A result has been published since reset.
    pub have_speeds: bool,
}

/// Cycle-by-cycle model of `hdl::SpeedCalc`: the request register and the fixed schedule,
/// with the results computed exactly by [`speeds`] (so a match with the hardware proves its
/// datapath exact, not merely equal to a copy of itself).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpeedCalcModel {
    format: SpeedFormat,
    timing: LatestRequest<(RequestTag, bool, u32), (Speeds, RequestTag)>,
    out: SpeedCalcOutputs,
}

impl SpeedCalcModel {
    /// A calculator in its power-up state (equal to the state after reset).
    pub fn new(format: SpeedFormat) -> SpeedCalcModel {
        SpeedCalcModel {
            format,
            timing: LatestRequest::new(),
            out: SpeedCalcOutputs::default(),
        }
    }

    /// The format.
    pub fn format(&self) -> SpeedFormat {
        self.format
    }

    /// Outputs after the last edge.
    pub fn outputs(&self) -> SpeedCalcOutputs {
        self.out
    }

    /// One rising clock edge with `inp` applied; the outputs after it. Panics if `nep` or
    /// `ndt` does not fit N bits or `position` [`POSITION_BITS`] bits (the ports' widths).
    pub fn step(&mut self, inp: SpeedCalcInputs) -> SpeedCalcOutputs {
        let max = self.format.counter_max();
        assert!(
            inp.nep <= max && inp.ndt <= max,
            "nep or ndt does not fit {} bits",
            self.format.counter_bits()
        );
        assert!(
            inp.position >> POSITION_BITS == 0,
            "position does not fit {POSITION_BITS} bits"
        );
        let mut out = SpeedCalcOutputs {
            valid: false,
            ..self.out
        };
        let format = self.format;
        let tag = RequestTag {
            position: inp.position,
            nep: inp.nep,
            ndt: inp.ndt,
        };
        let start = inp.start.then_some((tag, inp.negative, inp.shift.min(2)));
        if let Some((result, tag)) = self.timing.edge(
            start,
            inp.reset,
            format.latency_cycles(),
            |(tag, negative, shift)| {
                let s = speeds(format, tag.nep, tag.ndt, negative);
                let scaled = Speeds {
                    n1: mode_scale(s.n1, shift),
                    n2: mode_scale(s.n2, shift),
                    n3: mode_scale(s.n3, shift),
                };
                (scaled, tag)
            },
        ) {
            out.speeds = result;
            out.tag = tag;
            out.valid = true;
            out.have_speeds = true;
        }
        if inp.reset {
            out = SpeedCalcOutputs::default();
        }
        out.busy = self.timing.busy();
        self.out = out;
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widths_and_latency() {
        assert_eq!(speed_bits(24, 16), 41);
        assert_eq!(product_bits(24), 49);
        // By hand: S = 41, 1 + 3·(2 + 2·41) + 3 = 256; 2·256 − 1 = 511.
        assert_eq!(latency_cycles(24, 16), 256);
        assert_eq!(min_lossless_dt(24, 16), 511);
        assert_eq!(speed_lsb_error(16), 1.0 / 131_072.0);
    }

    #[test]
    fn raw_round_trip() {
        let f = SpeedFormat::new(8, 8).unwrap();
        assert_eq!(f.to_raw(-1), (1 << 17) - 1);
        assert_eq!(f.from_raw((1 << 17) - 1), -1);
        assert_eq!(f.from_raw(f.to_raw(-65_535)), -65_535);
    }
}
