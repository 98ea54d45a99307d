// SPDX-License-Identifier: MIT OR Apache-2.0
//! `SeqDivider<W>` against its bit-true model `golden::arith::seq_divider::SeqDividerModel`, every
//! cycle: the rust-hdl simulation (direct drive) on proptest stimuli for several W, and the
//! emitted Verilog of W = 24 in Icarus Verilog (a self-checking bench written under
//! `target/` at test time), because rust-hdl's simulator and its Verilog can disagree.
//! The model itself is checked against Rust's `/` and `%` in `golden/tests/divider.rs`.

use crate::common;

use golden::arith::seq_divider::{mask, DividerInputs, DividerOutputs, SeqDividerModel};
use hdl::{seq_divider_verilog, SeqDivider};
use proptest::prelude::*;
use rust_hdl::prelude::*;

/// One rising edge of the rust-hdl block with `inp` applied; the outputs after it.
fn step<const W: usize>(uut: &mut SeqDivider<W>, inp: &DividerInputs) -> DividerOutputs {
    uut.reset.next = inp.reset;
    uut.start.next = inp.start;
    uut.numerator.next = inp.numerator.into();
    uut.denominator.next = inp.denominator.into();
    uut.clock.next = Clock { clk: false };
    assert!(simulate(uut, 100), "design did not settle");
    uut.clock.next = Clock { clk: true };
    assert!(simulate(uut, 100), "design did not settle");
    DividerOutputs {
        busy: uut.busy.val(),
        done: uut.done.val(),
        quotient: uut.quotient.val().to_u64(),
        remainder: uut.remainder.val().to_u64(),
        div_by_zero: uut.div_by_zero.val(),
    }
}

/// One cycle of stimulus before it is cut to W bits: a control roll and two raw operands.
#[derive(Clone, Copy, Debug)]
struct Cycle {
    /// 0..2: reset (0.8 %); 2..128: no start; 128..=255: start (also while busy).
    roll: u8,
    numerator: u64,
    denominator: u64,
}

/// An operand for any W up to 64, often a corner value; [`inputs`] masks it to W bits, so
/// that `u64::MAX` becomes all ones and `1 << 63` becomes 0 for a narrower W.
fn raw_operand() -> impl Strategy<Value = u64> {
    prop_oneof![
        2 => Just(0u64),
        2 => Just(1u64),
        2 => Just(u64::MAX),
        1 => Just(u64::MAX - 1),
        1 => Just(1u64 << 63),
        1 => 2u64..=16,
        6 => any::<u64>(),
        // Short random widths, so that quotients are spread and not mostly 0 or 1.
        4 => (1u32..=64, any::<u64>()).prop_map(|(b, x)| x & mask(b)),
    ]
}

fn cycle() -> impl Strategy<Value = Cycle> {
    (any::<u8>(), raw_operand(), raw_operand()).prop_map(|(roll, numerator, denominator)| Cycle {
        roll,
        numerator,
        denominator,
    })
}

fn inputs(w: u32, c: &Cycle) -> DividerInputs {
    DividerInputs {
        reset: c.roll < 2,
        start: c.roll >= 128,
        numerator: c.numerator & mask(w),
        denominator: c.denominator & mask(w),
    }
}

/// The rust-hdl block and the model from power-up on the same stimulus; the number of
/// completed divisions. Fails at the first cycle that differs.
fn compare<const W: usize>(cycles: &[Cycle]) -> Result<u32, TestCaseError> {
    let mut uut = SeqDivider::<W>::default();
    uut.connect_all();
    let mut model = SeqDividerModel::new(W as u32);
    let mut divisions = 0;
    for (k, c) in cycles.iter().enumerate() {
        let inp = inputs(W as u32, c);
        let want = model.step(inp);
        let got = step(&mut uut, &inp);
        prop_assert_eq!(got, want, "W = {}, edge {}, inputs {:?}", W, k, inp);
        divisions += u32::from(got.done);
    }
    Ok(divisions)
}

