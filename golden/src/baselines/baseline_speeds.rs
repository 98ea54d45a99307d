// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::BaselineSpeeds`: the three baseline estimators (fixed-time PC,
//! fixed-space ET, M/T) turned from their raw counts into speeds in the format of
//! [`crate::estimator::speed_calc`], by one sequential shift-add multiplier and one sequential divider.
//!
//! # Values
//!
//! Units of ω_lim = one encoder **line** per dt (dt = `cfg_dt` clock cycles). The counters
//! count decoder steps, 2^s per line for the decoding multiplier x1, x2, x4
//! (s = `mode_shift` = 0, 1, 2; 3 counts as 2, [`effective_shift`]). With dt = max(`cfg_dt`, 1)
//! ([`effective_dt`]), the exact values, in units of 2^−F ω_lim, are
//!
//! | output | exact value (units of 2^−F ω_lim) | from |
//! |---|---|---|
//! | `speed_pc` | `pc_count`·2^(F−s) (exact, no rounding) | [`crate::baselines::pc_counter`]: net steps per window of dt cycles |
//! | `speed_et` | ±dt·2^(F−s)/`et_period`; 0 if `et_valid` = 0 or `et_period` = 0 | [`crate::baselines::et_timer`]: cycles between two steps |
//! | `speed_mt` | ±m·dt·2^(F−s)/t; 0 if m = 0 or t = 0 | [`crate::baselines::mt_counter`]: m steps in t cycles |
//!
//! (the sign is − when `et_negative` resp. `mt_negative` is 1). [`speed_pc`], [`speed_et`]
//! and [`speed_mt`] compute them in u128 integers; [`baseline_speeds`] gives all three.
//!
//! # Format
//!
//! The format of the speed calculator ([`crate::estimator::speed_calc`]): signed two's complement
//! Q(N).F in S = N + F + 1 bits, the value is `raw · 2^−F` ω_lim. N = counter width 8..=32,
//! F = fractional bits 2..=24 ([`BaselineFormat`]). F ≥ 2 makes `pc_count`·2^(F−s) an
//! integer for every s.
//!
//! # Rounding rule and range
//!
//! `speed_et` and `speed_mt`: the magnitude is the exact value rounded to the nearest integer,
//! ties away from zero, `⌊x + ½⌋` ([`round_scaled`]); the sign is applied afterwards, so
//! forward and reverse are exact mirror images and zero is always 0. Error ≤ ½ LSB =
//! 2^−(F+1) ω_lim ([`crate::estimator::speed_calc::speed_lsb_error`]).
//!
//! * `speed_pc` always fits: |`pc_count`| ≤ 2^(N−1), so |value| ≤ 2^(N+F−1).
//! * `speed_et` always fits: the magnitude is at most dt·2^F ≤ (2^N − 1)·2^F ≤ 2^(N+F) − 1.
//! * `speed_mt` fits whenever m ≤ t (always true of [`crate::baselines::mt_counter`], whose m steps lie
//!   at least one cycle apart inside t cycles): the magnitude is then at most dt·2^F. For
//!   other inputs (m > t, possible only from other sources) the magnitude **saturates** at
//!   2^(N+F) − 1, the largest of the format ([`BaselineFormat::max_magnitude`]): the output
//!   is ±(2^(N+F) − 1), never wrapped. The ½-LSB bound does not hold there.
//!
//! # Hardware algorithm
//!
//! [`hardware_magnitude`] restates, on integers, what the block does for `speed_et` and
//! `speed_mt`; the tests prove it equal to the exact rule (exhaustively for small widths):
//!
//! 1. X = m·dt by a shift-add multiplier, least significant bit first, N steps, into two
//!    N-bit halves {A, Q} ([`shift_add_multiply`]); for ET, A = 0 and Q = dt.
//! 2. num' = X·2^(2−s) (2N + 2 bits, never formed): the divider computes
//!    q = ⌊num'·2^(F−1)/den⌋ = ⌊X·2^(F+1−s)/den⌋ by restoring long division with the
//!    partial remainder preloaded with num' >> (N + 2) = A >> s, bringing down the low N + 2
//!    bits of num' (A's low s bits, Q, 2 − s zeros) and then F − 1 zeros: S = N + F + 1
//!    steps, as [`crate::estimator::speed_calc::long_division`]`(num', den, N + 2, F − 1)`.
//!    The partial remainder stays below den < 2^N.
//! 3. If the preload is not below den, num'/den ≥ 2^(N+2), the magnitude is at least
//!    2^(N+F): saturate. Else the magnitude is (q + 1) >> 1, except that q = 2^S − 1 (which
//!    would round up to 2^(N+F)) saturates to 2^(N+F) − 1.
//!
//! # Timing (shared with the HDL block)
//!
//! As [`crate::estimator::speed_calc`]: `start` latches every input into a one-deep request register and
//! marks it pending; a start while busy replaces a request that has not begun, so the
//! **last** start's values are always computed. At the first edge at which the block is idle
//! and a request is pending it takes the request; [`latency_cycles`]`(N, F)` =
//! 4·(N + F + 1) + 4 edges after a start edge (block idle) the three outputs change together
//! and `valid` is high for one cycle. `busy` is high while a computation runs or a request
//! is pending. Starts at least L edges apart each get their own `valid`, exactly L edges
//! after the start. `reset` (synchronous, active high) wins over `start`: outputs 0, `valid`
//! and `busy` 0, any computation or request abandoned.

