// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_wb` (the core behind its Wishbone register file) three ways, and as firmware
//! sees it:
//! - (a) the cycle model `golden::top::wb_top::WbTopModel` = the rust-hdl block
//!   `hdl::EncspeedWb` (top ports, and the core's and the register file's internal ports)
//!   = the emitted Verilog in Verilator (top ports), every cycle, on random bus programs
//!   (configuration writes, W1C, interrupt enable/clear, reads of every register and LO/HI
//!   pairs, resets) running while the encoder moves (quadrature at rates from 2 to 400
//!   cycles per step, reversals, stops, glitches);
//! - (b) a driver written as C firmware would be, with the header's offsets
//!   (`golden::bus::regmap`): x4 and dt over the bus, poll `STATUS.VALID`, read `SPEED_N3` LO
//!   then HI (and again after the next `SPEED` interrupt), against the core's own
//!   `speed_n3`, the hand-computed value and the Rairán budget;
//! - (c) the generated C header compiled by gcc into a program whose offsets, masks and
//!   speed decoding agree with `golden::bus::regmap` and with (b);
//! - the emitted `encspeed_wb.v` lints and synthesises; `docs/registers.md` is up to date.

use golden::bus::reg_file::WbBus;
use golden::bus::regmap::{self, LAYOUT, SPAN_BYTES, SPEEDS};
use golden::bus::wb_regs::WbRegsOutputs;
use golden::params::{Params, Spec};
use golden::top::core::CoreOutputs;
use golden::top::wb_top::{WbTopInputs, WbTopModel, WbTopOutputs};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use std::cell::RefCell;
use std::path::PathBuf;
use std::process::Command;
use std::sync::Mutex;
use tb::verilator::VerilatedWb;

/// Small parameters: 12-bit counters, dt = 200 cycles, 100 lines, timeout 20 dt.
fn small() -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: 200,
        counter_bits: 12,
        timeout_s: 20.0 * 200.0 / 1e6,
        ..Spec::default()
    })
    .unwrap()
}

fn default_params() -> Params {
    Params::new(Spec::default()).unwrap()
}

/// Compile the emitted Verilog of `p` once per process and parameter set (builds are
/// serialised so that two tests never build the same harness at once).
fn verilated(p: &Params) -> VerilatedWb {
    static BUILD: Mutex<()> = Mutex::new(());
    let _guard = BUILD.lock().unwrap_or_else(|e| e.into_inner());
    let v = &hdl::emit::wb::emit_wb(p)[0].1;
    VerilatedWb::build(v).unwrap()
}

// ---------------------------------------------------------------------------------------
// Stimulus: encoder motion and a bus program, run together
// ---------------------------------------------------------------------------------------

/// A stretch of encoder motion.
#[derive(Clone, Copy, Debug)]
struct Segment {
    /// Length, clock cycles.
    cycles: u32,
    /// Cycles per quadrature step (0: standing still).
    interval: u32,
    forward: bool,
    /// Glitches per 1000 cycles: a 1-3 cycle flip of A or B.
    glitches: u32,
}

/// One operation of the bus master.
#[derive(Clone, Copy, Debug)]
enum BusOp {
    Ctrl {
        mode: u8,
        z_mode: u8,
    },
    Dt(u32),
    Timeout(u32),
    Filter(u32),
    /// Write `STATUS` (W1C faults) with data and byte lanes.
    Status(u32, u8),
    IrqEnable(u32),
    IrqClear(u32),
    /// Write `CTRL`'s byte lane 1 alone: `SAMPLED` (bit 0 of the value), `HOLD` (bit 1),
    /// `TRIGGER` (bit 2).
    Snap(u32),
    Read(u32),
    /// Read a speed's LO then its HI register.
    Pair(usize),
    Idle(u32),
    Reset(u8),
}

#[derive(Clone, Debug)]
struct Case {
    /// Configuration writes before the motion starts.
    preamble: Vec<BusOp>,
    /// Bus operations, each after an idle gap (cycles).
    ops: Vec<(u32, BusOp)>,
    segments: Vec<Segment>,
    seed: u64,
}

fn segment(len: std::ops::Range<u32>) -> impl Strategy<Value = Segment> {
    (
        len,
        prop_oneof![1 => Just(0u32), 2 => 2u32..8, 3 => 8u32..60, 2 => 60u32..400],
        any::<bool>(),
        prop_oneof![3 => Just(0u32), 1 => 1u32..20],
    )
        .prop_map(|(cycles, interval, forward, glitches)| Segment {
            cycles,
            interval,
            forward,
            glitches,
        })
}

fn dt_value() -> impl Strategy<Value = u32> {
    prop_oneof![1 => Just(0u32), 4 => 20u32..400]
}

