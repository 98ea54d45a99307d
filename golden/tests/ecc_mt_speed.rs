// SPDX-License-Identifier: MIT OR Apache-2.0
//! Tests of the corrected M/T speed model `golden::ecc::ecc_mt_speed`. Truth from outside the
//! model: values worked by hand; `golden::baselines::baseline_speeds::speed_mt` (an independent,
//! already-verified definition) for δ = 0; the rounding rule restated here from quotient and
//! remainder; f64. The hardware algorithm (`hardware_*`) is proven equal to the exact rule
//! exhaustively at small widths (every m, t, dt, δ and mode_shift) and on random operands at
//! N = 24 and 32 with the real δ format; the schedule against edge counts worked by hand.

use golden::baselines::baseline_speeds::{speed_mt, BaselineFormat};
use golden::ecc::ecc_delta::{DELTA_BITS, DELTA_FRAC_BITS};
use golden::ecc::ecc_mt_speed::{
    corrected_bits, ecc_mt_speed, exact_speed, hardware_divide, hardware_multiply,
    hardware_request, hardware_speed, latency_cycles, speed_mtc, EccMtRequest, EccMtSpeedInputs,
    EccMtSpeedModel, EccMtSpeedOutputs, EccWidths,
};
use golden::estimator::speed_calc::speed_lsb_error;
use proptest::prelude::*;

fn fmt(n: u32, f: u32) -> BaselineFormat {
    BaselineFormat::new(n, f).unwrap()
}

/// δ in steps as D (units of 2^−16 step), exact for the values used here.
fn d(steps: f64) -> i64 {
    let v = steps * 65536.0;
    assert_eq!(v.fract(), 0.0);
    v as i64
}

/// round(num/den), ties up, from quotient and remainder; saturated at `max`.
fn reference(num: u128, den: u128, max: u128) -> u128 {
    let (q, r) = (num / den, num % den);
    (if 2 * r >= den { q + 1 } else { q }).min(max)
}

/// The rule restated: ±reference((m·2^g − D)·dt·2^F, t·2^(g+s)); 0 for m = 0, t = 0 or
/// m·2^g ≤ D.
fn restated(w: EccWidths, m: u64, t: u64, dt: u64, delta: i64, neg: bool, shift: u32) -> i64 {
    let c = i128::from(m) * (1i128 << w.delta_frac_bits) - i128::from(delta);
    if m == 0 || t == 0 || c <= 0 {
        return 0;
    }
    let s = shift.min(2);
    let num = c as u128 * u128::from(dt.max(1)) * (1u128 << w.frac_bits);
    let den = u128::from(t) * (1u128 << (w.delta_frac_bits + s));
    let mag = reference(num, den, w.max_magnitude()) as i64;
    if neg {
        -mag
    } else {
        mag
    }
}

#[test]
fn delta_format_is_the_ecc_delta_one() {
    assert_eq!((DELTA_BITS, DELTA_FRAC_BITS), (40, 16));
    let w = EccWidths::of(fmt(24, 16));
    assert_eq!((w.delta_bits, w.delta_frac_bits), (40, 16));
    assert_eq!(w.delta_range(), -(1i64 << 39)..=(1i64 << 39) - 1);
    assert_eq!(w.delta_to_raw(-1), (1u64 << 40) - 1);
    // C: the largest c = (2^N − 1)·2^16 + 2^39 needs 40 bits up to N = 23, N + 17 above.
    for n in 8..=32u32 {
        let max = (((1u128 << n) - 1) << 16) + (1u128 << 39);
        assert!(max < 1u128 << corrected_bits(n) && max >= 1u128 << (corrected_bits(n) - 1));
    }
    assert_eq!(corrected_bits(24), 41);
    assert_eq!(corrected_bits(12), 40);
}

