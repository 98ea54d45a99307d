// SPDX-License-Identifier: MIT OR Apache-2.0
//! `IdentGatherer` against its bit-true model (`golden::ecc::ident_gatherer`), every cycle: the
//! rust-hdl simulation (direct drive) on proptest stimuli, and the emitted Verilog in Icarus
//! Verilog (a self-checking replay bench written under `target/` at test time, ending in
//! one `RESULT PASS`/`RESULT FAIL` line that the test asserts).
//!
//! Stimuli: segments of 16..400 cycles, each with its own line rate (every cycle, every
//! other, sparse), positions counting up mod K with occasional jumps (sometimes ≥ K, out of
//! contract), periods random with their extremes (0, 1, 2^T − 1), an index after the
//! line at position 0 (same cycle or later) and sometimes anywhere, arms at random (also
//! during gathering and in the index's cycle), and random resets.

use crate::common;

use common::SplitMix;
use golden::ecc::ident_gatherer::{sum_bits, GatherInputs, GatherOutputs, IdentGatherer as Model};
use hdl::{ident_gatherer_verilog, IdentGatherer};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn sext(raw: u128, bits: u32) -> i128 {
    ((raw << (128 - bits)) as i128) >> (128 - bits)
}

/// A reproducible stimulus of `len` cycles for K = `lines`, A = `a`, T = `t` from `seed`.
fn stimulus(seed: u64, lines: u32, a: u32, t: u32, len: usize) -> Vec<GatherInputs> {
    let mut rng = SplitMix(seed);
    let amask = (1u64 << a) - 1;
    let tmask = (1u64 << t) - 1;
    let k = u64::from(lines);
    let mut out = Vec::with_capacity(len);
    let (mut rate, mut left, mut pos, mut z_due) = (0u64, 0u64, 0u64, false);
    while out.len() < len {
        if left == 0 {
            left = 16 + rng.next() % 384;
            rate = [1000, 500, 200, 50][(rng.next() % 4) as usize];
        }
        left -= 1;
        let mut c = GatherInputs {
            reset: rng
                .next()
                .is_multiple_of(if lines > 64 { 6000 } else { 700 }),
            arm: rng
                .next()
                .is_multiple_of(if lines > 64 { 900 } else { 120 }),
            ..GatherInputs::default()
        };
        if z_due && !rng.next().is_multiple_of(3) {
            c.index = true;
            z_due = false;
        }
        if rng.next() % 1000 < rate {
            pos = if rng.next().is_multiple_of(40) {
                rng.next() & amask
            } else {
                (pos + 1) % k
            };
            c.line = true;
            c.position = pos;
            c.period = match rng.next() % 10 {
                0 => 0,
                1 => tmask,
                2 => 1,
                3 => rng.next() & tmask,
                _ => (900 + rng.next() % 200) & tmask,
            };
            if pos == 0 {
                if rng.next().is_multiple_of(2) {
                    c.index = true;
                } else {
                    z_due = true;
                }
            }
        }
        if rng.next().is_multiple_of(500) {
            c.index = true;
        }
        out.push(c);
    }
    out
}

fn step<const A: usize, const T: usize, const W: usize>(
    uut: &mut IdentGatherer<A, T, W>,
    c: &GatherInputs,
) -> GatherOutputs {
    uut.reset.next = c.reset;
    uut.arm.next = c.arm;
    uut.index.next = c.index;
    uut.line.next = c.line;
    uut.position.next = c.position.into();
    uut.period.next = c.period.into();
    uut.clock.next = Clock { clk: false };
    assert!(simulate(uut, 100), "design did not settle");
    uut.clock.next = Clock { clk: true };
    assert!(simulate(uut, 100), "design did not settle");
    GatherOutputs {
        done: uut.done.val(),
        overflow: uut.overflow.val(),
        count: uut.count.val().to_u64(),
        t_min: uut.t_min.val().to_u64(),
        p_min: uut.p_min.val().to_u64(),
        t_max: uut.t_max.val().to_u64(),
        p_max: uut.p_max.val().to_u64(),
        sum_t: uut.sum_t.val().to_u128() as i128,
        sum_sin: sext(uut.sum_sin.val().to_u128(), W as u32),
        sum_cos: sext(uut.sum_cos.val().to_u128(), W as u32),
    }
}

