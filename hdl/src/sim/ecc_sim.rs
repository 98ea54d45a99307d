// SPDX-License-Identifier: MIT OR Apache-2.0
//! The rust-hdl `encspeed_ecc` ([`crate::EncspeedEcc`]) driven cycle by cycle, in the form
//! of [`golden::top::ecc_top::EccTopModel::step`], for any counter width.

use crate::sim::core_sim::{core_outputs, signed};
use crate::top::ecc_top::EncspeedEcc;
use golden::ecc::ident_gatherer::GatherOutputs;
use golden::params::Params;
use golden::top::ecc_top::{EccTopInputs, EccTopOutputs, IDENT_SUM_BITS};
use rust_hdl::prelude::*;

/// Module name of the emitted top.
pub const ECC_TOP_MODULE: &str = "encspeed_ecc";

/// A simulated `encspeed_ecc` of any counter width.
pub trait EccSim {
    /// One rising clock edge with `inp` applied; the outputs after it.
    fn step(&mut self, inp: &EccTopInputs) -> EccTopOutputs;
    /// The Verilog of this top, module `encspeed_ecc`.
    fn verilog(&self) -> String;
}

struct Driven<const N: usize, const P: usize, const S: usize, const CW: usize> {
    uut: EncspeedEcc<N, P, S, CW>,
}

impl<const N: usize, const P: usize, const S: usize, const CW: usize> Driven<N, P, S, CW> {
    fn settle(&mut self) {
        assert!(simulate(&mut self.uut, 100), "design did not settle");
    }
}

/// The 32-bit port value of a Q15.16 coefficient (two's complement).
fn coef_port(v: i64) -> Bits<32> {
    assert!(
        (-(1i64 << 31)..(1i64 << 31)).contains(&v),
        "coefficient {v} does not fit 32 bits"
    );
    ((v as u64) & 0xffff_ffff).into()
}

/// An identification sum's port value, two's complement (Σ T is never negative, so the
/// same reading serves it).
fn sum(raw: u128) -> i128 {
    let shift = 128 - IDENT_SUM_BITS;
    ((raw << shift) as i128) >> shift
}

impl<const N: usize, const P: usize, const S: usize, const CW: usize> EccSim
    for Driven<N, P, S, CW>
{
    fn step(&mut self, inp: &EccTopInputs) -> EccTopOutputs {
        let c = &inp.core;
        let u = &mut self.uut;
        u.reset.next = c.reset;
        u.enc_a.next = c.enc_a;
        u.enc_b.next = c.enc_b;
        u.enc_z.next = c.enc_z;
        u.cfg_dt.next = c.cfg_dt.into();
        u.cfg_timeout.next = c.cfg_timeout.into();
        u.cfg_filter.next = c.cfg_filter.into();
        u.cfg_mode.next = u64::from(c.cfg_mode).into();
        u.cfg_z_mode.next = u64::from(c.cfg_z_mode).into();
        u.clear_faults.next = c.clear_faults;
        u.ecc_c.next = coef_port(inp.ecc_c);
        u.ecc_d.next = coef_port(inp.ecc_d);
        u.ident_arm.next = inp.ident_arm;
        u.clock.next = Clock { clk: false };
        self.settle();
        self.uut.clock.next = Clock { clk: true };
        self.settle();
        let u = &self.uut;
        EccTopOutputs {
            core: core_outputs(&u.core),
            speed_mtc: signed(u.speed_mtc.val().to_u64(), S),
            mtc_strobe: u.mtc_strobe.val(),
            speed_n3c: signed(u.speed_n3c.val().to_u64(), S),
            n3c_strobe: u.n3c_strobe.val(),
            ident: GatherOutputs {
                done: u.ident_done.val(),
                overflow: u.ident_overflow.val(),
                count: u.ident_count.val().to_u64(),
                t_min: u.ident_t_min.val().to_u64(),
                p_min: u.ident_p_min.val().to_u64(),
                t_max: u.ident_t_max.val().to_u64(),
                p_max: u.ident_p_max.val().to_u64(),
                sum_t: sum(u.ident_sum_t.val().to_u128()),
                sum_sin: sum(u.ident_sum_sin.val().to_u128()),
                sum_cos: sum(u.ident_sum_cos.val().to_u128()),
            },
        }
    }

    fn verilog(&self) -> String {
        crate::verilog::named_verilog(&self.uut, ECC_TOP_MODULE)
    }
}

