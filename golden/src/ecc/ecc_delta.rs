// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::EccDelta<A, D>`: the eccentricity correction δ of a span between
//! two positions, in decoder steps, at fractional positions and with the exact phase of the
//! eccentricity. It supersedes the first corrector (whole-line phase m0, whole lines only).
//!
//! # What it computes
//! For a span from position x_a to x_b (lines, fractional), decoder shift s (x1: 0, x2: 1,
//! x4: 2; a position in steps is x·2^s):
//!
//! ```text
//! δ = 2^s · [ c·(S(x_b) − S(x_a)) + d·(C(x_b) − C(x_a)) ]   (decoder steps)
//! S(x) = sin(2πx/K), C(x) = cos(2πx/K), c = E·cos θ0, d = E·sin θ0, E = K·e/(2π) lines
//! ```
//!
//! This is the first-order correction of [`crate::eccentric::correct`]
//! (E·(S1\[m_b\] − S1\[m_a\]), S1\[m\] = sin(2πm/K + θ0), by sin(φ + θ0) = sin φ·cos θ0 +
//! cos φ·sin θ0) at any x and scaled to steps. The corrected count of a span of ΔM steps
//! is N_c = ΔM − δ. With c and d instead of (E, m0) the phase θ0 is exact (the first
//! corrector rounded it to a line: e·π/K = 36 ppm of ripple at K = 1024).
//!
//! # Ports and formats
//! | port | width | format |
//! |---|---|---|
//! | `start` | 1 | a request this cycle: latches the inputs below |
//! | `p_a`, `p_b` | 33 | span ends in half-steps, unsigned: h = x·2^(s+1), < K·2^(s+1) |
//! | `shift` | 2 | s; 3 is taken as 2 (like the core's `effective_shift`) |
//! | `coef_c`, `coef_d` | 32 | c, d: signed Q15.16 lines (value·2^16, two's complement) |
//! | `delta` | [`DELTA_BITS`] = 40 | δ·2^16: signed, [`DELTA_FRAC_BITS`] = 16 fractional bits (steps) |
//! | `valid` | 1 | one cycle: `delta` was just written |
//! | `busy` | 1 | a computation runs or a request is pending |
//!
//! Generation parameters: K (lines per revolution, a constructor argument, a multiple of 4
//! with 4 ≤ K ≤ 2^A), A (address bits, 2..=16) and D (table width, 8..=24; the integration
//! uses 24). [`check_params`] states the rules.
//!
//! A position h splits into line l = ⌊h/2^(s+1)⌋ (taken mod 2^A) and fraction
//! t = (h mod 2^(s+1))·2^(2−s) in eighths of a line (0..=7) ([`split_position`]): x = l + t/8.
//! Positions ≥ K·2^(s+1) are out of contract; they still give a defined result (the table's
//! A-bit address arithmetic, [`crate::ecc::sine_rom::sine_index`]).
//!
//! # Arithmetic (exact integer semantics, [`delta_raw`])
//! The table is [`crate::ecc::sine_rom::sine_table`] (K entries round(sin(2πi/K)·Q),
//! Q = 2^(D−1) − 1), read at (l + m0) mod K: sine at m0 = 0 and 1, cosine at m0 = K/4 and
//! K/4 + 1 (the reason K is a multiple of 4: cos(2πl/K) = sin(2π(l + K/4)/K) exactly).
//! 1. Interpolation, exact in integers (no rounding): T8(x) = 8·T\[l\] + t·(T\[l+1\] − T\[l\])
//!    ([`interpolate`]); |T8| ≤ 8Q.
//! 2. ΔS8 = S8(x_b) − S8(x_a), ΔC8 = C8(x_b) − C8(x_a): 28-bit signed (|·| ≤ 16Q < 2^27).
//! 3. P = 2^s·(coef_c·ΔS8 + coef_d·ΔC8) (a shift-add multiplier over the 28 bits of ΔS8,
//!    then of ΔC8, into a 63-bit accumulator).
//! 4. The table's scale is 1/Q, not 2^−(D−1): R = P + ⌊P/2^(D−1)⌋ (P·(1 + ε),
//!    ε = 2^−(D−1), the first two terms of 1/(1 − ε)).
//! 5. δ·2^16 = ⌊(R + 2^(D+1))/2^(D+2)⌋: R/2^(D+2) rounded to nearest, ties up (towards +∞).
//!
//! Since P/(8Q) = δ·2^16 exactly for exact tables, R/2^(D+2) is δ·2^16 up to the tiny
//! remainder of step 4.
//!
//! **Widths, proved.** |coef| ≤ 2^31, |ΔS8|, |ΔC8| ≤ 16Q < 2^(D+3), 2^s ≤ 4: |P| < 2^(D+37)
//! ≤ 2^61; |R| ≤ |P|·(1 + 2^−7) + 1 < 2^62 and |R + 2^(D+1)| < 2^62: 63 bits never wrap
//! ([`ACC_BITS`]). δ·2^16 < 2^62/2^(D+2) ≤ 2^52 in general and, with |P| < 2^(D+37),
//! |δ·2^16| ≤ 2^35·(1 + 2^−7) + 1 < 2^36: 37 bits suffice; [`DELTA_BITS`] = 40 never wraps.
//! Every partial sum of the multiplier is taken mod 2^63, so only the final value matters.
//!
//! # Timing (shared with the HDL block; [`EccDelta::step`])
//! * `start` sampled at a rising edge (reset low) decodes `p_a`, `p_b`, `shift` into
//!   (l, t) pairs and latches them with `coef_c`, `coef_d` into a one-deep request register
//!   and marks it pending. A start while busy is latched the same way: a newer start
//!   replaces a request that has not begun, so the **last** start is always computed.
//! * At the first edge at which no computation runs and a request is pending, the request
//!   is taken (copied into the job registers) and 67 steps follow: 8 table reads (one per
//!   cycle, one [`crate::ecc::sine_rom::SineRom`]; data one cycle later: steps 0..=8), 2 × 28
//!   multiplier steps (9..=64), the scale step (65) and the rounding step (66), which
//!   writes `delta` and raises `valid` for one cycle.
//! * A start sampled at edge k while idle gives `valid` after edge k + [`latency_cycles`]()
//!   = k + 68, whatever the operands and parameters. `busy` is high after edges k … k + 67
//!   and low in the `valid` cycle unless another request is pending; a pending request
//!   begins at the edge after `valid`, so back-to-back results are 68 edges apart. Starts at
//!   least 68 cycles apart are each computed; closer, a start can be replaced before it
//!   begins (never computed from mixed inputs).
//! * `delta` is a register, held until the next `valid`.
//! * `reset` (synchronous, active high) wins over `start`: `delta` 0, `valid` and `busy` 0,
//!   a computation in progress or pending is abandoned.
//!
//! # Error budget against f64 ([`error_budget`])
//! Reference: δ computed in f64 from the exact sin/cos at the fractional positions and the
//! exact register values c = coef_c/2^16, d = coef_d/2^16 ([`delta_f64`]). In steps:
//! * table, ½ LSB per entry: an interpolated value is a convex combination of two entries,
//!   so within 1/(2Q) of the interpolated sine: 2^s·(|c| + |d|)·2·1/(2Q);
//! * interpolation: V(x) = c·S(x) + d·C(x) = |E|·sin(…) with |E| = √(c² + d²), and
//!   |V − lerp V| ≤ t(1 − t)/2·max|V''| = t(1 − t)/2·|E|·(2π/K)² at each end (≤ |E|·(2π/K)²/8;
//!   zero at whole lines): 2^s·|E|·(2π/K)²·(t_a(1 − t_a) + t_b(1 − t_b))/2;
//! * scale and output rounding: ½ LSB plus (1 + |x|·ε²/(1 − ε)) units of 2^−(D+2) LSB
//!   (the floor in step 4 and the dropped ε² terms; x = δ·2^16, ε = 2^−(D−1)), LSB = 2^−16 step.
//!
//! At K = 1024, D = 24, e = 0.35/30 (|E| = 1.90 lines), x1: table 3.2e-7 lines, interpolation 0 at
//! whole lines (8.9e-6 lines per end at a half line), rounding 7.6e-6 steps.

