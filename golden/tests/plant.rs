// SPDX-License-Identifier: MIT OR Apache-2.0
//! Plant tests. Truth comes from hand calculations and closed forms written here, not from
//! the code under test: edge instants of constant and ramp motion in closed form, the
//! mirror symmetry of a reversal, a brute-force fine-grid scan of the level functions, and
//! random profiles checked for the invariants of a quadrature signal.

use golden::ideal::plant::{
    edges, initial_levels, pulse_times, Channel, ClockSampler, Disc, Edge, PlantError, Profile,
    Sample, Segment,
};
use proptest::prelude::*;

fn of(es: &[Edge], channel: Channel, rising: bool) -> Vec<f64> {
    pulse_times(es, channel, rising)
}

fn assert_close(got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "edge count");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!((g - w).abs() <= tol, "edge {i}: got {g}, want {w}");
    }
}

/// Levels from the definition, straight from frac(x) (independent of `Disc::levels`).
/// Only used away from level boundaries, where frac rounding cannot matter.
fn levels_by_definition(x: f64, k: u32) -> Sample {
    let f = x - x.floor();
    let r = x.rem_euclid(f64::from(k));
    Sample {
        a: f < 0.5,
        b: (0.25..0.75).contains(&f),
        z: (0.25..0.5).contains(&r),
    }
}

#[test]
fn constant_one_rev_per_second_k4() {
    // 1 rev/s, K = 4: x = 4t. A rises at x = n → t = n/4; B rises at x = n + ¼ → t = n/4 +
    // 1/16; A falls at x = n + ½ → t = n/4 + 1/8; B falls at t = n/4 + 3/16. Z is high for
    // x mod 4 ∈ [¼, ½): rises at t = 1/16 + n, falls at t = 1/8 + n. x = 0 at t = 0 is the
    // initial level (A high), not an edge; x = 8 at the end (t = 2) is an edge.
    let p = Profile::constant(1.0, 2.0).unwrap();
    let d = Disc::new(4).unwrap();
    let es = edges(&p, &d);
    assert_eq!(
        initial_levels(&p, &d),
        Sample {
            a: true,
            b: false,
            z: false
        }
    );
    let n = |count: usize, first: f64, step: f64| -> Vec<f64> {
        (0..count).map(|i| first + i as f64 * step).collect()
    };
    assert_close(&of(&es, Channel::A, true), &n(8, 0.25, 0.25), 1e-12);
    assert_close(&of(&es, Channel::B, true), &n(8, 1.0 / 16.0, 0.25), 1e-12);
    assert_close(&of(&es, Channel::A, false), &n(8, 0.125, 0.25), 1e-12);
    assert_close(&of(&es, Channel::B, false), &n(8, 3.0 / 16.0, 0.25), 1e-12);
    assert_close(&of(&es, Channel::Z, true), &n(2, 1.0 / 16.0, 1.0), 1e-12);
    assert_close(&of(&es, Channel::Z, false), &n(2, 0.125, 1.0), 1e-12);
    assert_eq!(es.len(), 32 + 4);
    // Order at positive speed from x = 0 (A high, B low): B↑ A↓ B↓ A↑ — B lags A by 90°.
    let ab: Vec<_> = es
        .iter()
        .filter(|e| e.channel != Channel::Z)
        .take(4)
        .collect();
    let pat: Vec<_> = ab.iter().map(|e| (e.channel, e.rising)).collect();
    assert_eq!(
        pat,
        [
            (Channel::B, true),
            (Channel::A, false),
            (Channel::B, false),
            (Channel::A, true)
        ]
    );
}

