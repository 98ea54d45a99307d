// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::ecc::ecc_mt_speed::EccMtSpeed`: the M/T speed of an
//! eccentricity-corrected step count (issue 4). The M/T counter ([`crate::baselines::mt_counter`])
//! measures m steps in t clock cycles; `EccDelta` ([`crate::ecc::ecc_delta`]) gives δ, the
//! eccentricity correction of the same span in steps; the block divides the corrected count
//! N_c = m − δ instead of m by the time (docs/eccentricity.md §5).
//!
//! # Value
//!
//! Units of ω_lim = one encoder **line** per dt (dt = `cfg_dt` clock cycles), as `speed_mt`
//! of [`crate::baselines::baseline_speeds`]. With s = [`effective_shift`]`(mode_shift)` (0, 1, 2; 3
//! counts as 2), dt = [`effective_dt`]`(cfg_dt)` (0 counts as 1) and δ = D·2^−16 steps (D the
//! raw [`DELTA_BITS`]-bit two's-complement input with [`DELTA_FRAC_BITS`] fractional bits),
//! the exact value in units of 2^−F ω_lim is
//!
//! ```text
//! speed_mtc = ±(m − δ)·dt·2^(F−s)/t  =  ±c·dt·2^(F−s) / (t·2^16),   c = m·2^16 − D
//! ```
//!
//! − when `negative` is 1. [`speed_mtc`] computes it in u128/i128 integers; that is the
//! definition. With δ = 0 it is exactly [`crate::baselines::baseline_speeds::speed_mt`].
//!
//! # Format, rounding and corner cases
//!
//! The format of `speed_mt`: signed two's complement Q(N).F in S = N + F + 1 bits, the value
//! is `raw · 2^−F` ω_lim ([`BaselineFormat`]: N = 8..=32, F = 2..=24). The magnitude is the
//! exact value rounded to the nearest integer, ties away from zero, ⌊x + ½⌋; the sign is
//! applied afterwards (forward and reverse are mirror images, zero is always 0). Error
//! ≤ ½ LSB = 2^−(F+1) ω_lim wherever the result is not saturated or zeroed.
//!
//! * m = 0 or t = 0: **0** (as `speed_mt`: m = 0 is a decay bound, not an estimate), whatever
//!   δ.
//! * c = m·2^16 − D ≤ 0, i.e. δ ≥ m (possible only with absurd coefficients, |δ| is a few
//!   steps at most): **0**.
//! * Magnitude above 2^(N+F) − 1 (possible when m − δ > t, e.g. δ very negative, or m > t):
//!   **saturates** at ±(2^(N+F) − 1), never wraps. The ½-LSB bound does not hold there.
//!
//! # Hardware algorithm
//!
//! The `hardware_*` functions restate, on integers and for any widths
//! ([`EccWidths`]: N, F, and the width d and fractional bits g of δ, so the tests can go
//! exhaustive at small widths), what the block does; the tests prove
//! [`hardware_speed`] = [`exact_speed`] (the general form of [`speed_mtc`]).
//!
//! 1. **Start** ([`hardware_request`]): c = m·2^g − D in C bits, C = [`corrected_bits`]
//!    (N, d, g) = the width of the largest c, (2^N − 1)·2^g + 2^(d−1) (41 for N = 24, 40
//!    for N ≤ 23, 49 for N = 32). D is sign-extended to C bits, the subtraction wraps, and is
//!    exact whenever c > 0; c ≤ 0 is detected as "D ≥ 0 and m·2^g ≤ D": the borrow of the
//!    same C-bit subtraction (from the top bits of operands and difference) or a zero
//!    difference. The request register keeps c, dt (0 replaced by 1), t, the sign, s and a
//!    zero flag (m = 0, t = 0 or c ≤ 0).
//! 2. **Multiply** ([`hardware_multiply`]): P = c·dt by N shift-add steps, least
//!    significant bit first: Q = dt (N bits) is the multiplier, A (C bits) accumulates c, each
//!    step adds c to A when Q's bit 0 is set and shifts {carry, A, Q} right by one. After N
//!    steps P = A·2^N + Q.
//! 3. **Divide** ([`hardware_divide`]): q = ⌊c·dt·2^(F+1−s)/(t·2^g)⌋ = ⌊Y/t⌋ with
//!    Y = ⌊P·2^(F+1−s−g)⌋, by restoring long division of S steps. The partial remainder is
//!    preloaded with Y >> S = P >> (N + g + s) = A >> (g + s), independent of F; if that is
//!    not below t, q ≥ 2^S: saturate. Else the S-bit register `dq` starts with the bits of P
//!    below that (A's low g + s bits, then Q), top-aligned: the bits that do not fit fall
//!    off (⌊⌊P/2^j⌋/t⌋ = ⌊P/(2^j·t)⌋), missing ones are zeros. Each step brings down its top
//!    bit and shifts in one quotient bit; after S steps `dq` = q.
//! 4. **Round and sign** ([`hardware_round_sign`]): ⌊x + ½⌋ = (q + 1) >> 1 for q = ⌊2x⌋;
//!    q = 2^S − 1 (which would round to 2^(N+F)) and a saturating preload give 2^(N+F) − 1;
//!    the zero flag gives 0. With h = q >> 1 and r = q & 1 one S-bit adder gives
//!    (h, or !h if negative) + (r xor negative).
//!
//! # Timing (shared with the HDL block)
//!
//! As [`crate::baselines::baseline_speeds`]: `start` latches every input into a one-deep request
//! register and marks it pending; a start while busy replaces a request that has not begun,
//! so the **last** start's values are always computed. At the first edge at which the block
//! is idle and a request is pending it takes the request; [`latency_cycles`]`(N, F)` =
//! N + S + 3 = 2N + F + 4 edges after a start edge (block idle) `speed_mtc` changes and
//! `valid` is high for one cycle (one edge takes the request, N multiply steps, one edge
//! loads the divider, S divide steps, one edge publishes: 68 for N = 24, F = 16). `busy` is
//! high while a computation runs or a request is pending. `reset` (synchronous, active high)
//! wins over `start`: output 0, `valid` and `busy` 0, any computation or request abandoned.

