// SPDX-License-Identifier: MIT OR Apache-2.0
//! The protocol engine of the UART-to-Wishbone bridge: takes the received bytes, decodes the
//! commands of [`golden::board::protocol`] (whose [`Parser`](golden::board::protocol::Parser)
//! is its byte-level model), runs one Wishbone B4 classic access per command as bus master
//! and hands the response bytes to the transmitter, one at a time.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | everything is registered at its rising edge |
//! | `reset` | in | 1 | synchronous, active high: idle, no bus cycle |
//! | `rx_data`, `rx_valid`, `rx_error` | in | 8, 1, 1 | from `UartRx`: a byte, its strobe, a framing error |
//! | `tx_busy` | in | 1 | from `UartTx` |
//! | `tx_start`, `tx_data` | out | 1, 8 | to `UartTx`: one-cycle strobe and the byte (registers) |
//! | `wb_cyc_o`, `wb_stb_o` | out | 1 | Wishbone: one register, high from the last argument byte's edge until the edge that samples `wb_ack_i` |
//! | `wb_we_o` | out | 1 | Wishbone: 1 for a write (a register) |
//! | `wb_adr_o` | out | 8 | Wishbone: byte address as received (a register) |
//! | `wb_dat_o` | out | 32 | Wishbone: write data, d3:d2:d1:d0 (a register) |
//! | `wb_sel_o` | out | 4 | Wishbone: byte lanes, the low four bits of `sel`; `0xF` for a read (a register) |
//! | `wb_ack_i` | in | 1 | Wishbone: acknowledge |
//! | `wb_dat_i` | in | 32 | Wishbone: read data, taken with `wb_ack_i` |
//!
//! Latency: `wb_cyc_o` rises after the edge that takes the last argument byte's
//! `rx_valid`; after the edge that samples `wb_ack_i` it falls, and `tx_start` of the first
//! response byte follows one edge later (the transmitter is idle then); each further byte
//! two edges after the transmitter's `busy` falls.
//!
//! States: idle (wait for a command byte; any other byte and framing errors are ignored),
//! arguments (count the argument bytes; a framing error returns to idle), bus (cyc/stb held
//! until `wb_ack_i`), send (queue the response, least significant byte first). Bytes
//! received in bus and send are dropped: the protocol is stop-and-wait.
//!
//! Why the widening and narrowing are shift loops: a byte enters the 32-bit write data at
//! the top, bit by bit (so after the four data bytes d0 is at bits 7:0), and the response
//! byte leaves the 32-bit register the same way; a cast would be emitted as a mask of
//! another width (docs/design-decisions.md, D7).

use rust_hdl::prelude::*;