#[test]
fn ramp_edges_match_quadratic_inverse() {
    // θ(t) = v0 t + a t²/2 with a = (v1 − v0)/D. The m-th quarter level (x = m/4, θ =
    // m/(4K)) is reached at t = (−v0 + sqrt(v0² + 2aθ))/a.
    let (v0, v1, dur, k) = (0.5, 3.0, 2.0, 8u32);
    let a = (v1 - v0) / dur;
    let es = edges(&Profile::ramp(v0, v1, dur).unwrap(), &Disc::new(k).unwrap());
    let ab: Vec<&Edge> = es.iter().filter(|e| e.channel != Channel::Z).collect();
    let total_quarters = (4.0 * f64::from(k) * (v0 * dur + 0.5 * a * dur * dur)).floor() as usize;
    assert_eq!(ab.len(), total_quarters);
    for (i, e) in ab.iter().enumerate() {
        let m = i + 1;
        let theta = m as f64 / (4.0 * f64::from(k));
        let t = (-v0 + (v0 * v0 + 2.0 * a * theta).sqrt()) / a;
        assert!((e.t - t).abs() <= 1e-12, "quarter {m}: {} vs {t}", e.t);
        let want = match m % 4 {
            0 => (Channel::A, true),
            1 => (Channel::B, true),
            2 => (Channel::A, false),
            _ => (Channel::B, false),
        };
        assert_eq!((e.channel, e.rising), want, "quarter {m}");
    }
}

#[test]
fn reversal_mirrors_edges_and_flips_phase_order() {
    // Speed 2 → −2 rev/s over 1.3 s: the motion is symmetric about t = 0.65 s (peak angle
    // 2·1.3/4 = 0.65 rev, x = 4.55 lines for K = 7: not on a level). Every edge at t in the
    // way out has a mirror at 1.3 − t on the same channel with the opposite polarity.
    let (speed, t_ramp, k) = (2.0, 1.3, 7u32);
    let p = Profile::reversal(speed, t_ramp).unwrap();
    let d = Disc::new(k).unwrap();
    let es = edges(&p, &d);
    // B and Z change together at x ≡ ¼ (mod K), so mirror each channel group separately:
    // the tie order of simultaneous edges is not part of the symmetry.
    for group in [[Channel::A, Channel::B], [Channel::Z, Channel::Z]] {
        let g: Vec<&Edge> = es.iter().filter(|e| group.contains(&e.channel)).collect();
        let n = g.len();
        assert!(n > 0);
        assert_eq!(n % 2, 0, "edges pair up");
        for i in 0..n / 2 {
            let (e, m) = (g[i], g[n - 1 - i]);
            assert_eq!(e.channel, m.channel, "pair {i}");
            assert_ne!(e.rising, m.rising, "pair {i}");
            assert!(
                (e.t + m.t - t_ramp).abs() <= 1e-12,
                "pair {i}: {} + {}",
                e.t,
                m.t
            );
            assert!(e.t < t_ramp / 2.0 && m.t > t_ramp / 2.0);
        }
    }
    // Phase order: at each A rising edge, B is low going forward and high going back.
    let mut lv = initial_levels(&p, &d);
    let mut seen = [false; 2];
    for e in &es {
        if e.channel == Channel::A && e.rising {
            let forward = e.t < t_ramp / 2.0;
            assert_eq!(lv.b, !forward, "A rising at {}", e.t);
            seen[usize::from(forward)] = true;
        }
        lv.apply(e);
    }
    assert_eq!(seen, [true, true]);
    assert_eq!(lv, initial_levels(&p, &d), "back at the start angle");
}

#[test]
fn rising_a_count_over_whole_revolutions() {
    // A sine speed that never reverses (1.5 < 2), over 3 whole periods: the angle advances
    // mean·D = 6 rev exactly, so A rises exactly 6K times whatever the start angle.
    for k in [1u32, 3, 100, 1024] {
        let p = Profile::sine(2.0, 1.5, 1.0, 3.0)
            .unwrap()
            .with_initial_angle(0.1)
            .unwrap();
        let es = edges(&p, &Disc::new(k).unwrap());
        assert_eq!(of(&es, Channel::A, true).len(), 6 * k as usize, "K = {k}");
        assert_eq!(of(&es, Channel::Z, true).len(), 6, "K = {k}");
    }
}

