// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_wb`: the core [`EncspeedCore`] behind its Wishbone B4 classic register file
//! [`WbRegs`], wired 1:1 (every configuration output of the file drives the core input of
//! the same name, every core output drives the file's status input of the same name). Its
//! cycle model is [`golden::top::wb_top::WbTopModel`]; the register map is [`golden::bus::regmap`].
//!
//! ```text
//! enc_a, enc_b, enc_z ─► EncspeedCore ── 24 status outputs ──► WbRegs ◄─► wb_*
//!                            ▲                                   │
//!                            └── cfg_dt, cfg_timeout, cfg_filter, ┤
//!                                cfg_mode, cfg_z_mode, clear_faults └─► irq
//! ```
//!
//! # Parameters
//! N = `counter_bits` (8..=32), P = 2N + 1, S = N + 17 as for the core
//! ([`build_wb`](crate::sim::wb_sim::build_wb) picks them from [`Params`]); the register file's other widths are the
//! core's fixed ones (C = [`POSITION_BITS`], FB = [`FILTER_BITS`], G = [`ERROR_COUNT_BITS`]).
//!
//! # Ports
//! `clock`, `reset` (synchronous, active high, both halves), `enc_a`, `enc_b`, `enc_z`
//! (asynchronous), `sample` (synchronous snapshot strobe), `wb_cyc_i`, `wb_stb_i`, `wb_we_i`, `wb_adr_i[7:0]`, `wb_dat_i[31:0]`,
//! `wb_sel_i[3:0]`, `wb_dat_o[31:0]`, `wb_ack_o`, `irq`
//! ([`golden::top::wb_top::wb_top_ports`] describes each).
//!
//! # Timing
//! Both halves have registered outputs, so there is no combinational path between them
//! and none from an input to an output. An access takes three cycles (request edge, read
//! stage edge, ack cycle); a configuration write acts in the core from the edge after the
//! write edge (the edge that raises `wb_ack_o`); a read returns the core's outputs as they stood
//! in the request cycle. A change of `CTRL.MODE` resets the core at the edge after the one
//! that sees it (the core registers its configuration inputs once; docs/ports.md).

use crate::bus::wb_regs::WbRegs;
use crate::top::core::EncspeedCore;
use golden::bus::regmap::ADDR_BITS;
use golden::params::{Params, ERROR_COUNT_BITS, FILTER_BITS, POSITION_BITS};
use rust_hdl::prelude::*;

const C: usize = POSITION_BITS as usize;
const FB: usize = FILTER_BITS as usize;
const G: usize = ERROR_COUNT_BITS as usize;

/// The core with its Wishbone register file, N-bit counters (P = 2N + 1, S = N + 17).
#[derive(LogicBlock)]
pub struct EncspeedWb<const N: usize, const P: usize, const S: usize> {
    /// Core and bus clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset of the core and the register file.
    pub reset: Signal<In, Bit>,
    /// Encoder channel A (asynchronous).
    pub enc_a: Signal<In, Bit>,
    /// Encoder channel B (asynchronous).
    pub enc_b: Signal<In, Bit>,
    /// Encoder index Z (asynchronous).
    pub enc_z: Signal<In, Bit>,
    /// Take a snapshot (synchronous; ignored while `CTRL.HOLD`).
    pub sample: Signal<In, Bit>,
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
    /// Wishbone: byte lanes of a write.
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone: read data (0 outside a read's ack cycle).
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone: acknowledge, for one cycle from the edge after the request edge.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Interrupt request, level.
    pub irq: Signal<Out, Bit>,
    /// The core (its ports are readable in simulation).
    pub core: EncspeedCore<N, P, S>,
    /// The register file (its ports are readable in simulation).
    pub regs: WbRegs<N, S, C, FB, G>,
}

impl<const N: usize, const P: usize, const S: usize> EncspeedWb<N, P, S> {
    /// The core and register file of validated parameters `p`; panics unless `N` is
    /// `p`'s counter width (the dispatch in [`build_wb`](crate::sim::wb_sim::build_wb) guarantees it).
    pub fn new(p: &Params) -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            enc_a: Default::default(),
            enc_b: Default::default(),
            enc_z: Default::default(),
            sample: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_sel_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            irq: Default::default(),
            core: EncspeedCore::new(p),
            regs: WbRegs::new(p),
        }
    }
}

impl<const N: usize, const P: usize, const S: usize> Logic for EncspeedWb<N, P, S> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, core, regs);
        self.core.reset.next = self.reset.val();
        self.regs.reset.next = self.reset.val();
        self.regs.sample.next = self.sample.val();

        // Encoder and bus in.
        self.core.enc_a.next = self.enc_a.val();
        self.core.enc_b.next = self.enc_b.val();
        self.core.enc_z.next = self.enc_z.val();
        self.regs.wb_cyc_i.next = self.wb_cyc_i.val();
        self.regs.wb_stb_i.next = self.wb_stb_i.val();
        self.regs.wb_we_i.next = self.wb_we_i.val();
        self.regs.wb_adr_i.next = self.wb_adr_i.val();
        self.regs.wb_dat_i.next = self.wb_dat_i.val();
        self.regs.wb_sel_i.next = self.wb_sel_i.val();

        // Configuration: register file → core.
        self.core.cfg_dt.next = self.regs.cfg_dt.val();
        self.core.cfg_timeout.next = self.regs.cfg_timeout.val();
        self.core.cfg_filter.next = self.regs.cfg_filter.val();
        self.core.cfg_mode.next = self.regs.cfg_mode.val();
        self.core.cfg_z_mode.next = self.regs.cfg_z_mode.val();
        self.core.clear_faults.next = self.regs.clear_faults.val();

        // Status: core → register file.
        self.regs.position.next = self.core.position.val();
        self.regs.z_latch.next = self.core.z_latch.val();
        self.regs.index.next = self.core.index.val();
        self.regs.direction.next = self.core.direction.val();
        self.regs.nep.next = self.core.nep.val();
        self.regs.ndt.next = self.core.ndt.val();
        self.regs.update.next = self.core.update.val();
        self.regs.speed_n1.next = self.core.speed_n1.val();
        self.regs.speed_n2.next = self.core.speed_n2.val();
        self.regs.speed_n3.next = self.core.speed_n3.val();
        self.regs.speed_strobe.next = self.core.speed_strobe.val();
        self.regs.speed_pc.next = self.core.speed_pc.val();
        self.regs.speed_et.next = self.core.speed_et.val();
        self.regs.speed_mt.next = self.core.speed_mt.val();
        self.regs.baseline_strobe.next = self.core.baseline_strobe.val();
        self.regs.valid.next = self.core.valid.val();
        self.regs.stalled.next = self.core.stalled.val();
        self.regs.fault_illegal.next = self.core.fault_illegal.val();
        self.regs.fault_overspeed.next = self.core.fault_overspeed.val();
        self.regs.fault_revolution.next = self.core.fault_revolution.val();
        self.regs.cfg_error.next = self.core.cfg_error.val();
        self.regs.glitch_count.next = self.core.glitch_count.val();
        self.regs.illegal_count.next = self.core.illegal_count.val();
        self.regs.rev_error_count.next = self.core.rev_error_count.val();

        // Bus and interrupt out.
        self.wb_dat_o.next = self.regs.wb_dat_o.val();
        self.wb_ack_o.next = self.regs.wb_ack_o.val();
        self.irq.next = self.regs.irq.val();
    }
}
