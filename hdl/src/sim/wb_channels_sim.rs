// SPDX-License-Identifier: MIT OR Apache-2.0
//! Direct-drive simulation of `encspeed_wb` with several channels
//! ([`crate::top::wb_channels::EncspeedWbChannels`]) of any counter width and channel count,
//! stepped edge for edge like [`golden::top::wb_channels::WbChannelsModel`].

use crate::top::wb_channels::EncspeedWbChannels;
use golden::params::Params;
use golden::top::core::CoreOutputs;
use golden::top::wb_channels::{address_bits, WbChannelsInputs, WbChannelsOutputs};
use rust_hdl::prelude::*;

/// A simulated several-channel `encspeed_wb` (direct drive).
pub trait WbChannelsSim {
    /// One rising clock edge with `inp` applied; the outputs after it, as
    /// [`golden::top::wb_channels::WbChannelsModel::step`].
    fn step(&mut self, inp: &WbChannelsInputs) -> WbChannelsOutputs;
    /// Channel `c`'s core outputs after the last edge (internal signals).
    fn core_outputs(&self, c: usize) -> CoreOutputs;
    /// The Verilog of this design, top module named `module_name`.
    fn verilog(&self, module_name: &str) -> String;
}

struct Driven<
    const N: usize,
    const P: usize,
    const S: usize,
    const CH: usize,
    const B: usize,
    const A: usize,
> {
    uut: EncspeedWbChannels<N, P, S, CH, B, A>,
}

impl<
        const N: usize,
        const P: usize,
        const S: usize,
        const CH: usize,
        const B: usize,
        const A: usize,
    > Driven<N, P, S, CH, B, A>
{
    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 100), "design did not settle");
    }
}

impl<
        const N: usize,
        const P: usize,
        const S: usize,
        const CH: usize,
        const B: usize,
        const A: usize,
    > WbChannelsSim for Driven<N, P, S, CH, B, A>
{
    fn step(&mut self, inp: &WbChannelsInputs) -> WbChannelsOutputs {
        let b = &inp.bus;
        assert!(
            b.wb_adr_i >> address_bits(CH as u32) == 0
                && b.wb_sel_i < 16
                && [inp.enc_a, inp.enc_b, inp.enc_z]
                    .iter()
                    .all(|e| u32::from(*e) >> CH == 0),
            "input out of range for {CH} channels: {inp:?}"
        );
        let u = &mut self.uut;
        u.reset.next = inp.reset;
        u.enc_a.next = u64::from(inp.enc_a).into();
        u.enc_b.next = u64::from(inp.enc_b).into();
        u.enc_z.next = u64::from(inp.enc_z).into();
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
        WbChannelsOutputs {
            wb_dat_o: u.wb_dat_o.val().to_u64() as u32,
            wb_ack_o: u.wb_ack_o.val(),
            irq: u.irq.val().to_u64() as u8,
        }
    }

    fn core_outputs(&self, c: usize) -> CoreOutputs {
        crate::sim::core_sim::core_outputs(&self.uut.channels[c].core)
    }

    fn verilog(&self, module_name: &str) -> String {
        crate::verilog::named_verilog(&self.uut, module_name)
    }
}

fn boxed<
    const N: usize,
    const P: usize,
    const S: usize,
    const CH: usize,
    const B: usize,
    const A: usize,
>(
    p: &Params,
) -> Box<dyn WbChannelsSim> {
    let mut uut = EncspeedWbChannels::<N, P, S, CH, B, A>::new(p);
    uut.connect_all();
    let mut d = Driven { uut };
    d.settle();
    Box::new(d)
}

/// The counter width's dispatch picks N, P, S; this one the channels CH with their channel
/// bits B and address width A = 8 + B.
fn driven<const N: usize, const P: usize, const S: usize>(p: &Params) -> Box<dyn WbChannelsSim> {
    match p.channels() {
        2 => boxed::<N, P, S, 2, 1, 9>(p),
        3 => boxed::<N, P, S, 3, 2, 10>(p),
        4 => boxed::<N, P, S, 4, 2, 10>(p),
        5 => boxed::<N, P, S, 5, 3, 11>(p),
        6 => boxed::<N, P, S, 6, 3, 11>(p),
        7 => boxed::<N, P, S, 7, 3, 11>(p),
        8 => boxed::<N, P, S, 8, 3, 11>(p),
        other => panic!("channels = {other}: the several-channel top takes 2..=8"),
    }
}

/// The rust-hdl several-channel `encspeed_wb` for `p` (`p.channels()` ≥ 2), ready to step
/// (power-up state: every flop 0, as the emitted Verilog's; apply `reset` before relying on
/// the outputs).
pub fn build_wb_channels(p: &Params) -> Box<dyn WbChannelsSim> {
    crate::sim::core_sim::seq_width!(p.counter_bits(), driven, p)
}
