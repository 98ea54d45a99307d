//! Bit-true models of the quadrature front end: [`GlitchFilter`] (one per channel),
//! [`QuadratureDecoder`] and [`PositionCounter`].
//!
//! These are the golden models of the rust-hdl blocks `hdl::GlitchFilter`,
//! `hdl::QuadratureDecoder` and `hdl::PositionCounter`, cycle for cycle and in the
//! hardware's widths. Conventions (as [`crate::top::core::CoreModel`]): one `step` per rising
//! clock edge with the inputs applied during the cycle before it; every register is updated
//! from the values before the edge; `step` returns the outputs after the edge. Reset is
//! synchronous and active high. Counters saturate at 2^bits − 1, none wraps (the position
//! is an angle: its wrap at `counts_per_rev` is its definition, not an overflow).
//!
//! Intended chain (the core wires it; these blocks are standalone):
//!
//! ```text
//! sync A ─ GlitchFilter ─ a ─┐
//! sync B ─ GlitchFilter ─ b ─┴─ QuadratureDecoder ─ step, forward ─┐
//! sync Z ─ GlitchFilter ─ z ────────────────────────────────────────┴─ PositionCounter
//! ```
//!
//! `z` enters the [`PositionCounter`] in the same cycle as `a`, `b` enter the decoder; the
//! counter delays it by the decoder's latency (one cycle), so that an index edge and the
//! step made by the same encoder transition are processed at the same clock edge.
//!
//! # Start-up
//! A [`GlitchFilter`] leaves reset with its output low and passes a high input only after
//! max(`cfg_filter`, 1) edges, which the decoder would take for a transition. Whoever wires
//! the chain must therefore hold the decoder and the counter in reset until the filters'
//! outputs are real samples: through edge max(L, 1) counted from the filters' reset edge 0
//! (as `golden/tests/frontend.rs` does). Each block then ignores its own first edge after
//! reset: the decoder takes the inputs at that edge as the reference (`primed`), and the
//! counter sees no index edge before it has compared two real samples of `z` (its delay
//! flops reset high). The reference is then the level of the first sample after reset,
//! provided the channels hold it for L cycles (a level that changes sooner is a pulse, and
//! a glitch, to a filter that starts low).

/// `cfg_mode` value: x1, one step per line, at the A edge while B is low.
pub const MODE_X1: u8 = 0;
/// `cfg_mode` value: x2, one step per A edge.
pub const MODE_X2: u8 = 1;
/// `cfg_mode` value: x4, one step per A or B edge.
pub const MODE_X4: u8 = 2;
/// `cfg_mode` value that is not a mode: decoded as x4, flagged on `mode_error`.
pub const MODE_INVALID: u8 = 3;

/// `cfg_z_mode` value: the index does nothing (no reset, no latch, no revolution check).
pub const Z_MODE_IGNORE: u8 = 0;
/// `cfg_z_mode` value: a rising index edge sets the position to 0.
pub const Z_MODE_RESET: u8 = 1;
/// `cfg_z_mode` value: a rising index edge copies the position into `z_latch`.
pub const Z_MODE_LATCH: u8 = 2;
/// `cfg_z_mode` value: a rising index edge latches the position, then sets it to 0.
pub const Z_MODE_LATCH_RESET: u8 = 3;

/// Widest register any front-end model accepts (bits).
pub const MAX_BITS: u32 = 32;

fn max_of(bits: u32) -> u64 {
    assert!(
        (1..=MAX_BITS).contains(&bits),
        "register width {bits} outside 1..={MAX_BITS}"
    );
    (1u64 << bits) - 1
}

fn sat_inc(v: u64, max: u64) -> u64 {
    if v >= max {
        max
    } else {
        v + 1
    }
}

// ---------------------------------------------------------------------------------------
// Glitch filter
// ---------------------------------------------------------------------------------------

/// Inputs of a [`GlitchFilter`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GlitchFilterInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Channel level, already synchronised to the clock.
    pub level_in: bool,
    /// L: cycles a new level must be seen before it passes (0 and 1: every change passes).
    pub cfg_filter: u64,
}

/// Outputs of a [`GlitchFilter`] after a clock edge (all registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GlitchFilterOutputs {
    /// Filtered level.
    pub level_out: bool,
    /// Rejected pulses since reset (saturating).
    pub glitches: u64,
    /// One cycle: this edge rejected a pulse (the event `glitches` counts, also when it
    /// has saturated).
    pub rejected: bool,
}

/// Registers of a [`GlitchFilter`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GlitchFilterState {
    /// Filtered level (`level_out`).
    pub out: bool,
    /// Consecutive cycles, before this edge, in which the input differed from `out`.
    pub run: u64,
    /// Rejected pulses.
    pub glitches: u64,
    /// `rejected` register.
    pub rejected: bool,
}