use crate::ecc::sine_rom::{full_scale, sine_index, sine_table, MAX_ADDR_BITS};
use std::f64::consts::TAU;
use std::fmt;

/// Width of δ (signed two's complement).
pub const DELTA_BITS: u32 = 40;
/// Fractional bits of δ (δ is in units of 2^−16 decoder step).
pub const DELTA_FRAC_BITS: u32 = 16;
/// Width of `p_a`, `p_b` (half-steps).
pub const POS_BITS: u32 = 33;
/// Width of `coef_c`, `coef_d`.
pub const COEF_BITS: u32 = 32;
/// Fractional bits of `coef_c`, `coef_d` (Q15.16 lines).
pub const COEF_FRAC_BITS: u32 = 16;
/// Width of the interpolated differences ΔS8, ΔC8 (the multiplier operands).
pub const DIFF_BITS: u32 = 28;
/// Width of the accumulator P, R.
pub const ACC_BITS: u32 = 63;
/// Smallest table width D.
pub const MIN_DATA_BITS: u32 = 8;
/// Largest table width D (keeps |ΔS8| < 2^27 and |R| < 2^62).
pub const MAX_DATA_BITS: u32 = 24;
/// Steps of a computation after the request is taken: 8 reads (data in steps 1..=8),
/// 2 × 28 multiplier steps, the scale step and the rounding step.
pub const STEPS: u32 = 9 + 2 * DIFF_BITS + 2;