fn config_op() -> impl Strategy<Value = BusOp> {
    prop_oneof![
        3 => (0u8..3, 0u8..4).prop_map(|(mode, z_mode)| BusOp::Ctrl { mode, z_mode }),
        3 => dt_value().prop_map(BusOp::Dt),
        1 => prop_oneof![Just(0u32), 1u32..30].prop_map(BusOp::Timeout),
        1 => (0u32..5).prop_map(BusOp::Filter),
        1 => (0u32..128).prop_map(BusOp::IrqEnable),
        2 => (0u32..8).prop_map(BusOp::Snap),
    ]
}

fn bus_op() -> impl Strategy<Value = BusOp> {
    let addr = prop_oneof![
        6 => (0..LAYOUT.len()).prop_map(|k| LAYOUT[k].1),
        1 => (0..SPAN_BYTES).prop_map(|a| a),
    ];
    prop_oneof![
        4 => config_op(),
        1 => (any::<u32>(), prop_oneof![Just(0xFu8), 0u8..16])
            .prop_map(|(d, s)| BusOp::Status(d & 0x7F, s)),
        1 => (0u32..64).prop_map(BusOp::IrqClear),
        6 => addr.prop_map(BusOp::Read),
        3 => (0usize..6).prop_map(BusOp::Pair),
        2 => (1u32..400).prop_map(BusOp::Idle),
        1 => (1u8..3).prop_map(BusOp::Reset),
    ]
}

fn case(max_ops: usize, seg_len: std::ops::Range<u32>) -> impl Strategy<Value = Case> {
    (
        prop::collection::vec(config_op(), 0..4),
        prop::collection::vec((0u32..30, bus_op()), 5..max_ops),
        prop::collection::vec(segment(seg_len), 1..5),
        any::<u64>(),
    )
        .prop_map(|(preamble, ops, segments, seed)| Case {
            preamble,
            ops,
            segments,
            seed,
        })
}

/// splitmix64, for the glitches.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        golden::splitmix::next(&mut self.0)
    }
}

/// A quadrature encoder following a list of segments, then standing still. Forward =
/// A leads B: (A, B) = 00, 10, 11, 01; Z is high in the one state of the revolution where
/// the step count is 0 modulo 4·lines.
struct Encoder {
    segments: Vec<Segment>,
    k: usize,
    left: u32,
    acc: u32,
    state: u32,
    pos: i64,
    steps_per_rev: i64,
    glitch: (u32, bool),
    rng: SplitMix,
}

impl Encoder {
    fn new(segments: &[Segment], lines: u32, seed: u64) -> Encoder {
        Encoder {
            segments: segments.to_vec(),
            k: 0,
            left: segments.first().map_or(0, |s| s.cycles),
            acc: 0,
            state: 0,
            pos: 0,
            steps_per_rev: 4 * i64::from(lines),
            glitch: (0, false),
            rng: SplitMix(seed),
        }
    }

    fn done(&self) -> bool {
        self.k >= self.segments.len()
    }

    /// The levels for the next cycle.
    fn next(&mut self) -> (bool, bool, bool) {
        while !self.done() && self.left == 0 {
            self.k += 1;
            self.acc = 0;
            self.left = self.segments.get(self.k).map_or(0, |s| s.cycles);
        }
        if let Some(s) = self.segments.get(self.k).copied() {
            self.left -= 1;
            if s.interval > 0 {
                self.acc += 1;
                if self.acc >= s.interval {
                    self.acc = 0;
                    let d = if s.forward { 1 } else { 3 };
                    self.state = (self.state + d) % 4;
                    self.pos += if s.forward { 1 } else { -1 };
                }
            }
            if self.glitch.0 == 0 && (self.rng.next() % 1000) < u64::from(s.glitches) {
                self.glitch = (
                    1 + (self.rng.next() % 3) as u32,
                    self.rng.next().is_multiple_of(2),
                );
            }
        }
        let mut a = self.state == 1 || self.state == 2;
        let mut b = self.state == 2 || self.state == 3;
        if self.glitch.0 > 0 {
            self.glitch.0 -= 1;
            if self.glitch.1 {
                a = !a;
            } else {
                b = !b;
            }
        }
        (a, b, self.pos.rem_euclid(self.steps_per_rev) == 0)
    }
}

/// What a trace reached, to check that the stimulus exercises what it is meant to.
#[derive(Clone, Copy, Debug, Default)]
struct Coverage {
    cycles: usize,
    reads: usize,
    writes: usize,
    /// Reads of a speed LO or HI register that returned a non-zero word.
    speed_words: usize,
    speed_strobes: usize,
    valid_cycles: usize,
    irq_cycles: usize,
    clear_faults: usize,
    fault_cycles: usize,
    mode_changes: usize,
    index: usize,
    /// Snapshots taken (by `sample` or `CTRL.TRIGGER`).
    snapshots: usize,
    /// Reads executed while `CTRL.SAMPLED`.
    sampled_reads: usize,
}

