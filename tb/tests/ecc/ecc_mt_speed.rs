// SPDX-License-Identifier: MIT OR Apache-2.0
//! `EccMtSpeed` against its bit-true model `golden::ecc::ecc_mt_speed::EccMtSpeedModel`, every
//! cycle: the rust-hdl simulation (direct drive) on proptest stimuli for (N, F) = (8, 16),
//! (12, 8), (24, 16), (32, 16) and the ends (8, 2), (32, 24) (random start timings, bursts
//! of starts while busy, resets mid-computation, every `mode_shift`, corner operands 0, 1,
//! 2^N − 1, δ realistic, anywhere in 40 bits, at its extremes and within a few LSB of m),
//! and the emitted Verilog in Icarus Verilog on long random replays (a self-checking bench
//! from `common::replay_bench`, written under `target/` at test time), because rust-hdl's
//! simulator and its Verilog can disagree. The model computes the speed by the exact rule in
//! u128 (not by the hardware's algorithm), so a match proves the corrected count, the
//! multiplier, the divider, the rounding, the zero cases and the saturation exact; the model
//! itself is checked against hand-worked values and `speed_mt` in
//! `golden/tests/ecc_mt_speed.rs`.

use crate::common;

use common::SplitMix;
use golden::baselines::baseline_speeds::BaselineFormat;
use golden::ecc::ecc_mt_speed::{
    latency_cycles, EccMtRequest, EccMtSpeedInputs, EccMtSpeedModel, EccMtSpeedOutputs, EccWidths,
};
use hdl::ecc::ecc_mt_speed::{ecc_mt_speed_verilog, EccMtSpeed};
use hdl::ecc_mt_speed_type;
use proptest::prelude::*;
use rust_hdl::prelude::*;

/// One rising edge of the rust-hdl block with `inp` applied; the outputs after it.
fn step<const N: usize, const F: usize, const S: usize, const C: usize>(
    uut: &mut EccMtSpeed<N, F, S, C>,
    f: BaselineFormat,
    inp: &EccMtSpeedInputs,
) -> EccMtSpeedOutputs {
    let r = &inp.req;
    let w = EccWidths::of(f);
    uut.reset.next = inp.reset;
    uut.start.next = inp.start;
    uut.mt_m.next = r.mt_m.into();
    uut.mt_t.next = r.mt_t.into();
    uut.mt_negative.next = r.mt_negative;
    uut.ecc_delta.next = w.delta_to_raw(r.ecc_delta).into();
    uut.cfg_dt.next = r.cfg_dt.into();
    uut.mode_shift.next = u64::from(r.mode_shift).into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    EccMtSpeedOutputs {
        busy: uut.busy.val(),
        valid: uut.valid.val(),
        speed_mtc: f.from_raw(uut.speed_mtc.val().to_u64()),
    }
}

/// One cycle of stimulus before it is cut to N bits.
#[derive(Clone, Copy, Debug)]
struct Cycle {
    /// Uniform 0..1000: below 2 reset; below 2 + the case's start rate, start.
    roll: u16,
    /// mt_m, mt_t, cfg_dt (raw, masked to N bits).
    values: [u64; 3],
    /// D (units of 2^−16 step), unless `near` is set.
    delta: i64,
    /// D = m·2^16 + `delta` mod 8 − 4 (m − δ within 4 LSB of 0), if that fits 40 bits.
    near: bool,
    negative: bool,
    mode_shift: u32,
}

/// A counter value for any N up to 32, often a corner; [`inputs`] masks it to N bits (so
/// `u64::MAX` becomes 2^N − 1).
fn raw_counter() -> impl Strategy<Value = u64> {
    prop_oneof![
        2 => Just(0u64),
        2 => Just(1u64),
        1 => Just(2u64),
        2 => Just(u64::MAX),
        1 => Just(u64::MAX - 1),
        2 => 1u64..=16,
        3 => any::<u64>(),
        // Short random widths: ratios over the whole range (and m > t: saturation).
        5 => (1u32..=32, any::<u64>()).prop_map(|(b, x)| x & ((1u64 << b) - 1)),
    ]
}

