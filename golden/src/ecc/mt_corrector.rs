// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::MtCorrector`: the eccentricity-corrected M/T speed of every
//! window the core's M/T counter closes, from the core's taps (`mt_strobe`, `mt_m`, `mt_t`,
//! `mt_negative`, `position`, `dt_active`) and the runtime coefficients c = E·cos θ0,
//! d = E·sin θ0 (Q15.16 lines, [`crate::ecc::ecc_delta::coefficients`]).
//!
//! # Value
//! A window of m steps ending on the step at position P (the `position` in the `mt_strobe`
//! cycle, decoder steps, 0 ≤ P < R with R = lines·2^s the steps per revolution) covers, in
//! increasing position order,
//!
//! ```text
//! forward:  (P − m) mod R  →  P          backward:  P  →  (P + m) mod R
//! ```
//!
//! (the positions only matter mod R: a window of whole revolutions has δ = 0). δ of that
//! span comes from [`crate::ecc::span_delta`], and the
//! speed is [`crate::ecc::ecc_mt_speed::ecc_mt_speed`] of (m, t, negative, dt, s, δ):
//! ±(m − δ)·dt·2^(F−s)/t. For a backward window the magnitude of the true motion is
//! m − δ of the span taken upwards, which is why the span is always in increasing order
//! (the rigid disc reads h(x) = x + E·sin(2πx/K + θ0) lines at shaft angle x: a window
//! from x_a to x_b reads m = |h(x_b) − h(x_a)| and moves |x_b − x_a|).
//!
//! # Timing ([`latency_cycles`])
//! One request register, the latest `start` wins ([`crate::arith::latest_request`]): take (1 edge),
//! `SpanDelta` started the next edge (N + 68 to δ), EccMtSpeed started the edge after δ
//! (2N + F + 4), output register (1): 3N + F + 76 edges from a start (idle) to `valid`
//! (164 at N = 24, F = 16). Reset abandons everything; `speed_mtc` is then 0.

use crate::arith::latest_request::LatestRequest;
use crate::baselines::baseline_speeds::BaselineFormat;
use crate::ecc::ecc_mt_speed::{self, ecc_mt_speed, EccMtRequest};
use crate::ecc::span_delta::{self, span_delta, SpanRequest};

/// Edges from a start (block idle) to `valid`, N-bit counters and F fractional bits.
pub const fn latency_cycles(counter_bits: u32, frac_bits: u32) -> u32 {
    // take, SpanDelta's start, δ, EccMtSpeed's start the edge after δ, output register.
    2 + span_delta::latency_cycles(counter_bits)
        + 1
        + ecc_mt_speed::latency_cycles(counter_bits, frac_bits)
        + 1
}

/// Everything one `start` latches.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MtJob {
    /// Position P of the window's last step, decoder steps (< R).
    pub position: u64,
    /// Steps of the window.
    pub mt_m: u64,
    /// Cycles spanning them.
    pub mt_t: u64,
    /// The steps were backward.
    pub mt_negative: bool,
    /// dt in use, cycles.
    pub cfg_dt: u64,
    /// log2 of the steps per line (0, 1, 2).
    pub mode_shift: u32,
    /// c = E·cos θ0, Q15.16 lines (two's complement value).
    pub coef_c: i64,
    /// d = E·sin θ0, Q15.16 lines.
    pub coef_d: i64,
}

/// The span of a window: m steps ending at P, δ from the lower to the upper end (module
/// docs).
pub fn span(job: &MtJob) -> SpanRequest {
    SpanRequest {
        position: job.position,
        count: job.mt_m,
        negative: job.mt_negative,
        half_end: false,
        motion_order: false,
        shift: job.mode_shift,
        coef_c: job.coef_c,
        coef_d: job.coef_d,
    }
}

/// The corrected speed of `job` (units of 2^−F ω_lim), as the hardware computes it.
pub fn corrected_speed(lines: u32, table: (u32, u32), format: BaselineFormat, job: &MtJob) -> i64 {
    let delta = span_delta(lines, table, &span(job));
    ecc_mt_speed(
        format,
        &EccMtRequest {
            mt_m: job.mt_m,
            mt_t: job.mt_t,
            mt_negative: job.mt_negative,
            cfg_dt: job.cfg_dt,
            mode_shift: job.mode_shift,
            ecc_delta: delta,
        },
    )
}

/// Outputs after a rising edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MtCorrectorOutputs {
    /// Corrected M/T speed, units of 2^−F ω_lim, held.
    pub speed_mtc: i64,
    /// One cycle: `speed_mtc` was just written.
    pub valid: bool,
}

/// Cycle model of `hdl::MtCorrector`.
#[derive(Clone, Debug)]
pub struct MtCorrectorModel {
    lines: u32,
    table: (u32, u32),
    format: BaselineFormat,
    timing: LatestRequest<MtJob, i64>,
    out: MtCorrectorOutputs,
}

impl MtCorrectorModel {
    /// For a disc of `lines` lines, a sine table of `table` = (address bits, data bits) and
    /// the core's speed format.
    pub fn new(lines: u32, table: (u32, u32), format: BaselineFormat) -> Self {
        Self {
            lines,
            table,
            format,
            timing: LatestRequest::new(),
            out: MtCorrectorOutputs::default(),
        }
    }

    /// Outputs after the last edge.
    pub fn outputs(&self) -> MtCorrectorOutputs {
        self.out
    }

    /// One rising edge: `start` latches `job`.
    pub fn step(&mut self, reset: bool, start: Option<MtJob>) -> MtCorrectorOutputs {
        let (lines, table, format) = (self.lines, self.table, self.format);
        let latency = latency_cycles(format.counter_bits(), format.frac_bits());
        self.out.valid = false;
        if let Some(v) = self.timing.edge(start, reset, latency, |j| {
            corrected_speed(lines, table, format, &j)
        }) {
            self.out = MtCorrectorOutputs {
                speed_mtc: v,
                valid: true,
            };
        }
        if reset {
            self.out = MtCorrectorOutputs::default();
        }
        self.out
    }
}