use crate::arith::latest_request::LatestRequest;
use crate::estimator::speed_calc::SpeedFormat;
use std::fmt;

/// Counter widths N: the validated parameters' range (the core's counters feed this block).
pub use crate::params::{MAX_COUNTER_BITS, MIN_COUNTER_BITS};
/// Fewest fractional bits F (pc_count·2^(F−s) must be an integer for s ≤ 2).
pub const MIN_FRAC_BITS: u32 = 2;
/// Most fractional bits F (keeps S = N + F + 1 ≤ 57 bits).
pub const MAX_FRAC_BITS: u32 = 24;
/// Largest effective `mode_shift` (x4 decoding).
pub const MAX_SHIFT: u32 = 2;

/// Width S of each speed output: N integer bits, F fractional bits and a sign bit.
pub const fn speed_bits(counter_bits: u32, frac_bits: u32) -> u32 {
    counter_bits + frac_bits + 1
}

/// Clock edges from the edge that samples a `start` (block idle) to the edge after which
/// `valid` is high: 4·(N + F + 1) + 4 (one edge takes the request and sets up the ET
/// division, S = N + F + 1 ET steps of two edges each (the divider's adder is split by a
/// register; the multiplier runs during the first N steps), one edge puts the ET quotient
/// into the two-cycle round-and-sign adder and sets up the M/T division (the first M/T
/// step stages the ET result), S M/T steps of two edges, one edge puts the M/T quotient
/// into the adder, one edge publishes).
pub const fn latency_cycles(counter_bits: u32, frac_bits: u32) -> u32 {
    4 * speed_bits(counter_bits, frac_bits) + 4
}

/// `mode_shift` as used: 0, 1, 2; 3 counts as 2.
pub const fn effective_shift(mode_shift: u32) -> u32 {
    if mode_shift > MAX_SHIFT {
        MAX_SHIFT
    } else {
        mode_shift
    }
}

/// `cfg_dt` as used: 0 counts as 1.
pub const fn effective_dt(cfg_dt: u64) -> u64 {
    if cfg_dt == 0 {
        1
    } else {
        cfg_dt
    }
}

/// A format the block cannot be built for.
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
                "speed_frac_bits = {b}: must be {MIN_FRAC_BITS}..={MAX_FRAC_BITS} for the baseline speeds"
            ),
        }
    }
}

impl std::error::Error for FormatError {}

/// A validated pair (N, F) for [`BaselineSpeedsModel`]: the [`SpeedFormat`] Q(N).F with
/// F ≥ 2.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BaselineFormat {
    speed: SpeedFormat,
}

