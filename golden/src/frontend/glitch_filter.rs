// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::frontend::glitch_filter::GlitchFilter`: one channel's glitch filter.
//!
//! Conventions and the chain it belongs to: [`crate::frontend`].

use crate::frontend::config::{max_of, sat_inc};

/// Inputs of a [`GlitchFilter`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GlitchFilterInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Channel level, already synchronised to the clock.
    pub level_in: bool,
    /// L: cycles a new level must be seen before it passes (0 and 1: every change passes).
    /// The filter compares with it an edge ahead: a change acts one edge later.
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
    /// run + 1 ≥ L for this edge's run and the L of the edge before: the pass decision,
    /// registered an edge ahead (false at power-up; a reset edge sets it to L ≤ 1).
    pub ready: bool,
}

/// Programmable glitch filter of one channel.
///
/// Per edge: if the input differs from `out`, then if run + 1 ≥ L the input passes
/// (`out` = input, run = 0), else run += 1; if the input equals `out`, a non-zero run is a
/// rejected pulse (`glitches` += 1, saturating) and run = 0. L is the `cfg_filter` of the
/// edge before: the comparison is made an edge ahead and registered (`ready`), so that no
/// carry chain drives the output register's enable. With a constant L this is the rule
/// above exactly; a change of L acts one edge later.
///
/// Latency: a level held for at least max(L, 1) cycles appears on `level_out` max(L, 1)
/// edges after the first edge that sampled it (L ≤ 1: the next edge); a pulse shorter than
/// L cycles never appears and counts one glitch when the input returns. run + 1 < L (the L
/// of the edge before) holds after every increment, so run never overflows its F bits.
/// Reset: out = 0, run = 0, glitches = 0, `ready` = (L ≤ 1).
#[derive(Clone, Debug)]
pub struct GlitchFilter {
    filter_max: u64,
    glitch_max: u64,
    s: GlitchFilterState,
}

impl GlitchFilter {
    /// A filter with an F = `filter_bits` wide `cfg_filter` and a G = `glitch_bits` wide
    /// glitch counter, in its power-up state (`ready` low: reset it before use, as the
    /// hardware).
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
            if s.ready {
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
        // The decision of the next edge, with this edge's L.
        n.ready = n.run + 1 >= inp.cfg_filter;
        self.s = n;
        self.outputs()
    }
}