/// Programmable glitch filter of one channel.
///
/// Per edge: if the input differs from `out`, then if run + 1 ≥ L the input passes
/// (`out` = input, run = 0), else run += 1; if the input equals `out`, a non-zero run is a
/// rejected pulse (`glitches` += 1, saturating) and run = 0.
///
/// Latency: a level held for at least max(L, 1) cycles appears on `level_out` max(L, 1)
/// edges after the first edge that sampled it (L ≤ 1: the next edge); a pulse shorter than
/// L cycles never appears and counts one glitch when the input returns. run < L − 1 holds
/// after every increment, so run never overflows its F bits. Reset: out = 0, run = 0,
/// glitches = 0.
#[derive(Clone, Debug)]
pub struct GlitchFilter {
    filter_max: u64,
    glitch_max: u64,
    s: GlitchFilterState,
}

impl GlitchFilter {
    /// A filter with an F = `filter_bits` wide `cfg_filter` and a G = `glitch_bits` wide
    /// glitch counter, in its reset state.
    pub fn new(filter_bits: u32, glitch_bits: u32) -> GlitchFilter {
        GlitchFilter {
            filter_max: max_of(filter_bits),
            glitch_max: max_of(glitch_bits),
            s: GlitchFilterState::default(),
        }
    }

    /// The registers as they stand.
    pub fn state(&self) -> GlitchFilterState {
        self.s
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> GlitchFilterOutputs {
        GlitchFilterOutputs {
            level_out: self.s.out,
            glitches: self.s.glitches,
            rejected: self.s.rejected,
        }
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: GlitchFilterInputs) -> GlitchFilterOutputs {
        assert!(
            inp.cfg_filter <= self.filter_max,
            "cfg_filter = {} does not fit its port",
            inp.cfg_filter
        );
        let s = self.s;
        let mut n = GlitchFilterState {
            rejected: false,
            ..s
        };
        if inp.reset {
            n = GlitchFilterState::default();
        } else if inp.level_in != s.out {
            if s.run + 1 >= inp.cfg_filter {
                n.out = inp.level_in;
                n.run = 0;
            } else {
                n.run = s.run + 1;
            }
        } else {
            if s.run != 0 {
                n.glitches = sat_inc(s.glitches, self.glitch_max);
                n.rejected = true;
            }
            n.run = 0;
        }
        self.s = n;
        self.outputs()
    }
}

// ---------------------------------------------------------------------------------------
// Quadrature decoder
// ---------------------------------------------------------------------------------------

/// Inputs of a [`QuadratureDecoder`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DecoderInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Filtered channel A.
    pub a: bool,
    /// Filtered channel B.
    pub b: bool,
    /// Decoding mode: [`MODE_X1`], [`MODE_X2`], [`MODE_X4`] ([`MODE_INVALID`] = x4).
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
    /// `direction` register.
    pub direction: bool,
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
                direction: if step { fwd } else { s.direction },
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
            direction: n.direction,
            illegal: n.illegal,
            illegal_seen: n.illegal_seen,
            illegal_count: n.illegal_count,
            mode_error: inp.cfg_mode == MODE_INVALID,
        }
    }
}

// ---------------------------------------------------------------------------------------
// Position counter
// ---------------------------------------------------------------------------------------

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

/// Position modulo the counts per revolution, index reset/latch and revolution check.
///
/// Per edge (R = `counts_per_rev`, with 0 meaning 2^C; limit = R − 1):
/// 1. Index: rise = z(one edge ago) ∧ ¬z(two edges ago). Both delay flops reset high, so no
///    index edge is seen before two real samples of `z` are compared (the third edge after
///    reset, in step with the decoder's first possible step).
/// 2. Stepped position p: forward from p ≥ limit goes to 0, else p + 1; backward from p = 0
///    (or from p > limit, after R was lowered) goes to limit, else p − 1.
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
    s: CounterState,
}

impl PositionCounter {
    /// A counter with C = `position_bits` wide position, `counts_per_rev` and latch, and a
    /// G = `error_bits` wide revolution-error counter, after reset.
    pub fn new(position_bits: u32, error_bits: u32) -> PositionCounter {
        let mut c = PositionCounter {
            position_max: max_of(position_bits),
            error_max: max_of(error_bits),
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
        if inp.reset {
            self.s = self.reset_state();
            return self.outputs();
        }
        let s = self.s;
        let max = self.position_max;
        // R − 1 in C bits: 0 stands for 2^C.
        let limit = if inp.counts_per_rev == 0 {
            max
        } else {
            inp.counts_per_rev - 1
        };
        let rev_len = limit + 1;
        let rise = s.z_delay && !s.z_prev;
        let stepped = match (inp.step, inp.forward) {
            (false, _) => s.position,
            (true, true) if s.position >= limit => 0,
            (true, true) => s.position + 1,
            (true, false) if s.position == 0 || s.position > limit => limit,
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