use crate::arith::latest_request::LatestRequest;
use crate::baselines::baseline_speeds::BaselineFormat;
pub use crate::baselines::baseline_speeds::{effective_dt, effective_shift};
use crate::ecc::ecc_delta::{DELTA_BITS, DELTA_FRAC_BITS};

/// Width C of the corrected count c = m·2^g − D for N-bit m and a d-bit δ with g fractional
/// bits: the bit length of its largest value (2^N − 1)·2^g + 2^(d−1).
pub const fn corrected_bits_for(counter_bits: u32, delta_bits: u32, delta_frac_bits: u32) -> u32 {
    let max = (((1u128 << counter_bits) - 1) << delta_frac_bits) + (1u128 << (delta_bits - 1));
    128 - max.leading_zeros()
}

/// Width C of the corrected count of the block for counter width N (δ of [`DELTA_BITS`]
/// bits, [`DELTA_FRAC_BITS`] fractional): 40 for N ≤ 23, N + 17 above.
pub const fn corrected_bits(counter_bits: u32) -> u32 {
    corrected_bits_for(counter_bits, DELTA_BITS, DELTA_FRAC_BITS)
}

/// Clock edges from the edge that samples a `start` (block idle) to the edge after which
/// `valid` is high: N + S + 3 = 2N + F + 4 (take, N multiply steps, divider set-up, S divide
/// steps, publish).
pub const fn latency_cycles(counter_bits: u32, frac_bits: u32) -> u32 {
    2 * counter_bits + frac_bits + 4
}