/// Edges from a `start` sampled while idle to the edge after which `valid` is high: one to
/// take the request, then [`STEPS`]. The same for every K, A, D and operand.
pub const fn latency_cycles() -> u32 {
    1 + STEPS
}

/// Why a parameter set is refused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum EccDeltaError {
    /// A outside 2..=16.
    AddrBits(u32),
    /// D outside 8..=24.
    DataBits(u32),
    /// K not a multiple of 4, or outside 4..=2^A.
    Lines { lines: u32, addr_bits: u32 },
}

impl fmt::Display for EccDeltaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::AddrBits(a) => write!(f, "EccDelta: A = {a} outside 2..={MAX_ADDR_BITS}"),
            Self::DataBits(d) => write!(
                f,
                "EccDelta: D = {d} outside {MIN_DATA_BITS}..={MAX_DATA_BITS}"
            ),
            Self::Lines { lines, addr_bits } => write!(
                f,
                "EccDelta: K = {lines} must be a multiple of 4 with 4 <= K <= 2^{addr_bits}"
            ),
        }
    }
}

impl std::error::Error for EccDeltaError {}

/// Checks the generation parameters: 2 ≤ A ≤ 16, 8 ≤ D ≤ 24, K a multiple of 4 with
/// 4 ≤ K ≤ 2^A.
pub fn check_params(lines: u32, addr_bits: u32, data_bits: u32) -> Result<(), EccDeltaError> {
    if !(2..=MAX_ADDR_BITS).contains(&addr_bits) {
        return Err(EccDeltaError::AddrBits(addr_bits));
    }
    if !(MIN_DATA_BITS..=MAX_DATA_BITS).contains(&data_bits) {
        return Err(EccDeltaError::DataBits(data_bits));
    }
    if lines < 4 || !lines.is_multiple_of(4) || u64::from(lines) > 1u64 << addr_bits {
        return Err(EccDeltaError::Lines { lines, addr_bits });
    }
    Ok(())
}

/// s = min(shift mod 4, 2).
pub fn effective_shift(shift: u32) -> u32 {
    (shift & 3).min(2)
}

/// (line l mod 2^A, fraction t in eighths of a line) of a position `h` in half-steps
/// (33 bits) at shift `shift`.
pub fn split_position(h: u64, shift: u32, addr_bits: u32) -> (u64, u32) {
    let s = effective_shift(shift);
    let h = h & ((1u64 << POS_BITS) - 1);
    let l = (h >> (s + 1)) & ((1u64 << addr_bits) - 1);
    let t = ((h & ((1u64 << (s + 1)) - 1)) << (2 - s)) as u32;
    (l, t)
}

/// 8·v0 + t·(v1 − v0): the table interpolated at t/8 between two entries, times 8, exact.
pub fn interpolate(v0: i64, v1: i64, t: u32) -> i64 {
    8 * v0 + i64::from(t) * (v1 - v0)
}

