// SPDX-License-Identifier: MIT OR Apache-2.0
//! Direct-drive simulation of `encspeed_wb` ([`crate::top::wb_top::EncspeedWb`]) of any counter
//! width, stepped edge for edge like [`golden::top::wb_top::WbTopModel`].

use crate::bus::wb_regs::WbRegs;
use crate::top::wb_top::EncspeedWb;
use golden::bus::regmap::ADDR_BITS;
use golden::bus::wb_regs::WbRegsOutputs;
use golden::params::Params;
use golden::params::{ERROR_COUNT_BITS, FILTER_BITS, POSITION_BITS};
use golden::top::core::CoreOutputs;
use golden::top::wb_top::{WbTopInputs, WbTopOutputs};
use rust_hdl::prelude::*;

const C: usize = POSITION_BITS as usize;
const FB: usize = FILTER_BITS as usize;
const G: usize = ERROR_COUNT_BITS as usize;

/// A simulated `encspeed_wb` of any counter width (direct drive).
pub trait WbSim {
    /// One rising clock edge with `inp` applied; the outputs after it, as
    /// [`golden::top::wb_top::WbTopModel::step`].
    fn step(&mut self, inp: &WbTopInputs) -> WbTopOutputs;
    /// The core's outputs after the last edge (internal signals).
    fn core_outputs(&self) -> CoreOutputs;
    /// The register file's configuration outputs after the last edge (internal signals).
    fn regs_outputs(&self) -> WbRegsOutputs;
    /// The Verilog of this design, top module named `module_name`.
    fn verilog(&self, module_name: &str) -> String;
}

struct Driven<const N: usize, const P: usize, const S: usize> {
    uut: EncspeedWb<N, P, S>,
}

impl<const N: usize, const P: usize, const S: usize> Driven<N, P, S> {
    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 100), "design did not settle");
    }
}

impl<const N: usize, const P: usize, const S: usize> WbSim for Driven<N, P, S> {
    fn step(&mut self, inp: &WbTopInputs) -> WbTopOutputs {
        let b = &inp.bus;
        assert!(
            b.wb_adr_i >> ADDR_BITS == 0 && b.wb_sel_i < 16,
            "bus input out of range: {b:?}"
        );
        let u = &mut self.uut;
        u.reset.next = inp.reset;
        u.enc_a.next = inp.enc_a;
        u.enc_b.next = inp.enc_b;
        u.enc_z.next = inp.enc_z;
        u.sample.next = inp.sample;
        u.wb_cyc_i.next = b.wb_cyc_i;
        u.wb_stb_i.next = b.wb_stb_i;
        u.wb_we_i.next = b.wb_we_i;
        u.wb_adr_i.next = u64::from(b.wb_adr_i).into();
        u.wb_dat_i.next = u64::from(b.wb_dat_i).into();
        u.wb_sel_i.next = u64::from(b.wb_sel_i).into();
        u.clock.next = Clock { clk: false };
        self.settle();
        self.uut.clock.next = Clock { clk: true };
        self.settle();
        let u = &self.uut;
        WbTopOutputs {
            wb_ack_o: u.wb_ack_o.val(),
            wb_dat_o: u.wb_dat_o.val().to_u64() as u32,
            irq: u.irq.val(),
        }
    }

    fn core_outputs(&self) -> CoreOutputs {
        crate::sim::core_sim::core_outputs(&self.uut.core)
    }

    fn regs_outputs(&self) -> WbRegsOutputs {
        regs_outputs(&self.uut.regs)
    }

    fn verilog(&self, module_name: &str) -> String {
        crate::verilog::named_verilog(&self.uut, module_name)
    }
}

/// The outputs of a simulated register file after the last edge.
pub(crate) fn regs_outputs<const N: usize, const S: usize>(
    r: &WbRegs<N, S, C, FB, G>,
) -> WbRegsOutputs {
    WbRegsOutputs {
        wb_ack_o: r.wb_ack_o.val(),
        wb_dat_o: r.wb_dat_o.val().to_u64() as u32,
        irq: r.irq.val(),
        cfg_dt: r.cfg_dt.val().to_u64(),
        cfg_timeout: r.cfg_timeout.val().to_u64(),
        cfg_filter: r.cfg_filter.val().to_u64(),
        cfg_mode: r.cfg_mode.val().to_u64() as u8,
        cfg_z_mode: r.cfg_z_mode.val().to_u64() as u8,
        clear_faults: r.clear_faults.val(),
    }
}

fn driven<const N: usize, const P: usize, const S: usize>(p: &Params) -> Box<dyn WbSim> {
    let mut uut = EncspeedWb::<N, P, S>::new(p);
    uut.connect_all();
    let mut d = Driven { uut };
    d.settle();
    Box::new(d)
}

/// The rust-hdl `encspeed_wb` for `p`, ready to step (power-up state: every flop 0, as
/// the emitted Verilog's; apply `reset` before relying on the outputs).
pub fn build_wb(p: &Params) -> Box<dyn WbSim> {
    // The same width dispatch as `crate::sim::core_sim::build_core` (N → <N, 2N + 1, N + 17>).
    crate::sim::core_sim::seq_width!(p.counter_bits(), driven, p)
}