#[test]
fn known_answers_by_hand() {
    let f = fmt(24, 16);
    // m = 100 steps, δ = 0.5 step, dt = 10 000, t = 1 000 000, x1:
    // (99.5·10 000/1e6)·2^16 = 0.995·65536 = 65208.32 → 65208; reversed −65208.
    assert_eq!(
        speed_mtc(f, 100, 1_000_000, 10_000, d(0.5), false, 0),
        65_208
    );
    assert_eq!(
        speed_mtc(f, 100, 1_000_000, 10_000, d(0.5), true, 0),
        -65_208
    );
    // Without the correction the same counts give exactly 1.0 = 65536.
    assert_eq!(speed_mtc(f, 100, 1_000_000, 10_000, 0, false, 0), 65_536);
    // The same at x4: 65208.32/4 = 16302.08 → 16302; x2: 32604.16 → 32604.
    assert_eq!(
        speed_mtc(f, 100, 1_000_000, 10_000, d(0.5), false, 2),
        16_302
    );
    assert_eq!(
        speed_mtc(f, 100, 1_000_000, 10_000, d(0.5), false, 3),
        16_302
    );
    assert_eq!(
        speed_mtc(f, 100, 1_000_000, 10_000, d(0.5), false, 1),
        32_604
    );
    // x2, m = 7, δ = −1.75: 8.75 steps·1000/3000 = 2.916 666… steps per dt,
    // ·2^15 = 95 573.33 → 95 573.
    assert_eq!(speed_mtc(f, 7, 3000, 1000, d(-1.75), false, 1), 95_573);
    // x4, m = 3, δ = −0.25, dt = 1, t = 8192: 3.25·2^14/8192 = 6.5, a tie: 7 (−7 reversed).
    assert_eq!(speed_mtc(f, 3, 8192, 1, d(-0.25), false, 2), 7);
    assert_eq!(speed_mtc(f, 3, 8192, 1, d(-0.25), true, 2), -7);
    // Just below the tie (t = 8193): 6.4992 → 6.
    assert_eq!(speed_mtc(f, 3, 8193, 1, d(-0.25), true, 2), -6);
    // cfg_dt = 0 counts as 1: m = 3, δ = 0.5, t = 5, N = 8, F = 4, x1: 2.5·16/5 = 8.
    assert_eq!(speed_mtc(fmt(8, 4), 3, 5, 0, d(0.5), false, 0), 8);
    // Rounding to zero is 0, never −0 or −1: 0.25·16/255 = 0.016.
    assert_eq!(speed_mtc(fmt(8, 4), 1, 255, 1, d(0.75), true, 0), 0);
}

#[test]
fn zeros() {
    let f = fmt(24, 16);
    // m = 0 or t = 0: 0, whatever δ (a negative δ would make m − δ positive).
    assert_eq!(speed_mtc(f, 0, 1000, 1000, d(-3.0), false, 0), 0);
    assert_eq!(speed_mtc(f, 0, 1000, 1000, d(-3.0), true, 0), 0);
    assert_eq!(speed_mtc(f, 10, 0, 1000, d(0.5), true, 0), 0);
    // m − δ ≤ 0: δ = m gives 0, δ = m + 2^−16 gives 0, the largest δ gives 0.
    assert_eq!(speed_mtc(f, 5, 1, 1000, d(5.0), false, 0), 0);
    assert_eq!(speed_mtc(f, 5, 1, 1000, d(5.0) + 1, true, 0), 0);
    assert_eq!(speed_mtc(f, 5, 1, 1000, (1 << 39) - 1, false, 0), 0);
    // δ = m − 2^−16: c = 1, so the value is dt·2^−16·2^16/t = dt: with dt = 2^24 − 1,
    // t = 1, x1, exactly 16 777 215 (−16 777 215 reversed).
    let dt = (1 << 24) - 1;
    assert_eq!(speed_mtc(f, 5, 1, dt, d(5.0) - 1, false, 0), 16_777_215);
    assert_eq!(speed_mtc(f, 5, 1, dt, d(5.0) - 1, true, 0), -16_777_215);
}

