//! Direct-drive simulation of the rust-hdl core behind a width-independent interface.
//!
//! rust-hdl counter widths are const generics; [`build_core`] picks the instance that
//! matches the validated counter width, so callers (tests, the CLI) never name a width.
//! One [`CoreSim::step`] is one rising clock edge with the inputs applied, exactly as
//! [`golden::bittrue::CoreModel::step`], so the two are compared output for output.

use crate::core::EncspeedCore;
use golden::bittrue::{CoreInputs, CoreOutputs};
use golden::params::Params;
use rust_hdl::core::vcd_probe::{write_vcd_change, write_vcd_header, VCDProbe};
use rust_hdl::prelude::*;
use std::io::Write;

/// Internal counters of the core, read from the rust-hdl signals (for waveforms and
/// cycle-by-cycle comparison with the golden model's registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CoreProbe {
    /// ts counter of the time base.
    pub ts_count: u64,
    /// Encoder pulse `lep` in the cycle just before the last edge.
    pub lep: bool,
}

/// A simulated core of any counter width.
pub trait CoreSim {
    /// One rising clock edge with `inp` applied; the outputs after it.
    fn step(&mut self, inp: &CoreInputs) -> CoreOutputs;
    /// The ts counter after the last edge.
    fn ts_count(&self) -> u64;
    /// Emit the Verilog of this core, top module named `module_name`.
    fn verilog(&self, module_name: &str) -> String;
    /// From now on, write every signal of the design to a VCD (timescale 1 ps, one clock
    /// period of `period_ps`). Call [`CoreSim::finish_vcd`] to flush it.
    fn start_vcd(&mut self, out: Box<dyn Write>, period_ps: u64);
    /// Flush and close the VCD, if one was started.
    fn finish_vcd(&mut self) -> std::io::Result<()>;
}

/// Dispatch a runtime counter width to the const-generic instance `$f::<N>($arg)`.
macro_rules! seq_width {
    ($bits:expr, $f:ident, $arg:expr) => {
        match $bits {
            8 => $f::<8>($arg),
            9 => $f::<9>($arg),
            10 => $f::<10>($arg),
            11 => $f::<11>($arg),
            12 => $f::<12>($arg),
            13 => $f::<13>($arg),
            14 => $f::<14>($arg),
            15 => $f::<15>($arg),
            16 => $f::<16>($arg),
            17 => $f::<17>($arg),
            18 => $f::<18>($arg),
            19 => $f::<19>($arg),
            20 => $f::<20>($arg),
            21 => $f::<21>($arg),
            22 => $f::<22>($arg),
            23 => $f::<23>($arg),
            24 => $f::<24>($arg),
            25 => $f::<25>($arg),
            26 => $f::<26>($arg),
            27 => $f::<27>($arg),
            28 => $f::<28>($arg),
            29 => $f::<29>($arg),
            30 => $f::<30>($arg),
            31 => $f::<31>($arg),
            32 => $f::<32>($arg),
            other => unreachable!("counter width {other} passed validation"),
        }
    };
}

struct Driven<const N: usize> {
    uut: EncspeedCore<N>,
    vcd: Option<VCDProbe<Box<dyn Write>>>,
    period_ps: u64,
    cycle: u64,
}

impl<const N: usize> Driven<N> {
    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 100), "design did not settle");
    }

    fn dump(&mut self, t: u64) {
        if let Some(mut v) = self.vcd.take() {
            v.timestamp(t).expect("VCD write");
            self.vcd = Some(write_vcd_change(v, &self.uut));
        }
    }
}

impl<const N: usize> CoreSim for Driven<N> {
    fn step(&mut self, inp: &CoreInputs) -> CoreOutputs {
        assert!(
            inp.cfg_dt < (1u64 << N),
            "cfg_dt = {} does not fit {N} bits",
            inp.cfg_dt
        );
        let u = &mut self.uut;
        u.reset.next = inp.reset;
        u.enc_a.next = inp.enc_a;
        u.enc_b.next = inp.enc_b;
        u.enc_z.next = inp.enc_z;
        u.cfg_dt.next = inp.cfg_dt.into();
        u.clock.next = Clock { clk: false };
        self.settle();
        let t0 = self.cycle * self.period_ps;
        self.dump(t0 + self.period_ps / 2);
        self.uut.clock.next = Clock { clk: true };
        self.settle();
        self.cycle += 1;
        self.dump(self.cycle * self.period_ps);
        let u = &self.uut;
        CoreOutputs {
            nep: u.nep.val().to_u64(),
            ndt: u.ndt.val().to_u64(),
            update: u.update.val(),
            stalled: u.stalled.val(),
            cfg_error: u.cfg_error.val(),
        }
    }

    fn ts_count(&self) -> u64 {
        self.uut.timebase.ts_count.q.val().to_u64()
    }

    fn verilog(&self, module_name: &str) -> String {
        crate::emit::named_verilog(&self.uut, module_name)
    }

    fn start_vcd(&mut self, out: Box<dyn Write>, period_ps: u64) {
        self.period_ps = period_ps;
        self.vcd = Some(write_vcd_header(out, &self.uut));
        self.dump(self.cycle * period_ps);
    }

    fn finish_vcd(&mut self) -> std::io::Result<()> {
        // VCDProbe owns the writer; dropping it flushes a BufWriter and closes the file.
        self.vcd.take();
        Ok(())
    }
}

fn driven<const N: usize>(p: &Params) -> Box<dyn CoreSim> {
    let mut uut = EncspeedCore::<N>::new(p);
    uut.connect_all();
    let mut d = Driven {
        uut,
        vcd: None,
        period_ps: 10_000,
        cycle: 0,
    };
    d.settle();
    Box::new(d)
}

/// The rust-hdl core for `p`, ready to step (power-up state: every flop 0, as the emitted
/// Verilog's `initial` blocks; apply `reset` before relying on the outputs).
pub fn build_core(p: &Params) -> Box<dyn CoreSim> {
    seq_width!(p.counter_bits(), driven, p)
}
