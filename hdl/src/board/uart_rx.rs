// SPDX-License-Identifier: MIT OR Apache-2.0
//! UART 8N1 receiver: a two-flop synchroniser on `rx`, start-bit detection on the falling
//! edge of the synchronised line, every bit sampled at its middle, `divisor` clock cycles
//! per bit (a [`Constant`] set from the validated [`UartTiming`] at construction).
//!
//! Line timing, the sampling rule and the baud limits: [`golden::board::uart`]; the
//! receiver samples exactly as [`golden::board::uart::decode`] does, two cycles later (the
//! synchroniser).
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | everything is registered at its rising edge |
//! | `reset` | in | 1 | synchronous, active high: back to idle, the line taken as idle (1) |
//! | `rx` | in | 1 | the serial line, asynchronous (idle 1) |
//! | `data` | out | 8 | the last byte received with a good stop bit (a register) |
//! | `valid` | out | 1 | one cycle when `data` has just been loaded (a register) |
//! | `frame_error` | out | 1 | one cycle when a frame's stop bit was sampled 0 (a register); its data is dropped |
//!
//! Latency: a frame whose start bit's falling edge is in the `rx` of edge c gives `valid`
//! (or `frame_error`) after edge c + 2 + ⌊divisor/2⌋ + 9·divisor (the synchroniser, then
//! the stop bit's middle).
//!
//! Why the synchroniser stores the line inverted (1 = low): its flops power up at 0, which
//! then reads as an idle line rather than as a start bit. Why a falling edge, not a low
//! level, starts a frame: after a framing error (a line held low, a break) the receiver
//! waits for the line to go high again instead of taking the low stop bit for a start bit.
//! A start bit that is high again at its middle was a glitch and is ignored.
//!
//! Resources: measured for the whole bridge, [`crate::board::uart_wishbone`].

use golden::board::uart::UartTiming;
use rust_hdl::prelude::*;

/// Width of the bit-time counter: the divisor is at most
/// [`golden::board::uart::MAX_DIVISOR`] = 2^16 − 1.
pub const DIV_BITS: usize = 16;
/// Width of the bit index (0 start, 1..=8 data, 9 stop).
const IDX_BITS: usize = 4;
/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// UART 8N1 receiver.
#[derive(LogicBlock)]
pub struct UartRx {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Serial line (asynchronous).
    pub rx: Signal<In, Bit>,
    /// The last byte received.
    pub data: Signal<Out, Bits<8>>,
    /// One cycle per byte received with a good stop bit.
    pub valid: Signal<Out, Bit>,
    /// One cycle per frame whose stop bit was 0.
    pub frame_error: Signal<Out, Bit>,
    /// The synchroniser, inverted: 1 = line low. `s3` is the synchronised line one cycle
    /// earlier, for the falling edge.
    s1: DFF<Bit>,
    s2: DFF<Bit>,
    s3: DFF<Bit>,
    /// A frame is being received.
    busy: DFF<Bit>,
    /// Cycles to the next sample.
    count: DFF<Bits<DIV_BITS>>,
    /// The bit sampled next: 0 start, 1..=8 data, 9 stop.
    idx: DFF<Bits<IDX_BITS>>,
    /// Data bits so far, shifted in at the top (LSB first on the line).
    shift: DFF<Bits<8>>,
    data_r: DFF<Bits<8>>,
    valid_r: DFF<Bit>,
    ferr_r: DFF<Bit>,
    /// divisor − 1: cycles between two samples, less the sampling one.
    div_m1: Constant<Bits<DIV_BITS>>,
    /// ⌊divisor/2⌋ − 1: from the edge to the start bit's middle.
    half_m1: Constant<Bits<DIV_BITS>>,
    z16: Constant<Bits<DIV_BITS>>,
    one16: Constant<Bits<DIV_BITS>>,
    idx_zero: Constant<Bits<IDX_BITS>>,
    idx_one: Constant<Bits<IDX_BITS>>,
    idx_stop: Constant<Bits<IDX_BITS>>,
    msb8: Constant<Bits<8>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
}

impl UartRx {
    /// A receiver at `timing`'s divisor.
    pub fn new(timing: &UartTiming) -> UartRx {
        let d = u64::from(timing.divisor());
        Self {
            clock: Default::default(),
            reset: Default::default(),
            rx: Default::default(),
            data: Default::default(),
            valid: Default::default(),
            frame_error: Default::default(),
            s1: Default::default(),
            s2: Default::default(),
            s3: Default::default(),
            busy: Default::default(),
            count: Default::default(),
            idx: Default::default(),
            shift: Default::default(),
            data_r: Default::default(),
            valid_r: Default::default(),
            ferr_r: Default::default(),
            div_m1: Constant::new((d - 1).into()),
            half_m1: Constant::new((d / 2 - 1).into()),
            z16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            idx_zero: Constant::new(0.into()),
            idx_one: Constant::new(1.into()),
            idx_stop: Constant::new(9.into()),
            msb8: Constant::new(0x80.into()),
            sh_one: Constant::new(1.into()),
        }
    }
}

impl Logic for UartRx {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s1, s2, s3, busy, count, idx, shift, data_r, valid_r, ferr_r);
        self.s1.d.next = !self.rx.val();
        self.s2.d.next = self.s1.q.val();
        self.s3.d.next = self.s2.q.val();
        self.valid_r.d.next = false;
        self.ferr_r.d.next = false;
        if !self.busy.q.val() {
            // Falling edge of the synchronised line: a start bit begins.
            if self.s2.q.val() & (!self.s3.q.val()) {
                self.busy.d.next = true;
                self.count.d.next = self.half_m1.val();
                self.idx.d.next = self.idx_zero.val();
            }
        } else if self.count.q.val() != self.z16.val() {
            self.count.d.next = self.count.q.val() - self.one16.val();
        } else {
            // The middle of bit `idx`.
            self.count.d.next = self.div_m1.val();
            self.idx.d.next = self.idx.q.val() + self.idx_one.val();
            if self.idx.q.val() == self.idx_zero.val() {
                if !self.s2.q.val() {
                    // High again at the start bit's middle: a glitch.
                    self.busy.d.next = false;
                }
            } else if self.idx.q.val() == self.idx_stop.val() {
                self.busy.d.next = false;
                if self.s2.q.val() {
                    self.ferr_r.d.next = true;
                } else {
                    self.valid_r.d.next = true;
                    self.data_r.d.next = self.shift.q.val();
                }
            } else {
                self.shift.d.next = self.shift.q.val() >> self.sh_one.val();
                if !self.s2.q.val() {
                    self.shift.d.next = (self.shift.q.val() >> self.sh_one.val()) | self.msb8.val();
                }
            }
        }
        if self.reset.val() {
            self.s1.d.next = false;
            self.s2.d.next = false;
            self.s3.d.next = false;
            self.busy.d.next = false;
            self.valid_r.d.next = false;
            self.ferr_r.d.next = false;
        }
        self.data.next = self.data_r.q.val();
        self.valid.next = self.valid_r.q.val();
        self.frame_error.next = self.ferr_r.q.val();
    }
}

/// The Verilog of a `UartRx` at `timing` with its top module named `module_name`.
pub fn uart_rx_verilog(timing: &UartTiming, module_name: &str) -> String {
    let mut uut = UartRx::new(timing);
    uut.connect_all();
    crate::verilog::named_verilog(&uut, module_name)
}
