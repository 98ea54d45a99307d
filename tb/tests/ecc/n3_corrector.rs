// SPDX-License-Identifier: MIT OR Apache-2.0
//! `N3Corrector` (Rairán's n3 corrected for the eccentricity of its span) against its
//! bit-true model `golden::ecc::n3_corrector::N3CorrectorModel`, every cycle: the rust-hdl
//! simulation (direct drive) on proptest stimuli for N = 24, 8 and 32 (S = N + 17) and
//! several K, the emitted Verilog linted by Verilator and replayed in Icarus (a self-checking
//! bench from `common::replay_bench`, under `target/`), and, by hand, the latency N + 92 and
//! n3 unchanged when E = 0.
//!
//! Stimuli: starts at random times (sparse, about one per latency, bursts while busy: the
//! one-deep request register, the latest wins), n3 of every size and sign (0, ±max, the most
//! negative value), Nep1 0, 1, 2 and up to 2^N − 1 (the span's three rules), Ndt1 1 and
//! others, every shift (0, 1, 2) with R = K·2^s, positions P < R, coefficients random with
//! their extremes (E = 0 included), random resets.
//!
//! The lint waives what the shipped `encspeed_ecc` waives for this block
//! (`common::CORRECTOR_WAIVERS`): WIDTH on the masks of rust-hdl's `bit_cast`, and the
//! arithmetic blocks' unused `busy`.

use crate::common::{self, SplitMix};
use golden::ecc::n3_corrector::{latency_cycles, N3CorrectorModel, N3CorrectorOutputs, N3Job};
use golden::top::ecc_top::{TABLE_ADDRESS_BITS, TABLE_DATA_BITS};
use hdl::verilog::named_verilog;
use hdl::N3Corrector;
use proptest::prelude::*;
use rust_hdl::prelude::*;

const TABLE: (u32, u32) = (TABLE_ADDRESS_BITS, TABLE_DATA_BITS);

