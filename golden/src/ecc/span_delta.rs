// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::SpanDelta`: the eccentricity correction δ
//! ([`crate::ecc::ecc_delta`]) of a span of disc given by its end and its length, as the
//! core's taps give it: the M/T window's last step and m, n3's `speed_position` and Nep1.
//!
//! # The span
//! A span of r = `count` mod R steps (R = lines·2^s steps per revolution: the positions
//! only matter mod R, a span of whole revolutions has δ = 0) ends at position P (steps,
//! < R). In half-steps (h = 2·position, the unit of `EccDelta`), with `half_end` adding
//! half a step beyond P in the direction of motion:
//!
//! | motion | lower end | upper end |
//! |---|---|---|
//! | forward | 2·((P − r) mod R) | 2P + half_end |
//! | backward | (2P − half_end) mod 2R | 2·((P + r) mod R) |
//!
//! δ is taken from the lower to the upper end (`motion_order` = false: the correction of
//! the magnitude of the motion, what `EccMtSpeed` subtracts), or in the order of motion
//! (`motion_order` = true: what `EccN3` expects, which negates it for a backward n3).
//!
//! # Timing
//! No request register: the caller holds the inputs from `start` until `valid`. The start
//! edge takes the first of N restoring-subtraction steps of r, N − 1 more follow, the next
//! edge starts `EccDelta`, whose result is `valid` 68 edges later: [`latency_cycles`] =
//! N + 68 from the start edge.

use crate::ecc::ecc_delta::{self, delta_raw, Request};

/// Edges from the start edge to `valid`.
pub const fn latency_cycles(counter_bits: u32) -> u32 {
    counter_bits + ecc_delta::latency_cycles()
}

/// A span and the coefficients it is corrected with.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SpanRequest {
    /// P: the end of the span, steps (< R).
    pub position: u64,
    /// Length in steps (taken mod R).
    pub count: u64,
    /// The motion was backward.
    pub negative: bool,
    /// The span ends half a step beyond P.
    pub half_end: bool,
    /// δ in the order of motion instead of from the lower to the upper end.
    pub motion_order: bool,
    /// s: log2 of steps per line (0, 1, 2).
    pub shift: u32,
    /// c = E·cos θ0, Q15.16 lines.
    pub coef_c: i64,
    /// d = E·sin θ0, Q15.16 lines.
    pub coef_d: i64,
}

/// (p_a, p_b) in half-steps, the order `EccDelta` takes them (module docs).
pub fn half_steps(lines: u32, req: &SpanRequest) -> (u64, u64) {
    let r_rev = u64::from(lines) << req.shift.min(2);
    let r = req.count % r_rev;
    let p = req.position;
    let half = u64::from(req.half_end);
    let (lo, hi) = if req.negative {
        (
            (2 * p + 2 * r_rev - half) % (2 * r_rev),
            2 * ((p + r) % r_rev),
        )
    } else {
        (2 * ((p + r_rev - r) % r_rev), 2 * p + half)
    };
    if req.motion_order && req.negative {
        (hi, lo)
    } else {
        (lo, hi)
    }
}

/// δ of the span (units of 2^−16 step), as the hardware computes it with a sine table of
/// `table` = (address bits, data bits).
pub fn span_delta(lines: u32, table: (u32, u32), req: &SpanRequest) -> i64 {
    let (p_a, p_b) = half_steps(lines, req);
    delta_raw(
        lines,
        table.0,
        table.1,
        &Request {
            p_a,
            p_b,
            shift: req.shift,
            coef_c: req.coef_c,
            coef_d: req.coef_d,
        },
    )
}
