// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::frontend::position_counter::PositionCounter`: position modulo a revolution, index reset/latch and the revolution check.
//!
//! Conventions and the chain it belongs to: [`crate::frontend`].

use crate::frontend::config::{
    max_of, sat_inc, Z_MODE_IGNORE, Z_MODE_LATCH, Z_MODE_LATCH_RESET, Z_MODE_RESET,
};

/// Inputs of a [`PositionCounter`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CounterInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// A step of the decoder.
    pub step: bool,
    /// The step is forward.
    pub forward: bool,
    /// Filtered index level, in the timing of the decoder's `a`/`b` inputs (one cycle ahead
    /// of `step`); the counter delays it by one cycle.
    pub z: bool,
    /// Counts per revolution R (C bits; 0 stands for 2^C). The position runs over 0..R.
    pub counts_per_rev: u64,
    /// What an index edge does: [`Z_MODE_IGNORE`], [`Z_MODE_RESET`], [`Z_MODE_LATCH`],
    /// [`Z_MODE_LATCH_RESET`].
    pub cfg_z_mode: u8,
}

/// Outputs of a [`PositionCounter`] after a clock edge (all registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CounterOutputs {
    /// Position, 0..R.
    pub position: u64,
    /// Position at the last index edge (latch modes).
    pub z_latch: u64,
    /// One cycle: this edge processed a rising index edge.
    pub index: bool,
    /// A checked revolution had the wrong count (sticky).
    pub rev_error: bool,
    /// Revolutions with the wrong count (saturating).
    pub rev_error_count: u64,
    /// One cycle: this edge found a bad revolution (the event `rev_error_count` counts).
    pub rev_fault: bool,
}

/// Registers of a [`PositionCounter`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CounterState {
    /// Position.
    pub position: u64,
    /// Latched position.
    pub z_latch: u64,
    /// `index` register.
    pub index: bool,
    /// `z` one edge ago (aligns the index with the decoder's registered step).
    pub z_delay: bool,
    /// `z` two edges ago.
    pub z_prev: bool,
    /// A rising index edge has been seen since reset (revolutions can be checked).
    pub armed: bool,
    /// Steps since the last index edge, saturating at 2^C + 1 (one more than any R).
    pub rev_steps: u64,
    /// Direction of the first step since the last index edge (of every step if `!rev_mixed`).
    pub rev_forward: bool,
    /// Steps of both directions since the last index edge.
    pub rev_mixed: bool,
    /// `rev_error` register.
    pub rev_error: bool,
    /// `rev_error_count` register.
    pub rev_error_count: u64,
    /// `rev_fault` register.
    pub rev_fault: bool,
}

/// The three constants the hardware block takes for counts per revolution `counts_per_rev`
/// (0 standing for 2^C) at C = `position_bits`: limit = R − 1, R − 2 and R − 3, all mod
/// 2^C. The block compares with them instead of subtracting from R in the cycle.
pub fn limits(counts_per_rev: u64, position_bits: u32) -> (u64, u64, u64) {
    let mask = max_of(position_bits);
    (
        counts_per_rev.wrapping_sub(1) & mask,
        counts_per_rev.wrapping_sub(2) & mask,
        counts_per_rev.wrapping_sub(3) & mask,
    )
}

/// Position modulo the counts per revolution, index reset/latch and revolution check.
///
/// Per edge (R = `counts_per_rev`, with 0 meaning 2^C; limit = R − 1):
/// 1. Index: rise = z(one edge ago) ∧ ¬z(two edges ago). Both delay flops reset high, so no
///    index edge is seen before two real samples of `z` are compared (the third edge after
///    reset, in step with the decoder's first possible step).
/// 2. Stepped position p: forward from p = limit goes to 0, else p + 1; backward from p = 0
///    goes to limit, else p − 1. R may change only at a reset edge (the core changes it
///    only with the decoding mode, which resets the core), so p ≤ limit always holds; the
///    model asserts it. The hardware keeps "p = 0" and "p = limit" as registered flags.
/// 3. On rise: latch modes (2, 3) set `z_latch` = p (the step of this cycle included: the
///    index edge and the step of the same encoder transition arrive together); reset modes
///    (1, 3) set the position to 0 instead of p; `index` is high after the edge.
/// 4. Revolution check. Steps since the last index edge are counted with their directions;
///    the step in the cycle of an index edge belongs to the interval that edge closes. At
///    a rise, if a previous rise was seen (`armed`), `cfg_z_mode` ≠ 0, the closed interval
///    has at least one step and all its steps have one direction, and its count ≠ R, then
///    `rev_error` is set (sticky) and `rev_error_count` incremented (saturating).
///
/// Why this rule: the index rises on entering the Z window from either side, and the step
/// made by that entry comes with it, so between two rises the net count is a multiple of R
/// (0 or ±R) for a fault-free encoder, whatever the motion. An interval of one direction has
/// |net| = count, which must then be exactly R; an interval with a reversal (a shaft swinging
/// back across the index) is not checked, because its count is not the count of a
/// revolution; an interval without steps is not a revolution (index noise at rest).
/// Reversal-free revolutions are the ones a missed or extra pulse shows in for sure.
///
/// Latency: a step on the input is in `position` after the same edge; an index level change
/// on `z` acts one edge later (the decoder's latency). Reset: position, latch, flags and
/// counters 0, both index delay flops 1.
#[derive(Clone, Debug)]
pub struct PositionCounter {
    position_max: u64,
    error_max: u64,
    /// R since the last reset edge (None until the first edge).
    counts_per_rev: Option<u64>,
    s: CounterState,
}