#[test]
fn saturates_never_wraps() {
    let f = fmt(8, 4);
    assert_eq!(f.max_magnitude(), 4095);
    // m = t = 200, dt = 255, x1: (200 − δ)/200·4080. δ = −0.5: 200.5·20.4 = 4090.2 → 4090;
    // δ = −1: 201·20.4 = 4100.4 > 4095: saturates.
    assert_eq!(speed_mtc(f, 200, 200, 255, d(-0.5), false, 0), 4090);
    assert_eq!(speed_mtc(f, 200, 200, 255, d(-1.0), false, 0), 4095);
    assert_eq!(speed_mtc(f, 200, 200, 255, d(-1.0), true, 0), -4095);
    // δ = −0.75: 200.75·20.4 = 4095.3 → 4095 without saturating; −0.78125: 4095.94 → sat.
    assert_eq!(speed_mtc(f, 200, 200, 255, d(-0.75), false, 0), 4095);
    assert_eq!(speed_mtc(f, 200, 200, 255, d(-0.78125), true, 0), -4095);
    // The most negative δ (−2^23 steps), largest m and dt, t = 1: far beyond: ±4095.
    let dmin = -(1i64 << 39);
    assert_eq!(speed_mtc(f, 255, 1, 255, dmin, false, 0), 4095);
    assert_eq!(speed_mtc(f, 255, 1, 255, dmin, true, 2), -4095);
    // The same δ at N = 32, F = 24 with the largest t fits: m − δ = 255 + 2^23 steps,
    // (2^23 + 255)·255·2^24/(2^32 − 1) ≈ 8.36e6 < 2^56 − 1, rounded as restated here.
    let g = fmt(32, 24);
    let want =
        ((255u128 + (1 << 23)) * 255 * (1 << 24) * 2 + ((1 << 32) - 1)) / (2 * ((1u128 << 32) - 1));
    assert_eq!(
        speed_mtc(g, 255, (1 << 32) - 1, 255, dmin, false, 0),
        want as i64
    );
}

#[test]
fn hardware_request_corners() {
    let w = EccWidths::of(fmt(24, 16));
    // c = m·2^16 − D; D = −2^39 (sign-extended to C = 41 bits), m = 2^24 − 1: the largest c.
    let r = hardware_request(w, (1 << 24) - 1, 1, 0, w.delta_to_raw(-(1 << 39)));
    assert_eq!(r.corrected, (((1u64 << 24) - 1) << 16) + (1 << 39));
    assert_eq!((r.dt, r.zero), (1, false));
    assert!(r.corrected < 1 << 41);
    // c = 0 and c = −1 are zero; c = 1 is not.
    let m = 7u64;
    assert!(hardware_request(w, m, 1, 1, w.delta_to_raw(d(7.0))).zero);
    assert!(hardware_request(w, m, 1, 1, w.delta_to_raw(d(7.0) + 1)).zero);
    let r = hardware_request(w, m, 1, 1, w.delta_to_raw(d(7.0) - 1));
    assert_eq!((r.corrected, r.zero), (1, false));
    // The largest positive D with the largest m at N = 8 (C = 40): zero.
    let w8 = EccWidths::of(fmt(8, 16));
    assert!(hardware_request(w8, 255, 1, 1, w8.delta_to_raw((1 << 39) - 1)).zero);
    // Multiplier: c·dt in {A, Q} halves.
    let (a, q) = hardware_multiply(w, (1 << 41) - 1, (1 << 24) - 1);
    assert_eq!(
        (u128::from(a) << 24) + u128::from(q),
        ((1u128 << 41) - 1) * ((1 << 24) - 1)
    );
    // Divider: preload A >> (16 + s) not below t saturates.
    assert!(hardware_divide(w, 5 << 16, 0, 5, 0).1);
    assert!(!hardware_divide(w, 5 << 16, 0, 6, 0).1);
    assert!(!hardware_divide(w, 5 << 16, 0, 5, 1).1);
}