impl Coverage {
    fn add(&mut self, o: &Coverage) {
        self.cycles += o.cycles;
        self.reads += o.reads;
        self.writes += o.writes;
        self.speed_words += o.speed_words;
        self.speed_strobes += o.speed_strobes;
        self.valid_cycles += o.valid_cycles;
        self.irq_cycles += o.irq_cycles;
        self.clear_faults += o.clear_faults;
        self.fault_cycles += o.fault_cycles;
        self.mode_changes += o.mode_changes;
        self.index += o.index;
        self.snapshots += o.snapshots;
        self.sampled_reads += o.sampled_reads;
    }
}

/// Every cycle of a run of the golden model: inputs, top outputs and the internal ports.
#[derive(Default)]
struct Trace {
    inputs: Vec<WbTopInputs>,
    outs: Vec<WbTopOutputs>,
    core: Vec<CoreOutputs>,
    regs: Vec<WbRegsOutputs>,
    cov: Coverage,
}

/// A classic master and the encoder in front of the golden model, recording every cycle.
struct Master {
    model: WbTopModel,
    enc: Encoder,
    /// Draws the `sample` strobes (about one cycle in 40).
    strobes: SplitMix,
    t: Trace,
}

impl Master {
    fn cycle(&mut self, reset: bool, bus: WbBus) -> WbTopOutputs {
        let (enc_a, enc_b, enc_z) = self.enc.next();
        let inp = WbTopInputs {
            reset,
            enc_a,
            enc_b,
            enc_z,
            sample: self.strobes.next().is_multiple_of(40),
            bus,
        };
        let mode_before = self.model.regs_outputs().cfg_mode;
        let snapshots_before = self.model.regs().snapshot().count;
        let o = self.model.step(&inp);
        let (c, r) = (self.model.core_outputs(), self.model.regs_outputs());
        let cov = &mut self.t.cov;
        cov.cycles += 1;
        cov.speed_strobes += usize::from(c.speed_strobe);
        cov.valid_cycles += usize::from(c.valid);
        cov.irq_cycles += usize::from(o.irq);
        cov.clear_faults += usize::from(r.clear_faults);
        cov.fault_cycles += usize::from(c.fault_illegal | c.fault_overspeed | c.fault_revolution);
        cov.mode_changes += usize::from(r.cfg_mode != mode_before);
        cov.index += usize::from(c.index);
        cov.snapshots +=
            usize::from(!reset && self.model.regs().snapshot().count != snapshots_before);
        self.t.inputs.push(inp);
        self.t.outs.push(o);
        self.t.core.push(c);
        self.t.regs.push(r);
        o
    }

    fn idle(&mut self, n: u32) {
        for _ in 0..n {
            self.cycle(false, WbBus::default());
        }
    }

    /// One access, the request held through its ack cycle; the data of the ack cycle.
    fn access(&mut self, we: bool, adr: u32, dat: u32, sel: u8) -> u32 {
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: we,
            wb_adr_i: adr,
            wb_dat_i: dat,
            wb_sel_i: sel,
        };
        assert!(
            !self.model.regs().busy(),
            "an access starts with the slave idle"
        );
        let sampled = self.model.regs().sampled();
        let executed = self.cycle(false, bus);
        assert!(
            !executed.wb_ack_o,
            "no ack in the cycle after the request edge"
        );
        let ack = self.cycle(false, bus);
        assert!(
            ack.wb_ack_o,
            "ack in the cycle after the edge after the request's"
        );
        let o = self.cycle(false, bus);
        assert!(!o.wb_ack_o, "one ack per access");
        self.t.cov.sampled_reads += usize::from(sampled && !we);
        if we {
            self.t.cov.writes += 1;
        } else {
            self.t.cov.reads += 1;
            let off = adr & !3;
            if SPEEDS.iter().any(|s| s.0 == off || s.1 == off) && ack.wb_dat_o != 0 {
                self.t.cov.speed_words += 1;
            }
        }
        ack.wb_dat_o
    }

    fn write(&mut self, adr: u32, dat: u32) {
        self.access(true, adr, dat, 0xF);
    }

    fn op(&mut self, op: BusOp) {
        match op {
            BusOp::Ctrl { mode, z_mode } => {
                let v = (u32::from(mode) << regmap::CTRL_MODE_LSB)
                    | (u32::from(z_mode) << regmap::CTRL_Z_MODE_LSB);
                let defined = self.model.regs().map().reg("CTRL").defined_mask();
                assert_eq!(v & !defined, 0);
                self.write(regmap::CTRL, v);
            }
            BusOp::Dt(v) => self.write(regmap::CFG_DT, v),
            BusOp::Timeout(v) => self.write(regmap::CFG_TIMEOUT, v),
            BusOp::Filter(v) => self.write(regmap::CFG_FILTER, v),
            BusOp::Status(v, sel) => {
                self.access(true, regmap::STATUS, v, sel);
            }
            BusOp::IrqEnable(v) => self.write(regmap::IRQ_ENABLE, v),
            BusOp::IrqClear(v) => self.write(regmap::IRQ_STATUS, v),
            BusOp::Snap(v) => {
                self.access(true, regmap::CTRL, v << regmap::CTRL_SAMPLED_LSB, 0b0010);
            }
            BusOp::Read(a) => {
                self.access(false, a, 0, 0);
            }
            BusOp::Pair(k) => {
                self.access(false, SPEEDS[k].0, 0, 0);
                self.access(false, SPEEDS[k].1, 0, 0);
            }
            BusOp::Idle(n) => self.idle(n),
            BusOp::Reset(n) => {
                for _ in 0..n {
                    self.cycle(true, WbBus::default());
                }
            }
        }
    }
}

