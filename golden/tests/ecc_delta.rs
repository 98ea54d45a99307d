// SPDX-License-Identifier: MIT OR Apache-2.0
//! `golden::ecc::ecc_delta`: the bit-true correction δ of a span against hand-computed answers,
//! against f64 sin/cos within its derived error budget (max and RMS), against the f64
//! correction of `golden::eccentric::correct` (`Correction::count`), the cycle model against
//! the arithmetic's definition (timing included), and the ripple left on the rigid-disc
//! plant (e = 0.35/30, θ0 = 50°, K = 1024) by exact-time M/T with counts corrected by this δ.
//!
//! Figures: `cargo test --release -p encspeed-golden --test ecc_delta -- --nocapture`.

use golden::ecc::ecc_delta::{
    coefficients, delta_f64, delta_raw, error_budget, error_budget_max, latency_cycles, EccDelta,
    Inputs, Outputs, Request, DELTA_FRAC_BITS,
};
use golden::eccentric::correct::{ripple, Correction};
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::ideal::plant::Profile;
use std::f64::consts::TAU;

const ONE: f64 = (1u64 << DELTA_FRAC_BITS) as f64;
const E_EX: f64 = 0.35 / 30.0;

/// splitmix64, reproducible.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        golden::splitmix::next(&mut self.0)
    }
    fn signed(&mut self, bits: u32) -> i64 {
        ((self.next() << (64 - bits)) as i64) >> (64 - bits)
    }
}

/// The cycle model's δ for one request (start while idle), checking the latency.
fn cycle_delta(lines: u32, a: u32, d: u32, req: Request) -> i64 {
    let mut m = EccDelta::new(lines, a, d);
    let o = m.step(Inputs {
        start: true,
        req,
        ..Inputs::default()
    });
    assert!(o.busy && !o.valid);
    for _ in 1..latency_cycles() {
        let o = m.step(Inputs::default());
        assert!(o.busy && !o.valid);
    }
    let o = m.step(Inputs::default());
    assert!(o.valid && !o.busy);
    o.delta
}

#[test]
fn hand_computed_answers() {
    assert_eq!(latency_cycles(), 68);
    // K = 1024, c = 1 line, d = 0, x1, from line 0 to line 256: δ = sin(π/2) − 0 = 1 step.
    // By hand: ΔS8 = 8Q, P = 2^16·8·(2^23 − 1) = 2^42 − 2^19, ⌊P/2^23⌋ = 2^19 − 1,
    // R = 2^42 − 1, ⌊(R + 2^25)/2^26⌋ = 2^16: exactly 1 step.
    let req = Request {
        p_a: 0,
        p_b: 2 * 256,
        shift: 0,
        coef_c: 1 << 16,
        coef_d: 0,
    };
    assert_eq!(delta_raw(1024, 10, 24, &req), 1 << 16);
    assert_eq!(cycle_delta(1024, 10, 24, req), 1 << 16);
    // Backwards: −1 step; and with d = 1 line (cos): C(256) − C(0) = −1.
    let back = Request {
        p_a: 512,
        p_b: 0,
        ..req
    };
    assert_eq!(delta_raw(1024, 10, 24, &back), -(1 << 16));
    let cos = Request {
        coef_c: 0,
        coef_d: 1 << 16,
        ..req
    };
    assert_eq!(delta_raw(1024, 10, 24, &cos), -(1 << 16));
    // x4, a quarter line (one step = 2 half-steps): x_b = 1/4, t = 2/8. The exact value is
    // 4·sin(2π/4096) = 0.006135923 steps = 402.124 LSB. The table: S[1] =
    // round(sin(2π/1024)·(2^23 − 1)) = 51472; ΔS8 = 2·51472; P = 4·2^16·2·51472;
    // R/2^26 = 402.125 (linear interpolation, 3.6e-8 steps below the sine); rounded: 402.
    let q = Request {
        p_a: 0,
        p_b: 2,
        shift: 2,
        coef_c: 1 << 16,
        coef_d: 0,
    };
    assert_eq!(delta_raw(1024, 10, 24, &q), 402);
    assert_eq!(cycle_delta(1024, 10, 24, q), 402);
    assert!((delta_f64(1024, &q) * ONE - 402.124).abs() < 1e-3);
    // shift = 3 is taken as 2.
    assert_eq!(delta_raw(1024, 10, 24, &Request { shift: 3, ..q }), 402);
    // Half a line in x1 (Rairán's middle of a step): x = ½, t = 4/8: S8 = 4·S[1].
    let h = Request {
        p_a: 0,
        p_b: 1,
        shift: 0,
        coef_c: 1 << 16,
        coef_d: 0,
    };
    let r = (1i128 << 16) * 4 * 51472;
    let r = r + (r >> 23);
    assert_eq!(delta_raw(1024, 10, 24, &h), ((r + (1 << 25)) >> 26) as i64);
}

