// SPDX-License-Identifier: MIT OR Apache-2.0
//! Tests of the baseline-speeds model. Truth comes from outside the model: values worked by
//! hand, the rounding rule restated here as quotient and remainder (not the model's
//! formula), f64, and edge counts of the documented schedule worked by hand. The hardware
//! algorithm ([`hardware_magnitude`], [`shift_add_multiply`]) is checked exhaustively at
//! small widths and on random wide operands against that restated rule.

use golden::baselines::baseline_speeds::{
    baseline_speeds, hardware_magnitude, latency_cycles, shift_add_multiply, speed_bits, speed_et,
    speed_mt, speed_pc, BaselineFormat, BaselineRequest, BaselineSpeedsInputs, BaselineSpeedsModel,
    BaselineSpeedsOutputs, BaselineValues, FormatError,
};
use golden::estimator::speed_calc::speed_lsb_error;
use proptest::prelude::*;

fn fmt(n: u32, f: u32) -> BaselineFormat {
    BaselineFormat::new(n, f).unwrap()
}

/// round(x·2^e/den), ties up, from quotient and remainder; saturated at `max`.
fn reference(x: u128, den: u128, e: u32, max: u128) -> u128 {
    let num = x << e;
    let (q, r) = (num / den, num % den);
    let rounded = if 2 * r >= den { q + 1 } else { q };
    rounded.min(max)
}

#[test]
fn known_answers_by_hand() {
    let f = fmt(8, 4);
    // ET, period 3 cycles, dt = 10: x1: 10·16/3 = 53.33 → 53; x2: 10·8/3 = 26.67 → 27;
    // x4: 10·4/3 = 13.33 → 13; mode_shift 3 counts as x4.
    assert_eq!(speed_et(f, 3, 10, false, true, 0), 53);
    assert_eq!(speed_et(f, 3, 10, false, true, 1), 27);
    assert_eq!(speed_et(f, 3, 10, false, true, 2), 13);
    assert_eq!(speed_et(f, 3, 10, false, true, 3), 13);
    // Reverse mirrors.
    assert_eq!(speed_et(f, 3, 10, true, true, 0), -53);
    assert_eq!(speed_et(f, 3, 10, true, true, 1), -27);
    // M/T, m = 3 steps in t = 7 cycles, dt = 10: x1: 30·16/7 = 68.57 → 69;
    // x2: 30·8/7 = 34.29 → 34; x4: 30·4/7 = 17.14 → 17.
    assert_eq!(speed_mt(f, 3, 7, 10, false, 0), 69);
    assert_eq!(speed_mt(f, 3, 7, 10, false, 1), 34);
    assert_eq!(speed_mt(f, 3, 7, 10, false, 2), 17);
    assert_eq!(speed_mt(f, 3, 7, 10, true, 0), -69);
    assert_eq!(speed_mt(f, 3, 7, 10, true, 2), -17);
    // PC: −5 steps at x2: −5·2^(4−1) = −40; 127 at x1: 127·16 = 2032; −128 at x4:
    // −128·4 = −512; 3 at mode_shift 3 (x4): 12.
    assert_eq!(speed_pc(f, -5, 1), -40);
    assert_eq!(speed_pc(f, 127, 0), 2032);
    assert_eq!(speed_pc(f, -128, 2), -512);
    assert_eq!(speed_pc(f, 3, 3), 12);
    // N = 24, F = 16, x4, dt = 1000 cycles: ET period 250 cycles → 1000/(250·4) = 1 line
    // per dt = 65536; M/T 40 steps in 9999 cycles → 40·1000/(4·9999) = 1.00010001 lines
    // per dt → 65542.55 → 65543.
    let g = fmt(24, 16);
    assert_eq!(speed_et(g, 250, 1000, false, true, 2), 65_536);
    assert_eq!(speed_mt(g, 40, 9999, 1000, false, 2), 65_543);
}

