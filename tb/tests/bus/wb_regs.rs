// SPDX-License-Identifier: MIT OR Apache-2.0
//! `WbRegs` against its cycle model `golden::bus::wb_regs::WbRegsModel`, every cycle, on random
//! Wishbone transactions (reads and writes of mapped and unmapped offsets with random byte
//! lanes, W1C writes to `STATUS` and `IRQ_STATUS`, writes to `CTRL` that set and clear
//! `SAMPLED` and `HOLD` and pulse `TRIGGER`, LO-then-HI speed reads, idle cycles, resets,
//! and cycles of arbitrary bus signals), random `sample` strobes and random status inputs
//! (strobes, levels that rise and fall, values with corner cases):
//! - rust-hdl simulation (direct drive) = model: property tests at the widths of the
//!   default `Params`, at small widths (N = 8, F = 2, C = 4, FB = 1, G = 1) and at the widest
//!   (N = 32, F = 24, C = FB = G = 32);
//! - emitted Verilog in Icarus = model: one long replay per width set.
//!
//! The bus follows the classic protocol as a master would (request held through its ack
//! cycle, back-to-back requests when no idle op comes between), driven by the model's
//! `wb_ack_o` and busy state; the "chaos" cycles break the protocol on purpose. The status stream comes
//! from a seeded generator; proptest chooses the seed and the list of bus operations.

use crate::common;

use common::SplitMix;
use golden::bus::reg_file::WbBus;
use golden::bus::regmap::{self, MapParams, RegMap, LAYOUT, SPAN_BYTES, SPEEDS};
use golden::bus::wb_regs::{CoreStatus, WbRegsInputs, WbRegsModel, WbRegsOutputs};
use golden::params::{Params, Spec};
use hdl::{wb_regs_verilog, WbRegs};
use proptest::prelude::*;
use rust_hdl::prelude::*;

/// Call `$f::<N, S, C, FB, G>($args)` for the widths of `$map`.
macro_rules! with_widths {
    ($map:expr, $f:ident ( $($arg:expr),* )) => {{
        let mp = $map.params();
        match (
            mp.counter_bits,
            mp.speed_bits(),
            mp.position_bits,
            mp.filter_bits,
            mp.error_count_bits,
        ) {
            (24, 41, 32, 16, 16) => $f::<24, 41, 32, 16, 16>($($arg),*),
            (24, 41, 12, 8, 16) => $f::<24, 41, 12, 8, 16>($($arg),*),
            (8, 11, 4, 1, 1) => $f::<8, 11, 4, 1, 1>($($arg),*),
            (32, 57, 32, 32, 32) => $f::<32, 57, 32, 32, 32>($($arg),*),
            w => panic!("no WbRegs instance for widths {w:?}: add one to with_widths!"),
        }
    }};
}

fn default_map() -> RegMap {
    RegMap::new(&Params::new(Spec::default()).unwrap())
}

fn small_map() -> RegMap {
    RegMap::from_map_params(MapParams::for_widths(8, 2, 4, 1, 1))
}

fn wide_map() -> RegMap {
    RegMap::from_map_params(MapParams::for_widths(32, 24, 32, 32, 32))
}

// ---------------------------------------------------------------------------------------
// Stimulus
// ---------------------------------------------------------------------------------------

/// One bus operation of the master.
#[derive(Clone, Copy, Debug)]
enum Op {
    Read(u32),
    Write(u32, u32, u8),
    /// Read a speed's LO then its HI register, back to back.
    Pair(usize),
    Idle(u8),
    Reset(u8),
    /// One cycle of arbitrary bus signals.
    Chaos(WbBus),
}

fn address(rng: &mut SplitMix) -> u32 {
    let low = if rng.next().is_multiple_of(4) {
        (rng.next() % 4) as u32
    } else {
        0
    };
    match rng.next() % 8 {
        0 => (rng.next() % u64::from(SPAN_BYTES)) as u32,
        1 => regmap::STATUS | low,
        2 => regmap::IRQ_STATUS | low,
        3 => regmap::CTRL | low,
        _ => LAYOUT[(rng.next() % LAYOUT.len() as u64) as usize].1 | low,
    }
}