/// Every m, t, dt (N bits), D (d bits) and mode_shift: the hardware algorithm against the
/// restated rule and the model's exact rule. Returns how often each special path was taken:
/// (c ≤ 0 with m, t ≥ 1; preload saturation; all-ones quotient; rounding ties).
fn exhaustive(w: EccWidths) -> [u32; 4] {
    let top = 1u64 << w.counter_bits;
    let mut paths = [0u32; 4];
    let max = w.max_magnitude();
    for s in 0..4u32 {
        for delta in w.delta_range() {
            for m in 0..top {
                let c = (i64::from(m as u32) << w.delta_frac_bits) - delta;
                for dt in 0..top {
                    for t in 0..top {
                        let neg = (m + dt + t + delta as u64).is_multiple_of(2);
                        let want = restated(w, m, t, dt, delta, neg, s);
                        let got = hardware_speed(w, m, t, dt, delta, neg, s);
                        assert_eq!(got, want, "{w:?} s {s}: m {m} D {delta} dt {dt} t {t}");
                        assert_eq!(exact_speed(w, m, t, dt, delta, neg, s), want);
                        if m == 0 || t == 0 {
                            continue;
                        }
                        if c <= 0 {
                            paths[0] += 1;
                            continue;
                        }
                        let r = hardware_request(w, m, t, dt, w.delta_to_raw(delta));
                        let (a, _) = hardware_multiply(w, r.corrected, r.dt);
                        if a >> (w.delta_frac_bits + s.min(2)) >= t {
                            paths[1] += 1;
                            continue;
                        }
                        let num = (c as u128 * u128::from(dt.max(1))) << (w.frac_bits + 1);
                        let den = u128::from(t) << (w.delta_frac_bits + s.min(2));
                        if num / den == 2 * max + 1 {
                            paths[2] += 1;
                        }
                        if num.is_multiple_of(den) && (num / den) % 2 == 1 {
                            paths[3] += 1;
                        }
                    }
                }
            }
        }
    }
    paths
}

#[test]
fn hardware_algorithm_is_exact_exhaustively_at_small_widths() {
    let mut totals = [0u32; 4];
    for n in 2..=4 {
        for f in 0..=4 {
            // δ: 4 bits with 1 fractional, 5 with 2, 6 with 2 (C = 4..6 bits).
            for (db, g) in [(4, 1), (5, 2), (6, 2)] {
                let p = exhaustive(EccWidths::new(n, f, db, g));
                for (t, x) in totals.iter_mut().zip(p) {
                    *t += x;
                }
            }
        }
    }
    // Every special path is exercised.
    assert!(totals.iter().all(|&x| x > 100), "{totals:?}");
}

/// The real δ format (d = 40, g = 16) at N = 8, exhaustive in m, t and dt for δ around the
/// edges: 0, ±2^−16, ±0.5, m itself, and the two extremes.
#[test]
fn hardware_algorithm_is_exact_at_n8_with_real_delta() {
    let w = EccWidths::of(fmt(8, 16));
    for m in 0..256u64 {
        let dm = (m as i64) << 16;
        for delta in [
            0,
            1,
            -1,
            1 << 15,
            -(1 << 15),
            dm,
            dm - 1,
            dm + 1,
            -(1 << 39),
        ] {
            for dt in [0u64, 1, 2, 3, 100, 254, 255] {
                for t in 0..256u64 {
                    for s in 0..4 {
                        let neg = (m ^ t) & 1 == 1;
                        assert_eq!(
                            hardware_speed(w, m, t, dt, delta, neg, s),
                            restated(w, m, t, dt, delta, neg, s),
                            "m {m} D {delta} dt {dt} t {t} s {s}"
                        );
                    }
                }
            }
        }
    }
}

/// An N-bit counter value, often a corner.
fn counter(n: u32) -> impl Strategy<Value = u64> {
    let max = (1u64 << n) - 1;
    prop_oneof![
        1 => Just(0u64),
        1 => Just(1u64),
        1 => Just(max),
        1 => Just(max - 1),
        1 => 1u64..=16,
        3 => 0u64..=max,
        3 => (1u32..=n).prop_flat_map(|b| 0u64..=((1u64 << b) - 1)),
    ]
}

/// D (units of 2^−16 step): mostly realistic (a few steps), sometimes anything in 40 bits,
/// sometimes m·2^16 ± a little (m − δ ≈ 0).
fn delta() -> impl Strategy<Value = i64> {
    prop_oneof![
        2 => Just(0i64),
        4 => -(8i64 << 16)..=(8i64 << 16),
        2 => -(1i64 << 39)..=(1i64 << 39) - 1,
        1 => Just(-(1i64 << 39)),
        1 => Just((1i64 << 39) - 1),
        2 => (1u32..=40).prop_flat_map(|b| {
            let h = 1i64 << (b - 1);
            -h..=h - 1
        }),
    ]
}

