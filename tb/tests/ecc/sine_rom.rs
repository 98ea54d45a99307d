// SPDX-License-Identifier: MIT OR Apache-2.0
//! `SineRom` against its bit-true model (`golden::ecc::sine_rom`), every cycle: the rust-hdl
//! simulation (direct drive) on proptest stimuli with random K, and the emitted Verilog in
//! Icarus Verilog (a self-checking replay bench written under `target/` at test time,
//! ending in one `RESULT PASS`/`RESULT FAIL` line that the test asserts). The correction
//! built on the table is tested in `ecc_delta.rs`.
//!
//! Stimuli: positions and offsets mostly within 0..K, sometimes anywhere in A bits (out of
//! contract, still defined).

use crate::common;

use common::SplitMix;
use golden::ecc::sine_rom::SineRom as RomModel;
use hdl::{sine_rom_verilog, SineRom};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn sext(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

/// One cycle's inputs: (m, m0).
#[derive(Clone, Copy, Debug)]
struct RomIn {
    m_a: u64,
    m0: u64,
}

/// A reproducible stimulus of `len` cycles for K = `lines`, A = `a` from `seed`.
fn stimulus(seed: u64, lines: u32, a: u32, len: usize) -> Vec<RomIn> {
    let mut rng = SplitMix(seed);
    let amask = (1u64 << a) - 1;
    let k = u64::from(lines);
    let pos = |rng: &mut SplitMix| {
        if rng.next().is_multiple_of(20) {
            rng.next() & amask
        } else {
            [0, k - 1, rng.next() % k, rng.next() % k][(rng.next() % 4) as usize]
        }
    };
    (0..len)
        .map(|_| RomIn {
            m_a: pos(&mut rng),
            m0: pos(&mut rng),
        })
        .collect()
}

fn rom_step<const A: usize, const D: usize>(uut: &mut SineRom<A, D>, c: &RomIn) -> i64 {
    uut.m.next = c.m_a.into();
    uut.m0.next = c.m0.into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    sext(uut.data.val().to_u64(), D as u32)
}

fn compare_rom<const A: usize, const D: usize>(
    lines: u32,
    cycles: &[RomIn],
) -> Result<(), TestCaseError> {
    let mut uut = SineRom::<A, D>::new(lines);
    uut.connect_all();
    let mut model = RomModel::new(lines, A as u32, D as u32);
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(c.m_a, c.m0);
        prop_assert_eq!(
            rom_step(&mut uut, c),
            want,
            "K {} edge {} {:?}",
            lines,
            k,
            c
        );
    }
    Ok(())
}

fn some_k(pick: u32, max: u32) -> u32 {
    match pick % 4 {
        0 => max,
        1 => 1000.min(max),
        _ => 2 + pick % (max - 1),
    }
}

proptest! {
    #![proptest_config(common::proptest_config(300))]

    #[test]
    fn sine_rom_rust_hdl_equals_model(seed in any::<u64>(), pick in any::<u32>(),
                                      len in 100usize..800) {
        let lines = some_k(pick, 1024);
        compare_rom::<10, 16>(lines, &stimulus(seed, lines, 10, len))?;
        let small = 2 + pick % 3;
        compare_rom::<2, 4>(small, &stimulus(seed, small, 2, 100))?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(30))]

    /// Other widths: a 12-bit, 24-bit table (K up to 4096).
    #[test]
    fn other_widths_rust_hdl_equal_model(seed in any::<u64>(), pick in any::<u32>()) {
        let lines = some_k(pick, 4096);
        compare_rom::<12, 24>(lines, &stimulus(seed, lines, 12, 300))?;
    }
}

/// Many stimulus cases back to back.
fn long_stimulus(seed: u64, lines: u32, a: u32, cases: u64) -> Vec<RomIn> {
    let mut out = vec![];
    for i in 0..cases {
        out.extend(stimulus(seed.wrapping_add(i), lines, a, 500));
    }
    out
}

fn rom_icarus<const A: usize, const D: usize>(lines: u32, seed: u64) {
    let mut model = RomModel::new(lines, A as u32, D as u32);
    let (mut vectors, mut nonzero) = (String::new(), 0);
    let dmask = (1u64 << D) - 1;
    for c in long_stimulus(seed, lines, A as u32, 40) {
        let d = model.step(c.m_a, c.m0);
        nonzero += usize::from(d != 0);
        vectors += &format!("{:x} {:x} {:x}\n", c.m_a, c.m0, (d as u64) & dmask);
    }
    let tb = common::replay_bench("sine_rom", &[("m", A), ("m0", A)], &[("data", D)], "data");
    let v = sine_rom_verilog::<A, D>(lines, "sine_rom");
    let dir = format!("rom_a{A}_d{D}_k{lines}");
    common::replay("sine_rom_ecc", &dir, "sine_rom", &v, &tb, &vectors, nonzero);
}

#[test]
fn sine_rom_emitted_verilog_in_icarus_equals_model() {
    rom_icarus::<10, 16>(1000, 0x51_1000);
    rom_icarus::<10, 16>(1024, 0x51_1024);
    rom_icarus::<2, 4>(3, 0x51_0003);
    rom_icarus::<12, 24>(2500, 0x51_2500);
}
