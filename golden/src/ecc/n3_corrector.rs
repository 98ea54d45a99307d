// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::N3Corrector`: Rairán's n3 corrected for the eccentricity of its
//! span ([`crate::ecc::ecc_n3`]), from the core's `speed_strobe` taps (`speed_n3`,
//! `speed_position`, `speed_nep`, `speed_ndt`) and the runtime coefficients c, d.
//!
//! # Value
//! The span ([`crate::eccentric::n3`]) in the order of motion, ending at P =
//! `speed_position`: Nep1 = 1, one step (the pulse period that ended at the restart pulse
//! P); Nep1 ≥ 2, Nep1 − 1 steps and half a step beyond P (the window started at the
//! restart pulse Nep1 − 1 steps before its last pulse P, and n3 ≈ Nep1 − ½).
//! δ = [`crate::ecc::span_delta::span_delta`] of it, in steps. `speed_n3` is in lines per dt
//! (after the mode scaling), so the block takes
//!
//! | case | δ given to `EccN3` | result |
//! |---|---|---|
//! | Nep1 = 1 | δ (steps: the span is one step) | n3·(1 − δ) |
//! | Nep1 ≥ 2 | ⌊δ/2^s⌋ (lines, arithmetic shift) | n3 − δ/2^s when Ndt1 = 1, else n3 |
//!
//! and the result is [`crate::ecc::ecc_n3::block_result`] of them.
//!
//! # Timing ([`latency_cycles`])
//! As [`crate::ecc::mt_corrector`] with `EccN3` (20 edges) as the second stage: take, SpanDelta
//! (N + 68), EccN3, output register: N + 92 edges (116 at N = 24), less than the speed
//! calculator's 3(N + 17) + 5 between two `speed_strobe`s, so no strobe is ever dropped.

use crate::arith::latest_request::LatestRequest;
use crate::ecc::ecc_n3::{self, block_result, EccN3Inputs};
use crate::ecc::span_delta::{self, span_delta, SpanRequest};

/// Edges from a start (block idle) to `valid`.
pub const fn latency_cycles(counter_bits: u32) -> u32 {
    2 + span_delta::latency_cycles(counter_bits) + 1 + ecc_n3::LATENCY_CYCLES + 1
}

/// Everything one `start` latches.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct N3Job {
    /// `speed_n3` (units of 2^−16 line per dt, signed).
    pub n3: i64,
    /// `speed_position`: the span's end, steps.
    pub position: u64,
    /// `speed_nep`.
    pub nep: u64,
    /// `speed_ndt`.
    pub ndt: u64,
    /// log2 of steps per line.
    pub mode_shift: u32,
    /// c = E·cos θ0, Q15.16 lines.
    pub coef_c: i64,
    /// d = E·sin θ0, Q15.16 lines.
    pub coef_d: i64,
}

/// The span of an n3 estimate (module docs).
pub fn span(job: &N3Job) -> SpanRequest {
    let one = job.nep <= 1;
    SpanRequest {
        position: job.position,
        count: if one { 1 } else { job.nep - 1 },
        negative: job.n3 < 0,
        half_end: !one,
        motion_order: true,
        shift: job.mode_shift,
        coef_c: job.coef_c,
        coef_d: job.coef_d,
    }
}

/// The corrected n3 of `job`, as the hardware computes it (S = `speed_bits`).
pub fn corrected_n3(lines: u32, table: (u32, u32), speed_bits: u32, job: &N3Job) -> i64 {
    let delta = span_delta(lines, table, &span(job));
    let nep_is_one = job.nep == 1;
    block_result(
        &EccN3Inputs {
            reset: false,
            start: true,
            n3: job.n3,
            nep_is_one,
            ndt_is_one: job.ndt == 1,
            delta: if nep_is_one {
                delta
            } else {
                delta >> job.mode_shift.min(2)
            },
        },
        speed_bits,
    )
}

/// Outputs after a rising edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct N3CorrectorOutputs {
    /// Corrected n3 (format of `speed_n3`), held.
    pub n3c: i64,
    /// One cycle: `n3c` was just written.
    pub valid: bool,
}

/// Cycle model of `hdl::N3Corrector`.
#[derive(Clone, Debug)]
pub struct N3CorrectorModel {
    lines: u32,
    table: (u32, u32),
    counter_bits: u32,
    speed_bits: u32,
    timing: LatestRequest<N3Job, i64>,
    out: N3CorrectorOutputs,
}

impl N3CorrectorModel {
    /// For a disc of `lines` lines, a sine table of `table` = (address, data bits),
    /// N-bit counters and S-bit speeds.
    pub fn new(lines: u32, table: (u32, u32), counter_bits: u32, speed_bits: u32) -> Self {
        Self {
            lines,
            table,
            counter_bits,
            speed_bits,
            timing: LatestRequest::new(),
            out: N3CorrectorOutputs::default(),
        }
    }

    /// One rising edge: `start` latches `job`.
    pub fn step(&mut self, reset: bool, start: Option<N3Job>) -> N3CorrectorOutputs {
        let (lines, table, s) = (self.lines, self.table, self.speed_bits);
        let latency = latency_cycles(self.counter_bits);
        self.out.valid = false;
        if let Some(v) = self
            .timing
            .edge(start, reset, latency, |j| corrected_n3(lines, table, s, &j))
        {
            self.out = N3CorrectorOutputs {
                n3c: v,
                valid: true,
            };
        }
        if reset {
            self.out = N3CorrectorOutputs::default();
        }
        self.out
    }
}
