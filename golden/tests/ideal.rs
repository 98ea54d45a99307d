// SPDX-License-Identifier: MIT OR Apache-2.0
//! Ideal-estimator tests. Known answers are worked out by hand in the comments from
//! Rairán's Table 1 (order of the four steps as in docs/design-decisions.md#table1-order),
//! and bounds come from the paper's equations (1), (6), (11) and (13), restated here rather
//! than imported.

use golden::ideal::plant::{edges, pulse_times, Channel, Disc, Profile};
use golden::ideal::{
    fixed_space, fixed_time, n1, n2, n3, update_interval, IdealError, RairanIdeal, Update,
};

/// Pulses at phase + n·period for n = 0, 1, … while ≤ t_end (s).
fn train(phase: f64, period: f64, t_end: f64) -> Vec<f64> {
    (0u64..)
        .map(|n| phase + n as f64 * period)
        .take_while(|&t| t <= t_end)
        .collect()
}

fn run(dt: f64, pulses: &[f64], t_end: f64) -> Vec<Update> {
    RairanIdeal::new(dt, 1).unwrap().run(pulses, t_end).unwrap()
}

/// (t, Nep1 written?, Ndt1 written?, Nep1, Ndt1) of the first updates.
fn trace(u: &[Update], n: usize) -> Vec<(f64, bool, bool, u64, u64)> {
    u.iter()
        .take(n)
        .map(|u| {
            (
                (u.t * 1e9).round() / 1e9,
                u.wrote_nep,
                u.wrote_ndt,
                u.nep1,
                u.ndt1,
            )
        })
        .collect()
}

/// Eq. (13): worst-case relative error of n3 as a function of n1.
fn eq13(n1: f64) -> f64 {
    if n1 <= 1.0 {
        1.0 / (1.0 + 2.0 / n1)
    } else {
        1.0 / (2.0 * n1 - 1.0)
    }
}

/// Eq. (1): the paper's update interval (units of dt) for r ≥ 1.
fn eq1(r: f64) -> f64 {
    let f = r.floor();
    -r / f + 2.0 + 1.0 / f
}

#[test]
fn estimate_functions_by_hand() {
    // High speed, Nep1 = 4, Ndt1 = 1: n1 = 4, n2 = 3, n3 = 2·4·3/7 = 24/7.
    assert_eq!((n1(4, 1), n2(4, 1)), (4.0, 3.0));
    assert!((n3(4, 1) - 24.0 / 7.0).abs() < 1e-15);
    // Low speed, Nep1 = 1, Ndt1 = 3: n1 = 1/3, n2 = 1/4, n3 = 2/(3+4) = 2/7.
    assert_eq!((n1(1, 3), n2(1, 3)), (1.0 / 3.0, 0.25));
    assert!((n3(1, 3) - 2.0 / 7.0).abs() < 1e-15);
    // n1 = 1 is "low": n2 = 1/2, n3 = 2/3.
    assert_eq!(n2(1, 1), 0.5);
    assert!((n3(1, 1) - 2.0 / 3.0).abs() < 1e-15);
    // Nothing counted yet.
    assert_eq!(n3(0, 1), 0.0);
    // Closed forms of the harmonic mean (docs/design-decisions.md#table1-estimates):
    // 2·Nep1/(2·Ndt1+1) (low), 2·N(N−1)/(Ndt1(2N−1)) (high).
    for ndt in 1..50u64 {
        assert!((n3(1, ndt) - 2.0 / (2 * ndt + 1) as f64).abs() < 1e-15);
    }
    for nep in 2..200u64 {
        let want = (2 * nep * (nep - 1)) as f64 / (2 * nep - 1) as f64;
        assert!((n3(nep, 1) - want).abs() < 1e-12 * want);
    }
}

#[test]
fn period_0_3_dt_1_by_hand() {
    // dt = 1, pulses at 0.3 n (n ≥ 1), r = 10/3.
    // 0.3, 0.6, 0.9: Cdt = 0 (no tick yet) so no restart; Cep = 3.
    // 1.0 tick: Nep1 = 3 (unsynchronised first window); Cdt = 1, Cep = 0; next tick 2.0.
    // 1.2 pulse: Cdt = 1 → Ndt1 = 1, restart (next tick 2.2); Cep = 1, Cdt = 0.
    // 1.5, 1.8, 2.1: Cep = 4. 2.2 tick: Nep1 = 4; Cdt = 1; next 3.2.
    // 2.4 pulse: Ndt1 = 1, restart (tick 3.4). 2.7, 3.0, 3.3 → Cep 4. 3.4: Nep1 = 4 …
    // Nep1 = 4 = ⌈1/0.3⌉ from then on, no dither; cycle 1.2 = 4·0.3.
    let u = run(1.0, &train(0.3, 0.3, 20.0), 20.0);
    assert_eq!(
        trace(&u, 6),
        [
            (1.0, true, false, 3, 1),
            (1.2, false, true, 3, 1),
            (2.2, true, false, 4, 1),
            (2.4, false, true, 4, 1),
            (3.4, true, false, 4, 1),
            (3.6, false, true, 4, 1),
        ]
    );
    assert!(u[2..].iter().all(|u| (u.nep1, u.ndt1) == (4, 1)));
}

