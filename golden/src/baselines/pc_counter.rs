// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of the fixed-time (pulse count, PC) counter `hdl::PcCounter<N>`, and the
//! PC error bound.
//!
//! # Semantics (per rising clock edge, N = `bits`, 2..=32)
//! Inputs sampled at the edge: `reset`, `step`, `forward` (one-cycle pulses from the
//! quadrature decoder) and `cfg_dt` (window length in clock cycles, N bits, unsigned).
//!
//! 1. Free-running time base, [`WindowTimer`]: the edge is a *window end* (tick) when its
//!    phase p has reached max(cfg_dt, 1) − 1 for the cfg_dt of the edge before; then
//!    p ← 0, else p ← p + 1. Steps never restart it. After a reset at edge 0 and with a
//!    constant cfg_dt = D ≥ 1, the ticks are the edges D, 2D, … A change of cfg_dt acts
//!    one edge later; lowering it ends the current window at the next edge (the comparison
//!    is ≥); cfg_dt = 0 counts as 1 (a window end on every edge).
//! 2. Two unsigned counters, f (forward steps) and b (backward steps), of the current window.
//!    A window is half-open: it holds the steps sampled at the edges [tick, next tick), i.e.
//!    a step sampled on a window-end edge belongs to the *next* window. This is
//!    [`crate::ideal::fixed_time`]'s convention [k·dt, (k+1)·dt) with the pulse instant taken
//!    as the index of the clock edge that samples the step. At a window end: f, b ← this
//!    edge's step; otherwise f, b += this edge's step. A window spans at most 2^N − 1 edges
//!    (p never exceeds 2^N − 2), so f and b never overflow.
//! 3. At a window end the registered outputs take: `count` = clamp(f − b) as N-bit two's
//!    complement, clamped to [−2^(N−1), 2^(N−1) − 1] (saturating, never wrapping; only
//!    possible when cfg_dt > 2^(N−1) − 1), `saturated` = the clamp acted, `strobe` = 1.
//!    Otherwise `strobe` = 0 and `count`, `saturated` hold.
//!
//! Reset (synchronous, active high, wins): p, f, b, count, saturated, strobe ← 0 (and the
//! time base takes the reset edge's cfg_dt, [`WindowTimer`]). Power-up is the state after
//! a reset with cfg_dt ≥ 2.
//!
//! # Latency
//! A step sampled at edge j, with the window [tick_w, tick_{w+1}) containing j, is in the
//! `count` published by edge tick_{w+1} (with `strobe` high after that edge): the outputs
//! are registers written by the window-end edge, no extra pipeline stage.
//!
//! # Error bound (see [`pc_error_bound`])
//! At constant speed r (units of ω_lim = one pulse per dt), pulses are P = D/r cycles apart.
//! Quantising each pulse instant t to the first clock edge at or after it (j = ⌈t⌉) maps
//! the window [kD, (k+1)D) of edges onto the real interval (kD − 1, (k+1)D − 1], still D
//! cycles long: it holds ⌊r⌋ or ⌈r⌉ pulses, exactly as without quantisation. Hence
//! |count − r| < 1 and the relative error is below 1/r (100 % and more at r < 1, where a
//! window often holds no pulse). The clock adds nothing to the count error; it only
//! shifts the windows by under one cycle.

use crate::baselines::window_timer::WindowTimer;

/// Inputs of a [`PcCounter`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PcInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// One step of the decoder in this cycle.
    pub step: bool,
    /// The step is forward (ignored without `step`).
    pub forward: bool,
    /// Window length, clock cycles (N bits; 0 counts as 1).
    pub cfg_dt: u64,
}

/// Outputs of a [`PcCounter`] after a clock edge (all registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PcOutputs {
    /// Net steps (forward − backward) of the last complete window, saturated to N-bit
    /// two's complement.
    pub count: i64,
    /// The last `count` was clamped.
    pub saturated: bool,
    /// High for one cycle: this edge ended a window and wrote `count`.
    pub strobe: bool,
}

/// Fixed-time (PC) counter, bit-true model of `hdl::PcCounter<N>` (module docs).
#[derive(Clone, Debug)]
pub struct PcCounter {
    bits: u32,
    timer: WindowTimer,
    fwd: u64,
    bwd: u64,
    out: PcOutputs,
}

/// Largest value of an unsigned `bits`-wide register.
pub(crate) fn unsigned_max(bits: u32) -> u64 {
    assert!((2..=32).contains(&bits), "width {bits} outside 2..=32");
    (1u64 << bits) - 1
}

impl PcCounter {
    /// A counter with N = `bits` (2..=32) wide `cfg_dt` and `count`, at power-up.
    pub fn new(bits: u32) -> PcCounter {
        unsigned_max(bits);
        PcCounter {
            bits,
            timer: WindowTimer::new(),
            fwd: 0,
            bwd: 0,
            out: PcOutputs::default(),
        }
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> PcOutputs {
        self.out
    }

    /// Largest count, 2^(N−1) − 1.
    pub fn count_max(&self) -> i64 {
        (1i64 << (self.bits - 1)) - 1
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: PcInputs) -> PcOutputs {
        let max = unsigned_max(self.bits);
        assert!(inp.cfg_dt <= max, "cfg_dt {} does not fit", inp.cfg_dt);
        let tick = self.timer.step(inp.reset, inp.cfg_dt);
        if inp.reset {
            *self = PcCounter {
                timer: self.timer,
                ..PcCounter::new(self.bits)
            };
            return self.out;
        }
        let f_in = u64::from(inp.step && inp.forward);
        let b_in = u64::from(inp.step && !inp.forward);
        self.out.strobe = tick;
        if tick {
            let net = self.fwd as i64 - self.bwd as i64;
            let (hi, lo) = (self.count_max(), -self.count_max() - 1);
            self.out.count = net.clamp(lo, hi);
            self.out.saturated = net > hi || net < lo;
            (self.fwd, self.bwd) = (f_in, b_in);
        } else {
            self.fwd += f_in;
            self.bwd += b_in;
        }
        assert!(
            self.fwd <= max && self.bwd <= max,
            "window counters overflow"
        );
        self.out
    }
}

/// Worst-case relative error |count/r − 1| of a PC count at constant speed r > 0 (units of
/// ω_lim), with or without clock quantisation (module docs): the count is ⌊r⌋ or ⌈r⌉, so
/// the error is below 1/r.
pub fn pc_error_bound(r: f64) -> f64 {
    assert!(r > 0.0, "speed must be > 0");
    1.0 / r
}