/// The golden model's run of `case` on `p`: reset, the preamble, then the bus program and
/// the motion together until both are done.
fn trace(p: &Params, case: &Case) -> Trace {
    let mut m = Master {
        model: WbTopModel::new(p),
        enc: Encoder::new(&case.segments, p.lines(), case.seed),
        strobes: SplitMix(case.seed ^ 0x5a3b_1e5e),
        t: Trace::default(),
    };
    for _ in 0..3 {
        m.cycle(true, WbBus::default());
    }
    for &op in &case.preamble {
        m.op(op);
    }
    for &(gap, op) in &case.ops {
        m.idle(gap);
        m.op(op);
    }
    while !m.enc.done() {
        m.idle(1);
    }
    // Read every speed at the end, so that each run reads back what it measured.
    for k in 0..SPEEDS.len() {
        m.op(BusOp::Pair(k));
    }
    m.t
}

fn mismatch<T: std::fmt::Debug>(what: &str, k: usize, t: &Trace, want: T, got: T) -> TestCaseError {
    let from = k.saturating_sub(3);
    let ctx: Vec<String> = (from..=k)
        .map(|j| format!("  cycle {j}: {:?}", t.inputs[j]))
        .collect();
    TestCaseError::fail(format!(
        "{what} differs from the golden model at cycle {k}:\n  golden {want:?}\n  got    {got:?}\ninputs:\n{}",
        ctx.join("\n")
    ))
}

/// The rust-hdl block and the Verilator build against the golden trace, every cycle.
fn check(p: &Params, v: &VerilatedWb, t: &Trace) -> Result<(), TestCaseError> {
    let mut sim = hdl::build_wb(p);
    for (k, inp) in t.inputs.iter().enumerate() {
        let o = sim.step(inp);
        if o != t.outs[k] {
            return Err(mismatch("rust-hdl top", k, t, t.outs[k], o));
        }
        let c = sim.core_outputs();
        if c != t.core[k] {
            return Err(mismatch("rust-hdl core", k, t, t.core[k], c));
        }
        let r = sim.regs_outputs();
        if r != t.regs[k] {
            return Err(mismatch("rust-hdl regs", k, t, t.regs[k], r));
        }
    }
    let outs = v
        .run(&t.inputs, None)
        .map_err(|e| TestCaseError::fail(format!("verilator: {e}")))?;
    if outs.len() != t.outs.len() {
        return Err(TestCaseError::fail(format!(
            "verilator returned {} cycles of {}",
            outs.len(),
            t.outs.len()
        )));
    }
    if let Some(k) = (0..outs.len()).find(|&k| outs[k] != t.outs[k]) {
        return Err(mismatch("verilator", k, t, t.outs[k], outs[k]));
    }
    Ok(())
}