fn data(rng: &mut SplitMix) -> u32 {
    match rng.next() % 5 {
        0 => u32::MAX,
        1 => 1 << (rng.next() % 32),
        2 => (rng.next() % 256) as u32,
        _ => rng.next() as u32,
    }
}

/// The operation drawn from `x` (proptest draws `x`; the Icarus runs draw it from a
/// generator).
fn op(x: u64) -> Op {
    let rng = &mut SplitMix(x);
    let sel = |rng: &mut SplitMix| {
        if rng.next().is_multiple_of(2) {
            0xF
        } else {
            (rng.next() % 16) as u8
        }
    };
    match rng.next() % 100 {
        0..=34 => Op::Read(address(rng)),
        35..=64 => {
            let (a, d) = (address(rng), data(rng));
            Op::Write(a, d, sel(rng))
        }
        65..=71 => Op::Pair((rng.next() % 6) as usize),
        72..=85 => Op::Idle(1 + (rng.next() % 3) as u8),
        86..=87 => Op::Reset(1 + (rng.next() % 2) as u8),
        _ => Op::Chaos(WbBus {
            wb_cyc_i: !rng.next().is_multiple_of(4),
            wb_stb_i: !rng.next().is_multiple_of(4),
            wb_we_i: rng.next().is_multiple_of(2),
            wb_adr_i: address(rng),
            wb_dat_i: data(rng),
            wb_sel_i: (rng.next() % 16) as u8,
        }),
    }
}

/// A random value of `bits` bits, often a corner.
fn value(rng: &mut SplitMix, bits: u32) -> u64 {
    let max = if bits == 64 {
        u64::MAX
    } else {
        (1u64 << bits) - 1
    };
    let v = match rng.next() % 8 {
        0 => 0,
        1 => max,
        2 => 1,
        3 => max >> 1,       // largest positive speed
        4 => (max >> 1) + 1, // most negative speed
        5 => rng.next() % 16,
        6 => max - rng.next() % 16, // small negative speeds
        _ => rng.next(),
    };
    v & max
}

/// The next cycle's status: strobes in about one cycle in five, levels that flip now and
/// then (so that rising edges occur), values that change in about one cycle in four.
fn next_status(rng: &mut SplitMix, mp: &MapParams, s: &CoreStatus) -> CoreStatus {
    let mut n = *s;
    let mut strobe = || rng.next().is_multiple_of(5);
    n.index = strobe();
    n.update = strobe();
    n.speed_strobe = strobe();
    n.baseline_strobe = strobe();
    let mut flip = |b: &mut bool| {
        if rng.next().is_multiple_of(10) {
            *b = !*b;
        }
    };
    flip(&mut n.direction);
    flip(&mut n.valid);
    flip(&mut n.stalled);
    flip(&mut n.fault_illegal);
    flip(&mut n.fault_overspeed);
    flip(&mut n.fault_revolution);
    flip(&mut n.cfg_error);
    let mut change = |v: &mut u64, bits: u32| {
        if rng.next().is_multiple_of(4) {
            *v = value(rng, bits);
        }
    };
    change(&mut n.position, mp.position_bits);
    change(&mut n.z_latch, mp.position_bits);
    change(&mut n.nep, mp.counter_bits);
    change(&mut n.ndt, mp.counter_bits);
    let s_bits = mp.speed_bits();
    change(&mut n.speed_n1, s_bits);
    change(&mut n.speed_n2, s_bits);
    change(&mut n.speed_n3, s_bits);
    change(&mut n.speed_pc, s_bits);
    change(&mut n.speed_et, s_bits);
    change(&mut n.speed_mt, s_bits);
    change(&mut n.glitch_count, mp.error_count_bits);
    change(&mut n.illegal_count, mp.error_count_bits);
    change(&mut n.rev_error_count, mp.error_count_bits);
    n
}