#[test]
fn sine_with_reversals_matches_fine_grid_scan() {
    // Brute force: evaluate the levels from the definition on a 1 µs grid and list every
    // change; each must match, in order, one edge lying inside that grid interval.
    let p = Profile::sine(0.3, 2.0, 2.0, 1.0)
        .unwrap()
        .with_initial_angle(0.37)
        .unwrap();
    let k = 50u32;
    let es = edges(&p, &Disc::new(k).unwrap());
    let h = 1e-6;
    let mut grid_changes = Vec::new();
    let mut prev = levels_by_definition(f64::from(k) * p.angle(0.0), k);
    for j in 1..=1_000_000u32 {
        let t = f64::from(j) * h;
        let now = levels_by_definition(f64::from(k) * p.angle(t), k);
        for (ch, was, is) in [
            (Channel::A, prev.a, now.a),
            (Channel::B, prev.b, now.b),
            (Channel::Z, prev.z, now.z),
        ] {
            if was != is {
                grid_changes.push((t - h, t, ch, is));
            }
        }
        prev = now;
    }
    assert!(
        grid_changes.len() > 20,
        "the profile must move through levels"
    );
    assert_eq!(grid_changes.len(), es.len());
    // Within one grid interval the order of channels may differ; compare sorted by channel.
    let key = |c: Channel| c as u8;
    let mut sorted_grid = grid_changes.clone();
    sorted_grid.sort_by(|a, b| a.0.total_cmp(&b.0).then(key(a.2).cmp(&key(b.2))));
    let mut sorted_edges = es.clone();
    sorted_edges.sort_by(|a, b| {
        ((a.t / h).ceil())
            .total_cmp(&(b.t / h).ceil())
            .then(key(a.channel).cmp(&key(b.channel)))
    });
    for ((lo, hi, ch, rising), e) in sorted_grid.iter().zip(&sorted_edges) {
        assert_eq!((e.channel, e.rising), (*ch, *rising), "grid change at {hi}");
        assert!(
            e.t > lo - 1e-12 && e.t <= hi + 1e-12,
            "edge {} not in ({lo}, {hi}]",
            e.t
        );
    }
}

#[test]
fn sampler_matches_brute_force_levels() {
    let p = Profile::new(
        0.2,
        vec![
            Segment::Ramp {
                from: 0.0,
                to: 4.0,
                duration: 0.5,
            },
            Segment::Sine {
                mean: 1.0,
                amplitude: 3.0,
                freq_hz: 3.0,
                duration: 1.0,
            },
            Segment::Stop { duration: 0.1 },
            Segment::Constant {
                speed: -2.3,
                duration: 0.4,
            },
        ],
    )
    .unwrap();
    let d = Disc::new(16).unwrap();
    let es = edges(&p, &d);
    let clock = 200_000.0;
    let sampler = ClockSampler::for_profile(&p, &d, &es, clock).unwrap();
    let n = sampler.len();
    assert_eq!(n as f64, (p.duration() * clock).floor() + 1.0);
    let mut near = 0usize;
    let mut next = 0usize;
    for (k, s) in sampler.enumerate() {
        let t = k as f64 / clock;
        while next < es.len() && es[next].t < t - 1e-12 {
            next += 1;
        }
        if next < es.len() && es[next].t <= t + 1e-12 {
            near += 1;
            continue;
        }
        assert_eq!(s, d.levels(d.position(p.angle(t))), "cycle {k}");
        assert_eq!(
            s,
            levels_by_definition(d.position(p.angle(t)), 16),
            "cycle {k}"
        );
    }
    assert!(near < 10, "only exact coincidences may be skipped ({near})");
    // Past the end the motion holds: the last sample equals the final levels.
    let last = ClockSampler::new(initial_levels(&p, &d), &es, clock, n as u64 + 1000)
        .unwrap()
        .last()
        .unwrap();
    assert_eq!(last, d.levels(d.position(p.angle(p.duration()))));
}

#[test]
fn edge_at_segment_boundary_is_neither_lost_nor_doubled() {
    // 1 rev/s for 0.25 s ends exactly on x = 1 (K = 4): A must rise once, at 0.25 s,
    // whether the next segment keeps going, stops or turns back.
    let d = Disc::new(4).unwrap();
    for next in [
        Segment::Constant {
            speed: 1.0,
            duration: 0.1,
        },
        Segment::Stop { duration: 0.1 },
        Segment::Constant {
            speed: -1.0,
            duration: 0.1,
        },
    ] {
        let p = Profile::constant(1.0, 0.25).unwrap().then(next).unwrap();
        let es = edges(&p, &d);
        let a: Vec<_> = es.iter().filter(|e| e.channel == Channel::A).collect();
        // A falls at x = ½ (t = 1/8) and rises at x = 1 (t = ¼), exactly once.
        assert_eq!((a[0].t, a[0].rising), (0.125, false), "{next:?}");
        assert_eq!((a[1].t, a[1].rising), (0.25, true), "{next:?}");
        assert_eq!(of(&es, Channel::A, true).len(), 1, "{next:?}");
        let reverses = matches!(next, Segment::Constant { speed, .. } if speed < 0.0);
        if reverses {
            // Turning back right at the level: A falls as soon as x < 1, i.e. at once.
            assert_eq!(a.len(), 3, "{next:?}");
            assert!(!a[2].rising && a[2].t >= 0.25 && a[2].t <= 0.25 + 1e-12);
        } else {
            assert_eq!(a.len(), 2, "{next:?}");
        }
    }
}

