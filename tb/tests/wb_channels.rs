// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_wb` generated with several encoder channels (`--channels`):
//! - hand-counted: three channels in x4, channel 1 moved 37 steps forward, channel 2 11
//!   steps back, channel 0 still; each window's `POSITION` reads its own channel's count
//!   (0, 37, 4·100 − 11), the window above the last channel reads 0 and is acknowledged,
//!   a `CFG_DT` written in one window reads back there only, and `irq` has the bit of the
//!   channel whose interrupt was enabled; on the cycle model, the rust-hdl block and the
//!   emitted Verilog in Verilator alike;
//! - the cycle model `golden::top::wb_channels::WbChannelsModel` = the rust-hdl block
//!   `hdl::EncspeedWbChannels` = the emitted Verilog in Verilator, every cycle, on random
//!   programs: each channel's encoder moving at its own rate and direction while a master
//!   writes and reads random registers of random windows (the empty one included), with
//!   `sample` strobes and a reset;
//! - the C header's channel macros compiled by gcc; the emitted Verilog lints clean in
//!   Verilator with the shipped waivers for 2, 3 and 8 channels.

use golden::bus::reg_file::WbBus;
use golden::bus::regmap::{self, LAYOUT, SPAN_BYTES};
use golden::params::{Params, Spec};
use golden::top::wb_channels::{
    channel_base, wb_channels_ports, WbChannelsInputs, WbChannelsModel, WbChannelsOutputs,
};
use golden::top::wb_top::TOP_MODULE;
use hdl::sim::wb_channels_sim::{build_wb_channels, WbChannelsSim};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use std::process::Command;
use tb::verilator::Simulator;

/// Small parameters (12-bit counters, dt = 200 cycles, 100 lines) with `channels` channels.
fn params(channels: u32) -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: 200,
        counter_bits: 12,
        timeout_s: 20.0 * 200.0 / 1e6,
        channels,
        ..Spec::default()
    })
    .unwrap()
}

fn offset(name: &str) -> u32 {
    regmap::offset(name).unwrap()
}

/// The emitted Verilog of `p` in Verilator.
fn verilated(p: &Params) -> Simulator<WbChannelsInputs, WbChannelsOutputs> {
    let v = &hdl::emit::wb::emit_wb(p)[0].1;
    Simulator::compile(
        v,
        TOP_MODULE,
        &wb_channels_ports(p.channels()),
        &hdl::Top::Wb.waivers(),
        None,
    )
    .unwrap()
}

/// One channel's encoder: a quadrature step every `interval` cycles (0: still), forward =
/// A leads B: (A, B) = 00, 10, 11, 01; Z high where the step count is 0 mod 4·lines.
#[derive(Clone, Copy, Debug, Default)]
struct Motion {
    interval: u32,
    forward: bool,
    /// Steps still to make (u32::MAX: for ever).
    left: u32,
    acc: u32,
    pos: i64,
}

impl Motion {
    fn ab(&self) -> (bool, bool) {
        match self.pos.rem_euclid(4) {
            0 => (false, false),
            1 => (true, false),
            2 => (true, true),
            _ => (false, true),
        }
    }

    fn advance(&mut self) {
        if self.interval == 0 || self.left == 0 {
            return;
        }
        self.acc += 1;
        if self.acc >= self.interval {
            self.acc = 0;
            self.pos += if self.forward { 1 } else { -1 };
            self.left = self.left.saturating_sub(1);
        }
    }
}

/// The model and the rust-hdl block stepped together, every input and model output kept
/// for the Verilator run.
struct Bench {
    model: WbChannelsModel,
    hdl: Box<dyn WbChannelsSim>,
    motions: Vec<Motion>,
    lines: i64,
    inputs: Vec<WbChannelsInputs>,
    outputs: Vec<WbChannelsOutputs>,
}

impl Bench {
    fn new(p: &Params) -> Bench {
        Bench {
            model: WbChannelsModel::new(p),
            hdl: build_wb_channels(p),
            motions: vec![Motion::default(); p.channels() as usize],
            lines: i64::from(p.lines()),
            inputs: Vec::new(),
            outputs: Vec::new(),
        }
    }

    /// One edge with the encoders where their motions stand and `bus`, `reset`, `sample`.
    fn step(&mut self, bus: WbBus, reset: bool, sample: bool) -> WbChannelsOutputs {
        let mut inp = WbChannelsInputs {
            reset,
            sample,
            bus,
            ..Default::default()
        };
        for (c, m) in self.motions.iter_mut().enumerate() {
            let (a, b) = m.ab();
            inp.enc_a |= u8::from(a) << c;
            inp.enc_b |= u8::from(b) << c;
            inp.enc_z |= u8::from(m.pos.rem_euclid(4 * self.lines) == 0) << c;
            m.advance();
        }
        let want = self.model.step(&inp);
        let got = self.hdl.step(&inp);
        assert_eq!(
            got,
            want,
            "rust-hdl vs model at cycle {}",
            self.inputs.len()
        );
        self.inputs.push(inp);
        self.outputs.push(want);
        want
    }

