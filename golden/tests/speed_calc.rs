// SPDX-License-Identifier: MIT OR Apache-2.0
//! Tests of the speed calculator model. Truth comes from outside the model: values worked by
//! hand from eq. (5), (6) and (11), the float estimators of `golden::ideal` (written
//! independently, in f64), the exact fractions restated here and checked with u128
//! cross-multiplication, and edge counts of the documented schedule worked by hand.

use golden::estimator::speed_calc::{
    latency_cycles, long_division, min_lossless_dt, speed_bits, speed_lsb_error, speeds,
    FormatError, RequestTag, SpeedCalcInputs, SpeedCalcModel, SpeedCalcOutputs, SpeedFormat,
    Speeds,
};
use golden::ideal;
use golden::params::{Params, Spec};
use proptest::prelude::*;

fn fmt(n: u32, f: u32) -> SpeedFormat {
    SpeedFormat::new(n, f).unwrap()
}

fn s(n1: i64, n2: i64, n3: i64) -> Speeds {
    Speeds { n1, n2, n3 }
}

#[test]
fn known_answers_by_hand() {
    let f16 = fmt(24, 16);
    // Nep = 4, Ndt = 1 (r = 4 in docs/accuracy.md): n1 = 4, n2 = 3, n3 = 2·4·3/(1·7) = 24/7.
    // 4·65536 = 262144; 3·65536 = 196608; 24/7·65536 = 1572864/7 = 224694.857… → 224695.
    assert_eq!(speeds(f16, 4, 1, false), s(262_144, 196_608, 224_695));
    // Nep = 1, Ndt = 2 (low speed): n1 = 1/2, n2 = 1/3, n3 = 2/5.
    // 32768; 65536/3 = 21845.33 → 21845; 2/5·65536 = 26214.4 → 26214.
    assert_eq!(speeds(f16, 1, 2, false), s(32_768, 21_845, 26_214));
    // Nep = 50, Ndt = 1 (r = 50): n2 = 49; n3 = 2·50·49/99 = 4900/99.
    // 4900·65536 = 321126400 = 99·3243701 + 1 → 3243701.0101 → 3243701.
    assert_eq!(
        speeds(f16, 50, 1, false),
        s(3_276_800, 3_211_264, 3_243_701)
    );
    // Nep = 1, Ndt = 9 (r = 1/10): n1 = 1/9 → 7281.78 → 7282; n2 = 1/10 → 6553.6 → 6554;
    // n3 = 2/19 → 131072/19 = 6898.53 → 6899.
    assert_eq!(speeds(f16, 1, 9, false), s(7_282, 6_554, 6_899));
    // Nep = 0: no pulse, all zero, in both directions.
    assert_eq!(speeds(f16, 0, 1, false), Speeds::default());
    assert_eq!(speeds(f16, 0, 77, true), Speeds::default());
    // Nep = 3, Ndt = 2, n1 = 1.5 < 2 (low-speed branch): n2 = 3/3 = 1, n3 = 6/5 = 1.2;
    // 1.5·65536 = 98304, 1.2·65536 = 78643.2 → 78643.
    assert_eq!(speeds(f16, 3, 2, false), s(98_304, 65_536, 78_643));
    // Nep = 4, Ndt = 2: n1 = 2 exactly, high-speed branch: n2 = 3/2,
    // n3 = 2·4·3/(2·7) = 12/7 → 786432/7 = 112347.43 → 112347.
    assert_eq!(speeds(f16, 4, 2, false), s(131_072, 98_304, 112_347));
    // The largest speed of an 8-bit counter, F = 8: Nep = 255, Ndt = 1.
    // n1 = 255·256 = 65280; n2 = 254·256 = 65024;
    // n3 = 2·255·254/509 = 129540/509 = 254.49902 → ·256 = 65151.75 → 65152.
    assert_eq!(speeds(fmt(8, 8), 255, 1, false), s(65_280, 65_024, 65_152));
}