/// Widths of the algorithm: N, F, and δ's width d and fractional bits g. The block uses
/// [`EccWidths::of`]; the tests also use small ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EccWidths {
    /// N: width of m, t and `cfg_dt`.
    pub counter_bits: u32,
    /// F: fractional bits of the speed.
    pub frac_bits: u32,
    /// d: width of δ (two's complement).
    pub delta_bits: u32,
    /// g: fractional bits of δ.
    pub delta_frac_bits: u32,
}

impl EccWidths {
    /// The block's widths for `format`: δ of [`DELTA_BITS`] bits, [`DELTA_FRAC_BITS`]
    /// fractional.
    pub fn of(format: BaselineFormat) -> EccWidths {
        EccWidths::new(
            format.counter_bits(),
            format.frac_bits(),
            DELTA_BITS,
            DELTA_FRAC_BITS,
        )
    }

    /// Any widths the integer restatements can hold: N ≥ 1, d ≥ g + 1 (δ has an integer
    /// bit), C ≤ 63, S ≤ 63. Panics otherwise.
    pub fn new(counter_bits: u32, frac_bits: u32, delta_bits: u32, delta_frac_bits: u32) -> Self {
        let w = EccWidths {
            counter_bits,
            frac_bits,
            delta_bits,
            delta_frac_bits,
        };
        assert!(
            counter_bits >= 1 && delta_bits > delta_frac_bits && delta_bits <= 63,
            "unsupported widths {w:?}"
        );
        assert!(
            w.corrected_bits() <= 63 && w.speed_bits() <= 63,
            "unsupported widths {w:?}"
        );
        w
    }

    /// C: width of the corrected count ([`corrected_bits_for`]).
    pub fn corrected_bits(&self) -> u32 {
        corrected_bits_for(self.counter_bits, self.delta_bits, self.delta_frac_bits)
    }

    /// S = N + F + 1: width of the speed.
    pub fn speed_bits(&self) -> u32 {
        self.counter_bits + self.frac_bits + 1
    }

    /// 2^(N+F) − 1: the largest magnitude.
    pub fn max_magnitude(&self) -> u128 {
        (1u128 << (self.counter_bits + self.frac_bits)) - 1
    }

    /// 2^N − 1: the largest m, t and `cfg_dt`.
    pub fn counter_max(&self) -> u64 {
        (1u64 << self.counter_bits) - 1
    }

    /// The range of D (δ in units of 2^−g step): −2^(d−1)..=2^(d−1) − 1.
    pub fn delta_range(&self) -> std::ops::RangeInclusive<i64> {
        let half = 1i64 << (self.delta_bits - 1);
        -half..=half - 1
    }

    /// D as the raw bits of its d-bit port.
    pub fn delta_to_raw(&self, delta: i64) -> u64 {
        (delta as u64) & ((1u64 << self.delta_bits) - 1)
    }

    /// The raw bits of the d-bit δ port as a signed D.
    pub fn delta_from_raw(&self, raw: u64) -> i64 {
        let sh = 64 - self.delta_bits;
        ((raw << sh) as i64) >> sh
    }

    fn check(&self, m: u64, t: u64, cfg_dt: u64, delta: i64, mode_shift: u32) {
        let max = self.counter_max();
        assert!(
            m <= max && t <= max && cfg_dt <= max,
            "m = {m}, t = {t} or cfg_dt = {cfg_dt} does not fit {} bits",
            self.counter_bits
        );
        assert!(
            self.delta_range().contains(&delta),
            "delta = {delta} does not fit {} bits",
            self.delta_bits
        );
        assert!(mode_shift <= 3, "mode_shift is 2 bits");
    }
}

