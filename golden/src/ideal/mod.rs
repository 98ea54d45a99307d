// SPDX-License-Identifier: MIT OR Apache-2.0
//! Layer-1 float estimators in continuous time: Rairán's synchronised estimator (Table 1)
//! and the classical fixed-time (PC) and fixed-space (ET) baselines.
//!
//! Input is the exact pulse instants (s) of the encoder — the rising edges of A, e.g.
//! [`crate::ideal::plant::pulse_times`]`(edges, Channel::A, true)` — sorted, finite and ≥ 0.
//! Every speed estimate is in units of ω_lim = 1/(lines·dt) rev/s, the speed at which
//! consecutive pulses are exactly dt apart; r = ω/ω_lim is the true speed in those units.
//!
//! # Simultaneous pulse and tick
//! Table 1 orders what happens when a pulse and a dt tick fall in the same step, and at
//! speeds that are integer multiples (or integer fractions) of ω_lim they do coincide
//! every cycle. Ticks are therefore generated as t_restart + k·dt (no accumulated sum) and
//! a pulse within [`COINCIDENCE_REL`]·t of a tick counts as simultaneous with it: a few
//! ulps, enough to absorb the rounding of n·T against t_restart + k·dt when a test builds
//! an exact coincidence, far too little to merge instants that are really distinct.
//!
//! # Update interval (why not eq. (1))
//! At constant speed with r > 1 non-integer a cycle is: a pulse restarts the dt base, the
//! tick dt later writes Nep1, and the first pulse after the tick restarts again and writes
//! Ndt1. That pulse is the ⌈r⌉-th after the restart, so both registers update every
//! ⌈r⌉·T = ⌈r⌉/r·dt (T = dt/r the pulse period). At integer r the pulse coinciding with
//! the tick is counted and then cleared by the tick (it is dropped), so the cycle is
//! (r+1)·T. Both cases are (⌊r⌋+1)/r·dt. The paper's eq. (1),
//! dt_a = (−r/⌊r⌋ + 2 + 1/⌊r⌋)·dt, equals this at integer r and at the left limits
//! r → n+1, and is the straight chord between them: it lies above the convex (⌊r⌋+1)/r
//! in between, so it is an upper bound, not the interval. See [`update_interval`].
//! For r < 1 both registers update once per pulse period T.

pub mod mt;
pub mod plant;

use std::fmt;

/// Relative tolerance under which a pulse and a tick are the same instant (see the module
/// docs): 16 ulps of the time.
pub const COINCIDENCE_REL: f64 = 16.0 * f64::EPSILON;

/// Why an estimator run was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum IdealError {
    /// dt (s) must be finite and > 0.
    BadDt(f64),
    /// At least one line per revolution.
    ZeroLines,
    /// The ET time quantum (s) must be finite and > 0.
    BadQuantum(f64),
    /// The end time (s) must be finite.
    BadEnd(f64),
    /// A pulse instant that is not finite, is negative, or precedes its predecessor.
    BadPulse {
        /// Position in the pulse list.
        index: usize,
        /// The offending instant (s).
        t: f64,
    },
}

impl fmt::Display for IdealError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadDt(dt) => write!(f, "dt {dt} s must be finite and > 0"),
            Self::ZeroLines => write!(f, "encoder must have at least one line per revolution"),
            Self::BadQuantum(q) => write!(f, "time quantum {q} s must be finite and > 0"),
            Self::BadEnd(t) => write!(f, "end time {t} s must be finite"),
            Self::BadPulse { index, t } => write!(
                f,
                "pulse {index} at {t} s: pulses must be finite, >= 0 and in time order"
            ),
        }
    }
}

impl std::error::Error for IdealError {}

fn check_positive(v: f64, err: fn(f64) -> IdealError) -> Result<(), IdealError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(err(v))
    }
}

fn check_pulses(pulses: &[f64]) -> Result<(), IdealError> {
    let mut prev = 0.0;
    for (index, &t) in pulses.iter().enumerate() {
        if !(t.is_finite() && t >= prev) {
            return Err(IdealError::BadPulse { index, t });
        }
        prev = t;
    }
    Ok(())
}