/// (format, m, t, dt, D, negative, mode_shift); D near m·2^16 in one case of 8.
fn case() -> impl Strategy<Value = (BaselineFormat, EccMtRequest)> {
    (8u32..=32, 2u32..=24).prop_flat_map(|(n, fb)| {
        let f = fmt(n, fb);
        (
            Just(f),
            counter(n),
            counter(n),
            counter(n),
            delta(),
            any::<bool>(),
            0u32..4,
            0u8..8,
            -3i64..=3,
        )
            .prop_map(|(f, m, t, dt, delta, neg, s, near, k)| {
                // m·2^16 + k when it fits D's 40 bits (m < 2^23), else the drawn δ.
                let near_m = ((m as i64) << 16) + k;
                let delta = if near == 0 && near_m < (1 << 39) {
                    near_m
                } else {
                    delta
                };
                (
                    f,
                    EccMtRequest {
                        mt_m: m,
                        mt_t: t,
                        mt_negative: neg,
                        cfg_dt: dt,
                        mode_shift: s,
                        ecc_delta: delta,
                    },
                )
            })
    })
}

fn check_case(f: BaselineFormat, r: &EccMtRequest) -> Result<(), TestCaseError> {
    let w = EccWidths::of(f);
    let (m, t, dt, delta, neg, s) = (
        r.mt_m,
        r.mt_t,
        r.cfg_dt,
        r.ecc_delta,
        r.mt_negative,
        r.mode_shift,
    );
    let v = ecc_mt_speed(f, r);
    prop_assert_eq!(v, restated(w, m, t, dt, delta, neg, s));
    prop_assert_eq!(hardware_speed(w, m, t, dt, delta, neg, s), v);
    // Mirror image.
    prop_assert_eq!(speed_mtc(f, m, t, dt, delta, !neg, s), -v);
    // Fits the port.
    prop_assert_eq!(f.from_raw(f.to_raw(v)), v);
    // Within ½ LSB of f64 unless saturated or zeroed (f64 carries 53 bits: add its error).
    let c = m as f64 - delta as f64 / 65536.0;
    let max = f.max_magnitude();
    if m > 0 && t > 0 && c > 0.0 && v.abs() < max {
        let exact = c * dt.max(1) as f64 * (-(s.min(2) as f64)).exp2() / t as f64;
        let got = f.speed_format().to_f64(v).abs();
        let tol = speed_lsb_error(f.frac_bits()) + 16.0 * f64::EPSILON * exact;
        prop_assert!((got - exact).abs() <= tol, "{} vs {}", got, exact);
    }
    // δ = 0: the baseline M/T speed, an independent definition.
    prop_assert_eq!(
        speed_mtc(f, m, t, dt, 0, neg, s),
        speed_mt(f, m, t, dt, neg, s)
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 20_000, ..ProptestConfig::default() })]

    /// Every format: exact rule = restated rule = hardware algorithm, mirror, f64, δ = 0.
    #[test]
    fn exact_rule_and_hardware_agree_in_every_format((f, r) in case()) {
        check_case(f, &r)?;
    }

    /// N = 24 and N = 32 with F = 16 (the core's format).
    #[test]
    fn hardware_equals_exact_at_n24_and_n32(
        m24 in counter(24), t24 in counter(24), dt24 in counter(24),
        m32 in counter(32), t32 in counter(32), dt32 in counter(32),
        delta in delta(), neg: bool, s in 0u32..4,
    ) {
        for (n, m, t, dt) in [(24, m24, t24, dt24), (32, m32, t32, dt32)] {
            let r = EccMtRequest { mt_m: m, mt_t: t, mt_negative: neg, cfg_dt: dt,
                mode_shift: s, ecc_delta: delta };
            check_case(fmt(n, 16), &r)?;
        }
    }

    /// δ = 0 gives `speed_mt` exactly, in every format and for every input.
    #[test]
    fn zero_delta_is_speed_mt((f, r) in case()) {
        prop_assert_eq!(
            speed_mtc(f, r.mt_m, r.mt_t, r.cfg_dt, 0, r.mt_negative, r.mode_shift),
            speed_mt(f, r.mt_m, r.mt_t, r.cfg_dt, r.mt_negative, r.mode_shift)
        );
    }
}