#[test]
fn validation_rejects_bad_profiles() {
    assert_eq!(Profile::new(0.0, vec![]), Err(PlantError::EmptyProfile));
    assert!(matches!(
        Profile::constant(1.0, 0.0),
        Err(PlantError::BadDuration { index: 0, .. })
    ));
    assert!(matches!(
        Profile::constant(f64::NAN, 1.0),
        Err(PlantError::NonFiniteSpeed { index: 0, .. })
    ));
    assert!(matches!(
        Profile::sine(1.0, 1.0, 0.0, 1.0),
        Err(PlantError::BadFrequency { .. })
    ));
    assert!(matches!(
        Profile::step(1.0, 2.0, 3.0, 2.0),
        Err(PlantError::BadStepTime { .. })
    ));
    assert!(Profile::constant(1.0, 1.0)
        .unwrap()
        .with_initial_angle(f64::INFINITY)
        .is_err());
    assert_eq!(Disc::new(0), Err(PlantError::ZeroLines));
    assert!(ClockSampler::new(Sample::default(), &[], 0.0, 1).is_err());
    let msg = Profile::ramp(1.0, 2.0, -1.0).unwrap_err().to_string();
    assert!(
        msg.contains("segment 0") && msg.contains("duration"),
        "{msg}"
    );
}

#[test]
fn step_and_stop_helpers() {
    // 2 rev/s for 0.5 s then 4 rev/s for 0.5 s, K = 1: angle 1 at 0.5 s, 3 at 1 s; A rises
    // at x = 1 (t = 0.5), 2 (t = 0.75) and 3 (t = 1.0).
    let es = edges(
        &Profile::step(2.0, 4.0, 0.5, 1.0).unwrap(),
        &Disc::new(1).unwrap(),
    );
    assert_close(&of(&es, Channel::A, true), &[0.5, 0.75, 1.0], 1e-12);
    // Stop: nothing after the run ends.
    let p = Profile::stop_after(3.0, 1.0, 5.0).unwrap();
    let es = edges(&p, &Disc::new(10).unwrap());
    assert!(es.iter().all(|e| e.t <= 1.0));
    assert_eq!(of(&es, Channel::A, true).len(), 30);
    assert_eq!(p.angle(4.0), 3.0);
    assert_eq!(p.speed(4.0), 0.0);
}

#[test]
fn ten_million_edges() {
    // 1000 rev/s, K = 1024, 2.5 s: 4·1024·2500 = 10,240,000 quadrature edges + 5000 Z.
    let k = 1024u32;
    let es = edges(
        &Profile::constant(1000.0, 2.5).unwrap(),
        &Disc::new(k).unwrap(),
    );
    assert_eq!(es.len(), 10_240_000 + 5000);
    let a = of(&es, Channel::A, true);
    assert_eq!(a.len(), 2_560_000);
    // A rises at t = n/(K·1000).
    for (i, t) in a.iter().enumerate().step_by(9973) {
        let want = (i + 1) as f64 / (f64::from(k) * 1000.0);
        assert!((t - want).abs() <= 1e-15, "{t} vs {want}");
    }
    assert!(es.windows(2).all(|w| w[0].t <= w[1].t));
}