/// Coefficient registers (coef_c, coef_d) = round((E·cos θ0, E·sin θ0)·2^16), E = K·e/(2π)
/// lines (the first-order correction of [`crate::eccentric::correct::Correction::first_order`]).
/// Panics if they do not fit 32 bits.
pub fn coefficients(lines: u32, e: f64, theta0: f64) -> (i64, i64) {
    let big_e = f64::from(lines) * e / TAU;
    let q = |v: f64| {
        let r = (v * f64::from(1u32 << COEF_FRAC_BITS)).round();
        assert!(
            (-(2f64.powi(31))..2f64.powi(31)).contains(&r),
            "coefficient {v} lines does not fit Q15.16"
        );
        r as i64
    };
    (q(big_e * theta0.cos()), q(big_e * theta0.sin()))
}

/// One request: what `start` latches (raw port values).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Request {
    /// First span end, half-steps (33 bits).
    pub p_a: u64,
    /// Second span end, half-steps (33 bits).
    pub p_b: u64,
    /// Decoder shift (2 bits; 3 is taken as 2).
    pub shift: u32,
    /// c·2^16, signed 32 bits.
    pub coef_c: i64,
    /// d·2^16, signed 32 bits.
    pub coef_d: i64,
}

impl Request {
    fn check(&self) {
        let half = 1i64 << (COEF_BITS - 1);
        assert!(
            (-half..half).contains(&self.coef_c) && (-half..half).contains(&self.coef_d),
            "coefficients do not fit 32 bits: {self:?}"
        );
        assert!(
            self.p_a >> POS_BITS == 0 && self.p_b >> POS_BITS == 0 && self.shift < 4,
            "positions or shift do not fit their ports: {self:?}"
        );
    }
}

/// δ·2^16 of a request, straight from the definition in the module docs (step 1 to 5 in
/// wide integers); the cycle model [`EccDelta`] computes it with the hardware's sequence.
pub fn delta_raw(lines: u32, addr_bits: u32, data_bits: u32, req: &Request) -> i64 {
    check_params(lines, addr_bits, data_bits).unwrap_or_else(|e| panic!("{e}"));
    req.check();
    let table = sine_table(lines, addr_bits, data_bits);
    let s = effective_shift(req.shift);
    let k4 = u64::from(lines / 4);
    let at = |l: u64, m0: u64| table[sine_index(lines, addr_bits, l, m0) as usize];
    let (la, ta) = split_position(req.p_a, s, addr_bits);
    let (lb, tb) = split_position(req.p_b, s, addr_bits);
    let s8 = |l, t| interpolate(at(l, 0), at(l, 1), t);
    let c8 = |l, t| interpolate(at(l, k4), at(l, k4 + 1), t);
    let ds = i128::from(s8(lb, tb) - s8(la, ta));
    let dc = i128::from(c8(lb, tb) - c8(la, ta));
    let p = (i128::from(req.coef_c) * ds + i128::from(req.coef_d) * dc) << s;
    let r = p + (p >> (data_bits - 1));
    let out = (r + (1i128 << (data_bits + 1))) >> (data_bits + 2);
    debug_assert!(r.abs() < 1i128 << (ACC_BITS - 1));
    out as i64
}

/// δ (steps) in f64: exact sin/cos at the fractional positions of `req` (in contract:
/// positions < K·2^(s+1)) with the exact register values of c and d.
pub fn delta_f64(lines: u32, req: &Request) -> f64 {
    let s = effective_shift(req.shift);
    let k = f64::from(lines);
    let scale = f64::from(1u32 << (s + 1));
    let x = |h: u64| TAU * (h as f64 / scale) / k;
    let (xa, xb) = (x(req.p_a), x(req.p_b));
    let c = req.coef_c as f64 / f64::from(1u32 << COEF_FRAC_BITS);
    let d = req.coef_d as f64 / f64::from(1u32 << COEF_FRAC_BITS);
    f64::from(1u32 << s) * (c * (xb.sin() - xa.sin()) + d * (xb.cos() - xa.cos()))
}

/// The three terms of the error budget (steps) of one request (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget {
    /// Table, ½ LSB per entry.
    pub table: f64,
    /// Linear interpolation between lines.
    pub interpolation: f64,
    /// Scale remainder and output rounding.
    pub rounding: f64,
}

impl Budget {
    /// The sum (steps).
    pub fn total(&self) -> f64 {
        self.table + self.interpolation + self.rounding
    }
}

