// SPDX-License-Identifier: MIT OR Apache-2.0
//! Cycle model of `encspeed_wb` (the block `hdl::EncspeedWb`): the core
//! ([`CoreModel`]) behind its Wishbone register file ([`WbRegsModel`]), wired 1:1 as the
//! hardware wires them.
//!
//! ```text
//! enc_a, enc_b, enc_z ─► CoreModel ── 24 status outputs ──► WbRegsModel ◄─► Wishbone
//!                            ▲                                  │
//!                            └── cfg_dt, cfg_timeout, cfg_filter,┤
//!                                cfg_mode, cfg_z_mode,           │
//!                                clear_faults                    └─► irq
//! ```
//!
//! Conventions as in [`crate::estimator::sync_estimator`]: one [`WbTopModel::step`] per rising clock edge
//! with the inputs applied during the cycle before it; `step` returns the outputs after
//! the edge. Both halves are registered at their outputs, so at every edge each side sees
//! the other's outputs as they stood **before** the edge: the core steps with the register
//! file's configuration outputs before the edge, the register file steps with the core's
//! status outputs before the edge. Hence a bus write to a configuration register reaches
//! the core one edge after the write edge (the edge that raises `wb_ack_o`), and a read
//! returns the core's outputs as they stood in the cycle of the request.
//!
//! The reset is shared: `reset` resets the register file at the edge that samples it and
//! the core at the edge after (the core registers its reset: docs/ports.md).
//! After reset `CTRL` is 0 (x1, Z ignored), `CFG_DT` and `CFG_TIMEOUT` are 0 (the
//! generation defaults), `CFG_FILTER` is 0 (off). A write that changes `CTRL.MODE` resets
//! the whole core at the edge after the one that sees the new mode (the core's own rule,
//! [`crate::top::core`]); the register file keeps its state.

use crate::bus::reg_file::WbBus;
use crate::bus::regmap::{ADDR_BITS, DATA_BITS};
use crate::bus::wb_regs::{CoreStatus, WbRegsInputs, WbRegsModel, WbRegsOutputs};
use crate::params::Params;
use crate::top::core::{CoreInputs, CoreModel, CoreOutputs};
use crate::top::port_fields::{port_struct, visit_fields, PortFields, PortValue};
use crate::top::ports::{encoder_inputs, Port};

/// Name of the top module of the emitted Verilog.
pub const TOP_MODULE: &str = "encspeed_wb";

/// Inputs of `encspeed_wb` during one clock cycle (sampled at its rising edge).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WbTopInputs {
    /// Synchronous active-high reset of the core and the register file.
    pub reset: bool,
    /// Encoder channel A (asynchronous).
    pub enc_a: bool,
    /// Encoder channel B (asynchronous).
    pub enc_b: bool,
    /// Encoder index Z (asynchronous).
    pub enc_z: bool,
    /// Take a snapshot (synchronous; ignored while `CTRL.HOLD`).
    pub sample: bool,
    /// Wishbone inputs.
    pub bus: WbBus,
}

impl PortFields for WbTopInputs {
    fn visit_ports(&mut self, visit: &mut dyn FnMut(&'static str, &mut dyn PortValue)) {
        visit_fields!(visit, self, "": reset, enc_a, enc_b, enc_z, sample);
        visit_fields!(visit, self.bus, "":
            wb_cyc_i, wb_stb_i, wb_we_i, wb_adr_i, wb_dat_i, wb_sel_i);
    }
}

port_struct! {
    /// Outputs of `encspeed_wb` after a rising clock edge, named as its ports.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct WbTopOutputs {
        /// Wishbone read data (0 unless `wb_ack_o` of a read).
        pub wb_dat_o: u32,
        /// Wishbone acknowledge (one cycle per access, after the edge after the request's).
        pub wb_ack_o: bool,
        /// Interrupt request, level.
        pub irq: bool,
    }
}

