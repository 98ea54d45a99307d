// SPDX-License-Identifier: MIT OR Apache-2.0
//! `BaselineSpeeds` against its bit-true model `golden::baselines::baseline_speeds::BaselineSpeedsModel`,
//! every cycle: the rust-hdl simulation (direct drive) on proptest stimuli for (N, F) =
//! (8, 2), (12, 8), (24, 16) and the ends (32, 24) (random start timings, bursts of starts
//! while busy, resets mid-computation, every `mode_shift`, corner operands 0, 1 and 2^N − 1),
//! and the emitted Verilog in Icarus Verilog on long random replays (a self-checking bench
//! from `common::replay_bench`, written under `target/` at test time), because rust-hdl's
//! simulator and its Verilog can disagree. The model computes the speeds exactly in u128
//! (not by the hardware's algorithm), so a match proves the multiplier, the divider, the
//! rounding and the saturation exact; the model itself is checked against hand-worked
//! values in `golden/tests/baseline_speeds.rs`.

use crate::common;

use common::SplitMix;
use golden::baselines::baseline_speeds::{
    BaselineFormat, BaselineRequest, BaselineSpeedsInputs, BaselineSpeedsModel,
    BaselineSpeedsOutputs, BaselineValues,
};
use hdl::{baseline_speeds_type, baseline_speeds_verilog, BaselineSpeeds};
use proptest::prelude::*;
use rust_hdl::prelude::*;

/// One rising edge of the rust-hdl block with `inp` applied; the outputs after it.
fn step<const N: usize, const F: usize, const S: usize>(
    uut: &mut BaselineSpeeds<N, F, S>,
    f: BaselineFormat,
    inp: &BaselineSpeedsInputs,
) -> BaselineSpeedsOutputs {
    let r = &inp.req;
    uut.reset.next = inp.reset;
    uut.start.next = inp.start;
    uut.pc_count.next = f.pc_to_raw(r.pc_count).into();
    uut.et_period.next = r.et_period.into();
    uut.et_negative.next = r.et_negative;
    uut.et_valid.next = r.et_valid;
    uut.mt_m.next = r.mt_m.into();
    uut.mt_t.next = r.mt_t.into();
    uut.mt_negative.next = r.mt_negative;
    uut.cfg_dt.next = r.cfg_dt.into();
    uut.mode_shift.next = u64::from(r.mode_shift).into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    BaselineSpeedsOutputs {
        busy: uut.busy.val(),
        valid: uut.valid.val(),
        speeds: BaselineValues {
            pc: f.from_raw(uut.speed_pc.val().to_u64()),
            et: f.from_raw(uut.speed_et.val().to_u64()),
            mt: f.from_raw(uut.speed_mt.val().to_u64()),
        },
    }
}

/// One cycle of stimulus before it is cut to N bits.
#[derive(Clone, Copy, Debug)]
struct Cycle {
    /// Uniform 0..1000: below 2 reset; below 2 + the case's start rate, start.
    roll: u16,
    /// pc_count, et_period, mt_m, mt_t, cfg_dt (raw, masked to N bits).
    values: [u64; 5],
    /// et_negative, et_valid, mt_negative.
    flags: [bool; 3],
    mode_shift: u32,
}

/// A counter value for any N up to 32, often a corner; [`inputs`] masks it to N bits (so
/// `u64::MAX` becomes 2^N − 1, and −1 as `pc_count`).
fn raw_counter() -> impl Strategy<Value = u64> {
    prop_oneof![
        2 => Just(0u64),
        2 => Just(1u64),
        1 => Just(2u64),
        2 => Just(u64::MAX),
        1 => Just(u64::MAX - 1),
        // 2^(N−1) for N = 8, 12, 24, 32: the most negative pc_count.
        1 => prop_oneof![Just(1u64 << 7), Just(1 << 11), Just(1 << 23), Just(1 << 31)],
        2 => 1u64..=16,
        3 => any::<u64>(),
        // Short random widths: ratios over the whole range (and m > t: saturation).
        5 => (1u32..=32, any::<u64>()).prop_map(|(b, x)| x & ((1u64 << b) - 1)),
    ]
}

