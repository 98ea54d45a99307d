// SPDX-License-Identifier: MIT OR Apache-2.0
//! `UartWishbone`: the UART-to-Wishbone bridge a board top puts in front of `encspeed_wb`,
//! so that a host reads and writes its registers over a serial line: [`UartRx`] →
//! [`UartWbBridge`] → [`UartTx`]. Protocol: [`golden::board::protocol`]; line timing and
//! baud limits: [`golden::board::uart`]; docs/uart-bridge.md.
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | everything is registered at its rising edge |
//! | `reset` | in | 1 | synchronous, active high |
//! | `rx` | in | 1 | serial line from the host (asynchronous, idle 1) |
//! | `tx` | out | 1 | serial line to the host (idle 1, a register through one inverter) |
//! | `frame_error` | out | 1 | one cycle per received frame whose stop bit was 0 (a register) |
//! | `wb_cyc_o`, `wb_stb_o`, `wb_we_o` | out | 1 | Wishbone B4 classic master (registers) |
//! | `wb_adr_o` | out | 8 | byte address (a register) |
//! | `wb_dat_o` | out | 32 | write data (a register) |
//! | `wb_sel_o` | out | 4 | byte lanes (a register) |
//! | `wb_ack_i` | in | 1 | acknowledge |
//! | `wb_dat_i` | in | 32 | read data, taken with `wb_ack_i` |
//!
//! Latency (clock edges, divisor D): from the `rx` of the last argument byte's start edge
//! to `wb_cyc_o`: 2 + ⌊D/2⌋ + 9·D + 1 (receiver, then the bridge's edge); from the edge
//! that samples `wb_ack_i` to the start bit of the first response byte on `tx`: 2 (the
//! bridge's `tx_start`, then the transmitter's edge). A read then takes 4 frames of at
//! least 10·D + 1 cycles, a write's acknowledge 1.
//!
//! Resources: the emitted Verilog at D = 104 (12 MHz, 115 200 baud) as the top, its ports on
//! pins and no other register; yosys 0.23 `synth_ice40`, nextpnr-ice40 0.4 `--hx8k
//! --package ct256 --freq 48`: 148 SB_LUT4, 167 flip-flops, 34 SB_CARRY (254 logic cells
//! of 7680), 85 SB_IO; Fmax 90.5 MHz (seeds 1, 2, 3), so 48 MHz is met with margin. The
//! divisor only changes constants: the counters are 16 bits at every D.

use golden::board::uart::UartTiming;
use rust_hdl::prelude::*;

use super::uart_rx::UartRx;
use super::uart_tx::UartTx;
use super::uart_wb_bridge::UartWbBridge;

/// UART receiver, protocol engine and transmitter: a Wishbone master behind a serial line.
#[derive(LogicBlock)]
pub struct UartWishbone {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Serial line from the host.
    pub rx: Signal<In, Bit>,
    /// Serial line to the host.
    pub tx: Signal<Out, Bit>,
    /// A received frame had a bad stop bit.
    pub frame_error: Signal<Out, Bit>,
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
    urx: UartRx,
    bridge: UartWbBridge,
    utx: UartTx,
}

impl UartWishbone {
    /// The bridge at `timing`'s divisor.
    pub fn new(timing: &UartTiming) -> UartWishbone {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            rx: Default::default(),
            tx: Default::default(),
            frame_error: Default::default(),
            wb_cyc_o: Default::default(),
            wb_stb_o: Default::default(),
            wb_we_o: Default::default(),
            wb_adr_o: Default::default(),
            wb_dat_o: Default::default(),
            wb_sel_o: Default::default(),
            wb_ack_i: Default::default(),
            wb_dat_i: Default::default(),
            urx: UartRx::new(timing),
            bridge: UartWbBridge::default(),
            utx: UartTx::new(timing),
        }
    }
}

impl Logic for UartWishbone {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, urx, bridge, utx);
        self.urx.reset.next = self.reset.val();
        self.bridge.reset.next = self.reset.val();
        self.utx.reset.next = self.reset.val();
        self.urx.rx.next = self.rx.val();
        self.bridge.rx_data.next = self.urx.data.val();
        self.bridge.rx_valid.next = self.urx.valid.val();
        self.bridge.rx_error.next = self.urx.frame_error.val();
        self.bridge.tx_busy.next = self.utx.busy.val();
        self.utx.start.next = self.bridge.tx_start.val();
        self.utx.data.next = self.bridge.tx_data.val();
        self.bridge.wb_ack_i.next = self.wb_ack_i.val();
        self.bridge.wb_dat_i.next = self.wb_dat_i.val();
        self.tx.next = self.utx.tx.val();
        self.frame_error.next = self.urx.frame_error.val();
        self.wb_cyc_o.next = self.bridge.wb_cyc_o.val();
        self.wb_stb_o.next = self.bridge.wb_stb_o.val();
        self.wb_we_o.next = self.bridge.wb_we_o.val();
        self.wb_adr_o.next = self.bridge.wb_adr_o.val();
        self.wb_dat_o.next = self.bridge.wb_dat_o.val();
        self.wb_sel_o.next = self.bridge.wb_sel_o.val();
    }
}

/// The Verilog of a `UartWishbone` at `timing` with its top module named `module_name`.
pub fn uart_wishbone_verilog(timing: &UartTiming, module_name: &str) -> String {
    let mut uut = UartWishbone::new(timing);
    uut.connect_all();
    crate::verilog::named_verilog(&uut, module_name)
}
