// SPDX-License-Identifier: MIT OR Apache-2.0
//! The decoding mode register and the reset a change of mode causes, shared by the core and
//! the eccentricity top (hardware: `hdl/src/top/mode_reset.rs`).
//!
//! A count made in one decoding mode means nothing in another, so a change of `cfg_mode`
//! resets the core as `reset` does. Both the mode and the change are registered: the edge
//! that sees a new `cfg_mode` stores it and the fact that it changed; the next edge resets
//! the core with the new mode already in place. So `rst` is `reset` or one registered flag,
//! not a comparator, at the head of the core's widest fan-out, and the decoder, the
//! position counter and the speed scaling read a register. A change sampled at a `reset`
//! edge is not flagged: that edge resets the core already, and the start-up hold keeps the
//! decoder and the position counter in reset until the new mode is in place. So the state
//! after a reset edge does not depend on the mode before it (a reset leaves no trace).
//!
//! The model follows the crate's conventions: [`ModeReset::rst`] and [`ModeReset::mode`] are
//! the values in the cycle before an edge, [`ModeReset::step`] is the edge.

/// The registered decoding mode and mode-change flag.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ModeReset {
    mode: u8,
    changed: bool,
}

impl ModeReset {
    /// At power-up: mode 0 (x1), no change pending.
    pub fn new() -> Self {
        Self::default()
    }

    /// The reset the core's registers see in this cycle: `reset`, or a mode change seen at
    /// the edge before.
    pub fn rst(&self, reset: bool) -> bool {
        reset || self.changed
    }

    /// The decoding mode in use in this cycle (`cfg_mode` of the cycle before).
    pub fn mode(&self) -> u8 {
        self.mode
    }

    /// One rising edge with `reset` and `cfg_mode` applied.
    pub fn step(&mut self, reset: bool, cfg_mode: u8) {
        self.changed = !reset && cfg_mode != self.mode;
        self.mode = cfg_mode;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_change_resets_at_the_next_edge_with_the_new_mode() {
        // By hand: cfg_mode 0, 0, 2, 2, 2, 1 at edges 0..5. Edge 2 sees 2 ≠ 0: from then on
        // the mode is 2 and `changed` is set, so the cycle before edge 3 has rst = 1 and
        // mode = 2; edge 3 sees no change. Edge 5 likewise for 1.
        let cfg = [0, 0, 2, 2, 2, 1, 1];
        let mut m = ModeReset::new();
        let mut seen = vec![];
        for &c in &cfg {
            seen.push((m.rst(false), m.mode()));
            m.step(false, c);
        }
        assert_eq!(
            seen,
            vec![
                (false, 0),
                (false, 0),
                (false, 0),
                (true, 2),
                (false, 2),
                (false, 2),
                (true, 1)
            ]
        );
        assert!(m.rst(true), "reset passes straight through");
    }

    #[test]
    fn a_change_at_a_reset_edge_is_not_flagged() {
        // Power-up mode 0; reset with cfg_mode 2 at edge 0: the mode is 2 after it and no
        // second reset follows, as after a reset from any earlier mode.
        for before in [0u8, 1, 2] {
            let mut m = ModeReset::new();
            m.step(false, before);
            m.step(false, before);
            m.step(true, 2);
            assert_eq!((m.rst(false), m.mode()), (false, 2), "from mode {before}");
        }
    }
}