fn driven<const N: usize, const P: usize, const S: usize, const CW: usize>(
    p: &Params,
) -> Box<dyn EccSim> {
    let mut uut = EncspeedEcc::<N, P, S, CW>::new(p);
    uut.connect_all();
    let mut d = Driven { uut };
    d.settle();
    Box::new(d)
}

/// Dispatch a runtime counter width N to `$f::<N, 2N+1, N+17, corrected_width(N)>`.
macro_rules! ecc_width {
    ($bits:expr, $f:ident, $arg:expr) => {
        match $bits {
            8 => $f::<8, 17, 25, { $crate::ecc::ecc_mt_speed::corrected_width(8) }>($arg),
            9 => $f::<9, 19, 26, { $crate::ecc::ecc_mt_speed::corrected_width(9) }>($arg),
            10 => $f::<10, 21, 27, { $crate::ecc::ecc_mt_speed::corrected_width(10) }>($arg),
            11 => $f::<11, 23, 28, { $crate::ecc::ecc_mt_speed::corrected_width(11) }>($arg),
            12 => $f::<12, 25, 29, { $crate::ecc::ecc_mt_speed::corrected_width(12) }>($arg),
            13 => $f::<13, 27, 30, { $crate::ecc::ecc_mt_speed::corrected_width(13) }>($arg),
            14 => $f::<14, 29, 31, { $crate::ecc::ecc_mt_speed::corrected_width(14) }>($arg),
            15 => $f::<15, 31, 32, { $crate::ecc::ecc_mt_speed::corrected_width(15) }>($arg),
            16 => $f::<16, 33, 33, { $crate::ecc::ecc_mt_speed::corrected_width(16) }>($arg),
            17 => $f::<17, 35, 34, { $crate::ecc::ecc_mt_speed::corrected_width(17) }>($arg),
            18 => $f::<18, 37, 35, { $crate::ecc::ecc_mt_speed::corrected_width(18) }>($arg),
            19 => $f::<19, 39, 36, { $crate::ecc::ecc_mt_speed::corrected_width(19) }>($arg),
            20 => $f::<20, 41, 37, { $crate::ecc::ecc_mt_speed::corrected_width(20) }>($arg),
            21 => $f::<21, 43, 38, { $crate::ecc::ecc_mt_speed::corrected_width(21) }>($arg),
            22 => $f::<22, 45, 39, { $crate::ecc::ecc_mt_speed::corrected_width(22) }>($arg),
            23 => $f::<23, 47, 40, { $crate::ecc::ecc_mt_speed::corrected_width(23) }>($arg),
            24 => $f::<24, 49, 41, { $crate::ecc::ecc_mt_speed::corrected_width(24) }>($arg),
            25 => $f::<25, 51, 42, { $crate::ecc::ecc_mt_speed::corrected_width(25) }>($arg),
            26 => $f::<26, 53, 43, { $crate::ecc::ecc_mt_speed::corrected_width(26) }>($arg),
            27 => $f::<27, 55, 44, { $crate::ecc::ecc_mt_speed::corrected_width(27) }>($arg),
            28 => $f::<28, 57, 45, { $crate::ecc::ecc_mt_speed::corrected_width(28) }>($arg),
            29 => $f::<29, 59, 46, { $crate::ecc::ecc_mt_speed::corrected_width(29) }>($arg),
            30 => $f::<30, 61, 47, { $crate::ecc::ecc_mt_speed::corrected_width(30) }>($arg),
            31 => $f::<31, 63, 48, { $crate::ecc::ecc_mt_speed::corrected_width(31) }>($arg),
            32 => $f::<32, 65, 49, { $crate::ecc::ecc_mt_speed::corrected_width(32) }>($arg),
            other => unreachable!("counter width {other} passed validation"),
        }
    };
}

pub(crate) use ecc_width;

/// The rust-hdl `encspeed_ecc` for `p`, ready to step; an error where
/// [`golden::top::ecc_top::check`] refuses `p`.
pub fn build_ecc(p: &Params) -> Result<Box<dyn EccSim>, String> {
    golden::top::ecc_top::check(p)?;
    Ok(ecc_width!(p.counter_bits(), driven, p))
}