/// The exact rule (the definition) for any [`EccWidths`]: ±round(c·dt·2^(F−s)/(t·2^g)) with
/// c = m·2^g − D, ties away from zero, saturated at 2^(N+F) − 1; 0 if m = 0, t = 0 or c ≤ 0.
/// Integers only (u128/i128). Panics if an input does not fit its port.
pub fn exact_speed(
    w: EccWidths,
    m: u64,
    t: u64,
    cfg_dt: u64,
    delta: i64,
    negative: bool,
    mode_shift: u32,
) -> i64 {
    w.check(m, t, cfg_dt, delta, mode_shift);
    if m == 0 || t == 0 {
        return 0;
    }
    let c = (i128::from(m) << w.delta_frac_bits) - i128::from(delta);
    if c <= 0 {
        return 0;
    }
    let s = effective_shift(mode_shift);
    // round(num/den) = ⌊(2·num + den)/(2·den)⌋ with num = c·dt·2^F, den = t·2^(g+s).
    let num = (c as u128 * u128::from(effective_dt(cfg_dt))) << w.frac_bits;
    let den = u128::from(t) << (w.delta_frac_bits + s);
    let magnitude = ((2 * num + den) / (2 * den)).min(w.max_magnitude()) as i64;
    if negative {
        -magnitude
    } else {
        magnitude
    }
}

/// `speed_mtc` of the block (module docs): [`exact_speed`] with δ = `delta`·2^−16 steps
/// ([`DELTA_BITS`]-bit D). With `delta` = 0 it equals
/// [`crate::baselines::baseline_speeds::speed_mt`].
pub fn speed_mtc(
    format: BaselineFormat,
    m: u64,
    t: u64,
    cfg_dt: u64,
    delta: i64,
    negative: bool,
    mode_shift: u32,
) -> i64 {
    exact_speed(
        EccWidths::of(format),
        m,
        t,
        cfg_dt,
        delta,
        negative,
        mode_shift,
    )
}

/// What the block's request register holds after a start (algorithm step 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HardwareRequest {
    /// c = m·2^g − D modulo 2^C (exact when `zero` is false).
    pub corrected: u64,
    /// dt with 0 replaced by 1.
    pub dt: u64,
    /// The result is 0: m = 0, t = 0 or c ≤ 0.
    pub zero: bool,
}

/// Step 1 on integers, as the hardware does it: c in C-bit wrapping arithmetic from D
/// sign-extended, c ≤ 0 from the subtraction's borrow and a zero test. `delta_raw` is the raw d-bit port.
pub fn hardware_request(
    w: EccWidths,
    m: u64,
    t: u64,
    cfg_dt: u64,
    delta_raw: u64,
) -> HardwareRequest {
    let c_bits = w.corrected_bits();
    let c_mask = (1u64 << c_bits) - 1;
    assert!(delta_raw < (1u64 << w.delta_bits), "delta_raw is d bits");
    let m_g = m << w.delta_frac_bits;
    let d_negative = (delta_raw >> (w.delta_bits - 1)) & 1 == 1;
    // Sign extension: the d bits, then copies of the sign bit up to C.
    let d_ext = if d_negative {
        delta_raw | (c_mask & !((1u64 << w.delta_bits) - 1))
    } else {
        delta_raw
    };
    let corrected = m_g.wrapping_sub(d_ext) & c_mask;
    // The borrow of the C-bit subtraction, from the top bits of operands and difference.
    let top = |x: u64| (x >> (c_bits - 1)) & 1 == 1;
    let borrow = (!top(m_g) && top(d_ext)) || (top(m_g) == top(d_ext) && top(corrected));
    let non_positive = !d_negative && (borrow || corrected == 0);
    HardwareRequest {
        corrected,
        dt: effective_dt(cfg_dt),
        zero: m == 0 || t == 0 || non_positive,
    }
}

/// Step 2 on integers: c·dt by N shift-add steps, least significant bit first, returned as
/// (A, Q) = (product >> N, product mod 2^N), A of C bits. Each step adds c to A if Q's bit 0
/// is set (a C-bit add with carry) and shifts {carry, A, Q} right by one.
pub fn hardware_multiply(w: EccWidths, corrected: u64, dt: u64) -> (u64, u64) {
    let (n, c_bits) = (w.counter_bits, w.corrected_bits());
    assert!(corrected < (1u64 << c_bits) && dt <= w.counter_max());
    let (mut a, mut q) = (0u64, dt);
    for _ in 0..n {
        let sum = if q & 1 == 1 { a + corrected } else { a };
        q = (q >> 1) | ((sum & 1) << (n - 1));
        a = sum >> 1; // carry included: sum < 2^(C+1)
    }
    (a, q)
}

