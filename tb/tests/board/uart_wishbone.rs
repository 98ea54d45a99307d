// SPDX-License-Identifier: MIT OR Apache-2.0
//! `UartWishbone` (receiver, protocol engine, transmitter) against the golden protocol,
//! closed loop: the `rx` line is the golden waveform (`golden::board::uart::line_levels`)
//! of random command sequences with garbage bytes between the frames, bad stop bits and
//! commands cut off by one; the Wishbone master drives [`Slave`], a 64-word memory with
//! byte lanes and a random acknowledge delay, stepped every cycle; the `tx` line is
//! decoded by `golden::board::uart::decode`. Asserted against the golden side
//! (`golden::board::protocol::Parser` on the same received events and a plain memory
//! model): every access and its lanes, every response byte, the frame errors, the final
//! memory. The emitted Verilog runs in Verilator on the inputs the rust-hdl run recorded
//! and must give the same outputs on every cycle (so the same closed loop), and lints
//! clean.

use crate::common;

use golden::board::protocol::{Command, Parser, Response, READ, WRITE};
use golden::board::uart::{decode, frame_levels, line_levels, LineFrame, RxEvent, UartTiming};
use golden::bus::reg_file::lane_mask;
use golden::top::port_fields::{PortFields, PortValue};
use golden::top::ports::Port;
use hdl::{uart_wb_bridge_verilog, uart_wishbone_verilog, UartWishbone};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use rust_hdl::prelude::*;
use tb::verilator::Simulator;

/// Module name of the emitted bridge.
const MODULE: &str = "uart_wishbone";

/// One cycle's inputs, in the order of [`ports`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Inputs {
    reset: bool,
    rx: bool,
    wb_ack_i: bool,
    wb_dat_i: u32,
}

/// One cycle's outputs (after the edge), in the order of [`ports`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Outputs {
    tx: bool,
    frame_error: bool,
    wb_cyc_o: bool,
    wb_stb_o: bool,
    wb_we_o: bool,
    wb_adr_o: u8,
    wb_dat_o: u32,
    wb_sel_o: u8,
}

impl PortFields for Inputs {
    fn visit_ports(&mut self, visit: &mut dyn FnMut(&'static str, &mut dyn PortValue)) {
        visit("reset", &mut self.reset);
        visit("rx", &mut self.rx);
        visit("wb_ack_i", &mut self.wb_ack_i);
        visit("wb_dat_i", &mut self.wb_dat_i);
    }
}

impl PortFields for Outputs {
    fn visit_ports(&mut self, visit: &mut dyn FnMut(&'static str, &mut dyn PortValue)) {
        visit("tx", &mut self.tx);
        visit("frame_error", &mut self.frame_error);
        visit("wb_cyc_o", &mut self.wb_cyc_o);
        visit("wb_stb_o", &mut self.wb_stb_o);
        visit("wb_we_o", &mut self.wb_we_o);
        visit("wb_adr_o", &mut self.wb_adr_o);
        visit("wb_dat_o", &mut self.wb_dat_o);
        visit("wb_sel_o", &mut self.wb_sel_o);
    }
}

/// The ports of `UartWishbone`, as its module docs list them.
fn ports() -> Vec<Port> {
    vec![
        Port::input("clock", 1, "clock"),
        Port::input("reset", 1, "synchronous reset"),
        Port::input("rx", 1, "serial line in"),
        Port::input("wb_ack_i", 1, "acknowledge"),
        Port::input("wb_dat_i", 32, "read data"),
        Port::output("tx", 1, "serial line out"),
        Port::output("frame_error", 1, "bad stop bit"),
        Port::output("wb_cyc_o", 1, "cycle"),
        Port::output("wb_stb_o", 1, "strobe"),
        Port::output("wb_we_o", 1, "write"),
        Port::output("wb_adr_o", 8, "byte address"),
        Port::output("wb_dat_o", 32, "write data"),
        Port::output("wb_sel_o", 4, "byte lanes"),
    ]
}

/// A Wishbone classic slave: 64 words with byte lanes, acknowledging each request after
/// 0..=`max_wait` idle cycles (random), for one cycle, with the read word.
struct Slave {
    mem: [u32; 64],
    rng: u64,
    max_wait: u64,
    /// Cycles still to wait for the request under way.
    wait: Option<u64>,
    /// The acknowledge given for the next edge.
    ack: bool,
    /// (write, byte address, lanes, write data) of every access acknowledged.
    log: Vec<(bool, u8, u8, u32)>,
}

impl Slave {
    fn new(seed: u64, max_wait: u64) -> Slave {
        let mut rng = seed;
        let mut mem = [0u32; 64];
        for w in &mut mem {
            *w = golden::splitmix::next(&mut rng) as u32;
        }
        Slave {
            mem,
            rng,
            max_wait,
            wait: None,
            ack: false,
            log: Vec::new(),
        }
    }

