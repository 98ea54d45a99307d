// SPDX-License-Identifier: MIT OR Apache-2.0
//! The host program's protocol (`golden::board::host`, what `encspeed monitor` runs) against
//! the board top's emitted Verilog in Verilator (the Verilog that `board_top` proves equal
//! to the rust-hdl board cycle for cycle, and the shipped file), through a simulated serial
//! port: the bytes the host writes become `rx` frames, the `tx` frames become the bytes it
//! reads. Verilator, stepped one edge at a time (`Simulator::session`), runs the test's
//! 271 605 cycles in seconds, where rust-hdl took four and a half minutes. The host
//! identifies the IP from its registers (known answers: 24-bit counters, F = 16, 1024
//! lines, 12 MHz, dt 12 000), writes a shorter dt, and reads a sample while an encoder
//! turns at a constant speed: position, status and the speeds in r/min, each speed within
//! its error budget (`golden::top::error_budget::output_bound`) of the true speed, which is
//! fixed by the stimulus (one quadrature step every 23 cycles of 12 MHz, four steps a
//! line: 12e6 / (23 · 4 · 1024) rev/s = 7 642.66 r/min), decoded x1 (the mode after reset).

use golden::board::boards::{board_ports, Board, BoardInputs, BoardOutputs};
use golden::board::host::{identify, sample, Bridge, DeviceInfo};
use golden::board::uart::{decode, line_levels, LineFrame, RxEvent};
use golden::bus::regmap;
use golden::estimator::bounds::Estimator;
use golden::params::Spec;
use golden::top::error_budget::output_bound;
use std::collections::VecDeque;
use std::io::{self, Read, Write};
use tb::verilator::{Session, Simulator};

/// Cycles between two encoder steps.
const PERIOD: usize = 23;

/// A serial port wired to a simulated board: writes queue `rx` frames, reads step the
/// board until `tx` has delivered a byte.
struct SimSerial {
    sim: Session<BoardInputs, BoardOutputs>,
    divisor: u32,
    /// `rx` levels still to send.
    pending: VecDeque<bool>,
    /// `tx` after every edge.
    tx: Vec<bool>,
    /// Start of the `tx` frame under way.
    frame_start: Option<usize>,
    received: VecDeque<u8>,
    /// Edges so far (the encoder turns from the first).
    cycle: usize,
    /// Edges a read may wait for a byte before it times out.
    patience: usize,
}

impl SimSerial {
    fn new(board: Board) -> SimSerial {
        let p = board.params(&Spec::default()).unwrap();
        let verilog = hdl::build_board(board, &p).verilog(&board.module());
        let waivers = hdl::emit::waivers::board_waivers(&board.module());
        let verilated: Simulator<BoardInputs, BoardOutputs> =
            Simulator::compile(&verilog, &board.module(), &board_ports(), &waivers, None).unwrap();
        SimSerial {
            sim: verilated.session().unwrap(),
            divisor: board.uart().divisor(),
            pending: VecDeque::new(),
            tx: Vec::new(),
            frame_start: None,
            received: VecDeque::new(),
            cycle: 0,
            patience: 200_000,
        }
    }

    /// One edge: the next `rx` level, the encoder's quadrature state.
    fn step(&mut self) {
        let rx = self.pending.pop_front().unwrap_or(true);
        let (a, b) =
            [(false, false), (true, false), (true, true), (false, true)][(self.cycle / PERIOD) % 4];
        let o = self
            .sim
            .step(&BoardInputs {
                rx,
                enc_a: a,
                enc_b: b,
                enc_z: false,
            })
            .unwrap();
        self.tx.push(o.tx);
        let frame = 10 * self.divisor as usize;
        match self.frame_start {
            None if !o.tx => self.frame_start = Some(self.cycle),
            Some(s) if self.cycle + 1 >= s + frame => {
                for r in decode(self.divisor, &self.tx[s..]) {
                    match r.event {
                        RxEvent::Byte(b) => self.received.push_back(b),
                        RxEvent::FrameError => panic!("a bad frame on tx at edge {s}"),
                    }
                }
                self.frame_start = None;
            }
            _ => {}
        }
        self.cycle += 1;
    }
}

