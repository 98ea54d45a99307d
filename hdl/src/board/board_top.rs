// SPDX-License-Identifier: MIT OR Apache-2.0
//! `EncspeedBoard`: the top of a board bitstream. `encspeed_wb` with the UART-to-Wishbone
//! bridge [`UartWishbone`] as its bus master, a power-on reset and four LEDs, all on the
//! board's oscillator. The boards, their clock, baud and IP parameters:
//! [`golden::board::boards`]; pins: `constraints/<board>.pcf` (iCE40) or `.lpf` (ECP5);
//! docs/boards.md.
//!
//! ```text
//!  rx ──► UartWishbone ──wb_*──► EncspeedWb ◄── enc_a, enc_b, enc_z
//!  tx ◄──      ▲   ◄──wb_dat_o/ack──┘   │ irq
//!              └── reset ◄── power-on reset (16 cycles)      led[1] ◄─┘
//! ```
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | the board oscillator (12 MHz on the iCE40 boards, 25 MHz on the ULX3S) |
//! | `rx` | in | 1 | serial line from the host (asynchronous, idle 1) |
//! | `tx` | out | 1 | serial line to the host (idle 1 from power-up) |
//! | `enc_a`, `enc_b`, `enc_z` | in | 1 | encoder channels (asynchronous; pulled up by the PCF) |
//! | `led` | out | 4 | `led[0]` heartbeat (bit 23 of a free-running counter), `led[1]` `irq`, `led[2]` A, `led[3]` B (each a register) |
//!
//! Why a power-on reset and no reset pin: neither board has a free button on the FPGA's
//! side, and the iCE40's flip-flops start at 0 after configuration (as the emitted
//! Verilog's `initial` values and rust-hdl's simulation do), so a 4-bit counter that
//! starts at 0 holds `reset` high for the first 16 edges and then stays at 15. A host
//! that wants a fresh start writes `CTRL.MODE` (a mode change resets the core) or
//! reconfigures the FPGA.
//!
//! Timing: the bridge's Wishbone master drives `encspeed_wb`'s slave directly (both are
//! registered on both sides), so a command's access reaches the registers at the
//! bridge's latency (docs/uart-bridge.md) and is acknowledged in the cycle after the next
//! edge.

use crate::board::uart_wishbone::UartWishbone;
use crate::top::wb_top::EncspeedWb;
use golden::board::uart::UartTiming;
use golden::params::Params;
use rust_hdl::prelude::*;

/// Width of the power-on reset counter: `reset` is high for its 2^4 = 16 first edges.
const POR_BITS: usize = 4;
/// Width of the heartbeat counter: its top bit (23, written as a literal in `update`, where
/// rust-hdl cannot emit a named constant) toggles every 2^23 cycles (0.70 s at 12 MHz,
/// 0.34 s at 25 MHz).
const BEAT_BITS: usize = 24;

/// `encspeed_wb` behind the UART bridge, with a power-on reset and four LEDs.
#[derive(LogicBlock)]
pub struct EncspeedBoard<const N: usize, const P: usize, const S: usize> {
    /// The board oscillator.
    pub clock: Signal<In, Clock>,
    /// Serial line from the host.
    pub rx: Signal<In, Bit>,
    /// Serial line to the host.
    pub tx: Signal<Out, Bit>,
    /// Encoder channel A (asynchronous).
    pub enc_a: Signal<In, Bit>,
    /// Encoder channel B (asynchronous).
    pub enc_b: Signal<In, Bit>,
    /// Encoder index Z (asynchronous).
    pub enc_z: Signal<In, Bit>,
    /// LEDs: heartbeat, irq, A, B.
    pub led: Signal<Out, Bits<4>>,
    /// Edges since configuration, saturating at 15.
    por: DFF<Bits<POR_BITS>>,
    /// The power-on reset is over (0 at configuration, then 1 for good).
    running: DFF<Bit>,
    /// Free-running heartbeat counter.
    beat: DFF<Bits<BEAT_BITS>>,
    /// The LEDs, registered.
    led_r: DFF<Bits<4>>,
    por_last: Constant<Bits<POR_BITS>>,
    por_one: Constant<Bits<POR_BITS>>,
    beat_one: Constant<Bits<BEAT_BITS>>,
    led_none: Constant<Bits<4>>,
    led_beat: Constant<Bits<4>>,
    led_irq: Constant<Bits<4>>,
    led_a: Constant<Bits<4>>,
    led_b: Constant<Bits<4>>,
    led_bits: Signal<Local, Bits<4>>,
    bridge: UartWishbone,
    ip: EncspeedWb<N, P, S>,
}

