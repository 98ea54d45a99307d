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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn delays_by_two_edges_and_resets() {
        let mut uut = TwoFlopSync::default();
        uut.connect_all();
        let input = [1, 0, 1, 1, 0, 0];
        let reset = [0, 0, 0, 1, 0, 0];
        // By hand: out after edge k = in at edge k−1, except cleared through a reset edge.
        let expect = [0, 1, 0, 0, 0, 0];
        for k in 0..input.len() {
            uut.level_in.next = input[k] == 1;
            uut.reset.next = reset[k] == 1;
            uut.clock.next = Clock { clk: false };
            assert!(simulate(&mut uut, 10));
            uut.clock.next = Clock { clk: true };
            assert!(simulate(&mut uut, 10));
            assert_eq!(uut.level_out.val(), expect[k] == 1, "after edge {k}");
        }
    }

    #[test]
    fn synthesises() {
        let mut uut = TwoFlopSync::default();
        uut.connect_all();
        yosys_validate("encspeed_two_flop_sync", &generate_verilog(&uut)).unwrap();
    }
}