fn sext(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

fn mask(bits: u32) -> u64 {
    (1u64 << bits) - 1
}

/// One cycle's inputs (`job` is on the ports every cycle, latched with `start`).
#[derive(Clone, Copy, Debug, Default)]
struct In {
    reset: bool,
    start: bool,
    job: N3Job,
}

/// A random n3 estimate for K = `lines`, N = `bits`, S = N + 17.
fn job(rng: &mut SplitMix, lines: u32, bits: u32) -> N3Job {
    let s = bits + 17;
    let half = 1i64 << (s - 1);
    let mode_shift = (rng.next() % 3) as u32;
    let r = u64::from(lines) << mode_shift;
    let max = mask(bits);
    let n3 = match rng.next() % 8 {
        0 => 0,
        1 => half - 1,
        2 => -half,
        3 => -(half - 1),
        4 => (rng.next() % 65_536) as i64 - 32_768,
        _ => sext(rng.next(), s),
    };
    let nep = match rng.next() % 6 {
        0 => 0,
        1 | 2 => 1,
        3 => 2,
        4 => max,
        _ => rng.next() & max,
    };
    let ndt = match rng.next() % 4 {
        0 | 1 => 1,
        2 => 0,
        _ => rng.next() & max,
    };
    let zero = rng.next().is_multiple_of(8);
    let coef = |rng: &mut SplitMix| match rng.next() % 6 {
        _ if zero => 0,
        0 => -(1i64 << 31),
        1 => (1i64 << 31) - 1,
        2 => 124_609,
        _ => sext(rng.next(), 32),
    };
    let (coef_c, coef_d) = (coef(rng), coef(rng));
    N3Job {
        n3,
        position: match rng.next() % 5 {
            0 => 0,
            1 => r - 1,
            _ => rng.next() % r,
        },
        nep,
        ndt,
        mode_shift,
        coef_c,
        coef_d,
    }
}

/// A reproducible stimulus of `len` cycles from `seed` (the first cycle resets).
fn stimulus(seed: u64, lines: u32, bits: u32, len: usize) -> Vec<In> {
    let mut rng = SplitMix(seed);
    let per_latency = (1000 / u64::from(latency_cycles(bits))).max(1);
    let (mut rate, mut left) = (0u64, 0u64);
    let mut out = vec![In {
        reset: true,
        ..In::default()
    }];
    while out.len() < len {
        if left == 0 {
            left = 16 + rng.next() % 500;
            rate = [0, 2, per_latency, per_latency, 200][(rng.next() % 5) as usize];
        }
        left -= 1;
        out.push(In {
            reset: rng.next().is_multiple_of(1000),
            start: rng.next() % 1000 < rate,
            job: job(&mut rng, lines, bits),
        });
    }
    out
}

fn step<const N: usize, const S: usize>(
    uut: &mut N3Corrector<N, S>,
    lines: u32,
    c: &In,
) -> N3CorrectorOutputs {
    let j = &c.job;
    uut.reset.next = c.reset;
    uut.start.next = c.start;
    uut.n3.next = ((j.n3 as u64) & mask(S as u32)).into();
    uut.position.next = j.position.into();
    uut.nep.next = j.nep.into();
    uut.ndt.next = j.ndt.into();
    uut.shift.next = u64::from(j.mode_shift).into();
    uut.counts_per_rev.next = (u64::from(lines) << j.mode_shift).into();
    uut.coef_c.next = ((j.coef_c as u64) & 0xffff_ffff).into();
    uut.coef_d.next = ((j.coef_d as u64) & 0xffff_ffff).into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    N3CorrectorOutputs {
        n3c: sext(uut.n3c.val().to_u64(), S as u32),
        valid: uut.valid.val(),
    }
}

fn model_step(model: &mut N3CorrectorModel, c: &In) -> N3CorrectorOutputs {
    model.step(c.reset, c.start.then_some(c.job))
}

/// rust-hdl = model on `len` cycles from `seed`; the number of results.
fn compare<const N: usize, const S: usize>(
    seed: u64,
    lines: u32,
    len: usize,
) -> Result<usize, TestCaseError> {
    assert_eq!(S, N + 17);
    let mut uut = N3Corrector::<N, S>::new(lines);
    uut.connect_all();
    let mut model = N3CorrectorModel::new(lines, TABLE, N as u32, S as u32);
    let mut valids = 0;
    for (k, c) in stimulus(seed, lines, N as u32, len).iter().enumerate() {
        let want = model_step(&mut model, c);
        valids += usize::from(want.valid);
        prop_assert_eq!(
            step(&mut uut, lines, c),
            want,
            "N {} K {} edge {} {:?}",
            N,
            lines,
            k,
            c
        );
    }
    Ok(valids)
}

/// A multiple of 4 in 4..=max, often max, 1000 or a small one.
fn some_k(pick: u32, max: u32) -> u32 {
    match pick % 5 {
        0 => max,
        1 => 1000.min(max),
        2 => 4 * (1 + pick / 5 % 4),
        _ => 4 * (1 + (pick / 5) % (max / 4)),
    }
}

proptest! {
    #![proptest_config(common::proptest_config(40))]

    #[test]
    fn rust_hdl_equals_model_n24(seed in any::<u64>(), pick in any::<u32>(),
                                 len in 400usize..2000) {
        compare::<24, 41>(seed, some_k(pick, 1024), len)?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(12))]

    /// The narrowest (N = 8, S = 25) and the widest (N = 32, S = 49) speeds.
    #[test]
    fn rust_hdl_equals_model_n8_and_n32(seed in any::<u64>(), pick in any::<u32>()) {
        compare::<8, 25>(seed, some_k(pick, 64), 1000)?;
        compare::<32, 49>(seed ^ 1, some_k(pick, 4096), 1000)?;
    }
}