/// `cases` random cases on `p`, each compared three ways; the coverage summed over them.
fn run_cases(
    p: &Params,
    cases: u32,
    max_ops: usize,
    seg_len: std::ops::Range<u32>,
    prepend: &[BusOp],
) -> Coverage {
    let v = verilated(p);
    let total = RefCell::new(Coverage::default());
    let mut runner = TestRunner::new(Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    });
    let t0 = std::time::Instant::now();
    let result = runner.run(&case(max_ops, seg_len), |mut c| {
        c.preamble.splice(0..0, prepend.iter().copied());
        let t = trace(p, &c);
        check(p, &v, &t)?;
        total.borrow_mut().add(&t.cov);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    let cov = total.into_inner();
    println!(
        "counter_bits {}: {cases} cases, {} cycles identical in {:.1} s: {cov:?}",
        p.counter_bits(),
        cov.cycles,
        t0.elapsed().as_secs_f64()
    );
    cov
}

/// Whether the stimulus reached what it is meant to, over `cases` cases. The thresholds
/// are per case, well below the means; `small` adds what only the small parameters reach
/// often (index edges with 100 lines, fault clears). Half of the default-parameter cases
/// compute no speed at all (the random program changes dt, the mode or resets before a
/// speed is ready; measured over 200 cases: 95 with none, a mean of 4.6 strobes), so a
/// fixed batch of 10 can fall short by chance: [`run_until_covered`] adds batches instead.
fn covered(cov: &Coverage, cases: u32, small: bool) -> Result<(), String> {
    let n = cases as usize;
    let checks = [
        (
            cov.reads >= 10 * n && cov.writes >= 3 * n,
            "bus reads and writes",
        ),
        (cov.speed_strobes >= n, "speeds are computed"),
        (cov.speed_words >= n / 2, "non-zero speeds are read"),
        (cov.valid_cycles > 0 && cov.irq_cycles > 0, "valid and irq"),
        (cov.mode_changes >= n / 2, "mode changes"),
        (
            cov.snapshots >= n && cov.sampled_reads >= n / 2,
            "snapshots taken and read",
        ),
        (
            !small || (cov.fault_cycles > 0 && cov.clear_faults > 0 && cov.index > 0),
            "faults, clears and index edges",
        ),
    ];
    match checks.iter().find(|c| !c.0) {
        Some((_, what)) => Err(format!("{what}: {cases} cases: {cov:?}")),
        None => Ok(()),
    }
}

/// Random batches of `batch` cases (each compared three ways, every one must agree) until
/// their summed coverage meets [`covered`], at most `max_batches` batches: coverage closure,
/// so that a batch that fell short by chance is followed by more random cases rather than
/// a failure. Failing to close within the limit fails the test.
fn run_until_covered(
    p: &Params,
    batch: u32,
    max_batches: u32,
    max_ops: usize,
    seg_len: std::ops::Range<u32>,
    prepend: &[BusOp],
    small: bool,
) {
    let mut total = Coverage::default();
    for k in 1..=max_batches {
        total.add(&run_cases(p, batch, max_ops, seg_len.clone(), prepend));
        match covered(&total, k * batch, small) {
            Ok(()) => return,
            Err(e) if k == max_batches => panic!("coverage not closed: {e}"),
            Err(e) => println!("batch {k} short ({e}): another batch"),
        }
    }
}

#[test]
fn golden_rust_hdl_and_verilator_agree_small_params_a() {
    run_until_covered(&small(), 48, 3, 40, 50..800, &[], true);
}

#[test]
fn golden_rust_hdl_and_verilator_agree_small_params_b() {
    run_until_covered(&small(), 48, 3, 40, 50..800, &[], true);
}

/// At the default parameters dt is 100 000 cycles: the program sets a short dt first, and
/// the motion lasts longer (the speed calculator takes 128 cycles at N = 24).
#[test]
fn golden_rust_hdl_and_verilator_agree_default_params() {
    run_until_covered(
        &default_params(),
        10,
        5,
        30,
        300..1500,
        &[BusOp::Dt(160), BusOp::Timeout(30)],
        false,
    );
}

// ---------------------------------------------------------------------------------------
// (b) A driver, as firmware would write it
// ---------------------------------------------------------------------------------------

/// The device as firmware sees it: a bus and an encoder turning at a constant speed (A a
/// square wave of `period` cycles, B a quarter period behind). Every cycle steps the golden
/// model and the rust-hdl block together and compares them; the inputs are kept for a
/// Verilator replay.
struct Device {
    model: WbTopModel,
    sim: Box<dyn hdl::WbSim>,
    period: u64,
    cycle: u64,
    inputs: Vec<WbTopInputs>,
    outs: Vec<WbTopOutputs>,
    /// The core's speed_n3 as it stood at the last request edge.
    n3_at_request: i64,
}

impl Device {
    fn new(p: &Params, period: u64) -> Device {
        let mut d = Device {
            model: WbTopModel::new(p),
            sim: hdl::build_wb(p),
            period,
            cycle: 0,
            inputs: Vec::new(),
            outs: Vec::new(),
            n3_at_request: 0,
        };
        for _ in 0..3 {
            d.clock(true, WbBus::default());
        }
        d
    }

    fn clock(&mut self, reset: bool, bus: WbBus) -> WbTopOutputs {
        let m = self.cycle % self.period;
        let inp = WbTopInputs {
            reset,
            enc_a: m < self.period / 2,
            enc_b: (m + self.period - self.period / 4) % self.period < self.period / 2,
            enc_z: false,
            sample: false,
            bus,
        };
        self.cycle += 1;
        let o = self.model.step(&inp);
        let h = self.sim.step(&inp);
        assert_eq!(h, o, "rust-hdl = golden at cycle {}", self.cycle);
        assert_eq!(self.sim.core_outputs(), self.model.core_outputs());
        self.inputs.push(inp);
        self.outs.push(o);
        o
    }

    fn access(&mut self, we: bool, off: u32, dat: u32) -> u32 {
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: we,
            wb_adr_i: off,
            wb_dat_i: dat,
            wb_sel_i: 0xF,
        };
        self.n3_at_request = self.model.core_outputs().speed_n3;
        // Hold the request until the ack, then release the bus.
        let mut o = self.clock(false, bus);
        while !o.wb_ack_o {
            o = self.clock(false, bus);
        }
        self.clock(false, WbBus::default());
        o.wb_dat_o
    }

    // The firmware's two primitives.
    fn wb_read(&mut self, off: u32) -> u32 {
        self.access(false, off, 0)
    }
    fn wb_write(&mut self, off: u32, v: u32) {
        self.access(true, off, v);
    }
}

