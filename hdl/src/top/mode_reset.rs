// SPDX-License-Identifier: MIT OR Apache-2.0
//! The decoding mode register and the reset a change of mode causes; bit-true model
//! [`golden::top::mode_reset::ModeReset`], whose docs give the rule.
//!
//! Both the mode and the change are registered, so that the core's reset is `reset` ORed
//! with one flip-flop: the mode comparator does not sit in front of the reset's fan-out
//! (every register of the core), and the decoder and the speed scaling read a register.
//! Latency: a new `cfg_mode` is in `mode` one edge after the edge that samples it, with
//! `rst` high in that same cycle. A change sampled at a `reset` edge raises no second
//! reset (that edge resets the core already), so a reset leaves no trace of the old mode.

use rust_hdl::prelude::*;

/// Registered `cfg_mode` and the reset its change causes.
#[derive(LogicBlock, Default)]
pub struct ModeReset {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset of the core.
    pub reset: Signal<In, Bit>,
    /// The decoding mode input.
    pub cfg_mode: Signal<In, Bits<2>>,
    /// The reset of the core's registers: `reset`, or a mode change seen at the edge before.
    pub rst: Signal<Out, Bit>,
    /// The decoding mode in use (`cfg_mode` one edge later).
    pub mode: Signal<Out, Bits<2>>,
    mode_reg: DFF<Bits<2>>,
    changed: DFF<Bit>,
}

impl Logic for ModeReset {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, mode_reg, changed);
        self.mode_reg.d.next = self.cfg_mode.val();
        self.changed.d.next = !self.reset.val() & (self.cfg_mode.val() != self.mode_reg.q.val());
        self.rst.next = self.reset.val() | self.changed.q.val();
        self.mode.next = self.mode_reg.q.val();
    }
}