/// The core's outputs as the register file's status inputs: the same values, the speeds
/// as S-bit two's complement port patterns.
pub fn core_status(o: &CoreOutputs, speed_bits: u32) -> CoreStatus {
    let raw = |v: i64| (v as u64) & ((1u64 << speed_bits) - 1);
    CoreStatus {
        position: o.position,
        z_latch: o.z_latch,
        index: o.index,
        direction: o.direction,
        nep: o.nep,
        ndt: o.ndt,
        update: o.update,
        speed_n1: raw(o.speed_n1),
        speed_n2: raw(o.speed_n2),
        speed_n3: raw(o.speed_n3),
        speed_strobe: o.speed_strobe,
        speed_pc: raw(o.speed_pc),
        speed_et: raw(o.speed_et),
        speed_mt: raw(o.speed_mt),
        baseline_strobe: o.baseline_strobe,
        valid: o.valid,
        stalled: o.stalled,
        fault_illegal: o.fault_illegal,
        fault_overspeed: o.fault_overspeed,
        fault_revolution: o.fault_revolution,
        cfg_error: o.cfg_error,
        glitch_count: o.glitch_count,
        illegal_count: o.illegal_count,
        rev_error_count: o.rev_error_count,
    }
}

/// The core's inputs driven by the register file's outputs `r`, with the top-level
/// `reset` and encoder inputs of `inp`.
pub fn core_inputs(inp: &WbTopInputs, r: &WbRegsOutputs) -> CoreInputs {
    CoreInputs {
        reset: inp.reset,
        enc_a: inp.enc_a,
        enc_b: inp.enc_b,
        enc_z: inp.enc_z,
        cfg_dt: r.cfg_dt,
        cfg_timeout: r.cfg_timeout,
        cfg_filter: r.cfg_filter,
        cfg_mode: r.cfg_mode,
        cfg_z_mode: r.cfg_z_mode,
        clear_faults: r.clear_faults,
    }
}

/// Cycle model of `encspeed_wb`.
#[derive(Clone, Debug)]
pub struct WbTopModel {
    core: CoreModel,
    regs: WbRegsModel,
    speed_bits: u32,
}