#[test]
fn zeros_and_invalid_inputs() {
    let f = fmt(8, 4);
    // No valid period, or a zero period: 0 in both directions.
    assert_eq!(speed_et(f, 3, 10, true, false, 0), 0);
    assert_eq!(speed_et(f, 0, 10, true, true, 0), 0);
    // M/T with m = 0 (a decay bound, not an estimate) or t = 0: 0.
    assert_eq!(speed_mt(f, 0, 7, 10, true, 0), 0);
    assert_eq!(speed_mt(f, 3, 0, 10, false, 0), 0);
    // Rounding to zero is 0, never −0 or −1: dt = 1, period 255, x4: 4/255 = 0.016 → 0.
    assert_eq!(speed_et(f, 255, 1, true, true, 2), 0);
    // cfg_dt = 0 counts as 1: ET period 3: 16/3 = 5.33 → 5; M/T 3/7·16 = 6.86 → 7.
    assert_eq!(speed_et(f, 3, 0, false, true, 0), 5);
    assert_eq!(speed_et(f, 3, 1, false, true, 0), 5);
    assert_eq!(speed_mt(f, 3, 7, 0, true, 0), -7);
}

#[test]
fn ties_round_away_from_zero() {
    // N = 8, F = 4: dt = 1, period 32: 16/32 = ½ → 1 (−1 reversed).
    let f = fmt(8, 4);
    assert_eq!(speed_et(f, 32, 1, false, true, 0), 1);
    assert_eq!(speed_et(f, 32, 1, true, true, 0), -1);
    // Just below a tie: period 33 → 16/33 = 0.485 → 0.
    assert_eq!(speed_et(f, 33, 1, true, true, 0), 0);
    // N = 8, F = 2, x4: dt = 3, period 2: 3/2 = 1.5 → 2; M/T m = 5, t = 2, dt = 1:
    // 5/2 = 2.5 → 3, reversed −3.
    let g = fmt(8, 2);
    assert_eq!(speed_et(g, 2, 3, false, true, 2), 2);
    assert_eq!(speed_et(g, 2, 3, true, true, 2), -2);
    assert_eq!(speed_mt(g, 5, 2, 1, true, 2), -3);
}

#[test]
fn mt_saturates_only_past_the_format() {
    let f = fmt(8, 4);
    assert_eq!(f.max_magnitude(), 4095);
    // m ≤ t never saturates: m = t = dt = 255 gives exactly dt·16 = 4080.
    assert_eq!(speed_mt(f, 255, 255, 255, false, 0), 4080);
    assert_eq!(speed_mt(f, 254, 254, 255, true, 0), -4080);
    // m = 255 > t = 254, dt = 255, x1: 65025·16/254 = 4096.06 > 4095: saturates.
    assert_eq!(speed_mt(f, 255, 254, 255, false, 0), 4095);
    assert_eq!(speed_mt(f, 255, 254, 255, true, 0), -4095);
    // x4, t = 64: 65025·4/64 = 4064.06 → 4064 (fits); t = 63: 4128.57 saturates.
    assert_eq!(speed_mt(f, 255, 64, 255, false, 2), 4064);
    assert_eq!(speed_mt(f, 255, 63, 255, false, 2), 4095);
    // The largest possible: m = dt = 255, t = 1: 1040400 → 4095.
    assert_eq!(speed_mt(f, 255, 1, 255, true, 0), -4095);
    // ET never needs it: dt = 255, period 1, x1: 255·16 = 4080.
    assert_eq!(speed_et(f, 1, 255, false, true, 0), 4080);
    // The hardware's two saturation paths on the same cases. 65025 = 254·256 + 1, so
    // A = 254, Q = 1; x4, t = 63: A >> 2 = 63 ≥ 63, the preload check saturates.
    assert_eq!(shift_add_multiply(255, 255, 8), (254, 1));
    assert_eq!(hardware_magnitude(254, 1, 63, 8, 4, 2), 4095);
    assert_eq!(hardware_magnitude(254, 1, 64, 8, 4, 2), 4064);
    // x1, t = 254: A = 254 ≥ 254 also saturates at the preload.
    assert_eq!(hardware_magnitude(254, 1, 254, 8, 4, 0), 4095);
}

