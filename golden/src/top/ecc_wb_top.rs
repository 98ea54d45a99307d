// SPDX-License-Identifier: MIT OR Apache-2.0
//! Cycle model of `encspeed_ecc_wb` (the block `hdl::EncspeedEccWb`): `encspeed_ecc`
//! ([`EccTopModel`]) behind one Wishbone window served by two slaves, the core's register
//! file ([`WbRegsModel`], offsets below [`ECC_BASE`]) and the eccentricity window
//! ([`EccRegsModel`], [`ECC_BASE`] and up).
//!
//! ```text
//! enc_a, enc_b, enc_z ─► EccTopModel ─ core status ─► WbRegsModel ◄─┐
//!                          ▲   ▲                                      ├─ wb_* (stb routed
//!                          │   └─ ecc_c, ecc_d, ident_arm ─ EccRegs ◄─┘   by wb_adr_i)
//!                          └─ cfg_*, clear_faults ─ WbRegsModel
//!  wb_ack_o, wb_dat_o, irq = the OR of both slaves' outputs
//! ```
//!
//! The routing is combinational: `wb_stb_i` reaches the register file when
//! `wb_adr_i` < [`ECC_BASE`] and the window otherwise; every other bus input reaches both.
//! A slave that is not addressed never acknowledges and outputs `wb_dat_o` = 0, so the ORs
//! are the addressed slave's outputs. Conventions and timing as in [`crate::top::wb_top`]: every
//! side sees the others' outputs as they stood before the edge, so a write reaches
//! `encspeed_ecc` one edge after the write edge, and a read returns its outputs as they
//! stood in the request cycle.

use crate::bus::ecc_regmap::in_window;
use crate::bus::ecc_regs::{EccRegsInputs, EccRegsModel, EccRegsOutputs, EccStatus};
use crate::bus::reg_file::WbBus;
use crate::bus::wb_regs::{WbRegsInputs, WbRegsModel, WbRegsOutputs};
use crate::params::Params;
use crate::top::ecc_top::{EccTopInputs, EccTopModel, EccTopOutputs};
use crate::top::wb_top::{core_inputs, core_status, WbTopInputs, WbTopOutputs};

pub use crate::bus::ecc_regmap::ECC_BASE;

/// Module name of the emitted top.
pub const ECC_WB_TOP_MODULE: &str = "encspeed_ecc_wb";

/// The window's status inputs from `encspeed_ecc`'s outputs (speeds as S-bit patterns).
pub fn ecc_status(o: &EccTopOutputs, speed_bits: u32) -> EccStatus {
    let raw = |v: i64| (v as u64) & ((1u64 << speed_bits) - 1);
    EccStatus {
        speed_mtc: raw(o.speed_mtc),
        mtc_strobe: o.mtc_strobe,
        speed_n3c: raw(o.speed_n3c),
        n3c_strobe: o.n3c_strobe,
        ident: o.ident,
    }
}

/// `bus` as the slave of the window (`ecc`) or the register file (`!ecc`) sees it.
pub fn routed(bus: &WbBus, ecc: bool) -> WbBus {
    WbBus {
        wb_stb_i: bus.wb_stb_i && in_window(bus.wb_adr_i) == ecc,
        ..*bus
    }
}

/// Cycle model of `encspeed_ecc_wb`.
#[derive(Clone, Debug)]
pub struct EccWbTopModel {
    ecc: EccTopModel,
    last: EccTopOutputs,
    regs: WbRegsModel,
    window: EccRegsModel,
    speed_bits: u32,
}

impl EccWbTopModel {
    /// The top for validated parameters, before reset (hold `reset` for an edge first).
    /// Panics where [`crate::top::ecc_top::check`] refuses `p`.
    pub fn new(p: &Params) -> Self {
        Self {
            ecc: EccTopModel::new(p),
            last: EccTopOutputs::default(),
            regs: WbRegsModel::new(p),
            window: EccRegsModel::new(p.speed_bits()),
            speed_bits: p.speed_bits(),
        }
    }

