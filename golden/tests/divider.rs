// SPDX-License-Identifier: MIT OR Apache-2.0
//! Tests of the divider model. Truth comes from outside the model's recurrence: quotients and
//! remainders worked by hand, Rust's integer `/` and `%` on u64/u128, and a transaction-level
//! description of the handshake (start accepted when idle, done exactly W edges later)
//! written here independently of the model's registers.

use golden::arith::seq_divider::{
    divide, fixed_quotient, latency_cycles, mask, shifted_numerator, DividerInputs, DividerOutputs,
    Overflow, SeqDividerModel,
};
use proptest::prelude::*;

const WIDTHS: [u32; 7] = [2, 8, 16, 24, 32, 48, 64];

fn start(numerator: u64, denominator: u64) -> DividerInputs {
    DividerInputs {
        reset: false,
        start: true,
        numerator,
        denominator,
    }
}

const IDLE: DividerInputs = DividerInputs {
    reset: false,
    start: false,
    numerator: 0,
    denominator: 0,
};

/// One division from idle: the outputs at `done` and the number of edges from the start
/// edge to the edge after which `done` is high.
fn run(m: &mut SeqDividerModel, n: u64, d: u64) -> (DividerOutputs, u32) {
    let o = m.step(start(n, d));
    assert!(o.busy && !o.done, "start not accepted");
    for k in 1..=200 {
        let o = m.step(IDLE);
        if o.done {
            assert!(!o.busy);
            return (o, k);
        }
        assert!(o.busy, "busy dropped without done");
    }
    panic!("no done after 200 edges");
}

fn result(w: u32, n: u64, d: u64) -> (u64, u64, bool, u32) {
    let mut m = SeqDividerModel::new(w);
    let (o, k) = run(&mut m, n, d);
    (o.quotient, o.remainder, o.div_by_zero, k)
}

#[test]
fn known_answers_by_hand() {
    for w in [9, 16, 24, 48, 64] {
        // 113 · 3 = 339, 355 − 339 = 16.
        assert_eq!(result(w, 355, 113), (3, 16, false, w));
        // 113 · 3 = 339 > 300, 113 · 2 = 226, 300 − 226 = 74.
        assert_eq!(result(w, 300, 113), (2, 74, false, w));
    }
    // 100 = 7 · 14 + 2.
    assert_eq!(result(8, 100, 7), (14, 2, false, 8));
    // 255 / 16 = 15 r 15; 255 / 255 = 1 r 0; 254 / 255 = 0 r 254.
    assert_eq!(result(8, 255, 16), (15, 15, false, 8));
    assert_eq!(result(8, 255, 255), (1, 0, false, 8));
    assert_eq!(result(8, 254, 255), (0, 254, false, 8));
    // 3 / 2 = 1 r 1 in the smallest width.
    assert_eq!(result(2, 3, 2), (1, 1, false, 2));
    // 2^24 − 1 = 16 777 215 = 1000 · 16 777 + 215.
    assert_eq!(result(24, 16_777_215, 1000), (16_777, 215, false, 24));
    // 2^48 − 1 = 3 · 93 824 992 236 885 (0x5555_5555_5555).
    assert_eq!(
        result(48, (1 << 48) - 1, 3),
        (0x5555_5555_5555, 0, false, 48)
    );
    for w in [2, 8, 24, 48, 64] {
        let all = if w == 64 { u64::MAX } else { (1u64 << w) - 1 };
        // 2^W − 1 over 1, 1 over 2^W − 1, 2^W − 1 over itself, 0 over anything.
        assert_eq!(result(w, all, 1), (all, 0, false, w));
        assert_eq!(result(w, 1, all), (0, 1, false, w));
        assert_eq!(result(w, all, all), (1, 0, false, w));
        assert_eq!(result(w, 0, 1), (0, 0, false, w));
        assert_eq!(result(w, 0, all), (0, 0, false, w));
        // 2^(W−1) / 2 = 2^(W−2).
        assert_eq!(result(w, 1 << (w - 1), 2), (1 << (w - 2), 0, false, w));
        // Division by zero: quotient all ones, remainder = numerator, flag.
        assert_eq!(result(w, 355 & all, 0), (all, 355 & all, true, w));
        assert_eq!(result(w, 0, 0), (all, 0, true, w));
        assert_eq!(result(w, all, 0), (all, all, true, w));
    }
}

#[test]
fn divide_rule() {
    assert_eq!(divide(355, 113, 16).quotient, 3);
    assert_eq!(divide(355, 113, 16).remainder, 16);
    let z = divide(7, 0, 8);
    assert_eq!((z.quotient, z.remainder, z.div_by_zero), (255, 7, true));
}

#[test]
#[should_panic(expected = "does not fit 8 bits")]
fn operands_wider_than_w_are_refused() {
    SeqDividerModel::new(8).step(start(256, 3));
}

#[test]
#[should_panic(expected = "outside 2..=64")]
fn width_out_of_range_is_refused() {
    SeqDividerModel::new(65);
}

