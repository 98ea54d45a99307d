// SPDX-License-Identifier: MIT OR Apache-2.0
//! `golden::ecc::ident_gatherer`: hand-worked sums on K = 4, the control sequence (arm, index,
//! done, overflow, reset), and on the rigid eccentric disc (K = 1024, 100 MHz clock,
//! e = 0.35/30) the gathered results against the golden identification.

use golden::ecc::ident_gatherer::{identify_from_sums, GatherInputs, GatherOutputs, IdentGatherer};
use golden::eccentric::identify::{harmonic_fit, paper_identify, revolution_periods, FitOptions};
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::ideal::plant::Profile;

const Q: i128 = (1 << 23) - 1;

fn idle() -> GatherInputs {
    GatherInputs::default()
}

fn line(position: u64, period: u64) -> GatherInputs {
    GatherInputs {
        line: true,
        position,
        period,
        ..idle()
    }
}

fn index() -> GatherInputs {
    GatherInputs {
        index: true,
        ..idle()
    }
}

fn arm() -> GatherInputs {
    GatherInputs {
        arm: true,
        ..idle()
    }
}

/// K = 4, periods 10, 20, 30, 40 closed by the edges at positions 1, 2, 3, 0.
/// S = [0, Q, 0, −Q], C[p] = S[p + 1] = [Q, 0, −Q, 0]:
/// ΣT = 100, ΣT·S = 10Q − 30Q = −20Q, ΣT·C = −20Q + 40Q = 20Q.
#[test]
fn hand_values_k4() {
    let mut g = IdentGatherer::new(4, 2, 8);
    g.step(GatherInputs {
        reset: true,
        ..idle()
    });
    g.step(arm());
    g.step(line(0, 99)); // before the first Z: ignored
    g.step(index());
    g.step(line(1, 10));
    g.step(idle());
    g.step(line(2, 20));
    g.step(line(3, 30)); // back to back
    g.step(idle());
    let before = g.step(GatherInputs {
        index: true,
        ..line(0, 40) // the Z line, same cycle as the closing index
    });
    assert!(!before.done);
    assert_eq!(before.count, 3);
    let o = g.step(idle());
    let want = GatherOutputs {
        done: true,
        overflow: false,
        count: 4,
        t_min: 10,
        p_min: 1,
        t_max: 40,
        p_max: 0,
        sum_t: 100,
        sum_sin: -20 * Q,
        sum_cos: 20 * Q,
    };
    assert_eq!(o, want);
    // Held and sticky: later lines and Z pulses change nothing.
    g.step(line(1, 7));
    g.step(index());
    assert_eq!(g.step(line(2, 7)), want);
    // Arm clears done only; the results hold until the next gathering starts.
    let a = g.step(arm());
    assert_eq!(
        a,
        GatherOutputs {
            done: false,
            ..want
        }
    );
    let s = g.step(index());
    assert_eq!(s, GatherOutputs::default());
}

/// Ties keep the first occurrence; an arm during gathering restarts; more than 2^A lines
/// set `overflow` and are dropped; reset clears everything.
#[test]
fn control_ties_overflow_reset() {
    let mut g = IdentGatherer::new(4, 2, 8);
    g.step(arm());
    g.step(index());
    g.step(line(1, 5));
    g.step(arm()); // restart: abandon this gathering
    g.step(line(2, 6)); // armed, not gathering
    g.step(index());
    for p in [1, 2, 3, 0] {
        g.step(line(p, 9)); // all equal: first occurrence
    }
    g.step(line(1, 200)); // fifth line: overflow, dropped
    g.step(index());
    let o = g.step(idle());
    assert!(o.done && o.overflow);
    assert_eq!(
        (o.count, o.t_min, o.p_min, o.t_max, o.p_max),
        (4, 9, 1, 9, 1)
    );
    assert_eq!(o.sum_t, 36);
    assert_eq!((o.sum_sin, o.sum_cos), (0, 0));
    let r = g.step(GatherInputs {
        reset: true,
        ..idle()
    });
    assert_eq!(r, GatherOutputs::default());
    // After reset, not armed: a revolution is ignored.
    g.step(index());
    g.step(line(1, 3));
    g.step(index());
    assert_eq!(g.step(idle()), GatherOutputs::default());
}

/// Rigid disc, K = 1024, 100 MHz clock, e = 0.35/30: the gatherer fed the clock-quantised
/// periods of one revolution gives T_min/T_max/positions equal to paper_identify's inputs and,
/// through identify_from_sums, e within 0.01 % and θ0 within 0.01° of harmonic_fit.
#[test]
fn rigid_disc_sums_match_harmonic_fit() {
    const K: u32 = 1024;
    let e = 0.35 / 30.0;
    let mut worst = (0.0f64, 0.0f64);
    for &(rpm, theta0_deg) in &[(100.0, 50.0), (1000.0, 200.0), (3000.0, 310.0)] {
        let theta0 = f64::to_radians(theta0_deg);
        let d = EccentricDisc::new(K, Eccentricity::new(Model::Rigid, e, theta0).unwrap()).unwrap();
        let speed = rpm / 60.0;
        let p = Profile::constant(speed, 2.1 / speed)
            .unwrap()
            .with_initial_angle(d.shaft_angle_rev(-1.2))
            .unwrap();
        let periods = revolution_periods(&d.edges(&p), K, Some(100e6)).unwrap();
        let cycles: Vec<u64> = periods.iter().map(|t| (t * 100e6).round() as u64).collect();
        let mut g = IdentGatherer::new(K, 10, 32);
        g.step(arm());
        g.step(line(0, 12345));
        g.step(index());
        for (m, &c) in cycles.iter().enumerate() {
            g.step(line((m as u64 + 1) % u64::from(K), c));
            g.step(idle());
        }
        g.step(index());
        let o = g.step(idle());
        assert!(o.done && !o.overflow);
        assert_eq!(o.count, u64::from(K));
        let paper = paper_identify(&periods).unwrap();
        assert_eq!(o.t_min as f64, (paper.t_min * 100e6).round());
        assert_eq!(o.t_max as f64, (paper.t_max * 100e6).round());
        assert_eq!(o.p_min, paper.k2 as u64 % u64::from(K));
        assert_eq!(o.p_max, paper.k1 as u64 % u64::from(K));
        assert_eq!(o.sum_t, cycles.iter().map(|&c| i128::from(c)).sum::<i128>());
        let id = identify_from_sums(K, o.sum_t, o.sum_sin, o.sum_cos, Model::Rigid);
        let fit = harmonic_fit(&periods, FitOptions::default())
            .unwrap()
            .identified(Model::Rigid);
        let de = (id.e / fit.e - 1.0).abs();
        let dth = golden::eccentric::identify::phase_difference(id.theta0, fit.theta0)
            .abs()
            .to_degrees();
        println!(
            "{rpm} rpm: sums e = {:.7} θ0 = {:.5}°, fit e = {:.7} θ0 = {:.5}° (Δe {:.2e} rel, Δθ0 {:.2e}°)",
            id.e,
            id.theta0.to_degrees(),
            fit.e,
            fit.theta0.to_degrees(),
            de,
            dth
        );
        worst = (worst.0.max(de), worst.1.max(dth));
    }
    assert!(worst.0 < 1e-4, "e differs by {:.2e}", worst.0);
    assert!(worst.1 < 0.01, "θ0 differs by {:.2e}°", worst.1);
}
