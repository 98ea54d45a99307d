//! The sine table (`golden::sine_rom`) and the first-harmonic corrector
//! (`golden::ecc_corrector`): hand-worked values, the table's ½-LSB bound against f64 sin,
//! the compare-and-subtract index against `%`, and the bit-true corrector against the f64
//! correction (`golden::eccentric::correct`) within its derived error budget, including the
//! speed ripple on the rigid-disc plant at e = 0.35/30, K = 1024.
//!
//! Figures: `cargo test --release -p encspeed-golden --test sine_rom_ecc -- --nocapture`.

use golden::ecc_corrector::{
    corrected, e_register, error_budget, EccCorrector, EccInputs, EccOutputs, NC_FRAC,
};
use golden::eccentric::correct::{line_period_speeds, ripple, Correction};
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::plant::Profile;
use golden::sine_rom::{full_scale, sine_index, sine_table, table_error_bound, SineRom};
use std::f64::consts::TAU;

const K: u32 = 1024;

#[test]
fn k4_table_is_0_max_0_minus_max() {
    assert_eq!(sine_table(4, 2, 16), vec![0, 32767, 0, -32767]);
    assert_eq!(sine_table(4, 3, 8), vec![0, 127, 0, -127, 0, 0, 0, 0]);
    // K = 6, D = 8: round(127·sin 60°) = round(109.985) = 110.
    assert_eq!(sine_table(6, 3, 8), vec![0, 110, 110, 0, -110, -110, 0, 0]);
    assert_eq!(full_scale(16), 32767);
    assert_eq!(table_error_bound(16), 0.5 / 32767.0);
}

#[test]
fn table_within_half_lsb_of_sin() {
    for &(lines, a) in &[
        (3u32, 2u32),
        (4, 2),
        (1000, 10),
        (1024, 10),
        (4096, 12),
        (2500, 12),
    ] {
        for &d in &[4u32, 8, 12, 16, 24, 32] {
            let q = full_scale(d) as f64;
            let t = sine_table(lines, a, d);
            assert_eq!(t.len(), 1 << a);
            let worst = (0..lines as usize)
                .map(|i| (t[i] as f64 / q - (TAU * i as f64 / f64::from(lines)).sin()).abs())
                .fold(0.0, f64::max);
            assert!(
                worst <= table_error_bound(d) * (1.0 + 1e-9),
                "K {lines} D {d}: {worst}"
            );
            // With many entries the bound is nearly reached: it is the right bound.
            if lines >= 1000 && d <= 16 {
                assert!(
                    worst > 0.9 * table_error_bound(d),
                    "K {lines} D {d}: {worst}"
                );
            }
            assert!(t[lines as usize..].iter().all(|&v| v == 0));
        }
    }
}

#[test]
fn index_is_sum_mod_k_without_division() {
    for &(lines, a) in &[
        (2u32, 1u32),
        (4, 2),
        (5, 3),
        (1000, 10),
        (1024, 10),
        (700, 12),
    ] {
        for m in 0..u64::from(lines) {
            for m0 in 0..u64::from(lines) {
                assert_eq!(sine_index(lines, a, m, m0), (m + m0) % u64::from(lines));
            }
        }
    }
    // Out of contract (m ≥ K): still a defined A-bit address.
    assert_eq!(
        sine_index(1000, 10, 1023, 1023),
        (1023 + 1023 - 1000) & 1023
    );
}

#[test]
fn rom_has_one_cycle_latency() {
    let mut rom = SineRom::new(4, 2, 16);
    assert_eq!(rom.data(), 0);
    assert_eq!(rom.step(1, 0), 32767);
    assert_eq!(rom.step(1, 2), -32767);
    assert_eq!(rom.step(3, 3), 0);
    assert_eq!(rom.step(2, 3), 32767);
}

#[test]
fn corrector_hand_values() {
    const Q: i64 = (1 << 23) - 1;
    const ONE: i64 = 1 << 24;
    // E_reg = 8192, S_b = Q, S_a = 0: d = 2^13·(2^23 − 1) = 2^36 − 2^13, so
    // ⌊(d + 2^11)/2^12⌋ = ⌊2^24 − 1.5⌋ = 2^24 − 2: W = 1 − 2^-23 lines.
    assert_eq!(corrected(3, 8192, 0, Q), 3 * ONE - (ONE - 2));
    assert_eq!(corrected(-2, -8192, 0, Q), -2 * ONE + (ONE - 2));
    // Rounding half up: d = −2048 → 0, d = −2049 → −1, d = 2047 → 0, d = 2048 → 1.
    assert_eq!(corrected(0, 1, 2048, 0), 0);
    assert_eq!(corrected(0, 1, 2049, 0), 1);
    assert_eq!(corrected(0, 1, 0, 2047), 0);
    assert_eq!(corrected(0, 1, 0, 2048), -1);
    // Extremes: |E_reg·ΔS| < 2^39, |N_c·2^24| < 2^48.
    assert_eq!(
        corrected(-(1 << 23), -32768, Q, -Q),
        -(1i64 << 47) - ((32768 * 2 * Q + 2048) >> 12)
    );
    // E = 1 line: E_reg = round(8192·2^23/Q) = round(8192.00098) = 8192.
    assert_eq!(e_register(1.0), 8192);
    assert_eq!(e_register(-3.9), -31949);
    // Pipeline: request at edge 0, result after edge 1, valid for one cycle.
    let mut c = EccCorrector::new(4, 2);
    let req = EccInputs {
        start: true,
        delta_m: 5,
        m_a: 0,
        m_b: 1,
        m0: 0,
        e_coef: 8192,
        ..EccInputs::default()
    };
    assert_eq!(c.step(req), EccOutputs::default());
    let want = EccOutputs {
        n_c: 5 * ONE - (ONE - 2),
        valid: true,
    };
    assert_eq!(c.step(EccInputs::default()), want);
    assert_eq!(
        c.step(EccInputs::default()),
        EccOutputs {
            valid: false,
            ..want
        }
    );
}