#[test]
fn formats_are_validated() {
    assert_eq!(BaselineFormat::new(7, 8), Err(FormatError::CounterBits(7)));
    assert_eq!(
        BaselineFormat::new(33, 8),
        Err(FormatError::CounterBits(33))
    );
    assert_eq!(BaselineFormat::new(8, 1), Err(FormatError::FracBits(1)));
    assert_eq!(BaselineFormat::new(8, 25), Err(FormatError::FracBits(25)));
    assert!(FormatError::FracBits(1).to_string().contains("2..=24"));
    assert_eq!(fmt(32, 24).speed_bits(), 57);
    assert_eq!(speed_bits(8, 2), 11);
    // Raw bits of the 41-bit port: 2^41 − 69.
    let g = fmt(24, 16);
    assert_eq!(g.to_raw(-69), (1u64 << 41) - 69);
    assert_eq!(g.from_raw(g.to_raw(-69)), -69);
}

#[test]
fn multiplier_is_exact_exhaustively_at_8_bits() {
    for m in 0..256u64 {
        for dt in 0..256u64 {
            let (a, q) = shift_add_multiply(m, dt, 8);
            assert_eq!(a * 256 + q, m * dt, "{m}·{dt}");
        }
    }
}

/// Every (m, dt, t) and mode_shift for N-bit operands, frac bits F: the hardware algorithm
/// (multiply, divide, round, saturate) against the restated rule. Returns how many cases
/// saturated at the preload and through an all-ones quotient.
fn exhaustive(n: u32, f: u32) -> (u32, u32) {
    let top = 1u64 << n;
    let max = (1u128 << (n + f)) - 1;
    let (mut preload, mut all_ones) = (0, 0);
    for s in 0..4u32 {
        let e = f - s.min(2);
        for m in 0..top {
            for dt in 0..top {
                let (a, q) = shift_add_multiply(m, dt, n);
                let x = u128::from(m * dt);
                for t in 1..top {
                    let got = hardware_magnitude(a, q, t, n, f, s);
                    let want = reference(x, t.into(), e, max);
                    assert_eq!(got, want, "N {n} F {f} s {s}: {m}·{dt}/{t}");
                    if (a >> s.min(2)) >= t {
                        preload += 1;
                    } else if ((x << (e + 1)) / u128::from(t)) == (2 * max + 1) {
                        all_ones += 1;
                    }
                }
            }
        }
    }
    (preload, all_ones)
}

#[test]
fn hardware_algorithm_is_exact_exhaustively_at_small_widths() {
    let mut all_ones = 0;
    for n in 3..=5 {
        for f in 2..=5 {
            let (p, a) = exhaustive(n, f);
            assert!(p > 0, "N {n} F {f}: no preload saturation");
            all_ones += a;
        }
    }
    // The rarer path (quotient all ones, rounding would carry out) must be exercised.
    assert!(all_ones > 0);
}

#[test]
fn hardware_algorithm_is_exact_exhaustively_at_n8_f2() {
    let (p, _) = exhaustive(8, 2);
    assert!(p > 0);
}

/// A counter value of `n` bits, often a corner.
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

fn request(f: BaselineFormat) -> impl Strategy<Value = BaselineRequest> {
    let n = f.counter_bits();
    let pc = f.pc_range();
    (
        pc,
        counter(n),
        counter(n),
        counter(n),
        counter(n),
        0u32..4,
        any::<[bool; 4]>(),
    )
        .prop_map(
            |(pc_count, et_period, mt_m, mt_t, cfg_dt, mode_shift, b)| BaselineRequest {
                pc_count,
                et_period,
                et_negative: b[0],
                et_valid: b[1],
                mt_m,
                mt_t,
                mt_negative: b[2],
                cfg_dt,
                mode_shift,
            },
        )
}