#[test]
fn reverse_is_the_mirror_image() {
    let f16 = fmt(24, 16);
    assert_eq!(speeds(f16, 4, 1, true), s(-262_144, -196_608, -224_695));
    assert_eq!(speeds(f16, 1, 2, true), s(-32_768, -21_845, -26_214));
    // Raw bits on the 41-bit port: 2^41 − 224695.
    assert_eq!(f16.to_raw(-224_695), (1u64 << 41) - 224_695);
}

#[test]
fn ties_round_away_from_zero() {
    // F = 8, Nep = 1, Ndt = 512: n1 = 1/512 = exactly ½ LSB → 1 (−1 reversed); n2 = 1/513 and
    // n3 = 2/1025 are just below ½ LSB → 0 (never −0).
    let f8 = fmt(16, 8);
    assert_eq!(speeds(f8, 1, 512, false), s(1, 0, 0));
    assert_eq!(speeds(f8, 1, 512, true), s(-1, 0, 0));
    // F = 0 (integers): Nep = 3, Ndt = 2: n1 = 1.5 → 2, n2 = 1, n3 = 1.2 → 1.
    let f0 = fmt(8, 0);
    assert_eq!(speeds(f0, 3, 2, false), s(2, 1, 1));
    assert_eq!(speeds(f0, 3, 2, true), s(-2, -1, -1));
    // Nep = 5, Ndt = 2: n1 = 2.5 → 3, n2 = 4/2 = 2, n3 = 2·5·4/(2·9) = 20/9 = 2.22 → 2.
    assert_eq!(speeds(f0, 5, 2, true), s(-3, -2, -2));
}

#[test]
fn zero_ndt_saturates_and_zero_nep_is_zero() {
    let f = fmt(8, 8);
    assert_eq!(f.max_magnitude(), 65_535);
    assert_eq!(speeds(f, 5, 0, false), s(65_535, 65_535, 65_535));
    assert_eq!(speeds(f, 1, 0, true), s(-65_535, -65_535, -65_535));
    assert_eq!(speeds(f, 0, 0, true), Speeds::default());
}

#[test]
fn formats_are_validated() {
    assert_eq!(SpeedFormat::new(7, 8), Err(FormatError::CounterBits(7)));
    assert_eq!(SpeedFormat::new(33, 8), Err(FormatError::CounterBits(33)));
    assert_eq!(SpeedFormat::new(8, 25), Err(FormatError::FracBits(25)));
    assert!(FormatError::FracBits(25)
        .to_string()
        .contains("speed_frac_bits = 25"));
    let f = fmt(32, 24);
    assert_eq!(f.speed_bits(), 57);
    assert_eq!(speed_bits(8, 0), 9);
}

#[test]
fn lsb_error_budget() {
    assert_eq!(speed_lsb_error(0), 0.5);
    assert_eq!(speed_lsb_error(8), 1.0 / 512.0);
    assert_eq!(speed_lsb_error(16), 1.0 / 131_072.0);
    assert_eq!(speed_lsb_error(24), 1.0 / 33_554_432.0);
}

/// The exact fractions, restated from the paper (not taken from the module).
fn exact(nep: u64, ndt: u64) -> [(u128, u128); 3] {
    let (p, d) = (u128::from(nep), u128::from(ndt));
    if p >= 2 * d {
        [(p, d), (p - 1, d), (2 * p * (p - 1), d * (2 * p - 1))]
    } else {
        [(p, d), (p, d + 1), (2 * p, 2 * d + 1)]
    }
}

/// A counter value of `n` bits, often a corner.
fn counter(n: u32) -> impl Strategy<Value = u64> {
    let max = (1u64 << n) - 1;
    prop_oneof![
        1 => Just(1u64),
        1 => Just(2u64),
        1 => Just(max),
        1 => Just(max - 1),
        1 => 1u64..=16,
        3 => 1u64..=max,
        3 => (1u32..=n).prop_flat_map(|b| 1u64..=((1u64 << b) - 1)),
    ]
}

fn format() -> impl Strategy<Value = SpeedFormat> {
    (8u32..=32, 0u32..=24).prop_map(|(n, f)| fmt(n, f))
}