fn cycle() -> impl Strategy<Value = Cycle> {
    (
        0u16..1000,
        [
            raw_counter(),
            raw_counter(),
            raw_counter(),
            raw_counter(),
            raw_counter(),
        ],
        any::<[bool; 3]>(),
        0u32..4,
    )
        .prop_map(|(roll, values, flags, mode_shift)| Cycle {
            roll,
            values,
            flags,
            mode_shift,
        })
}

/// Start rate per 1000 cycles: bursts (starts in most cycles, nearly all while busy), about
/// one per latency, and sparse (mostly from idle).
fn start_rate() -> impl Strategy<Value = u16> {
    prop_oneof![2 => Just(600u16), 1 => Just(30), 1 => Just(5)]
}

/// `raw` (N bits) as a two's-complement value.
fn signed_n(raw: u64, n: u32) -> i64 {
    ((raw << (64 - n)) as i64) >> (64 - n)
}

fn inputs(f: BaselineFormat, rate: u16, c: &Cycle) -> BaselineSpeedsInputs {
    let max = f.counter_max();
    let v = c.values.map(|x| x & max);
    BaselineSpeedsInputs {
        reset: c.roll < 2,
        start: c.roll >= 2 && c.roll < 2 + rate,
        req: BaselineRequest {
            pc_count: signed_n(v[0], f.counter_bits()),
            et_period: v[1],
            et_negative: c.flags[0],
            et_valid: c.flags[1],
            mt_m: v[2],
            mt_t: v[3],
            mt_negative: c.flags[2],
            cfg_dt: v[4],
            mode_shift: c.mode_shift,
        },
    }
}

/// The rust-hdl block and the model from power-up on the same stimulus; the number of
/// results (`valid`). Fails at the first cycle that differs.
fn compare<const N: usize, const F: usize, const S: usize>(
    rate: u16,
    cycles: &[Cycle],
) -> Result<u32, TestCaseError> {
    let f = BaselineFormat::new(N as u32, F as u32).unwrap();
    let mut uut = BaselineSpeeds::<N, F, S>::default();
    uut.connect_all();
    let mut model = BaselineSpeedsModel::new(f);
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
    #![proptest_config(common::proptest_config(96))]

    #[test]
    fn rust_hdl_equals_model_n8_f2((rate, cycles) in stimulus()) {
        compare::<8, 2, 11>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n12_f8((rate, cycles) in stimulus()) {
        compare::<12, 8, 21>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n24_f16((rate, cycles) in stimulus()) {
        compare::<24, 16, 41>(rate, &cycles)?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(24))]

    /// The ends of the supported ranges: N = 32, F = 24 (57-bit outputs) and N = 32, F = 2.
    #[test]
    fn rust_hdl_equals_model_edge_formats((rate, cycles) in stimulus()) {
        compare::<32, 24, 57>(rate, &cycles)?;
        compare::<32, 2, 35>(rate, &cycles)?;
    }
}

/// Starts in every cycle with no reset: one result every L cycles (the pending request
/// begins at the edge after each `valid`), equal to the model throughout.
#[test]
fn back_to_back_starts_give_one_result_per_latency() {
    type Uut = baseline_speeds_type!(12, 8);
    let _: fn() -> Uut = BaselineSpeeds::<12, 8, 21>::default;
    let l = golden::baselines::baseline_speeds::latency_cycles(12, 8) as usize;
    let cycles: Vec<Cycle> = (0..=6 * l)
        .map(|k| {
            let k = k as u64;
            Cycle {
                roll: 500,
                values: [k * 37, k % 7, k * 13 % 300, 1 + k % 11, k * 7919 % 5000],
                flags: [
                    k.is_multiple_of(2),
                    !k.is_multiple_of(3),
                    k.is_multiple_of(5),
                ],
                mode_shift: (k % 4) as u32,
            }
        })
        .collect();
    assert_eq!(compare::<12, 8, 21>(600, &cycles).unwrap(), 6);
}

/// A reset in every cycle of a computation, one at a time: after each the block is idle
/// with zero outputs, and the next start computes from scratch (model equality throughout).
#[test]
fn reset_at_every_cycle_of_a_computation() {
    let l = golden::baselines::baseline_speeds::latency_cycles(8, 2) as usize;
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
                values: [u64::MAX, 3, 255, 254, 255],
                flags: [true, true, false],
                mode_shift: 0,
            })
            .collect();
        // Two results when the reset comes after the first `valid` (edge L), else one (a
        // reset at edge L itself wins over publishing).
        let want = if at > l { 2 } else { 1 };
        assert_eq!(compare::<8, 2, 11>(10, &cycles).unwrap(), want, "at {at}");
    }
}

