// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `hdl::WindowTimer<N>`: the free-running time base whose ticks end the
//! windows of the PC counter ([`crate::baselines::pc_counter`]) and the M/T counter
//! ([`crate::baselines::mt_counter`]).
//!
//! # Semantics (per rising clock edge, N-bit `cfg_dt`)
//! Inputs sampled at the edge: `reset` and `cfg_dt` (window length in clock cycles, 0
//! counts as 1). Registers: the phase p and the flag `due`.
//!
//! 1. The edge is a *window end* (tick) when `due` is set and `reset` is not.
//! 2. After the edge, p ← 0 on a tick or a reset, else p + 1.
//! 3. `due` ← p ≥ max(`cfg_dt`, 1) − 1, for the new p and this edge's `cfg_dt`.
//!
//! So an edge is a window end when the phase before it has reached max(dt, 1) − 1, with
//! the dt sampled at the edge before. This is the plain rule "tick when p ≥ max(dt, 1) − 1"
//! with dt taken one edge earlier: a change of `cfg_dt` acts one edge later, and lowering
//! it ends the current window at the next edge. The comparison is made one edge ahead so
//! that the tick is a register: it drives the enables of every window register of the
//! counters (a carry chain in front of them was the slowest path of the core).
//!
//! After a reset at edge 0 and with a constant `cfg_dt` = D ≥ 1, the ticks are the edges
//! D, 2D, … Steps never restart the time base. p never exceeds 2^N − 2: at p = 2^N − 2,
//! p ≥ max(dt, 1) − 1 holds for every N-bit dt.
//!
//! Power-up state: p = 0, `due` = 0, the state after a reset with `cfg_dt` ≥ 2.

/// The free-running window time base (module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WindowTimer {
    phase: u64,
    due: bool,
}

impl WindowTimer {
    /// The power-up state.
    pub fn new() -> WindowTimer {
        WindowTimer::default()
    }

    /// The phase p (cycles since the last window end or reset).
    pub fn phase(&self) -> u64 {
        self.phase
    }

    /// One rising clock edge with `reset` and `cfg_dt`: returns whether the edge is a window
    /// end.
    pub fn step(&mut self, reset: bool, cfg_dt: u64) -> bool {
        let tick = self.due && !reset;
        self.phase = if tick || reset { 0 } else { self.phase + 1 };
        self.due = self.phase >= cfg_dt.max(1) - 1;
        tick
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ticks (edge indices) of `edges` edges after a reset at edge 0, dt per edge.
    fn ticks(edges: usize, dt: impl Fn(usize) -> u64) -> Vec<usize> {
        let mut t = WindowTimer::new();
        assert!(!t.step(true, dt(0)));
        (1..edges).filter(|&k| t.step(false, dt(k))).collect()
    }

    #[test]
    fn constant_dt_ticks_every_dt_edges_by_hand() {
        assert_eq!(ticks(13, |_| 4), vec![4, 8, 12]);
        assert_eq!(ticks(4, |_| 1), vec![1, 2, 3]);
        assert_eq!(ticks(4, |_| 0), vec![1, 2, 3]);
        assert_eq!(ticks(7, |_| 2), vec![2, 4, 6]);
    }

    #[test]
    fn a_dt_change_acts_one_edge_later_by_hand() {
        // dt 10 until edge 5, then 3: after edge 5 the phase is 5 ≥ 3 − 1, so edge 6 ends
        // the window (the plain rule with this edge's dt would have ended it at edge 5).
        assert_eq!(ticks(13, |k| if k < 5 { 10 } else { 3 }), vec![6, 9, 12]);
        // Raised from 3 to 10 at edge 2 (phase 2 after it): the window runs to phase 9.
        assert_eq!(ticks(13, |k| if k < 2 { 3 } else { 10 }), vec![10]);
    }

    #[test]
    fn power_up_is_the_reset_state_for_dt_of_two_or_more() {
        let mut a = WindowTimer::new();
        let mut b = WindowTimer::new();
        b.step(true, 5);
        assert_eq!(a, b);
        // With dt ≤ 1 a reset sets `due`: the edge after it is a window end.
        a.step(true, 1);
        assert!(a.step(false, 1));
    }

    #[test]
    fn the_largest_dt_keeps_the_phase_below_its_limit() {
        // N = 2: dt = 3, phase 0, 1, 2 then a tick; 2 = 2^N − 2.
        let mut t = WindowTimer::new();
        t.step(true, 3);
        let mut max_phase = 0;
        for _ in 0..12 {
            t.step(false, 3);
            max_phase = max_phase.max(t.phase());
        }
        assert_eq!(max_phase, 2);
    }
}