/// D: realistic (a few steps), anywhere in 40 bits, the extremes, random widths.
fn raw_delta() -> impl Strategy<Value = i64> {
    prop_oneof![
        2 => Just(0i64),
        4 => -(8i64 << 16)..=(8i64 << 16),
        2 => -(1i64 << 39)..(1i64 << 39),
        1 => Just(-(1i64 << 39)),
        1 => Just((1i64 << 39) - 1),
        2 => (1u32..=40).prop_flat_map(|b| {
            let h = 1i64 << (b - 1);
            -h..h
        }),
    ]
}

fn cycle() -> impl Strategy<Value = Cycle> {
    (
        0u16..1000,
        [raw_counter(), raw_counter(), raw_counter()],
        raw_delta(),
        0u8..8,
        any::<bool>(),
        0u32..4,
    )
        .prop_map(|(roll, values, delta, near, negative, mode_shift)| Cycle {
            roll,
            values,
            delta,
            near: near == 0,
            negative,
            mode_shift,
        })
}

/// Start rate per 1000 cycles: bursts (starts in most cycles, nearly all while busy), about
/// one per latency, and sparse (mostly from idle).
fn start_rate() -> impl Strategy<Value = u16> {
    prop_oneof![2 => Just(600u16), 1 => Just(30), 1 => Just(5)]
}

fn inputs(f: BaselineFormat, rate: u16, c: &Cycle) -> EccMtSpeedInputs {
    let max = f.counter_max();
    let v = c.values.map(|x| x & max);
    let near = ((v[0] as i64) << 16) + c.delta.rem_euclid(8) - 4;
    let delta = if c.near && near < (1 << 39) {
        near
    } else {
        c.delta
    };
    EccMtSpeedInputs {
        reset: c.roll < 2,
        start: c.roll >= 2 && c.roll < 2 + rate,
        req: EccMtRequest {
            mt_m: v[0],
            mt_t: v[1],
            mt_negative: c.negative,
            cfg_dt: v[2],
            mode_shift: c.mode_shift,
            ecc_delta: delta,
        },
    }
}

/// The rust-hdl block and the model from power-up on the same stimulus; the number of
/// results (`valid`). Fails at the first cycle that differs.
fn compare<const N: usize, const F: usize, const S: usize, const C: usize>(
    rate: u16,
    cycles: &[Cycle],
) -> Result<u32, TestCaseError> {
    let f = BaselineFormat::new(N as u32, F as u32).unwrap();
    let mut uut = EccMtSpeed::<N, F, S, C>::default();
    uut.connect_all();
    let mut model = EccMtSpeedModel::new(f);
    let mut results = 0;
    for (k, c) in cycles.iter().enumerate() {
        let inp = inputs(f, rate, c);
        let want = model.step(inp);
        let got = step(&mut uut, f, &inp);
        prop_assert_eq!(got, want, "N = {}, F = {}, edge {}, {:?}", N, F, k, inp);
        results += u32::from(got.valid);
    }
    Ok(results)
}

fn stimulus() -> impl Strategy<Value = (u16, Vec<Cycle>)> {
    (start_rate(), prop::collection::vec(cycle(), 200..1200))
}