#[test]
fn period_2_5_dt_1_by_hand() {
    // dt = 1, pulses at 2.5 n (n ≥ 1), r = 0.4.
    // Ticks 1, 2: Cep = 0 so Nep1 stays 0; Cdt = 2.
    // 2.5 pulse: Ndt1 = 2, restart (ticks 3.5, 4.5); Cep = 1, Cdt = 0.
    // 3.5 tick: Nep1 = 1, Cdt = 1, Cep = 0. 4.5 tick: Cep = 0, no write; Cdt = 2.
    // 5.0 pulse: Ndt1 = 2, restart … so Nep1 = 1, Ndt1 = 2 = ⌊1/0.4⌋, each per period T.
    let u = run(1.0, &train(2.5, 2.5, 20.0), 20.0);
    assert_eq!(
        trace(&u, 4),
        [
            (2.5, false, true, 0, 2),
            (3.5, true, false, 1, 2),
            (5.0, false, true, 1, 2),
            (6.0, true, false, 1, 2),
        ]
    );
    assert!(u[1..].iter().all(|u| (u.nep1, u.ndt1) == (1, 2)));
}

#[test]
fn period_0_25_coincident_pulse_and_tick_by_hand() {
    // dt = 1, pulses at 0.25 n (n ≥ 1): r = 4, every restart puts a tick on a pulse.
    // 0.25, 0.5, 0.75: Cep = 3.
    // 1.0 pulse + tick: Cdt = 0 → no restart; tick: Nep1 = 3; pulse: Cep = 4, Cdt = 0;
    //     tick: Cdt = 1, Cep = 0 (the pulse at 1.0 is dropped); next tick 2.0.
    // 1.25 pulse: Ndt1 = 1, restart → next tick 2.25; Cep = 1.
    // 1.5, 1.75, 2.0: Cep = 4 (2.0 is no longer a tick).
    // 2.25 pulse + tick: no restart (Cdt = 0); Nep1 = 4; the pulse is dropped; Cdt = 1.
    // 2.5 pulse: Ndt1 = 1, restart (tick 3.5). 3.5: Nep1 = 4 … 3.75: Ndt1 = 1.
    // So Nep1 = 4 = r and the cycle is 1.25 = (r+1)·T, not ⌈r⌉·T = 1.
    let u = run(1.0, &train(0.25, 0.25, 20.0), 20.0);
    assert_eq!(
        trace(&u, 6),
        [
            (1.0, true, false, 3, 1),
            (1.25, false, true, 3, 1),
            (2.25, true, false, 4, 1),
            (2.5, false, true, 4, 1),
            (3.5, true, false, 4, 1),
            (3.75, false, true, 4, 1),
        ]
    );
    // Same answer when the coincidence is only equal to a few ulps: dt = 0.1,
    // T = 0.025, where n·0.025 and t_restart + 0.1 differ in the last bits.
    let v = run(0.1, &train(0.025, 0.025, 2.0), 2.0);
    let ndt_times: Vec<f64> = v.iter().filter(|u| u.wrote_ndt).map(|u| u.t).collect();
    assert!(v[2..].iter().all(|u| (u.nep1, u.ndt1) == (4, 1)));
    for w in ndt_times.windows(2) {
        assert!((w[1] - w[0] - 0.125).abs() < 1e-12, "cycle {}", w[1] - w[0]);
    }
}

#[test]
fn period_2_exactly_drops_the_coincident_tick() {
    // dt = 1, pulses at 2n: r = 1/2. Tick 1: Cdt = 1. 2.0 pulse + tick: Cdt = 1 ≠ 0 →
    // Ndt1 = 1 and restart, which cancels the tick due at 2.0. 3.0 tick: Nep1 = 1, Cdt = 1.
    // 4.0 pulse + tick (2.0 + 2·1): Ndt1 = 1 again. So Ndt1 = 1/r − 1 = 1, not 2: at
    // r = 1/n exactly n1 = 1/(n−1) and n3 sits exactly on the eq. (13) bound.
    let u = run(1.0, &train(2.0, 2.0, 20.0), 20.0);
    assert!(u.iter().all(|u| u.ndt1 == 1));
    let last = u.last().unwrap();
    assert_eq!((last.nep1, last.ndt1), (1, 1));
    let err = (last.n3() - 0.5).abs() / 0.5;
    assert!((err - eq13(last.n1())).abs() < 1e-12);
}