/// The divider's corners at N = 8, F = 2, found by search over (m, dt) for each s and a
/// spread of t: a quotient of all ones (the rounding would carry out of the format:
/// saturate), and preloads A >> s = ⌊m·dt/2^(N+s)⌋ one below, at and one above t (the
/// saturation boundary). One start per case, each `latency` cycles apart.
fn divider_corners() -> Vec<Cycle> {
    let (n, fb) = (8u32, 2u32);
    let sb = n + fb + 1;
    let l = golden::baselines::baseline_speeds::latency_cycles(n, fb) as usize;
    let mut cycles = vec![];
    let mut counts = [0usize; 4];
    for s in 0..3u32 {
        for t in [1u64, 2, 3, 5, 64, 127, 128, 200, 253, 254, 255] {
            let mut found = [false; 4];
            for m in (1..256u64).rev() {
                for dt in (1..256u64).rev() {
                    let x = u128::from(m * dt);
                    let q = (x << (fb + 1 - s)) / u128::from(t);
                    let pre = (x >> (n + s)) as u64;
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
                    let i = cycles.len() as u64;
                    for k in 0..l {
                        cycles.push(Cycle {
                            roll: if k == 0 { 2 } else { 999 },
                            values: [i, t, m, t, dt],
                            flags: [i.is_multiple_of(2), true, i.is_multiple_of(3)],
                            // s = 2 also as mode_shift 3.
                            mode_shift: s + u32::from(s == 2 && i % 2 == 1),
                        });
                    }
                }
            }
        }
    }
    assert!(counts.iter().all(|&c| c > 5), "{counts:?}");
    cycles
}

#[test]
fn divider_corners_at_n8_f2() {
    let cycles = divider_corners();
    let l = golden::baselines::baseline_speeds::latency_cycles(8, 2) as usize;
    // Every start gets its result (the last one's comes after the end).
    let results = compare::<8, 2, 11>(10, &cycles).unwrap() as usize;
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

    /// A random cycle; `inputs` turns its roll into 2 resets in 1000 cycles and starts.
    fn cycle(&mut self) -> Cycle {
        let roll = (self.next() % 1000) as u16;
        Cycle {
            roll,
            values: [
                self.counter(),
                self.counter(),
                self.counter(),
                self.counter(),
                self.counter(),
            ],
            flags: [
                self.next().is_multiple_of(2),
                !self.next().is_multiple_of(4),
                self.next().is_multiple_of(2),
            ],
            mode_shift: (self.next() % 4) as u32,
        }
    }
}