/// n1 = Nep1/Ndt1 (units of ω_lim): the paper's upper estimate. `ndt1` ≥ 1 (0 gives a
/// non-finite result).
pub fn n1(nep1: u64, ndt1: u64) -> f64 {
    nep1 as f64 / ndt1 as f64
}

/// n2, eq. (6) (units of ω_lim): the lower estimate, (Nep1−1)/Ndt1 when n1 ≥ 2 (high
/// speed), else Nep1/(Ndt1+1). The paper splits on ω ≥ ω_lim, which is unknown; n1 ≥ 2 is
/// the observable test it names.
pub fn n2(nep1: u64, ndt1: u64) -> f64 {
    if n1(nep1, ndt1) >= 2.0 {
        (nep1 - 1) as f64 / ndt1 as f64
    } else {
        nep1 as f64 / (ndt1 + 1) as f64
    }
}

/// n3, eq. (11) (units of ω_lim): harmonic mean 2/(1/n1 + 1/n2), the estimate with the
/// smallest worst-case relative error (eq. 13). Defined as 0 when Nep1 = 0 (no speed seen).
pub fn n3(nep1: u64, ndt1: u64) -> f64 {
    let (a, b) = (n1(nep1, ndt1), n2(nep1, ndt1));
    if nep1 == 0 {
        0.0
    } else {
        2.0 * a * b / (a + b)
    }
}

/// Interval (units of dt) between updates of each register at constant speed r = ω/ω_lim
/// (r > 0), as derived in the module docs: 1/r for r < 1, (⌊r⌋+1)/r for r ≥ 1. The paper's
/// eq. (1) is the chord above this curve.
pub fn update_interval(r: f64) -> f64 {
    if r < 1.0 {
        1.0 / r
    } else {
        (r.floor() + 1.0) / r
    }
}

/// One instant at which Table 1 wrote Nep1 and/or Ndt1, with the register values after it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Update {
    /// Instant (s).
    pub t: f64,
    /// Nep1: pulses counted in the last dt window (held).
    pub nep1: u64,
    /// Ndt1: whole dt intervals between the last two pulses (held, ≥ 1).
    pub ndt1: u64,
    /// Nep1 was written at this instant (possibly with its old value).
    pub wrote_nep: bool,
    /// Ndt1 was written at this instant.
    pub wrote_ndt: bool,
}

impl Update {
    /// [`n1`] of these registers (units of ω_lim).
    pub fn n1(&self) -> f64 {
        n1(self.nep1, self.ndt1)
    }
    /// [`n2`] of these registers (units of ω_lim).
    pub fn n2(&self) -> f64 {
        n2(self.nep1, self.ndt1)
    }
    /// [`n3`] of these registers (units of ω_lim).
    pub fn n3(&self) -> f64 {
        n3(self.nep1, self.ndt1)
    }
}

/// Rairán's synchronised estimator (Table 1) in continuous time.
///
/// Per event instant (a pulse, a tick, or both), in this order:
/// 1. pulse and Cdt ≠ 0: Ndt1 ← Cdt, restart the dt base (next tick = now + dt; a tick
///    due now is cancelled);
/// 2. tick and Cep ≠ 0: Nep1 ← Cep;
/// 3. pulse: Cep += 1, Cdt ← 0;
/// 4. tick: Cdt += 1, Cep ← 0, next tick = now + dt.
///
/// Reset: Cep = Cdt = Nep1 = 0, Ndt1 = 1, first tick at t = dt.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RairanIdeal {
    dt: f64,
    lines: u32,
}

impl RairanIdeal {
    /// Estimator with time base `dt` (s) for an encoder of `lines` pulses per revolution.
    pub fn new(dt: f64, lines: u32) -> Result<Self, IdealError> {
        check_positive(dt, IdealError::BadDt)?;
        if lines == 0 {
            return Err(IdealError::ZeroLines);
        }
        Ok(Self { dt, lines })
    }

    /// The time base dt (s).
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Pulses per revolution.
    pub fn lines(&self) -> u32 {
        self.lines
    }

    /// ω_lim = 1/(lines·dt) (rev/s): multiply any n by this to get rev/s.
    pub fn omega_lim(&self) -> f64 {
        1.0 / (f64::from(self.lines) * self.dt)
    }