/// Step 3 on integers: the S-bit quotient `dq` = ⌊(A·2^N + Q)·2^(F+1−s)/(t·2^g)⌋ of the
/// preloaded restoring division, and whether the preload A >> (g + s) was not below t
/// (quotient ≥ 2^S: saturate; `dq` is then meaningless and returned as 0). `t` ≥ 1.
pub fn hardware_divide(w: EccWidths, a: u64, q: u64, t: u64, mode_shift: u32) -> (u64, bool) {
    let (n, g) = (w.counter_bits, w.delta_frac_bits);
    let s = effective_shift(mode_shift);
    let width = w.speed_bits();
    assert!(t >= 1 && t <= w.counter_max() && q <= w.counter_max());
    assert!(a < (1u64 << w.corrected_bits()));
    let pre = a >> (g + s);
    if pre >= t {
        return (0, true);
    }
    let top = 1u128 << (width - 1);
    let mask = (top << 1) - 1;
    // Q's N bits shifted in at the top, then A's bits 0 .. g + s − 1: the bits below the
    // preload, top-aligned; what does not fit falls off the bottom.
    let mut dq = 0u128;
    let bits = (0..n)
        .map(|i| (q >> i) & 1)
        .chain((0..g + s).map(|i| (a >> i) & 1));
    for b in bits {
        dq = (dq >> 1) | (u128::from(b) * top);
    }
    let mut rem = u128::from(pre);
    let den = u128::from(t);
    for _ in 0..width {
        let trial = 2 * rem + u128::from(dq & top != 0);
        let fits = trial >= den;
        rem = if fits { trial - den } else { trial };
        dq = ((dq << 1) & mask) | u128::from(fits);
    }
    (dq as u64, false)
}

/// Step 4 on integers: the raw S-bit output from the quotient, as the hardware's one adder
/// forms it: h = q >> 1, r = q & 1 (dropped when q is all ones); saturation: h = 2^(N+F) − 1,
/// r = 0; zero: h = 0, r = 0; raw = (h, or !h if negative) + (r xor negative) mod 2^S.
pub fn hardware_round_sign(
    w: EccWidths,
    dq: u64,
    saturate: bool,
    zero: bool,
    negative: bool,
) -> u64 {
    let width = w.speed_bits();
    let mask = (1u64 << width) - 1;
    let (mut h, mut r) = (dq >> 1, (dq & 1 == 1) && dq != mask);
    if saturate {
        (h, r) = (w.max_magnitude() as u64, false);
    }
    if zero {
        (h, r) = (0, false);
    }
    let addend = if negative { !h & mask } else { h };
    (addend + u64::from(r ^ negative)) & mask
}

/// Steps 1–4: the block's output as a signed value, by the hardware's algorithm.
pub fn hardware_speed(
    w: EccWidths,
    m: u64,
    t: u64,
    cfg_dt: u64,
    delta: i64,
    negative: bool,
    mode_shift: u32,
) -> i64 {
    w.check(m, t, cfg_dt, delta, mode_shift);
    let req = hardware_request(w, m, t, cfg_dt, w.delta_to_raw(delta));
    let (a, q) = hardware_multiply(w, req.corrected, req.dt);
    // The divider runs whatever the flags say; t = 0 only with the zero flag set.
    let (dq, saturate) = if t == 0 {
        (0, false)
    } else {
        hardware_divide(w, a, q, t, mode_shift)
    };
    let raw = hardware_round_sign(w, dq, saturate, req.zero, negative);
    let sh = 64 - w.speed_bits();
    ((raw << sh) as i64) >> sh
}