/// Firmware: read a speed coherently (LO latches HI), as a signed 64-bit raw value; with
/// it, the core's `speed_n3` at the LO read's request edge (what the pair must equal).
fn read_speed(dev: &mut Device, lo: u32, hi: u32) -> (i64, i64) {
    let l = dev.wb_read(lo);
    let core = dev.n3_at_request;
    let h = dev.wb_read(hi);
    (((u64::from(h) << 32) | u64::from(l)) as i64, core)
}

#[test]
fn a_driver_configures_x4_and_dt_and_reads_n3_by_hand() {
    use regmap::*;
    let p = default_params();
    // A square wave of 16 cycles: 10 lines per dt at dt = 160 cycles.
    let (period, dt) = (16u64, 160u32);
    let mut dev = Device::new(&p, period);

    // Probe and configure.
    assert_eq!(dev.wb_read(ID), ID_MAGIC);
    assert_eq!(dev.wb_read(VERSION) >> 16, MAP_VERSION >> 16);
    let map = RegMap::new(&p);
    let frac_field = map.reg("PARAM0").field("SPEED_FRAC_BITS");
    let frac = (dev.wb_read(PARAM0) & frac_field.mask()) >> frac_field.lsb;
    assert_eq!(frac, 16);
    let mode = map.reg("CTRL").field("MODE");
    dev.wb_write(CTRL, (2 << mode.lsb) & mode.mask()); // x4: resets the core
    dev.wb_write(CFG_DT, dt);
    assert_eq!(dev.wb_read(CFG_DT), dt);
    dev.wb_write(IRQ_ENABLE, map.mask("IRQ_ENABLE", "SPEED"));

    // Poll STATUS.VALID.
    let valid = map.mask("STATUS", "VALID");
    let mut polls = 0;
    while dev.wb_read(STATUS) & valid == 0 {
        polls += 1;
        assert!(polls < 2000, "STATUS.VALID never rose");
    }
    let irq_seen = dev.outs.iter().any(|o| o.irq);
    assert!(irq_seen, "the SPEED interrupt fired with the first speed");
    let speed_event = map.mask("IRQ_STATUS", "SPEED");
    assert_ne!(dev.wb_read(IRQ_STATUS) & speed_event, 0);
    // The first speed after VALID: LO then HI.
    let (n3, core_n3) = read_speed(&mut dev, SPEED_N3_LO, SPEED_N3_HI);
    assert_eq!(n3, core_n3, "equals the core's speed_n3");
    // Handle the interrupt: clear the event, wait for the next speed (irq), read again.
    dev.wb_write(IRQ_STATUS, speed_event);
    let mut waited = 0;
    while !dev.outs.last().unwrap().irq {
        dev.clock(false, WbBus::default());
        waited += 1;
        assert!(waited < 10 * dt, "no second SPEED interrupt");
    }
    let (next, core_next) = read_speed(&mut dev, SPEED_N3_LO, SPEED_N3_HI);
    assert_eq!(
        (next, core_next),
        (n3, n3),
        "constant speed, the same value"
    );
    // A few dt later: still the same.
    for _ in 0..(3 * dt) {
        dev.clock(false, WbBus::default());
    }
    let (again, core_again) = read_speed(&mut dev, SPEED_N3_LO, SPEED_N3_HI);
    assert_eq!((again, core_again), (n3, n3), "steady");
    // By hand: x4 steps every 4 cycles, 40 in every dt window starting at a step: Nep1 = 40,
    // Ndt1 = 1; n3 = 2·Nep(Nep − 1)/(Ndt(2·Nep − 1)) = 3120/79 steps/dt, in 2^−16:
    // 204 472 320 / 79 = 2 588 257 r 17 → 2 588 257; ÷ 4 (x4) = 647 064.25 → 647 064.
    let steps_q16 = (2 * 40 * 39 * 65_536 + 79 / 2) / 79;
    assert_eq!(steps_q16, 2_588_257);
    assert_eq!((steps_q16 + 2) / 4, 647_064);
    assert_eq!(n3, 647_064);
    // Within the Rairán budget of the true speed, 10 lines per dt.
    let measured = n3 as f64 / f64::from(1u32 << frac);
    let truth = (dt as f64) / (period as f64);
    let budget = golden::estimator::bounds::n3_error_budget(40.0, u64::from(dt));
    let rel = (measured / truth - 1.0).abs();
    assert!(rel <= budget, "relative error {rel} > budget {budget}");
    println!(
        "n3 = {measured:.6} lines/dt (truth {truth}), error {:.4} %, budget {:.4} %; {polls} \
         polls, {} cycles",
        rel * 100.0,
        budget * 100.0,
        dev.cycle
    );

    // Clear the handled interrupt: irq drops.
    dev.wb_write(IRQ_ENABLE, 0);
    dev.wb_write(IRQ_STATUS, speed_event);
    assert!(!dev.outs.last().unwrap().irq);

    // The whole session replayed in Verilator.
    let v = verilated(&p);
    let got = v.run(&dev.inputs, None).unwrap();
    assert_eq!(got.len(), dev.outs.len());
    if let Some(k) = (0..got.len()).find(|&k| got[k] != dev.outs[k]) {
        panic!(
            "verilator differs at cycle {k}: {:?} vs golden {:?}",
            got[k], dev.outs[k]
        );
    }
}