impl Read for SimSerial {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let deadline = self.cycle + self.patience;
        while self.received.is_empty() {
            if self.cycle >= deadline {
                return Err(io::Error::new(io::ErrorKind::TimedOut, "no byte on tx"));
            }
            self.step();
        }
        let n = buf.len().min(self.received.len());
        for b in buf.iter_mut().take(n) {
            *b = self.received.pop_front().unwrap();
        }
        Ok(n)
    }
}

impl Write for SimSerial {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let frames: Vec<LineFrame> = buf
            .iter()
            .map(|&byte| LineFrame {
                idle_cycles: 1,
                byte,
                stop: true,
            })
            .collect();
        self.pending.extend(line_levels(self.divisor, &frames));
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

#[test]
fn host_identifies_the_board_and_reads_speeds_within_their_budget() {
    let mut bridge = Bridge::new(SimSerial::new(Board::Hx8kBreakout));
    let info = identify(&mut bridge).unwrap();
    assert_eq!(
        info,
        DeviceInfo {
            counter_bits: 24,
            speed_frac_bits: 16,
            lines: 1024,
            clock_hz: 12_000_000,
            dt_default: 12_000,
        }
    );
    // dt = 600 cycles: r = 600 / (23 · 4) = 6.52 lines per dt.
    let dt = 600u32;
    bridge.write(regmap::CFG_DT, dt, 0xF).unwrap();
    // Let the estimators see a few dt at the new dt before sampling.
    for _ in 0..8 * dt {
        bridge.port().step();
    }
    let before = bridge.port().cycle;
    let s = sample(&mut bridge, &info).unwrap();
    let true_rpm = 12e6 / (PERIOD as f64 * 4.0 * 1024.0) * 60.0;
    assert!((true_rpm - 7_642.66).abs() < 0.01);
    assert_eq!(s.dt_cycles, dt);
    assert_eq!(
        s.status & 0b111,
        0b101,
        "valid, not stalled, forward: {:#x}",
        s.status
    );
    assert_eq!(s.status >> 3, 0, "no fault, no cfg_error: {:#x}", s.status);
    assert_eq!(s.snapshot, 1, "the first snapshot since reset");
    // The position counts lines (x1) modulo 1024. The snapshot is taken at the edge after
    // the trigger write's edge, whose request reaches the bus once its seven frames are in
    // (7 × 10 × 104 = 7 280 cycles) plus the bridge's few cycles: at most 7 400 / 92 = 80.4
    // lines after the lines made by the sample's start (the input pipeline's few cycles
    // behind the stimulus are under one step).
    let ahead = (s.position + 1024 - (before / PERIOD / 4) as u32 % 1024) % 1024;
    assert!(
        ahead <= 81,
        "position {} is {ahead} lines past the sample's start",
        s.position
    );
    let r = f64::from(dt) / (PERIOD as f64 * 4.0);
    for (k, est) in [
        (0, Estimator::N1),
        (2, Estimator::N3),
        (3, Estimator::Pc),
        (4, Estimator::Et),
        (5, Estimator::Mt),
    ] {
        let rpm = s.speed_rpm(&info, k);
        // x1: one decoder step a line (shift 0).
        let bound = output_bound(est, r, 0, u64::from(dt), info.speed_frac_bits);
        let err = (rpm - true_rpm).abs() / true_rpm;
        assert!(
            err <= bound,
            "{est:?}: {rpm} r/min, error {err:.3e} > bound {bound:.3e}"
        );
    }
    let line = s.line(&info);
    assert!(line.contains("valid forward"), "{line}");
    // HOLD keeps the snapshot while the disc turns on (the sample's 16 reads of six frames
    // took 16 × 6 × 1 040 ≈ 100 000 cycles, some 1 080 lines): POSITION still reads the
    // snapshot's.
    assert_eq!(bridge.read(regmap::POSITION).unwrap(), s.position);
    // The next sample is the next snapshot, of a later position.
    let again = sample(&mut bridge, &info).unwrap();
    assert_eq!(again.snapshot, 2);
    assert_ne!(again.position, s.position);
    println!("{} cycles of the board in Verilator", bridge.port().cycle);
}