/// Coverage of a trace, to check that the stimulus reaches what it is meant to.
#[derive(Debug, Default)]
struct Coverage {
    acks: usize,
    reads: usize,
    writes: usize,
    clears: usize,
    irqs: usize,
    back_to_back: usize,
    /// Snapshots taken (by `sample` or `CTRL.TRIGGER`).
    snapshots: usize,
    /// Reads executed while `CTRL.SAMPLED`.
    sampled_reads: usize,
}

type Trace = Vec<(WbRegsInputs, WbRegsOutputs)>;

/// A classic master and the status stream in front of the model, recording every cycle.
struct Tracer {
    model: WbRegsModel,
    rng: SplitMix,
    status: CoreStatus,
    out: Trace,
    snapshots: usize,
    sampled_reads: usize,
}

impl Tracer {
    fn cycle(&mut self, reset: bool, bus: WbBus) {
        let mp = self.model.map().params().clone();
        self.status = next_status(&mut self.rng, &mp, &self.status);
        let inp = WbRegsInputs {
            reset,
            sample: self.rng.next().is_multiple_of(6),
            bus,
            status: self.status,
        };
        let (count, sampled) = (self.model.snapshot().count, self.model.sampled());
        let o = self.model.step(&inp);
        self.snapshots += usize::from(self.model.snapshot().count != count && !reset);
        self.sampled_reads += usize::from(sampled && o.wb_ack_o && !inp.bus.wb_we_i);
        self.out.push((inp, o));
    }

    /// One access: the request is held until the slave's ack cycle and through it, as a
    /// classic master does (an access left in progress by a chaos cycle is waited out: the
    /// slave takes no request until it is idle).
    fn access(&mut self, we: bool, adr: u32, dat: u32, sel: u8) {
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: we,
            wb_adr_i: adr,
            wb_dat_i: dat,
            wb_sel_i: sel,
        };
        for _ in 0..2 {
            if self.model.busy() {
                self.cycle(false, bus);
            }
        }
        assert!(
            !self.model.busy(),
            "a chaos cycle's access lasts 2 more cycles at most"
        );
        // Taken at this edge, acknowledged from the next, held through the ack cycle.
        self.cycle(false, bus);
        self.cycle(false, bus);
        assert!(self.model.outputs().wb_ack_o, "ack after the second edge");
        self.cycle(false, bus);
    }
}

/// The inputs and the model's outputs, cycle by cycle, of `ops` with the status stream of
/// `seed`, from power-up (reset in the first cycle).
fn trace(map: &RegMap, seed: u64, ops: &[Op]) -> (Trace, Coverage) {
    let mut t = Tracer {
        model: WbRegsModel::from_map(map.clone()),
        rng: SplitMix(seed),
        status: CoreStatus::default(),
        out: Vec::new(),
        snapshots: 0,
        sampled_reads: 0,
    };
    let mut cov = Coverage::default();
    t.cycle(true, WbBus::default());
    let mut previous_was_access = false;
    for &o in ops {
        let is_access = matches!(o, Op::Read(_) | Op::Write(..) | Op::Pair(_));
        cov.back_to_back += usize::from(is_access && previous_was_access);
        previous_was_access = is_access;
        match o {
            Op::Read(a) => t.access(false, a, 0, 0),
            Op::Write(a, d, s) => t.access(true, a, d, s),
            Op::Pair(k) => {
                t.access(false, SPEEDS[k].0, 0, 0);
                t.access(false, SPEEDS[k].1, 0, 0);
            }
            Op::Idle(n) => (0..n).for_each(|_| t.cycle(false, WbBus::default())),
            Op::Reset(n) => (0..n).for_each(|_| t.cycle(true, WbBus::default())),
            Op::Chaos(bus) => t.cycle(false, bus),
        }
    }
    (cov.snapshots, cov.sampled_reads) = (t.snapshots, t.sampled_reads);
    let out = t.out;
    for (k, (i, o)) in out.iter().enumerate() {
        cov.acks += usize::from(o.wb_ack_o);
        cov.clears += usize::from(o.clear_faults);
        cov.irqs += usize::from(o.irq);
        // An access acknowledged from this edge (the bus held since its request edge).
        let was_acked = k > 0 && out[k - 1].1.wb_ack_o;
        if o.wb_ack_o && !was_acked && !i.reset {
            if i.bus.wb_we_i {
                cov.writes += 1;
            } else {
                cov.reads += 1;
            }
        }
    }
    (out, cov)
}