impl BaselineFormat {
    /// The format Q(`counter_bits`).`frac_bits`, or the reason it is refused.
    pub fn new(counter_bits: u32, frac_bits: u32) -> Result<BaselineFormat, FormatError> {
        if !(MIN_COUNTER_BITS..=MAX_COUNTER_BITS).contains(&counter_bits) {
            return Err(FormatError::CounterBits(counter_bits));
        }
        if !(MIN_FRAC_BITS..=MAX_FRAC_BITS).contains(&frac_bits) {
            return Err(FormatError::FracBits(frac_bits));
        }
        let speed = SpeedFormat::new(counter_bits, frac_bits)
            .expect("the baseline ranges lie inside the speed calculator's");
        Ok(BaselineFormat { speed })
    }

    /// The same format as a [`SpeedFormat`] (raw-bit conversions, f64).
    pub fn speed_format(&self) -> SpeedFormat {
        self.speed
    }

    /// N: width of the counter inputs.
    pub fn counter_bits(&self) -> u32 {
        self.speed.counter_bits()
    }

    /// F: fractional bits of the outputs.
    pub fn frac_bits(&self) -> u32 {
        self.speed.frac_bits()
    }

    /// [`speed_bits`] of this format.
    pub fn speed_bits(&self) -> u32 {
        self.speed.speed_bits()
    }

    /// [`latency_cycles`] of this format.
    pub fn latency_cycles(&self) -> u32 {
        latency_cycles(self.counter_bits(), self.frac_bits())
    }

    /// Largest output magnitude, 2^(N+F) − 1 (the saturation value of `speed_mt`).
    pub fn max_magnitude(&self) -> i64 {
        self.speed.max_magnitude()
    }

    /// Largest unsigned counter value, 2^N − 1.
    pub fn counter_max(&self) -> u64 {
        self.speed.counter_max()
    }

    /// Range of `pc_count` (N-bit two's complement): −2^(N−1)..=2^(N−1) − 1.
    pub fn pc_range(&self) -> std::ops::RangeInclusive<i64> {
        let half = 1i64 << (self.counter_bits() - 1);
        -half..=half - 1
    }

    /// `value` as the raw two's-complement bits of an S-bit port.
    pub fn to_raw(&self, value: i64) -> u64 {
        self.speed.to_raw(value)
    }

    /// The raw bits of an S-bit port as a signed value.
    pub fn from_raw(&self, raw: u64) -> i64 {
        self.speed.from_raw(raw)
    }

    /// `pc_count` as the raw bits of its N-bit port.
    pub fn pc_to_raw(&self, count: i64) -> u64 {
        (count as u64) & self.counter_max()
    }
}

/// ⌊num·2^exp/den + ½⌋: num·2^exp/den rounded to the nearest integer, ties up. Panics if
/// `den` is 0.
pub fn round_scaled(num: u128, den: u128, exp: u32) -> u128 {
    assert!(den != 0, "round_scaled: zero denominator");
    (2 * (num << exp) + den) / (2 * den)
}

/// `speed_pc` for `count` steps: count·2^(F−s), exact.
pub fn speed_pc(format: BaselineFormat, count: i64, mode_shift: u32) -> i64 {
    assert!(
        format.pc_range().contains(&count),
        "pc_count = {count} does not fit {} bits",
        format.counter_bits()
    );
    count * (1i64 << (format.frac_bits() - effective_shift(mode_shift)))
}

/// Sign and saturate a magnitude.
fn signed(format: BaselineFormat, magnitude: u128, negative: bool) -> i64 {
    let m = magnitude.min(format.max_magnitude() as u128) as i64;
    if negative {
        -m
    } else {
        m
    }
}

/// `speed_et`: ±round(dt·2^(F−s)/period), 0 without a valid period.
pub fn speed_et(
    format: BaselineFormat,
    period: u64,
    cfg_dt: u64,
    negative: bool,
    valid: bool,
    mode_shift: u32,
) -> i64 {
    if !valid || period == 0 {
        return 0;
    }
    let e = format.frac_bits() - effective_shift(mode_shift);
    signed(
        format,
        round_scaled(effective_dt(cfg_dt).into(), period.into(), e),
        negative,
    )
}

