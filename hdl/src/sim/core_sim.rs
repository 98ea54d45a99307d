// SPDX-License-Identifier: MIT OR Apache-2.0
//! Direct-drive simulation of the rust-hdl core behind a width-independent interface.
//!
//! rust-hdl counter widths are const generics; [`build_core`] picks the instance that
//! matches the validated counter width, so callers (tests, the CLI) never name a width.
//! One [`CoreSim::step`] is one rising clock edge with the inputs applied, exactly as
//! [`golden::top::core::CoreModel::step`], so the two are compared output for output.

use crate::top::core::EncspeedCore;
use golden::params::Params;
use golden::top::core::{CoreInputs, CoreOutputs};
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

/// Dispatch a runtime counter width N to the const-generic instance `$f::<N, 2N+1, N+17>`
/// (the speed calculator's product width and the speed width, with 16 fractional bits).
macro_rules! seq_width {
    ($bits:expr, $f:ident, $arg:expr) => {
        match $bits {
            8 => $f::<8, 17, 25>($arg),
            9 => $f::<9, 19, 26>($arg),
            10 => $f::<10, 21, 27>($arg),
            11 => $f::<11, 23, 28>($arg),
            12 => $f::<12, 25, 29>($arg),
            13 => $f::<13, 27, 30>($arg),
            14 => $f::<14, 29, 31>($arg),
            15 => $f::<15, 31, 32>($arg),
            16 => $f::<16, 33, 33>($arg),
            17 => $f::<17, 35, 34>($arg),
            18 => $f::<18, 37, 35>($arg),
            19 => $f::<19, 39, 36>($arg),
            20 => $f::<20, 41, 37>($arg),
            21 => $f::<21, 43, 38>($arg),
            22 => $f::<22, 45, 39>($arg),
            23 => $f::<23, 47, 40>($arg),
            24 => $f::<24, 49, 41>($arg),
            25 => $f::<25, 51, 42>($arg),
            26 => $f::<26, 53, 43>($arg),
            27 => $f::<27, 55, 44>($arg),
            28 => $f::<28, 57, 45>($arg),
            29 => $f::<29, 59, 46>($arg),
            30 => $f::<30, 61, 47>($arg),
            31 => $f::<31, 63, 48>($arg),
            32 => $f::<32, 65, 49>($arg),
            other => unreachable!("counter width {other} passed validation"),
        }
    };
}
pub(crate) use seq_width;

struct Driven<const N: usize, const P: usize, const S: usize> {
    uut: EncspeedCore<N, P, S>,
    vcd: Option<VCDProbe<Box<dyn Write>>>,
    period_ps: u64,
    cycle: u64,
}

impl<const N: usize, const P: usize, const S: usize> Driven<N, P, S> {
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

impl<const N: usize, const P: usize, const S: usize> CoreSim for Driven<N, P, S> {
    fn step(&mut self, inp: &CoreInputs) -> CoreOutputs {
        assert!(
            inp.cfg_dt < (1u64 << N) && inp.cfg_timeout < (1u64 << N),
            "cfg_dt = {} or cfg_timeout = {} does not fit {N} bits",
            inp.cfg_dt,
            inp.cfg_timeout
        );
        let u = &mut self.uut;
        u.reset.next = inp.reset;
        u.enc_a.next = inp.enc_a;
        u.enc_b.next = inp.enc_b;
        u.enc_z.next = inp.enc_z;
        u.cfg_dt.next = inp.cfg_dt.into();
        u.cfg_timeout.next = inp.cfg_timeout.into();
        u.cfg_filter.next = inp.cfg_filter.into();
        u.cfg_mode.next = u64::from(inp.cfg_mode).into();
        u.cfg_z_mode.next = u64::from(inp.cfg_z_mode).into();
        u.clear_faults.next = inp.clear_faults;
        u.clock.next = Clock { clk: false };
        self.settle();
        let t0 = self.cycle * self.period_ps;
        self.dump(t0 + self.period_ps / 2);
        self.uut.clock.next = Clock { clk: true };
        self.settle();
        self.cycle += 1;
        self.dump(self.cycle * self.period_ps);
        core_outputs(&self.uut)
    }

    fn ts_count(&self) -> u64 {
        // The block keeps count + 2 mod 2^N.
        let ts_plus_two = self.uut.timebase.ts_plus_two.q.val().to_u64();
        ts_plus_two.wrapping_sub(2) & ((1u64 << N) - 1)
    }

    fn verilog(&self, module_name: &str) -> String {
        crate::verilog::named_verilog(&self.uut, module_name)
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

/// The outputs of a rust-hdl core as they stand, in the golden model's form (the core
/// harness and the tops that embed the core share it).
pub fn core_outputs<const N: usize, const P: usize, const S: usize>(
    u: &EncspeedCore<N, P, S>,
) -> CoreOutputs {
    let speed = |b: Bits<S>| signed(b.to_u64(), S);
    CoreOutputs {
        position: u.position.val().to_u64(),
        z_latch: u.z_latch.val().to_u64(),
        index: u.index.val(),
        direction: u.direction.val(),
        nep: u.nep.val().to_u64(),
        ndt: u.ndt.val().to_u64(),
        update: u.update.val(),
        speed_n1: speed(u.speed_n1.val()),
        speed_n2: speed(u.speed_n2.val()),
        speed_n3: speed(u.speed_n3.val()),
        speed_strobe: u.speed_strobe.val(),
        speed_pc: speed(u.speed_pc.val()),
        speed_et: speed(u.speed_et.val()),
        speed_mt: speed(u.speed_mt.val()),
        baseline_strobe: u.baseline_strobe.val(),
        valid: u.valid.val(),
        stalled: u.stalled.val(),
        fault_illegal: u.fault_illegal.val(),
        fault_overspeed: u.fault_overspeed.val(),
        fault_revolution: u.fault_revolution.val(),
        cfg_error: u.cfg_error.val(),
        glitch_count: u.glitch_count.val().to_u64(),
        illegal_count: u.illegal_count.val().to_u64(),
        rev_error_count: u.rev_error_count.val().to_u64(),
        speed_position: u.speed_position.val().to_u64(),
        speed_nep: u.speed_nep.val().to_u64(),
        speed_ndt: u.speed_ndt.val().to_u64(),
        mt_strobe: u.mt_strobe.val(),
        mt_m: u.mt_m.val().to_u64(),
        mt_t: u.mt_t.val().to_u64(),
        mt_negative: u.mt_negative.val(),
        dt_active: u.dt_active.val().to_u64(),
    }
}

/// The two's complement value of the low `bits` bits of `raw`.
pub fn signed(raw: u64, bits: usize) -> i64 {
    let sh = 64 - bits as u32;
    ((raw << sh) as i64) >> sh
}

fn driven<const N: usize, const P: usize, const S: usize>(p: &Params) -> Box<dyn CoreSim> {
    let mut uut = EncspeedCore::<N, P, S>::new(p);
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
