// SPDX-License-Identifier: MIT OR Apache-2.0
//! Direct-drive simulation of `encspeed_ecc_wb` ([`crate::top::ecc_wb_top::EncspeedEccWb`]) of
//! any counter width, stepped edge for edge like [`golden::top::ecc_wb_top::EccWbTopModel`].

use crate::top::ecc_wb_top::EncspeedEccWb;
use golden::bus::ecc_regs::EccRegsOutputs;
use golden::bus::regmap::ADDR_BITS;
use golden::bus::wb_regs::WbRegsOutputs;
use golden::params::Params;
use golden::top::wb_top::{WbTopInputs, WbTopOutputs};
use rust_hdl::prelude::*;

/// A simulated `encspeed_ecc_wb` of any counter width (direct drive).
pub trait EccWbSim {
    /// One rising clock edge with `inp` applied; the outputs after it, as
    /// [`golden::top::ecc_wb_top::EccWbTopModel::step`].
    fn step(&mut self, inp: &WbTopInputs) -> WbTopOutputs;
    /// The register file's outputs after the last edge (internal signals).
    fn regs_outputs(&self) -> WbRegsOutputs;
    /// The window's outputs after the last edge (internal signals).
    fn window_outputs(&self) -> EccRegsOutputs;
    /// The Verilog of this design, top module `encspeed_ecc_wb`.
    fn verilog(&self) -> String;
}

struct Driven<const N: usize, const P: usize, const S: usize, const CW: usize> {
    uut: EncspeedEccWb<N, P, S, CW>,
}

impl<const N: usize, const P: usize, const S: usize, const CW: usize> Driven<N, P, S, CW> {
    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 100), "design did not settle");
    }
}

impl<const N: usize, const P: usize, const S: usize, const CW: usize> EccWbSim
    for Driven<N, P, S, CW>
{
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

    fn regs_outputs(&self) -> WbRegsOutputs {
        crate::sim::wb_sim::regs_outputs(&self.uut.regs)
    }

    fn window_outputs(&self) -> EccRegsOutputs {
        let w = &self.uut.window;
        EccRegsOutputs {
            wb_ack_o: w.wb_ack_o.val(),
            wb_dat_o: w.wb_dat_o.val().to_u64() as u32,
            irq: w.irq.val(),
            ecc_c: w.ecc_c.val().to_u64() as u32,
            ecc_d: w.ecc_d.val().to_u64() as u32,
            ident_arm: w.ident_arm.val(),
        }
    }

    fn verilog(&self) -> String {
        crate::verilog::named_verilog(&self.uut, golden::top::ecc_wb_top::ECC_WB_TOP_MODULE)
    }
}

fn driven<const N: usize, const P: usize, const S: usize, const CW: usize>(
    p: &Params,
) -> Box<dyn EccWbSim> {
    let mut uut = EncspeedEccWb::<N, P, S, CW>::new(p);
    uut.connect_all();
    let mut d = Driven { uut };
    d.settle();
    Box::new(d)
}

/// The rust-hdl `encspeed_ecc_wb` for `p`, ready to step (power-up state: every flop 0;
/// apply `reset` first); an error where [`golden::top::ecc_top::check`] refuses `p`.
pub fn build_ecc_wb(p: &Params) -> Result<Box<dyn EccWbSim>, String> {
    golden::top::ecc_top::check(p)?;
    // The width dispatch of `crate::sim::ecc_sim::build_ecc`.
    Ok(crate::sim::ecc_sim::ecc_width!(p.counter_bits(), driven, p))
}