// ---------------------------------------------------------------------------------------
// rust-hdl = model
// ---------------------------------------------------------------------------------------

/// One rising edge of the rust-hdl block with `inp` applied; the outputs after it.
fn step<const N: usize, const S: usize, const C: usize, const FB: usize, const G: usize>(
    uut: &mut WbRegs<N, S, C, FB, G>,
    inp: &WbRegsInputs,
) -> WbRegsOutputs {
    let (b, s) = (&inp.bus, &inp.status);
    uut.reset.next = inp.reset;
    uut.sample.next = inp.sample;
    uut.wb_cyc_i.next = b.wb_cyc_i;
    uut.wb_stb_i.next = b.wb_stb_i;
    uut.wb_we_i.next = b.wb_we_i;
    uut.wb_adr_i.next = u64::from(b.wb_adr_i).into();
    uut.wb_dat_i.next = u64::from(b.wb_dat_i).into();
    uut.wb_sel_i.next = u64::from(b.wb_sel_i).into();
    uut.position.next = s.position.into();
    uut.z_latch.next = s.z_latch.into();
    uut.index.next = s.index;
    uut.direction.next = s.direction;
    uut.nep.next = s.nep.into();
    uut.ndt.next = s.ndt.into();
    uut.update.next = s.update;
    uut.speed_n1.next = s.speed_n1.into();
    uut.speed_n2.next = s.speed_n2.into();
    uut.speed_n3.next = s.speed_n3.into();
    uut.speed_strobe.next = s.speed_strobe;
    uut.speed_pc.next = s.speed_pc.into();
    uut.speed_et.next = s.speed_et.into();
    uut.speed_mt.next = s.speed_mt.into();
    uut.baseline_strobe.next = s.baseline_strobe;
    uut.valid.next = s.valid;
    uut.stalled.next = s.stalled;
    uut.fault_illegal.next = s.fault_illegal;
    uut.fault_overspeed.next = s.fault_overspeed;
    uut.fault_revolution.next = s.fault_revolution;
    uut.cfg_error.next = s.cfg_error;
    uut.glitch_count.next = s.glitch_count.into();
    uut.illegal_count.next = s.illegal_count.into();
    uut.rev_error_count.next = s.rev_error_count.into();
    common::edge(uut, |u, c| u.clock.next = Clock { clk: c });
    WbRegsOutputs {
        wb_ack_o: uut.wb_ack_o.val(),
        wb_dat_o: uut.wb_dat_o.val().to_u64() as u32,
        irq: uut.irq.val(),
        cfg_dt: uut.cfg_dt.val().to_u64(),
        cfg_timeout: uut.cfg_timeout.val().to_u64(),
        cfg_filter: uut.cfg_filter.val().to_u64(),
        cfg_mode: uut.cfg_mode.val().to_u64() as u8,
        cfg_z_mode: uut.cfg_z_mode.val().to_u64() as u8,
        clear_faults: uut.clear_faults.val(),
    }
}

/// The rust-hdl block against the model's trace; fails at the first cycle that differs.
fn compare<const N: usize, const S: usize, const C: usize, const FB: usize, const G: usize>(
    map: &RegMap,
    cycles: &[(WbRegsInputs, WbRegsOutputs)],
) -> Result<(), TestCaseError> {
    let mut uut = WbRegs::<N, S, C, FB, G>::from_map(map);
    uut.connect_all();
    for (k, (inp, want)) in cycles.iter().enumerate() {
        let got = step(&mut uut, inp);
        prop_assert_eq!(
            got,
            *want,
            "widths {:?}, edge {}, {:?}",
            (N, S, C, FB, G),
            k,
            inp
        );
    }
    Ok(())
}

fn check(map: &RegMap, seed: u64, ops: &[u64]) -> Result<(), TestCaseError> {
    let ops: Vec<Op> = ops.iter().map(|&x| op(x)).collect();
    let (cycles, _) = trace(map, seed, &ops);
    with_widths!(map, compare(map, &cycles))
}