/// Hand-worked: a lone start while idle gives `valid` exactly N + 92 edges later (116 at
/// N = 24); with E = 0 (δ = 0) n3 comes out unchanged, at Nep1 = 1 (n3·(1 − 0)), at
/// Nep1 ≥ 2 with Ndt1 = 1 (n3 − 0) and with Ndt1 ≥ 2, in both directions, and the most
/// negative value as −(2^(S−1) − 1); a reset clears `n3c` to 0.
#[test]
fn latency_no_eccentricity_and_reset_by_hand() {
    const LATENCY: usize = 116;
    assert_eq!(latency_cycles(24) as usize, LATENCY);
    let lines = 1024;
    let mut uut = N3Corrector::<24, 41>::new(lines);
    uut.connect_all();
    let mut at = |c: In| step(&mut uut, lines, &c);
    at(In {
        reset: true,
        ..In::default()
    });
    let max = (1i64 << 40) - 1;
    let cases = [
        // (n3, Nep1, Ndt1, shift, expected)
        (123_456_789, 1, 1, 0, 123_456_789),
        (-987_654, 1, 7, 2, -987_654),
        (5 << 16, 6, 1, 1, 5 << 16),
        (-(3 << 16) - 17, 4, 1, 2, -(3 << 16) - 17),
        (77 << 16, 78, 3, 0, 77 << 16),
        (max, 1, 1, 0, max),
        (-max - 1, 2, 1, 0, -max),
    ];
    let mut last = 0;
    for (n3, nep, ndt, shift, want) in cases {
        let job = N3Job {
            n3,
            position: 300,
            nep,
            ndt,
            mode_shift: shift,
            coef_c: 0,
            coef_d: 0,
        };
        for k in 0..LATENCY + 3 {
            let o = at(In {
                start: k == 0,
                job,
                ..In::default()
            });
            assert_eq!(o.valid, k == LATENCY, "edge {k} after the start");
            let held = if k >= LATENCY { want } else { last };
            assert_eq!(o.n3c, held, "edge {k}, n3 {n3} Nep1 {nep} Ndt1 {ndt}");
        }
        last = want;
    }
    let o = at(In {
        reset: true,
        ..In::default()
    });
    assert_eq!((o.n3c, o.valid), (0, false));
}

fn icarus<const N: usize, const S: usize>(lines: u32, seed: u64) {
    let mut model = N3CorrectorModel::new(lines, TABLE, N as u32, S as u32);
    let (mut vectors, mut valids) = (String::new(), 0);
    let smask = mask(S as u32);
    for c in stimulus(seed, lines, N as u32, 16_000) {
        let o = model_step(&mut model, &c);
        valids += usize::from(o.valid);
        let j = &c.job;
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.start),
            (j.n3 as u64) & smask,
            j.position,
            j.nep,
            j.ndt,
            j.mode_shift,
            u64::from(lines) << j.mode_shift,
            (j.coef_c as u64) & 0xffff_ffff,
            (j.coef_d as u64) & 0xffff_ffff,
            (o.n3c as u64) & smask,
            u8::from(o.valid)
        );
    }
    assert!(valids > 40, "too few results: {valids}");
    let tb = common::replay_bench(
        "n3_corrector",
        &[
            ("reset", 1),
            ("start", 1),
            ("n3", S),
            ("position", 32),
            ("nep", N),
            ("ndt", N),
            ("shift", 2),
            ("counts_per_rev", 32),
            ("coef_c", 32),
            ("coef_d", 32),
        ],
        &[("n3c", S), ("valid", 1)],
        "valid",
    );
    let mut uut = N3Corrector::<N, S>::new(lines);
    uut.connect_all();
    let v = named_verilog(&uut, "n3_corrector");
    common::lint_with_waivers("n3_corrector", &v, common::CORRECTOR_WAIVERS);
    common::replay(
        "n3_corrector",
        &format!("n{N}_k{lines}"),
        "n3_corrector",
        &v,
        &tb,
        &vectors,
        valids,
    );
}

#[test]
fn emitted_verilog_lints_and_equals_model_in_icarus() {
    icarus::<24, 41>(1024, 0x33c_1024);
    icarus::<8, 25>(12, 0x33c_0012);
    icarus::<32, 49>(1000, 0x33c_1000);
}
