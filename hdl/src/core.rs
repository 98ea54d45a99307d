//! `encspeed_core`: the top of the IP.
//!
//! ```text
//! enc_a ─ TwoFlopSync ─ RisingEdge ─ lep ─┬─ Timebase ── tick, restart, Cdt ─┐   stalled
//!                            ▲             └──────────────── SyncEstimator ──┴─ nep, ndt, update
//!                 Startup ───┴─ (holds Timebase and SyncEstimator in reset for 2 edges,
//!                               masks the edge detector for the 3rd)
//! ```
//!
//! Ports (all synchronous to `clock`, reset synchronous and active high):
//! - `enc_a`, `enc_b`, `enc_z`: raw encoder channels (asynchronous). The x1 estimator uses
//!   A only; B and Z are reserved for quadrature decoding and the index.
//! - `cfg_dt[N-1:0]`: dt in clock cycles, registered: a change takes effect one cycle later
//!   (values below 2 are used as 2 and flag `cfg_error`).
//! - `nep[N-1:0]`, `ndt[N-1:0]`: Nep1 and Ndt1 of Rairán's Table 1 (0 and 1 after reset).
//! - `update`: one cycle high when `nep` or `ndt` has just been written.
//! - `stalled`: no pulse for the zero-speed timeout.
//! - `cfg_error`: `cfg_dt` < 2 (combinational from `cfg_dt`).
//!
//! Latency: the core is Table 1 run on the samples of `enc_a` taken at each clock edge after
//! reset, delayed by 2 clock cycles (see `golden::bittrue`).

use crate::rising_edge::RisingEdge;
use crate::startup::Startup;
use crate::sync_estimator::SyncEstimator;
use crate::timebase::Timebase;
use crate::two_flop_sync::TwoFlopSync;
use golden::params::Params;
use rust_hdl::prelude::*;

/// The encoder speed core with N-bit counters.
#[derive(LogicBlock)]
pub struct EncspeedCore<const N: usize> {
    /// Core clock; one Table 1 step per cycle.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Encoder channel A.
    pub enc_a: Signal<In, Bit>,
    /// Encoder channel B (reserved).
    pub enc_b: Signal<In, Bit>,
    /// Encoder index Z (reserved).
    pub enc_z: Signal<In, Bit>,
    /// dt in clock cycles.
    pub cfg_dt: Signal<In, Bits<N>>,
    /// Nep1.
    pub nep: Signal<Out, Bits<N>>,
    /// Ndt1.
    pub ndt: Signal<Out, Bits<N>>,
    /// Nep1 or Ndt1 just written.
    pub update: Signal<Out, Bit>,
    /// Zero-speed timeout reached.
    pub stalled: Signal<Out, Bit>,
    /// `cfg_dt` below 2.
    pub cfg_error: Signal<Out, Bit>,
    pub(crate) sync_a: TwoFlopSync,
    pub(crate) startup: Startup,
    pub(crate) edge_a: RisingEdge,
    pub(crate) timebase: Timebase<N>,
    pub(crate) table1: SyncEstimator<N>,
    engine_reset: Signal<Local, Bit>,
    min_dt: Constant<Bits<N>>,
}

impl<const N: usize> EncspeedCore<N> {
    /// Build the core for validated parameters. Panics if `N` is not the parameters'
    /// counter width (the dispatch in [`crate::build_core`] guarantees it).
    pub fn new(p: &Params) -> Self {
        assert_eq!(p.counter_bits() as usize, N, "counter width mismatch");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            enc_a: Default::default(),
            enc_b: Default::default(),
            enc_z: Default::default(),
            cfg_dt: Default::default(),
            nep: Default::default(),
            ndt: Default::default(),
            update: Default::default(),
            stalled: Default::default(),
            cfg_error: Default::default(),
            sync_a: Default::default(),
            startup: Default::default(),
            edge_a: Default::default(),
            timebase: Timebase::new(p.timeout_dt()),
            table1: Default::default(),
            engine_reset: Default::default(),
            min_dt: Constant::new(golden::params::MIN_DT_CYCLES.into()),
        }
    }
}

impl<const N: usize> Logic for EncspeedCore<N> {
    #[hdl_gen]
    fn update(&mut self) {
        self.sync_a.clock.next = self.clock.val();
        self.startup.clock.next = self.clock.val();
        self.edge_a.clock.next = self.clock.val();
        self.timebase.clock.next = self.clock.val();
        self.table1.clock.next = self.clock.val();

        self.engine_reset.next = self.reset.val() | !self.startup.engine_run.val();
        self.sync_a.reset.next = self.reset.val();
        self.startup.reset.next = self.reset.val();
        self.edge_a.reset.next = self.reset.val();
        self.timebase.reset.next = self.engine_reset.val();
        self.table1.reset.next = self.engine_reset.val();

        self.sync_a.level_in.next = self.enc_a.val();
        self.edge_a.level.next = self.sync_a.level_out.val();
        self.edge_a.enable.next = self.startup.edge_enable.val();
        self.timebase.lep.next = self.edge_a.pulse.val();
        self.timebase.dt.next = self.cfg_dt.val();
        self.table1.lep.next = self.edge_a.pulse.val();
        self.table1.tick.next = self.timebase.tick.val();
        self.table1.restart.next = self.timebase.restart.val();
        self.table1.cdt.next = self.timebase.cdt.val();

        self.nep.next = self.table1.nep.val();
        self.ndt.next = self.table1.ndt.val();
        self.update.next = self.table1.update.val();
        self.stalled.next = self.timebase.stalled.val();
        self.cfg_error.next = self.cfg_dt.val() < self.min_dt.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn synthesises() {
        let p = Params::new(golden::params::Spec {
            counter_bits: 12,
            dt_cycles: 1000,
            timeout_s: 1e-3,
            ..Default::default()
        })
        .unwrap();
        let mut uut = EncspeedCore::<12>::new(&p);
        uut.connect_all();
        yosys_validate("encspeed_core", &generate_verilog(&uut)).unwrap();
    }
}
