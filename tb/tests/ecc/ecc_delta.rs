// SPDX-License-Identifier: MIT OR Apache-2.0
//! `EccDelta` against its bit-true model (`golden::ecc::ecc_delta::EccDelta`), every cycle: the
//! rust-hdl simulation (direct drive) on proptest stimuli for several (A, D, K), K = 1000
//! and other K not a power of two included, and the emitted Verilog in Icarus Verilog on a
//! long random stimulus (a self-checking replay bench under `target/`, ending in one
//! `RESULT PASS`/`RESULT FAIL` line that the test asserts).
//!
//! Stimuli: segments of 16..400 cycles, each with its own request rate (none, rare, about
//! one per latency, every cycle: back-to-back starts and starts while busy), every shift
//! (3 included), positions mostly within 0..K·2^(s+1) and sometimes anywhere in 33 bits,
//! coefficients random with their extremes, and random resets.

use crate::common;

use common::SplitMix;
use golden::ecc::ecc_delta::{EccDelta as Model, Inputs, Outputs, Request, DELTA_BITS};
use hdl::{ecc_delta_verilog, EccDelta};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn sext(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

/// A reproducible stimulus of `len` cycles for K = `lines` from `seed`.
fn stimulus(seed: u64, lines: u32, len: usize) -> Vec<Inputs> {
    let mut rng = SplitMix(seed);
    let mut out = Vec::with_capacity(len);
    let (mut rate, mut left) = (0u64, 0u64);
    while out.len() < len {
        if left == 0 {
            left = 16 + rng.next() % 384;
            rate = [0, 3, 15, 100, 1000][(rng.next() % 5) as usize];
        }
        left -= 1;
        let shift = (rng.next() % 4) as u32;
        let span = u64::from(lines) << (shift.min(2) + 1);
        let mut pos = || {
            if rng.next().is_multiple_of(20) {
                rng.next() & ((1 << 33) - 1)
            } else {
                [0, span - 1, rng.next() % span, rng.next() % span][(rng.next() % 4) as usize]
            }
        };
        let (p_a, p_b) = (pos(), pos());
        let mut coef = || match rng.next() % 6 {
            0 => -(1i64 << 31),
            1 => (1i64 << 31) - 1,
            2 => 124_609, // 1.90 lines: e = 0.35/30 at K = 1024
            _ => sext(rng.next(), 32),
        };
        let (coef_c, coef_d) = (coef(), coef());
        out.push(Inputs {
            reset: rng.next().is_multiple_of(300),
            start: rng.next() % 1000 < rate,
            req: Request {
                p_a,
                p_b,
                shift,
                coef_c,
                coef_d,
            },
        });
    }
    out
}

fn step<const A: usize, const D: usize>(uut: &mut EccDelta<A, D>, c: &Inputs) -> Outputs {
    uut.reset.next = c.reset;
    uut.start.next = c.start;
    uut.p_a.next = c.req.p_a.into();
    uut.p_b.next = c.req.p_b.into();
    uut.shift.next = u64::from(c.req.shift).into();
    uut.coef_c.next = ((c.req.coef_c as u64) & 0xffff_ffff).into();
    uut.coef_d.next = ((c.req.coef_d as u64) & 0xffff_ffff).into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    Outputs {
        delta: sext(uut.delta.val().to_u64(), DELTA_BITS),
        valid: uut.valid.val(),
        busy: uut.busy.val(),
    }
}

/// Runs `cycles` through both; returns the number of results.
fn compare<const A: usize, const D: usize>(
    lines: u32,
    cycles: &[Inputs],
) -> Result<usize, TestCaseError> {
    let mut uut = EccDelta::<A, D>::new(lines);
    uut.connect_all();
    let mut model = Model::new(lines, A as u32, D as u32);
    let mut results = 0;
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(*c);
        results += usize::from(want.valid);
        prop_assert_eq!(
            step(&mut uut, c),
            want,
            "K {} A {} D {} edge {} {:?}",
            lines,
            A,
            D,
            k,
            c
        );
    }
    Ok(results)
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
    #![proptest_config(common::proptest_config(200))]

    #[test]
    fn rust_hdl_equals_model_a10_d24(seed in any::<u64>(), pick in any::<u32>(),
                                     len in 200usize..1500) {
        let lines = some_k(pick, 1024);
        compare::<10, 24>(lines, &stimulus(seed, lines, len))?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(40))]

    /// Other (A, D): the smallest table (K = 4, A = 2, D = 8), A = 12 with K up to 4096
    /// (2500 and other non-powers of two), D = 16 and 12.
    #[test]
    fn rust_hdl_equals_model_other_widths(seed in any::<u64>(), pick in any::<u32>()) {
        compare::<2, 8>(4, &stimulus(seed, 4, 400))?;
        let lines = some_k(pick, 4096);
        compare::<12, 16>(lines, &stimulus(seed, lines, 600))?;
        let lines = if pick % 2 == 0 { 2500 } else { some_k(pick, 4096) };
        compare::<12, 24>(lines, &stimulus(seed ^ 1, lines, 600))?;
        let lines = some_k(pick, 16);
        compare::<4, 12>(lines, &stimulus(seed ^ 2, lines, 400))?;
    }
}