/// Worst-case |δ − δ_f64| (steps) for `req` ([`delta_f64`], module docs), term by term.
pub fn error_budget(lines: u32, data_bits: u32, req: &Request) -> Budget {
    let s = effective_shift(req.shift);
    let two_s = f64::from(1u32 << s);
    let one = f64::from(1u32 << COEF_FRAC_BITS);
    let (c, d) = (req.coef_c as f64 / one, req.coef_d as f64 / one);
    let q = full_scale(data_bits) as f64;
    let w = TAU / f64::from(lines);
    let tt = |h: u64| {
        let t = f64::from(split_position(h, s, 16).1) / 8.0;
        t * (1.0 - t)
    };
    let eps = 0.5f64.powi(data_bits as i32 - 1);
    let x_max = two_s * 2.0 * (c.abs() + d.abs()) * one * (1.0 + eps);
    let lsb = 1.0 / one;
    Budget {
        table: two_s * (c.abs() + d.abs()) / q,
        interpolation: two_s * c.hypot(d) * w * w * (tt(req.p_a) + tt(req.p_b)) / 2.0,
        rounding: lsb
            * (0.5 + (1.0 + x_max * eps * eps / (1.0 - eps)) / 2f64.powi(data_bits as i32 + 2)),
    }
}

/// The budget of the worst positions (t = ½ at both ends) for these coefficients and shift.
pub fn error_budget_max(
    lines: u32,
    data_bits: u32,
    shift: u32,
    coef_c: i64,
    coef_d: i64,
) -> Budget {
    let s = effective_shift(shift);
    let half = 1u64 << s; // t = ½
    error_budget(
        lines,
        data_bits,
        &Request {
            p_a: half,
            p_b: half,
            shift: s,
            coef_c,
            coef_d,
        },
    )
}

/// Inputs of an [`EccDelta`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Inputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// A request this cycle.
    pub start: bool,
    /// The request's ports (sampled only with `start`).
    pub req: Request,
}

/// Outputs of an [`EccDelta`] after a clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outputs {
    /// δ·2^16 (signed).
    pub delta: i64,
    /// `delta` was just written.
    pub valid: bool,
    /// A computation runs or a request is pending.
    pub busy: bool,
}

/// A decoded request, as the request and job registers hold it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Decoded {
    la: u64,
    ta: u32,
    lb: u64,
    tb: u32,
    s: u32,
    c: i64,
    d: i64,
}

fn wrap(v: i128, bits: u32) -> i128 {
    let sh = 128 - bits;
    (v << sh) >> sh
}

/// Cycle model of `hdl::EccDelta<A, D>` (module docs): the registers of the hardware and
/// its step sequence (shift-add multiplier in 63 bits), independent of [`delta_raw`], which
/// the tests compare it with.
#[derive(Clone, Debug)]
pub struct EccDelta {
    lines: u32,
    addr_bits: u32,
    data_bits: u32,
    table: Vec<i64>,
    rom: i64,
    pend: bool,
    req: Decoded,
    run: bool,
    k: u32,
    job: Decoded,
    v0: i64,
    acc_s: i128,
    acc_c: i128,
    acc: i128,
    mcand: i128,
    out: Outputs,
}