impl PositionCounter {
    /// A counter with C = `position_bits` wide position, `counts_per_rev` and latch, and a
    /// G = `error_bits` wide revolution-error counter, after reset.
    pub fn new(position_bits: u32, error_bits: u32) -> PositionCounter {
        let mut c = PositionCounter {
            position_max: max_of(position_bits),
            error_max: max_of(error_bits),
            counts_per_rev: None,
            s: CounterState::default(),
        };
        c.s = c.reset_state();
        c
    }

    fn reset_state(&self) -> CounterState {
        CounterState {
            z_delay: true,
            z_prev: true,
            ..CounterState::default()
        }
    }

    /// The registers as they stand.
    pub fn state(&self) -> CounterState {
        self.s
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> CounterOutputs {
        CounterOutputs {
            position: self.s.position,
            z_latch: self.s.z_latch,
            index: self.s.index,
            rev_error: self.s.rev_error,
            rev_error_count: self.s.rev_error_count,
            rev_fault: self.s.rev_fault,
        }
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: CounterInputs) -> CounterOutputs {
        assert!(
            inp.counts_per_rev <= self.position_max,
            "counts_per_rev = {} does not fit its port",
            inp.counts_per_rev
        );
        assert!(inp.cfg_z_mode <= Z_MODE_LATCH_RESET, "cfg_z_mode");
        let r_before = self.counts_per_rev.replace(inp.counts_per_rev);
        assert!(
            inp.reset || r_before.is_none_or(|r| r == inp.counts_per_rev),
            "counts_per_rev changed from {r_before:?} to {} without a reset",
            inp.counts_per_rev
        );
        if inp.reset {
            self.s = self.reset_state();
            return self.outputs();
        }
        let s = self.s;
        let max = self.position_max;
        // R − 1 in C bits (0 stands for 2^C): the hardware's own constant.
        let limit = limits(inp.counts_per_rev, max.count_ones()).0;
        let rev_len = limit + 1;
        let rise = s.z_delay && !s.z_prev;
        let stepped = match (inp.step, inp.forward) {
            (false, _) => s.position,
            (true, true) if s.position == limit => 0,
            (true, true) => s.position + 1,
            (true, false) if s.position == 0 => limit,
            (true, false) => s.position - 1,
        };
        // The interval including this cycle's step.
        let (steps, forward, mixed) = if !inp.step {
            (s.rev_steps, s.rev_forward, s.rev_mixed)
        } else if s.rev_steps == 0 {
            (1, inp.forward, false)
        } else {
            (
                sat_inc(s.rev_steps, max + 2),
                s.rev_forward,
                s.rev_mixed || inp.forward != s.rev_forward,
            )
        };
        let mut n = s;
        n.z_prev = s.z_delay;
        n.z_delay = inp.z;
        n.index = rise;
        n.position = stepped;
        n.rev_steps = steps;
        n.rev_forward = forward;
        n.rev_mixed = mixed;
        n.rev_fault = false;
        if rise {
            let latch = inp.cfg_z_mode == Z_MODE_LATCH || inp.cfg_z_mode == Z_MODE_LATCH_RESET;
            let reset = inp.cfg_z_mode == Z_MODE_RESET || inp.cfg_z_mode == Z_MODE_LATCH_RESET;
            if latch {
                n.z_latch = stepped;
            }
            if reset {
                n.position = 0;
            }
            let bad = s.armed
                && inp.cfg_z_mode != Z_MODE_IGNORE
                && steps != 0
                && !mixed
                && steps != rev_len;
            if bad {
                n.rev_error = true;
                n.rev_fault = true;
                n.rev_error_count = sat_inc(s.rev_error_count, self.error_max);
            }
            n.armed = true;
            n.rev_steps = 0;
            n.rev_mixed = false;
        }
        self.s = n;
        self.outputs()
    }
}
