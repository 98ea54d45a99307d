// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::EccN3`: Rairán's n3 with the eccentricity correction δ of its
//! span applied to its count ([`crate::eccentric::n3`] derives the rule in f64 and measures
//! what it does).
//!
//! # Values
//! Inputs: `n3`, the speed calculator's n3 in decoder steps per dt (signed, S = N + 17
//! bits, units of 2^−16 step per dt: [`crate::estimator::speed_calc`] with F = 16, before the mode
//! scaling), whether Nep1 = 1 and whether Ndt1 = 1 for the registers it was computed from,
//! and δ, the correction of its span in decoder steps (signed,
//! [`DELTA_BITS`] bits, 16 fractional bits, the span taken in
//! the order of motion: [`crate::ecc::ecc_delta`]). With m = |n3| and d = δ for a forward n3, −δ
//! for a backward one (so that d is the correction of the magnitude), the corrected
//! magnitude is
//!
//! | case | corrected magnitude (units of 2^−16 step per dt) | why |
//! |---|---|---|
//! | n3 = 0 | 0 | no speed |
//! | Nep1 = 1 | ⌊m·f/2^16 + ½⌋, f = clamp(2^16 − d, 0, 2^17) | the span is one step: n3·(1 − δ) |
//! | Nep1 ≥ 2, Ndt1 = 1 | clamp(m − d, 0, max) | dn3/dNep1 = 1 + 1/(2(2·Nep1 − 1)²) ≈ 1: n3 − δ |
//! | otherwise | m | a speed transient: no steady span to correct |
//!
//! max = 2^(S−1) − 1; every result is clamped to [0, max], never wrapped. The sign is then
//! put back: zero stays 0 and forward and backward stay mirror images. The clamp of f only
//! acts for |δ| ≥ 1 step on a one-step span, which needs e ≳ 1/√2: never a real disc.
//!
//! # Error budget against the f64 rule ([`crate::eccentric::n3::N3Sample::n3_hardware_rule`])
//! Nep1 = 1: ½ LSB of rounding; Nep1 ≥ 2: exact (integers). The inputs' own rounding (n3
//! ½ LSB from the speed calculator, δ ½ LSB from [`crate::ecc::ecc_delta`]) adds to it; the mode
//! scaling after this block adds its ½ LSB as for n3.
//!
//! # Timing (as [`crate::estimator::speed_calc`])
//! `start` latches `n3`, `nep_is_one`, `ndt_is_one` and `delta` into a one-deep request
//! register (a newer start replaces a request that has not begun). At the first edge at
//! which the block is idle and a request is pending it begins; [`LATENCY_CYCLES`] edges
//! after a start edge (block idle) `n3c` changes and `valid` is high for one cycle. `busy` is
//! high while a computation runs or a request is pending. `reset` (synchronous, active high)
//! wins: `n3c` 0, `valid` and `busy` 0, any request abandoned.
//!
//! # Hardware algorithm ([`hardware_magnitude`])
//! One shift-add multiply of m by f, least significant bit of f first, 18 steps, into two
//! halves {A (S bits), Q (18 bits)}: m·f = A·2^18 + Q; then ⌊(A·2^18 + Q + 2^15)/2^16⌋ =
//! 4·A + ⌊(Q + 2^15)/2^16⌋. The subtraction and the pass-through are taken at the end, so
//! the latency is the same in every case.

use crate::arith::latest_request::LatestRequest;
use crate::ecc::ecc_delta::{DELTA_BITS, DELTA_FRAC_BITS};

/// Steps of the shift-add multiply (bits of f ≤ 2^17).
pub const MUL_STEPS: u32 = 18;

/// Edges from a start (block idle) to `valid`: take the request, 18 multiply steps, finish.
pub const LATENCY_CYCLES: u32 = MUL_STEPS + 2;

/// One unit of δ and of n3: 2^16.
const ONE: i128 = 1 << DELTA_FRAC_BITS;

/// The factor f = clamp(2^16 − d, 0, 2^17) of the Nep1 = 1 case.
pub fn factor(d: i128) -> u64 {
    (ONE - d).clamp(0, 2 * ONE) as u64
}

/// The corrected magnitude by the rule of the module docs, for S = `speed_bits`.
pub fn corrected_magnitude(
    m: u64,
    d: i128,
    nep_is_one: bool,
    ndt_is_one: bool,
    speed_bits: u32,
) -> u64 {
    let max = (1i128 << (speed_bits - 1)) - 1;
    let m = i128::from(m);
    let c = if m == 0 {
        0
    } else if nep_is_one {
        (m * i128::from(factor(d)) + ONE / 2) >> DELTA_FRAC_BITS
    } else if ndt_is_one {
        m - d
    } else {
        m
    };
    c.clamp(0, max) as u64
}

