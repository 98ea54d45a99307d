// SPDX-License-Identifier: MIT OR Apache-2.0
//! The free-running window time base of the PC and M/T counters: `tick` ends a window every
//! max(`cfg_dt`, 1) cycles. Bit-true model: [`golden::baselines::window_timer::WindowTimer`],
//! whose module docs give the rule in full.
//!
//! Per clock edge (N = width, 2..=32): a tick when `due` is set (and no reset); the phase
//! p ← 0 on a tick or reset, else p + 1; `due` ← p ≥ max(`cfg_dt`, 1) − 1 for the new p and
//! this edge's `cfg_dt`. So `tick` is a register: it drives the enables of every window
//! register of the counters, and a carry chain in front of that fanout was the core's
//! slowest path. The price is that `cfg_dt` acts one edge later than a comparison in the
//! same cycle would make it (the core feeds the dt that its dt register takes at the same
//! edge, so its windows are unchanged).
//!
//! For the new p: after a tick or reset p = 0, and 0 ≥ max(dt, 1) − 1 is dt ≤ 1, that is
//! 1 ≥ dt; otherwise p + 1 ≥ max(dt, 1) − 1 is p + 2 ≥ dt (dt = 0 included). So `due` is
//! one comparison x ≥ dt whose left side x is 1 or p + 2: the choice is made on the
//! operand, one LUT in front of the carry chain, and the chain's carry out is `due`'s input
//! (with a test of dt's bits and a multiplexer after the chain instead, three LUT levels and
//! a long route to `due` made the core's critical path on HX8K).
//! The register keeps p + 2 mod 2^N with bit 1 inverted, so that its power-up value 0 is
//! p = 0: the comparison is one carry chain from it. p + 2 wraps only at p = 2^N − 2, the
//! largest max(dt, 1) − 1, where `due` is already set and the result is not used.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | everything happens at its rising edge |
//! | `reset` | in | 1 | synchronous, active high: p ← 0 |
//! | `cfg_dt` | in | N | window length in clock cycles (0 counts as 1), used from the next cycle on |
//! | `tick` | out | 1 | registered: this cycle's edge ends a window (unless `reset` is high) |

use rust_hdl::prelude::*;

/// Window time base with an N-bit phase and a registered tick.
#[derive(LogicBlock)]
pub struct WindowTimer<const N: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Window length, clock cycles (0 counts as 1), used from the next cycle on.
    pub cfg_dt: Signal<In, Bits<N>>,
    /// This cycle's edge ends a window (unless `reset` is high).
    pub tick: Signal<Out, Bit>,
    /// p + 2 mod 2^N with bit 1 inverted (power-up and reset value 0 is p = 0).
    plus_two_reg: DFF<Bits<N>>,
    /// p ≥ max(dt, 1) − 1 for the phase and the dt of this cycle.
    due: DFF<Bit>,
    /// p + 2 mod 2^N.
    plus_two: Signal<Local, Bits<N>>,
    /// The left side of `due`'s comparison: 1 after a tick or reset, else p + 2.
    compared: Signal<Local, Bits<N>>,
    zero: Constant<Bits<N>>,
    one: Constant<Bits<N>>,
    two: Constant<Bits<N>>,
}

impl<const N: usize> Default for WindowTimer<N> {
    fn default() -> Self {
        assert!((2..=32).contains(&N), "N outside 2..=32");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            cfg_dt: Default::default(),
            tick: Default::default(),
            plus_two_reg: Default::default(),
            due: Default::default(),
            plus_two: Default::default(),
            compared: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            two: Constant::new(2.into()),
        }
    }
}

impl<const N: usize> Logic for WindowTimer<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, plus_two_reg, due);
        self.plus_two.next = self.plus_two_reg.q.val() ^ self.two.val();
        // Not a tick: p + 1 is the new phase, its p + 2 is this cycle's p + 3.
        self.plus_two_reg.d.next = (self.plus_two.val() + self.one.val()) ^ self.two.val();
        self.compared.next = self.plus_two.val();
        if self.due.q.val() | self.reset.val() {
            self.plus_two_reg.d.next = self.zero.val();
            self.compared.next = self.one.val();
        }
        self.due.d.next = self.compared.val() >= self.cfg_dt.val();
        // The counters' own resets win over the tick: no reset in front of their enables.
        self.tick.next = self.due.q.val();
    }
}

/// The Verilog of a [`WindowTimer`], top module named `module_name`.
pub fn window_timer_verilog<const N: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<WindowTimer<N>>(module_name)
}