/// `speed_mt`: ±round(m·dt·2^(F−s)/t), saturated at 2^(N+F) − 1; 0 if m = 0 or t = 0.
pub fn speed_mt(
    format: BaselineFormat,
    m: u64,
    t: u64,
    cfg_dt: u64,
    negative: bool,
    mode_shift: u32,
) -> i64 {
    if m == 0 || t == 0 {
        return 0;
    }
    let e = format.frac_bits() - effective_shift(mode_shift);
    let x = u128::from(m) * u128::from(effective_dt(cfg_dt));
    signed(format, round_scaled(x, t.into(), e), negative)
}

/// Everything latched by one `start`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BaselineRequest {
    /// PC net steps of the window, N-bit two's complement.
    pub pc_count: i64,
    /// ET period, clock cycles (N bits, unsigned).
    pub et_period: u64,
    /// ET direction, 1 = reverse.
    pub et_negative: bool,
    /// A trustworthy ET period is available (else `speed_et` = 0).
    pub et_valid: bool,
    /// M/T steps m (N bits).
    pub mt_m: u64,
    /// M/T cycles t (N bits).
    pub mt_t: u64,
    /// M/T direction, 1 = reverse.
    pub mt_negative: bool,
    /// Window dt, clock cycles (N bits; 0 counts as 1).
    pub cfg_dt: u64,
    /// log2 of the decoding multiplier, 0..=3 (3 counts as 2).
    pub mode_shift: u32,
}

/// The three outputs of one computation (values in units of 2^−F ω_lim, not raw bits).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BaselineValues {
    /// `speed_pc`.
    pub pc: i64,
    /// `speed_et`.
    pub et: i64,
    /// `speed_mt`.
    pub mt: i64,
}

/// What the block outputs for `req` (exact rule of the module docs). Panics if an input
/// does not fit its port.
pub fn baseline_speeds(format: BaselineFormat, req: &BaselineRequest) -> BaselineValues {
    let max = format.counter_max();
    assert!(
        req.et_period <= max && req.mt_m <= max && req.mt_t <= max && req.cfg_dt <= max,
        "an unsigned input does not fit {} bits: {req:?}",
        format.counter_bits()
    );
    assert!(req.mode_shift <= 3, "mode_shift is 2 bits");
    BaselineValues {
        pc: speed_pc(format, req.pc_count, req.mode_shift),
        et: speed_et(
            format,
            req.et_period,
            req.cfg_dt,
            req.et_negative,
            req.et_valid,
            req.mode_shift,
        ),
        mt: speed_mt(
            format,
            req.mt_m,
            req.mt_t,
            req.cfg_dt,
            req.mt_negative,
            req.mode_shift,
        ),
    }
}

/// The hardware's multiplier on integers: m·dt by N shift-add steps, least significant bit
/// first, returned as the halves (A, Q) = (product >> N, product mod 2^N). Each step adds dt
/// to A if Q's bit 0 is set (an N-bit add with carry c) and shifts {c, A, Q} right by one.
pub fn shift_add_multiply(m: u64, dt: u64, counter_bits: u32) -> (u64, u64) {
    let n = counter_bits;
    let mask = (1u64 << n) - 1;
    assert!(m <= mask && dt <= mask, "operands must fit {n} bits");
    let (mut a, mut q) = (0u64, m);
    for _ in 0..n {
        let sum = if q & 1 == 1 { a + dt } else { a };
        q = (q >> 1) | ((sum & 1) << (n - 1));
        a = sum >> 1; // carry included: sum < 2^(N+1)
    }
    (a, q)
}