// ---------------------------------------------------------------------------------------
// (c) The C header, as firmware compiles it
// ---------------------------------------------------------------------------------------

fn work_dir(name: &str) -> PathBuf {
    tools::work_dir("wishbone_top", name).unwrap()
}

#[test]
fn the_c_header_compiles_and_a_c_program_agrees_with_the_map() {
    let p = default_params();
    let dir = work_dir("c_header");
    let files = hdl::emit::wb::emit_wb(&p);
    let (_, header) = files
        .iter()
        .find(|(n, _)| *n == "encspeed_regs.h")
        .expect("emit_wb writes the header");
    std::fs::write(dir.join("encspeed_regs.h"), header).unwrap();
    // Prints every offset by name, some masks, and decodes a speed from its two words.
    let mut c = String::from(
        "#include <stdint.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include \"encspeed_regs.h\"\n\
         static int64_t speed_raw(uint32_t lo, uint32_t hi) {\n\
         \treturn (int64_t)(((uint64_t)hi << 32) | lo);\n}\n\
         int main(int argc, char **argv) {\n\
         \tif (argc != 3) return 2;\n",
    );
    for (name, _) in LAYOUT {
        c += &format!("\tprintf(\"{name} %u\\n\", (unsigned)ENCSPEED_{name}_OFFSET);\n");
    }
    for (reg, field) in [
        ("CTRL", "MODE"),
        ("CTRL", "Z_MODE"),
        ("STATUS", "VALID"),
        ("STATUS", "FAULT_ILLEGAL"),
        ("IRQ_STATUS", "SPEED"),
    ] {
        c += &format!(
            "\tprintf(\"{reg}.{field} %u %u\\n\", (unsigned)ENCSPEED_{reg}_{field}_MASK, \
             (unsigned)ENCSPEED_{reg}_{field}_SHIFT);\n"
        );
    }
    c += "\tint64_t raw = speed_raw((uint32_t)strtoul(argv[1], 0, 0), (uint32_t)strtoul(argv[2], 0, 0));\n\
          \tprintf(\"speed %lld %.9f\\n\", (long long)raw, (double)raw / (double)(1u << ENCSPEED_SPEED_FRAC_BITS));\n\
          \treturn 0;\n}\n";
    std::fs::write(dir.join("driver.c"), c).unwrap();
    tools::run(
        Command::new("gcc")
            .current_dir(&dir)
            .args([
                "-std=c99",
                "-Wall",
                "-Wextra",
                "-Werror",
                "-pedantic-errors",
            ])
            .args(["-o", "driver", "driver.c"]),
        "gcc",
    )
    .unwrap();
    // The driver's speed of (b) and a negative one: -1.5 lines/dt = -98 304 raw.
    let neg = (-98_304i64) as u64;
    for (lo, hi, raw) in [
        (647_064u64, 0u64, 647_064i64),
        (neg & 0xFFFF_FFFF, neg >> 32, -98_304),
    ] {
        let text = tools::run(
            Command::new(dir.join("driver")).args([lo.to_string(), hi.to_string()]),
            "driver",
        )
        .unwrap();
        let mut lines = text.lines();
        for (name, off) in LAYOUT {
            assert_eq!(lines.next(), Some(format!("{name} {off}").as_str()));
        }
        let map = regmap::RegMap::new(&p);
        for (reg, field) in [
            ("CTRL", "MODE"),
            ("CTRL", "Z_MODE"),
            ("STATUS", "VALID"),
            ("STATUS", "FAULT_ILLEGAL"),
            ("IRQ_STATUS", "SPEED"),
        ] {
            let f = map.reg(reg).field(field);
            assert_eq!(
                lines.next(),
                Some(format!("{reg}.{field} {} {}", f.mask(), f.lsb).as_str())
            );
        }
        let want = format!("speed {raw} {:.9}", raw as f64 / 65_536.0);
        assert_eq!(lines.next(), Some(want.as_str()));
        // Spot checks by hand.
        assert!(text.contains("SPEED_N3_LO 96\n") && text.contains("CTRL.MODE 3 0\n"));
    }
}

