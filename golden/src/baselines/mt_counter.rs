// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of the M/T counter `hdl::MtCounter<N>` (Ohmae 1982), and the M/T error
//! bound at a given speed.
//!
//! The counter measures, per window of the free-running time base
//! [`crate::baselines::window_timer::WindowTimer`] (cfg_dt cycles, the same tick as the PC counter), the
//! integers m and T of [`crate::ideal::mt`]: m = steps since the step that closed the previous
//! measurement (the *anchor*), T = clock cycles from the anchor to the last of those steps.
//! The speed m·dt/T (units of ω_lim) is left to a divider downstream.
//!
//! # Semantics (per rising clock edge, N = `bits`, 2..=32; max = 2^N − 1; x⁺ = min(x + 1, max))
//! Inputs sampled at the edge: `reset`, `step`, `forward`, `cfg_dt`. Registers: the time base
//! ([`WindowTimer`]), `anchored`, `have_dir`, `dir`, m (steps since the anchor), a (cycles since
//! the anchor), span (a at the last step), l (cycles since the last step); all saturating.
//!
//! 1. rev = step ∧ have_dir ∧ (forward ≠ dir) (a reversal); cont = step ∧ ¬rev.
//! 2. The measurement including this edge: m' = cont ? m⁺ : m, span' = cont ? a⁺ : span,
//!    l' = cont ? 0 : l⁺ (a reversing step is *not* part of it).
//! 3. Window end (tick): if `anchored`, `strobe` ← 1, `negative` ← ¬dir, `m` ← m' and
//!    `t` ← span' if m' ≥ 1, else `t` ← l' (the cycles since the last step, from which the
//!    consumer bounds the speed by dt/t as [`crate::ideal::mt::mt_estimates`] does). If m' ≥ 1 the
//!    last step becomes the new anchor: `anchored` ← 1, a ← l', m ← 0, span ← 0 (this is how
//!    the first anchor is set after reset, with no output, as in [`crate::ideal::mt`]). If m' = 0:
//!    a ← a⁺. Either way m, span ← 0.
//!    Not a window end: `strobe` ← 0, m ← m', span ← span', a ← a⁺.
//!    In both cases l ← l'.
//! 4. A reversal (after the window end of the same edge, which closes the old direction's
//!    measurement without it) restarts the measurement on the reversing step: `anchored` ← 1,
//!    m, a, span, l ← 0. The next window gives m steps of the new direction only, timed
//!    from that step (or m = 0 and the cycles since it), never a mix of signs.
//! 5. `have_dir` ← have_dir ∨ step; on a step `dir` ← forward.
//!
//! A window is closed: it holds the steps sampled at the edges (tick_w, tick_{w+1}], the
//! convention of [`crate::ideal::mt::mt_estimates`] (a pulse stamped at or before the sample
//! instant is seen by it) with pulse instants at their sampling edges. m never exceeds the
//! window length, so it never saturates; T saturates at max when the anchor is older than
//! max cycles (then T means "at least max"); `stalled` = (l = max).
//!
//! Reset (synchronous, active high, wins): every register 0 (the time base takes the reset
//! edge's cfg_dt, [`WindowTimer`]). Power-up is the state after a reset with cfg_dt ≥ 2.
//!
//! # Latency
//! The outputs are registers written by the window-end edge: a step sampled at edge j is
//! in the `m`, `t` published after the first window-end edge at or after j.
//!
//! # Error bound (see [`mt_error_bound_at_speed`])
//! At constant speed r (units of ω_lim), window D cycles, pulses P = D/r cycles apart.
//! Each pulse instant t is stamped at the first clock edge at or after it, j = ⌈t⌉. The
//! anchor is the last step at or before the previous window end, so (in steady state) the m
//! steps of a measurement are exactly the steps of the window: D consecutive edges, which
//! are the stamps of the pulses in a real interval D cycles long, hence ⌊r⌋ or ⌈r⌉ of them
//! (0 or 1 when r < 1). An estimate (m ≥ 1) therefore has m ≥ max(1, ⌊r⌋) and a true span
//! T = m·P ≥ T_min = max(1, ⌊r⌋)·P. The stamps are in [t, t + 1), so the measured T̂ is an
//! integer with |T̂ − T| < 1 and the relative error of m·D/T̂ is
//! |T/T̂ − 1| < 1/T̂ ([`crate::ideal::mt::mt_error_bound`]). With T_min = max(1, ⌊r⌋)·P, T̂ > T_min − 1
//! so T̂ ≥ ⌊T_min⌋, hence the bound 1/⌊max(1, ⌊r⌋)·D/r⌋, about 1/D for r ≥ 1 and 1/⌊P⌋ (the
//! ET bound) below. Windows with m = 0 are decay bounds, not estimates, and are excluded.

