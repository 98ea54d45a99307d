// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of the identification gatherer `hdl::IdentGatherer<A, T, W>`: between two
//! index (Z) pulses after `arm`, it gathers what both identifications of
//! [`crate::eccentric::identify`] need, and [`identify_from_sums`] turns the sums into e and
//! θ0 (the [`harmonic_fit`](crate::eccentric::identify::harmonic_fit) of the first harmonic,
//! computed from the sums alone).
//!
//! # Inputs (sampled at each rising clock edge)
//! `arm`, `index` (1-cycle pulse at the Z edge), `line` (1-cycle pulse at each line edge of
//! one direction), `position` (A bits: the line number 0..K − 1 of this edge) and `period`
//! (T bits, unsigned: clock cycles since the previous line edge, from an ET-type timer).
//! Between two Z pulses the line edges have positions 1, 2, …, K − 1, 0: the edge at
//! position p closes `periods[(p − 1) mod K]` of
//! [`revolution_periods`](crate::eccentric::identify::revolution_periods).
//!
//! # Results
//! | output | width | meaning |
//! |---|---|---|
//! | `count` | 17 | lines gathered N (≤ 2^A ≤ 2^16) |
//! | `t_min`, `t_max` | T | shortest / longest period (first occurrence on ties) |
//! | `p_min`, `p_max` | A | position of the line edge that closed it (paper's k2, k1 mod K) |
//! | `sum_t` | W | Σ T_i, unsigned |
//! | `sum_sin` | W | Σ T_i·S\[p_i\], signed, S\[p\] = round(Q·sin(2πp/K)), Q = 2^23 − 1 |
//! | `sum_cos` | W | Σ T_i·S\[(p_i + K/4) mod K\] = Σ T_i·round(Q·cos(2πp_i/K)), signed |
//! | `overflow` | 1 | a line arrived with N = 2^A already gathered (contract broken): dropped |
//! | `done` | 1 | the results are complete; sticky until the next `arm` |
//!
//! Widths: W = A + T + 24. Σ T_i < 2^A·2^T needs A + T bits; |T_i·S| < 2^T·2^23, so
//! |Σ T_i·S| < 2^(A + T + 23) needs A + T + 24 signed bits. No line beyond the 2^A-th is
//! accumulated (it sets `overflow` instead), so no sum can wrap whatever the inputs.
//! K must be a multiple of 4 (4 ≤ K ≤ 2^A, 2 ≤ A ≤ 16, 1 ≤ T ≤ 40) so that cos is the
//! same table read at m0 = K/4 (a second [`SineRom`], same contents).
//!
//! # Semantics (per rising clock edge, in this order)
//! 1. Stage 2, from the registers before the edge: if a line is pending, then if N = 2^A
//!    `overflow` ← 1, else N ← N + 1, the sums take T·S and T·C (S, C: the two ROM
//!    outputs), and T_min/T_max (with their positions) take T if N was 0 or T is strictly
//!    smaller/greater. If `fin` was set, `done` ← 1.
//! 2. Stage 1: pending ← `line` ∧ (state = GATHER); the period and position are
//!    registered; both ROMs read (position, 0) and (position, K/4); `fin` ← 0.
//! 3. Control: if `arm`: state ← ARMED, `done` ← 0 (an index in the same cycle is not the
//!    "next" one). Else if `index`: in ARMED, state ← GATHER and all results are cleared
//!    (N, sums, extremes, `overflow`; this wins over stage 1's accumulation); in GATHER,
//!    state ← IDLE and `fin` ← 1 (a line in the same cycle as the closing index is still
//!    gathered: it is the Z line). Results hold until the next gathering starts.
//! 4. `reset` (synchronous, active high) clears every register but the ROM outputs.
//!
//! Latency: a line sampled at edge j is in the results after edge j + 1; a closing index
//! sampled at edge j raises `done` after edge j + 1, with the last line in. A line may come
//! every cycle: the minimum line period is 1 clock cycle.

use crate::ecc::sine_rom::{full_scale, SineRom};
use crate::eccentric::identify::{rigid_e_from_first_harmonic, Identified};
use crate::eccentric::Model;
use std::f64::consts::{PI, TAU};