fn case() -> impl Strategy<Value = (SpeedFormat, u64, u64, bool)> {
    format().prop_flat_map(|f| {
        let n = f.counter_bits();
        (Just(f), counter(n), counter(n), any::<bool>())
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4000, ..ProptestConfig::default() })]

    /// Every output is the exact value rounded to nearest, ties away from zero: checked by
    /// cross-multiplication in u128 (|m·den − num·2^F| ≤ den/2, and a tie goes up), and
    /// within ½ LSB of the float estimators of `golden::ideal`.
    #[test]
    fn outputs_are_the_exact_values_rounded((f, nep, ndt, neg) in case()) {
        let got = speeds(f, nep, ndt, neg);
        let fb = f.frac_bits();
        let floats = [ideal::n1(nep, ndt), ideal::n2(nep, ndt), ideal::n3(nep, ndt)];
        for (k, (v, (num, den))) in [got.n1, got.n2, got.n3].into_iter()
            .zip(exact(nep, ndt)).enumerate()
        {
            // Sign by direction, magnitude in range.
            let signed_ok = if neg { v <= 0 } else { v >= 0 };
            prop_assert!(signed_ok, "n{}: {} has the wrong sign", k + 1, v);
            let m = v.unsigned_abs() as u128;
            prop_assert!(m <= f.max_magnitude() as u128);
            // Exact: 2·|m·den − num·2^F| ≤ den, and = den only if m is the upper neighbour.
            let target = num << fb;
            let diff = (m * den).abs_diff(target);
            prop_assert!(2 * diff <= den, "n{}: m = {} for {}/{}", k + 1, m, num, den);
            if 2 * diff == den {
                prop_assert!(m * den > target, "tie rounded down");
            }
            // Float: within ½ LSB, plus f64 rounding of values up to 2^32 at 2^−24.
            let x = f.to_f64(v).abs();
            let tol = speed_lsb_error(fb) + 4.0 * f64::EPSILON * floats[k];
            prop_assert!((x - floats[k]).abs() <= tol, "n{}: {} vs {}", k + 1, x, floats[k]);
        }
        // Reverse is the exact mirror image.
        let other = speeds(f, nep, ndt, !neg);
        prop_assert_eq!((other.n1, other.n2, other.n3), (-got.n1, -got.n2, -got.n3));
        // The raw port bits decode back.
        prop_assert_eq!(f.from_raw(f.to_raw(got.n3)), got.n3);
    }

    /// The hardware's algorithm (remainder preloaded with num >> N, then N numerator bits and
    /// F + 1 zero bits) meets its precondition for every n1/n2/n3 fraction of N-bit counters
    /// and gives ⌊num·2^(F+1)/den⌋; rounding that by (q + 1) >> 1 is the documented rule.
    #[test]
    fn long_division_is_exact_for_every_ratio((f, nep, ndt, neg) in case()) {
        let n = f.counter_bits();
        let fb = f.frac_bits();
        let got = speeds(f, nep, ndt, neg);
        for (v, (num, den)) in [got.n1, got.n2, got.n3].into_iter().zip(exact(nep, ndt)) {
            let q = long_division(num, den, n, fb + 1);
            prop_assert_eq!(q, Some((num << (fb + 1)) / den));
            // The numerator and denominator fit 2N + 1 bits, the quotient N + F + 1.
            prop_assert!(num < 1 << (2 * n + 1) && den < 1 << (2 * n + 1));
            let q = q.unwrap();
            prop_assert!(q < 1 << speed_bits(n, fb));
            prop_assert_eq!(((q + 1) >> 1) as i64, v.abs());
        }
    }
}

#[test]
fn long_division_by_hand_and_precondition() {
    // 24/7 with 4 integer bits and 4 fraction bits: 24·16/7 = 54.86 → 54 = 0b0011_0110.
    assert_eq!(long_division(24, 7, 4, 4), Some(54));
    // 355/113, 8 integer bits, 20 fraction bits: 3 294 198 (golden/tests/divider.rs).
    assert_eq!(long_division(355, 113, 8, 20), Some(3_294_198));
    // The quotient must fit the integer bits: 16/1 does not fit 4 bits (16 >> 4 = 1 ≥ 1).
    assert_eq!(long_division(16, 1, 4, 0), None);
    assert_eq!(long_division(15, 1, 4, 0), Some(15));
}