/// The hardware's computation of [`corrected_magnitude`] (module docs); panics if `m` does
/// not fit S − 1 bits.
pub fn hardware_magnitude(
    m: u64,
    d: i128,
    nep_is_one: bool,
    ndt_is_one: bool,
    speed_bits: u32,
) -> u64 {
    let s = speed_bits;
    assert!(m < 1 << (s - 1), "magnitude does not fit");
    let f = factor(d);
    let (mut a, mut q) = (0u64, f);
    for _ in 0..MUL_STEPS {
        let sum = if q & 1 == 1 { a + m } else { a };
        q = (q >> 1) | ((sum & 1) << (MUL_STEPS - 1));
        a = sum >> 1;
    }
    let max = (1u64 << (s - 1)) - 1;
    if m == 0 {
        0
    } else if nep_is_one {
        (4 * u128::from(a) + u128::from((q + (1 << 15)) >> 16)).min(u128::from(max)) as u64
    } else if ndt_is_one {
        (i128::from(m) - d).clamp(0, i128::from(max)) as u64
    } else {
        m
    }
}

/// The signed corrected n3 (units of 2^−16 step per dt) of the module docs.
pub fn corrected(n3: i64, delta: i64, nep_is_one: bool, ndt_is_one: bool, speed_bits: u32) -> i64 {
    let d = if n3 < 0 {
        -i128::from(delta)
    } else {
        i128::from(delta)
    };
    let c = corrected_magnitude(n3.unsigned_abs(), d, nep_is_one, ndt_is_one, speed_bits) as i64;
    if n3 < 0 {
        -c
    } else {
        c
    }
}

/// What the block outputs for the request `r` with S = `speed_bits`: [`corrected`], the
/// most negative S-bit n3 (which has no magnitude in S − 1 bits) taken as saturated.
pub fn block_result(r: &EccN3Inputs, speed_bits: u32) -> i64 {
    let n3 = r.n3.max(-((1 << (speed_bits - 1)) - 1));
    corrected(n3, r.delta, r.nep_is_one, r.ndt_is_one, speed_bits)
}

/// Inputs during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccN3Inputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Latch a request.
    pub start: bool,
    /// n3 (signed, S bits).
    pub n3: i64,
    /// Nep1 = 1.
    pub nep_is_one: bool,
    /// Ndt1 = 1.
    pub ndt_is_one: bool,
    /// δ (signed, DELTA_BITS bits, 16 fractional bits).
    pub delta: i64,
}

/// Outputs after an edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccN3Outputs {
    /// Corrected n3 (signed), held between results.
    pub n3c: i64,
    /// A new `n3c` this cycle.
    pub valid: bool,
    /// A computation runs or a request is pending.
    pub busy: bool,
}

/// `hdl::EccN3<S>`, bit-true (module docs).
#[derive(Clone, Debug)]
pub struct EccN3 {
    speed_bits: u32,
    timing: LatestRequest<EccN3Inputs, i64>,
    out: EccN3Outputs,
}

impl EccN3 {
    /// A block for S-bit speeds (25 ≤ S ≤ 49: N = 8..=32 with 16 fractional bits), reset.
    pub fn new(speed_bits: u32) -> Self {
        assert!(
            (25..=49).contains(&speed_bits),
            "S = {speed_bits} outside 25..=49"
        );
        Self {
            speed_bits,
            timing: LatestRequest::new(),
            out: EccN3Outputs::default(),
        }
    }

    /// One rising clock edge with `inp` applied; the outputs after it. Panics if `n3` or
    /// `delta` does not fit its port.
    pub fn step(&mut self, inp: EccN3Inputs) -> EccN3Outputs {
        let s = self.speed_bits;
        assert!(
            inp.n3.unsigned_abs() < 1 << (s - 1) || inp.n3 == -(1 << (s - 1)),
            "n3 does not fit {s} bits"
        );
        let dh = 1i64 << (DELTA_BITS - 1);
        assert!((-dh..dh).contains(&inp.delta), "delta does not fit");
        let mut out = EccN3Outputs {
            valid: false,
            ..self.out
        };
        let start = inp.start.then_some(inp);
        if let Some(result) = self
            .timing
            .edge(start, inp.reset, LATENCY_CYCLES, |r| block_result(&r, s))
        {
            out.n3c = result;
            out.valid = true;
        }
        if inp.reset {
            out = EccN3Outputs::default();
        }
        out.busy = self.timing.busy();
        self.out = out;
        out
    }
}
