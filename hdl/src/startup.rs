//! Start-up sequencer: counts the first clock edges after reset.
//!
//! After reset the synchroniser and the edge detector hold cleared values, not samples of
//! the encoder. The sequencer holds the Table 1 engine in reset for the first
//! [`CORE_LATENCY_CYCLES`](golden::params::CORE_LATENCY_CYCLES) = 2 edges (so that the ts/dt
//! time base starts in step with the first real sample: the core is then exactly Table 1
//! delayed by 2 cycles) and masks the edge detector for one edge more (so that a channel
//! already high at reset is not taken for a pulse).

use rust_hdl::prelude::*;

/// Saturating count of clock edges since reset.
#[derive(LogicBlock)]
pub struct Startup {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// High once the Table 1 engine may run (2 or more edges since reset).
    pub engine_run: Signal<Out, Bit>,
    /// High once the edge detector compares two real samples (3 or more edges since reset).
    pub edge_enable: Signal<Out, Bit>,
    edges_seen: DFF<Bits<2>>,
    zero: Constant<Bits<2>>,
    one: Constant<Bits<2>>,
    two: Constant<Bits<2>>,
    three: Constant<Bits<2>>,
}

impl Default for Startup {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            engine_run: Default::default(),
            edge_enable: Default::default(),
            edges_seen: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            two: Constant::new(2.into()),
            three: Constant::new(3.into()),
        }
    }
}

impl Logic for Startup {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, edges_seen);
        if self.edges_seen.q.val() != self.three.val() {
            self.edges_seen.d.next = self.edges_seen.q.val() + self.one.val();
        }
        if self.reset.val() {
            self.edges_seen.d.next = self.zero.val();
        }
        self.engine_run.next = self.edges_seen.q.val() >= self.two.val();
        self.edge_enable.next = self.edges_seen.q.val() == self.three.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_the_engine_after_two_edges_and_enables_edges_after_three() {
        let mut uut = Startup::default();
        uut.connect_all();
        // Edge 0 with reset, then edges 1, 2, 3, 4 without: (engine_run, edge_enable)
        // after each edge, by hand.
        let expect = [
            (false, false),
            (false, false),
            (true, false),
            (true, true),
            (true, true),
        ];
        for (k, e) in expect.iter().enumerate() {
            uut.reset.next = k == 0;
            uut.clock.next = Clock { clk: false };
            assert!(simulate(&mut uut, 10));
            uut.clock.next = Clock { clk: true };
            assert!(simulate(&mut uut, 10));
            assert_eq!(
                (uut.engine_run.val(), uut.edge_enable.val()),
                *e,
                "after edge {k}"
            );
        }
    }

    #[test]
    fn synthesises() {
        let mut uut = Startup::default();
        uut.connect_all();
        yosys_validate("encspeed_startup", &generate_verilog(&uut)).unwrap();
    }
}