proptest! {
    #![proptest_config(common::proptest_config(500))]

    #[test]
    fn rust_hdl_equals_model_w8(cycles in prop::collection::vec(cycle(), 1..400)) {
        compare::<8>(&cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_w24(cycles in prop::collection::vec(cycle(), 1..400)) {
        compare::<24>(&cycles)?;
    }

    #[test]
    fn rust_hdl_equals_model_w48(cycles in prop::collection::vec(cycle(), 1..400)) {
        compare::<48>(&cycles)?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(200))]

    /// The edges of the supported range (W = 2, and 64 where rust-hdl's long bit vectors and
    /// the model's u64 arithmetic are both at their limit) and the short/long boundary of
    /// rust-hdl's `Bits` (32/33).
    #[test]
    fn rust_hdl_equals_model_edge_widths(cycles in prop::collection::vec(cycle(), 1..400)) {
        compare::<2>(&cycles)?;
        compare::<32>(&cycles)?;
        compare::<33>(&cycles)?;
        compare::<64>(&cycles)?;
    }
}

/// Back-to-back divisions (a start in every cycle) with no reset: the stimulus must complete
/// a division every W + 1 cycles, as documented, and still match the model.
#[test]
fn back_to_back_starts_give_one_result_per_w_plus_1_cycles() {
    let cycles: Vec<Cycle> = (0..25 * 10)
        .map(|k: u64| Cycle {
            roll: 255,
            numerator: k * 7919 + 13,
            denominator: k % 11,
        })
        .collect();
    assert_eq!(compare::<24>(&cycles).unwrap(), 10);
}

/// Self-checking bench: reads one line per clock cycle (inputs, then the expected outputs
/// after the edge, in hex), applies the inputs, checks every output after the edge, and ends
/// with one `RESULT` line.
const BENCH: &str = r#"module seq_divider_tb;
    reg clock = 1'b0;
    reg reset = 1'b0, start = 1'b0;
    reg [`W-1:0] numerator = 0, denominator = 0;
    wire busy, done, div_by_zero;
    wire [`W-1:0] quotient, remainder;
    reg e_reset, e_start, e_busy, e_done, e_dbz;
    reg [`W-1:0] e_num, e_den, e_quo, e_rem;
    integer fd, n, cycles, errors, dones;
    seq_divider uut(.clock(clock), .reset(reset), .start(start), .numerator(numerator),
        .denominator(denominator), .busy(busy), .done(done), .quotient(quotient),
        .remainder(remainder), .div_by_zero(div_by_zero));
    initial begin
        cycles = 0; errors = 0; dones = 0;
        fd = $fopen("vectors.txt", "r");
        if (fd == 0) begin
            $display("RESULT FAIL cannot open vectors.txt");
            $finish;
        end
        n = $fscanf(fd, "%h %h %h %h %h %h %h %h %h\n", e_reset, e_start, e_num, e_den,
            e_busy, e_done, e_quo, e_rem, e_dbz);
        while (n == 9) begin
            reset = e_reset; start = e_start; numerator = e_num; denominator = e_den;
            #5 clock = 1'b1;
            #1;
            if (busy !== e_busy || done !== e_done || quotient !== e_quo
                    || remainder !== e_rem || div_by_zero !== e_dbz) begin
                if (errors < 10)
                    $display("MISMATCH cycle %0d: got %b %b %h %h %b, want %b %b %h %h %b",
                        cycles, busy, done, quotient, remainder, div_by_zero,
                        e_busy, e_done, e_quo, e_rem, e_dbz);
                errors = errors + 1;
            end
            if (done === 1'b1) dones = dones + 1;
            cycles = cycles + 1;
            #4 clock = 1'b0;
            n = $fscanf(fd, "%h %h %h %h %h %h %h %h %h\n", e_reset, e_start, e_num, e_den,
                e_busy, e_done, e_quo, e_rem, e_dbz);
        end
        $fclose(fd);
        if (errors == 0 && cycles > 0)
            $display("RESULT PASS %0d cycles %0d divisions", cycles, dones);
        else
            $display("RESULT FAIL %0d cycles %0d mismatches", cycles, errors);
        $finish;
    end
endmodule
"#;

use common::SplitMix;

impl SplitMix {
    fn operand(&mut self) -> u64 {
        match self.next() % 10 {
            0 => 0,
            1 => 1,
            2 => u64::MAX,
            3 => self.next() & mask(1 + (self.next() % 64) as u32),
            _ => self.next(),
        }
    }
}

#[test]
fn emitted_verilog_w24_in_icarus_equals_model() {
    const W: u32 = 24;
    let mut rng = SplitMix(0x5eed_d1d1);
    let mut model = SeqDividerModel::new(W);
    let mut vectors = String::new();
    let mut divisions = 0;
    let mut zero_divisions = 0;
    while divisions < 400 {
        let roll = (rng.next() % 1000) as u16;
        let c = Cycle {
            // Rare resets (0.5 %), frequent starts (also while busy).
            roll: if roll < 5 {
                0
            } else if roll < 400 {
                10
            } else {
                200
            },
            numerator: rng.operand(),
            denominator: rng.operand(),
        };
        let i = inputs(W, &c);
        let o = model.step(i);
        divisions += u32::from(o.done);
        zero_divisions += u32::from(o.done && o.div_by_zero);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(i.reset),
            u8::from(i.start),
            i.numerator,
            i.denominator,
            u8::from(o.busy),
            u8::from(o.done),
            o.quotient,
            o.remainder,
            u8::from(o.div_by_zero)
        );
    }
    assert!(zero_divisions > 10, "the stimulus must divide by zero too");

    let dir = tools::work_dir("seq_divider", "icarus24").unwrap();
    std::fs::write(
        dir.join("seq_divider.v"),
        seq_divider_verilog::<24>("seq_divider"),
    )
    .unwrap();
    std::fs::write(dir.join("seq_divider_tb.v"), BENCH).unwrap();
    std::fs::write(dir.join("vectors.txt"), &vectors).unwrap();
    common::assert_bench_passes(
        &dir,
        &[&format!("-DW={W}")],
        &["seq_divider_tb.v", "seq_divider.v"],
        &vectors,
        &format!("{divisions} divisions"),
    );
}
