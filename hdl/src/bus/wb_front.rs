// SPDX-License-Identifier: MIT OR Apache-2.0
//! Wishbone B4 classic front end of a register file: decodes the request and acknowledges
//! it. A request is `wb_cyc_i & wb_stb_i` while neither `wb_ack_o` nor the request's own
//! `pending` flag is high; it is executed at the edge that samples it (edge k), the read
//! data is gathered at edge k + 1 ([`crate::bus::read_data`]) and `wb_ack_o` is high in the
//! cycle after edge k + 1: three cycles per access. The second edge is there for timing:
//! the 32-bit read multiplexer of some 30 words does not fit one 10 ns cycle on an iCE40
//! behind the address decode, so it is split over two registers.
//!
//! A register file is this front end, one cell per register of its map, each decoding its
//! own offset from `adr` and driving its word on `rdata` (0 elsewhere)
//! ([`crate::bus::const_cell`], [`crate::bus::rw_cell`], [`crate::bus::read_cell`],
//! [`crate::bus::shadow_cell`], [`crate::bus::pulse_cell`], [`crate::bus::irq_cell`]), and
//! the read-data register [`crate::bus::read_data`] that takes the OR of the words; the
//! front end, the interrupt pair and the read data are wired together in
//! [`crate::bus::reg_file::RegFile`]. The decoder and the read-data register are two
//! blocks so that no block both drives `adr` and reads the words that depend on it
//! (Verilator would see a combinational loop).
//! Cycle model of a whole file: [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `clock`, `reset` (synchronous); the Wishbone inputs; `wb_ack_o` (a register);
//! to the cells, combinational from the bus inputs, `wb_ack_o` and `pending`: `adr` (8, the word's
//! byte offset: `wb_adr_i` with bits 1:0 cleared), `rd`, `wr` (a read or write request this
//! cycle), `lanes` (32, the byte lanes of `wb_sel_i` as a mask), `ones` (32, `wb_dat_i &
//! lanes`: the bits written 1).

use golden::bus::regmap::{ADDR_BITS, SPAN_BYTES};
use rust_hdl::prelude::*;

/// Request decoder and acknowledge of a Wishbone classic slave.
#[derive(LogicBlock)]
pub struct WbFront {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Wishbone: bus cycle.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone: strobe.
    pub wb_stb_i: Signal<In, Bit>,
    /// Wishbone: 1 write, 0 read.
    pub wb_we_i: Signal<In, Bit>,
    /// Wishbone: byte address (bits 1:0 ignored).
    pub wb_adr_i: Signal<In, Bits<ADDR_BITS>>,
    /// Wishbone: write data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Wishbone: byte lanes.
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone: acknowledge.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Byte offset of the addressed word.
    pub adr: Signal<Out, Bits<ADDR_BITS>>,
    /// A read request this cycle.
    pub rd: Signal<Out, Bit>,
    /// A write request this cycle.
    pub wr: Signal<Out, Bit>,
    /// The written byte lanes as a 32-bit mask.
    pub lanes: Signal<Out, Bits<32>>,
    /// The bits written 1.
    pub ones: Signal<Out, Bits<32>>,
    ack: DFF<Bit>,
    /// A request was executed at the last edge: its ack comes at the next.
    pending: DFF<Bit>,
    req: Signal<Local, Bit>,
    l_lanes: Signal<Local, Bits<32>>,
    adr_mask: Constant<Bits<ADDR_BITS>>,
    lane0: Constant<Bits<32>>,
    lane1: Constant<Bits<32>>,
    lane2: Constant<Bits<32>>,
    lane3: Constant<Bits<32>>,
    z32: Constant<Bits<32>>,
}

impl Default for WbFront {
    fn default() -> Self {
        assert_eq!(SPAN_BYTES, 1 << ADDR_BITS);
        let k = |v: u32| -> Constant<Bits<32>> { Constant::new(u64::from(v).into()) };
        Self {
            clock: Default::default(),
            reset: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_sel_i: Default::default(),
            wb_ack_o: Default::default(),
            adr: Default::default(),
            rd: Default::default(),
            wr: Default::default(),
            lanes: Default::default(),
            ones: Default::default(),
            ack: Default::default(),
            pending: Default::default(),
            req: Default::default(),
            l_lanes: Default::default(),
            adr_mask: Constant::new(u64::from((SPAN_BYTES - 1) & !3).into()),
            lane0: k(0x0000_00FF),
            lane1: k(0x0000_FF00),
            lane2: k(0x00FF_0000),
            lane3: k(0xFF00_0000),
            z32: k(0),
        }
    }
}

impl Logic for WbFront {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, ack, pending);
        self.req.next = self.wb_cyc_i.val()
            & self.wb_stb_i.val()
            & (!self.ack.q.val())
            & (!self.pending.q.val());
        self.pending.d.next = self.req.val();
        self.ack.d.next = self.pending.q.val();
        if self.reset.val() {
            self.pending.d.next = false;
            self.ack.d.next = false;
        }
        self.l_lanes.next = self.z32.val();
        if self.wb_sel_i.val().get_bit(0) {
            self.l_lanes.next = self.l_lanes.val() | self.lane0.val();
        }
        if self.wb_sel_i.val().get_bit(1) {
            self.l_lanes.next = self.l_lanes.val() | self.lane1.val();
        }
        if self.wb_sel_i.val().get_bit(2) {
            self.l_lanes.next = self.l_lanes.val() | self.lane2.val();
        }
        if self.wb_sel_i.val().get_bit(3) {
            self.l_lanes.next = self.l_lanes.val() | self.lane3.val();
        }
        self.wb_ack_o.next = self.ack.q.val();
        self.adr.next = self.wb_adr_i.val() & self.adr_mask.val();
        self.rd.next = self.req.val() & (!self.wb_we_i.val());
        self.wr.next = self.req.val() & self.wb_we_i.val();
        self.lanes.next = self.l_lanes.val();
        self.ones.next = self.wb_dat_i.val() & self.l_lanes.val();
    }
}
