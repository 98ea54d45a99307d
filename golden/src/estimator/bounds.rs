// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's error bounds and the error budget of the clock-quantised hardware.
//!
//! The paper's bounds assume exact pulse instants. The hardware sees each pulse at the
//! first clock edge after it, so a pulse interval measured in clock cycles is off by less
//! than one cycle. [`n3_error_budget`] adds that term to eq. (13): the number every
//! accuracy test asserts against and the docs quote.

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
