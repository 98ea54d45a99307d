// SPDX-License-Identifier: MIT OR Apache-2.0
//! `SpeedCalc` against its bit-true model `golden::estimator::speed_calc::SpeedCalcModel`, every cycle:
//! the rust-hdl simulation (direct drive) on proptest stimuli for N = 8, 16, 24, 32 and
//! F = 0, 8, 16, 24 (random start timings, starts while busy, random resets, every mode
//! shift, random carried positions; every output compared, the request tag
//! `speed_position`/`speed_nep`/`speed_ndt` and `have_speeds` included), and the
//! emitted Verilog in Icarus Verilog (a self-checking bench written under `target/` at test
//! time), because rust-hdl's simulator and its Verilog can disagree. The model computes the
//! speeds exactly from the fractions (u128) and mode-scales them with a second rounding, so
//! a match proves the hardware's divider, multiplier and its one-adder rounding and scaling
//! exact; the model itself is checked against hand-worked values and
//! f64 in `golden/tests/speed_calc.rs`.

use crate::common;

use golden::estimator::speed_calc::{
    RequestTag, SpeedCalcInputs, SpeedCalcModel, SpeedCalcOutputs, SpeedFormat, Speeds,
};
use hdl::{speed_calc_type, speed_calc_verilog, SpeedCalc};
use proptest::prelude::*;
use rust_hdl::prelude::*;

/// One rising edge of the rust-hdl block with `inp` applied; the outputs after it.
fn step<const N: usize, const F: usize, const P: usize, const S: usize>(
    uut: &mut SpeedCalc<N, F, P, S>,
    f: SpeedFormat,
    inp: &SpeedCalcInputs,
) -> SpeedCalcOutputs {
    uut.reset.next = inp.reset;
    uut.start.next = inp.start;
    uut.nep.next = inp.nep.into();
    uut.ndt.next = inp.ndt.into();
    uut.negative.next = inp.negative;
    uut.mode_shift.next = u64::from(inp.shift).into();
    uut.position.next = inp.position.into();
    uut.clock.next = Clock { clk: false };
    assert!(simulate(uut, 100), "design did not settle");
    uut.clock.next = Clock { clk: true };
    assert!(simulate(uut, 100), "design did not settle");
    SpeedCalcOutputs {
        busy: uut.busy.val(),
        valid: uut.valid.val(),
        speeds: Speeds {
            n1: f.from_raw(uut.speed_n1.val().to_u64()),
            n2: f.from_raw(uut.speed_n2.val().to_u64()),
            n3: f.from_raw(uut.speed_n3.val().to_u64()),
        },
        tag: RequestTag {
            position: uut.speed_position.val().to_u64(),
            nep: uut.speed_nep.val().to_u64(),
            ndt: uut.speed_ndt.val().to_u64(),
        },
        have_speeds: uut.have_speeds.val(),
    }
}

/// One cycle of stimulus before it is cut to N bits.
#[derive(Clone, Copy, Debug)]
struct Cycle {
    /// Uniform 0..1000: below 2 reset; below the case's start rate, start.
    roll: u16,
    nep: u64,
    ndt: u64,
    negative: bool,
    /// Mode shift 0..=3 (3 acts as 2).
    shift: u32,
    /// The carried position (32 bits).
    position: u32,
}

/// A counter value for any N up to 32, often a corner; [`inputs`] masks it to N bits (so
/// `u64::MAX` becomes 2^N − 1).
fn raw_counter() -> impl Strategy<Value = u64> {
    prop_oneof![
        1 => Just(0u64),
        2 => Just(1u64),
        1 => Just(2u64),
        2 => Just(u64::MAX),
        1 => Just(u64::MAX - 1),
        2 => 1u64..=16,
        4 => any::<u64>(),
        // Short random widths: spread the ratios Nep/Ndt over the whole range.
        5 => (1u32..=32, any::<u64>()).prop_map(|(b, x)| x & ((1u64 << b) - 1)),
    ]
}

fn cycle() -> impl Strategy<Value = Cycle> {
    (
        0u16..1000,
        raw_counter(),
        raw_counter(),
        any::<bool>(),
        0u32..4,
        any::<u32>(),
    )
        .prop_map(|(roll, nep, ndt, negative, shift, position)| Cycle {
            roll,
            nep,
            ndt,
            negative,
            shift,
            position,
        })
}

/// Start rate per 1000 cycles: bursts (starts in most cycles, nearly all while busy), about
/// one per latency (some while busy), and sparse (mostly from idle).
fn start_rate() -> impl Strategy<Value = u16> {
    prop_oneof![2 => Just(600u16), 1 => Just(20), 1 => Just(5)]
}

fn inputs(f: SpeedFormat, rate: u16, c: &Cycle) -> SpeedCalcInputs {
    let max = f.counter_max();
    SpeedCalcInputs {
        reset: c.roll < 2,
        start: c.roll >= 2 && c.roll < 2 + rate,
        nep: c.nep & max,
        ndt: c.ndt & max,
        negative: c.negative,
        shift: c.shift,
        position: u64::from(c.position),
    }
}

