// SPDX-License-Identifier: MIT OR Apache-2.0
//! Two-flop synchroniser for one asynchronous encoder channel.
//!
//! Latency: 2 clock cycles from the clock edge that samples `level_in` to `level_out`.
//! Reset (synchronous, active high) clears both flops, so that the waveform after reset
//! does not depend on what the flops held before; the start-up sequencer keeps the
//! cleared value from being mistaken for a signal level.

use rust_hdl::prelude::*;

/// Two flip-flops in series on one asynchronous input.
#[derive(LogicBlock, Default)]
pub struct TwoFlopSync {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Asynchronous input level (an encoder channel).
    pub level_in: Signal<In, Bit>,
    /// `level_in` two clock edges later, safe to use in the clock domain.
    pub level_out: Signal<Out, Bit>,
    meta: DFF<Bit>,
    stable: DFF<Bit>,
}

impl Logic for TwoFlopSync {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, meta, stable);
        self.meta.d.next = self.level_in.val();
        self.stable.d.next = self.meta.q.val();
        if self.reset.val() {
            self.meta.d.next = false;
            self.stable.d.next = false;
        }
        self.level_out.next = self.stable.q.val();
    }
}