impl<const N: usize, const P: usize, const S: usize> EncspeedBoard<N, P, S> {
    /// The board top of validated parameters `p` with the bridge at `uart`'s divisor;
    /// panics unless `N` is `p`'s counter width (the dispatch of
    /// [`crate::sim::board_sim::build_board`] guarantees it).
    pub fn new(p: &Params, uart: &UartTiming) -> Self {
        Self {
            clock: Default::default(),
            rx: Default::default(),
            tx: Default::default(),
            enc_a: Default::default(),
            enc_b: Default::default(),
            enc_z: Default::default(),
            led: Default::default(),
            por: Default::default(),
            running: Default::default(),
            beat: Default::default(),
            led_r: Default::default(),
            por_last: Constant::new(((1u64 << POR_BITS) - 1).into()),
            por_one: Constant::new(1u64.into()),
            beat_one: Constant::new(1u64.into()),
            led_none: Constant::new(0u64.into()),
            led_beat: Constant::new(1u64.into()),
            led_irq: Constant::new(2u64.into()),
            led_a: Constant::new(4u64.into()),
            led_b: Constant::new(8u64.into()),
            led_bits: Default::default(),
            bridge: UartWishbone::new(uart),
            ip: EncspeedWb::new(p),
        }
    }
}

impl<const N: usize, const P: usize, const S: usize> Logic for EncspeedBoard<N, P, S> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, por, running, beat, led_r);
        clock!(self, clock, bridge, ip);

        // Power-on reset: count to 15, then hold; `running` follows one edge later.
        if self.por.q.val() != self.por_last.val() {
            self.por.d.next = self.por.q.val() + self.por_one.val();
        }
        self.running.d.next = self.por.q.val() == self.por_last.val();
        self.bridge.reset.next = !self.running.q.val();
        self.ip.reset.next = !self.running.q.val();
        self.beat.d.next = self.beat.q.val() + self.beat_one.val();

        // Serial line and encoder.
        self.bridge.rx.next = self.rx.val();
        self.tx.next = self.bridge.tx.val();
        self.ip.enc_a.next = self.enc_a.val();
        self.ip.enc_b.next = self.enc_b.val();
        self.ip.enc_z.next = self.enc_z.val();
        // No PWM carrier on the board: snapshots by CTRL.TRIGGER only.
        self.ip.sample.next = false;

        // Bridge (master) ↔ encspeed_wb (slave).
        self.ip.wb_cyc_i.next = self.bridge.wb_cyc_o.val();
        self.ip.wb_stb_i.next = self.bridge.wb_stb_o.val();
        self.ip.wb_we_i.next = self.bridge.wb_we_o.val();
        self.ip.wb_adr_i.next = self.bridge.wb_adr_o.val();
        self.ip.wb_dat_i.next = self.bridge.wb_dat_o.val();
        self.ip.wb_sel_i.next = self.bridge.wb_sel_o.val();
        self.bridge.wb_ack_i.next = self.ip.wb_ack_o.val();
        self.bridge.wb_dat_i.next = self.ip.wb_dat_o.val();

        // LEDs: heartbeat, irq, A, B. OR-ing 4-bit constants keeps every operand 4 bits
        // wide in the Verilog (`replace_bit` shifts a 1-bit value by a 32-bit amount).
        self.led_bits.next = self.led_none.val();
        if self.beat.q.val().get_bit(23) {
            self.led_bits.next = self.led_bits.val() | self.led_beat.val();
        }
        if self.ip.irq.val() {
            self.led_bits.next = self.led_bits.val() | self.led_irq.val();
        }
        if self.enc_a.val() {
            self.led_bits.next = self.led_bits.val() | self.led_a.val();
        }
        if self.enc_b.val() {
            self.led_bits.next = self.led_bits.val() | self.led_b.val();
        }
        self.led_r.d.next = self.led_bits.val();
        self.led.next = self.led_r.q.val();
    }
}
