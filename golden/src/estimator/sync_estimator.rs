// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's Table 1 as one step per clock (ts = one clock period), in the order of
//! docs/design-decisions.md#table1-order, with counters that saturate at the counter width
//! instead of wrapping: the estimator engine of `encspeed_core` (layer 2, bit-true). The
//! whole core, with its quadrature front end, speed calculators and faults, is
//! [`crate::top::core::CoreModel`] (re-exported here); its Rairán pulse `lep` is a decoder
//! step.

use crate::params::{Params, MIN_DT_CYCLES};

/// Outputs of [`Table1`] after a step (the hardware's registers after a clock edge).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Table1Out {
    /// Nep1: encoder pulses counted in the last dt window that started at a pulse.
    pub nep: u64,
    /// Ndt1: whole dt intervals between the last two pulses (1 at high speed).
    pub ndt: u64,
    /// One-cycle strobe: Nep1 or Ndt1 was written by the step just taken.
    pub update: bool,
    /// Zero speed: Cdt has reached the timeout (no pulse for `timeout_dt` dt intervals).
    pub stalled: bool,
}

/// Internal registers of [`Table1`], for waveforms and debugging.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Table1State {
    /// ts counter since the last dt tick or restart ("clock" in Table 1).
    pub clock: u64,
    /// Cep: pulses counted since the last dt tick.
    pub cep: u64,
    /// Cdt: dt ticks counted since the last pulse.
    pub cdt: u64,
    /// Nep1 register.
    pub nep1: u64,
    /// Ndt1 register.
    pub ndt1: u64,
    /// Registered update strobe.
    pub update: bool,
    /// The last step wrote Nep1 (a tick with Cep ≠ 0).
    pub wrote_nep: bool,
    /// The last step was a restart (it wrote Ndt1).
    pub restarted: bool,
}

/// Rairán's Table 1, one step per clock cycle, saturating.
#[derive(Clone, Debug)]
pub struct Table1 {
    counter_max: u64,
    timeout_dt: u64,
    s: Table1State,
}

impl Table1 {
    /// A Table 1 engine in its reset state.
    pub fn new(p: &Params) -> Table1 {
        let mut t = Table1 {
            counter_max: p.counter_max(),
            timeout_dt: p.timeout_dt(),
            s: Table1State::default(),
        };
        t.reset();
        t
    }

    /// Table 1 line 1-2: Cep = Cdt = Nep1 = clock = 0, Ndt1 = 1.
    pub fn reset(&mut self) {
        self.s = Table1State {
            ndt1: 1,
            ..Table1State::default()
        };
    }

    /// Reset, with the pulse `lep` of the same cycle counted as the first of the new
    /// measurement (Cep = 1): the state a restart at that pulse leaves, with Nep1 and Ndt1
    /// cleared. The core does this at the first step of each direction, so that the first
    /// window after reset or a reversal starts at a pulse, as every later one does.
    pub fn reset_with_pulse(&mut self, lep: bool) {
        self.reset();
        if lep {
            self.s.cep = 1;
        }
    }

