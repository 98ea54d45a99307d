// SPDX-License-Identifier: MIT OR Apache-2.0
//! `golden::ecc::ecc_n3` (the bit-true n3 corrector): hand-worked values, the hardware
//! algorithm against the rule (exhaustive on small operands, proptest on the full ranges),
//! the rule against the f64 rule of `golden::eccentric::n3`, and the timing.

use golden::ecc::ecc_n3::{
    corrected, corrected_magnitude, factor, hardware_magnitude, EccN3, EccN3Inputs, LATENCY_CYCLES,
};
use proptest::prelude::*;

const S: u32 = 41; // N = 24
const ONE: i64 = 1 << 16;

#[test]
fn hand_values() {
    // Nep1 ≥ 2, Ndt1 = 1: n3 = 29.5 steps/dt, δ = +0.25 step → 29.25 (forward);
    // backward the magnitude grows: −29.5 → −29.75.
    let n3 = 59 * ONE / 2;
    assert_eq!(corrected(n3, ONE / 4, false, true, S), 117 * ONE / 4);
    assert_eq!(corrected(-n3, ONE / 4, false, true, S), -119 * ONE / 4);
    // Nep1 = 1: n3 = 2/3 step/dt → raw 43691 (rounded); δ = 0.01 step = 655.36 → 655:
    // 43691·(65536 − 655)/65536 = 43254.33… → 43254.
    assert_eq!(corrected(43_691, 655, true, true, S), 43_254);
    // Transient (Nep1 ≥ 2, Ndt1 ≥ 2): unchanged.
    assert_eq!(corrected(12_345, 999, false, false, S), 12_345);
    // Zero stays zero; clamps, never wraps.
    assert_eq!(corrected(0, 5 * ONE, true, false, S), 0);
    assert_eq!(corrected(ONE, 2 * ONE, false, true, S), 0);
    let max = (1i64 << (S - 1)) - 1;
    assert_eq!(corrected(max, -ONE, false, true, S), max);
    assert_eq!(corrected(-max, ONE, false, true, S), -max);
    assert_eq!(factor(-10 * i128::from(ONE)), 1 << 17);
    assert_eq!(factor(2 * i128::from(ONE)), 0);
    assert_eq!(corrected(max, -ONE, true, false, S), max);
}

#[test]
fn hardware_algorithm_equals_the_rule_on_small_operands() {
    for m in (0..2000u64).chain([1 << 20, (1 << 40) - 1]) {
        for d in (-70_000i128..=140_000).step_by(997) {
            for (a, b) in [(true, true), (true, false), (false, true), (false, false)] {
                assert_eq!(
                    hardware_magnitude(m, d, a, b, S),
                    corrected_magnitude(m, d, a, b, S),
                    "m = {m}, d = {d}, nep1 = {a}, ndt1 = {b}"
                );
            }
        }
    }
}

proptest! {
    #[test]
    fn hardware_algorithm_equals_the_rule(s in 25u32..=49, m in any::<u64>(), d in any::<i64>(),
                                          a in any::<bool>(), b in any::<bool>()) {
        let m = m & ((1u64 << (s - 1)) - 1);
        let d = i128::from(d >> 24); // 40-bit δ
        prop_assert_eq!(hardware_magnitude(m, d, a, b, s), corrected_magnitude(m, d, a, b, s));
    }

    /// Against the f64 rule n3·(1 − δ) / n3 − δ of `eccentric::n3` (forward; backward mirrored): within ½ LSB plus the
    /// f64 rounding of the comparison, in the range the core produces.
    #[test]
    fn rule_matches_the_f64_rule(n3 in -(1i64 << 39)..(1i64 << 39), delta in -(1i64 << 20)..(1i64 << 20),
                                 nep1 in any::<bool>()) {
        // A one-step span cannot move by a step or more (that needs e ≥ 1/√2): f is clamped
        // there by definition.
        prop_assume!(!nep1 || delta.abs() < ONE);
        let (n, d) = (n3 as f64 / 65_536.0, delta as f64 / 65_536.0);
        let sign = if n3 < 0 { -1.0 } else { 1.0 };
        // δ is taken in the order of motion (ΔM = ±N), so n3·(ΔM − δ)/ΔM is n3·(1 − sign·δ)
        // for a one-step span and n3 − δ (signed) for the others.
        let want = if nep1 { n * (1.0 - sign * d) } else { n - d };
        let got = corrected(n3, delta, nep1, true, S) as f64 / 65_536.0;
        // Clamped results (a correction larger than the speed) are 0 by definition.
        // n3 = 0 means no speed, and stays 0.
        if n3 != 0 && want * sign > 0.0 {
            prop_assert!((got - want).abs() <= 0.5 / 65_536.0 + 1e-9 * want.abs(), "{got} vs {want}");
        } else {
            prop_assert_eq!(got, 0.0);
        }
    }
}

#[test]
fn timing_latency_latest_start_and_reset() {
    let mut b = EccN3::new(S);
    let idle = EccN3Inputs::default();
    let req = |n3| EccN3Inputs {
        start: true,
        n3,
        ndt_is_one: true,
        delta: ONE,
        ..idle
    };
    let o = b.step(req(10 * ONE));
    assert!(o.busy && !o.valid);
    for i in 1..LATENCY_CYCLES {
        let o = b.step(idle);
        assert!(!o.valid, "valid early at {i}");
    }
    let o = b.step(idle);
    assert!(o.valid && !o.busy);
    assert_eq!(o.n3c, 9 * ONE);
    // Two starts while busy: the last one is computed next.
    b.step(req(20 * ONE));
    b.step(req(30 * ONE));
    b.step(req(40 * ONE));
    let mut seen = vec![];
    for _ in 0..3 * LATENCY_CYCLES {
        let o = b.step(idle);
        if o.valid {
            seen.push(o.n3c);
        }
    }
    assert_eq!(seen, vec![19 * ONE, 39 * ONE]);
    // Reset wins.
    b.step(req(50 * ONE));
    let o = b.step(EccN3Inputs {
        reset: true,
        ..idle
    });
    assert_eq!((o.n3c, o.valid, o.busy), (0, false, false));
    for _ in 0..2 * LATENCY_CYCLES {
        assert!(!b.step(idle).valid);
    }
}
