// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_ecc_wb`: [`EncspeedEcc`] behind one Wishbone B4 classic window served by two
//! slaves: the core's register file [`WbRegs`] (offsets below
//! [`golden::bus::ecc_regmap::ECC_BASE`], the map of `encspeed_wb` unchanged) and the
//! eccentricity window [`EccRegs`] (from `ECC_BASE` up: coefficients, identification,
//! corrected speeds). Cycle model: [`golden::top::ecc_wb_top::EccWbTopModel`].
//!
//! ```text
//! enc_a/b/z ─► EncspeedEcc ── core status ──────────► WbRegs ◄── wb_stb_i if adr < ECC_BASE
//!               ▲  ▲  └──── speed_mtc/n3c, ident_* ─► EccRegs ◄─ wb_stb_i if adr ≥ ECC_BASE
//!               │  └─ ecc_c, ecc_d, ident_arm ─────── EccRegs
//!               └──── cfg_*, clear_faults ─────────── WbRegs
//! wb_ack_o, wb_dat_o, irq: the OR of both slaves' (the one not addressed outputs 0)
//! ```
//!
//! One snapshot for both slaves: `WbRegs` stores position and the six speeds at an edge
//! with (`sample` & !`CTRL.HOLD`) | the `CTRL.TRIGGER` pulse, and this top applies the same
//! rule to `WbRegs`' `snap_hold`/`snap_trigger` outputs to drive `EccRegs`' `snap_take`, so
//! that the window stores the two corrected speeds at the same edge (and reads them while
//! `snap_sampled`, `CTRL.SAMPLED`). The rule is applied here rather than output by `WbRegs`
//! so that its outputs stay registers (docs/resources.md, "Placement noise").
//!
//! # Ports
//! Those of `encspeed_wb` (`golden::top::wb_top::wb_top_ports`): `clock`, `reset`, `enc_a`,
//! `enc_b`, `enc_z`, `sample`, `wb_cyc_i`, `wb_stb_i`, `wb_we_i`, `wb_adr_i[7:0]`, `wb_dat_i[31:0]`,
//! `wb_sel_i[3:0]`, `wb_dat_o[31:0]`, `wb_ack_o`, `irq`.
//!
//! # Timing
//! As `encspeed_wb`: every block's outputs are registers, an access takes three cycles, a
//! write acts in `encspeed_ecc` from the edge after the write edge, and a read returns the
//! outputs as they stood in the request cycle. The routing is the one combinational path
//! (`wb_adr_i` → each slave's request), ahead of the slaves' registers.

use crate::bus::ecc_regs::EccRegs;
use crate::bus::wb_regs::WbRegs;
use crate::top::ecc_top::EncspeedEcc;
use golden::bus::ecc_regmap::ECC_BASE;
use golden::bus::regmap::ADDR_BITS;
use golden::params::{Params, ERROR_COUNT_BITS, FILTER_BITS, POSITION_BITS};
use rust_hdl::prelude::*;

const C: usize = POSITION_BITS as usize;
const FB: usize = FILTER_BITS as usize;
const G: usize = ERROR_COUNT_BITS as usize;

/// `encspeed_ecc` behind its Wishbone window, N-bit counters (P = 2N + 1, S = N + 17,
/// CW = the corrector's width).
#[derive(LogicBlock)]
pub struct EncspeedEccWb<const N: usize, const P: usize, const S: usize, const CW: usize> {
    /// Core and bus clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset of every block.
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
    /// Interrupt request, level: either slave's.
    pub irq: Signal<Out, Bit>,
    /// The core with its correctors and identification.
    pub ecc: EncspeedEcc<N, P, S, CW>,
    /// The core's register file (offsets below `ECC_BASE`).
    pub regs: WbRegs<N, S, C, FB, G>,
    /// The eccentricity window (offsets from `ECC_BASE`).
    pub window: EccRegs<S>,
    /// The request addresses the window.
    in_window: Signal<Local, Bit>,
    ecc_base: Constant<Bits<ADDR_BITS>>,
}

impl<const N: usize, const P: usize, const S: usize, const CW: usize> EncspeedEccWb<N, P, S, CW> {
    /// The top of validated parameters `p`; panics where [`golden::top::ecc_top::check`]
    /// refuses them or unless `N` is their counter width (the dispatch in
    /// [`build_ecc_wb`](crate::sim::ecc_wb_sim::build_ecc_wb) guarantees it).
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
            ecc: EncspeedEcc::new(p),
            regs: WbRegs::new(p),
            window: EccRegs::new(),
            in_window: Default::default(),
            ecc_base: Constant::new(u64::from(ECC_BASE).into()),
        }
    }
}