#[test]
fn extremes_fit_the_format() {
    for n in [8, 16, 24, 32] {
        for fb in [0, 8, 16, 24] {
            let f = fmt(n, fb);
            let max = f.counter_max();
            for (nep, ndt) in [
                (max, 1),
                (max, max),
                (1, max),
                (max - 1, 1),
                (2, 1),
                (max, 2),
            ] {
                let v = speeds(f, nep, ndt, true);
                assert!(v.n1 >= -f.max_magnitude() && v.n3 <= 0 && v.n2 <= 0);
            }
            // Nep = 2^N − 1, Ndt = 1: n1 = 2^N − 1 exactly, the largest value reached with
            // Ndt ≥ 1.
            assert_eq!(
                speeds(f, max, 1, false).n1,
                ((1i64 << n) - 1) << fb,
                "N = {n}, F = {fb}"
            );
        }
    }
}

// ---- Timing -----------------------------------------------------------------------------

const IDLE: SpeedCalcInputs = SpeedCalcInputs {
    reset: false,
    start: false,
    nep: 0,
    ndt: 0,
    negative: false,
    shift: 0,
    position: 0,
};

/// A start whose carried position is made from its operands (so a published tag shows
/// which request it came from).
fn start(nep: u64, ndt: u64, negative: bool) -> SpeedCalcInputs {
    SpeedCalcInputs {
        start: true,
        nep,
        ndt,
        negative,
        position: tag_position(nep, ndt),
        ..IDLE
    }
}

fn tag_position(nep: u64, ndt: u64) -> u64 {
    (0xC000_0000 | (nep << 12) | ndt) & 0xFFFF_FFFF
}

fn tag(nep: u64, ndt: u64) -> RequestTag {
    RequestTag {
        position: tag_position(nep, ndt),
        nep,
        ndt,
    }
}

/// The speeds come out in lines per dt: x1 unchanged, x2 and x4 divided by 2 and 4 with a
/// second rounding of the magnitude (nearest, ties away from zero), then the sign.
#[test]
fn speeds_are_mode_scaled_by_the_latched_shift() {
    let f = fmt(24, 16);
    let l = latency_cycles(24, 16);
    let result = |nep, ndt, negative, shift| {
        let mut m = SpeedCalcModel::new(f);
        m.step(SpeedCalcInputs {
            shift,
            ..start(nep, ndt, negative)
        });
        // A different shift after the start does not change the result.
        for _ in 0..l {
            m.step(SpeedCalcInputs { shift: 1, ..IDLE });
        }
        assert!(m.outputs().valid);
        m.outputs().speeds
    };
    // Nep = 4, Ndt = 1: n1 = 4, n2 = 3, n3 = 24/7 steps per dt. x1: 262144, 196608,
    // 224694.857 → 224695. x4: 1 line = 65536, 0.75 = 49152, 224695/4 = 56173.75 → 56174.
    assert_eq!(result(4, 1, false, 0), s(262_144, 196_608, 224_695));
    assert_eq!(result(4, 1, false, 2), s(65_536, 49_152, 56_174));
    assert_eq!(result(4, 1, true, 2), s(-65_536, -49_152, -56_174));
    // shift 3 acts as x4.
    assert_eq!(result(4, 1, true, 3), s(-65_536, -49_152, -56_174));
    // x2: 224695/2 = 112347.5 → 112348 (the tie goes away from zero, in both directions).
    assert_eq!(result(4, 1, false, 1), s(131_072, 98_304, 112_348));
    assert_eq!(result(4, 1, true, 1), s(-131_072, -98_304, -112_348));
}