/// Width of the table entries.
pub const S_BITS: u32 = 24;
/// Width of `count`.
pub const COUNT_BITS: u32 = 17;

/// Accumulator width W = A + T + 24 (module docs).
pub const fn sum_bits(addr_bits: u32, period_bits: u32) -> u32 {
    addr_bits + period_bits + S_BITS
}

/// Inputs during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GatherInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Start gathering at the next index.
    pub arm: bool,
    /// Z pulse.
    pub index: bool,
    /// Line edge.
    pub line: bool,
    /// Position of this line edge (A bits).
    pub position: u64,
    /// Cycles since the previous line edge (T bits).
    pub period: u64,
}

/// Registered outputs after an edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct GatherOutputs {
    /// Results complete (sticky until `arm`).
    pub done: bool,
    /// More than 2^A lines between the Z pulses.
    pub overflow: bool,
    /// Lines gathered.
    pub count: u64,
    /// Shortest period.
    pub t_min: u64,
    /// Its position.
    pub p_min: u64,
    /// Longest period.
    pub t_max: u64,
    /// Its position.
    pub p_max: u64,
    /// Σ T.
    pub sum_t: i128,
    /// Σ T·S.
    pub sum_sin: i128,
    /// Σ T·C.
    pub sum_cos: i128,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum State {
    Idle,
    Armed,
    Gather,
}

/// The gatherer, bit-true model of `hdl::IdentGatherer<A, T, W>` (module docs).
#[derive(Clone, Debug)]
pub struct IdentGatherer {
    addr_bits: u32,
    period_bits: u32,
    quarter: u64,
    rom_s: SineRom,
    rom_c: SineRom,
    state: State,
    fin: bool,
    pend: bool,
    t_reg: u64,
    p_reg: u64,
    out: GatherOutputs,
}