#[test]
fn cycle_model_equals_definition() {
    let mut rng = Rng(0xde17a);
    for &(lines, a, d) in &[
        (1024u32, 10u32, 24u32),
        (1000, 10, 24),
        (4, 2, 8),
        (4096, 12, 16),
        (2500, 12, 24),
        (12, 4, 12),
    ] {
        for i in 0..300 {
            let s = (rng.next() % 4) as u32;
            let span = u64::from(lines) << ((s.min(2)) + 1);
            let pos = |rng: &mut Rng| {
                if i % 10 == 0 {
                    rng.next() & ((1 << 33) - 1)
                } else {
                    rng.next() % span
                }
            };
            let coef = |rng: &mut Rng| match rng.next() % 5 {
                0 => -(1i64 << 31),
                1 => (1i64 << 31) - 1,
                _ => rng.signed(32),
            };
            let req = Request {
                p_a: pos(&mut rng),
                p_b: pos(&mut rng),
                shift: s,
                coef_c: coef(&mut rng),
                coef_d: coef(&mut rng),
            };
            assert_eq!(
                cycle_delta(lines, a, d, req),
                delta_raw(lines, a, d, &req),
                "K {lines} A {a} D {d} {req:?}"
            );
        }
    }
}

#[test]
fn timing_pending_requests_and_reset() {
    let req = |p_b: u64| Request {
        p_a: 0,
        p_b,
        shift: 0,
        coef_c: 1 << 16,
        coef_d: 3 << 14,
    };
    let val = |p_b| delta_raw(1024, 10, 24, &req(p_b));
    let start = |p_b| Inputs {
        start: true,
        req: req(p_b),
        ..Inputs::default()
    };
    let l = latency_cycles() as usize;
    // Three starts: at edge 0 (taken at 1), at 5 and at 9 (both while busy: the one at 9
    // replaces the one at 5), then one at 2L − 20 while the second job runs.
    let mut m = EccDelta::new(1024, 10, 24);
    let mut valids = vec![];
    for k in 0..4 * l {
        let inp = match k {
            0 => start(100),
            5 => start(200),
            9 => start(300),
            k if k == 2 * l - 20 => start(400),
            _ => Inputs::default(),
        };
        let o = m.step(inp);
        if o.valid {
            valids.push((k, o.delta));
        }
    }
    assert_eq!(
        valids,
        vec![(l, val(100)), (2 * l, val(300)), (3 * l, val(400)),]
    );
    // Reset wins over start and abandons everything.
    let mut m = EccDelta::new(1024, 10, 24);
    m.step(start(100));
    for _ in 0..10 {
        m.step(Inputs::default());
    }
    let o = m.step(Inputs {
        reset: true,
        ..start(200)
    });
    assert_eq!(o, Outputs::default());
    for _ in 0..3 * l {
        assert_eq!(m.step(Inputs::default()), Outputs::default());
    }
    // Starts exactly L apart: each gets its own result, L edges later.
    let mut m = EccDelta::new(1024, 10, 24);
    let mut got = vec![];
    for k in 0..5 * l + 1 {
        let o = m.step(if k.is_multiple_of(l) && k < 5 * l {
            start(10 * k as u64 + 1)
        } else {
            Inputs::default()
        });
        if o.valid {
            got.push((k, o.delta));
        }
    }
    let want: Vec<_> = (1..=5)
        .map(|i| (i * l, val(10 * ((i - 1) * l) as u64 + 1)))
        .collect();
    assert_eq!(got, want);
}

