//! Rising-edge detector on a synchronised channel: produces `lep`, Rairán's encoder pulse.
//!
//! `pulse` is combinational: high during the cycle in which `level` is high and was low one
//! cycle before, and `enable` is high. Two pulses are therefore at least two cycles apart.

use rust_hdl::prelude::*;

/// Rising-edge detector with an enable (the start-up mask).
#[derive(LogicBlock, Default)]
pub struct RisingEdge {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Synchronised channel level.
    pub level: Signal<In, Bit>,
    /// Pulses are suppressed while low.
    pub enable: Signal<In, Bit>,
    /// One cycle per rising edge of `level`.
    pub pulse: Signal<Out, Bit>,
    previous: DFF<Bit>,
}

impl Logic for RisingEdge {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, previous);
        self.previous.d.next = self.level.val();
        if self.reset.val() {
            self.previous.d.next = false;
        }
        self.pulse.next = self.level.val() & !self.previous.q.val() & self.enable.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pulses_once_per_rising_edge_when_enabled() {
        let mut uut = RisingEdge::default();
        uut.connect_all();
        let level = [0, 1, 1, 0, 1, 0, 1, 1, 1, 0];
        let enable = [1, 1, 1, 1, 1, 1, 0, 1, 1, 1];
        // By hand: rising edges at 1, 4, 6; the one at 6 is masked.
        let expect = [0, 1, 0, 0, 1, 0, 0, 0, 0, 0];
        for k in 0..level.len() {
            uut.level.next = level[k] == 1;
            uut.enable.next = enable[k] == 1;
            uut.clock.next = Clock { clk: false };
            assert!(simulate(&mut uut, 10));
            assert_eq!(uut.pulse.val(), expect[k] == 1, "cycle {k}");
            uut.clock.next = Clock { clk: true };
            assert!(simulate(&mut uut, 10));
        }
    }

    #[test]
    fn synthesises() {
        let mut uut = RisingEdge::default();
        uut.connect_all();
        yosys_validate("encspeed_rising_edge", &generate_verilog(&uut)).unwrap();
    }
}
