// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::LineTap`: the line edges that `encspeed_ecc` feeds its
//! identification gatherer ([`crate::ecc::ident_gatherer`]), taken from the core's registered
//! `position` and `direction`.
//!
//! # Outputs (functions of the registers and the core's outputs in the same cycle)
//! - `line`: the core's position made one forward step since the last edge (position =
//!   last + 1, or position = 0 after last = R − 1, R = `counts_per_rev`: the wrap, also when
//!   an index edge resets the position in the same cycle), the last step was forward and
//!   the new position is the first step of a line (position mod 2^s = 0, s the decoder's
//!   shift: one pulse per line in x1, x2 and x4). An index edge that moves the position
//!   to 0 from elsewhere (the first alignment after reset, `cfg_z_mode` 1 or 3) is not a
//!   step and makes no line.
//! - `line_position`: the line number position / 2^s, taken mod 2^16 (< K whenever the
//!   position is counted mod R = K·2^s, which the core always does).
//! - `period`: clock cycles from the previous `line` to this one, saturating at 2^32 − 1
//!   (cycles since reset for the first line).
//!
//! # Registers (per rising edge)
//! `last_position` ← position; `since` ← 1 if `line`, else `since` + 1 saturating. `reset`
//! (synchronous) clears both, so the core's position (0 after its reset) makes no line.
//!
//! Contract: the gatherer is armed once the position is aligned (after the first `index`
//! since reset or a change of `cfg_mode`): before that, the period of the first line is
//! counted from reset or from a step of the unaligned count. `encspeed_ecc` ensures it by
//! holding an earlier arm until that index ([`crate::top::ecc_top`]).
//!
//! Latency: the line is seen in the cycle after the edge that moved the core's position,
//! i.e. `edge_to_position` + 1 edges after its A/B edge was sampled; the gatherer registers
//! it at the following edge. The period is exact in clock cycles between two line steps of
//! the core, which are the line edges delayed by the same front end.

/// Width of the core's position (`crate::params::POSITION_BITS`).
const _: () = assert!(crate::params::POSITION_BITS == 32);

/// Width of `line_position` (the table address of `encspeed_ecc`).
pub const LINE_BITS: u32 = 16;

/// Width of `period`.
pub const PERIOD_BITS: u32 = 32;

/// Width of the identification sums gathered from this tap's lines and periods:
/// `sum_bits(LINE_BITS, PERIOD_BITS)` = 72 ([`crate::ecc::ident_gatherer::sum_bits`]).
pub const IDENT_SUM_BITS: u32 = crate::ecc::ident_gatherer::sum_bits(LINE_BITS, PERIOD_BITS);

/// What the tap shows in one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LineTapOutputs {
    /// A line edge (forward) this cycle.
    pub line: bool,
    /// Its line number.
    pub line_position: u64,
    /// Cycles since the previous line edge.
    pub period: u64,
}

/// The tap's registers.
#[derive(Clone, Copy, Debug, Default)]
pub struct LineTap {
    last_position: u64,
    since: u64,
}

impl LineTap {
    /// The tap after reset.
    pub fn new() -> Self {
        Self::default()
    }

    /// The outputs for the core's `position` and `direction` in this cycle, shift `s` and
    /// R = `counts_per_rev` steps per revolution.
    pub fn outputs(
        &self,
        position: u64,
        forward: bool,
        shift: u32,
        counts_per_rev: u64,
    ) -> LineTapOutputs {
        let first_step = position & ((1 << shift) - 1) == 0;
        let after = (self.last_position + 1) & 0xffff_ffff;
        let stepped = position == after || (position == 0 && after == counts_per_rev);
        LineTapOutputs {
            line: stepped && forward && first_step,
            line_position: (position >> shift) & ((1 << LINE_BITS) - 1),
            period: self.since,
        }
    }

    /// One rising edge; `reset` is synchronous.
    pub fn step(
        &mut self,
        reset: bool,
        position: u64,
        forward: bool,
        shift: u32,
        counts_per_rev: u64,
    ) {
        let line = self.outputs(position, forward, shift, counts_per_rev).line;
        let max = (1u64 << PERIOD_BITS) - 1;
        self.since = if line { 1 } else { (self.since + 1).min(max) };
        self.last_position = position;
        if reset {
            *self = Self::default();
        }
    }
}