impl WbTopModel {
    /// The model of `p` in the state the hardware has after reset.
    pub fn new(p: &Params) -> WbTopModel {
        WbTopModel {
            core: CoreModel::new(p),
            regs: WbRegsModel::new(p),
            speed_bits: p.speed_bits(),
        }
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: &WbTopInputs) -> WbTopOutputs {
        // Both sides from the other's outputs before the edge.
        let cfg = self.regs.outputs();
        let status = core_status(&self.core.outputs(), self.speed_bits);
        self.core.step(core_inputs(inp, &cfg));
        self.regs.step(&WbRegsInputs {
            reset: inp.reset,
            sample: inp.sample,
            bus: inp.bus,
            status,
        });
        self.outputs()
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> WbTopOutputs {
        let r = self.regs.outputs();
        WbTopOutputs {
            wb_ack_o: r.wb_ack_o,
            wb_dat_o: r.wb_dat_o,
            irq: r.irq,
        }
    }

    /// The core's outputs as they stand (internal signals of `encspeed_wb`).
    pub fn core_outputs(&self) -> CoreOutputs {
        self.core.outputs()
    }

    /// The register file's outputs as they stand: the core's configuration inputs for the
    /// next edge (internal signals of `encspeed_wb`).
    pub fn regs_outputs(&self) -> WbRegsOutputs {
        self.regs.outputs()
    }

    /// The core model.
    pub fn core(&self) -> &CoreModel {
        &self.core
    }

    /// The register file model.
    pub fn regs(&self) -> &WbRegsModel {
        &self.regs
    }
}

/// Every port of `encspeed_wb`, in the order of the Verilog module header.
pub fn wb_top_ports() -> Vec<Port> {
    let (i, o) = (Port::input, Port::output);
    let a = ADDR_BITS as u32;
    let d = DATA_BITS as u32;
    let mut v = vec![
        i("clock", 1, "core and bus clock; everything happens at its rising edge"),
        i("reset", 1, "synchronous, active high: resets every register at the edge that samples it, and the core (which registers it) at the edge after; the core also resets at the first edge after power-up"),
    ];
    v.extend(encoder_inputs());
    v.extend([
        i("sample", 1, "synchronous strobe: at the edge that samples it high (unless CTRL.HOLD) the register file takes a coherent snapshot of position, nep, ndt, the speeds and valid/stalled/direction as the core outputs them in that cycle (CTRL.SAMPLED reads it); tie to 0 if unused"),
        i("wb_cyc_i", 1, "Wishbone B4 classic: bus cycle"),
        i("wb_stb_i", 1, "Wishbone: strobe (this slave is addressed)"),
        i("wb_we_i", 1, "Wishbone: 1 = write, 0 = read"),
        i(
            "wb_adr_i",
            a,
            "Wishbone: byte address within the register window; bits 1:0 ignored",
        ),
        i("wb_dat_i", d, "Wishbone: write data"),
        i(
            "wb_sel_i",
            4,
            "Wishbone: byte lanes of a write (lane j = bits 8j+7..8j)",
        ),
        o(
            "wb_dat_o",
            d,
            "Wishbone: read data, valid with wb_ack_o (0 otherwise)",
        ),
        o(
            "wb_ack_o",
            1,
            "Wishbone: acknowledge, high for one cycle from the edge after the request edge",
        ),
        o(
            "irq",
            1,
            "interrupt request, level: (IRQ_STATUS & IRQ_ENABLE) != 0, a register output",
        ),
    ]);
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::regmap;
    use crate::params::Spec;

    fn small() -> Params {
        Params::new(Spec {
            clock_hz: 1e6,
            lines: 100,
            dt_cycles: 200,
            counter_bits: 12,
            timeout_s: 20.0 * 200.0 / 1e6,
            ..Spec::default()
        })
        .unwrap()
    }

    /// One classic access (the request held until the ack, which comes after the second
    /// edge); the ack cycle's outputs.
    fn access(m: &mut WbTopModel, we: bool, adr: u32, dat: u32) -> WbTopOutputs {
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
        assert!(!m.step(&inputs).wb_ack_o, "executed, not yet acknowledged");
        let o = m.step(&inputs);
        assert!(o.wb_ack_o);
        let idle = m.step(&WbTopInputs::default());
        assert!(!idle.wb_ack_o);
        o
    }

    #[test]
    fn a_config_write_reaches_the_core_one_edge_after_the_ack() {
        let mut m = WbTopModel::new(&small());
        m.step(&WbTopInputs {
            reset: true,
            ..Default::default()
        });
        assert_eq!(
            access(&mut m, false, regmap::ID, 0).wb_dat_o,
            regmap::ID_MAGIC
        );
        // Write CFG_DT = 1: the register file shows it after the write edge, the core flags
        // cfg_error one edge later (it registers cfg_error from cfg_dt).
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: true,
            wb_adr_i: regmap::CFG_DT,
            wb_dat_i: 1,
            wb_sel_i: 0xF,
        };
        let inputs = WbTopInputs {
            bus,
            ..Default::default()
        };
        m.step(&inputs);
        assert_eq!(m.regs_outputs().cfg_dt, 1);
        assert!(!m.core_outputs().cfg_error);
        assert!(m.step(&inputs).wb_ack_o);
        assert!(m.core_outputs().cfg_error);
        m.step(&WbTopInputs::default());
        // A STATUS read in the next access sees it.
        let st = access(&mut m, false, regmap::STATUS, 0).wb_dat_o;
        assert_ne!(st & m.regs().map().mask("STATUS", "CFG_ERROR"), 0);
    }

    #[test]
    fn ports_are_named_once_and_the_bus_widths_are_the_maps() {
        let ports = wb_top_ports();
        let names: Vec<&str> = ports.iter().map(|p| p.name).collect();
        let mut sorted = names.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), names.len());
        let w = |n: &str| ports.iter().find(|p| p.name == n).unwrap().width;
        assert_eq!((w("wb_adr_i"), w("wb_dat_o"), w("wb_sel_i")), (8, 32, 4));
    }
}
