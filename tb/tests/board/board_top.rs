// SPDX-License-Identifier: MIT OR Apache-2.0
//! The board top (`EncspeedBoard`: `encspeed_wb` behind the UART bridge, a power-on reset,
//! LEDs) as the host sees it: bytes in on `rx`, register values out on `tx`, while an
//! encoder turns. The golden side is `golden::board::protocol` (the commands in the
//! received bytes) driving the golden register model `WbTopModel` as the bridge's
//! Wishbone master does, at the bridge's documented latency (docs/uart-bridge.md): a
//! request reaches the slave at the edge s + 2 + ⌊D/2⌋ + 9·D + 2 after the start edge s of
//! the command's last byte, stays there for the edge after its acknowledge, and the
//! response's start bit is on `tx` 2 edges after that. Asserted: every response byte,
//! the start edge of every response, and the LEDs on every cycle; known answers computed
//! by hand (the ID magic, the board clock, the default dt of 1 ms at 12 MHz); the emitted
//! Verilog in Verilator gives the same outputs as rust-hdl on every cycle, and the
//! shipped `generated/encspeed_board_*.v` is that Verilog.

use golden::board::boards::{board_ports, Board, BoardInputs, BoardOutputs};
use golden::board::protocol::{Command, Parser, Response};
use golden::board::uart::{decode, line_levels, LineFrame, RxEvent};
use golden::bus::reg_file::WbBus;
use golden::bus::regmap;
use golden::params::{Params, Spec};
use golden::top::wb_top::{WbTopInputs, WbTopModel};
use hdl::build_board;
use tb::verilator::Simulator;

/// Edges with the power-on reset high: `running` rises after edge 16.
const RESET_EDGES: usize = 17;

/// One host step: a command, sent after `idle` idle cycles, then the line idles until the
/// response is surely over.
struct Step {
    cmd: Command,
    idle: u32,
}

/// The stimulus of a run: the `rx` line of `steps` (stop-and-wait) and an encoder that
/// makes one quadrature step every `period` cycles from cycle `turn_from` on, forward.
fn stimulus(d: u32, steps: &[Step], period: usize, turn_from: usize) -> Vec<BoardInputs> {
    let answer = 4 * (10 * d as usize + 4) + 2 * d as usize + 16;
    let mut line: Vec<bool> = vec![true; 40];
    for s in steps {
        let frames: Vec<LineFrame> = s
            .cmd
            .encode()
            .iter()
            .enumerate()
            .map(|(k, &byte)| LineFrame {
                idle_cycles: if k == 0 { s.idle } else { 1 + k as u32 % 3 },
                byte,
                stop: true,
            })
            .collect();
        line.extend(line_levels(d, &frames));
        line.extend(std::iter::repeat_n(true, answer));
    }
    line.iter()
        .enumerate()
        .map(|(c, &rx)| {
            let steps = c.saturating_sub(turn_from) / period * usize::from(c >= turn_from);
            // Quadrature state of `steps` forward steps: 00 → 10 → 11 → 01.
            let (a, b) = [(false, false), (true, false), (true, true), (false, true)][steps % 4];
            BoardInputs {
                rx,
                enc_a: a,
                enc_b: b,
                // One state wide, once per revolution (4096 steps at 1024 lines).
                enc_z: steps % 4096 == 2,
            }
        })
        .collect()
}

/// The golden board: the commands in the `rx` line, executed on `WbTopModel` at the
/// bridge's latency. Returns the LEDs after every edge, and for every command its
/// response bytes and the edge after which the response's start bit is on `tx`.
struct GoldenRun {
    leds: Vec<u8>,
    responses: Vec<(Command, Vec<u8>, usize)>,
}