/// Steady-state cycle: times between consecutive Ndt1 and Nep1 writes, after `settle` s.
fn steady(u: &[Update], settle: f64) -> (Vec<f64>, Vec<f64>) {
    let gaps = |pick: fn(&Update) -> bool| -> Vec<f64> {
        let t: Vec<f64> = u
            .iter()
            .filter(|u| u.t > settle && pick(u))
            .map(|u| u.t)
            .collect();
        t.windows(2).map(|w| w[1] - w[0]).collect()
    };
    (gaps(|u| u.wrote_ndt), gaps(|u| u.wrote_nep))
}

#[test]
fn update_interval_versus_paper_eq1() {
    // Hand derivation (module docs of ideal.rs): (⌊r⌋+1)/r·dt for r ≥ 1, i.e. ⌈r⌉·T for
    // non-integer r and (r+1)·T at integer r; eq. (1) is the chord above it.
    let dt = 1.0;
    let rs = [
        1.0,
        1.3,
        1.5,
        1.9,
        2.0,
        2.5,
        3.0,
        10.0 / 3.0,
        3.7,
        4.0,
        5.0,
        6.6,
        12.25,
    ];
    for &r in &rs {
        let t = dt / r;
        let u = run(dt, &train(0.37 * t, t, 40.0), 40.0);
        let (ndt, nep) = steady(&u, 10.0);
        assert!(ndt.len() > 10 && nep.len() > 10, "r = {r}");
        let want = if r.fract() == 0.0 {
            (r + 1.0) * t
        } else {
            r.ceil() * t
        };
        for g in ndt.iter().chain(&nep) {
            assert!(
                (g - want).abs() < 1e-9,
                "r = {r}: interval {g}, want {want}"
            );
        }
        assert!((update_interval(r) - want / dt).abs() < 1e-12, "r = {r}");
        // eq. (1) never under-states it, and is exact at integer r.
        assert!(
            eq1(r) >= want / dt - 1e-12,
            "r = {r}: eq1 {} < {want}",
            eq1(r)
        );
        if r.fract() == 0.0 {
            assert!((eq1(r) - want / dt).abs() < 1e-12, "r = {r}");
        } else {
            assert!(
                eq1(r) > want / dt + 1e-6,
                "r = {r}: strictly above in between"
            );
        }
    }
    // Equal at the left end of each interval too: r → n+1 from below gives 1 both ways.
    for n in 1..10 {
        let r = f64::from(n) + 1.0 - 1e-9;
        assert!((eq1(r) - update_interval(r)).abs() < 1e-8);
    }
    // Below ω_lim both registers update once per pulse period.
    for &r in &[0.05, 0.3, 0.7, 0.95] {
        let t = dt / r;
        let u = run(dt, &train(0.37 * t, t, 40.0 * t), 40.0 * t);
        let (ndt, nep) = steady(&u, 5.0 * t);
        for g in ndt.iter().chain(&nep) {
            assert!((g - t).abs() < 1e-9, "r = {r}: interval {g}, want {t}");
        }
        assert!((update_interval(r) - t / dt).abs() < 1e-12);
    }
}

#[test]
fn sweep_r_against_eq13_and_counts() {
    let dt = 1e-3;
    let mut checked = 0;
    for i in 0..200 {
        let r = 10f64.powf(-2.0 + 4.0 * f64::from(i) / 199.0);
        let near_int = |v: f64| (v - v.round()).abs() < 1e-6;
        if near_int(r) || near_int(1.0 / r) {
            continue;
        }
        let t = dt / r;
        let t_end = 30.0 * t.max(2.0 * dt);
        let u = run(dt, &train(0.41 * t, t, t_end), t_end);
        // Settled: the last third of the run holds one register pair, no dither.
        let late: Vec<&Update> = u.iter().filter(|u| u.t > 20.0 * t.max(2.0 * dt)).collect();
        assert!(late.len() >= 3, "r = {r}");
        let last = *late[0];
        assert!(
            late.iter()
                .all(|u| (u.nep1, u.ndt1) == (last.nep1, last.ndt1)),
            "r = {r}"
        );
        if r > 1.0 {
            assert_eq!((last.nep1, last.ndt1), (r.ceil() as u64, 1), "r = {r}");
        } else {
            assert_eq!(
                (last.nep1, last.ndt1),
                (1, (1.0 / r).floor() as u64),
                "r = {r}"
            );
        }
        // n1 is an upper, n2 a lower estimate, and n3 is within eq. (13).
        assert!(last.n1() >= r && r >= last.n2(), "r = {r}: {last:?}");
        let err = (last.n3() - r).abs() / r;
        assert!(
            err <= eq13(last.n1()) + 1e-12,
            "r = {r}: err {err} > {}",
            eq13(last.n1())
        );
        checked += 1;
    }
    assert!(checked > 190, "{checked}");
}

