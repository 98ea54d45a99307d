// SPDX-License-Identifier: MIT OR Apache-2.0
//! The decoding mode register and the core's registered reset; bit-true model
//! [`golden::top::mode_reset::ModeReset`], whose docs give the rule.
//!
//! `rst` is a flip-flop loaded with `reset` or "`cfg_mode` differs from the mode register",
//! so that the head of the core's widest fan-out (every register) is a register: neither the
//! `reset` input, nor the mode comparator, nor an OR gate sits in front of it.
//! Latency: `reset` sampled at an edge raises `rst` after that edge (it resets the core at
//! the next edge); a new `cfg_mode` is in `mode` one edge after the edge that samples it,
//! with `rst` high in that same cycle. `rst_next` is the value `rst` takes at the next edge
//! (for registers that must follow `rst` exactly, such as the core's estimator reset).
//! `rst` powers up high: the first edge after configuration resets the core whether or not
//! `reset` is high, so the state after it is the model's reset state.

use rust_hdl::prelude::*;

/// Registered `cfg_mode` and the registered reset.
#[derive(LogicBlock)]
pub struct ModeReset {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset input of the core.
    pub reset: Signal<In, Bit>,
    /// The decoding mode input.
    pub cfg_mode: Signal<In, Bits<2>>,
    /// The reset of the core's registers: `reset` or a mode change, seen at the edge before.
    pub rst: Signal<Out, Bit>,
    /// What `rst` will be after the next edge.
    pub rst_next: Signal<Out, Bit>,
    /// The decoding mode in use (`cfg_mode` one edge later).
    pub mode: Signal<Out, Bits<2>>,
    mode_reg: DFF<Bits<2>>,
    rst_reg: DFFWithInit<Bit>,
    rst_now: Signal<Local, Bit>,
}

impl Default for ModeReset {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            cfg_mode: Default::default(),
            rst: Default::default(),
            rst_next: Default::default(),
            mode: Default::default(),
            mode_reg: Default::default(),
            rst_reg: DFFWithInit::new(true),
            rst_now: Default::default(),
        }
    }
}

impl Logic for ModeReset {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, mode_reg, rst_reg);
        self.mode_reg.d.next = self.cfg_mode.val();
        self.rst_now.next = self.reset.val() | (self.cfg_mode.val() != self.mode_reg.q.val());
        self.rst_reg.d.next = self.rst_now.val();
        self.rst_next.next = self.rst_now.val();
        self.rst.next = self.rst_reg.q.val();
        self.mode.next = self.mode_reg.q.val();
    }
}