#[test]
fn latency_is_exactly_w_edges() {
    for w in WIDTHS {
        assert_eq!(latency_cycles(w), w);
        let mut m = SeqDividerModel::new(w);
        let mut trace = vec![m.step(start(3, 2))];
        for _ in 0..w + 2 {
            trace.push(m.step(IDLE));
        }
        // Outputs after the start edge (index 0) … : busy for W edges, then done for one.
        for (k, o) in trace.iter().enumerate() {
            let k = k as u32;
            assert_eq!(o.busy, k < w, "busy after edge {k}, W = {w}");
            assert_eq!(o.done, k == w, "done after edge {k}, W = {w}");
        }
        // 3 = 2 · 1 + 1 (fits the smallest width).
        assert_eq!(
            (trace[w as usize].quotient, trace[w as usize].remainder),
            (1, 1)
        );
        // Held until the next result.
        assert_eq!(trace[w as usize + 2].quotient, 1);
    }
}

#[test]
fn start_while_busy_is_ignored_and_start_in_the_done_cycle_is_accepted() {
    let w = 8;
    let mut m = SeqDividerModel::new(w);
    m.step(start(200, 10));
    // Starts with other operands during the division change nothing.
    for _ in 1..w {
        let o = m.step(start(7, 7));
        assert!(o.busy && !o.done);
    }
    let o = m.step(start(7, 7));
    assert!(o.done && !o.busy);
    assert_eq!((o.quotient, o.remainder), (20, 0));
    // The done cycle is idle: a start applied now is taken at the next edge.
    let o = m.step(start(9, 4));
    assert!(o.busy && !o.done);
    assert_eq!(o.quotient, 20, "previous result held while busy");
    for _ in 1..w {
        m.step(IDLE);
    }
    let o = m.step(IDLE);
    assert!(o.done);
    assert_eq!((o.quotient, o.remainder), (2, 1));
}

#[test]
fn reset_abandons_a_division_and_clears_the_outputs() {
    let w = 16;
    let mut m = SeqDividerModel::new(w);
    let (o, _) = run(&mut m, 1000, 0);
    assert!(o.div_by_zero);
    m.step(start(1000, 3));
    m.step(IDLE);
    let o = m.step(DividerInputs {
        reset: true,
        ..start(1000, 3)
    });
    assert_eq!(o, DividerOutputs::default(), "reset wins over start");
    for _ in 0..2 * w {
        assert_eq!(m.step(IDLE), DividerOutputs::default());
    }
}

#[test]
fn fixed_quotient_by_hand() {
    // 1/3 with 16 fraction bits: 65536 / 3 = 21845.33…
    assert_eq!(fixed_quotient(1, 3, 16, 24), Ok(21_845));
    assert_eq!(shifted_numerator(1, 16, 24), Ok(65_536));
    // 2/3 → 43690.67 → 43690; 5/4 with 8 bits → 320 exactly.
    assert_eq!(fixed_quotient(2, 3, 16, 24), Ok(43_690));
    assert_eq!(fixed_quotient(5, 4, 8, 16), Ok(320));
    // 355/113 with 20 bits: 355 · 2^20 = 372 244 480; / 113 = 3 294 199.0… (113 · 3 294 199 =
    // 372 244 487 > 372 244 480, so 3 294 198).
    assert_eq!(fixed_quotient(355, 113, 20, 32), Ok(3_294_198));
    // π ≈ 355/113 = 3.14159292…: 3 294 198 / 2^20 = 3.1415920…
    let pi = 3_294_198.0 / f64::from(1 << 20);
    assert!((pi - 355.0 / 113.0).abs() < 1.0 / f64::from(1 << 20));
    // 1 << 23 fits 24 bits; 1 << 24 does not; 2 << 23 does not.
    assert_eq!(fixed_quotient(1, 1, 23, 24), Ok(1 << 23));
    assert_eq!(
        fixed_quotient(1, 1, 24, 24),
        Err(Overflow::Numerator {
            bits_needed: 25,
            width: 24
        })
    );
    assert_eq!(
        fixed_quotient(2, 1, 23, 24),
        Err(Overflow::Numerator {
            bits_needed: 25,
            width: 24
        })
    );
    // A zero numerator never overflows, whatever the shift; a zero denominator always fails.
    assert_eq!(fixed_quotient(0, 7, 200, 8), Ok(0));
    assert_eq!(fixed_quotient(0, 0, 4, 8), Err(Overflow::ZeroDenominator));
    assert_eq!(fixed_quotient(3, 0, 4, 8), Err(Overflow::ZeroDenominator));
    // Large shifts are refused, not wrapped.
    assert!(fixed_quotient(1, 1, u32::MAX, 64).is_err());
    assert_eq!(fixed_quotient(1, 1, 63, 64), Ok(1 << 63));
    assert!(Overflow::ZeroDenominator.to_string().contains("zero"));
}