fn case() -> impl Strategy<Value = (BaselineFormat, BaselineRequest)> {
    (8u32..=32, 2u32..=24).prop_flat_map(|(n, f)| {
        let f = fmt(n, f);
        (Just(f), request(f))
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 5000, ..ProptestConfig::default() })]

    /// Every output against the restated rule and f64, in every format; the hardware
    /// algorithm against the same rule; reverse mirrors forward.
    #[test]
    fn outputs_are_the_exact_values_rounded((f, r) in case()) {
        let v = baseline_speeds(f, &r);
        let s = r.mode_shift.min(2);
        let e = f.frac_bits() - s;
        let dt = r.cfg_dt.max(1);
        let max = f.max_magnitude() as u128;
        let sign = |neg: bool, m: u128| if neg { -(m as i64) } else { m as i64 };
        // PC: an exact product.
        prop_assert_eq!(v.pc, r.pc_count * (1i64 << e));
        // ET.
        let et = if r.et_valid && r.et_period > 0 {
            sign(r.et_negative, reference(dt.into(), r.et_period.into(), e, max))
        } else {
            0
        };
        prop_assert_eq!(v.et, et);
        // M/T.
        let x = u128::from(r.mt_m) * u128::from(dt);
        let mt = if r.mt_m > 0 && r.mt_t > 0 {
            sign(r.mt_negative, reference(x, r.mt_t.into(), e, max))
        } else {
            0
        };
        prop_assert_eq!(v.mt, mt);
        // Within ½ LSB of f64 unless saturated (f64 carries 53 bits: add its rounding).
        if r.mt_m > 0 && r.mt_t > 0 && v.mt.unsigned_abs() < max as u64 {
            let exact = (x as f64) * (-(s as f64)).exp2() / r.mt_t as f64;
            let got = f.speed_format().to_f64(v.mt).abs();
            let tol = speed_lsb_error(f.frac_bits()) + 8.0 * f64::EPSILON * exact;
            prop_assert!((got - exact).abs() <= tol, "{} vs {}", got, exact);
        }
        // m ≤ t never saturates.
        if r.mt_m <= r.mt_t {
            prop_assert!(v.mt.unsigned_abs() <= (dt << f.frac_bits()));
        }
        // The hardware algorithm.
        let n = f.counter_bits();
        if r.et_period > 0 {
            prop_assert_eq!(
                hardware_magnitude(0, dt, r.et_period, n, f.frac_bits(), r.mode_shift),
                reference(dt.into(), r.et_period.into(), e, max)
            );
        }
        if r.mt_t > 0 {
            let (a, q) = shift_add_multiply(r.mt_m, dt, n);
            prop_assert_eq!((u128::from(a) << n) + u128::from(q), x);
            prop_assert_eq!(
                hardware_magnitude(a, q, r.mt_t, n, f.frac_bits(), r.mode_shift),
                reference(x, r.mt_t.into(), e, max)
            );
        }
        // Mirror images.
        let mirrored = BaselineRequest {
            pc_count: r.pc_count,
            et_negative: !r.et_negative,
            mt_negative: !r.mt_negative,
            ..r
        };
        let w = baseline_speeds(f, &mirrored);
        prop_assert_eq!((w.et, w.mt), (-v.et, -v.mt));
        // Every value fits the port.
        for x in [v.pc, v.et, v.mt] {
            prop_assert_eq!(f.from_raw(f.to_raw(x)), x);
        }
    }
}

// ---- Timing -----------------------------------------------------------------------------

const IDLE: BaselineSpeedsInputs = BaselineSpeedsInputs {
    reset: false,
    start: false,
    req: BaselineRequest {
        pc_count: 0,
        et_period: 0,
        et_negative: false,
        et_valid: false,
        mt_m: 0,
        mt_t: 0,
        mt_negative: false,
        cfg_dt: 0,
        mode_shift: 0,
    },
};

/// The hand-worked request of [`known_answers_by_hand`] with `pc_count` = `pc`.
fn req(pc: i64) -> BaselineRequest {
    BaselineRequest {
        pc_count: pc,
        et_period: 3,
        et_negative: false,
        et_valid: true,
        mt_m: 3,
        mt_t: 7,
        mt_negative: true,
        cfg_dt: 10,
        mode_shift: 0,
    }
}

fn start(r: BaselineRequest) -> BaselineSpeedsInputs {
    BaselineSpeedsInputs {
        start: true,
        req: r,
        ..IDLE
    }
}