/// The bit-true corrector's N_c (lines) for a request.
fn hw_count(lines: u32, e_reg: i64, m0: u64, m_a: i64, m_b: i64) -> f64 {
    let mut c = EccCorrector::new(lines, 10);
    let k = i64::from(lines);
    c.step(EccInputs {
        start: true,
        delta_m: m_b - m_a,
        m_a: m_a.rem_euclid(k) as u64,
        m_b: m_b.rem_euclid(k) as u64,
        m0,
        e_coef: e_reg,
        ..EccInputs::default()
    });
    let o = c.step(EccInputs::default());
    assert!(o.valid);
    o.n_c as f64 / f64::from(1u32 << NC_FRAC)
}

#[test]
fn corrector_within_budget_of_f64_correction() {
    let e = 0.35 / 30.0;
    let mut worst_ratio: f64 = 0.0;
    let mut worst_single: f64 = 0.0;
    for &(lines, m0) in &[(K, 300u64), (K, 0), (1000, 777)] {
        let theta0 = TAU * m0 as f64 / f64::from(lines);
        let corr = Correction::first_order(lines, e, theta0);
        let e_lines = corr.terms[0].amplitude;
        let e_reg = e_register(e_lines);
        for m_a in (-1500i64..1500).step_by(7) {
            for span in [1i64, 2, 17, 64, 333, 1024, 5000, -1, -300] {
                let m_b = m_a + span;
                let want = corr.count(m_a, m_b);
                let got = hw_count(lines, e_reg, m0, m_a, m_b);
                let ds = corr.sine(&corr.terms[0], m_b) - corr.sine(&corr.terms[0], m_a);
                let budget = error_budget(e_lines, ds);
                worst_ratio = worst_ratio.max((got - want).abs() / budget);
                if span == 1 {
                    worst_single = worst_single.max((got - want).abs());
                }
                assert!(
                    (got - want).abs() <= budget,
                    "K {lines} m0 {m0} m_a {m_a} span {span}: {got} vs {want}, budget {budget}"
                );
            }
        }
    }
    println!(
        "corrector vs f64 correction: worst |error|/budget {worst_ratio:.3}; worst single-line \
         error {:.2e} lines (budget {:.2e})",
        worst_single,
        error_budget(f64::from(K) * e / TAU, TAU / f64::from(K))
    );
}

#[test]
fn ripple_on_rigid_disc_before_and_after_hardware_correction() {
    let e = 0.35 / 30.0;
    let m0 = 300u64;
    let theta0 = TAU * m0 as f64 / f64::from(K);
    let disc = EccentricDisc::new(K, Eccentricity::new(Model::Rigid, e, theta0).unwrap()).unwrap();
    let corr = Correction::first_order(K, e, theta0);
    let e_lines = corr.terms[0].amplitude;
    let e_reg = e_register(e_lines);
    println!("rigid disc e = {e:.6}, K = {K}, m0 = {m0}, E = {e_lines:.5} lines, E_reg = {e_reg}");
    for &rpm in &[104.087, 1000.0] {
        let speed = rpm / 60.0;
        let p = Profile::constant(speed, 1.02 / speed)
            .unwrap()
            .with_initial_angle(disc.shaft_angle_rev(-1.5))
            .unwrap();
        let lines = disc.line_crossings(&p);
        let omega = speed * TAU;
        let speeds = |c: &Correction| -> Vec<f64> {
            line_period_speeds(&lines, c)
                .iter()
                .map(|s| s.speed)
                .collect()
        };
        let before = ripple(&speeds(&Correction::none(K)), omega);
        let f64_after = ripple(&speeds(&corr), omega);
        for &w in &[1usize, 64] {
            let hw: Vec<f64> = lines
                .windows(w + 1)
                .map(|s| {
                    let (a, b) = (s[0], s[w]);
                    let n = hw_count(K, e_reg, m0, a.0, b.0);
                    TAU * n / f64::from(K) / (b.1 - a.1)
                })
                .collect();
            let after = ripple(&hw, omega);
            // Budget (relative): the f64 correction's own residual plus the quantisation
            // budget over w lines.
            let budget = 0.31e-6
                + error_budget(e_lines, 2.0 * (TAU * w as f64 / 2048.0).sin()) / w as f64 * 1.02;
            println!(
                "{rpm:>8} rpm, {w:>2}-line spans: before {:.1} ppm peak; f64 correction {:.3} \
                 ppm; hardware {:.3} ppm peak ({:.3} p-p), budget {:.3} ppm",
                before.peak * 1e6,
                f64_after.peak * 1e6,
                after.peak * 1e6,
                after.peak_to_peak * 1e6,
                budget * 1e6
            );
            assert!(after.peak <= budget, "{}", after.peak);
            assert!(before.peak / after.peak > 5_000.0);
        }
        assert!((before.peak * 1e6 - 11_804.0).abs() < 1.0);
    }
}