use crate::baselines::pc_counter::unsigned_max;
use crate::baselines::window_timer::WindowTimer;

/// Inputs of an [`MtCounter`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MtInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// One step of the decoder in this cycle.
    pub step: bool,
    /// The step is forward (ignored without `step`).
    pub forward: bool,
    /// Window length, clock cycles (N bits; 0 counts as 1).
    pub cfg_dt: u64,
}

/// Outputs of an [`MtCounter`] after a clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MtOutputs {
    /// Steps in the measurement (0: none since the anchor).
    pub m: u64,
    /// m ≥ 1: cycles from the anchor to the last step; m = 0: cycles since the last step
    /// (both saturated at 2^N − 1).
    pub t: u64,
    /// The measurement is of backward steps.
    pub negative: bool,
    /// High for one cycle: this window-end edge wrote `m`, `t`, `negative`.
    pub strobe: bool,
    /// No step for 2^N − 1 cycles or more.
    pub stalled: bool,
}

/// M/T counter, bit-true model of `hdl::MtCounter<N>` (module docs).
#[derive(Clone, Debug)]
pub struct MtCounter {
    bits: u32,
    timer: WindowTimer,
    anchored: bool,
    have_dir: bool,
    dir: bool,
    m: u64,
    age: u64,
    span: u64,
    last: u64,
    out: MtOutputs,
}

impl MtCounter {
    /// A counter with N = `bits` (2..=32) wide counters and `cfg_dt`, at power-up.
    pub fn new(bits: u32) -> MtCounter {
        unsigned_max(bits);
        MtCounter {
            bits,
            timer: WindowTimer::new(),
            anchored: false,
            have_dir: false,
            dir: false,
            m: 0,
            age: 0,
            span: 0,
            last: 0,
            out: MtOutputs::default(),
        }
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> MtOutputs {
        self.out
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: MtInputs) -> MtOutputs {
        let max = unsigned_max(self.bits);
        assert!(inp.cfg_dt <= max, "cfg_dt {} does not fit", inp.cfg_dt);
        let tick = self.timer.step(inp.reset, inp.cfg_dt);
        if inp.reset {
            *self = MtCounter {
                timer: self.timer,
                ..MtCounter::new(self.bits)
            };
            return self.out;
        }
        let inc = |x: u64| (x + 1).min(max);
        let rev = inp.step && self.have_dir && inp.forward != self.dir;
        let cont = inp.step && !rev;
        let m_now = if cont { inc(self.m) } else { self.m };
        let span_now = if cont { inc(self.age) } else { self.span };
        let last_now = if cont { 0 } else { inc(self.last) };
        self.out.strobe = tick && self.anchored;
        if tick {
            if self.anchored {
                self.out.m = m_now;
                self.out.t = if m_now != 0 { span_now } else { last_now };
                self.out.negative = !self.dir;
            }
            (self.m, self.span) = (0, 0);
            if m_now != 0 {
                self.anchored = true;
                self.age = last_now;
            } else {
                self.age = inc(self.age);
            }
        } else {
            self.m = m_now;
            self.span = span_now;
            self.age = inc(self.age);
        }
        self.last = last_now;
        if rev {
            self.anchored = true;
            (self.m, self.age, self.span, self.last) = (0, 0, 0, 0);
        }
        self.have_dir |= inp.step;
        if inp.step {
            self.dir = inp.forward;
        }
        self.out.stalled = self.last == max;
        self.out
    }
}

/// Worst-case relative error of an M/T estimate (m ≥ 1) at constant speed r > 0 (units of
/// ω_lim) with a window of `dt_cycles` clock cycles (module docs):
/// 1/⌊max(1, ⌊r⌋)·dt/r⌋.
pub fn mt_error_bound_at_speed(r: f64, dt_cycles: u64) -> f64 {
    assert!(r > 0.0 && dt_cycles >= 1, "bad speed or dt");
    let t_min = r.floor().max(1.0) * dt_cycles as f64 / r;
    assert!(t_min >= 1.0, "pulses closer than one cycle");
    1.0 / t_min.floor()
}