/// Width of the state register.
const STATE_BITS: usize = 2;
/// Width of the argument-byte counter (a write has 6).
const GOT_BITS: usize = 3;
/// Width of the response-byte counter (a read has 4).
const LEFT_BITS: usize = 3;
/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// The bridge's command decoder and Wishbone master.
#[derive(LogicBlock)]
pub struct UartWbBridge {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// The received byte.
    pub rx_data: Signal<In, Bits<8>>,
    /// `rx_data` is a new byte.
    pub rx_valid: Signal<In, Bit>,
    /// A frame with a bad stop bit was received.
    pub rx_error: Signal<In, Bit>,
    /// The transmitter is sending.
    pub tx_busy: Signal<In, Bit>,
    /// Send `tx_data`.
    pub tx_start: Signal<Out, Bit>,
    /// The response byte.
    pub tx_data: Signal<Out, Bits<8>>,
    /// Wishbone: bus cycle.
    pub wb_cyc_o: Signal<Out, Bit>,
    /// Wishbone: strobe.
    pub wb_stb_o: Signal<Out, Bit>,
    /// Wishbone: 1 write, 0 read.
    pub wb_we_o: Signal<Out, Bit>,
    /// Wishbone: byte address.
    pub wb_adr_o: Signal<Out, Bits<8>>,
    /// Wishbone: write data.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone: byte lanes.
    pub wb_sel_o: Signal<Out, Bits<4>>,
    /// Wishbone: acknowledge.
    pub wb_ack_i: Signal<In, Bit>,
    /// Wishbone: read data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    state: DFF<Bits<STATE_BITS>>,
    /// Argument bytes received so far.
    got: DFF<Bits<GOT_BITS>>,
    we: DFF<Bit>,
    adr: DFF<Bits<8>>,
    dat: DFF<Bits<32>>,
    sel: DFF<Bits<4>>,
    cyc: DFF<Bit>,
    /// The response bytes still to send, next at bits 7:0.
    resp: DFF<Bits<32>>,
    /// Response bytes still to send.
    left: DFF<Bits<LEFT_BITS>>,
    start_r: DFF<Bit>,
    txd: DFF<Bits<8>>,
    /// `dat` with `rx_data` shifted in at the top.
    dat_in: Signal<Local, Bits<32>>,
    /// The low four bits of `rx_data`.
    sel_in: Signal<Local, Bits<4>>,
    /// Bits 7:0 of `resp`.
    resp_lo: Signal<Local, Bits<8>>,
    /// The argument byte being taken is the command's last.
    last_arg: Signal<Local, Bit>,
    st_idle: Constant<Bits<STATE_BITS>>,
    st_args: Constant<Bits<STATE_BITS>>,
    st_bus: Constant<Bits<STATE_BITS>>,
    st_send: Constant<Bits<STATE_BITS>>,
    got_zero: Constant<Bits<GOT_BITS>>,
    got_one: Constant<Bits<GOT_BITS>>,
    /// The index of a write's last argument byte.
    got_write_last: Constant<Bits<GOT_BITS>>,
    left_zero: Constant<Bits<LEFT_BITS>>,
    left_one: Constant<Bits<LEFT_BITS>>,
    left_read: Constant<Bits<LEFT_BITS>>,
    cmd_read: Constant<Bits<8>>,
    cmd_write: Constant<Bits<8>>,
    ack32: Constant<Bits<32>>,
    msb32: Constant<Bits<32>>,
    msb8: Constant<Bits<8>>,
    msb4: Constant<Bits<4>>,
    z8: Constant<Bits<8>>,
    z4: Constant<Bits<4>>,
    sel_all: Constant<Bits<4>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    sh_byte: Constant<Bits<SHIFT_BITS>>,
}

impl Default for UartWbBridge {
    fn default() -> Self {
        use golden::board::protocol::{READ, WRITE, WRITE_ACK, WRITE_ARGS};
        Self {
            clock: Default::default(),
            reset: Default::default(),
            rx_data: Default::default(),
            rx_valid: Default::default(),
            rx_error: Default::default(),
            tx_busy: Default::default(),
            tx_start: Default::default(),
            tx_data: Default::default(),
            wb_cyc_o: Default::default(),
            wb_stb_o: Default::default(),
            wb_we_o: Default::default(),
            wb_adr_o: Default::default(),
            wb_dat_o: Default::default(),
            wb_sel_o: Default::default(),
            wb_ack_i: Default::default(),
            wb_dat_i: Default::default(),
            state: Default::default(),
            got: Default::default(),
            we: Default::default(),
            adr: Default::default(),
            dat: Default::default(),
            sel: Default::default(),
            cyc: Default::default(),
            resp: Default::default(),
            left: Default::default(),
            start_r: Default::default(),
            txd: Default::default(),
            dat_in: Default::default(),
            sel_in: Default::default(),
            resp_lo: Default::default(),
            last_arg: Default::default(),
            st_idle: Constant::new(0.into()),
            st_args: Constant::new(1.into()),
            st_bus: Constant::new(2.into()),
            st_send: Constant::new(3.into()),
            got_zero: Constant::new(0.into()),
            got_one: Constant::new(1.into()),
            got_write_last: Constant::new(u64::try_from(WRITE_ARGS - 1).unwrap().into()),
            left_zero: Constant::new(0.into()),
            left_one: Constant::new(1.into()),
            left_read: Constant::new(4.into()),
            cmd_read: Constant::new(u64::from(READ).into()),
            cmd_write: Constant::new(u64::from(WRITE).into()),
            ack32: Constant::new(u64::from(WRITE_ACK).into()),
            msb32: Constant::new(0x8000_0000.into()),
            msb8: Constant::new(0x80.into()),
            msb4: Constant::new(0x8.into()),
            z8: Constant::new(0.into()),
            z4: Constant::new(0.into()),
            sel_all: Constant::new(0xF.into()),
            sh_one: Constant::new(1.into()),
            sh_byte: Constant::new(8.into()),
        }
    }
}

