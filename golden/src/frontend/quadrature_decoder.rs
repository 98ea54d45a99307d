// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::frontend::quadrature_decoder::QuadratureDecoder`: x1/x2/x4 decoding with direction.
//!
//! Conventions and the chain it belongs to: [`crate::frontend`].

use crate::frontend::config::{max_of, sat_inc, MODE_INVALID, MODE_X1, MODE_X2};

/// Inputs of a [`QuadratureDecoder`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DecoderInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Filtered channel A.
    pub a: bool,
    /// Filtered channel B.
    pub b: bool,
    /// Decoding mode: [`MODE_X1`], [`MODE_X2`], [`MODE_X4`](crate::frontend::config::MODE_X4) ([`MODE_INVALID`] = x4).
    pub cfg_mode: u8,
}

/// Outputs of a [`QuadratureDecoder`] after a clock edge. All are registers except
/// `mode_error`, which is combinational from `cfg_mode`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DecoderOutputs {
    /// One cycle: the edge counted a step.
    pub step: bool,
    /// One cycle, with `step`: the step is forward (low whenever `step` is low).
    pub forward: bool,
    /// One cycle, with `step`: the first step since reset, or a step against the direction
    /// of the last one (a reversal); low whenever `step` is low.
    pub first: bool,
    /// Direction of the last step (high = forward; low after reset).
    pub direction: bool,
    /// One cycle: both channels changed between two samples (no step is made).
    pub illegal: bool,
    /// An illegal transition since reset (sticky).
    pub illegal_seen: bool,
    /// Illegal transitions since reset (saturating).
    pub illegal_count: u64,
    /// `cfg_mode` is [`MODE_INVALID`] (combinational from `cfg_mode`).
    pub mode_error: bool,
}

/// Registers of a [`QuadratureDecoder`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DecoderState {
    /// A at the previous edge.
    pub a_prev: bool,
    /// B at the previous edge.
    pub b_prev: bool,
    /// `a_prev`/`b_prev` hold a real sample (not the reset value).
    pub primed: bool,
    /// `step` register.
    pub step: bool,
    /// `forward` register.
    pub forward: bool,
    /// `first` register.
    pub first: bool,
    /// `direction` register.
    pub direction: bool,
    /// A step since reset (`direction` holds a real direction).
    pub have_step: bool,
    /// `illegal` register.
    pub illegal: bool,
    /// `illegal_seen` register.
    pub illegal_seen: bool,
    /// `illegal_count` register.
    pub illegal_count: u64,
}

/// Quadrature decoder in x1, x2 or x4 with direction and illegal-transition detection.
///
/// With da = A ⊕ A_prev and db = B ⊕ B_prev at an edge, and the decoder primed:
/// - illegal = da ∧ db (both changed: the direction is unknown, no step);
/// - a single-channel change is forward iff A_prev = B (the forward Gray sequence, B
///   lagging A by 90°, is (A,B) = 00 → 10 → 11 → 01 → 00);
/// - step in x4: da ⊕ db; x2: da ∧ ¬db; x1: da ∧ ¬db ∧ ¬B, the change of A while B is low,
///   i.e. one physical edge per line: A rising forward and A falling backward. (Counting
///   "A rising" in both directions would count +1 at each forward crossing of that edge
///   and nothing at the backward one, so a shaft dithering on it would drift.)
///
/// Latency: outputs are registered, so a change of `a`/`b` applied before edge k shows on
/// `step` after edge k (one cycle after the filter's output changed).
///
/// Start-up: the first edge after reset only loads A_prev/B_prev from the inputs and sets
/// `primed`; no step or illegal transition comes from it. Reset clears every register.
#[derive(Clone, Debug)]
pub struct QuadratureDecoder {
    count_max: u64,
    s: DecoderState,
}

impl QuadratureDecoder {
    /// A decoder with a G = `count_bits` wide illegal-transition counter, after reset.
    pub fn new(count_bits: u32) -> QuadratureDecoder {
        QuadratureDecoder {
            count_max: max_of(count_bits),
            s: DecoderState::default(),
        }
    }

    /// The registers as they stand.
    pub fn state(&self) -> DecoderState {
        self.s
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: DecoderInputs) -> DecoderOutputs {
        assert!(inp.cfg_mode <= MODE_INVALID, "cfg_mode = {}", inp.cfg_mode);
        let s = self.s;
        let n = if inp.reset {
            DecoderState::default()
        } else {
            let da = inp.a != s.a_prev;
            let db = inp.b != s.b_prev;
            let illegal = s.primed && da && db;
            let moved = match inp.cfg_mode {
                MODE_X1 => da && !db && !inp.b,
                MODE_X2 => da && !db,
                _ => da != db,
            };
            let step = s.primed && moved;
            let fwd = s.a_prev == inp.b;
            DecoderState {
                a_prev: inp.a,
                b_prev: inp.b,
                primed: true,
                step,
                forward: step && fwd,
                first: step && (!s.have_step || fwd != s.direction),
                direction: if step { fwd } else { s.direction },
                have_step: s.have_step || step,
                illegal,
                illegal_seen: s.illegal_seen || illegal,
                illegal_count: if illegal {
                    sat_inc(s.illegal_count, self.count_max)
                } else {
                    s.illegal_count
                },
            }
        };
        self.s = n;
        DecoderOutputs {
            step: n.step,
            forward: n.forward,
            first: n.first,
            direction: n.direction,
            illegal: n.illegal,
            illegal_seen: n.illegal_seen,
            illegal_count: n.illegal_count,
            mode_error: inp.cfg_mode == MODE_INVALID,
        }
    }
}