impl EccDelta {
    /// A block for K = `lines`, A = `addr_bits`, D = `data_bits`, after reset.
    ///
    /// # Panics
    /// On parameters refused by [`check_params`].
    pub fn new(lines: u32, addr_bits: u32, data_bits: u32) -> Self {
        check_params(lines, addr_bits, data_bits).unwrap_or_else(|e| panic!("{e}"));
        Self {
            lines,
            addr_bits,
            data_bits,
            table: sine_table(lines, addr_bits, data_bits),
            rom: 0,
            pend: false,
            req: Decoded::default(),
            run: false,
            k: 0,
            job: Decoded::default(),
            v0: 0,
            acc_s: 0,
            acc_c: 0,
            acc: 0,
            mcand: 0,
            out: Outputs::default(),
        }
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> Outputs {
        self.out
    }

    fn load(&self, coef: i64, s: u32) -> i128 {
        wrap(i128::from(coef) << s, ACC_BITS)
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: Inputs) -> Outputs {
        if inp.start {
            inp.req.check();
        }
        let (a, d) = (self.addr_bits, self.data_bits);
        let take = !self.run && self.pend;
        let mut valid = false;
        // The ROM address during this cycle (reads in steps 0..=7).
        let mut read = None;
        if self.run {
            let k = self.k;
            let j = self.job;
            if k < 8 {
                let l = if k < 4 { j.la } else { j.lb };
                let m0 = if k & 2 != 0 {
                    u64::from(self.lines / 4)
                } else {
                    0
                } + u64::from(k & 1);
                read = Some(sine_index(self.lines, a, l, m0));
            }
            match k {
                0 => {
                    self.acc = 0;
                    self.acc_s = 0;
                    self.acc_c = 0;
                    self.mcand = self.load(j.c, j.s);
                }
                1 | 3 | 5 | 7 => self.v0 = self.rom,
                2 | 4 | 6 | 8 => {
                    let t = if k <= 4 { j.ta } else { j.tb };
                    let v = i128::from(interpolate(self.v0, self.rom, t));
                    let target = if k == 2 || k == 6 {
                        &mut self.acc_s
                    } else {
                        &mut self.acc_c
                    };
                    *target = wrap(if k <= 4 { *target - v } else { *target + v }, DIFF_BITS);
                }
                9..=64 => {
                    let (i, x) = if k <= 36 {
                        (k - 9, &mut self.acc_s)
                    } else {
                        (k - 37, &mut self.acc_c)
                    };
                    let bit = *x & 1 == 1;
                    // Logical shift right in 28 bits: the bits of ΔS8 (ΔC8) LSB first.
                    *x = (*x & ((1 << DIFF_BITS) - 1)) >> 1;
                    if bit {
                        self.acc = if i == DIFF_BITS - 1 {
                            wrap(self.acc - self.mcand, ACC_BITS)
                        } else {
                            wrap(self.acc + self.mcand, ACC_BITS)
                        };
                    }
                    self.mcand = match k {
                        36 => self.load(j.d, j.s),
                        64 => 1i128 << (d + 1),
                        _ => wrap(self.mcand << 1, ACC_BITS),
                    };
                }
                65 => self.acc = wrap(self.acc + (self.acc >> (d - 1)), ACC_BITS),
                _ => {
                    self.acc = wrap(self.acc + self.mcand, ACC_BITS);
                    self.out.delta = wrap(self.acc >> (d + 2), DELTA_BITS) as i64;
                    valid = true;
                }
            }
            self.k += 1;
            if valid {
                self.run = false;
            }
        }
        if let Some(addr) = read {
            self.rom = self.table[addr as usize];
        }
        if take {
            self.job = self.req;
            self.run = true;
            self.k = 0;
            self.pend = false;
        }
        if inp.start {
            let s = effective_shift(inp.req.shift);
            let (la, ta) = split_position(inp.req.p_a, s, a);
            let (lb, tb) = split_position(inp.req.p_b, s, a);
            self.req = Decoded {
                la,
                ta,
                lb,
                tb,
                s,
                c: inp.req.coef_c,
                d: inp.req.coef_d,
            };
            self.pend = true;
        }
        self.out.valid = valid;
        if inp.reset {
            self.pend = false;
            self.run = false;
            self.k = 0;
            self.out = Outputs::default();
        }
        self.out.busy = self.run || self.pend;
        self.out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn params_are_checked() {
        assert!(check_params(1024, 10, 24).is_ok());
        assert!(check_params(1000, 10, 24).is_ok());
        assert!(check_params(4, 2, 8).is_ok());
        assert!(check_params(1026, 11, 24).is_err());
        assert!(check_params(2048, 10, 24).is_err());
        assert!(check_params(1024, 10, 25).is_err());
        assert!(check_params(1024, 17, 24).is_err());
        assert!(check_params(0, 10, 24).is_err());
    }

    #[test]
    fn positions_split_into_line_and_eighths() {
        assert_eq!(split_position(2 * 5 + 1, 0, 10), (5, 4));
        assert_eq!(split_position(4 * 5 + 3, 1, 10), (5, 6));
        assert_eq!(split_position(8 * 5 + 7, 2, 10), (5, 7));
        assert_eq!(split_position(8 * 5 + 7, 3, 10), (5, 7));
        assert_eq!(split_position(8 * 1025, 2, 10), (1, 0));
    }
}