/// Run the emitted Verilog of `BaselineSpeeds<N, F, S>` in Icarus on `results` results of a
/// random stimulus (starts at random times, bursts while busy, rare resets) and assert that
/// the bench passes every cycle; the stimulus must cover reverse, saturation, zero outputs
/// and every `mode_shift`.
fn icarus_equals_model<const N: usize, const F: usize, const S: usize>(
    seed: u64,
    prefix: &[Cycle],
    results: u32,
) {
    let f = BaselineFormat::new(N as u32, F as u32).unwrap();
    let mut rng = SplitMix(seed);
    let mut model = BaselineSpeedsModel::new(f);
    let mut vectors = String::new();
    let (mut valids, mut saturated, mut zeros) = (0, 0, 0);
    let mut negatives = [0u32; 3];
    let mut shifts = [0u32; 4];
    let mut directed = prefix.iter();
    while valids < results {
        let rate = if (valids / 20) % 2 == 0 { 15 } else { 400 };
        let (c, rate) = match directed.next() {
            Some(c) => (*c, 15),
            None => (rng.cycle(), rate),
        };
        let i = inputs(f, rate, &c);
        let o = model.step(i);
        let r = &i.req;
        valids += u32::from(o.valid);
        if o.valid {
            for (k, v) in [o.speeds.pc, o.speeds.et, o.speeds.mt]
                .into_iter()
                .enumerate()
            {
                negatives[k] += u32::from(v < 0);
            }
        }
        saturated += u32::from(o.valid && o.speeds.mt.abs() == f.max_magnitude());
        zeros += u32::from(o.valid && o.speeds.et == 0 && o.speeds.mt == 0);
        if i.start {
            shifts[r.mode_shift as usize] += 1;
        }
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(i.reset),
            u8::from(i.start),
            f.pc_to_raw(r.pc_count),
            r.et_period,
            u8::from(r.et_negative),
            u8::from(r.et_valid),
            r.mt_m,
            r.mt_t,
            u8::from(r.mt_negative),
            r.cfg_dt,
            r.mode_shift,
            f.to_raw(o.speeds.pc),
            f.to_raw(o.speeds.et),
            f.to_raw(o.speeds.mt),
            u8::from(o.valid),
            u8::from(o.busy)
        );
    }
    assert!(
        negatives.iter().all(|&n| n > results / 8),
        "the stimulus must cover reverse: {negatives:?}"
    );
    assert!(saturated > 0, "the stimulus must cover M/T saturation");
    assert!(zeros > 0, "the stimulus must cover zero outputs");
    assert!(
        shifts.iter().all(|&s| s > 10),
        "every mode_shift: {shifts:?}"
    );
    let tb = common::replay_bench(
        "baseline_speeds",
        &[
            ("reset", 1),
            ("start", 1),
            ("pc_count", N),
            ("et_period", N),
            ("et_negative", 1),
            ("et_valid", 1),
            ("mt_m", N),
            ("mt_t", N),
            ("mt_negative", 1),
            ("cfg_dt", N),
            ("mode_shift", 2),
        ],
        &[
            ("speed_pc", S),
            ("speed_et", S),
            ("speed_mt", S),
            ("valid", 1),
            ("busy", 1),
        ],
        "valid",
    );
    common::replay(
        "baseline_speeds",
        &format!("icarus_n{N}_f{F}"),
        "baseline_speeds",
        &baseline_speeds_verilog::<N, F, S>("baseline_speeds"),
        &tb,
        &vectors,
        valids as usize,
    );
}

#[test]
fn emitted_verilog_n24_f16_in_icarus_equals_model() {
    icarus_equals_model::<24, 16, 41>(0xba5e_5bee_d024, &[], 600);
}

#[test]
fn emitted_verilog_n12_f8_in_icarus_equals_model() {
    icarus_equals_model::<12, 8, 21>(0xba5e_5bee_d012, &[], 600);
}

/// With the divider corners of [`divider_corners`] first.
#[test]
fn emitted_verilog_n8_f2_in_icarus_equals_model() {
    let corners = divider_corners();
    let results = corners.len() / golden::baselines::baseline_speeds::latency_cycles(8, 2) as usize;
    icarus_equals_model::<8, 2, 11>(0xba5e_5bee_d008, &corners, results as u32 + 600);
}

#[test]
fn emitted_verilog_n32_f24_in_icarus_equals_model() {
    icarus_equals_model::<32, 24, 57>(0xba5e_5bee_d032, &[], 300);
}