#[test]
fn plant_pulses_drive_the_estimator() {
    // 12.3 rev/s on a 100-line disc with dt = 1 ms: ω_lim = 1/(100·1e-3) = 10 rev/s,
    // r = 1.23 → Nep1 = 2, Ndt1 = 1, n3 = 4/3 ω_lim = 13.33 rev/s (error 8.4 % ≤ 1/3).
    let edges = edges(
        &Profile::constant(12.3, 0.25).unwrap(),
        &Disc::new(100).unwrap(),
    );
    let pulses = pulse_times(&edges, Channel::A, true);
    assert_eq!(pulses.len(), 307); // x ends at 12.3·0.25·100 = 307.5: A rises at 1 … 307
    let est = RairanIdeal::new(1e-3, 100).unwrap();
    assert!((est.omega_lim() - 10.0).abs() < 1e-12);
    let u = est.run(&pulses, 0.25).unwrap();
    let last = u.last().unwrap();
    assert_eq!((last.nep1, last.ndt1), (2, 1));
    assert!((last.n3() * est.omega_lim() - 40.0 / 3.0).abs() < 1e-9);
}

#[test]
fn pc_dithers_between_floor_and_ceil() {
    // r = 3.3, dt = 1: each window [k, k+1) holds 3 or 4 pulses; over 1000 windows the
    // 3300 − (phase) pulses average 3.3 to within one pulse / 1000 windows.
    let t = 1.0 / 3.3;
    let pulses = train(0.2 * t, t, 1000.5);
    let est = fixed_time(&pulses, 1.0, 1000.0).unwrap();
    assert_eq!(est.len(), 1000);
    assert!(est.iter().all(|e| e.n == 3.0 || e.n == 4.0));
    assert!(est.iter().any(|e| e.n == 3.0) && est.iter().any(|e| e.n == 4.0));
    let mean = est.iter().map(|e| e.n).sum::<f64>() / 1000.0;
    assert!((mean - 3.3).abs() <= 1.0 / 1000.0, "mean {mean}");
    assert_eq!(est[0].t, 1.0);
    assert_eq!(est[999].t, 1000.0);
}

#[test]
fn et_resolves_low_speed() {
    // r = 0.4, dt = 1, q = 1 ms: T = 2.5 s = 2500 q → N ∈ {2499, 2500, 2501}, and
    // dt/(N·q) = 1000/N = 0.4 within 0.4/2500 relative 4e-4 ≤ 1e-3.
    let t = 2.5;
    let pulses = train(0.1234, t, 100.0);
    let est = fixed_space(&pulses, 1.0, 1e-3).unwrap();
    assert_eq!(est.len(), pulses.len() - 1);
    for e in &est {
        assert!((e.n - 0.4).abs() / 0.4 <= 1e-3, "{e:?}");
    }
    // Two pulses inside one quantum: no tick between them → infinite speed.
    let est = fixed_space(&[0.0101, 0.0102], 1.0, 0.01).unwrap();
    assert_eq!(est[0].n, f64::INFINITY);
}

#[test]
fn validation() {
    assert_eq!(RairanIdeal::new(0.0, 1), Err(IdealError::BadDt(0.0)));
    assert_eq!(RairanIdeal::new(1.0, 0), Err(IdealError::ZeroLines));
    let est = RairanIdeal::new(1.0, 1).unwrap();
    assert!(matches!(
        est.run(&[1.0, 0.5], 2.0),
        Err(IdealError::BadPulse { index: 1, .. })
    ));
    assert!(matches!(
        est.run(&[-1.0], 2.0),
        Err(IdealError::BadPulse { index: 0, .. })
    ));
    assert!(est.run(&[], f64::NAN).is_err());
    assert!(fixed_space(&[], 1.0, 0.0).is_err());
    assert!(fixed_time(&[], -1.0, 1.0).is_err());
    assert!(IdealError::BadDt(0.0).to_string().contains("dt"));
    // No pulses: the registers are never written.
    assert!(est.run(&[], 100.0).unwrap().is_empty());
}