/// Compares every cycle; returns the number of cycles with `done` and with `overflow`.
fn compare<const A: usize, const T: usize, const W: usize>(
    lines: u32,
    cycles: &[GatherInputs],
) -> Result<(usize, usize), TestCaseError> {
    let mut uut = IdentGatherer::<A, T, W>::new(lines);
    uut.connect_all();
    let mut model = Model::new(lines, A as u32, T as u32);
    let (mut dones, mut ovfs) = (0, 0);
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(*c);
        dones += usize::from(want.done);
        ovfs += usize::from(want.overflow);
        prop_assert_eq!(step(&mut uut, c), want, "K {} edge {} {:?}", lines, k, c);
    }
    Ok((dones, ovfs))
}

proptest! {
    #![proptest_config(common::proptest_config(250))]

    /// A = 2 (K = 4: overflow is common), A = 6 (K any multiple of 4 up to 64) and
    /// A = 10, T = 32 (K = 1024 or a random multiple of 4).
    #[test]
    fn ident_gatherer_rust_hdl_equals_model(seed in any::<u64>(), pick in any::<u32>(),
                                            len in 200usize..1200) {
        compare::<2, 8, 34>(4, &stimulus(seed, 4, 2, 8, len))?;
        let small = 4 * (1 + pick % 16);
        compare::<6, 16, 46>(small, &stimulus(seed ^ 1, small, 6, 16, len))?;
        let big = if pick.is_multiple_of(2) { 1024 } else { 4 * (1 + (pick >> 1) % 256) };
        compare::<10, 32, 66>(big, &stimulus(seed ^ 2, big, 10, 32, len))?;
    }
}

/// The stimulus exercises what it claims: results complete and overflows happen.
#[test]
fn stimulus_reaches_done_and_overflow() {
    let s = stimulus(7, 4, 2, 8, 20_000);
    let (d, o) = compare::<2, 8, 34>(4, &s).unwrap();
    println!("K = 4: done {d} overflow {o}");
    assert!(d > 1000 && o > 100, "done {d} overflow {o}");
    let s = stimulus(8, 1024, 10, 32, 20_000);
    let (d, _) = compare::<10, 32, 66>(1024, &s).unwrap();
    println!("K = 1024: done {d}");
    assert!(d > 500, "done {d}");
}

fn icarus<const A: usize, const T: usize, const W: usize>(lines: u32, seed: u64) {
    assert_eq!(W as u32, sum_bits(A as u32, T as u32));
    let mut model = Model::new(lines, A as u32, T as u32);
    let wmask = if W >= 128 {
        u128::MAX
    } else {
        (1u128 << W) - 1
    };
    let (mut vectors, mut dones) = (String::new(), 0);
    let mut cycles = vec![];
    for i in 0..4u64 {
        let mut s = stimulus(seed.wrapping_add(i), lines, A as u32, T as u32, 5000);
        s[0].reset = true;
        cycles.extend(s);
    }
    for c in cycles {
        let o = model.step(c);
        dones += usize::from(o.done);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.arm),
            u8::from(c.index),
            u8::from(c.line),
            c.position,
            c.period,
            u8::from(o.done),
            u8::from(o.overflow),
            o.count,
            o.t_min,
            o.p_min,
            o.t_max,
            o.p_max,
            (o.sum_t as u128) & wmask,
            (o.sum_sin as u128) & wmask,
            (o.sum_cos as u128) & wmask,
        );
    }
    assert!(dones > 200, "too few results in the stimulus");
    let tb = common::replay_bench(
        "ident_gatherer",
        &[
            ("reset", 1),
            ("arm", 1),
            ("index", 1),
            ("line", 1),
            ("position", A),
            ("period", T),
        ],
        &[
            ("done", 1),
            ("overflow", 1),
            ("count", 17),
            ("t_min", T),
            ("p_min", A),
            ("t_max", T),
            ("p_max", A),
            ("sum_t", W),
            ("sum_sin", W),
            ("sum_cos", W),
        ],
        "done",
    );
    let v = ident_gatherer_verilog::<A, T, W>(lines, "ident_gatherer");
    common::replay(
        "ident_gatherer",
        &format!("a{A}_t{T}_k{lines}"),
        "ident_gatherer",
        &v,
        &tb,
        &vectors,
        dones,
    );
}

#[test]
fn ident_gatherer_emitted_verilog_in_icarus_equals_model() {
    icarus::<10, 32, 66>(1024, 0x1d_1024);
    icarus::<2, 8, 34>(4, 0x1d_0004);
    icarus::<6, 16, 46>(60, 0x1d_0060);
}