/// δ against f64 over random spans; returns (max error, RMS error, max error/budget).
fn against_f64(
    lines: u32,
    a: u32,
    d: u32,
    shift: u32,
    e: f64,
    seed: u64,
    n: usize,
) -> (f64, f64, f64) {
    let mut rng = Rng(seed);
    let (mut max, mut sq, mut ratio) = (0f64, 0f64, 0f64);
    for _ in 0..n {
        let theta0 = TAU * (rng.next() % 1_000_000) as f64 / 1e6;
        let (c, dd) = coefficients(lines, e, theta0);
        let span = u64::from(lines) << (shift + 1);
        let req = Request {
            p_a: rng.next() % span,
            p_b: rng.next() % span,
            shift,
            coef_c: c,
            coef_d: dd,
        };
        let got = delta_raw(lines, a, d, &req) as f64 / ONE;
        let want = delta_f64(lines, &req);
        let err = (got - want).abs();
        let b = error_budget(lines, d, &req).total();
        assert!(
            err <= b,
            "K {lines} D {d} {req:?}: {got} vs {want}, budget {b}"
        );
        max = max.max(err);
        sq += err * err;
        ratio = ratio.max(err / b);
    }
    let rms = (sq / n as f64).sqrt();
    (max, rms, ratio)
}

#[test]
fn within_budget_of_f64() {
    println!("δ − δ_f64 over random spans (e = 0.35/30, random θ0), steps:");
    for &(lines, a, d) in &[
        (1024u32, 10u32, 24u32),
        (1000, 10, 24),
        (4096, 12, 24),
        (1024, 10, 16),
    ] {
        for shift in 0..3 {
            let (max, rms, ratio) =
                against_f64(lines, a, d, shift, E_EX, 0xe1 + u64::from(shift), 20_000);
            let (c, dd) = coefficients(lines, E_EX, 50f64.to_radians());
            let b = error_budget_max(lines, d, shift, c, dd);
            println!(
                "K {lines:>4} D {d} x{}: max {max:.3e}, RMS {rms:.3e}, max/own budget {ratio:.3}; \
                 worst-case budget {:.3e} (table {:.2e}, interpolation {:.2e}, rounding {:.2e})",
                1 << shift,
                b.total(),
                b.table,
                b.interpolation,
                b.rounding
            );
            assert!(max <= b.total());
            // RMS: well below the worst case (each term is bounded, not typical).
            assert!(rms <= b.total() / 2.0, "{rms}");
        }
    }
    // Large coefficients (|c|, |d| up to 2^15 lines) and any positions: budget holds.
    let mut rng = Rng(77);
    for _ in 0..20_000 {
        let shift = (rng.next() % 3) as u32;
        let req = Request {
            p_a: rng.next() % (1024 << (shift + 1)),
            p_b: rng.next() % (1024 << (shift + 1)),
            shift,
            coef_c: rng.signed(32),
            coef_d: rng.signed(32),
        };
        let err = (delta_raw(1024, 10, 24, &req) as f64 / ONE - delta_f64(1024, &req)).abs();
        assert!(err <= error_budget(1024, 24, &req).total(), "{req:?}");
    }
}

#[test]
fn equals_correction_count_at_lines() {
    // x1 at whole lines: N_c = ΔM − δ against Correction::first_order(K, e, θ0).count, to the
    // budget plus the coefficients' quantisation (½ LSB of Q15.16 each, times |ΔS|, |ΔC| ≤ 2).
    let mut worst: f64 = 0.0;
    for &lines in &[1024u32, 1000] {
        for &theta0 in &[50f64.to_radians(), -2.0, 3.0] {
            let corr = Correction::first_order(lines, E_EX, theta0);
            let (c, d) = coefficients(lines, E_EX, theta0);
            for m_a in (-1500i64..1500).step_by(7) {
                for span in [1i64, 2, 17, 256, 1024, 5000, -1, -300] {
                    let m_b = m_a + span;
                    let k = i64::from(lines);
                    let req = Request {
                        p_a: 2 * m_a.rem_euclid(k) as u64,
                        p_b: 2 * m_b.rem_euclid(k) as u64,
                        shift: 0,
                        coef_c: c,
                        coef_d: d,
                    };
                    let n_c = span as f64 - delta_raw(lines, 10, 24, &req) as f64 / ONE;
                    let want = corr.count(m_a, m_b);
                    let budget = error_budget(lines, 24, &req).total() + 2.0 * 2.0 * 0.5 / 65536.0;
                    assert!(
                        (n_c - want).abs() <= budget,
                        "K {lines} θ0 {theta0} {m_a}..{m_b}: {n_c} vs {want}"
                    );
                    worst = worst.max((n_c - want).abs());
                }
            }
        }
    }
    println!("N_c = ΔM − δ vs Correction::count: worst {worst:.2e} lines");
}