/// Everything latched by one `start`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccMtRequest {
    /// M/T steps m (N bits, unsigned).
    pub mt_m: u64,
    /// M/T clock cycles t (N bits, unsigned).
    pub mt_t: u64,
    /// M/T direction, 1 = reverse.
    pub mt_negative: bool,
    /// Window dt, clock cycles (N bits; 0 counts as 1).
    pub cfg_dt: u64,
    /// log2 of the decoding multiplier, 0..=3 (3 counts as 2).
    pub mode_shift: u32,
    /// D: δ in units of 2^−16 step, [`DELTA_BITS`]-bit two's complement.
    pub ecc_delta: i64,
}

/// Inputs of the block during one clock cycle (sampled at its rising edge).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccMtSpeedInputs {
    /// Synchronous active-high reset (wins over `start`).
    pub reset: bool,
    /// Request a computation: latch `req`.
    pub start: bool,
    /// The data inputs.
    pub req: EccMtRequest,
}

/// Outputs of the block after a rising clock edge (all from registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccMtSpeedOutputs {
    /// A computation runs or a request is pending.
    pub busy: bool,
    /// One-cycle strobe: `speed_mtc` was just written.
    pub valid: bool,
    /// `speed_mtc` (units of 2^−F ω_lim, held).
    pub speed_mtc: i64,
}

/// What the block outputs for `req` ([`speed_mtc`]). Panics if an input does not fit its
/// port.
pub fn ecc_mt_speed(format: BaselineFormat, req: &EccMtRequest) -> i64 {
    speed_mtc(
        format,
        req.mt_m,
        req.mt_t,
        req.cfg_dt,
        req.ecc_delta,
        req.mt_negative,
        req.mode_shift,
    )
}

/// Cycle-by-cycle model of `hdl::ecc::ecc_mt_speed::EccMtSpeed`: the request register and the
/// fixed schedule, with the result computed by the exact rule [`speed_mtc`] (not the
/// hardware algorithm), so a match with the hardware proves its datapath exact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EccMtSpeedModel {
    format: BaselineFormat,
    timing: LatestRequest<EccMtRequest, i64>,
    out: EccMtSpeedOutputs,
}

impl EccMtSpeedModel {
    /// A block in its power-up state (equal to the state after reset).
    pub fn new(format: BaselineFormat) -> EccMtSpeedModel {
        EccMtSpeedModel {
            format,
            timing: LatestRequest::new(),
            out: EccMtSpeedOutputs::default(),
        }
    }

    /// The format.
    pub fn format(&self) -> BaselineFormat {
        self.format
    }

    /// [`latency_cycles`] of the format.
    pub fn latency_cycles(&self) -> u32 {
        latency_cycles(self.format.counter_bits(), self.format.frac_bits())
    }

    /// Outputs after the last edge.
    pub fn outputs(&self) -> EccMtSpeedOutputs {
        self.out
    }

    /// One rising clock edge with `inp` applied; the outputs after it. Panics if an input
    /// does not fit its port (even without `start`).
    pub fn step(&mut self, inp: EccMtSpeedInputs) -> EccMtSpeedOutputs {
        // Checks the widths of the inputs.
        let _ = ecc_mt_speed(self.format, &inp.req);
        let mut out = EccMtSpeedOutputs {
            valid: false,
            ..self.out
        };
        let (format, latency) = (self.format, self.latency_cycles());
        let start = inp.start.then_some(inp.req);
        if let Some(result) = self
            .timing
            .edge(start, inp.reset, latency, |r| ecc_mt_speed(format, &r))
        {
            out.speed_mtc = result;
            out.valid = true;
        }
        if inp.reset {
            out = EccMtSpeedOutputs::default();
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
        assert_eq!(corrected_bits(8), 40);
        assert_eq!(corrected_bits(23), 40);
        assert_eq!(corrected_bits(24), 41);
        assert_eq!(corrected_bits(32), 49);
        assert_eq!(latency_cycles(24, 16), 68);
        let w = EccWidths::new(3, 2, 6, 2);
        assert_eq!(w.corrected_bits(), 6);
        assert_eq!(w.delta_from_raw(w.delta_to_raw(-32)), -32);
    }
}