#[test]
fn latency_is_fixed_by_hand() {
    // N = 24, F = 16: S = 41 quotient bits; 1 edge to take the request, 3 × (a set-up and
    // 41 steps of two edges each) = 3 × 84 = 252, 3 edges to round and publish: 256 edges
    // from the start edge to `valid`.
    assert_eq!(latency_cycles(24, 16), 256);
    // N = 8, F = 8: 1 + 3·(2 + 34) + 3 = 112; N = 32, F = 24: 1 + 3·(2 + 114) + 3 = 352.
    assert_eq!(latency_cycles(8, 8), 112);
    assert_eq!(latency_cycles(32, 24), 352);
    for (n, fb) in [(8, 0), (8, 8), (16, 16), (24, 16), (32, 24)] {
        let f = fmt(n, fb);
        let l = latency_cycles(n, fb) as usize;
        let mut m = SpeedCalcModel::new(f);
        let mut trace = vec![m.step(start(4, 1, true))];
        for _ in 0..l + 3 {
            trace.push(m.step(IDLE));
        }
        for (k, o) in trace.iter().enumerate() {
            assert_eq!(o.busy, k < l, "busy after edge {k}");
            assert_eq!(o.valid, k == l, "valid after edge {k}");
            let want = if k >= l {
                speeds(f, 4, 1, true)
            } else {
                Speeds::default()
            };
            assert_eq!(o.speeds, want, "speeds after edge {k}");
            let want_tag = if k >= l {
                tag(4, 1)
            } else {
                RequestTag::default()
            };
            assert_eq!(o.tag, want_tag, "tag after edge {k}");
            assert_eq!(o.have_speeds, k >= l, "have_speeds after edge {k}");
        }
    }
}

#[test]
fn a_start_while_busy_is_served_next_with_its_own_values() {
    let f = fmt(8, 8);
    let l = latency_cycles(8, 8);
    let mut m = SpeedCalcModel::new(f);
    m.step(start(10, 1, false)); // edge 0
    let mut valids = vec![];
    for k in 1..3 * l {
        let inp = match k {
            // Two starts while busy: the second replaces the first (which never began).
            5 => start(20, 1, false),
            9 => start(1, 3, true),
            _ => IDLE,
        };
        let o = m.step(inp);
        if o.valid {
            valids.push((k, o.speeds, o.tag));
        }
        assert_eq!(o.busy, k < 2 * l, "busy after edge {k}");
    }
    // First result at edge L; the pending request begins at edge L + 1, result at 2L; each
    // with the tag of its own request.
    assert_eq!(
        valids,
        vec![
            (l, speeds(f, 10, 1, false), tag(10, 1)),
            (2 * l, speeds(f, 1, 3, true), tag(1, 3))
        ]
    );
}

#[test]
fn starts_at_the_take_and_publish_edges_are_not_lost() {
    let f = fmt(8, 8);
    let l = latency_cycles(8, 8);
    let mut m = SpeedCalcModel::new(f);
    let mut valids = vec![];
    for k in 0..4 * l {
        let inp = match k {
            0 => start(3, 1, false),
            // Edge 1 takes the first request: this start is latched behind it.
            1 => start(4, 1, false),
            // Edge 2L is the second result's publish edge: latched, served after it.
            _ if k == 2 * l => start(5, 1, true),
            _ => IDLE,
        };
        let o = m.step(inp);
        if o.valid {
            valids.push((k, o.speeds));
        }
    }
    assert_eq!(
        valids,
        vec![
            (l, speeds(f, 3, 1, false)),
            (2 * l, speeds(f, 4, 1, false)),
            (3 * l, speeds(f, 5, 1, true)),
        ]
    );
}

#[test]
fn reset_abandons_everything_and_wins_over_start() {
    let f = fmt(16, 8);
    let l = latency_cycles(16, 8);
    let mut m = SpeedCalcModel::new(f);
    // Starts in every cycle: the first result comes L edges after the first.
    for _ in 0..=l {
        m.step(start(9, 2, true));
    }
    assert!(m.outputs().valid && m.outputs().busy);
    m.step(start(7, 1, false));
    let o = m.step(SpeedCalcInputs {
        reset: true,
        ..start(8, 1, false)
    });
    assert_eq!(o, SpeedCalcOutputs::default());
    for _ in 0..2 * l {
        assert_eq!(m.step(IDLE), SpeedCalcOutputs::default());
    }
}

