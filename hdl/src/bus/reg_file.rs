// SPDX-License-Identifier: MIT OR Apache-2.0
//! The part of a register file that every window shares: the Wishbone front end
//! ([`WbFront`]: request decoder, acknowledge), the interrupt pair ([`IrqCell`]) and the
//! registered read data ([`ReadData`]), wired together. A window adds one cell per
//! register of its map, each decoding its own offset from `adr` and driving its word on
//! its `rdata`, gives the OR of those words, in groups of a few (with the interrupt
//! pair's word `irq_rdata` in the group of its offsets), to `group0` … `group7` and its
//! interrupt events to `events` ([`crate::bus::wb_regs::WbRegs`], [`crate::bus::ecc_regs::EccRegs`]). Cycle
//! model of a whole file: [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `clock`, `reset` (synchronous); the Wishbone slave ports `wb_*`; `irq` (level,
//! an AND-OR of registers); `events` (32, this cycle's interrupt events in the status
//! register's bit positions); `group0` … `group7` (32 each, the OR of the words of each of
//! the window's read groups); `irq_rdata` (32, the interrupt pair's word, combinational
//! from `adr`); to the cells, combinational from the bus inputs and the
//! front end's registers: `adr`, `rd`, `wr`, `lanes`, `ones` ([`WbFront`]). Timing: a
//! request sampled at edge k executes at k and is acknowledged, with its read data (the
//! word as it stood before edge k), in the cycle after edge k + 1.
//!
//! Only plain assignments connect the three blocks here, so Verilator orders them one by
//! one: the decoder drives `adr` before the cells' words come back into the read data,
//! and no combinational loop appears (which a single block doing both would make).

use crate::bus::irq_cell::IrqCell;
use crate::bus::read_data::ReadData;
use crate::bus::wb_front::WbFront;
use golden::bus::regmap::{Register, ADDR_BITS};
use rust_hdl::prelude::*;

/// Front end, interrupt pair and read data of a register file.
#[derive(LogicBlock)]
pub struct RegFile {
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
    /// Wishbone: read data (0 outside a read's ack cycle).
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone: acknowledge.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Interrupt request, level.
    pub irq: Signal<Out, Bit>,
    /// Interrupt events of this cycle.
    pub events: Signal<In, Bits<32>>,
    /// The OR of the words of the window's read group 0.
    pub group0: Signal<In, Bits<32>>,
    /// The OR of the words of the window's read group 1.
    pub group1: Signal<In, Bits<32>>,
    /// The OR of the words of the window's read group 2.
    pub group2: Signal<In, Bits<32>>,
    /// The OR of the words of the window's read group 3.
    pub group3: Signal<In, Bits<32>>,
    /// The OR of the words of the window's read group 4.
    pub group4: Signal<In, Bits<32>>,
    /// The OR of the words of the window's read group 5.
    pub group5: Signal<In, Bits<32>>,
    /// The OR of the words of the window's read group 6.
    pub group6: Signal<In, Bits<32>>,
    /// The OR of the words of the window's read group 7.
    pub group7: Signal<In, Bits<32>>,
    /// The interrupt pair's word at `adr` (0 away from its two offsets), for the window to
    /// put in a read group.
    pub irq_rdata: Signal<Out, Bits<32>>,
    /// Byte offset of the addressed word, to the cells.
    pub adr: Signal<Out, Bits<ADDR_BITS>>,
    /// A read request this cycle, to the cells.
    pub rd: Signal<Out, Bit>,
    /// A write request this cycle, to the cells.
    pub wr: Signal<Out, Bit>,
    /// The written byte lanes as a mask, to the cells.
    pub lanes: Signal<Out, Bits<32>>,
    /// The bits written 1, to the cells.
    pub ones: Signal<Out, Bits<32>>,
    front: WbFront,
    irqs: IrqCell,
    read: ReadData,
}

impl RegFile {
    /// The shared part of a window whose interrupt pair is `irq_enable` (its RW fields are
    /// the enables) and `irq_status` (its W1C fields are the events).
    pub fn new(irq_enable: &Register, irq_status: &Register) -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_sel_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            irq: Default::default(),
            events: Default::default(),
            group0: Default::default(),
            group1: Default::default(),
            group2: Default::default(),
            group3: Default::default(),
            group4: Default::default(),
            group5: Default::default(),
            group6: Default::default(),
            group7: Default::default(),
            irq_rdata: Default::default(),
            adr: Default::default(),
            rd: Default::default(),
            wr: Default::default(),
            lanes: Default::default(),
            ones: Default::default(),
            front: WbFront::default(),
            irqs: IrqCell::new(irq_enable, irq_status),
            read: ReadData::default(),
        }
    }
}

impl Logic for RegFile {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, front, irqs, read);
        self.front.reset.next = self.reset.val();
        self.front.wb_cyc_i.next = self.wb_cyc_i.val();
        self.front.wb_stb_i.next = self.wb_stb_i.val();
        self.front.wb_we_i.next = self.wb_we_i.val();
        self.front.wb_adr_i.next = self.wb_adr_i.val();
        self.front.wb_dat_i.next = self.wb_dat_i.val();
        self.front.wb_sel_i.next = self.wb_sel_i.val();
        self.wb_ack_o.next = self.front.wb_ack_o.val();
        self.adr.next = self.front.adr.val();
        self.rd.next = self.front.rd.val();
        self.wr.next = self.front.wr.val();
        self.lanes.next = self.front.lanes.val();
        self.ones.next = self.front.ones.val();
        self.irqs.reset.next = self.reset.val();
        self.irqs.adr.next = self.front.adr.val();
        self.irqs.wr.next = self.front.wr.val();
        self.irqs.lanes.next = self.front.lanes.val();
        self.irqs.ones.next = self.front.ones.val();
        self.irqs.events.next = self.events.val();
        self.irq.next = self.irqs.irq.val();
        self.read.reset.next = self.reset.val();
        self.read.rd.next = self.front.rd.val();
        self.read.group0.next = self.group0.val();
        self.read.group1.next = self.group1.val();
        self.read.group2.next = self.group2.val();
        self.read.group3.next = self.group3.val();
        self.read.group4.next = self.group4.val();
        self.read.group5.next = self.group5.val();
        self.read.group6.next = self.group6.val();
        self.read.group7.next = self.group7.val();
        self.irq_rdata.next = self.irqs.rdata.val();
        self.wb_dat_o.next = self.read.wb_dat_o.val();
    }
}