    /// Runs Table 1 over all events with t ≤ `t_end` (s) and returns every instant at which
    /// a register was written. Several pulses at one instant are taken one after another.
    pub fn run(&self, pulses: &[f64], t_end: f64) -> Result<Vec<Update>, IdealError> {
        check_pulses(pulses)?;
        if !t_end.is_finite() {
            return Err(IdealError::BadEnd(t_end));
        }
        let (mut cep, mut cdt, mut nep1, mut ndt1) = (0u64, 0u64, 0u64, 1u64);
        // Next tick at base + k·dt: computed afresh, so it does not drift by summing dt.
        let (mut base, mut k) = (0.0f64, 1u64);
        let mut next_pulse = pulses.iter().copied().peekable();
        let mut out = Vec::new();
        loop {
            let tick_t = base + k as f64 * self.dt;
            let (now, lep, mut tick) = match next_pulse.peek() {
                Some(&tp) if (tp - tick_t).abs() <= COINCIDENCE_REL * tp.max(tick_t) => {
                    (tp, true, true)
                }
                Some(&tp) if tp < tick_t => (tp, true, false),
                _ => (tick_t, false, true),
            };
            if now > t_end {
                return Ok(out);
            }
            if lep {
                next_pulse.next();
            }
            let (mut wrote_nep, mut wrote_ndt) = (false, false);
            if lep && cdt != 0 {
                ndt1 = cdt;
                wrote_ndt = true;
                (base, k) = (now, 1);
                tick = false;
            }
            if tick && cep != 0 {
                nep1 = cep;
                wrote_nep = true;
            }
            if lep {
                cep += 1;
                cdt = 0;
            }
            if tick {
                cdt += 1;
                cep = 0;
                k += 1;
            }
            if wrote_nep || wrote_ndt {
                out.push(Update {
                    t: now,
                    nep1,
                    ndt1,
                    wrote_nep,
                    wrote_ndt,
                });
            }
        }
    }
}

/// One output of a classical estimator: speed `n` (units of ω_lim) available at `t` (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Instant the estimate becomes available (s).
    pub t: f64,
    /// Estimated speed (units of ω_lim = 1/(lines·dt)).
    pub n: f64,
}

/// Fixed-time (PC) estimator: pulses counted in each window [k·dt, (k+1)·dt) of a grid
/// free-running from t = 0, output at (k+1)·dt for every window ending by `t_end` (s).
/// The count is the speed in units of ω_lim; at constant non-integer r it dithers
/// between ⌊r⌋ and ⌈r⌉.
pub fn fixed_time(pulses: &[f64], dt: f64, t_end: f64) -> Result<Vec<Estimate>, IdealError> {
    check_positive(dt, IdealError::BadDt)?;
    check_pulses(pulses)?;
    if !t_end.is_finite() {
        return Err(IdealError::BadEnd(t_end));
    }
    let mut out = Vec::new();
    let mut p = 0usize;
    for k in 1u64.. {
        let end = k as f64 * dt;
        if end > t_end {
            break;
        }
        let first = p;
        while p < pulses.len() && pulses[p] < end {
            p += 1;
        }
        out.push(Estimate {
            t: end,
            n: (p - first) as f64,
        });
    }
    Ok(out)
}

/// Fixed-space (ET) estimator: for each pair of consecutive pulses, N = ticks of a grid
/// k·`q` (s, from t = 0) in (t_i, t_{i+1}], and the estimate dt/(N·q) in units of ω_lim
/// (+∞ when N = 0), output at t_{i+1}. Grid indices are ⌊t/q⌋ with correctly rounded
/// division, so a pulse within an ulp of a grid tick may fall on either side of it.
pub fn fixed_space(pulses: &[f64], dt: f64, q: f64) -> Result<Vec<Estimate>, IdealError> {
    check_positive(dt, IdealError::BadDt)?;
    check_positive(q, IdealError::BadQuantum)?;
    check_pulses(pulses)?;
    Ok(pulses
        .windows(2)
        .map(|w| {
            let ticks = (w[1] / q).floor() - (w[0] / q).floor();
            let n = if ticks > 0.0 {
                dt / (ticks * q)
            } else {
                f64::INFINITY
            };
            Estimate { t: w[1], n }
        })
        .collect())
}
