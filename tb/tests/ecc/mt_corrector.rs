// SPDX-License-Identifier: MIT OR Apache-2.0
//! `MtCorrector` (the eccentricity-corrected M/T speed of each window) against its bit-true
//! model `golden::ecc::mt_corrector::MtCorrectorModel`, every cycle: the rust-hdl simulation
//! (direct drive) on proptest stimuli for (N, F) = (24, 16), (8, 2), (8, 16) and (32, 24)
//! and several K, the emitted Verilog linted by Verilator and replayed in Icarus (a
//! self-checking bench from `common::replay_bench`, under `target/`), and, by hand, the
//! latency 3N + F + 76 and the uncorrected speed when E = 0
//! (`golden::baselines::baseline_speeds::speed_mt`, independent of the corrector).
//!
//! Stimuli: starts at random times (sparse, about one per latency, bursts while busy: the
//! one-deep request register, the latest wins), every shift (0, 1, 2) with R = K·2^s,
//! positions P < R, m, t and dt with their corners (0, 1, R − 1, R, R + 1, 2^N − 1), both
//! directions, coefficients random with their extremes (E = 0 included), random resets.
//!
//! The lint waives what the shipped `encspeed_ecc` waives for this block
//! (`common::CORRECTOR_WAIVERS`): WIDTH on the masks of rust-hdl's `bit_cast`, and the
//! arithmetic blocks' unused `busy`.

use crate::common::{self, SplitMix};
use golden::baselines::baseline_speeds::{speed_mt, BaselineFormat};
use golden::ecc::mt_corrector::{latency_cycles, MtCorrectorModel, MtCorrectorOutputs, MtJob};
use golden::top::ecc_top::{TABLE_ADDRESS_BITS, TABLE_DATA_BITS};
use hdl::verilog::named_verilog;
use hdl::MtCorrector;
use proptest::prelude::*;
use rust_hdl::prelude::*;

const TABLE: (u32, u32) = (TABLE_ADDRESS_BITS, TABLE_DATA_BITS);