fn golden(p: &Params, d: u32, inputs: &[BoardInputs]) -> GoldenRun {
    let rx: Vec<bool> = inputs.iter().map(|i| i.rx).collect();
    let mut parser = Parser::new();
    // (edge at which the slave first sees the request, command)
    let mut requests: Vec<(usize, Command)> = Vec::new();
    for r in decode(d, &rx) {
        if let Some(cmd) = parser.push(r.event) {
            let d = d as usize;
            requests.push((r.start + 2 + d / 2 + 9 * d + 2, cmd));
        }
    }
    let mut model = WbTopModel::new(p);
    let mut leds = Vec::with_capacity(inputs.len());
    let mut responses = Vec::new();
    let mut next = requests.iter().peekable();
    // The request on the bus, and whether its acknowledge was seen (one more edge).
    let mut active: Option<(Command, bool)> = None;
    let mut irq = false;
    for (k, i) in inputs.iter().enumerate() {
        if active.is_none() && next.peek().is_some_and(|(at, _)| *at == k) {
            active = Some((next.next().unwrap().1, false));
        }
        let bus = match active {
            None => WbBus::default(),
            Some((Command::Read { addr }, _)) => WbBus {
                wb_cyc_i: true,
                wb_stb_i: true,
                wb_adr_i: u32::from(addr),
                wb_sel_i: 0xF,
                ..WbBus::default()
            },
            Some((Command::Write { addr, data, sel }, _)) => WbBus {
                wb_cyc_i: true,
                wb_stb_i: true,
                wb_we_i: true,
                wb_adr_i: u32::from(addr),
                wb_dat_i: data,
                wb_sel_i: sel & 0xF,
            },
        };
        // LEDs after edge k: heartbeat = bit 23 of the edges before, irq after edge k − 1,
        // A and B of edge k.
        let beat = (k >> 23) & 1 == 1;
        leds.push(
            u8::from(beat) | u8::from(irq) << 1 | u8::from(i.enc_a) << 2 | u8::from(i.enc_b) << 3,
        );
        let o = model.step(&WbTopInputs {
            reset: k < RESET_EDGES,
            enc_a: i.enc_a,
            enc_b: i.enc_b,
            enc_z: i.enc_z,
            sample: false,
            bus,
        });
        irq = o.irq;
        active = match active {
            Some((_, true)) => None,
            Some((cmd, false)) if o.wb_ack_o => {
                let bytes = match cmd {
                    Command::Read { .. } => Response::Data(o.wb_dat_o).encode(),
                    Command::Write { .. } => Response::WriteAck.encode(),
                };
                // The bridge samples the acknowledge at edge k + 1; the start bit is on
                // `tx` after edge k + 1 + 2.
                responses.push((cmd, bytes, k + 3));
                Some((cmd, true))
            }
            other => other,
        };
    }
    assert!(next.next().is_none(), "every command was executed");
    GoldenRun { leds, responses }
}

/// Every check of the module docs on `outputs` of the run on `inputs`.
fn check(p: &Params, d: u32, inputs: &[BoardInputs], outputs: &[BoardOutputs]) -> GoldenRun {
    let g = golden(p, d, inputs);
    let tx: Vec<bool> = outputs.iter().map(|o| o.tx).collect();
    let sent = decode(d, &tx);
    let mut sent = sent.iter();
    for (cmd, bytes, start) in &g.responses {
        for (k, &b) in bytes.iter().enumerate() {
            let s = sent
                .next()
                .unwrap_or_else(|| panic!("{cmd:?}: byte {k} missing"));
            assert_eq!(s.event, RxEvent::Byte(b), "{cmd:?}: byte {k}");
            if k == 0 {
                assert_eq!(s.start, *start, "{cmd:?}: response start edge");
            }
        }
    }
    assert!(sent.next().is_none(), "no byte beyond the responses");
    let leds: Vec<u8> = outputs.iter().map(|o| o.led).collect();
    if let Some(c) = (0..leds.len()).find(|&c| leds[c] != g.leds[c]) {
        panic!(
            "LEDs after edge {c}: {:#06b}, golden {:#06b}",
            leds[c], g.leds[c]
        );
    }
    g
}

/// The host session of the bench: the identification registers, a smaller dt written and
/// read back, then the position, speed and status while the encoder turns.
fn session() -> Vec<Step> {
    let read = |addr: u32| Step {
        cmd: Command::Read { addr: addr as u8 },
        idle: 3,
    };
    vec![
        read(regmap::ID),
        read(regmap::CLOCK_HZ),
        read(regmap::DT_DEFAULT),
        Step {
            cmd: Command::Write {
                addr: regmap::CFG_DT as u8,
                data: 600,
                sel: 0xF,
            },
            idle: 7,
        },
        read(regmap::CFG_DT),
        read(regmap::POSITION),
        read(regmap::NEP),
        read(regmap::SPEED_N3_LO),
        read(regmap::SPEED_N3_HI),
        read(regmap::STATUS),
        read(regmap::POSITION),
    ]
}

fn board_params(board: Board) -> Params {
    board.params(&Spec::default()).unwrap()
}

/// The rust-hdl board top on `inputs`: the outputs after every edge.
fn run_rust_hdl(board: Board, inputs: &[BoardInputs]) -> Vec<BoardOutputs> {
    let mut sim = build_board(board, &board_params(board));
    inputs.iter().map(|i| sim.step(i)).collect()
}