// ---- Timing -----------------------------------------------------------------------------

const IDLE: EccMtSpeedInputs = EccMtSpeedInputs {
    reset: false,
    start: false,
    req: EccMtRequest {
        mt_m: 0,
        mt_t: 0,
        mt_negative: false,
        cfg_dt: 0,
        mode_shift: 0,
        ecc_delta: 0,
    },
};

/// m = `m` steps, δ = 0.5, t = 100, dt = 100, x1: (m − 0.5)·2^F.
fn req(m: u64) -> EccMtRequest {
    EccMtRequest {
        mt_m: m,
        mt_t: 100,
        mt_negative: false,
        cfg_dt: 100,
        mode_shift: 0,
        ecc_delta: 1 << 15,
    }
}

fn start(r: EccMtRequest) -> EccMtSpeedInputs {
    EccMtSpeedInputs {
        start: true,
        req: r,
        ..IDLE
    }
}

#[test]
fn latency_is_fixed_by_hand() {
    // N = 24, F = 16: 1 edge takes the request, 24 multiply steps, 1 divider set-up,
    // S = 41 divide steps, 1 edge publishes: 68.
    assert_eq!(latency_cycles(24, 16), 68);
    // N = 8, F = 16: 1 + 8 + 1 + 25 + 1 = 36; N = 32, F = 16: 1 + 32 + 1 + 49 + 1 = 84.
    assert_eq!(latency_cycles(8, 16), 36);
    assert_eq!(latency_cycles(32, 16), 84);
    for (n, fb) in [(8, 2), (8, 16), (24, 16), (32, 24)] {
        let f = fmt(n, fb);
        let l = latency_cycles(n, fb) as usize;
        let mut model = EccMtSpeedModel::new(f);
        let mut trace = vec![model.step(start(req(3)))];
        for _ in 0..l + 3 {
            trace.push(model.step(IDLE));
        }
        for (k, o) in trace.iter().enumerate() {
            assert_eq!(o.busy, k < l, "busy after edge {k}");
            assert_eq!(o.valid, k == l, "valid after edge {k}");
            // 2.5 steps per dt, as m = 3, δ = 0.5, t = dt: 2.5·2^F.
            let want = if k >= l { 5 << (fb - 1) } else { 0 };
            assert_eq!(o.speed_mtc, want, "speed after edge {k}");
        }
    }
}

#[test]
fn a_start_while_busy_is_served_next_with_its_own_values() {
    let f = fmt(8, 4);
    let l = latency_cycles(8, 4);
    let mut model = EccMtSpeedModel::new(f);
    model.step(start(req(1))); // edge 0
    let mut valids = vec![];
    for k in 1..3 * l {
        let inp = match k {
            // Two starts while busy: the second replaces the first (which never began).
            5 => start(req(2)),
            9 => start(req(3)),
            _ => IDLE,
        };
        let o = model.step(inp);
        if o.valid {
            valids.push((k, o.speed_mtc));
        }
        assert_eq!(o.busy, k < 2 * l, "busy after edge {k}");
    }
    // 0.5·16 = 8 at edge L; 2.5·16 = 40 at edge 2L.
    assert_eq!(valids, vec![(l, 8), (2 * l, 40)]);
}

#[test]
fn reset_abandons_everything_and_wins_over_start() {
    let f = fmt(12, 8);
    let l = latency_cycles(12, 8);
    let mut model = EccMtSpeedModel::new(f);
    for _ in 0..=l {
        model.step(start(req(7)));
    }
    assert!(model.outputs().valid && model.outputs().busy);
    model.step(start(req(8)));
    let o = model.step(EccMtSpeedInputs {
        reset: true,
        ..start(req(9))
    });
    assert_eq!(o, EccMtSpeedOutputs::default());
    for _ in 0..2 * l {
        assert_eq!(model.step(IDLE), EccMtSpeedOutputs::default());
    }
}

#[test]
#[should_panic(expected = "does not fit")]
fn inputs_wider_than_the_ports_are_refused() {
    let mut model = EccMtSpeedModel::new(fmt(8, 4));
    model.step(start(EccMtRequest {
        ecc_delta: 1 << 39,
        ..req(0)
    }));
}