proptest! {
    #![proptest_config(common::proptest_config(64))]

    #[test]
    fn rust_hdl_equals_model_n8_f16((rate, cycles) in stimulus()) {
        compare::<8, 16, 25, 40>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n12_f8((rate, cycles) in stimulus()) {
        compare::<12, 8, 21, 40>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n24_f16((rate, cycles) in stimulus()) {
        compare::<24, 16, 41, 41>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n32_f16((rate, cycles) in stimulus()) {
        compare::<32, 16, 49, 49>(rate, &cycles)?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(24))]

    /// The ends of the supported ranges: N = 32, F = 24 (57-bit output) and N = 8, F = 2.
    #[test]
    fn rust_hdl_equals_model_edge_formats((rate, cycles) in stimulus()) {
        compare::<32, 24, 57, 49>(rate, &cycles)?;
        compare::<8, 2, 11, 40>(rate, &cycles)?;
    }
}

/// The type macro names the widths the block asserts.
#[test]
fn type_macro_fills_in_the_derived_widths() {
    let _: fn() -> ecc_mt_speed_type!(24, 16) = EccMtSpeed::<24, 16, 41, 41>::default;
    let _: fn() -> ecc_mt_speed_type!(8, 16) = EccMtSpeed::<8, 16, 25, 40>::default;
    let _: fn() -> ecc_mt_speed_type!(23, 16) = EccMtSpeed::<23, 16, 40, 40>::default;
    let _: fn() -> ecc_mt_speed_type!(32, 16) = EccMtSpeed::<32, 16, 49, 49>::default;
    assert_eq!(hdl::ecc::ecc_mt_speed::corrected_width(24), 41);
}

/// Starts in every cycle with no reset: one result every L cycles (the pending request
/// begins at the edge after each `valid`), equal to the model throughout.
#[test]
fn back_to_back_starts_give_one_result_per_latency() {
    let l = latency_cycles(12, 8) as usize;
    let cycles: Vec<Cycle> = (0..=6 * l)
        .map(|k| {
            let k = k as u64;
            Cycle {
                roll: 500,
                values: [k * 13 % 300, 1 + k % 11, k * 7919 % 5000],
                delta: (k as i64 % 17 - 8) << 14,
                near: false,
                negative: k.is_multiple_of(5),
                mode_shift: (k % 4) as u32,
            }
        })
        .collect();
    assert_eq!(compare::<12, 8, 21, 40>(600, &cycles).unwrap(), 6);
}

/// A reset in every cycle of a computation, one at a time: after each the block is idle
/// with zero outputs, and the next start computes from scratch (model equality throughout).
#[test]
fn reset_at_every_cycle_of_a_computation() {
    let l = latency_cycles(8, 16) as usize;
    for at in 0..=l + 1 {
        let cycles: Vec<Cycle> = (0..3 * l)
            .map(|k| Cycle {
                roll: if k == at {
                    0
                } else if k == 0 || k == at + 1 {
                    2
                } else {
                    999
                },
                values: [255, 254, 255],
                delta: -(3 << 15),
                near: false,
                negative: true,
                mode_shift: 0,
            })
            .collect();
        // Two results when the reset comes after the first `valid` (edge L), else one (a
        // reset at edge L itself wins over publishing).
        let want = if at > l { 2 } else { 1 };
        assert_eq!(
            compare::<8, 16, 25, 40>(10, &cycles).unwrap(),
            want,
            "at {at}"
        );
    }
}

/// Directed corners at N = 8, F = 16, one start per case, each L cycles apart: for every s
/// and a spread of t, δ at c = −1, 0, 1, 2 (m − δ around 0), the extremes of D, and (m, dt)
/// found by search so that the preload A >> (16 + s) is one below, at and one above t (the
/// saturation boundary) and so that the quotient is all ones (the rounding would carry out
/// of the format).
fn corners() -> Vec<Cycle> {
    let (n, fb) = (8u32, 16u32);
    let sb = n + fb + 1;
    let l = latency_cycles(n, fb) as usize;
    let mut cases: Vec<(u64, u64, u64, i64, u32)> = vec![];
    let mut counts = [0usize; 4];
    for s in 0..3u32 {
        for t in [1u64, 2, 3, 5, 64, 127, 128, 200, 254, 255] {
            for m in [1u64, 2, 100, 255] {
                let dm = (m as i64) << 16;
                for delta in [dm + 1, dm, dm - 1, dm - 2, -(1 << 39), (1 << 39) - 1] {
                    cases.push((m, t, 255, delta, s));
                }
            }
            // c = m·2^16 − D for D in a few realistic values; search (m, dt).
            let mut found = [false; 4];
            for delta in [0i64, 1 << 15, -(1 << 15), -(5 << 16)] {
                for m in (1..256u64).rev() {
                    for dt in (1..256u64).rev() {
                        let c = ((m as i128) << 16) - delta as i128;
                        if c <= 0 {
                            continue;
                        }
                        let x = c as u128 * u128::from(dt);
                        let pre = (x >> (n + 16 + s)) as u64;
                        let q = (x << (fb + 1)) / (u128::from(t) << (16 + s));
                        let kind = if pre < t && q == (1 << sb) - 1 {
                            0
                        } else if pre + 1 == t {
                            1
                        } else if pre == t {
                            2
                        } else if pre == t + 1 {
                            3
                        } else {
                            continue;
                        };
                        if found[kind] {
                            continue;
                        }
                        found[kind] = true;
                        counts[kind] += 1;
                        cases.push((m, t, dt, delta, s));
                    }
                }
            }
        }
    }
    // All-ones quotients are rare in a search: construct them. With dt = 1 and m = 255,
    // the smallest c with c·2^(F+1)/(t·2^(16+s)) ≥ 2^S − 1, and D = m·2^16 − c.
    for s in 0..3u32 {
        for t in [1u64, 2, 3, 5, 64, 127, 128, 200, 254, 255] {
            let den = u128::from(t) << (16 + s);
            let c = ((((1u128 << sb) - 1) * den).div_ceil(1 << (fb + 1))) as i64;
            if ((c as u128) << (fb + 1)) / den == (1 << sb) - 1 {
                counts[0] += 1;
                cases.push((255, t, 1, (255 << 16) - c, s));
            }
        }
    }
    assert!(counts.iter().all(|&c| c > 5), "{counts:?}");
    let mut cycles = vec![];
    for (i, &(m, t, dt, delta, s)) in cases.iter().enumerate() {
        for k in 0..l {
            cycles.push(Cycle {
                roll: if k == 0 { 2 } else { 999 },
                values: [m, t, dt],
                delta,
                near: false,
                negative: i.is_multiple_of(3),
                // s = 2 also as mode_shift 3.
                mode_shift: s + u32::from(s == 2 && i % 2 == 1),
            });
        }
    }
    cycles
}

#[test]
fn corners_at_n8_f16() {
    let cycles = corners();
    let l = latency_cycles(8, 16) as usize;
    // Every start gets its result (the last one's comes after the end).
    let results = compare::<8, 16, 25, 40>(10, &cycles).unwrap() as usize;
    assert_eq!(results, cycles.len() / l - 1);
}

impl SplitMix {
    /// A counter value for any N up to 32, often a corner (masked to N bits later).
    fn counter(&mut self) -> u64 {
        match self.next() % 14 {
            0 => 0,
            1 | 2 => 1,
            3 => u64::MAX,
            4 => u64::MAX - 1,
            5 => 2 + self.next() % 15,
            6..=9 => self.next() & ((1u64 << (1 + self.next() % 32)) - 1),
            _ => self.next(),
        }
    }

    /// A D value: realistic, anywhere, extremes.
    fn delta(&mut self) -> i64 {
        match self.next() % 10 {
            0 => 0,
            1 => -(1 << 39),
            2 => (1 << 39) - 1,
            3 | 4 => ((self.next() << 24) as i64) >> 24,
            5 => {
                let b = 1 + self.next() % 40;
                ((self.next() << (64 - b)) as i64) >> (64 - b)
            }
            _ => (self.next() % (16 << 16)) as i64 - (8 << 16),
        }
    }

    /// A random cycle; `inputs` turns its roll into 2 resets in 1000 cycles and starts.
    fn cycle(&mut self) -> Cycle {
        let roll = (self.next() % 1000) as u16;
        Cycle {
            roll,
            values: [self.counter(), self.counter(), self.counter()],
            delta: self.delta(),
            near: self.next().is_multiple_of(8),
            negative: self.next().is_multiple_of(2),
            mode_shift: (self.next() % 4) as u32,
        }
    }
}

/// Run the emitted Verilog of `EccMtSpeed<N, F, S, C>` in Icarus on `results` results of a
/// random stimulus (starts at random times, bursts while busy, rare resets), after the
/// directed `prefix`, and assert that the bench passes every cycle; the stimulus must cover
/// reverse, saturation, zero outputs from m − δ ≤ 0 and every `mode_shift`.
fn icarus_equals_model<const N: usize, const F: usize, const S: usize, const C: usize>(
    seed: u64,
    prefix: &[Cycle],
    results: u32,
) {
    let f = BaselineFormat::new(N as u32, F as u32).unwrap();
    let w = EccWidths::of(f);
    let mut rng = SplitMix(seed);
    let mut model = EccMtSpeedModel::new(f);
    let mut vectors = String::new();
    let (mut valids, mut saturated, mut non_positive, mut negatives) = (0, 0, 0, 0);
    let mut shifts = [0u32; 4];
    let mut directed = prefix.iter();
    // The request being computed and the one pending, as the model schedules them (for
    // the coverage counts only).
    let (mut running, mut pending): (Option<EccMtRequest>, Option<EccMtRequest>) = (None, None);
    while valids < results {
        let rate = if (valids / 20u32).is_multiple_of(2) {
            15
        } else {
            400
        };
        let (c, rate) = match directed.next() {
            Some(c) => (*c, 15),
            None => (rng.cycle(), rate),
        };
        let i = inputs(f, rate, &c);
        let o = model.step(i);
        let r = &i.req;
        if let Some(q) = running {
            if o.valid {
                let c = (i128::from(q.mt_m) << 16) - i128::from(q.ecc_delta);
                non_positive += u32::from(q.mt_m > 0 && q.mt_t > 0 && c <= 0);
                running = None;
            }
        } else {
            running = pending.take();
        }
        if i.start {
            pending = Some(i.req);
        }
        if i.reset {
            (running, pending) = (None, None);
        }
        valids += u32::from(o.valid);
        if o.valid {
            negatives += u32::from(o.speed_mtc < 0);
            saturated += u32::from(o.speed_mtc.abs() == f.max_magnitude());
        }
        if i.start {
            shifts[r.mode_shift as usize] += 1;
        }
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(i.reset),
            u8::from(i.start),
            r.mt_m,
            r.mt_t,
            u8::from(r.mt_negative),
            w.delta_to_raw(r.ecc_delta),
            r.cfg_dt,
            r.mode_shift,
            f.to_raw(o.speed_mtc),
            u8::from(o.valid),
            u8::from(o.busy)
        );
    }
    assert!(
        negatives > results / 8,
        "the stimulus must cover reverse: {negatives}"
    );
    assert!(saturated > 0, "the stimulus must cover saturation");
    assert!(non_positive > 0, "the stimulus must cover m − δ ≤ 0");
    assert!(
        shifts.iter().all(|&s| s > 10),
        "every mode_shift: {shifts:?}"
    );
    let tb = common::replay_bench(
        "ecc_mt_speed",
        &[
            ("reset", 1),
            ("start", 1),
            ("mt_m", N),
            ("mt_t", N),
            ("mt_negative", 1),
            ("ecc_delta", 40),
            ("cfg_dt", N),
            ("mode_shift", 2),
        ],
        &[("speed_mtc", S), ("valid", 1), ("busy", 1)],
        "valid",
    );
    common::replay(
        "ecc_mt_speed",
        &format!("icarus_n{N}_f{F}"),
        "ecc_mt_speed",
        &ecc_mt_speed_verilog::<N, F, S, C>("ecc_mt_speed"),
        &tb,
        &vectors,
        valids as usize,
    );
}

#[test]
fn emitted_verilog_n24_f16_in_icarus_equals_model() {
    icarus_equals_model::<24, 16, 41, 41>(0xecc0_5bee_d024, &[], 1500);
}

/// With the directed corners of [`corners`] first.
#[test]
fn emitted_verilog_n8_f16_in_icarus_equals_model() {
    let prefix = corners();
    let results = prefix.len() / latency_cycles(8, 16) as usize;
    icarus_equals_model::<8, 16, 25, 40>(0xecc0_5bee_d008, &prefix, results as u32 + 800);
}

#[test]
fn emitted_verilog_n32_f24_in_icarus_equals_model() {
    icarus_equals_model::<32, 24, 57, 49>(0xecc0_5bee_d032, &[], 600);
}

#[test]
fn emitted_verilog_n12_f8_in_icarus_equals_model() {
    icarus_equals_model::<12, 8, 21, 40>(0xecc0_5bee_d012, &[], 600);
}
