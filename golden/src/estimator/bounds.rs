// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's error bounds and the error budget of the clock-quantised hardware.
//!
//! The paper's bounds assume exact pulse instants. The hardware sees each pulse at the
//! first clock edge after it, so a pulse interval measured in clock cycles is off by less
//! than one cycle. [`n3_error_budget`] adds that term to eq. (13): the number every
//! accuracy test asserts against and the docs quote. [`estimator_bound`] gives every
//! estimator's bound in one place: the accuracy sweep and `encspeed check --mode bound` use it.

use crate::baselines::et_timer::et_error_bound;
use crate::baselines::mt_counter::mt_error_bound_at_speed;
use crate::baselines::pc_counter::pc_error_bound;

/// Eq. (4): worst-case relative error of n1 = Nep1/Ndt1, as a function of n1.
pub fn er1_max(n1: f64) -> f64 {
    if n1 <= 1.0 {
        n1
    } else {
        1.0 / (n1 - 1.0)
    }
}

/// Eq. (13): worst-case relative error of n3 (the harmonic mean of n1 and n2), as a
/// function of n1: 1/(1 + 2/n1) for n1 ≤ 1, 1/(2·n1 − 1) for n1 ≥ 2. (n1 takes no value
/// strictly between 1 and 2.)
pub fn er3_max(n1: f64) -> f64 {
    if n1 <= 1.0 {
        1.0 / (1.0 + 2.0 / n1)
    } else {
        1.0 / (2.0 * n1 - 1.0)
    }
}

/// Worst-case relative error of the hardware's n3 at constant speed, for an estimate n1
/// and dt = `dt_cycles` clock cycles.
///
/// Derivation (docs/design-decisions.md#table1-bound, worked in docs/accuracy.md): with
/// pulse instants rounded up to the clock, q_i ∈ [t_i, t_i + 1) cycles.
/// - High speed: Nep1 counts the q_i in [q_0, q_0 + dt). The q_i are whole cycles, so
///   q_i − q_0 ≤ dt − 1 and t_i − t_0 < dt: the count is that of exact instants in a
///   window between dt − 1 and dt cycles long, i.e. the exact estimator at a speed r' with
///   r(1 − 1/dt) < r' ≤ r, within the bound below.
/// - Low speed: Ndt1 comes from a pulse interval T' = q_1 − q_0 with |T' − T| < 1 and
///   T ≥ dt, so again |r'/r − 1| = |T/T' − 1| ≤ 1/(T − 1) ≤ 1/(dt − 1).
///
/// The exact bound eq. (13) holds about r', so |n3/r − 1| ≤ (1 + er3)(1 + 1/(dt − 1)) − 1.
pub fn n3_error_budget(n1: f64, dt_cycles: u64) -> f64 {
    assert!(dt_cycles >= 2, "dt must be at least 2 cycles");
    let e = er3_max(n1);
    let clock = 1.0 / (dt_cycles as f64 - 1.0);
    e + (1.0 + e) * clock
}

/// The estimators with a proven bound at constant speed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Estimator {
    /// Pulse counting in a fixed window of dt (`speed_pc`).
    Pc,
    /// Elapsed time: the last step period (`speed_et`).
    Et,
    /// Table 1's n1 = Nep1/Ndt1 (`speed_n1`).
    N1,
    /// Table 1's n3, the harmonic mean of n1 and n2 (`speed_n3`).
    N3,
    /// M/T: steps over the time they span, in a window of at least dt (`speed_mt`).
    Mt,
}

impl Estimator {
    /// Every estimator, in a fixed order.
    pub const ALL: [Estimator; 5] = [
        Estimator::Pc,
        Estimator::Et,
        Estimator::N1,
        Estimator::N3,
        Estimator::Mt,
    ];

    /// Short name (CSV columns, legends, reports).
    pub fn name(self) -> &'static str {
        match self {
            Estimator::Pc => "pc",
            Estimator::Et => "et",
            Estimator::N1 => "n1",
            Estimator::N3 => "n3",
            Estimator::Mt => "mt",
        }
    }

    /// The core's output port of this estimator.
    pub fn port(self) -> &'static str {
        match self {
            Estimator::Pc => "speed_pc",
            Estimator::Et => "speed_et",
            Estimator::N1 => "speed_n1",
            Estimator::N3 => "speed_n3",
            Estimator::Mt => "speed_mt",
        }
    }

    /// Index into [`Estimator::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }
}

/// The ranges Table 1's registers can take at constant speed with clock-quantised pulses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Allowed {
    /// Nep1, inclusive.
    pub nep: (u64, u64),
    /// Ndt1, inclusive.
    pub ndt: (u64, u64),
}

impl Allowed {
    /// Both ranges hold a single value: the estimate cannot dither at any clock phase.
    pub fn single(&self) -> bool {
        self.nep.0 == self.nep.1 && self.ndt.0 == self.ndt.1
    }
}