/// The rust-hdl block and the model from power-up on the same stimulus; the number of
/// results (`valid`). Fails at the first cycle that differs.
fn compare<const N: usize, const F: usize, const P: usize, const S: usize>(
    rate: u16,
    cycles: &[Cycle],
) -> Result<u32, TestCaseError> {
    let f = SpeedFormat::new(N as u32, F as u32).unwrap();
    let mut uut = SpeedCalc::<N, F, P, S>::default();
    uut.connect_all();
    let mut model = SpeedCalcModel::new(f);
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
    fn rust_hdl_equals_model_n8_f8((rate, cycles) in stimulus()) {
        compare::<8, 8, 17, 17>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n8_f16((rate, cycles) in stimulus()) {
        compare::<8, 16, 17, 25>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n16_f8((rate, cycles) in stimulus()) {
        compare::<16, 8, 33, 25>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n16_f16((rate, cycles) in stimulus()) {
        compare::<16, 16, 33, 33>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n24_f8((rate, cycles) in stimulus()) {
        compare::<24, 8, 49, 33>(rate, &cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_n24_f16((rate, cycles) in stimulus()) {
        compare::<24, 16, 49, 41>(rate, &cycles)?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(24))]

    /// The ends of the supported ranges: F = 0 (integers) and N = 32, F = 24 (65-bit
    /// products, 57-bit outputs).
    #[test]
    fn rust_hdl_equals_model_edge_formats((rate, cycles) in stimulus()) {
        compare::<8, 0, 17, 9>(rate, &cycles)?;
        compare::<32, 24, 65, 57>(rate, &cycles)?;
    }
}

/// Starts in every cycle with no reset: one result every L cycles (the pending request
/// begins at the edge after each `valid`), equal to the model throughout.
#[test]
fn back_to_back_starts_give_one_result_per_latency() {
    type Calc = speed_calc_type!(16, 8);
    let _: fn() -> Calc = SpeedCalc::<16, 8, 33, 25>::default;
    let l = golden::estimator::speed_calc::latency_cycles(16, 8) as usize;
    let cycles: Vec<Cycle> = (0..=6 * l)
        .map(|k| Cycle {
            roll: 500,
            nep: (k as u64 * 7919 + 13) % 70_000,
            ndt: k as u64 % 5,
            negative: k.is_multiple_of(3),
            shift: (k % 4) as u32,
            position: (k as u32).wrapping_mul(2_654_435_761),
        })
        .collect();
    assert_eq!(compare::<16, 8, 33, 25>(600, &cycles).unwrap(), 6);
}

/// Self-checking bench: one line per clock cycle (inputs, then the expected outputs after
/// the edge, in hex); applies the inputs, checks every output after the edge, and ends with
/// one `RESULT` line.
const BENCH: &str = r#"module speed_calc_tb;
    reg clock = 1'b0;
    reg reset = 1'b0, start = 1'b0, negative = 1'b0;
    reg [1:0] mode_shift = 2'd0;
    reg [`N-1:0] nep = 0, ndt = 0;
    reg [31:0] position = 0;
    wire busy, valid, have_speeds;
    wire [`S-1:0] speed_n1, speed_n2, speed_n3;
    wire [31:0] speed_position;
    wire [`N-1:0] speed_nep, speed_ndt;
    reg e_reset, e_start, e_neg, e_busy, e_valid, e_have;
    reg [1:0] e_shift;
    reg [`N-1:0] e_nep, e_ndt, e_tnep, e_tndt;
    reg [31:0] e_pos, e_tpos;
    reg [`S-1:0] e_n1, e_n2, e_n3;
    integer fd, n, cycles, errors, valids;
    speed_calc uut(.clock(clock), .reset(reset), .start(start), .nep(nep), .ndt(ndt),
        .negative(negative), .mode_shift(mode_shift), .position(position),
        .speed_n1(speed_n1), .speed_n2(speed_n2), .speed_n3(speed_n3),
        .speed_position(speed_position), .speed_nep(speed_nep), .speed_ndt(speed_ndt),
        .valid(valid), .have_speeds(have_speeds), .busy(busy));
    initial begin
        cycles = 0; errors = 0; valids = 0;
        fd = $fopen("vectors.txt", "r");
        if (fd == 0) begin
            $display("RESULT FAIL cannot open vectors.txt");
            $finish;
        end
        n = $fscanf(fd, "%h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h\n", e_reset, e_start,
            e_nep, e_ndt, e_neg, e_shift, e_pos, e_busy, e_valid, e_n1, e_n2, e_n3, e_tpos,
            e_tnep, e_tndt, e_have);
        while (n == 16) begin
            reset = e_reset; start = e_start; nep = e_nep; ndt = e_ndt; negative = e_neg;
            mode_shift = e_shift; position = e_pos;
            #5 clock = 1'b1;
            #1;
            if (busy !== e_busy || valid !== e_valid || speed_n1 !== e_n1
                    || speed_n2 !== e_n2 || speed_n3 !== e_n3 || speed_position !== e_tpos
                    || speed_nep !== e_tnep || speed_ndt !== e_tndt
                    || have_speeds !== e_have) begin
                if (errors < 10)
                    $display("MISMATCH cycle %0d: got %b %b %h %h %h %h %h %h %b, want %b %b %h %h %h %h %h %h %b",
                        cycles, busy, valid, speed_n1, speed_n2, speed_n3, speed_position,
                        speed_nep, speed_ndt, have_speeds, e_busy, e_valid, e_n1, e_n2, e_n3,
                        e_tpos, e_tnep, e_tndt, e_have);
                errors = errors + 1;
            end
            if (valid === 1'b1) valids = valids + 1;
            cycles = cycles + 1;
            #4 clock = 1'b0;
            n = $fscanf(fd, "%h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h\n", e_reset,
                e_start, e_nep, e_ndt, e_neg, e_shift, e_pos, e_busy, e_valid, e_n1, e_n2, e_n3,
                e_tpos, e_tnep, e_tndt, e_have);
        end
        $fclose(fd);
        if (errors == 0 && cycles > 0)
            $display("RESULT PASS %0d cycles %0d results", cycles, valids);
        else
            $display("RESULT FAIL %0d cycles %0d mismatches", cycles, errors);
        $finish;
    end
endmodule
"#;

use common::SplitMix;

impl SplitMix {
    fn counter(&mut self) -> u64 {
        match self.next() % 12 {
            0 => 0,
            1 | 2 => 1,
            3 => u64::MAX,
            4 => 2 + self.next() % 15,
            5..=8 => self.next() & ((1u64 << (1 + self.next() % 32)) - 1),
            _ => self.next(),
        }
    }
}

/// Run the emitted Verilog of `SpeedCalc<N, F, P, S>` in Icarus on `results` results of a
/// random stimulus (starts at random times, also while busy, rare resets) and assert that
/// the bench passes every cycle.
fn icarus_equals_model<const N: usize, const F: usize, const P: usize, const S: usize>(
    seed: u64,
    results: u32,
) {
    let f = SpeedFormat::new(N as u32, F as u32).unwrap();
    let mut rng = SplitMix(seed);
    let mut model = SpeedCalcModel::new(f);
    let mut vectors = String::new();
    let (mut valids, mut negatives, mut saturated) = (0, 0, 0);
    while valids < results {
        let roll = (rng.next() % 1000) as u16;
        let rate = if (valids / 20) % 2 == 0 { 15 } else { 400 };
        let c = Cycle {
            roll,
            nep: rng.counter(),
            ndt: rng.counter(),
            negative: rng.next().is_multiple_of(2),
            shift: (rng.next() % 4) as u32,
            position: rng.next() as u32,
        };
        let i = inputs(f, rate, &c);
        let o = model.step(i);
        valids += u32::from(o.valid);
        negatives += u32::from(o.valid && o.speeds.n3 < 0);
        // Ndt = 0 saturates n1 to the largest magnitude, mode-scaled by 1, 2 or 4.
        let max = f.max_magnitude();
        saturated += u32::from(
            o.valid
                && (0..3).any(|s| {
                    o.speeds.n1.abs() == golden::estimator::speed_calc::mode_scale(max, s)
                }),
        );
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(i.reset),
            u8::from(i.start),
            i.nep,
            i.ndt,
            u8::from(i.negative),
            i.shift,
            i.position,
            u8::from(o.busy),
            u8::from(o.valid),
            f.to_raw(o.speeds.n1),
            f.to_raw(o.speeds.n2),
            f.to_raw(o.speeds.n3),
            o.tag.position,
            o.tag.nep,
            o.tag.ndt,
            u8::from(o.have_speeds)
        );
    }
    assert!(negatives > results / 4, "the stimulus must cover reverse");
    assert!(saturated > 0, "the stimulus must cover Ndt = 0");

    let dir = tools::work_dir("speed_calc", &format!("icarus_n{N}_f{F}")).unwrap();
    std::fs::write(
        dir.join("speed_calc.v"),
        speed_calc_verilog::<N, F, P, S>("speed_calc"),
    )
    .unwrap();
    std::fs::write(dir.join("speed_calc_tb.v"), BENCH).unwrap();
    std::fs::write(dir.join("vectors.txt"), &vectors).unwrap();
    common::assert_bench_passes(
        &dir,
        &[&format!("-DN={N}"), &format!("-DS={S}")],
        &["speed_calc_tb.v", "speed_calc.v"],
        &vectors,
        &format!("{valids} results"),
    );
}

#[test]
fn emitted_verilog_n24_f16_in_icarus_equals_model() {
    icarus_equals_model::<24, 16, 49, 41>(0x5eed_5bee_d024, 300);
}

#[test]
fn emitted_verilog_n8_f8_in_icarus_equals_model() {
    icarus_equals_model::<8, 8, 17, 17>(0x5eed_5bee_d008, 300);
}

#[test]
fn emitted_verilog_n32_f24_in_icarus_equals_model() {
    icarus_equals_model::<32, 24, 65, 57>(0x5eed_5bee_d032, 150);
}