impl<const N: usize, const P: usize, const S: usize, const CW: usize> Logic
    for EncspeedEccWb<N, P, S, CW>
{
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, ecc, regs, window);
        self.ecc.reset.next = self.reset.val();
        self.regs.reset.next = self.reset.val();
        self.regs.sample.next = self.sample.val();
        self.window.reset.next = self.reset.val();
        // One snapshot strobe for both slaves: the window stores the corrected speeds at
        // the edge where the register file stores position and the six speeds.
        // The register file's rule, on its controls: `sample` unless CTRL.HOLD, or the
        // CTRL.TRIGGER pulse.
        self.window.snap_take.next =
            (self.sample.val() & !self.regs.snap_hold.val()) | self.regs.snap_trigger.val();
        self.window.snap_sampled.next = self.regs.snap_sampled.val();

        // Encoder in.
        self.ecc.enc_a.next = self.enc_a.val();
        self.ecc.enc_b.next = self.enc_b.val();
        self.ecc.enc_z.next = self.enc_z.val();

        // The bus to both slaves; the strobe only to the one addressed.
        self.in_window.next = self.wb_adr_i.val() >= self.ecc_base.val();
        self.regs.wb_cyc_i.next = self.wb_cyc_i.val();
        self.regs.wb_stb_i.next = self.wb_stb_i.val() & (!self.in_window.val());
        self.regs.wb_we_i.next = self.wb_we_i.val();
        self.regs.wb_adr_i.next = self.wb_adr_i.val();
        self.regs.wb_dat_i.next = self.wb_dat_i.val();
        self.regs.wb_sel_i.next = self.wb_sel_i.val();
        self.window.wb_cyc_i.next = self.wb_cyc_i.val();
        self.window.wb_stb_i.next = self.wb_stb_i.val() & self.in_window.val();
        self.window.wb_we_i.next = self.wb_we_i.val();
        self.window.wb_adr_i.next = self.wb_adr_i.val();
        self.window.wb_dat_i.next = self.wb_dat_i.val();
        self.window.wb_sel_i.next = self.wb_sel_i.val();

        // Configuration: register file and window → encspeed_ecc.
        self.ecc.cfg_dt.next = self.regs.cfg_dt.val();
        self.ecc.cfg_timeout.next = self.regs.cfg_timeout.val();
        self.ecc.cfg_filter.next = self.regs.cfg_filter.val();
        self.ecc.cfg_mode.next = self.regs.cfg_mode.val();
        self.ecc.cfg_z_mode.next = self.regs.cfg_z_mode.val();
        self.ecc.clear_faults.next = self.regs.clear_faults.val();
        self.ecc.ecc_c.next = self.window.ecc_c.val();
        self.ecc.ecc_d.next = self.window.ecc_d.val();
        self.ecc.ident_arm.next = self.window.ident_arm.val();

        // Status: encspeed_ecc → register file.
        self.regs.position.next = self.ecc.position.val();
        self.regs.z_latch.next = self.ecc.z_latch.val();
        self.regs.index.next = self.ecc.index.val();
        self.regs.direction.next = self.ecc.direction.val();
        self.regs.nep.next = self.ecc.nep.val();
        self.regs.ndt.next = self.ecc.ndt.val();
        self.regs.update.next = self.ecc.update.val();
        self.regs.speed_n1.next = self.ecc.speed_n1.val();
        self.regs.speed_n2.next = self.ecc.speed_n2.val();
        self.regs.speed_n3.next = self.ecc.speed_n3.val();
        self.regs.speed_strobe.next = self.ecc.speed_strobe.val();
        self.regs.speed_pc.next = self.ecc.speed_pc.val();
        self.regs.speed_et.next = self.ecc.speed_et.val();
        self.regs.speed_mt.next = self.ecc.speed_mt.val();
        self.regs.baseline_strobe.next = self.ecc.baseline_strobe.val();
        self.regs.valid.next = self.ecc.valid.val();
        self.regs.stalled.next = self.ecc.stalled.val();
        self.regs.fault_illegal.next = self.ecc.fault_illegal.val();
        self.regs.fault_overspeed.next = self.ecc.fault_overspeed.val();
        self.regs.fault_revolution.next = self.ecc.fault_revolution.val();
        self.regs.cfg_error.next = self.ecc.cfg_error.val();
        self.regs.glitch_count.next = self.ecc.glitch_count.val();
        self.regs.illegal_count.next = self.ecc.illegal_count.val();
        self.regs.rev_error_count.next = self.ecc.rev_error_count.val();

        // Status: encspeed_ecc → window.
        self.window.speed_mtc.next = self.ecc.speed_mtc.val();
        self.window.mtc_strobe.next = self.ecc.mtc_strobe.val();
        self.window.speed_n3c.next = self.ecc.speed_n3c.val();
        self.window.n3c_strobe.next = self.ecc.n3c_strobe.val();
        self.window.ident_done.next = self.ecc.ident_done.val();
        self.window.ident_overflow.next = self.ecc.ident_overflow.val();
        self.window.ident_count.next = self.ecc.ident_count.val();
        self.window.ident_t_min.next = self.ecc.ident_t_min.val();
        self.window.ident_t_max.next = self.ecc.ident_t_max.val();
        self.window.ident_p_min.next = self.ecc.ident_p_min.val();
        self.window.ident_p_max.next = self.ecc.ident_p_max.val();
        self.window.ident_sum_t.next = self.ecc.ident_sum_t.val();
        self.window.ident_sum_sin.next = self.ecc.ident_sum_sin.val();
        self.window.ident_sum_cos.next = self.ecc.ident_sum_cos.val();

        // Bus and interrupt out: the slave not addressed holds 0.
        self.wb_dat_o.next = self.regs.wb_dat_o.val() | self.window.wb_dat_o.val();
        self.wb_ack_o.next = self.regs.wb_ack_o.val() | self.window.wb_ack_o.val();
        self.irq.next = self.regs.irq.val() | self.window.irq.val();
    }
}