    fn idle(&mut self, cycles: u32) {
        for _ in 0..cycles {
            self.step(WbBus::default(), false, false);
        }
    }

    /// One access held until `wb_ack_o` (then one idle cycle); the read data and the
    /// cycles from the request to the ack.
    fn access(&mut self, we: bool, adr: u32, dat: u32, sel: u8) -> (u32, u32) {
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: we,
            wb_adr_i: adr,
            wb_dat_i: dat,
            wb_sel_i: sel,
        };
        for cycles in 1..=8 {
            let o = self.step(bus, false, false);
            if o.wb_ack_o {
                self.idle(1);
                return (o.wb_dat_o, cycles);
            }
        }
        panic!("no acknowledge of 0x{adr:X}");
    }

    fn read(&mut self, adr: u32) -> u32 {
        self.access(false, adr, 0, 0).0
    }

    fn write(&mut self, adr: u32, dat: u32) {
        self.access(true, adr, dat, 0xF);
    }

    /// The whole run through the emitted Verilog: every cycle's outputs equal the model's.
    fn check_verilog(&self, sim: &Simulator<WbChannelsInputs, WbChannelsOutputs>) {
        let got = sim.run(&self.inputs, None).unwrap();
        for (k, (g, w)) in got.iter().zip(&self.outputs).enumerate() {
            assert_eq!(g, w, "Verilator vs model at cycle {k}");
        }
    }
}

#[test]
fn each_window_is_its_own_channel_by_hand() {
    let p = params(3);
    let mut b = Bench::new(&p);
    b.step(WbBus::default(), true, false);
    b.idle(20);
    // x4 (CTRL.MODE = 2) in every channel: the position counts quadrature steps.
    for c in 0..3 {
        b.write(channel_base(c) + offset("CTRL"), 2);
    }
    // CFG_DT of channel 2 only; the enable of the SPEED interrupt in channel 1 only.
    b.write(channel_base(2) + offset("CFG_DT"), 321);
    let speed_irq = regmap::RegMap::new(&p).mask("IRQ_STATUS", "SPEED");
    b.write(channel_base(1) + offset("IRQ_ENABLE"), speed_irq);
    b.idle(30);
    b.motions[1] = Motion {
        interval: 20,
        forward: true,
        left: 37,
        ..Default::default()
    };
    b.motions[2] = Motion {
        interval: 13,
        forward: false,
        left: 11,
        ..Default::default()
    };
    b.idle(37 * 20 + 400);
    let positions: Vec<u32> = (0..3)
        .map(|c| b.read(channel_base(c) + offset("POSITION")))
        .collect();
    assert_eq!(positions, [0, 37, 400 - 11]);
    let dts: Vec<u32> = (0..3)
        .map(|c| b.read(channel_base(c) + offset("CFG_DT")))
        .collect();
    assert_eq!(dts, [0, 0, 321]);
    // Every window answers its ID in three cycles (request, read stage, ack); the window
    // above the last channel answers 0 with the same timing.
    for c in 0..3 {
        assert_eq!(
            b.access(false, channel_base(c) + offset("ID"), 0, 0),
            (regmap::ID_MAGIC, 2)
        );
    }
    assert_eq!(
        b.access(false, channel_base(3) + offset("ID"), 0, 0),
        (0, 2)
    );
    // A write there changes nothing anywhere.
    b.write(channel_base(3) + offset("CFG_DT"), 99);
    let dts: Vec<u32> = (0..3)
        .map(|c| b.read(channel_base(c) + offset("CFG_DT")))
        .collect();
    assert_eq!(dts, [0, 0, 321]);
    // Channel 1 moved, so it published speeds: its SPEED interrupt is the only one.
    assert_eq!(b.outputs.last().unwrap().irq, 0b010);
    b.check_verilog(&verilated(&p));
}

/// One operation of the random master.
#[derive(Clone, Copy, Debug)]
enum Op {
    Read {
        window: u32,
        offset: u32,
    },
    Write {
        window: u32,
        offset: u32,
        dat: u32,
        sel: u8,
    },
    Sample,
    Idle(u32),
}

fn op(windows: u32) -> impl Strategy<Value = Op> {
    // The registers that change with the motion most often, any register, any word.
    let live = [
        "POSITION",
        "NEP",
        "NDT",
        "SPEED_N3_LO",
        "SPEED_MT_LO",
        "STATUS",
        "IRQ_STATUS",
    ];
    let offset = prop_oneof![
        4 => (0..live.len()).prop_map(move |k| offset_of(live[k])),
        4 => (0..LAYOUT.len()).prop_map(|k| LAYOUT[k].1),
        1 => (0..SPAN_BYTES / 4).prop_map(|w| 4 * w),
    ];
    let written = prop_oneof![
        Just(offset_of("CTRL")),
        Just(offset_of("CFG_DT")),
        Just(offset_of("IRQ_ENABLE")),
        Just(offset_of("IRQ_STATUS")),
        Just(offset_of("STATUS")),
    ];
    let dat = prop_oneof![0u32..4, 0u32..0x800, any::<u32>()];
    prop_oneof![
        6 => (0..windows, offset).prop_map(|(window, offset)| Op::Read { window, offset }),
        4 => (0..windows, written, dat, prop_oneof![Just(0xFu8), 0u8..16])
            .prop_map(|(window, offset, dat, sel)| Op::Write { window, offset, dat, sel }),
        1 => Just(Op::Sample),
        3 => (20u32..500).prop_map(Op::Idle),
    ]
}

