// SPDX-License-Identifier: MIT OR Apache-2.0
//! The interrupt pair of a register file ([`crate::bus::wb_front`]): an enable register
//! (its RW fields, written through the byte lanes like [`crate::bus::rw_cell`]) and a
//! status register that collects `events` and whose W1C fields a written 1 clears; an
//! event wins over a clear of the same bit at the same edge. `irq` is the level
//! (status & enable) ≠ 0. Model: the interrupt pair of
//! [`golden::bus::reg_file::RegFileModel`].
//!
//! Ports: `clock`, `reset` (synchronous, both to 0); `adr`, `wr`, `lanes`, `ones` from the
//! front end; `events` (32, this cycle's events in the status register's bit positions);
//! `rdata` (32) the enable or status word at their offsets, else 0; `irq`, an AND-OR of two
//! registers.

use golden::bus::regmap::{Access, Register, ADDR_BITS};
use rust_hdl::prelude::*;

/// Interrupt enable and status registers.
#[derive(LogicBlock)]
pub struct IrqCell {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Addressed word, from the front end.
    pub adr: Signal<In, Bits<ADDR_BITS>>,
    /// A write request, from the front end.
    pub wr: Signal<In, Bit>,
    /// Written byte lanes, from the front end.
    pub lanes: Signal<In, Bits<32>>,
    /// Bits written 1, from the front end.
    pub ones: Signal<In, Bits<32>>,
    /// Interrupt events of this cycle.
    pub events: Signal<In, Bits<32>>,
    /// The enable or status word at their offsets, else 0.
    pub rdata: Signal<Out, Bits<32>>,
    /// Interrupt request, level.
    pub irq: Signal<Out, Bit>,
    enable: DFF<Bits<32>>,
    status: DFF<Bits<32>>,
    cleared: Signal<Local, Bits<32>>,
    a_enable: Constant<Bits<ADDR_BITS>>,
    a_status: Constant<Bits<ADDR_BITS>>,
    m_enable: Constant<Bits<32>>,
    m_w1c: Constant<Bits<32>>,
    z32: Constant<Bits<32>>,
}

impl IrqCell {
    /// The pair `enable` (its RW fields are the enables) and `status` (its W1C fields are
    /// the events).
    pub fn new(enable: &Register, status: &Register) -> Self {
        let k = |v: u32| -> Constant<Bits<32>> { Constant::new(u64::from(v).into()) };
        Self {
            clock: Default::default(),
            reset: Default::default(),
            adr: Default::default(),
            wr: Default::default(),
            lanes: Default::default(),
            ones: Default::default(),
            events: Default::default(),
            rdata: Default::default(),
            irq: Default::default(),
            enable: Default::default(),
            status: Default::default(),
            cleared: Default::default(),
            a_enable: Constant::new(u64::from(enable.offset).into()),
            a_status: Constant::new(u64::from(status.offset).into()),
            m_enable: k(enable.mask_of(Access::Rw)),
            m_w1c: k(status.mask_of(Access::W1c)),
            z32: k(0),
        }
    }
}

impl Logic for IrqCell {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, enable, status);
        self.rdata.next = self.z32.val();
        self.cleared.next = self.z32.val();
        if self.adr.val() == self.a_enable.val() {
            self.rdata.next = self.enable.q.val();
            if self.wr.val() {
                self.enable.d.next = ((self.enable.q.val() & (!self.lanes.val()))
                    | self.ones.val())
                    & self.m_enable.val();
            }
        }
        if self.adr.val() == self.a_status.val() {
            self.rdata.next = self.status.q.val();
            if self.wr.val() {
                self.cleared.next = self.ones.val() & self.m_w1c.val();
            }
        }
        self.status.d.next = (self.status.q.val() & (!self.cleared.val())) | self.events.val();
        if self.reset.val() {
            self.enable.d.next = self.z32.val();
            self.status.d.next = self.z32.val();
        }
        self.irq.next = (self.status.q.val() & self.enable.q.val()) != self.z32.val();
    }
}
