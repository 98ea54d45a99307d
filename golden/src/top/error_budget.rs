// SPDX-License-Identifier: MIT OR Apache-2.0
//! The error budget of every speed output of the core, for the generated parameters: the
//! bound on its relative error at a constant speed, with the clock quantisation and the
//! output rounding included. The accuracy sweep asserts against [`output_bound`]; the
//! manifests carry [`budget`], a table of it at decades of r/min, so a user sees what the
//! configured clock, lines and dt give before building anything (docs/accuracy.md derives
//! each term).

use crate::estimator::bounds::{estimator_bound, Estimator};
use crate::estimator::speed_calc::mode_scale_error_lsb;
use crate::estimator::speed_calc::speed_lsb_error;
use crate::params::{Params, SpeedOutput};
use serde::Serialize;

/// The bound on the relative error of `est`'s output at a constant r lines per dt, decoding
/// 2^`shift` steps per line, dt = `dt_cycles`, F = `frac_bits`: the estimator's own term
/// at the step rate r·2^s ([`estimator_bound`]), plus the output rounding relative to r:
/// ½ LSB = 2^−(F+1) ω_lim for ET and M/T, for n1 and n3 the mode scaling's
/// [`mode_scale_error_lsb`], none for PC (`speed_pc` is exact).
pub fn output_bound(est: Estimator, r: f64, shift: u32, dt_cycles: u64, frac_bits: u32) -> f64 {
    let own = estimator_bound(est, r * f64::from(1u32 << shift), dt_cycles);
    let half_lsb = speed_lsb_error(frac_bits) / r;
    let scaled_lsb = mode_scale_error_lsb(shift) * (-f64::from(frac_bits)).exp2() / r;
    match est {
        Estimator::Pc => own,
        Estimator::Et | Estimator::Mt => own + half_lsb,
        Estimator::N1 | Estimator::N3 => own + scaled_lsb,
    }
}

/// One row of [`budget`]: the bound of each speed output at one speed and decode mode,
/// as a fraction of the true speed (0.01 = 1 %).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BudgetRow {
    /// Decode mode: "x1", "x2" or "x4".
    pub mode: &'static str,
    /// Shaft speed, r/min.
    pub rev_per_min: f64,
    /// The same in lines per dt (units of ω_lim).
    pub lines_per_dt: f64,
    /// Decoder steps per dt.
    pub steps_per_dt: f64,
    /// `speed_pc`; absent when it is left out (`estimators`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pc: Option<f64>,
    /// `speed_et`; absent when it is left out (`estimators`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub et: Option<f64>,
    /// `speed_n1`; absent when it is left out (`estimators`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n1: Option<f64>,
    /// `speed_n3` (Rairán eq. (13) with one clock and the rounding).
    pub n3: f64,
    /// `speed_mt`; absent when it is left out (`estimators`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mt: Option<f64>,
}

/// Speeds of the budget table, r/min: decades.
pub const BUDGET_RPM: [f64; 7] = [0.1, 1.0, 10.0, 100.0, 1_000.0, 10_000.0, 100_000.0];