fn ops(max: usize) -> impl Strategy<Value = Vec<u64>> {
    prop::collection::vec(any::<u64>(), 10..max)
}

proptest! {
    #![proptest_config(common::proptest_config(64))]

    #[test]
    fn rust_hdl_equals_model_default_params(seed in any::<u64>(), ops in ops(400)) {
        check(&default_map(), seed, &ops)?;
    }

    #[test]
    fn rust_hdl_equals_model_small_widths(seed in any::<u64>(), ops in ops(400)) {
        check(&small_map(), seed, &ops)?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(16))]

    #[test]
    fn rust_hdl_equals_model_widest(seed in any::<u64>(), ops in ops(400)) {
        check(&wide_map(), seed, &ops)?;
    }
}

/// The hardware on its own, by hand: the ID, the speed format, and a coherent 57-bit
/// negative speed read as LO then HI while the input changes between the two reads.
#[test]
fn hardware_reads_id_format_and_a_coherent_speed_by_hand() {
    let map = wide_map();
    let mut uut = WbRegs::<32, 57, 32, 32, 32>::from_map(&map);
    uut.connect_all();
    let speed = (-(1i64 << 55) + 3) as u64 & ((1 << 57) - 1);
    let mut st = CoreStatus {
        speed_n3: speed,
        ..Default::default()
    };
    let read = |uut: &mut WbRegs<32, 57, 32, 32, 32>, adr: u32, st: &CoreStatus| {
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_adr_i: adr,
            ..Default::default()
        };
        let inp = WbRegsInputs {
            reset: false,
            sample: false,
            bus,
            status: *st,
        };
        assert!(!step(uut, &inp).wb_ack_o, "executed, not yet acknowledged");
        let o = step(uut, &inp);
        assert!(o.wb_ack_o);
        let held = step(uut, &inp);
        assert!(!held.wb_ack_o && held.wb_dat_o == 0, "one ack per access");
        o.wb_dat_o
    };
    assert_eq!(read(&mut uut, regmap::ID, &st), 0x454E_4353);
    // F = 24 in PARAM0[15:8], S = 57 in [23:16].
    assert_eq!(
        (read(&mut uut, regmap::PARAM0, &st) >> 8) & 0xFFFF,
        57 << 8 | 24
    );
    let lo = read(&mut uut, regmap::SPEED_N3_LO, &st);
    st.speed_n3 = 5;
    let hi = read(&mut uut, regmap::SPEED_N3_HI, &st);
    assert_eq!(
        ((u64::from(hi) << 32) | u64::from(lo)) as i64,
        -(1i64 << 55) + 3
    );
}

// ---------------------------------------------------------------------------------------
// Icarus = model
// ---------------------------------------------------------------------------------------