/// An operand of `w` bits, often one of the corner values.
fn operand(w: u32) -> impl Strategy<Value = u64> {
    let m = mask(w);
    prop_oneof![
        1 => Just(0u64),
        1 => Just(1u64),
        1 => Just(m),
        1 => Just(m - 1),
        1 => 0u64..=m.min(8),
        5 => any::<u64>().prop_map(move |x| x & m),
        // Small values with a short random width, so that quotients are not all 0 or tiny.
        3 => (1u32..=w, any::<u64>()).prop_map(|(b, x)| x & mask(b)),
    ]
}

fn width_and_operands() -> impl Strategy<Value = (u32, u64, u64)> {
    prop::sample::select(WIDTHS.to_vec()).prop_flat_map(|w| (Just(w), operand(w), operand(w)))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    /// The recurrence equals Rust's `/` and `%` (and the zero rule), with the latency W.
    #[test]
    fn quotient_and_remainder_equal_rust_division((w, n, d) in width_and_operands()) {
        let (q, r, z, k) = result(w, n, d);
        prop_assert_eq!(k, w);
        if let (Some(want_q), Some(want_r)) = (n.checked_div(d), n.checked_rem(d)) {
            prop_assert_eq!((q, r, z), (want_q, want_r, false));
            // The division identity, in u128 so that nothing can wrap.
            prop_assert_eq!(u128::from(q) * u128::from(d) + u128::from(r), u128::from(n));
            prop_assert!(r < d);
        } else {
            prop_assert_eq!((q, r, z), (mask(w), n, true));
        }
        let ref_ = divide(n, d, w);
        prop_assert_eq!((ref_.quotient, ref_.remainder, ref_.div_by_zero), (q, r, z));
    }

    /// fixed_quotient = ⌊num · 2^F / den⌋ computed in u128, or an overflow exactly when
    /// num · 2^F ≥ 2^W (or den = 0).
    #[test]
    fn fixed_quotient_equals_u128_arithmetic(
        w in 2u32..=64,
        num in any::<u64>(),
        num_bits in 0u32..=64,
        den in any::<u64>(),
        den_bits in 0u32..=64,
        f in 0u32..=64,
    ) {
        let num = if num_bits == 64 { num } else { num & ((1u64 << num_bits) - 1) };
        let den = den & mask(w) & if den_bits == 64 { u64::MAX } else { (1u64 << den_bits) - 1 };
        let wide = u128::from(num) << f; // num < 2^64, f ≤ 64: fits u128
        let got = fixed_quotient(num, den, f, w);
        if wide >> w != 0 {
            let overflowed = matches!(got, Err(Overflow::Numerator { .. }));
            prop_assert!(overflowed, "{:?}", got);
        } else if den == 0 {
            prop_assert_eq!(got, Err(Overflow::ZeroDenominator));
        } else {
            let want = wide / u128::from(den);
            prop_assert_eq!(got.map(u128::from), Ok(want));
            // The same value from the cycle model fed with the shifted numerator.
            let n = shifted_numerator(num, f, w).unwrap();
            prop_assert_eq!(u128::from(n), wide);
            if w <= 24 {
                let (q, _, _, _) = result(w, n, den);
                prop_assert_eq!(u128::from(q), want);
            }
        }
    }

    /// Random handshakes (starts while busy, resets) against a transaction-level description:
    /// an accepted start at edge k gives `done` with `divide(n, d)` after edge k + W, `busy`
    /// after edges k … k + W − 1, results held, reset clears everything.
    #[test]
    fn handshake_matches_the_transaction_description(
        w in prop::sample::select(vec![2u32, 8, 24, 48, 64]),
        cycles in prop::collection::vec((0u8..100, any::<u64>(), any::<u64>()), 1..300),
    ) {
        let mut m = SeqDividerModel::new(w);
        // (edges left until done, expected result) of the division in flight.
        let mut pending: Option<(u32, golden::arith::seq_divider::Division)> = None;
        let mut held = DividerOutputs::default();
        for (k, &(roll, a, b)) in cycles.iter().enumerate() {
            let inp = DividerInputs {
                reset: roll < 3,
                start: roll >= 50,
                numerator: a & mask(w),
                denominator: if roll % 7 == 0 { 0 } else { b & mask(w) },
            };
            let o = m.step(inp);
            let mut want = DividerOutputs { done: false, ..held };
            if inp.reset {
                pending = None;
                want = DividerOutputs::default();
            } else if let Some((left, res)) = pending {
                if left == 1 {
                    pending = None;
                    want = DividerOutputs {
                        busy: false,
                        done: true,
                        quotient: res.quotient,
                        remainder: res.remainder,
                        div_by_zero: res.div_by_zero,
                    };
                } else {
                    pending = Some((left - 1, res));
                }
            } else if inp.start {
                pending = Some((latency_cycles(w), divide(inp.numerator, inp.denominator, w)));
                want.busy = true;
            }
            prop_assert_eq!(o, want, "edge {}", k);
            held = o;
        }
    }
}