// ---------------------------------------------------------------------------------------
// The emitted files
// ---------------------------------------------------------------------------------------

#[test]
fn emitted_files_are_deterministic_and_carry_the_header() {
    let p = default_params();
    let a = hdl::emit::wb::emit_wb(&p);
    let names: Vec<&str> = a.iter().map(|(n, _)| *n).collect();
    assert_eq!(names, ["encspeed_wb.v", "encspeed_regs.h"]);
    let v = &a[0].1;
    assert!(v.starts_with(&format!(
        "// Command: {}\n// SPDX-License-Identifier: MIT OR Apache-2.0\n\
         // encspeed_wb.v: generated by encspeed",
        hdl::emit::regenerate_command(&p)
    )));
    let ports: Vec<&str> = golden::top::wb_top::wb_top_ports()
        .iter()
        .map(|p| p.name)
        .collect();
    let module = format!("module encspeed_wb({});", ports.join(","));
    assert!(v.contains(&module), "the ports are {module}");
    assert_eq!(a[1].1, regmap::c_header(&p));
    let b = hdl::emit::wb::emit_wb(&p);
    assert!(a == b, "emission is deterministic");
    // write_all writes exactly these files.
    let dir = work_dir("write_all");
    let paths = hdl::emit::wb::write_all(&p, &dir).unwrap();
    for ((name, text), path) in a.iter().zip(paths) {
        assert_eq!(path, dir.join(name));
        assert_eq!(&std::fs::read_to_string(path).unwrap(), text);
    }
}

#[test]
fn emitted_verilog_lints_clean_with_the_documented_waivers() {
    for p in [default_params(), small()] {
        tb::verilator::lint_wb(&hdl::emit::wb::emit_wb(&p)[0].1).unwrap();
    }
}

#[test]
fn emitted_verilog_synthesises_for_ice40_without_latches() {
    let dir = work_dir("yosys");
    let v = dir.join("encspeed_wb.v");
    std::fs::write(&v, &hdl::emit::wb::emit_wb(&default_params())[0].1).unwrap();
    let log = tools::yosys_synth_ice40(&dir, "encspeed_wb", "encspeed_wb.v").unwrap();
    let stat = &log[log.rfind("Printing statistics").unwrap_or(0)..];
    let count = |cell: &str| -> u64 {
        stat.lines()
            .filter_map(|l| {
                let mut w = l.split_whitespace();
                (w.next() == Some(cell)).then(|| w.next()?.parse::<u64>().ok())?
            })
            .next_back()
            .unwrap_or(0)
    };
    let luts = count("SB_LUT4");
    let ffs: u64 = stat
        .lines()
        .filter_map(|l| {
            let mut w = l.split_whitespace();
            let cell = w.next()?;
            (cell.starts_with("SB_DFF")).then(|| w.next()?.parse::<u64>().ok())?
        })
        .sum();
    assert!(luts > 0 && ffs > 0, "no logic synthesised:\n{stat}");
    std::fs::write(dir.join("stat.txt"), stat).unwrap();
    println!("encspeed_wb (default parameters), synth_ice40: {luts} SB_LUT4, {ffs} flip-flops");
}

// ---------------------------------------------------------------------------------------
// docs/registers.md
// ---------------------------------------------------------------------------------------

/// `docs/registers.md` is what `hdl::emit::wb::default_registers_markdown` writes. To
/// regenerate it: `ENCSPEED_REGENERATE_DOCS=1 cargo test --release -p encspeed-tb --test
/// wishbone_top registers_doc` (or the CLI's `generate`, once it writes it).
#[test]
fn registers_doc_is_up_to_date() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/registers.md");
    let want = hdl::emit::wb::default_registers_markdown();
    if std::env::var_os("ENCSPEED_REGENERATE_DOCS").is_some() {
        std::fs::write(&path, &want).unwrap();
    }
    let have = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        have == want,
        "docs/registers.md is stale: run `ENCSPEED_REGENERATE_DOCS=1 cargo test --release \
         -p encspeed-tb --test wishbone_top registers_doc` and commit it"
    );
}
