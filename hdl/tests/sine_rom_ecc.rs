//! `SineRom` and `EccCorrector` against their bit-true models (`golden::sine_rom`,
//! `golden::ecc_corrector`), every cycle: the rust-hdl simulation (direct drive) on proptest
//! stimuli with random K, and the emitted Verilog in Icarus Verilog (a self-checking replay
//! bench written under `target/` at test time, ending in one `RESULT PASS`/`RESULT FAIL`
//! line that the test asserts).
//!
//! Stimuli: segments of 16..256 cycles, each with its own request rate (none, some, every
//! cycle), positions mostly within 0..K and sometimes anywhere in A bits (out of contract,
//! still defined), ΔM and E_reg random with their extremes, and random resets.

mod common;

use common::SplitMix;
use golden::ecc_corrector::{EccCorrector as EccModel, EccInputs, EccOutputs, NC_BITS};
use golden::sine_rom::SineRom as RomModel;
use hdl::{ecc_corrector_verilog, sine_rom_verilog, EccCorrector, SineRom};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn sext(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

/// A reproducible stimulus of `len` cycles for K = `lines`, A = `a` from `seed`.
fn stimulus(seed: u64, lines: u32, a: u32, len: usize) -> Vec<EccInputs> {
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
    let mut out = Vec::with_capacity(len);
    let (mut rate, mut left) = (0u64, 0u64);
    while out.len() < len {
        if left == 0 {
            left = 16 + rng.next() % 240;
            rate = [0, 100, 500, 1000][(rng.next() % 4) as usize];
        }
        left -= 1;
        let delta_m = match rng.next() % 8 {
            0 => -(1 << 23),
            1 => (1 << 23) - 1,
            2 => (rng.next() % 5) as i64 - 2,
            _ => sext(rng.next() & 0xff_ffff, 24),
        };
        let e_coef = match rng.next() % 6 {
            0 => -32768,
            1 => 32767,
            2 => 15576,
            _ => sext(rng.next() & 0xffff, 16),
        };
        out.push(EccInputs {
            reset: rng.next().is_multiple_of(60),
            start: rng.next() % 1000 < rate,
            delta_m,
            m_a: pos(&mut rng),
            m_b: pos(&mut rng),
            m0: pos(&mut rng),
            e_coef,
        });
    }
    out
}

fn rom_step<const A: usize, const D: usize>(uut: &mut SineRom<A, D>, c: &EccInputs) -> i64 {
    uut.m.next = c.m_a.into();
    uut.m0.next = c.m0.into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    sext(uut.data.val().to_u64(), D as u32)
}

fn ecc_step<const A: usize>(uut: &mut EccCorrector<A>, c: &EccInputs) -> EccOutputs {
    uut.reset.next = c.reset;
    uut.start.next = c.start;
    uut.delta_m.next = ((c.delta_m as u64) & 0xff_ffff).into();
    uut.m_a.next = c.m_a.into();
    uut.m_b.next = c.m_b.into();
    uut.m0.next = c.m0.into();
    uut.e_coef.next = ((c.e_coef as u64) & 0xffff).into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    EccOutputs {
        n_c: sext(uut.n_c.val().to_u64(), NC_BITS),
        valid: uut.valid.val(),
    }
}

fn compare_rom<const A: usize, const D: usize>(
    lines: u32,
    cycles: &[EccInputs],
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

fn compare_ecc<const A: usize>(lines: u32, cycles: &[EccInputs]) -> Result<(), TestCaseError> {
    let mut uut = EccCorrector::<A>::new(lines);
    uut.connect_all();
    let mut model = EccModel::new(lines, A as u32);
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(*c);
        prop_assert_eq!(
            ecc_step(&mut uut, c),
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
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn sine_rom_rust_hdl_equals_model(seed in any::<u64>(), pick in any::<u32>(),
                                      len in 100usize..800) {
        let lines = some_k(pick, 1024);
        compare_rom::<10, 16>(lines, &stimulus(seed, lines, 10, len))?;
        let small = 2 + pick % 3;
        compare_rom::<2, 4>(small, &stimulus(seed, small, 2, 100))?;
    }

    #[test]
    fn ecc_corrector_rust_hdl_equals_model(seed in any::<u64>(), pick in any::<u32>(),
                                           len in 100usize..800) {
        let lines = some_k(pick, 1024);
        compare_ecc::<10>(lines, &stimulus(seed, lines, 10, len))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 30, ..ProptestConfig::default() })]

    /// Other widths: a 12-bit, 24-bit table, and the corrector at A = 12 (K = 4096, 2500).
    #[test]
    fn other_widths_rust_hdl_equal_model(seed in any::<u64>(), pick in any::<u32>()) {
        let lines = some_k(pick, 4096);
        compare_rom::<12, 24>(lines, &stimulus(seed, lines, 12, 300))?;
        compare_ecc::<12>(lines, &stimulus(seed, lines, 12, 300))?;
    }
}

/// Many stimulus cases back to back, a reset first.
fn long_stimulus(seed: u64, lines: u32, a: u32, cases: u64) -> Vec<EccInputs> {
    let mut out = vec![];
    for i in 0..cases {
        let mut s = stimulus(seed.wrapping_add(i), lines, a, 500);
        s[0].reset = true;
        out.extend(s);
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

fn ecc_icarus<const A: usize>(lines: u32, seed: u64) {
    let mut model = EccModel::new(lines, A as u32);
    let (mut vectors, mut valids) = (String::new(), 0);
    let nmask = (1u64 << NC_BITS) - 1;
    for c in long_stimulus(seed, lines, A as u32, 40) {
        let o = model.step(c);
        valids += usize::from(o.valid);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.start),
            (c.delta_m as u64) & 0xff_ffff,
            c.m_a,
            c.m_b,
            c.m0,
            (c.e_coef as u64) & 0xffff,
            (o.n_c as u64) & nmask,
            u8::from(o.valid)
        );
    }
    assert!(valids > 1000, "too few results in the stimulus");
    let tb = common::replay_bench(
        "ecc_corrector",
        &[
            ("reset", 1),
            ("start", 1),
            ("delta_m", 24),
            ("m_a", A),
            ("m_b", A),
            ("m0", A),
            ("e_coef", 16),
        ],
        &[("n_c", NC_BITS as usize), ("valid", 1)],
        "valid",
    );
    let v = ecc_corrector_verilog::<A>(lines, "ecc_corrector");
    let dir = format!("ecc_a{A}_k{lines}");
    common::replay(
        "sine_rom_ecc",
        &dir,
        "ecc_corrector",
        &v,
        &tb,
        &vectors,
        valids,
    );
}

#[test]
fn sine_rom_emitted_verilog_in_icarus_equals_model() {
    rom_icarus::<10, 16>(1000, 0x51_1000);
    rom_icarus::<10, 16>(1024, 0x51_1024);
    rom_icarus::<2, 4>(3, 0x51_0003);
    rom_icarus::<12, 24>(2500, 0x51_2500);
}

#[test]
fn ecc_corrector_emitted_verilog_in_icarus_equals_model() {
    ecc_icarus::<10>(1024, 0xec_1024);
    ecc_icarus::<10>(1000, 0xec_1000);
}
