// SPDX-License-Identifier: MIT OR Apache-2.0
//! The decoding mode register and the reset a change of mode causes, shared by the core and
//! the eccentricity top (hardware: `hdl/src/top/mode_reset.rs`).
//!
//! A count made in one decoding mode means nothing in another, so a change of `cfg_mode`
//! resets the core as `reset` does. The core's reset `rst` is one register, loaded with
//! `reset` or "`cfg_mode` differs from the mode register": at the head of the core's widest
//! fan-out (every register) there is a flip-flop, not an input, a comparator or an OR gate.
//! So `reset` acts one edge after the edge that samples it (a reset held for k edges resets
//! the core at the k edges after those), and a change of `cfg_mode` resets the core at the
//! edge after the one that sees it, with the new mode already in place; the decoder, the
//! position counter and the speed scaling read the mode register. A change sampled at a
//! `reset` edge raises no second reset: the reset it loads is the same one, and the mode
//! register holds the new mode when it acts. So the state after a reset does not depend on
//! the mode before it (a reset leaves no trace).
//!
//! The model follows the crate's conventions: [`ModeReset::rst`] and [`ModeReset::mode`] are
//! the values in the cycle before an edge, [`ModeReset::step`] is the edge.

/// The registered decoding mode and the registered reset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ModeReset {
    mode: u8,
    rst: bool,
}

impl Default for ModeReset {
    fn default() -> Self {
        Self::new()
    }
}

impl ModeReset {
    /// At power-up: mode 0 (x1), and a reset pending: the register powers up high, so the
    /// first edge resets the core whether or not `reset` is high (the state after it is the
    /// reset state, as the core model's own initial state is).
    pub fn new() -> Self {
        Self { mode: 0, rst: true }
    }

    /// The reset the core's registers see in this cycle: `reset` at the edge before, or a
    /// mode change seen at the edge before.
    pub fn rst(&self) -> bool {
        self.rst
    }

    /// The decoding mode in use in this cycle (`cfg_mode` of the cycle before).
    pub fn mode(&self) -> u8 {
        self.mode
    }

    /// One rising edge with `reset` and `cfg_mode` applied.
    pub fn step(&mut self, reset: bool, cfg_mode: u8) {
        self.rst = reset || cfg_mode != self.mode;
        self.mode = cfg_mode;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_change_resets_at_the_next_edge_with_the_new_mode() {
        // By hand: cfg_mode 0, 0, 2, 2, 2, 1 at edges 0..5. The power-up reset acts at edge
        // 0 (rst high before it). Edge 2 sees 2 ≠ 0: from then on
        // the mode is 2 and `rst` is set, so the cycle before edge 3 has rst = 1 and
        // mode = 2; edge 3 sees no change. Edge 5 likewise for 1.
        let cfg = [0, 0, 2, 2, 2, 1, 1];
        let mut m = ModeReset::new();
        let mut seen = vec![];
        for &c in &cfg {
            seen.push((m.rst(), m.mode()));
            m.step(false, c);
        }
        assert_eq!(
            seen,
            vec![
                (true, 0),
                (false, 0),
                (false, 0),
                (true, 2),
                (false, 2),
                (false, 2),
                (true, 1)
            ]
        );
        m.step(true, 1);
        assert!(
            m.rst(),
            "reset acts at the edge after the one that samples it"
        );
    }

    #[test]
    fn a_mode_change_with_reset_resets_once() {
        // Reset with cfg_mode 2 sampled at an edge: the cycle after it resets with mode 2,
        // and no second reset follows, as after a reset from any earlier mode.
        for before in [0u8, 1, 2] {
            let mut m = ModeReset::new();
            m.step(false, before);
            m.step(false, before);
            m.step(true, 2);
            assert_eq!((m.rst(), m.mode()), (true, 2), "from mode {before}");
            m.step(false, 2);
            assert_eq!((m.rst(), m.mode()), (false, 2), "from mode {before}");
        }
    }
}
