// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of the fixed-space (elapsed time, ET) timer `hdl::EtTimer<N>`, and the
//! ET error bound.
//!
//! # Semantics (per rising clock edge, N = `bits`, 2..=32; max = 2^N − 1)
//! Inputs sampled at the edge: `reset`, `step`, `forward` (one-cycle pulses from the
//! quadrature decoder). Registers: e (cycles since the last step, saturating at max),
//! `armed` (a step has been seen since reset or since the last reversal), `dir` (direction
//! of that step). Let e⁺ = min(e + 1, max).
//!
//! - No step: e ← e⁺; `strobe` ← 0.
//! - Step, `armed` and `forward` = `dir`: `period` ← e⁺ (the clock edges from the previous
//!   step's edge to this one, saturated at max), `negative` ← ¬`forward`, `strobe` ← 1;
//!   then e ← 0.
//! - Step otherwise (the first after reset, or a *reversal*: `forward` ≠ `dir`): no period
//!   and no strobe (`period`, `negative` hold); `armed` ← 1, `dir` ← `forward`, e ← 0. So a
//!   reversal never produces a period that mixes the two directions (no spike): the first
//!   period in the new direction is measured from the reversing step.
//! - `stalled` = (e = max): no step for at least 2^N − 1 cycles (zero speed, timeout). The
//!   next step then gives `period` = max, meaning "at least max".
//!
//! Reset (synchronous, active high, wins): every register 0.
//!
//! # Latency
//! A step sampled at edge j gives its `period` and `strobe` after edge j itself (registered
//! outputs, no extra stage). The period is j − j_prev, [`crate::ideal::fixed_space`]'s tick
//! count with a time quantum of one clock cycle and pulse instants at the sampling edges;
//! the speed is r = dt/period in units of ω_lim for a time base of dt cycles.
//!
//! # Error bound (see [`et_error_bound`])
//! At constant speed the pulses are P cycles apart; quantised to the clock (j = ⌈t⌉) the
//! measured period is ⌊P⌋ or ⌈P⌉, i.e. |period − P| < 1. The relative error of
//! dt/period is |P/period − 1| = |P − period|/period, largest when period = ⌊P⌋:
//! (P − ⌊P⌋)/⌊P⌋ < 1/⌊P⌋ (0 when P is a whole number of cycles).

use crate::baselines::pc_counter::unsigned_max;

/// Inputs of an [`EtTimer`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EtInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// One step of the decoder in this cycle.
    pub step: bool,
    /// The step is forward (ignored without `step`).
    pub forward: bool,
}

/// Outputs of an [`EtTimer`] after a clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EtOutputs {
    /// Clock cycles between the last two steps of one direction (saturated at 2^N − 1).
    pub period: u64,
    /// The last period was measured backward.
    pub negative: bool,
    /// High for one cycle: this edge wrote `period`.
    pub strobe: bool,
    /// The running count has saturated: no step for 2^N − 1 cycles or more.
    pub stalled: bool,
}

/// Fixed-space (ET) timer, bit-true model of `hdl::EtTimer<N>` (module docs).
#[derive(Clone, Debug)]
pub struct EtTimer {
    bits: u32,
    elapsed: u64,
    armed: bool,
    dir: bool,
    out: EtOutputs,
}

impl EtTimer {
    /// A timer with N = `bits` (2..=32) wide counters, after reset.
    pub fn new(bits: u32) -> EtTimer {
        unsigned_max(bits);
        EtTimer {
            bits,
            elapsed: 0,
            armed: false,
            dir: false,
            out: EtOutputs::default(),
        }
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> EtOutputs {
        self.out
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: EtInputs) -> EtOutputs {
        let max = unsigned_max(self.bits);
        if inp.reset {
            *self = EtTimer::new(self.bits);
            return self.out;
        }
        let e_inc = (self.elapsed + 1).min(max);
        self.out.strobe = false;
        if inp.step {
            if self.armed && inp.forward == self.dir {
                self.out.period = e_inc;
                self.out.negative = !inp.forward;
                self.out.strobe = true;
            }
            self.armed = true;
            self.dir = inp.forward;
            self.elapsed = 0;
        } else {
            self.elapsed = e_inc;
        }
        self.out.stalled = self.elapsed == max;
        self.out
    }
}

/// Worst-case relative error of an ET speed dt/period at constant speed, when the true
/// pulse period is `period_cycles` (≥ 1) clock cycles (module docs): 1/⌊P⌋.
pub fn et_error_bound(period_cycles: f64) -> f64 {
    assert!(period_cycles >= 1.0, "period below one cycle");
    1.0 / period_cycles.floor()
}