impl Logic for UartWbBridge {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, state, got, we, adr, dat, sel, cyc, resp, left, start_r, txd);
        // The received byte shifted into the write data at the top, LSB first.
        self.dat_in.next = self.dat.q.val();
        for i in 0..8 {
            if self.rx_data.val().get_bit(i) {
                self.dat_in.next = (self.dat_in.val() >> self.sh_one.val()) | self.msb32.val();
            } else {
                self.dat_in.next = self.dat_in.val() >> self.sh_one.val();
            }
        }
        self.sel_in.next = self.z4.val();
        for i in 0..4 {
            if self.rx_data.val().get_bit(i) {
                self.sel_in.next = (self.sel_in.val() >> self.sh_one.val()) | self.msb4.val();
            } else {
                self.sel_in.next = self.sel_in.val() >> self.sh_one.val();
            }
        }
        self.resp_lo.next = self.z8.val();
        for i in 0..8 {
            if self.resp.q.val().get_bit(i) {
                self.resp_lo.next = (self.resp_lo.val() >> self.sh_one.val()) | self.msb8.val();
            } else {
                self.resp_lo.next = self.resp_lo.val() >> self.sh_one.val();
            }
        }
        self.last_arg.next = ((!self.we.q.val()) & (self.got.q.val() == self.got_zero.val()))
            | (self.we.q.val() & (self.got.q.val() == self.got_write_last.val()));
        self.start_r.d.next = false;
        if self.state.q.val() == self.st_idle.val() {
            if self.rx_valid.val() {
                if self.rx_data.val() == self.cmd_read.val() {
                    self.state.d.next = self.st_args.val();
                    self.we.d.next = false;
                    self.sel.d.next = self.sel_all.val();
                    self.got.d.next = self.got_zero.val();
                }
                if self.rx_data.val() == self.cmd_write.val() {
                    self.state.d.next = self.st_args.val();
                    self.we.d.next = true;
                    self.got.d.next = self.got_zero.val();
                }
            }
        } else if self.state.q.val() == self.st_args.val() {
            if self.rx_error.val() {
                self.state.d.next = self.st_idle.val();
            } else if self.rx_valid.val() {
                self.got.d.next = self.got.q.val() + self.got_one.val();
                // Every argument byte enters the data: after a write's six, the last four
                // are there.
                self.dat.d.next = self.dat_in.val();
                if self.got.q.val() == self.got_zero.val() {
                    self.adr.d.next = self.rx_data.val();
                }
                if self.we.q.val() & (self.got.q.val() == self.got_one.val()) {
                    self.sel.d.next = self.sel_in.val();
                }
                if self.last_arg.val() {
                    self.state.d.next = self.st_bus.val();
                    self.cyc.d.next = true;
                }
            }
        } else if self.state.q.val() == self.st_bus.val() {
            if self.wb_ack_i.val() {
                self.cyc.d.next = false;
                self.state.d.next = self.st_send.val();
                if self.we.q.val() {
                    self.resp.d.next = self.ack32.val();
                    self.left.d.next = self.left_one.val();
                } else {
                    self.resp.d.next = self.wb_dat_i.val();
                    self.left.d.next = self.left_read.val();
                }
            }
        } else if self.left.q.val() == self.left_zero.val() {
            self.state.d.next = self.st_idle.val();
        } else if (!self.tx_busy.val()) & (!self.start_r.q.val()) {
            self.start_r.d.next = true;
            self.txd.d.next = self.resp_lo.val();
            self.resp.d.next = self.resp.q.val() >> self.sh_byte.val();
            self.left.d.next = self.left.q.val() - self.left_one.val();
        }
        if self.reset.val() {
            self.state.d.next = self.st_idle.val();
            self.cyc.d.next = false;
            self.start_r.d.next = false;
        }
        self.tx_start.next = self.start_r.q.val();
        self.tx_data.next = self.txd.q.val();
        self.wb_cyc_o.next = self.cyc.q.val();
        self.wb_stb_o.next = self.cyc.q.val();
        self.wb_we_o.next = self.we.q.val();
        self.wb_adr_o.next = self.adr.q.val();
        self.wb_dat_o.next = self.dat.q.val();
        self.wb_sel_o.next = self.sel.q.val();
    }
}

/// The Verilog of a `UartWbBridge` with its top module named `module_name`.
pub fn uart_wb_bridge_verilog(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<UartWbBridge>(module_name)
}
