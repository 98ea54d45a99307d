// SPDX-License-Identifier: MIT OR Apache-2.0
//! Direct-drive simulation of a board top ([`crate::board::board_top::EncspeedBoard`]) of
//! any counter width, one rising edge per [`BoardSim::step`].

use crate::board::board_top::EncspeedBoard;
use golden::board::boards::{Board, BoardInputs, BoardOutputs};
use golden::board::uart::UartTiming;
use golden::params::Params;
use rust_hdl::prelude::*;

/// A simulated board top of any counter width (direct drive).
pub trait BoardSim {
    /// One rising clock edge with `inp` applied; the outputs after it.
    fn step(&mut self, inp: &BoardInputs) -> BoardOutputs;
    /// The Verilog of this design, top module named `module_name`.
    fn verilog(&self, module_name: &str) -> String;
}

struct Driven<const N: usize, const P: usize, const S: usize> {
    uut: EncspeedBoard<N, P, S>,
}

impl<const N: usize, const P: usize, const S: usize> Driven<N, P, S> {
    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 100), "design did not settle");
    }
}

impl<const N: usize, const P: usize, const S: usize> BoardSim for Driven<N, P, S> {
    fn step(&mut self, inp: &BoardInputs) -> BoardOutputs {
        let u = &mut self.uut;
        u.rx.next = inp.rx;
        u.enc_a.next = inp.enc_a;
        u.enc_b.next = inp.enc_b;
        u.enc_z.next = inp.enc_z;
        u.clock.next = Clock { clk: false };
        self.settle();
        self.uut.clock.next = Clock { clk: true };
        self.settle();
        BoardOutputs {
            tx: self.uut.tx.val(),
            led: self.uut.led.val().to_u64() as u8,
        }
    }

    fn verilog(&self, module_name: &str) -> String {
        crate::verilog::named_verilog(&self.uut, module_name)
    }
}

fn driven<const N: usize, const P: usize, const S: usize>(
    (p, uart): (&Params, &UartTiming),
) -> Box<dyn BoardSim> {
    let mut uut = EncspeedBoard::<N, P, S>::new(p, uart);
    uut.connect_all();
    let mut d = Driven { uut };
    d.settle();
    Box::new(d)
}

/// The rust-hdl top of `board` with its IP of validated parameters `p` (from
/// [`Board::params`]), at the power-up state (every flop 0, as after the FPGA's
/// configuration and as the emitted Verilog's `initial` values).
pub fn build_board(board: Board, p: &Params) -> Box<dyn BoardSim> {
    let uart = board.uart();
    crate::sim::core_sim::seq_width!(p.counter_bits(), driven, (p, &uart))
}