    /// The inputs `wb_ack_i`, `wb_dat_i` for the next edge, from the outputs after this one.
    fn step(&mut self, o: &Outputs) -> (bool, u32) {
        if self.ack || !(o.wb_cyc_o && o.wb_stb_o) {
            // The acknowledged request is over (the master samples ack at the edge).
            self.ack = false;
            self.wait = None;
            return (false, 0);
        }
        let w = self
            .wait
            .get_or_insert_with(|| golden::splitmix::next(&mut self.rng) % (self.max_wait + 1));
        if *w > 0 {
            *w -= 1;
            return (false, 0xDEAD_BEEF);
        }
        self.ack = true;
        let k = usize::from(o.wb_adr_o >> 2);
        self.log
            .push((o.wb_we_o, o.wb_adr_o, o.wb_sel_o, o.wb_dat_o));
        if o.wb_we_o {
            let m = lane_mask(o.wb_sel_o);
            self.mem[k] = (self.mem[k] & !m) | (o.wb_dat_o & m);
            (true, 0)
        } else {
            (true, self.mem[k])
        }
    }
}

/// What the host sends in one step, before it waits for the response.
#[derive(Clone, Debug)]
enum Item {
    /// Bytes that are no command byte, sent while the bridge is idle.
    Garbage(Vec<u8>),
    /// A byte with a bad stop bit.
    BadStop(u8),
    /// The first `n` bytes of a command, then a byte with a bad stop bit.
    Cut(Command, usize),
    /// A whole command.
    Cmd(Command),
}

fn command() -> impl Strategy<Value = Command> {
    prop_oneof![
        any::<u8>().prop_map(|addr| Command::Read { addr }),
        (any::<u8>(), any::<u32>(), any::<u8>()).prop_map(|(addr, data, sel)| Command::Write {
            addr,
            data,
            sel
        }),
    ]
}

fn item() -> impl Strategy<Value = Item> {
    prop_oneof![
        1 => prop::collection::vec(
            any::<u8>().prop_filter("no command byte", |b| *b != READ && *b != WRITE),
            1..4
        )
        .prop_map(Item::Garbage),
        1 => any::<u8>().prop_map(Item::BadStop),
        1 => (command(), 1usize..6).prop_map(|(c, n)| {
            let n = n.min(c.encode().len() - 1);
            Item::Cut(c, n)
        }),
        5 => command().prop_map(Item::Cmd),
    ]
}

/// The frames of one item; `idle` idle cycles before each.
fn item_frames(item: &Item, idle: u32) -> Vec<LineFrame> {
    let good = |byte| LineFrame {
        idle_cycles: idle,
        byte,
        stop: true,
    };
    let bad = |byte| LineFrame {
        idle_cycles: idle,
        byte,
        stop: false,
    };
    match item {
        Item::Garbage(g) => g.iter().map(|&b| good(b)).collect(),
        Item::BadStop(b) => vec![bad(*b)],
        Item::Cut(c, n) => {
            let mut v: Vec<LineFrame> = c.encode()[..*n].iter().map(|&b| good(b)).collect();
            v.push(bad(0xA5));
            v
        }
        Item::Cmd(c) => c.encode().iter().map(|&b| good(b)).collect(),
    }
}

/// One closed-loop run: the inputs applied and the outputs after each edge, the slave.
struct Run {
    inputs: Vec<Inputs>,
    outputs: Vec<Outputs>,
    slave: Slave,
}

/// The bridge in rust-hdl at `t`, two cycles of reset, then `items`, each after the bridge
/// had time to answer the one before (stop-and-wait), with the slave of `seed`.
fn run_rust_hdl(t: &UartTiming, items: &[Item], seed: u64, max_wait: u64) -> Run {
    let d = t.divisor();
    let mut uut = UartWishbone::new(t);
    uut.connect_all();
    let mut slave = Slave::new(seed, max_wait);
    let mut line: Vec<bool> = vec![true; 4];
    // Long enough for any response: the bus wait, 4 frames with their gaps, margins.
    let answer = (max_wait + 8) as usize + 4 * (10 * d as usize + 4) + 2 * d as usize;
    for (k, item) in items.iter().enumerate() {
        line.extend(line_levels(d, &item_frames(item, 1 + (k as u32 % 3) * d)));
        line.extend(std::iter::repeat_n(true, answer));
    }
    let (mut inputs, mut outputs) = (Vec::new(), Vec::new());
    let (mut ack, mut dat) = (false, 0u32);
    for (c, &rx) in line.iter().enumerate() {
        let i = Inputs {
            reset: c < 2,
            rx,
            wb_ack_i: ack,
            wb_dat_i: dat,
        };
        uut.reset.next = i.reset;
        uut.rx.next = i.rx;
        uut.wb_ack_i.next = i.wb_ack_i;
        uut.wb_dat_i.next = u64::from(i.wb_dat_i).into();
        common::edge(&mut uut, |u, l| u.clock.next = Clock { clk: l });
        let o = Outputs {
            tx: uut.tx.val(),
            frame_error: uut.frame_error.val(),
            wb_cyc_o: uut.wb_cyc_o.val(),
            wb_stb_o: uut.wb_stb_o.val(),
            wb_we_o: uut.wb_we_o.val(),
            wb_adr_o: uut.wb_adr_o.val().index() as u8,
            wb_dat_o: uut.wb_dat_o.val().index() as u32,
            wb_sel_o: uut.wb_sel_o.val().index() as u8,
        };
        (ack, dat) = slave.step(&o);
        inputs.push(i);
        outputs.push(o);
    }
    Run {
        inputs,
        outputs,
        slave,
    }
}

/// The golden side of a run: the commands the golden parser takes from the events the
/// golden decoder finds on `rx`, executed on the slave's initial memory; then every check
/// of the module docs on `outputs` (and the slave's log and memory).
fn check(
    t: &UartTiming,
    inputs: &[Inputs],
    outputs: &[Outputs],
    slave: &Slave,
    seed: u64,
) -> Result<(), TestCaseError> {
    let d = t.divisor();
    let rx: Vec<bool> = inputs.iter().map(|i| i.rx).collect();
    let received = decode(d, &rx);
    let mut parser = Parser::new();
    let mut mem = Slave::new(seed, 0).mem;
    let (mut accesses, mut responses) = (Vec::new(), Vec::new());
    let mut frame_errors = Vec::new();
    for r in &received {
        if r.event == RxEvent::FrameError {
            frame_errors.push(r.start + 2 + d as usize / 2 + 9 * d as usize);
        }
        match parser.push(r.event) {
            None => {}
            Some(Command::Read { addr }) => {
                let word = mem[usize::from(addr >> 2)];
                accesses.push((false, addr, 0xF, None));
                responses.extend(Response::Data(word).encode());
            }
            Some(Command::Write { addr, data, sel }) => {
                let m = lane_mask(sel & 0xF);
                let w = &mut mem[usize::from(addr >> 2)];
                *w = (*w & !m) | (data & m);
                accesses.push((true, addr, sel & 0xF, Some(data)));
                responses.extend(Response::WriteAck.encode());
            }
        }
    }
    // Accesses: order, direction, address, lanes, and the data of writes.
    let got: Vec<(bool, u8, u8, Option<u32>)> = slave
        .log
        .iter()
        .map(|&(we, a, s, dat)| (we, a, s, we.then_some(dat)))
        .collect();
    prop_assert_eq!(got, accesses);
    prop_assert_eq!(slave.mem, mem);
    // Responses: exactly the golden bytes, each frame exactly the golden waveform.
    let tx: Vec<bool> = outputs.iter().map(|o| o.tx).collect();
    let sent = decode(d, &tx);
    let bytes: Vec<RxEvent> = sent.iter().map(|s| s.event).collect();
    let want: Vec<RxEvent> = responses.iter().map(|&b| RxEvent::Byte(b)).collect();
    prop_assert_eq!(bytes, want);
    for s in &sent {
        let RxEvent::Byte(b) = s.event else {
            unreachable!()
        };
        let f = frame_levels(d, b, true);
        prop_assert_eq!(&tx[s.start..s.start + f.len()], &f[..]);
    }
    // Frame errors: one strobe per bad stop bit, at the receiver's latency.
    let strobes: Vec<usize> = (0..outputs.len())
        .filter(|&c| outputs[c].frame_error)
        .collect();
    prop_assert_eq!(strobes, frame_errors);
    prop_assert!(outputs.iter().all(|o| o.wb_cyc_o == o.wb_stb_o));
    Ok(())
}

/// 9 or 8 cycles a bit (odd and even halves).
fn timing(odd: bool) -> UartTiming {
    if odd {
        UartTiming::new(9_000_000, 1_000_000).unwrap()
    } else {
        UartTiming::new(8_000_000, 1_000_000).unwrap()
    }
}

proptest! {
    #![proptest_config(common::proptest_config(24))]

    #[test]
    fn rust_hdl_equals_golden_protocol(
        items in prop::collection::vec(item(), 1..10),
        seed in any::<u64>(),
        max_wait in 0u64..5,
        odd in any::<bool>(),
    ) {
        let t = timing(odd);
        let r = run_rust_hdl(&t, &items, seed, max_wait);
        check(&t, &r.inputs, &r.outputs, &r.slave, seed)?;
    }
}

/// The known answer of docs/uart-bridge.md: write 0x12345678 to 0x10 with sel 0xF, then
/// read 0x10: the host receives 4B, then 78 56 34 12. Then a write of 0xAABBCCDD to lanes
/// 1 and 3 only (sel 0x0A; address 0x12, bits 1:0 ignored by the slave) makes the word
/// 0xAA34CC78 (by hand: lane 1 = CC, lane 3 = AA), read back at 0x13 as 78 CC 34 AA.
#[test]
fn known_answer_write_then_read() {
    let t = UartTiming::new(12_000_000, 1_000_000).unwrap();
    let items = [
        Item::Garbage(vec![0x00, 0xFF]),
        Item::Cmd(Command::Write {
            addr: 0x10,
            data: 0x1234_5678,
            sel: 0x0F,
        }),
        Item::Cmd(Command::Read { addr: 0x10 }),
        Item::Cmd(Command::Write {
            addr: 0x12,
            data: 0xAABB_CCDD,
            sel: 0x0A,
        }),
        Item::Cmd(Command::Read { addr: 0x13 }),
    ];
    let r = run_rust_hdl(&t, &items, 7, 3);
    let tx: Vec<bool> = r.outputs.iter().map(|o| o.tx).collect();
    let bytes: Vec<RxEvent> = decode(12, &tx).iter().map(|s| s.event).collect();
    let want: Vec<RxEvent> = [0x4B, 0x78, 0x56, 0x34, 0x12, 0x4B, 0x78, 0xCC, 0x34, 0xAA]
        .iter()
        .map(|&b| RxEvent::Byte(b))
        .collect();
    assert_eq!(bytes, want);
    assert_eq!(r.slave.mem[4], 0xAA34_CC78);
    // (write, address, lanes, write data; `wb_dat_o` means nothing in a read).
    let log: Vec<(bool, u8, u8, Option<u32>)> = r
        .slave
        .log
        .iter()
        .map(|&(we, a, s, d)| (we, a, s, we.then_some(d)))
        .collect();
    assert_eq!(
        log,
        [
            (true, 0x10, 0xF, Some(0x1234_5678)),
            (false, 0x10, 0xF, None),
            (true, 0x12, 0xA, Some(0xAABB_CCDD)),
            (false, 0x13, 0xF, None),
        ]
    );
}

/// Latency of the module docs, D = 8: the last argument byte's start edge in the `rx` of
/// edge s gives `wb_cyc_o` after edge s + 2 + 4 + 72 + 1; with the acknowledge sampled at
/// edge a, the response's start bit is on `tx` after edge a + 2.
#[test]
fn latency_bytes_to_bus_and_ack_to_tx() {
    let t = timing(false);
    let items = [Item::Cmd(Command::Read { addr: 0x20 })];
    let r = run_rust_hdl(&t, &items, 1, 0);
    let rx: Vec<bool> = r.inputs.iter().map(|i| i.rx).collect();
    let last = decode(8, &rx)[1].start;
    let cyc = r.outputs.iter().position(|o| o.wb_cyc_o).unwrap();
    assert_eq!(cyc, last + 2 + 4 + 72 + 1);
    let ack = r.inputs.iter().position(|i| i.wb_ack_i).unwrap();
    assert_eq!(ack, cyc + 1, "the slave answers at once with max_wait 0");
    assert!(!r.outputs[ack].wb_cyc_o);
    let first_tx = r.outputs.iter().position(|o| !o.tx).unwrap();
    assert_eq!(first_tx, ack + 2);
}

/// The Verilog of the bridge at `t`.
fn verilog(t: &UartTiming) -> String {
    uart_wishbone_verilog(t, MODULE)
}

#[test]
fn verilog_lints_clean() {
    let t = UartTiming::new(12_000_000, 115_200).unwrap();
    common::lint_with_waivers(MODULE, &verilog(&t), &[]);
    common::lint_with_waivers(
        "uart_wb_bridge",
        &uart_wb_bridge_verilog("uart_wb_bridge"),
        &[],
    );
}

/// The emitted Verilog in Verilator, on the inputs of rust-hdl runs of random items (and
/// of the known answer): the same outputs on every cycle, and the golden checks on them.
#[test]
fn verilator_equals_rust_hdl_and_golden() {
    let mut rng = 0x0a57_b71d_u64;
    for odd in [false, true] {
        let t = timing(odd);
        let sim: Simulator<Inputs, Outputs> =
            Simulator::compile(&verilog(&t), MODULE, &ports(), "`verilator_config\n", None)
                .unwrap();
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        for case in 0..6 {
            let items = prop::collection::vec(item(), 4..12)
                .new_tree(&mut runner)
                .unwrap()
                .current();
            let seed = golden::splitmix::next(&mut rng);
            let max_wait = golden::splitmix::next(&mut rng) % 5;
            let r = run_rust_hdl(&t, &items, seed, max_wait);
            let got = sim.run(&r.inputs, None).unwrap();
            if let Some(c) = (0..got.len()).find(|&c| got[c] != r.outputs[c]) {
                panic!(
                    "D = {}, case {case}: Verilator and rust-hdl differ at cycle {c}: {:?} vs {:?}",
                    t.divisor(),
                    got[c],
                    r.outputs[c]
                );
            }
            // The slave again, on Verilator's outputs: the same inputs it was given.
            let mut slave = Slave::new(seed, max_wait);
            for (c, o) in got.iter().enumerate() {
                let (ack, dat) = slave.step(o);
                if let Some(next) = r.inputs.get(c + 1) {
                    assert_eq!((next.wb_ack_i, next.wb_dat_i), (ack, dat), "cycle {c}");
                }
            }
            check(&t, &r.inputs, &got, &slave, seed).unwrap();
        }
    }
}