fn icarus<const N: usize, const S: usize, const C: usize, const FB: usize, const G: usize>(
    map: &RegMap,
    name: &str,
    seed: u64,
    n_ops: usize,
) {
    let mut rng = SplitMix(seed);
    let ops: Vec<Op> = (0..n_ops).map(|_| op(rng.next())).collect();
    let (cycles, cov) = trace(map, seed ^ 0x5a5a, &ops);
    assert!(
        cov.reads > n_ops / 4
            && cov.writes > n_ops / 5
            && cov.clears > 10
            && cov.irqs > 100
            && cov.back_to_back > n_ops / 4
            && cov.snapshots > 100
            && cov.sampled_reads > 100,
        "stimulus coverage {cov:?}"
    );
    let b = |v: bool| u8::from(v);
    let mut vectors = String::new();
    for (i, o) in &cycles {
        let (bus, s) = (&i.bus, &i.status);
        let fields: Vec<String> = vec![
            format!("{:x}", b(i.reset)),
            format!("{:x}", b(bus.wb_cyc_i)),
            format!("{:x}", b(bus.wb_stb_i)),
            format!("{:x}", b(bus.wb_we_i)),
            format!("{:x}", bus.wb_adr_i),
            format!("{:x}", bus.wb_dat_i),
            format!("{:x}", bus.wb_sel_i),
            format!("{:x}", b(i.sample)),
            format!("{:x}", s.position),
            format!("{:x}", s.z_latch),
            format!("{:x}", b(s.index)),
            format!("{:x}", b(s.direction)),
            format!("{:x}", s.nep),
            format!("{:x}", s.ndt),
            format!("{:x}", b(s.update)),
            format!("{:x}", s.speed_n1),
            format!("{:x}", s.speed_n2),
            format!("{:x}", s.speed_n3),
            format!("{:x}", b(s.speed_strobe)),
            format!("{:x}", s.speed_pc),
            format!("{:x}", s.speed_et),
            format!("{:x}", s.speed_mt),
            format!("{:x}", b(s.baseline_strobe)),
            format!("{:x}", b(s.valid)),
            format!("{:x}", b(s.stalled)),
            format!("{:x}", b(s.fault_illegal)),
            format!("{:x}", b(s.fault_overspeed)),
            format!("{:x}", b(s.fault_revolution)),
            format!("{:x}", b(s.cfg_error)),
            format!("{:x}", s.glitch_count),
            format!("{:x}", s.illegal_count),
            format!("{:x}", s.rev_error_count),
            format!("{:x}", o.wb_dat_o),
            format!("{:x}", b(o.wb_ack_o)),
            format!("{:x}", b(o.irq)),
            format!("{:x}", o.cfg_dt),
            format!("{:x}", o.cfg_timeout),
            format!("{:x}", o.cfg_filter),
            format!("{:x}", o.cfg_mode),
            format!("{:x}", o.cfg_z_mode),
            format!("{:x}", b(o.clear_faults)),
        ];
        vectors += &fields.join(" ");
        vectors.push('\n');
    }
    let tb = common::replay_bench(
        "wb_regs",
        &[
            ("reset", 1),
            ("wb_cyc_i", 1),
            ("wb_stb_i", 1),
            ("wb_we_i", 1),
            ("wb_adr_i", regmap::ADDR_BITS),
            ("wb_dat_i", 32),
            ("wb_sel_i", 4),
            ("sample", 1),
            ("position", C),
            ("z_latch", C),
            ("index", 1),
            ("direction", 1),
            ("nep", N),
            ("ndt", N),
            ("update", 1),
            ("speed_n1", S),
            ("speed_n2", S),
            ("speed_n3", S),
            ("speed_strobe", 1),
            ("speed_pc", S),
            ("speed_et", S),
            ("speed_mt", S),
            ("baseline_strobe", 1),
            ("valid", 1),
            ("stalled", 1),
            ("fault_illegal", 1),
            ("fault_overspeed", 1),
            ("fault_revolution", 1),
            ("cfg_error", 1),
            ("glitch_count", G),
            ("illegal_count", G),
            ("rev_error_count", G),
        ],
        &[
            ("wb_dat_o", 32),
            ("wb_ack_o", 1),
            ("irq", 1),
            ("cfg_dt", N),
            ("cfg_timeout", N),
            ("cfg_filter", FB),
            ("cfg_mode", 2),
            ("cfg_z_mode", 2),
            ("clear_faults", 1),
        ],
        "wb_ack_o",
    );
    common::replay(
        "wb_regs",
        name,
        "wb_regs",
        &wb_regs_verilog::<N, S, C, FB, G>(map, "wb_regs"),
        &tb,
        &vectors,
        cov.acks,
    );
}

#[test]
fn emitted_verilog_in_icarus_equals_model_default_params() {
    let map = default_map();
    with_widths!(map, icarus(&map, "icarus_default", 0x5eed_0001, 12_000));
}

#[test]
fn emitted_verilog_in_icarus_equals_model_small_widths() {
    let map = small_map();
    with_widths!(map, icarus(&map, "icarus_small", 0x5eed_0002, 12_000));
}

#[test]
fn emitted_verilog_in_icarus_equals_model_widest() {
    let map = wide_map();
    with_widths!(map, icarus(&map, "icarus_wide", 0x5eed_0003, 6_000));
}
