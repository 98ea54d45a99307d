// SPDX-License-Identifier: MIT OR Apache-2.0
//! UART 8N1 transmitter: `divisor` clock cycles per bit (a [`Constant`] set from the
//! validated [`UartTiming`] at construction), start bit 0, `data` least significant bit
//! first, stop bit 1; the line idles high. Frame format: [`golden::board::uart`]; the
//! benches check the line with [`golden::board::uart::decode`] and compare every frame
//! with [`golden::board::uart::frame_levels`] cycle for cycle.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | everything is registered at its rising edge |
//! | `reset` | in | 1 | synchronous, active high: idle, line high |
//! | `start` | in | 1 | send `data`; taken at an edge where `busy` is low, ignored while it is high |
//! | `data` | in | 8 | the byte, sampled with `start` |
//! | `busy` | out | 1 | a frame is on the line (a register): high from the edge that takes `start` to the end of the stop bit |
//! | `tx` | out | 1 | the serial line (a register, through one inverter) |
//!
//! Latency: the start bit is on `tx` from the edge that takes `start`; the frame lasts
//! 10·divisor cycles, and `busy` falls with the end of the stop bit (so `start` at the
//! next edge gives a stop bit one cycle longer: frames are at least 10·divisor + 1 cycles
//! apart when `start` follows `busy` through a register, as the bridge does).
//!
//! Why `tx` is `!low`, the register holding the line inverted: rust-hdl flops power up at
//! 0, and an idle UART line must be high from power-up on, before any reset (rust-hdl's
//! `DFFWithInit` is the same flop and inverter).

use golden::board::uart::UartTiming;
use rust_hdl::prelude::*;

use super::uart_rx::DIV_BITS;

/// Width of the bit index (0 start, 1..=8 data, 9 stop).
const IDX_BITS: usize = 4;
/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// UART 8N1 transmitter.
#[derive(LogicBlock)]
pub struct UartTx {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Send `data` (while `busy` is low).
    pub start: Signal<In, Bit>,
    /// The byte to send.
    pub data: Signal<In, Bits<8>>,
    /// A frame is on the line.
    pub busy: Signal<Out, Bit>,
    /// Serial line.
    pub tx: Signal<Out, Bit>,
    busy_r: DFF<Bit>,
    /// The line, inverted: 1 = low.
    low: DFF<Bit>,
    /// Cycles to the end of the current bit.
    count: DFF<Bits<DIV_BITS>>,
    /// The bit on the line: 0 start, 1..=8 data, 9 stop.
    idx: DFF<Bits<IDX_BITS>>,
    /// The data bits still to send, next at bit 0.
    shift: DFF<Bits<8>>,
    /// divisor − 1.
    div_m1: Constant<Bits<DIV_BITS>>,
    z16: Constant<Bits<DIV_BITS>>,
    one16: Constant<Bits<DIV_BITS>>,
    idx_zero: Constant<Bits<IDX_BITS>>,
    idx_one: Constant<Bits<IDX_BITS>>,
    /// The last data bit: the stop bit follows.
    idx_last: Constant<Bits<IDX_BITS>>,
    idx_stop: Constant<Bits<IDX_BITS>>,
    one8: Constant<Bits<8>>,
    z8: Constant<Bits<8>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
}

impl UartTx {
    /// A transmitter at `timing`'s divisor.
    pub fn new(timing: &UartTiming) -> UartTx {
        let d = u64::from(timing.divisor());
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            data: Default::default(),
            busy: Default::default(),
            tx: Default::default(),
            busy_r: Default::default(),
            low: Default::default(),
            count: Default::default(),
            idx: Default::default(),
            shift: Default::default(),
            div_m1: Constant::new((d - 1).into()),
            z16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            idx_zero: Constant::new(0.into()),
            idx_one: Constant::new(1.into()),
            idx_last: Constant::new(8.into()),
            idx_stop: Constant::new(9.into()),
            one8: Constant::new(1.into()),
            z8: Constant::new(0.into()),
            sh_one: Constant::new(1.into()),
        }
    }
}

impl Logic for UartTx {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, busy_r, low, count, idx, shift);
        if !self.busy_r.q.val() {
            if self.start.val() {
                self.busy_r.d.next = true;
                self.low.d.next = true;
                self.count.d.next = self.div_m1.val();
                self.idx.d.next = self.idx_zero.val();
                self.shift.d.next = self.data.val();
            }
        } else if self.count.q.val() != self.z16.val() {
            self.count.d.next = self.count.q.val() - self.one16.val();
        } else {
            // The end of bit `idx`: the next bit goes on the line.
            self.count.d.next = self.div_m1.val();
            self.idx.d.next = self.idx.q.val() + self.idx_one.val();
            if self.idx.q.val() == self.idx_stop.val() {
                self.busy_r.d.next = false;
            } else if self.idx.q.val() == self.idx_last.val() {
                self.low.d.next = false;
            } else {
                self.low.d.next = (self.shift.q.val() & self.one8.val()) == self.z8.val();
                self.shift.d.next = self.shift.q.val() >> self.sh_one.val();
            }
        }
        if self.reset.val() {
            self.busy_r.d.next = false;
            self.low.d.next = false;
        }
        self.busy.next = self.busy_r.q.val();
        self.tx.next = !self.low.q.val();
    }
}

/// The Verilog of a `UartTx` at `timing` with its top module named `module_name`.
pub fn uart_tx_verilog(timing: &UartTiming, module_name: &str) -> String {
    let mut uut = UartTx::new(timing);
    uut.connect_all();
    crate::verilog::named_verilog(&uut, module_name)
}
