// SPDX-License-Identifier: MIT OR Apache-2.0
//! The corrected M/T speed on an eccentric disc, in the hardware's integer arithmetic:
//! clock-stamped pulses of the rigid disc (K = 1024, e = 0.35/30, θ0 = 50°, 100 MHz clock,
//! dt = 1 ms, x1), M/T windows as `golden::baselines::mt_counter` forms them, δ from
//! `golden::ecc::ecc_delta` (bit-true, D = 24) and the speed from `golden::ecc::ecc_mt_speed`
//! (bit-true) against the uncorrected `golden::baselines::baseline_speeds::speed_mt`. The truth is the
//! plant's constant shaft speed; the floor is M/T's own quantisation, 1/T̂ per estimate
//! (`golden::ideal::mt`), which averages out of the once-per-revolution harmonic. Run with
//! `--nocapture` for the figures of docs/eccentricity-hardware.md.

use golden::baselines::baseline_speeds::{speed_mt, BaselineFormat};
use golden::ecc::ecc_delta::{coefficients, delta_raw, Request};
use golden::ecc::ecc_mt_speed::speed_mtc;
use golden::eccentric::correct::{once_per_rev, ripple};
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::ideal::plant::Profile;
use std::f64::consts::TAU;

const K: u32 = 1024;
const CLOCK: f64 = 100e6;
const DT: u64 = 100_000;
const N: u32 = 24;

struct Ripple {
    estimates: usize,
    peak: f64,
    pp: f64,
    h1: f64,
    /// Largest |error| / (1/T̂ + ½ LSB/r): the quantisation budget of one estimate.
    budget_ratio: f64,
}

/// Figures of (shaft angle, speed, budget) samples against the true speed `r`.
fn figures(v: &[(f64, f64, f64)], r: f64) -> Ripple {
    let speeds: Vec<f64> = v.iter().map(|x| x.1).collect();
    let rel: Vec<(f64, f64)> = v.iter().map(|x| (x.0, x.1 / r - 1.0)).collect();
    let rp = ripple(&speeds, r);
    Ripple {
        estimates: v.len(),
        peak: rp.peak,
        pp: rp.peak_to_peak,
        h1: once_per_rev(&rel),
        budget_ratio: v
            .iter()
            .map(|(_, s, b)| (s / r - 1.0).abs() / b)
            .fold(0.0, f64::max),
    }
}

/// Before and after correction at `rpm` over `revs` revolutions (after one to settle).
fn run(rpm: f64, revs: f64) -> (Ripple, Ripple) {
    let (e, theta0) = (0.35 / 30.0, 50f64.to_radians());
    let rps = rpm / 60.0;
    let disc = EccentricDisc::new(K, Eccentricity::new(Model::Rigid, e, theta0).unwrap()).unwrap();
    let lines = disc.line_crossings(&Profile::constant(rps, (revs + 1.0) / rps).unwrap());
    // Each pulse is sampled at the first clock edge at or after it.
    let stamps: Vec<(i64, u64)> = lines
        .iter()
        .map(|&(m, t)| (m, (t * CLOCK).ceil() as u64))
        .collect();
    let format = BaselineFormat::new(N, 16).unwrap();
    let (c, d) = coefficients(K, e, theta0);
    let r = rps * f64::from(K) * DT as f64 / CLOCK; // true speed, lines per dt
    let half_lsb = 0.5 / 65_536.0 / r;
    let (mut before, mut after) = (vec![], vec![]);
    let mut next = 0usize;
    let mut anchor: Option<usize> = None;
    for w in 1u64.. {
        let end = w * DT;
        if next == stamps.len() {
            break;
        }
        while next < stamps.len() && stamps[next].1 <= end {
            next += 1;
        }
        let Some(last) = next.checked_sub(1) else {
            continue;
        };
        match anchor {
            Some(a) if last != a => {
                let (m, t) = ((last - a) as u64, stamps[last].1 - stamps[a].1);
                let half = |line: i64| 2 * line.rem_euclid(i64::from(K)) as u64;
                let delta = delta_raw(
                    K,
                    10,
                    24,
                    &Request {
                        p_a: half(stamps[a].0),
                        p_b: half(stamps[last].0),
                        shift: 0,
                        coef_c: c,
                        coef_d: d,
                    },
                );
                let mid = 0.5 * (lines[a].1 + lines[last].1);
                if mid > 1.0 / rps {
                    let angle = TAU * rps * mid;
                    let budget = 1.0 / t as f64 + half_lsb;
                    let v0 = speed_mt(format, m, t, DT, false, 0) as f64 / 65_536.0;
                    let v1 = speed_mtc(format, m, t, DT, delta, false, 0) as f64 / 65_536.0;
                    before.push((angle, v0, budget));
                    after.push((angle, v1, budget));
                }
                anchor = Some(last);
            }
            Some(_) => {}
            None => anchor = Some(last),
        }
    }
    (figures(&before, r), figures(&after, r))
}

#[test]
fn corrected_mt_ripple_falls_over_1000_times_to_its_quantisation() {
    println!("rpm  | r (lines/dt) | estimates | before: peak, p-p, 1/rev (ppm) | after: peak, p-p, 1/rev (ppm), worst error/budget | 1/rev ratio");
    for (rpm, revs) in [(30.0, 3.0), (600.0, 20.0), (6000.0, 150.0)] {
        let (b, a) = run(rpm, revs);
        let r = rpm / 60.0 * f64::from(K) * DT as f64 / CLOCK;
        println!(
            "{rpm:5} | {r:7.3} | {} | {:8.1} {:8.1} {:8.1} | {:6.2} {:6.2} {:6.3} {:.3} | {:.0}",
            a.estimates,
            b.peak * 1e6,
            b.pp * 1e6,
            b.h1 * 1e6,
            a.peak * 1e6,
            a.pp * 1e6,
            a.h1 * 1e6,
            a.budget_ratio,
            b.h1 / a.h1
        );
        // Before: the eccentricity, about e (the window averages a little of it at high speed).
        assert!(b.h1 > 0.9 * 0.35 / 30.0, "{rpm} rpm: 1/rev before {}", b.h1);
        // After: every estimate within its quantisation budget (1/T̂ + ½ LSB) plus the
        // first-order residual e³/3 (0.5 ppm) and δ's own rounding (< 0.1 ppm).
        assert!(
            a.budget_ratio < 1.1,
            "{rpm} rpm: error/budget {}",
            a.budget_ratio
        );
        // The once-per-revolution ripple falls by more than 1000×.
        assert!(b.h1 / a.h1 > 1000.0, "{rpm} rpm: 1/rev {} → {}", b.h1, a.h1);
    }
}