fn sext(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

/// One cycle's inputs (`job` is on the ports every cycle, latched with `start`).
#[derive(Clone, Copy, Debug, Default)]
struct In {
    reset: bool,
    start: bool,
    job: MtJob,
}

/// A random window for K = `lines` and N = `bits`.
fn job(rng: &mut SplitMix, lines: u32, bits: u32) -> MtJob {
    let mode_shift = (rng.next() % 3) as u32;
    let r = u64::from(lines) << mode_shift;
    let max = (1u64 << bits) - 1;
    let count = |rng: &mut SplitMix| match rng.next() % 10 {
        0 => 0,
        1 => 1,
        2 => max,
        3 => r - 1,
        4 => r,
        5 => r + 1,
        6 => 2 + rng.next() % 40,
        _ => rng.next() & max,
    } & max;
    let (mt_m, mt_t, cfg_dt) = (count(rng), count(rng), count(rng));
    let zero = rng.next().is_multiple_of(8);
    let coef = |rng: &mut SplitMix| match rng.next() % 6 {
        _ if zero => 0,
        0 => -(1i64 << 31),
        1 => (1i64 << 31) - 1,
        2 => 124_609,
        _ => sext(rng.next(), 32),
    };
    let (coef_c, coef_d) = (coef(rng), coef(rng));
    MtJob {
        position: match rng.next() % 5 {
            0 => 0,
            1 => r - 1,
            _ => rng.next() % r,
        },
        mt_m,
        mt_t,
        mt_negative: rng.next().is_multiple_of(2),
        cfg_dt,
        mode_shift,
        coef_c,
        coef_d,
    }
}

/// A reproducible stimulus of `len` cycles from `seed` (the first cycle resets).
fn stimulus(seed: u64, lines: u32, bits: u32, latency: u32, len: usize) -> Vec<In> {
    let mut rng = SplitMix(seed);
    let per_latency = (1000 / u64::from(latency)).max(1);
    let (mut rate, mut left) = (0u64, 0u64);
    let mut out = vec![In {
        reset: true,
        ..In::default()
    }];
    while out.len() < len {
        if left == 0 {
            left = 16 + rng.next() % 600;
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

fn step<const N: usize, const F: usize, const S: usize, const CW: usize>(
    uut: &mut MtCorrector<N, F, S, CW>,
    f: BaselineFormat,
    lines: u32,
    c: &In,
) -> MtCorrectorOutputs {
    let j = &c.job;
    uut.reset.next = c.reset;
    uut.start.next = c.start;
    uut.position.next = j.position.into();
    uut.mt_m.next = j.mt_m.into();
    uut.mt_t.next = j.mt_t.into();
    uut.mt_negative.next = j.mt_negative;
    uut.cfg_dt.next = j.cfg_dt.into();
    uut.shift.next = u64::from(j.mode_shift).into();
    uut.counts_per_rev.next = (u64::from(lines) << j.mode_shift).into();
    uut.coef_c.next = ((j.coef_c as u64) & 0xffff_ffff).into();
    uut.coef_d.next = ((j.coef_d as u64) & 0xffff_ffff).into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    MtCorrectorOutputs {
        speed_mtc: f.from_raw(uut.speed_mtc.val().to_u64()),
        valid: uut.valid.val(),
    }
}

fn model_step(model: &mut MtCorrectorModel, c: &In) -> MtCorrectorOutputs {
    model.step(c.reset, c.start.then_some(c.job))
}

/// rust-hdl = model on `len` cycles from `seed`; the number of results.
fn compare<const N: usize, const F: usize, const S: usize, const CW: usize>(
    seed: u64,
    lines: u32,
    len: usize,
) -> Result<usize, TestCaseError> {
    let f = BaselineFormat::new(N as u32, F as u32).unwrap();
    let latency = latency_cycles(N as u32, F as u32);
    let mut uut = MtCorrector::<N, F, S, CW>::new(lines);
    uut.connect_all();
    let mut model = MtCorrectorModel::new(lines, TABLE, f);
    let mut valids = 0;
    for (k, c) in stimulus(seed, lines, N as u32, latency, len)
        .iter()
        .enumerate()
    {
        let want = model_step(&mut model, c);
        valids += usize::from(want.valid);
        prop_assert_eq!(
            step(&mut uut, f, lines, c),
            want,
            "N {} F {} K {} edge {} {:?}",
            N,
            F,
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
    #![proptest_config(common::proptest_config(32))]

    #[test]
    fn rust_hdl_equals_model_n24_f16(seed in any::<u64>(), pick in any::<u32>(),
                                     len in 600usize..2500) {
        compare::<24, 16, 41, 41>(seed, some_k(pick, 1024), len)?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(8))]

    /// The narrowest (N = 8 with F = 2 and 16) and the widest (N = 32, F = 24) formats.
    #[test]
    fn rust_hdl_equals_model_other_widths(seed in any::<u64>(), pick in any::<u32>()) {
        compare::<8, 2, 11, 40>(seed, some_k(pick, 64), 1200)?;
        compare::<8, 16, 25, 40>(seed ^ 1, some_k(pick, 64), 1200)?;
        compare::<32, 24, 57, 49>(seed ^ 2, some_k(pick, 4096), 1200)?;
    }
}

/// Hand-worked: a lone start while idle gives `valid` exactly 3N + F + 76 edges later (164
/// at N = 24, F = 16); with E = 0 (c = d = 0, δ = 0) the result is the uncorrected M/T
/// speed `speed_mt`; a reset clears `speed_mtc` to 0.
#[test]
fn latency_no_eccentricity_and_reset_by_hand() {
    const LATENCY: usize = 164;
    assert_eq!(latency_cycles(24, 16) as usize, LATENCY);
    let f = BaselineFormat::new(24, 16).unwrap();
    let lines = 1024;
    let mut uut = MtCorrector::<24, 16, 41, 41>::new(lines);
    uut.connect_all();
    let mut at = |c: In| step(&mut uut, f, lines, &c);
    at(In {
        reset: true,
        ..In::default()
    });
    let windows = [
        (500, 37, 1000, false, 0),
        (3, 70_001, 200_000, true, 2),
        (4096, 4096, 1, false, 1),
    ];
    let mut last = 0;
    for (m, t, dt, negative, shift) in windows {
        let job = MtJob {
            position: 17,
            mt_m: m,
            mt_t: t,
            mt_negative: negative,
            cfg_dt: dt,
            mode_shift: shift,
            coef_c: 0,
            coef_d: 0,
        };
        let want = speed_mt(f, m, t, dt, negative, shift);
        for k in 0..LATENCY + 3 {
            let o = at(In {
                start: k == 0,
                job,
                ..In::default()
            });
            assert_eq!(o.valid, k == LATENCY, "edge {k} after the start");
            let held = if k >= LATENCY { want } else { last };
            assert_eq!(o.speed_mtc, held, "edge {k}, window {m} {t} {dt}");
        }
        last = want;
    }
    assert_ne!(last, 0);
    let o = at(In {
        reset: true,
        ..In::default()
    });
    assert_eq!((o.speed_mtc, o.valid), (0, false));
}

fn icarus<const N: usize, const F: usize, const S: usize, const CW: usize>(lines: u32, seed: u64) {
    let f = BaselineFormat::new(N as u32, F as u32).unwrap();
    let latency = latency_cycles(N as u32, F as u32);
    let mut model = MtCorrectorModel::new(lines, TABLE, f);
    let (mut vectors, mut valids) = (String::new(), 0);
    for c in stimulus(seed, lines, N as u32, latency, 20_000) {
        let o = model_step(&mut model, &c);
        valids += usize::from(o.valid);
        let j = &c.job;
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.start),
            j.position,
            j.mt_m,
            j.mt_t,
            u8::from(j.mt_negative),
            j.cfg_dt,
            j.mode_shift,
            u64::from(lines) << j.mode_shift,
            (j.coef_c as u64) & 0xffff_ffff,
            (j.coef_d as u64) & 0xffff_ffff,
            f.to_raw(o.speed_mtc),
            u8::from(o.valid)
        );
    }
    assert!(valids > 30, "too few results: {valids}");
    let tb = common::replay_bench(
        "mt_corrector",
        &[
            ("reset", 1),
            ("start", 1),
            ("position", 32),
            ("mt_m", N),
            ("mt_t", N),
            ("mt_negative", 1),
            ("cfg_dt", N),
            ("shift", 2),
            ("counts_per_rev", 32),
            ("coef_c", 32),
            ("coef_d", 32),
        ],
        &[("speed_mtc", S), ("valid", 1)],
        "valid",
    );
    let mut uut = MtCorrector::<N, F, S, CW>::new(lines);
    uut.connect_all();
    let v = named_verilog(&uut, "mt_corrector");
    common::lint_with_waivers("mt_corrector", &v, common::CORRECTOR_WAIVERS);
    common::replay(
        "mt_corrector",
        &format!("n{N}_f{F}_k{lines}"),
        "mt_corrector",
        &v,
        &tb,
        &vectors,
        valids,
    );
}

#[test]
fn emitted_verilog_lints_and_equals_model_in_icarus() {
    icarus::<24, 16, 41, 41>(1024, 0x3c0_1024);
    icarus::<8, 2, 11, 40>(12, 0x3c0_0012);
    icarus::<32, 24, 57, 49>(1000, 0x3c0_1000);
}