fn segment() -> impl Strategy<Value = Segment> {
    let dur = 0.05..1.5f64;
    prop_oneof![
        (-5.0..5.0f64, dur.clone())
            .prop_map(|(speed, duration)| Segment::Constant { speed, duration }),
        (-5.0..5.0f64, -5.0..5.0f64, dur.clone()).prop_map(|(from, to, duration)| Segment::Ramp {
            from,
            to,
            duration
        }),
        (-3.0..3.0f64, -4.0..4.0f64, 0.2..5.0f64, dur.clone()).prop_map(
            |(mean, amplitude, freq_hz, duration)| Segment::Sine {
                mean,
                amplitude,
                freq_hz,
                duration
            }
        ),
        dur.prop_map(|duration| Segment::Stop { duration }),
    ]
}

fn profile() -> impl Strategy<Value = Profile> {
    (-2.0..2.0f64, prop::collection::vec(segment(), 1..6))
        .prop_map(|(a, s)| Profile::new(a, s).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn random_profiles_give_a_valid_quadrature_signal(p in profile(), k in 1u32..40) {
        let d = Disc::new(k).unwrap();
        let es = edges(&p, &d);
        let mut lv = initial_levels(&p, &d);
        let mut last_ab: Option<Edge> = None;
        let mut count = 0i64;
        for (i, e) in es.iter().enumerate() {
            prop_assert!(e.t.is_finite() && e.t > 0.0 && e.t <= p.duration());
            if i > 0 {
                prop_assert!(es[i - 1].t <= e.t, "out of order at {}", i);
            }
            // Each edge flips its channel: never two edges of one channel with one polarity.
            let before = match e.channel { Channel::A => lv.a, Channel::B => lv.b, Channel::Z => lv.z };
            prop_assert_eq!(before, !e.rising, "edge {} {:?}", i, e);
            // The position sits on a quarter level of the right kind.
            let x4 = 4.0 * d.position(p.angle(e.t));
            let m = x4.round();
            prop_assert!((x4 - m).abs() < 1e-9, "edge {} at 4x = {}", i, x4);
            let m = m as i64;
            match e.channel {
                Channel::A => prop_assert!(m.rem_euclid(2) == 0),
                Channel::B => prop_assert!(m.rem_euclid(2) == 1),
                Channel::Z => prop_assert!([1, 2].contains(&m.rem_euclid(4 * i64::from(k)))),
            }
            if e.channel != Channel::Z {
                // Quadrature decoding: forward iff the new (A, B) follows the old one in the
                // cycle (1,0) → (1,1) → (0,1) → (0,0). Between two edges of one channel
                // the motion must have turned, so the decoded direction flips.
                let state = |s: Sample| match (s.a, s.b) { (true, false) => 0i32, (true, true) => 1, (false, true) => 2, _ => 3 };
                let old = state(lv);
                let mut nl = lv;
                nl.apply(e);
                let step = (state(nl) - old).rem_euclid(4);
                prop_assert!(step == 1 || step == 3);
                let forward = step == 1;
                count += if forward { 1 } else { -1 };
                let v = p.speed(e.t);
                if v.abs() > 1e-3 {
                    prop_assert_eq!(forward, v > 0.0, "edge {} speed {}", i, v);
                }
                if let Some(prev) = last_ab {
                    if prev.channel == e.channel {
                        prop_assert_ne!(prev.rising, e.rising);
                    }
                }
                last_ab = Some(*e);
            }
            lv.apply(e);
        }
        let x_end = d.position(p.angle(p.duration()));
        prop_assert_eq!(lv, d.levels(x_end));
        let net = (4.0 * x_end).floor() as i64 - (4.0 * d.position(p.initial_angle)).floor() as i64;
        prop_assert_eq!(count, net);
    }

    #[test]
    fn random_profiles_sample_like_brute_force(p in profile(), k in 1u32..40) {
        let d = Disc::new(k).unwrap();
        let es = edges(&p, &d);
        let clock = 20_000.0;
        let mut next = 0usize;
        for (c, s) in ClockSampler::for_profile(&p, &d, &es, clock).unwrap().enumerate() {
            let t = c as f64 / clock;
            while next < es.len() && es[next].t < t - 1e-12 {
                next += 1;
            }
            if next < es.len() && es[next].t <= t + 1e-12 {
                continue;
            }
            prop_assert_eq!(s, d.levels(d.position(p.angle(t))), "cycle {}", c);
        }
    }
}
