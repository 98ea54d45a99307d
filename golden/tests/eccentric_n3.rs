// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's n3 on an eccentric disc (rigid, K = 1024, e = 0.35/30, θ0 = 50°), before and
//! after the count correction of `golden::eccentric::n3`. The truth is Rairán's own bound,
//! eq. (13) (`rairan::er3_max`), and the plant's constant shaft speed: n3 is a quantiser
//! that asynchrony never dithers, so the correction can take out the eccentricity only
//! down to n3's quantisation, and the test asserts exactly that. Run with `--nocapture`
//! for the figures docs/eccentricity-hardware.md quotes.

use golden::eccentric::correct::{once_per_rev, ripple, Correction};
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::n3::{n3_on_disc, N3Sample};
use golden::eccentric::{Eccentricity, Model};
use golden::estimator::bounds::er3_max;
use golden::ideal::plant::Profile;
use std::f64::consts::TAU;

const K: u32 = 1024;
/// Shaft speed, rev/s.
const SPEED: f64 = 10.0;

fn e_paper() -> f64 {
    0.35 / 30.0
}

/// n3 estimates at r pulses per dt over a few revolutions, after half a revolution.
fn run(r: f64, e: f64) -> Vec<N3Sample> {
    let theta0 = 50f64.to_radians();
    let dt = r / (SPEED * f64::from(K));
    let disc = EccentricDisc::new(K, Eccentricity::new(Model::Rigid, e, theta0).unwrap()).unwrap();
    let revs = (4.0f64).max(6.0 * r / f64::from(K));
    let lines = disc.line_crossings(&Profile::constant(SPEED, revs / SPEED).unwrap());
    n3_on_disc(&lines, dt, K, &Correction::first_order(K, e, theta0))
        .into_iter()
        .filter(|s| s.t > 0.5 / SPEED)
        .collect()
}

/// (largest |v/r − 1| / er3_max(n1) over the samples, peak-to-peak of v/r, amplitude of
/// the once-per-revolution harmonic of v/r − 1 against the shaft angle).
fn figures(s: &[N3Sample], r: f64, v: impl Fn(&N3Sample) -> f64) -> (f64, f64, f64) {
    let worst = s
        .iter()
        .map(|x| (v(x) / r - 1.0).abs() / er3_max(x.nep1 as f64 / x.ndt1 as f64))
        .fold(0.0, f64::max);
    let speeds: Vec<f64> = s.iter().map(&v).collect();
    let rel: Vec<(f64, f64)> = s
        .iter()
        .map(|x| (TAU * SPEED * x.t, v(x) / r - 1.0))
        .collect();
    (worst, ripple(&speeds, r).peak_to_peak, once_per_rev(&rel))
}

const RATES: [f64; 6] = [0.047, 0.3, 0.9, 3.3, 33.0, 330.0];

#[test]
fn centred_disc_n3_never_dithers_and_keeps_its_bound() {
    for r in RATES {
        let s = run(r, 0.0);
        let (worst, pp, _) = figures(&s, r, |x| x.n3);
        println!(
            "e = 0, r = {r}: {} estimates, error/bound {worst:.4}, p-p {pp:e}",
            s.len()
        );
        assert!(s.len() >= 20, "r = {r}: only {} estimates", s.len());
        assert_eq!(pp, 0.0, "r = {r}: n3 dithers at constant speed");
        // Ceilings at the bound itself land on it to within rounding.
        assert!(worst <= 1.0 + 1e-9, "r = {r}: beyond eq. (13)");
        // With e = 0 the correction is exactly nothing.
        assert!(s.iter().all(|x| x.delta == 0.0 && x.n3_corrected() == x.n3));
    }
}

#[test]
fn corrected_n3_is_within_its_bound_and_the_ripple_falls_to_its_quantisation() {
    let e = e_paper();
    println!("r      | before: err/bound  p-p ppm  1/rev ppm | after: err/bound  p-p ppm  1/rev ppm | hardware rule 1/rev ppm");
    for r in RATES {
        let s = run(r, e);
        let before = figures(&s, r, |x| x.n3);
        let after = figures(&s, r, N3Sample::n3_corrected);
        let hw = figures(&s, r, N3Sample::n3_hardware_rule);
        println!(
            "{r:6} | {:.4} {:9.0} {:9.1} | {:.4} {:9.0} {:9.1} | {:9.1}",
            before.0,
            before.1 * 1e6,
            before.2 * 1e6,
            after.0,
            after.1 * 1e6,
            after.2 * 1e6,
            hw.2 * 1e6
        );
        // Corrected, n3 is within Rairán's bound again, whatever the speed: what is left is
        // its own quantisation (first-order residual e³/3 and the half-line span end, a
        // relative e/(2·Nep1), are far inside the bound).
        assert!(
            after.0 <= 1.0 + 1e-9,
            "r = {r}: corrected n3 beyond eq. (13): {}",
            after.0
        );
        assert!(
            hw.0 <= 1.0 + 1e-9,
            "r = {r}: hardware rule beyond eq. (13): {}",
            hw.0
        );
    }
    // Where the quantum (1/(2·330 − 1) = 0.15 %) is finer than the ripple (±1.17 %), the
    // eccentricity breaks the bound and the correction restores it, taking the
    // once-per-revolution harmonic down by more than 30×.
    let s = run(330.0, e);
    let before = figures(&s, 330.0, |x| x.n3);
    let after = figures(&s, 330.0, N3Sample::n3_hardware_rule);
    assert!(
        before.0 > 5.0,
        "eccentric n3 at r = 330 should break eq. (13): {}",
        before.0
    );
    // The quantiser passes a fundamental a little below e (0.85·e here).
    assert!(
        before.2 > 0.8 * e,
        "1/rev ripple {} should be about e",
        before.2
    );
    assert!(
        after.2 < before.2 / 30.0,
        "1/rev {} → {}",
        before.2,
        after.2
    );
    // At r = 33 the quantum (1.5 %) is as large as the ripple: the correction still halves
    // the harmonic, no more.
    let s = run(33.0, e);
    let (b, a) = (
        figures(&s, 33.0, |x| x.n3),
        figures(&s, 33.0, N3Sample::n3_hardware_rule),
    );
    assert!(a.2 < b.2 / 2.0, "r = 33: 1/rev {} → {}", b.2, a.2);
    // Below that the quantiser's dead zone hides the eccentricity altogether: n3 does not
    // move at all (p-p 0) before the correction, and the correction brings the ripple in,
    // inside the bound. A corrector for n3 is worth its cost only where 1/(2·n1 − 1) < e.
    for r in [0.3, 3.3] {
        let s = run(r, e);
        let (b, a) = (
            figures(&s, r, |x| x.n3),
            figures(&s, r, N3Sample::n3_corrected),
        );
        assert_eq!(b.1, 0.0, "r = {r}: n3 moved");
        assert!(
            a.1 > e,
            "r = {r}: the correction should show the ripple it adds"
        );
    }
}
