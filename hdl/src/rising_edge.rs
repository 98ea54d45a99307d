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