/// The hardware's divider and rounding on integers (see the module docs, steps 2 and 3):
/// round(X·2^(F−s)/den) with X = A·2^N + Q, saturated at 2^(N+F) − 1, for N = `counter_bits`
/// and F = `frac_bits` ≥ 2 (any widths, so tests can go exhaustive at small N). The S-bit
/// register `dq` starts with the N + 2 numerator bits at its top; each step shifts one
/// numerator bit out at the top and one quotient bit in at the bottom, so after S steps it
/// holds the quotient. Panics if `den` is 0 or does not fit N bits.
pub fn hardware_magnitude(
    a: u64,
    q: u64,
    den: u64,
    counter_bits: u32,
    frac_bits: u32,
    mode_shift: u32,
) -> u128 {
    let (n, f) = (counter_bits, frac_bits);
    let s = effective_shift(mode_shift);
    assert!(f >= MIN_FRAC_BITS && n + f < 64, "unsupported widths");
    let mask = (1u64 << n) - 1;
    assert!(den != 0 && den <= mask && a <= mask && q <= mask);
    let width = n + f + 1;
    let top = 1u128 << (width - 1);
    let max = (1u128 << (n + f)) - 1;
    let mut rem = u128::from(a >> s);
    let den = u128::from(den);
    if rem >= den {
        return max;
    }
    // Q at the top of dq, then shifted right by s with A's low bits entering at the top.
    let mut dq = u128::from(q) << (width - n);
    for k in 0..s {
        dq = (dq >> 1) | (u128::from((a >> k) & 1) << (width - 1));
    }
    for _ in 0..width {
        let b = u128::from(dq & top != 0);
        let trial = 2 * rem + b;
        let fits = trial >= den;
        rem = if fits { trial - den } else { trial };
        dq = ((dq << 1) & ((top << 1) - 1)) | u128::from(fits);
    }
    if dq == (top << 1) - 1 {
        max
    } else {
        (dq + 1) >> 1
    }
}

/// Inputs of the block during one clock cycle (sampled at its rising edge).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BaselineSpeedsInputs {
    /// Synchronous active-high reset (wins over `start`).
    pub reset: bool,
    /// Request a computation: latch `req`.
    pub start: bool,
    /// The data inputs.
    pub req: BaselineRequest,
}

/// Outputs of the block after a rising clock edge (all from registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BaselineSpeedsOutputs {
    /// A computation runs or a request is pending.
    pub busy: bool,
    /// One-cycle strobe: the three speeds were just written.
    pub valid: bool,
    /// The speeds (held).
    pub speeds: BaselineValues,
}

/// Cycle-by-cycle model of `hdl::BaselineSpeeds`: the request register and the fixed
/// schedule, with the results computed exactly by [`baseline_speeds`] (u128 arithmetic,
/// not the hardware algorithm), so a match with the hardware proves its datapath exact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BaselineSpeedsModel {
    format: BaselineFormat,
    timing: LatestRequest<BaselineRequest, BaselineValues>,
    out: BaselineSpeedsOutputs,
}

impl BaselineSpeedsModel {
    /// A block in its power-up state (equal to the state after reset).
    pub fn new(format: BaselineFormat) -> BaselineSpeedsModel {
        BaselineSpeedsModel {
            format,
            timing: LatestRequest::new(),
            out: BaselineSpeedsOutputs::default(),
        }
    }

    /// The format.
    pub fn format(&self) -> BaselineFormat {
        self.format
    }

    /// Outputs after the last edge.
    pub fn outputs(&self) -> BaselineSpeedsOutputs {
        self.out
    }

    /// One rising clock edge with `inp` applied; the outputs after it. Panics if an input
    /// does not fit its port (even without `start`: the ports are N wide).
    pub fn step(&mut self, inp: BaselineSpeedsInputs) -> BaselineSpeedsOutputs {
        // Checks the widths of the inputs.
        let _ = baseline_speeds(self.format, &inp.req);
        let mut out = BaselineSpeedsOutputs {
            valid: false,
            ..self.out
        };
        let format = self.format;
        let start = inp.start.then_some(inp.req);
        if let Some(result) = self
            .timing
            .edge(start, inp.reset, format.latency_cycles(), |r| {
                baseline_speeds(format, &r)
            })
        {
            out.speeds = result;
            out.valid = true;
        }
        if inp.reset {
            out = BaselineSpeedsOutputs::default();
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
        // 1 + S + 1 + S + 1 + 1 edges: S = 41 and S = 11.
        assert_eq!(latency_cycles(24, 16), 168);
        assert_eq!(latency_cycles(8, 2), 48);
        assert_eq!(effective_shift(3), 2);
        assert_eq!(effective_dt(0), 1);
    }

    #[test]
    fn pc_raw_round_trip() {
        let f = BaselineFormat::new(8, 4).unwrap();
        assert_eq!(f.pc_to_raw(-1), 255);
        assert_eq!(f.pc_range(), -128..=127);
    }
}
