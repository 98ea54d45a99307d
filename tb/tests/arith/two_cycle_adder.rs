// SPDX-License-Identifier: MIT OR Apache-2.0
//! `TwoCycleAdder<W>` against its bit-true model
//! `golden::arith::two_cycle_adder::TwoCycleAdderModel` (Rust's integer sum of the inputs
//! at the last edge, wrapped to W bits), every cycle: the rust-hdl simulation for several
//! W, on operands that exercise the registered middle carry at its limits, and the emitted
//! Verilog of W = 49 (`SpeedCalc`'s divider width at the default format) in Icarus.

use crate::common;

use golden::arith::two_cycle_adder::TwoCycleAdderModel;
use hdl::{two_cycle_adder_verilog, TwoCycleAdder};
use proptest::prelude::*;
use rust_hdl::prelude::*;

/// `x` (< 2^W) as rust-hdl bits, for any W up to 127.
fn bits<const W: usize>(x: u128) -> Bits<W> {
    (0..W).fold(Bits::<W>::default(), |b, i| {
        b.replace_bit(i, (x >> i) & 1 == 1)
    })
}

/// One cycle of stimulus: the operands (cut to W bits) and the carry in.
#[derive(Clone, Copy, Debug)]
struct Cycle {
    a: u128,
    b: u128,
    carry_in: bool,
}

fn operand() -> impl Strategy<Value = u128> {
    prop_oneof![
        1 => Just(0u128),
        1 => Just(u128::MAX),
        // All ones in the low half or the high half: the middle carry at its limits.
        1 => (0u32..127).prop_map(|k| (1u128 << k) - 1),
        4 => any::<u128>(),
    ]
}

fn stimulus() -> impl Strategy<Value = Vec<Cycle>> {
    prop::collection::vec(
        (operand(), operand(), any::<bool>()).prop_map(|(a, b, carry_in)| Cycle { a, b, carry_in }),
        1..200,
    )
}

/// The rust-hdl block and the model from power-up on the same stimulus.
fn compare<const W: usize>(cycles: &[Cycle]) -> Result<(), TestCaseError> {
    let mask = (1u128 << W) - 1;
    let mut uut = TwoCycleAdder::<W>::default();
    uut.connect_all();
    let mut model = TwoCycleAdderModel::new(W as u32);
    for (k, c) in cycles.iter().enumerate() {
        let (a, b) = (c.a & mask, c.b & mask);
        uut.a.next = bits::<W>(a);
        uut.b.next = bits::<W>(b);
        uut.carry_in.next = c.carry_in;
        common::edge(&mut uut, |u, level| u.clock.next = Clock { clk: level });
        let want = model.edge(a, b, c.carry_in);
        prop_assert_eq!(
            uut.sum.val().to_u128(),
            want,
            "W = {}, cycle {}, {:?}",
            W,
            k,
            c
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(common::proptest_config(200))]

    #[test]
    fn rust_hdl_equals_model_at_several_widths(cycles in stimulus()) {
        compare::<4>(&cycles)?;
        compare::<5>(&cycles)?;
        compare::<41>(&cycles)?;
        compare::<49>(&cycles)?;
        compare::<64>(&cycles)?;
        compare::<65>(&cycles)?;
        compare::<127>(&cycles)?;
    }
}

#[test]
fn emitted_verilog_w49_in_icarus_equals_model() {
    const W: u32 = 49;
    let mask = (1u128 << W) - 1;
    let mut rng = common::SplitMix(0x2c7c_add5);
    let mut model = TwoCycleAdderModel::new(W);
    let (mut vectors, mut want) = (Vec::new(), Vec::new());
    let mut carries = 0;
    while vectors.len() < 3000 {
        let a = u128::from(rng.next()) & mask;
        // Every fourth b is the complement of a or of a − 1 (with the carry in: the carry
        // runs through every bit).
        let b = match rng.next() % 4 {
            0 => !a & mask,
            1 => !(a.wrapping_sub(1)) & mask,
            _ => u128::from(rng.next()) & mask,
        };
        let c = rng.next() % 2 == 1;
        let sum = model.edge(a, b, c);
        carries += u32::from(a + b + u128::from(c) > mask);
        vectors.push(vec![a as u64, b as u64, u64::from(c)]);
        want.push(vec![sum as u64]);
    }
    assert!(carries > 500, "the stimulus must carry out often");
    let verilog = two_cycle_adder_verilog::<49>("two_cycle_adder");
    let got = common::icarus_rows(
        "two_cycle_adder",
        "two_cycle_adder",
        &verilog,
        &[("a", 49), ("b", 49), ("carry_in", 1)],
        &[("sum", 49)],
        &vectors,
    );
    common::compare_rows("TwoCycleAdder<49>", &got, &want);
}