#[test]
fn latency_is_fixed_by_hand() {
    // N = 24, F = 16: S = 41; 1 edge takes the request (and sets up ET), 41 ET steps of
    // 2 edges, 1 set-up of M/T (the ET quotient into the two-cycle round adder), 41 M/T
    // steps of 2 edges, 1 edge puts the M/T quotient into the adder, 1 edge publishes:
    // 1 + 82 + 1 + 82 + 1 + 1 = 168.
    assert_eq!(latency_cycles(24, 16), 168);
    // N = 8, F = 2: 4·11 + 4 = 48; N = 12, F = 8: 4·21 + 4 = 88; N = 32, F = 24: 232.
    assert_eq!(latency_cycles(8, 2), 48);
    assert_eq!(latency_cycles(12, 8), 88);
    assert_eq!(latency_cycles(32, 24), 232);
    for (n, fb) in [(8, 2), (8, 4), (12, 8), (24, 16), (32, 24)] {
        let f = fmt(n, fb);
        let l = latency_cycles(n, fb) as usize;
        let mut m = BaselineSpeedsModel::new(f);
        let mut trace = vec![m.step(start(req(-5)))];
        for _ in 0..l + 3 {
            trace.push(m.step(IDLE));
        }
        for (k, o) in trace.iter().enumerate() {
            assert_eq!(o.busy, k < l, "busy after edge {k}");
            assert_eq!(o.valid, k == l, "valid after edge {k}");
            let want = if k >= l {
                baseline_speeds(f, &req(-5))
            } else {
                BaselineValues::default()
            };
            assert_eq!(o.speeds, want, "speeds after edge {k}");
        }
    }
    // The values of that request at N = 8, F = 4, worked by hand above.
    assert_eq!(
        baseline_speeds(fmt(8, 4), &req(-5)),
        BaselineValues {
            pc: -80,
            et: 53,
            mt: -69
        }
    );
}

#[test]
fn a_start_while_busy_is_served_next_with_its_own_values() {
    let f = fmt(8, 4);
    let l = latency_cycles(8, 4);
    let mut m = BaselineSpeedsModel::new(f);
    m.step(start(req(1))); // edge 0
    let mut valids = vec![];
    for k in 1..3 * l {
        let inp = match k {
            // Two starts while busy: the second replaces the first (which never began).
            5 => start(req(2)),
            9 => start(req(3)),
            _ => IDLE,
        };
        let o = m.step(inp);
        if o.valid {
            valids.push((k, o.speeds.pc));
        }
        assert_eq!(o.busy, k < 2 * l, "busy after edge {k}");
    }
    // First result at edge L (pc 1·16); the pending request begins at L + 1, result at 2L.
    assert_eq!(valids, vec![(l, 16), (2 * l, 48)]);
}

#[test]
fn starts_l_apart_each_get_their_own_result_l_later() {
    let f = fmt(12, 8);
    let l = u64::from(latency_cycles(12, 8));
    let mut m = BaselineSpeedsModel::new(f);
    let mut valids = vec![];
    for k in 0..6 * l {
        let inp = if k % l == 0 && k < 5 * l {
            start(req((k / l) as i64))
        } else {
            IDLE
        };
        let o = m.step(inp);
        if o.valid {
            valids.push((k, o.speeds.pc >> 8));
        }
    }
    assert_eq!(
        valids,
        (1..=5).map(|i| (i * l, i as i64 - 1)).collect::<Vec<_>>()
    );
}

#[test]
fn reset_abandons_everything_and_wins_over_start() {
    let f = fmt(12, 8);
    let l = latency_cycles(12, 8);
    let mut m = BaselineSpeedsModel::new(f);
    for _ in 0..=l {
        m.step(start(req(7)));
    }
    assert!(m.outputs().valid && m.outputs().busy);
    m.step(start(req(8)));
    let o = m.step(BaselineSpeedsInputs {
        reset: true,
        ..start(req(9))
    });
    assert_eq!(o, BaselineSpeedsOutputs::default());
    for _ in 0..2 * l {
        assert_eq!(m.step(IDLE), BaselineSpeedsOutputs::default());
    }
}

#[test]
#[should_panic(expected = "does not fit")]
fn inputs_wider_than_the_ports_are_refused() {
    let mut m = BaselineSpeedsModel::new(fmt(8, 4));
    m.step(start(BaselineRequest {
        mt_t: 256,
        ..req(0)
    }));
}