/// The session on the iCE40-HX8K breakout top in rust-hdl, against the golden board, with
/// the known answers: ID "ENCS", CLOCK_HZ 12 000 000, DT_DEFAULT 12 000 (1 ms at 12 MHz),
/// CFG_DT 600 after the write, and a position that follows the encoder.
#[test]
fn rust_hdl_board_equals_golden_with_known_answers() {
    let board = Board::Hx8kBreakout;
    let p = board_params(board);
    let d = board.uart().divisor();
    let period = 23;
    let inputs = stimulus(d, &session(), period, 9_000);
    let outputs = run_rust_hdl(board, &inputs);
    let g = check(&p, d, &inputs, &outputs);
    let words: Vec<u32> = g
        .responses
        .iter()
        .filter(|(c, _, _)| matches!(c, Command::Read { .. }))
        .map(|(_, b, _)| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    // By hand: "ENCS" as a big-endian word; 12 MHz; 12e6 · 1 ms.
    assert_eq!(words[0], 0x454E_4353);
    assert_eq!(words[1], 12_000_000);
    assert_eq!(words[2], 12_000);
    assert_eq!(words[3], 600);
    // The position a read returns (x1 after reset, `CTRL.MODE` = 0: one count per line,
    // four quadrature steps) is the lines made by the edge whose request it answers, three
    // edges before its response starts, less the input pipeline (synchroniser and filter:
    // a few cycles, under one step of 23 cycles).
    let (_, _, start) = g.responses[5];
    let lines_by = |edge: usize| ((edge - 9_000) / period / 4) as u32;
    let pos = words[4];
    let approx = lines_by(start - 3);
    assert!(
        pos.abs_diff(approx) <= 1,
        "position {pos}, about {approx} lines"
    );
    assert!(pos > 100, "the encoder moved the position: {pos}");
    assert!(
        words[9] > words[4],
        "the position grows while the encoder turns forward"
    );
}

/// The contents of `generated/<name>`.
fn shipped_file(name: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../generated")
        .join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The emitted board top in Verilator on the rust-hdl run's inputs: the same outputs on
/// every cycle; the shipped file is that Verilog; and it lints with the IP's waivers.
#[test]
fn verilator_equals_rust_hdl_and_the_shipped_file_is_current() {
    for board in Board::ALL {
        let p = board_params(board);
        let d = board.uart().divisor();
        let verilog = hdl::build_board(board, &p).verilog(&board.module());
        let shipped = shipped_file(&format!("{}.v", board.module()));
        assert!(
            shipped.ends_with(&verilog),
            "generated/{}.v is not the board top's Verilog: run `encspeed generate`",
            board.module()
        );
        let waivers = hdl::emit::waivers::board_waivers(&board.module());
        let sim: Simulator<BoardInputs, BoardOutputs> =
            Simulator::compile(&verilog, &board.module(), &board_ports(), &waivers, None).unwrap();
        let steps = [
            Step {
                cmd: Command::Read {
                    addr: regmap::LINES as u8,
                },
                idle: 5,
            },
            Step {
                cmd: Command::Write {
                    addr: regmap::CFG_DT as u8,
                    data: 450,
                    sel: 0x3,
                },
                idle: 2,
            },
            Step {
                cmd: Command::Read {
                    addr: regmap::SPEED_N3_LO as u8,
                },
                idle: 9,
            },
        ];
        let inputs = stimulus(d, &steps, 31, 2_000);
        let want = run_rust_hdl(board, &inputs);
        let got = sim.run(&inputs, None).unwrap();
        if let Some(c) = (0..got.len()).find(|&c| got[c] != want[c]) {
            panic!(
                "{}: Verilator and rust-hdl differ after edge {c}: {:?} vs {:?}",
                board.name(),
                got[c],
                want[c]
            );
        }
        let g = check(&p, d, &inputs, &got);
        let (_, lines, _) = &g.responses[0];
        assert_eq!(lines, &1024u32.to_le_bytes(), "LINES");
        // The shipped waivers make `verilator --lint-only -Wall` clean.
        let module = board.module();
        let vlt = shipped_file(&format!("{module}.vlt"));
        let dir = tools::work_dir("board_lint", &module).unwrap();
        let file = format!("{module}.v");
        let vlt_file = format!("{module}.vlt");
        tools::stage(
            &dir,
            &[
                (file.as_str(), shipped.as_str()),
                (vlt_file.as_str(), vlt.as_str()),
            ],
        )
        .unwrap();
        tools::verilator_lint(&dir, &module, &[&vlt_file, &file]).unwrap();
    }
}