/// Feed `starts` (strictly increasing edges, each with its own Nep = index + 1) and return,
/// per start, the edge of the `valid` that carried its values (None if it was replaced).
fn serve(f: SpeedFormat, starts: &[u64]) -> Vec<Option<u64>> {
    let mut m = SpeedCalcModel::new(f);
    let mut result = vec![None; starts.len()];
    let end = starts.last().copied().unwrap_or(0) + 3 * u64::from(f.latency_cycles());
    let mut next = 0;
    for k in 0..end {
        let inp = if next < starts.len() && starts[next] == k {
            next += 1;
            start(next as u64, 1, false)
        } else {
            IDLE
        };
        let o = m.step(inp);
        if o.valid {
            let i = (o.speeds.n1 >> f.frac_bits()) as usize - 1;
            assert!(result[i].is_none());
            result[i] = Some(k);
        }
    }
    result
}

/// Update instants with the core's spacing: consecutive ≥ 1 apart, any three span ≥ dt + 1.
fn core_like_updates(dt: u64) -> impl Strategy<Value = Vec<u64>> {
    prop::collection::vec((any::<bool>(), 0u64..3 * dt), 1..30).prop_map(move |gaps| {
        let mut t: Vec<u64> = vec![];
        for (close, extra) in gaps {
            let n = t.len();
            let mut next = if n == 0 { 5 } else { t[n - 1] + 1 };
            if !close {
                next += extra;
            }
            if n >= 2 {
                next = next.max(t[n - 2] + dt + 1);
            }
            t.push(next);
        }
        t
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// At dt = min_lossless_dt every update of the core's pattern gets its own `valid`, at
    /// most 2L − 1 edges after its start.
    #[test]
    fn no_update_is_lost_at_the_minimum_dt(
        starts in core_like_updates(u64::from(min_lossless_dt(8, 4)))
    ) {
        let f = fmt(8, 4);
        let l = u64::from(f.latency_cycles());
        for (i, v) in serve(f, &starts).into_iter().enumerate() {
            let k = v.unwrap_or_else(|| panic!("update {i} at {} lost", starts[i]));
            prop_assert!(k >= starts[i] + l && k < starts[i] + 2 * l, "update {}", i);
        }
    }

    /// The spacing the claim relies on holds for Table 1 itself: at a constant dt, any three
    /// consecutive `update` strobes span at least dt + 1 cycles, whatever the pulses.
    #[test]
    fn table1_updates_have_the_assumed_spacing(
        dt in 2u64..40,
        pulses in prop::collection::vec(any::<u8>(), 50..3000),
    ) {
        let spec = Spec { dt_cycles: dt, counter_bits: 16, clock_hz: 1e6, lines: 1,
            timeout_s: 60.0 * dt as f64 / 1e6, ..Spec::default() };
        let mut t = golden::estimator::sync_estimator::Table1::new(&Params::new(spec).unwrap());
        let mut updates: Vec<u64> = vec![];
        for (k, &p) in pulses.iter().enumerate() {
            // Pulse density from the byte: dense bursts and long gaps.
            if t.step(p < 90, dt).update {
                updates.push(k as u64);
            }
        }
        for w in updates.windows(3) {
            prop_assert!(w[2] - w[0] > dt, "updates at {:?}, dt = {}", w, dt);
        }
    }
}

#[test]
fn below_the_minimum_dt_an_update_can_be_replaced() {
    // dt = 2L − 2: updates at 0, 1 (tick then restart), dt + 1 and dt + 2. The second is
    // taken at L + 1 and published at 2L; the third, at 2L − 1, waits until 2L + 1 and is
    // replaced by the fourth at 2L.
    let f = fmt(8, 4);
    let l = u64::from(f.latency_cycles());
    let dt = 2 * l - 2;
    let got = serve(f, &[10, 11, 10 + dt + 1, 10 + dt + 2]);
    assert!(got[0].is_some() && got[1].is_some() && got[3].is_some());
    assert_eq!(got[2], None);
    // One cycle more and nothing is lost.
    let dt = 2 * l - 1;
    let got = serve(f, &[10, 11, 10 + dt + 1, 10 + dt + 2]);
    assert!(got.iter().all(Option::is_some), "{got:?}");
}