    /// The registers as they stand.
    pub fn state(&self) -> Table1State {
        self.s
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> Table1Out {
        Table1Out {
            nep: self.s.nep1,
            ndt: self.s.ndt1,
            update: self.s.update,
            stalled: self.s.cdt >= self.timeout_dt,
        }
    }

    /// One ts step with encoder pulse `lep` and dt = `cfg_dt` clock cycles. A `cfg_dt`
    /// below 2 is treated as 2 (the hardware flags it on `cfg_error`). The dt comparison is
    /// `clock + 1 >= dt` rather than `==`, so that lowering `cfg_dt` at run time ends the
    /// current interval at once instead of letting the ts counter run to its limit; with a
    /// constant dt the two are the same.
    pub fn step(&mut self, lep: bool, cfg_dt: u64) -> Table1Out {
        assert!(
            cfg_dt <= self.counter_max,
            "cfg_dt = {cfg_dt} does not fit the {}-wide port",
            self.counter_max
        );
        let max = self.counter_max;
        let sat_inc = |v: u64| if v == max { v } else { v + 1 };
        let s = self.s;
        let dt = cfg_dt.max(MIN_DT_CYCLES);
        // line 4-7: a pulse after at least one dt tick restarts the time base.
        let restart = lep && s.cdt != 0;
        // line 8 and 12: clock == dt (never after a restart: dt >= 2 > 0).
        let clock_plus = s.clock + 1;
        let tick = !restart && clock_plus >= dt;
        // line 9
        let nep_write = tick && s.cep != 0;
        let mut n = s;
        n.clock = if restart || tick { 0 } else { clock_plus };
        if nep_write {
            n.nep1 = s.cep;
        }
        if restart {
            n.ndt1 = s.cdt;
        }
        // line 10-11 then 13: a pulse on the tick is counted and then cleared with Cep.
        let cep_after_pulse = if lep { sat_inc(s.cep) } else { s.cep };
        let cdt_after_pulse = if lep { 0 } else { s.cdt };
        n.cep = if tick { 0 } else { cep_after_pulse };
        n.cdt = if tick {
            sat_inc(cdt_after_pulse)
        } else {
            cdt_after_pulse
        };
        n.update = nep_write || restart;
        n.wrote_nep = nep_write;
        n.restarted = restart;
        self.s = n;
        self.outputs()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Spec;

    fn params(dt: u64) -> Params {
        Params::new(Spec {
            clock_hz: 1e6,
            lines: 100,
            dt_cycles: dt,
            counter_bits: 8,
            timeout_s: 10.0 * dt as f64 / 1e6,
            ..Spec::default()
        })
        .unwrap()
    }

    /// Run Table 1 on a pulse train of period `period` cycles (first pulse at `phase`).
    fn run_pulses(t: &mut Table1, dt: u64, period: u64, phase: u64, cycles: u64) -> Vec<Table1Out> {
        (1..=cycles)
            .map(|k| t.step(k >= phase && (k - phase).is_multiple_of(period), dt))
            .collect()
    }

    #[test]
    fn hand_worked_high_speed_example() {
        // dt = 10, pulses every 3 cycles starting at cycle 1: r = 10/3, ceil = 4.
        // Cycle 1: pulse, Cdt = 0 so no restart, Cep = 1. Pulses at 4, 7 → Cep = 3.
        // Cycle 10: tick, Nep1 = 3 (window from reset, not from a pulse), Cdt = 1 and the
        // pulse at 10 is counted then cleared. Cycle 13: pulse with Cdt = 1: restart,
        // Ndt1 = 1, Cep = 1. Pulses 16, 19, 22 → Cep = 4; tick at 23: Nep1 = 4 = ceil(r).
        let mut t = Table1::new(&params(10));
        let out = run_pulses(&mut t, 10, 3, 1, 23);
        assert_eq!(out[9].nep, 3);
        assert!(out[9].update);
        assert_eq!(out[12].ndt, 1);
        assert!(out[12].update);
        assert_eq!(out[21].nep, 3);
        assert_eq!(out[22].nep, 4);
        assert!(out[22].update);
        assert_eq!(t.state().clock, 0);
    }

    #[test]
    fn hand_worked_low_speed_example() {
        // dt = 10, pulses every 25 cycles from cycle 5: ticks at 10, 20 → Cdt = 2 at the
        // pulse at 30: Ndt1 = floor(25/10) = 2, clock restarts; ticks at 40, 50 → Cdt = 2
        // at 55 again. Nep1 = 1 from the tick after each pulse.
        let mut t = Table1::new(&params(10));
        let out = run_pulses(&mut t, 10, 25, 5, 60);
        assert_eq!(out[29].ndt, 2);
        assert_eq!(out[39].nep, 1);
        assert_eq!(out[54].ndt, 2);
        assert_eq!(out[59].nep, 1);
    }

    #[test]
    fn counters_saturate_and_timeout_flags() {
        // 8-bit counters, timeout 10 dt intervals: without pulses Cdt climbs to 10 and
        // `stalled` rises; it keeps climbing to 255 and stays there.
        let p = params(2);
        let mut t = Table1::new(&p);
        t.step(true, 2);
        let out = run_pulses(&mut t, 2, u64::MAX, u64::MAX, 2 * 300);
        assert_eq!(t.state().cdt, 255);
        let first_stall = out.iter().position(|o| o.stalled).unwrap() as u64;
        // Ticks at cycles 2, 4, …: the 10th tick after the pulse.
        assert_eq!(first_stall + 2, 2 * 10);
        // A pulse now writes the saturated count and clears the stall.
        let o = t.step(true, 2);
        assert_eq!(o.ndt, 255);
        assert!(!o.stalled);
    }
}