#[test]
fn named_scenarios_rust_hdl_equals_model() {
    // Back-to-back starts for 200 cycles, then quiet; starts exactly 68 apart; a reset in
    // the middle of a job.
    let req = Request {
        p_a: 17,
        p_b: 2047,
        shift: 0,
        coef_c: 80_097,
        coef_d: 95_455,
    };
    let mut cycles = vec![];
    for k in 0..600u64 {
        cycles.push(Inputs {
            start: k < 200,
            req: Request { p_b: k, ..req },
            ..Inputs::default()
        });
    }
    for k in 0..700u64 {
        cycles.push(Inputs {
            start: k.is_multiple_of(68),
            req: Request {
                p_a: 3 * k,
                shift: 2,
                ..req
            },
            ..Inputs::default()
        });
    }
    for k in 0..300u64 {
        cycles.push(Inputs {
            reset: k == 40,
            start: k == 0 || k == 100,
            req,
        });
    }
    let results = compare::<10, 24>(1024, &cycles).unwrap();
    assert!(results >= 13, "{results}");
    let results = compare::<10, 24>(1000, &cycles).unwrap();
    assert!(results >= 13);
}

/// Requests whose accumulator R (golden::ecc::ecc_delta module docs, steps 1–4) lands exactly on a
/// rounding tie or one unit below it, each followed by a quiet computation: an error of one
/// unit of R anywhere in the datapath (a lost carry-in, a floor) changes `delta` there,
/// where random operands would almost never show it.
fn tie_requests(lines: u32, a: u32, d: u32, seed: u64, n: usize) -> Vec<Inputs> {
    use golden::ecc::ecc_delta::{interpolate, split_position};
    use golden::ecc::sine_rom::{sine_index, sine_table};
    let table = sine_table(lines, a, d);
    let at = |l: u64, m0: u64| table[sine_index(lines, a, l, m0) as usize];
    let k4 = u64::from(lines / 4);
    let mut rng = SplitMix(seed);
    let mut out = vec![];
    let mut found = 0;
    while found < n {
        let shift = (rng.next() % 3) as u32;
        let span = u64::from(lines) << (shift + 1);
        let req = Request {
            p_a: rng.next() % span,
            p_b: rng.next() % span,
            shift,
            coef_c: sext(rng.next(), 32),
            coef_d: sext(rng.next(), 32),
        };
        let (la, ta) = split_position(req.p_a, shift, a);
        let (lb, tb) = split_position(req.p_b, shift, a);
        let s8 = |l, t| interpolate(at(l, 0), at(l, 1), t);
        let c8 = |l, t| interpolate(at(l, k4), at(l, k4 + 1), t);
        let ds = i128::from(s8(lb, tb) - s8(la, ta));
        let dc = i128::from(c8(lb, tb) - c8(la, ta));
        let p = (i128::from(req.coef_c) * ds + i128::from(req.coef_d) * dc) << shift;
        let r = p + (p >> (d - 1));
        let m = (r + (1 << (d + 1))).rem_euclid(1 << (d + 2));
        if m == 0 || m == (1 << (d + 2)) - 1 {
            found += 1;
            out.push(Inputs {
                start: true,
                req,
                ..Inputs::default()
            });
            out.extend(std::iter::repeat_n(Inputs::default(), 70));
        }
    }
    out
}

fn icarus<const A: usize, const D: usize>(lines: u32, seed: u64, cases: u64, ties: usize) {
    let mut model = Model::new(lines, A as u32, D as u32);
    let (mut vectors, mut valids) = (String::new(), 0);
    let dmask = (1u64 << DELTA_BITS) - 1;
    for i in 0..=cases {
        let mut s = if i < cases {
            stimulus(seed.wrapping_add(i), lines, 500)
        } else {
            tie_requests(lines, A as u32, D as u32, seed, ties)
        };
        if let Some(first) = s.first_mut() {
            first.reset |= i == 0;
        }
        for c in s {
            let o = model.step(c);
            valids += usize::from(o.valid);
            vectors += &format!(
                "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
                u8::from(c.reset),
                u8::from(c.start),
                c.req.p_a,
                c.req.p_b,
                c.req.shift,
                (c.req.coef_c as u64) & 0xffff_ffff,
                (c.req.coef_d as u64) & 0xffff_ffff,
                (o.delta as u64) & dmask,
                u8::from(o.valid),
                u8::from(o.busy),
            );
        }
    }
    assert!(
        valids as u64 > 3 * cases,
        "too few results in the stimulus: {valids}"
    );
    let tb = common::replay_bench(
        "ecc_delta",
        &[
            ("reset", 1),
            ("start", 1),
            ("p_a", 33),
            ("p_b", 33),
            ("shift", 2),
            ("coef_c", 32),
            ("coef_d", 32),
        ],
        &[("delta", DELTA_BITS as usize), ("valid", 1), ("busy", 1)],
        "valid",
    );
    let v = ecc_delta_verilog::<A, D>(lines, "ecc_delta");
    let dir = format!("a{A}_d{D}_k{lines}");
    common::replay("ecc_delta", &dir, "ecc_delta", &v, &tb, &vectors, valids);
}

#[test]
fn emitted_verilog_in_icarus_equals_model() {
    icarus::<10, 24>(1024, 0xde_1024, 60, 0);
    icarus::<10, 24>(1000, 0xde_1000, 60, 0);
    icarus::<2, 8>(4, 0xde_0004, 10, 100);
    icarus::<4, 8>(16, 0xde_0016, 2, 200);
    icarus::<12, 16>(2500, 0xde_2500, 20, 0);
}