    /// One rising edge with `inp`; the outputs after it.
    pub fn step(&mut self, inp: &WbTopInputs) -> WbTopOutputs {
        // Every side from the others' outputs before the edge.
        let cfg = self.regs.outputs();
        let w = self.window.outputs();
        let status = core_status(&self.last.core, self.speed_bits);
        let ecc_status = ecc_status(&self.last, self.speed_bits);
        // The window follows the core register file's snapshot strobe and CTRL.SAMPLED.
        let (snap_take, snap_sampled) = (self.regs.take(inp.sample), self.regs.sampled());
        self.last = self.ecc.step(EccTopInputs {
            core: core_inputs(inp, &cfg),
            ecc_c: w.coef_c(),
            ecc_d: w.coef_d(),
            ident_arm: w.ident_arm,
        });
        self.regs.step(&WbRegsInputs {
            reset: inp.reset,
            sample: inp.sample,
            bus: routed(&inp.bus, false),
            status,
        });
        self.window.step(&EccRegsInputs {
            reset: inp.reset,
            bus: routed(&inp.bus, true),
            status: ecc_status,
            snap_take,
            snap_sampled,
        });
        self.outputs()
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> WbTopOutputs {
        let r = self.regs.outputs();
        let w = self.window.outputs();
        WbTopOutputs {
            wb_ack_o: r.wb_ack_o || w.wb_ack_o,
            wb_dat_o: r.wb_dat_o | w.wb_dat_o,
            irq: r.irq || w.irq,
        }
    }

    /// `encspeed_ecc`'s outputs after the last edge (internal signals).
    pub fn ecc_outputs(&self) -> &EccTopOutputs {
        &self.last
    }

    /// The register file's outputs after the last edge (internal signals).
    pub fn regs_outputs(&self) -> WbRegsOutputs {
        self.regs.outputs()
    }

    /// The window's outputs after the last edge (internal signals).
    pub fn window_outputs(&self) -> EccRegsOutputs {
        self.window.outputs()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::ecc_regmap as m;
    use crate::bus::regmap;
    use crate::params::Spec;

    fn access(t: &mut EccWbTopModel, we: bool, adr: u32, dat: u32) -> u32 {
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: we,
            wb_adr_i: adr,
            wb_dat_i: dat,
            wb_sel_i: 0xF,
        };
        let inputs = WbTopInputs {
            bus,
            ..Default::default()
        };
        assert!(
            !t.step(&inputs).wb_ack_o,
            "no ack at the request edge at {adr:#x}"
        );
        let o = t.step(&inputs);
        assert!(o.wb_ack_o, "one ack per access at {adr:#x}");
        assert!(!t.step(&WbTopInputs::default()).wb_ack_o);
        o.wb_dat_o
    }

    /// Both slaves answer through the one window; a load reaches `encspeed_ecc` as the
    /// coefficient values written.
    #[test]
    fn one_window_two_slaves() {
        let p = Params::new(Spec::default()).unwrap();
        let mut t = EccWbTopModel::new(&p);
        t.step(&WbTopInputs {
            reset: true,
            ..Default::default()
        });
        assert_eq!(access(&mut t, false, regmap::ID, 0), 0x454E_4353);
        assert_eq!(access(&mut t, false, m::ECC_ID, 0), 0x454E_4345);
        assert_eq!(
            access(&mut t, false, 0x8C, 0),
            0,
            "unmapped below the window"
        );
        assert_eq!(access(&mut t, false, 0xFC, 0), 0, "unmapped in the window");
        access(&mut t, true, regmap::CTRL, 0b0100);
        assert_eq!(t.regs_outputs().cfg_z_mode, 1);
        access(&mut t, true, m::ECC_C, 0x0001_8000);
        access(&mut t, true, m::ECC_D, (-0x4000i32) as u32);
        access(&mut t, true, m::ECC_CTRL, 0b10);
        let w = t.window_outputs();
        assert_eq!((w.coef_c(), w.coef_d()), (98_304, -16_384));
    }
}