/// What clock quantisation allows for Nep1 and Ndt1 at a constant r_s = `steps_per_dt`
/// (P = dt/r_s, D = `dt_cycles`).
///
/// A pulse at instant t (cycles) is seen at q = ⌈t⌉; with a restarting pulse t0,
/// q_i − q_0 = ⌈iP − δ⌉ for some δ ∈ [0, 1).
/// - r_s > 1: Nep1 counts the i ≥ 0 with q_i − q_0 ≤ D − 1: every i with iP ≤ D − 1,
///   none with iP ≥ D, so Nep1 ∈ [⌊r_s(D−1)/D⌋ + 1, ⌈r_s⌉], Ndt1 = 1.
/// - r_s ≤ 1: the pulse interval is P' ∈ {⌊P⌋, ⌈P⌉}; the ticks strictly before the
///   next pulse number ⌈P'/D⌉ − 1 (a tick on the pulse is cancelled by the restart, and
///   at r_s = 1 exactly the pulse on the tick is dropped instead, Ndt1 = 1), so
///   Ndt1 ∈ [⌈⌊P⌋/D⌉ − 1, ⌈⌈P⌉/D⌉ − 1] (at least 1), Nep1 = 1.
pub fn allowed(steps_per_dt: f64, dt_cycles: u64) -> Allowed {
    let rs = steps_per_dt;
    let d = dt_cycles as f64;
    if rs > 1.0 {
        Allowed {
            nep: (
                ((rs * (d - 1.0) / d).floor() + 1.0) as u64,
                rs.ceil() as u64,
            ),
            ndt: (1, 1),
        }
    } else {
        let p = d / rs;
        let ndt = |t: f64| ((t / d).ceil() as u64).saturating_sub(1).max(1);
        Allowed {
            nep: (1, 1),
            ndt: (ndt(p.floor()), ndt(p.ceil())),
        }
    }
}

/// The n1 = Nep1/Ndt1 (in steps per dt) of the [`allowed`] range for which eq. (4) and
/// eq. (13) are largest: both grow with n1 up to 1 and fall from 2 on, so it is the
/// smallest Nep1 at high speed and the smallest Ndt1 at low speed.
pub fn worst_n1(steps_per_dt: f64, dt_cycles: u64) -> f64 {
    let a = allowed(steps_per_dt, dt_cycles);
    if steps_per_dt > 1.0 {
        a.nep.0 as f64
    } else {
        1.0 / a.ndt.0 as f64
    }
}

/// The estimator's own bound on its relative error at a constant r_s = `steps_per_dt`
/// decoder steps per dt, with pulses seen at the first clock edge after them (output
/// rounding not included: add it for the output format at hand).
/// - PC: 1/r_s ([`pc_error_bound`]).
/// - ET: 1/⌊P⌋, P = dt/r_s cycles ([`et_error_bound`]).
/// - M/T: [`mt_error_bound_at_speed`]`(r_s, dt)` (windows with a step only).
/// - n3: [`n3_error_budget`] (eq. (13) + one clock cycle) at [`worst_n1`].
/// - n1: the same with eq. (4): Er1 + (1 + Er1)/(dt − 1).
pub fn estimator_bound(est: Estimator, steps_per_dt: f64, dt_cycles: u64) -> f64 {
    let rs = steps_per_dt;
    match est {
        Estimator::Pc => pc_error_bound(rs),
        Estimator::Et => et_error_bound(dt_cycles as f64 / rs),
        Estimator::Mt => mt_error_bound_at_speed(rs, dt_cycles),
        Estimator::N3 => n3_error_budget(worst_n1(rs, dt_cycles), dt_cycles),
        Estimator::N1 => {
            let e = er1_max(worst_n1(rs, dt_cycles));
            e + (1.0 + e) / (dt_cycles as f64 - 1.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_match_the_papers_worked_values() {
        // Rairán, text under eq. (4): n1 = 3 → 50 %; n1 = 1/2 → 50 %.
        assert_eq!(er1_max(3.0), 0.5);
        assert_eq!(er1_max(0.5), 0.5);
        // Text under eq. (13): for n1 = 1 or 2, Er3 is a third of Er1 (Er1 = 1 at n1 = 1
        // and 2).
        assert!((er3_max(1.0) - 1.0 / 3.0).abs() < 1e-15);
        assert!((er3_max(2.0) - 1.0 / 3.0).abs() < 1e-15);
        // n1 → ∞ or → 0: Er3 goes below half of Er1.
        assert!(er3_max(1000.0) < 0.5 * er1_max(1000.0));
        assert!(er3_max(1e-3) < 0.5 * er1_max(1e-3));
    }

    #[test]
    fn budget_by_hand() {
        // n1 = 4, dt = 101: 1/7 + (8/7)/100 = 0.142857… + 0.0114285… = 0.1542857…
        assert!((n3_error_budget(4.0, 101) - 0.154_285_714_285_714_3).abs() < 1e-15);
    }
}