impl IdentGatherer {
    /// A gatherer for K = `lines`, A = `addr_bits`, T = `period_bits`, after reset.
    pub fn new(lines: u32, addr_bits: u32, period_bits: u32) -> Self {
        assert!(
            (2..=16).contains(&addr_bits),
            "A = {addr_bits} outside 2..=16"
        );
        assert!(
            (1..=40).contains(&period_bits),
            "T = {period_bits} outside 1..=40"
        );
        assert!(
            lines >= 4 && lines.is_multiple_of(4) && u64::from(lines) <= 1 << addr_bits,
            "K = {lines}: need a multiple of 4 in 4..=2^A"
        );
        Self {
            addr_bits,
            period_bits,
            quarter: u64::from(lines / 4),
            rom_s: SineRom::new(lines, addr_bits, S_BITS),
            rom_c: SineRom::new(lines, addr_bits, S_BITS),
            state: State::Idle,
            fin: false,
            pend: false,
            t_reg: 0,
            p_reg: 0,
            out: GatherOutputs::default(),
        }
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> GatherOutputs {
        self.out
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: GatherInputs) -> GatherOutputs {
        let amask = (1u64 << self.addr_bits) - 1;
        let tmask = (1u64 << self.period_bits) - 1;
        assert_eq!(inp.position & !amask, 0, "position does not fit A bits");
        assert_eq!(inp.period & !tmask, 0, "period does not fit T bits");
        // 1. Stage 2.
        let o = &mut self.out;
        if self.pend {
            if o.count == 1 << self.addr_bits {
                o.overflow = true;
            } else {
                let t = self.t_reg;
                if o.count == 0 || t < o.t_min {
                    o.t_min = t;
                    o.p_min = self.p_reg;
                }
                if o.count == 0 || t > o.t_max {
                    o.t_max = t;
                    o.p_max = self.p_reg;
                }
                o.count += 1;
                let ti = i128::from(t);
                o.sum_t += ti;
                o.sum_sin += ti * i128::from(self.rom_s.data());
                o.sum_cos += ti * i128::from(self.rom_c.data());
            }
        }
        if self.fin {
            o.done = true;
        }
        // 2. Stage 1.
        self.pend = inp.line && self.state == State::Gather;
        self.t_reg = inp.period;
        self.p_reg = inp.position;
        self.rom_s.step(inp.position, 0);
        self.rom_c.step(inp.position, self.quarter);
        self.fin = false;
        // 3. Control.
        if inp.arm {
            self.state = State::Armed;
            o.done = false;
        } else if inp.index {
            match self.state {
                State::Armed => {
                    self.state = State::Gather;
                    *o = GatherOutputs {
                        done: o.done,
                        ..GatherOutputs::default()
                    };
                }
                State::Gather => {
                    self.state = State::Idle;
                    self.fin = true;
                }
                State::Idle => {}
            }
        }
        // 4. Reset.
        if inp.reset {
            self.state = State::Idle;
            self.fin = false;
            self.pend = false;
            self.t_reg = 0;
            self.p_reg = 0;
            self.out = GatherOutputs::default();
        }
        self.out
    }
}

/// e and θ0 (this crate's convention, [`Identified`]) from gathered sums over one revolution
/// of K = `lines` lines: the first-harmonic least-squares fit of
/// [`harmonic_fit`](crate::eccentric::identify::harmonic_fit), computed from the sums.
///
/// The sums are taken at the edge phases ψ = 2πp/K, half a line after the period centres
/// Φ = ψ − π/K that `harmonic_fit` uses; with C' = Σ T·cos ψ, S' = Σ T·sin ψ (the sums ÷ Q),
/// C = C'·cos(π/K) + S'·sin(π/K), S = S'·cos(π/K) − C'·sin(π/K). Then, as in `harmonic_fit`,
/// α = 2C/(ΣT·sinc(π/K)), β = 2S/(ΣT·sinc(π/K)), a1 = hypot(α, β), θ0 = atan2(β, −α), and e
/// is a1 read through `model` ([`rigid_e_from_first_harmonic`] for the rigid disc).
pub fn identify_from_sums(
    lines: u32,
    sum_t: i128,
    sum_sin: i128,
    sum_cos: i128,
    model: Model,
) -> Identified {
    let q = full_scale(S_BITS) as f64;
    let k = f64::from(lines);
    let (s1, c1) = (sum_sin as f64 / q, sum_cos as f64 / q);
    let (sd, cd) = (PI / k).sin_cos();
    let c = c1 * cd + s1 * sd;
    let s = s1 * cd - c1 * sd;
    let sinc = sd / (PI / k);
    let norm = 2.0 / (sum_t as f64 * sinc);
    let (alpha, beta) = (c * norm, s * norm);
    let a1 = alpha.hypot(beta);
    let e = match model {
        Model::Rigid => rigid_e_from_first_harmonic(a1),
        Model::Zhao => a1,
    };
    Identified {
        e,
        theta0: beta.atan2(-alpha).rem_euclid(TAU),
    }
}

/// Bound on the error of e (absolute) and θ0 (radians) that [`identify_from_sums`] gives
/// from a revolution of `sum_t` clock cycles gathered on a disc of eccentricity `e`,
/// worked by hand:
/// - each line edge is sampled with an error q_i ∈ [0, 1) cycle, so a period is off by
///   q_i − q_(i−1); summed by parts against a table w (sin or cos), Σ (q_i − q_(i−1))·w_i
///   = Σ q_i·(w_i − w_(i+1)) + the two end terms, at most the total variation of a sine
///   over a revolution (4) plus 1: 5 cycles in each of C and S;
/// - α, β = 2C/(ΣT·sinc(π/K)), 2S/(…): each within 10/ΣT (sinc > 0.99 for K ≥ 8), a1
///   within √2·10/ΣT;
/// - the 24-bit table's rounding, ½ LSB of Q = 2^23 − 1 per entry: α, β within 1/Q,
///   a1 within √2/Q;
/// - the harmonic fit's own error on exact periods (docs/eccentricity.md): 2e-6·e and
///   4e-5° (7e-7 rad).
///
/// θ0's error is a1's divided by e.
pub fn error_budget(sum_t: f64, e: f64) -> (f64, f64) {
    let a1 = std::f64::consts::SQRT_2 * (10.0 / sum_t + 1.0 / f64::from((1u32 << 23) - 1));
    (a1 + 2e-6 * e, a1 / e + 7e-7)
}