/// (position in steps, instant) of every forward crossing of a step level: lines (x1) or
/// quarter lines (x4).
fn step_times(disc: &EccentricDisc, p: &Profile, shift: u32) -> Vec<(i64, f64)> {
    disc.crossings(p)
        .into_iter()
        .filter(|c| c.forward && c.quarter.rem_euclid(1 << (2 - shift)) == 0)
        .map(|c| (c.quarter >> (2 - shift), c.t))
        .collect()
}

/// The request of a span of steps (half-step positions, whole steps).
fn span_request(a: i64, b: i64, shift: u32, c: i64, d: i64) -> Request {
    let steps = 1024i64 << shift;
    Request {
        p_a: 2 * a.rem_euclid(steps) as u64,
        p_b: 2 * b.rem_euclid(steps) as u64,
        shift,
        coef_c: c,
        coef_d: d,
    }
}

#[test]
fn ripple_on_rigid_disc_with_exact_theta0() {
    let k = 1024u32;
    let theta0 = 50f64.to_radians();
    let disc =
        EccentricDisc::new(k, Eccentricity::new(Model::Rigid, E_EX, theta0).unwrap()).unwrap();
    let (c, d) = coefficients(k, E_EX, theta0);
    // Relative budget of a span: the f64 correction's own residual (docs/eccentricity.md §5:
    // 0.3077 ppm), the coefficients' rounding to Q15.16 (|Δc| + |Δd| lines times
    // |ΔS| ≤ (2π/K)·Δx, per Δx), and δ's budget over the span, all over the true angle
    // ≥ (1 − e)·Δx.
    let big_e = f64::from(k) * E_EX / TAU;
    let one = 65536.0;
    let coef_q = ((c as f64 / one - big_e * theta0.cos()).abs()
        + (d as f64 / one - big_e * theta0.sin()).abs())
        * TAU
        / f64::from(k);
    let f64_residual = 0.3077e-6 * 1.001;
    println!(
        "rigid disc e = 0.35/30, θ0 = 50° (off the line grid), K = {k}: coef_c = {c}, \
         coef_d = {d}; coefficient rounding {:.3} ppm",
        coef_q * 1e6
    );
    for &rpm in &[104.087, 1000.0] {
        let speed = rpm / 60.0;
        let omega = speed * TAU;
        let p = Profile::constant(speed, 1.02 / speed)
            .unwrap()
            .with_initial_angle(disc.shaft_angle_rev(-1.3))
            .unwrap();
        for shift in [0u32, 2] {
            let times = step_times(&disc, &p, shift);
            let steps = f64::from(k << shift);
            let spans: &[usize] = if shift == 0 { &[1, 16] } else { &[1, 4, 64] };
            for &w in spans {
                let (mut before, mut after) = (vec![], vec![]);
                let mut worst_excess: f64 = f64::NEG_INFINITY;
                let mut max_budget: f64 = 0.0;
                for s in times.windows(w + 1) {
                    let (a, b) = (s[0], s[w]);
                    let dt = b.1 - a.1;
                    let dm = (b.0 - a.0) as f64;
                    before.push(TAU * dm / steps / dt);
                    let req = span_request(a.0, b.0, shift, c, d);
                    let n_c = dm - delta_raw(k, 10, 24, &req) as f64 / ONE;
                    let v = TAU * n_c / steps / dt;
                    after.push(v);
                    let budget = f64_residual
                        + (coef_q + error_budget(k, 24, &req).total() / dm) / (1.0 - E_EX);
                    worst_excess = worst_excess.max((v / omega - 1.0).abs() - budget);
                    max_budget = max_budget.max(budget);
                }
                let before = ripple(&before, omega);
                let after = ripple(&after, omega);
                println!(
                    "{rpm:>8} rpm x{} {w:>2}-step spans: before {:.1} ppm peak, after {:.3} ppm \
                     peak ({:.3} p-p), largest span budget {:.3} ppm, suppression {:.0}x",
                    1 << shift,
                    before.peak * 1e6,
                    after.peak * 1e6,
                    after.peak_to_peak * 1e6,
                    max_budget * 1e6,
                    before.peak / after.peak
                );
                assert!(worst_excess <= 0.0, "over budget by {worst_excess}");
                assert!(before.peak > 10_000e-6);
            }
        }
    }
}