fn offset_of(name: &str) -> u32 {
    regmap::offset(name).unwrap()
}

/// Per channel: cycles per step (0: still) and direction.
fn motions(channels: usize) -> impl Strategy<Value = Vec<(u32, bool)>> {
    prop::collection::vec(
        (prop_oneof![1 => Just(0u32), 3 => 2u32..60], any::<bool>()),
        channels,
    )
}

#[test]
fn model_rust_hdl_and_verilator_agree_cycle_for_cycle() {
    for channels in [3u32, 2] {
        let p = params(channels);
        let sim = verilated(&p);
        let windows = 1 << golden::top::wb_channels::channel_bits(channels);
        let mut runner = TestRunner::new(Config {
            cases: 4,
            failure_persistence: None,
            ..Config::default()
        });
        runner
            .run(
                &(
                    motions(channels as usize),
                    prop::collection::vec(0u32..3, channels as usize),
                    prop::collection::vec(op(windows), 30..80),
                    0usize..80,
                ),
                |(moves, modes, ops, reset_at)| {
                    let mut b = Bench::new(&p);
                    b.step(WbBus::default(), true, false);
                    // Every interrupt enabled, each channel in its own decoding mode.
                    for (c, mode) in modes.iter().enumerate() {
                        b.write(channel_base(c as u32) + offset("IRQ_ENABLE"), u32::MAX);
                        b.write(channel_base(c as u32) + offset("CTRL"), *mode);
                    }
                    for (m, (interval, forward)) in b.motions.iter_mut().zip(&moves) {
                        *m = Motion {
                            interval: *interval,
                            forward: *forward,
                            left: u32::MAX,
                            ..Default::default()
                        };
                    }
                    for (k, o) in ops.iter().enumerate() {
                        // One reset in the middle of most programs.
                        if k == reset_at {
                            b.step(WbBus::default(), true, false);
                        }
                        let base = |w: u32| w * SPAN_BYTES;
                        match *o {
                            Op::Read { window, offset } => {
                                b.read(base(window) + offset);
                            }
                            Op::Write {
                                window,
                                offset,
                                dat,
                                sel,
                            } => {
                                b.access(true, base(window) + offset, dat, sel);
                            }
                            Op::Sample => {
                                b.step(WbBus::default(), false, true);
                            }
                            Op::Idle(n) => b.idle(n),
                        }
                    }
                    b.check_verilog(&sim);
                    Ok(())
                },
            )
            .unwrap();
    }
}

#[test]
fn the_c_header_gives_each_channels_base() {
    let p = params(5);
    let header = golden::bus::regmap::c_header(&p);
    let dir = tools::work_dir("wb_channels", "c_header").unwrap();
    std::fs::write(dir.join("encspeed_regs.h"), &header).unwrap();
    let c = "#include <stdio.h>\n#include \"encspeed_regs.h\"\n\
             int main(void) {\n\
             \tprintf(\"%u %u %u\\n\", ENCSPEED_CHANNELS, ENCSPEED_CHANNEL_ADDR_BITS, ENCSPEED_CHANNEL_STRIDE);\n\
             \tprintf(\"%u %u\\n\", ENCSPEED_CHANNEL_BASE(4) + ENCSPEED_POSITION_OFFSET, ENCSPEED_CH3_BASE);\n\
             \treturn 0;\n}\n";
    std::fs::write(dir.join("bases.c"), c).unwrap();
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
            .args(["-o", "bases", "bases.c"]),
        "gcc",
    )
    .unwrap();
    let out = tools::run(&mut Command::new(dir.join("bases")), "bases").unwrap();
    // 5 channels: 3 channel bits above the 8-bit window, 11-bit address; channel 4's
    // POSITION at 4 * 256 + its offset in the map.
    assert_eq!(
        out,
        format!("5 11 256\n{} 768\n", 1024 + offset("POSITION"))
    );
}

#[test]
fn several_channel_tops_lint_clean_with_the_shipped_waivers() {
    for channels in [2u32, 3, 8] {
        let p = Params::new(Spec {
            channels,
            ..Spec::default()
        })
        .unwrap();
        let v = &hdl::emit::wb::emit_wb(&p)[0].1;
        tb::verilator::lint_top(v, TOP_MODULE, &hdl::Top::Wb.waivers())
            .unwrap_or_else(|e| panic!("{channels} channels: {e}"));
    }
}