/// The budget of `p` at each speed of [`BUDGET_RPM`] and each decode mode the core
/// measures there: a step at least every half timeout (slower reads as `stalled`), each
/// quadrature state at least two clock cycles long (faster is an illegal transition or
/// an over-speed), at most `counter_max` steps per dt and at most `counter_max` cycles per
/// step (the counters saturate).
pub fn budget(p: &Params) -> Vec<BudgetRow> {
    let dt = p.dt_cycles();
    let mut rows = Vec::new();
    for (shift, mode) in ["x1", "x2", "x4"].into_iter().enumerate() {
        let shift = shift as u32;
        for rpm in BUDGET_RPM {
            let r = rpm / 60.0 * f64::from(p.lines()) * p.dt_s();
            let rs = r * f64::from(1u32 << shift);
            let quarter_cycles = dt as f64 / (4.0 * r);
            let steps_per_timeout = rs * p.timeout_dt() as f64;
            let step_cycles = dt as f64 / rs;
            let max = p.counter_max() as f64;
            if steps_per_timeout < 2.0 || quarter_cycles < 2.0 || rs > max || step_cycles > max {
                continue;
            }
            let b = |est| output_bound(est, r, shift, dt, p.speed_frac_bits());
            let built = |e: SpeedOutput, est| p.has(e).then(|| b(est));
            rows.push(BudgetRow {
                mode,
                rev_per_min: rpm,
                lines_per_dt: r,
                steps_per_dt: rs,
                pc: built(SpeedOutput::Pc, Estimator::Pc),
                et: built(SpeedOutput::Et, Estimator::Et),
                n1: built(SpeedOutput::N1, Estimator::N1),
                n3: b(Estimator::N3),
                mt: built(SpeedOutput::Mt, Estimator::Mt),
            });
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Spec;

    /// The default configuration (100 MHz, 1024 lines, dt = 100 000 cycles = 1 ms) at
    /// 1000 r/min in x4, by hand: r = 1000/60 · 1024 · 1e-3 = 17.0667 lines/dt, r_s = 68.267
    /// steps/dt.
    /// - PC: 1/r_s = 0.0146484.
    /// - n3: Nep1 ∈ [⌊r_s·99 999/100 000⌋ + 1, ⌈r_s⌉] = [69, 69], Er3 = 1/137, plus
    ///   (1 + 1/137)/99 999 for the clock, plus (½ + ⅛)·2^−16/r for the rounding.
    #[test]
    fn default_budget_at_1000_rpm_by_hand() {
        let p = Params::new(Spec::default()).unwrap();
        let rows = budget(&p);
        let row = rows
            .iter()
            .find(|r| r.mode == "x4" && r.rev_per_min == 1000.0)
            .unwrap();
        assert!((row.lines_per_dt - 17.066_666_666_666_67).abs() < 1e-12);
        assert!((row.pc.unwrap() - 1.0 / 68.266_666_666_666_67).abs() < 1e-12);
        let n3 =
            1.0 / 137.0 + (1.0 + 1.0 / 137.0) / 99_999.0 + 0.625 / 65_536.0 / 17.066_666_666_666_67;
        assert!((row.n3 - n3).abs() < 1e-15, "{} vs {n3}", row.n3);
        // Slow speeds are stalled or overflow the period counters, fast ones are beyond
        // the decoder: at 100 MHz, dt = 1 ms, timeout 1000 dt, 24-bit counters, 0.1 r/min
        // is 1.7 lines per s: in x1, r_s·timeout = 1.7 < 2; in x2 a step takes 29.3 M
        // cycles > 2^24 − 1; in x4 14.6 M cycles (kept). 100 000 r/min in x4 leaves 14.6
        // cycles per quadrature state (kept).
        let has =
            |mode: &str, rpm: f64| rows.iter().any(|r| r.mode == mode && r.rev_per_min == rpm);
        assert!(!has("x1", 0.1) && !has("x2", 0.1) && has("x4", 0.1));
        assert!(has("x4", 100_000.0));
    }

    /// A speed output left out has no budget; the others keep theirs.
    #[test]
    fn outputs_left_out_have_no_budget() {
        use crate::params::SpeedOutput::{Mt, N3};
        let full = budget(&Params::new(Spec::default()).unwrap());
        let p = Params::new(Spec {
            estimators: vec![N3, Mt],
            ..Spec::default()
        })
        .unwrap();
        let some = budget(&p);
        assert_eq!(some.len(), full.len());
        for (s, f) in some.iter().zip(&full) {
            assert_eq!((s.pc, s.et, s.n1), (None, None, None));
            assert_eq!((s.n3, s.mt), (f.n3, f.mt));
            assert!(f.pc.is_some() && f.et.is_some() && f.n1.is_some());
        }
    }
}
