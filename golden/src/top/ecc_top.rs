// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of `encspeed_ecc`: `encspeed_core` with the eccentricity-corrected M/T
//! speed ([`crate::ecc::mt_corrector`]) of every window, from runtime coefficients `ecc_c`,
//! `ecc_d` (c = E·cos θ0, d = E·sin θ0, Q15.16 lines: [`crate::ecc::ecc_delta::coefficients`]).
//!
//! Every output of the core is an output of the top, unchanged. Added: `speed_mtc` (format
//! of `speed_mt`) and `mtc_strobe`, [`crate::ecc::mt_corrector::latency_cycles`] edges after the
//! `mt_strobe` of the window (164 at N = 24), while `speed_mt` of the same window comes at
//! `baseline_strobe`. A window closing while the corrector is busy replaces a pending one
//! (the latest wins): with dt at least the latency, every window is corrected.
//! `reset` and a change of `cfg_mode` reset the corrector as they reset the core.
//!
//! **Identification.** A [`LineTap`] takes the line edges (forward, one per line) from the
//! core's `position` and `direction`, with their line numbers and periods, and feeds an
//! [`IdentGatherer`] (K = lines, A = [`LINE_BITS`], T = [`PERIOD_BITS`], W = 72) whose
//! `index` is the core's `index`: a pulse on `ident_arm` gathers the next revolution (index
//! to index) and raises `ident.done` ([`crate::ecc::ident_gatherer`] gives the timing). The
//! gatherer needs the position aligned by an index (the contract of [`crate::ecc::line_tap`]),
//! so the top keeps `aligned` (an index since reset or a change of `cfg_mode`) and holds an
//! arm that comes before it (`arm_pending`) until the aligning index: the gatherer is armed
//! in that index's cycle and gathers from the next one. `ident_done` clears when the
//! gatherer is armed.
//! [`crate::ecc::ident_gatherer::identify_from_sums`] turns the sums into e and θ0 in the frame
//! of the core's position, the frame of `ecc_c`/`ecc_d`. `reset` and a change of
//! `cfg_mode` reset both.
//!
//! **Without the identification** ([`Params::identification`] false, `generate
//! --no-identification`): every `ident_*` output reads 0 at every cycle and `ident_arm` does
//! nothing; every other output is that of the full top, cycle for cycle (the hardware ties
//! the ports to 0 and synthesis removes the tap and the gatherer).

use crate::baselines::baseline_speeds::BaselineFormat;
use crate::ecc::ident_gatherer::{GatherInputs, GatherOutputs, IdentGatherer};
use crate::ecc::line_tap::{LineTap, LINE_BITS, PERIOD_BITS};
use crate::ecc::mt_corrector::{MtCorrectorModel, MtJob};
use crate::ecc::n3_corrector::{N3CorrectorModel, N3Job};
use crate::params::{Params, SPEED_FRAC_BITS};
use crate::top::core::{mode_shift, CoreInputs, CoreModel, CoreOutputs};
use crate::top::mode_reset::ModeReset;
use crate::top::port_fields::{visit_fields, PortFields, PortValue};
use serde::{Deserialize, Serialize};

/// Address and data bits of the corrector's sine table (K entries of 24 bits, addressed
/// with 16 bits: any K ≤ 2^16).
pub fn table_bits() -> (u32, u32) {
    (TABLE_ADDRESS_BITS, TABLE_DATA_BITS)
}

/// Address width of the sine table.
pub const TABLE_ADDRESS_BITS: u32 = 16;

/// Width of the sine table's entries.
pub const TABLE_DATA_BITS: u32 = 24;

/// Edges from the one that raises the core's closing `index` to the one that raises
/// `ident.done`: the gatherer samples `index` at the next edge and registers `done` at the
/// one after ([`crate::ecc::ident_gatherer`]).
pub const IDENT_DONE_AFTER_INDEX: u64 = 2;

/// Edges from the one that raises the core's `mt_strobe` to the one that raises
/// `mtc_strobe` with that window's corrected speed: the corrector samples the strobe at the
/// next edge and its latency (from that sampling edge) follows
/// ([`crate::ecc::mt_corrector::latency_cycles`]).
pub fn mtc_after_mt_strobe(p: &Params) -> u64 {
    1 + u64::from(crate::ecc::mt_corrector::latency_cycles(
        p.counter_bits(),
        p.speed_frac_bits(),
    ))
}

/// Edges from the one that raises the core's `speed_strobe` to the one that raises
/// `n3c_strobe` with that n3 corrected (sampled at the next edge, as for
/// [`mtc_after_mt_strobe`]).
pub fn n3c_after_speed_strobe(p: &Params) -> u64 {
    1 + u64::from(crate::ecc::n3_corrector::latency_cycles(p.counter_bits()))
}

/// Width of the identification sums (defined beside the tap's widths it derives from).
pub use crate::ecc::line_tap::IDENT_SUM_BITS;

// The table holds one entry per line: its address width bounds the line count.
const _: () = assert!(crate::params::ECC_MAX_LINES as u64 == 1u64 << TABLE_ADDRESS_BITS);

/// Why `p` cannot have the eccentricity corrector ([`Params::check_ecc`]), or Ok.
pub fn check(p: &Params) -> Result<(), String> {
    p.check_ecc().map_err(|e| format!("encspeed_ecc: {e}"))
}

/// Inputs of `encspeed_ecc` in one cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct EccTopInputs {
    /// The core's inputs.
    pub core: CoreInputs,
    /// c = E·cos θ0, Q15.16 lines (value; the port is 32-bit two's complement).
    pub ecc_c: i64,
    /// d = E·sin θ0, Q15.16 lines.
    pub ecc_d: i64,
    /// Gather the next revolution for the identification (a one-cycle pulse).
    pub ident_arm: bool,
}

/// Outputs of `encspeed_ecc` after a rising edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct EccTopOutputs {
    /// The core's outputs.
    pub core: CoreOutputs,
    /// Corrected M/T speed (format of `speed_mt`), held.
    pub speed_mtc: i64,
    /// One cycle: `speed_mtc` was just written.
    pub mtc_strobe: bool,
    /// Corrected n3 (format of `speed_n3`), held.
    pub speed_n3c: i64,
    /// One cycle: `speed_n3c` was just written.
    pub n3c_strobe: bool,
    /// The identification gatherer's results (`ident_*` ports).
    pub ident: GatherOutputs,
}

impl PortFields for EccTopInputs {
    fn visit_ports(&mut self, visit: &mut dyn FnMut(&'static str, &mut dyn PortValue)) {
        self.core.visit_ports(visit);
        visit_fields!(visit, self, "": ecc_c, ecc_d, ident_arm);
    }
}

impl PortFields for EccTopOutputs {
    fn visit_ports(&mut self, visit: &mut dyn FnMut(&'static str, &mut dyn PortValue)) {
        self.core.visit_ports(visit);
        visit_fields!(visit, self, "": speed_mtc, mtc_strobe, speed_n3c, n3c_strobe);
        // The gatherer's results are named without the `ident_` of their ports.
        visit_fields!(visit, self.ident, "ident_":
            done, overflow, count, t_min, p_min, t_max, p_max, sum_t, sum_sin, sum_cos);
    }
}

/// Cycle model of `encspeed_ecc`.
#[derive(Clone, Debug)]
pub struct EccTopModel {
    core: CoreModel,
    mtc: MtCorrectorModel,
    n3c: N3CorrectorModel,
    line_tap: LineTap,
    gatherer: IdentGatherer,
    counts_per_rev: [u64; 3],
    aligned: bool,
    arm_pending: bool,
    mode_reset: ModeReset,
    /// `identification`: without it the gatherer's results read 0 (module docs).
    identification: bool,
}

impl EccTopModel {
    /// The top for validated parameters, in its state after reset. Panics where [`check`]
    /// refuses `p`.
    pub fn new(p: &Params) -> Self {
        check(p).unwrap_or_else(|e| panic!("{e}"));
        let format = BaselineFormat::new(p.counter_bits(), SPEED_FRAC_BITS)
            .expect("validated parameters give a legal baseline format");
        Self {
            core: CoreModel::new(p),
            mtc: MtCorrectorModel::new(p.lines(), table_bits(), format),
            n3c: N3CorrectorModel::new(p.lines(), table_bits(), p.counter_bits(), p.speed_bits()),
            line_tap: LineTap::new(),
            gatherer: IdentGatherer::new(p.lines(), LINE_BITS, PERIOD_BITS),
            counts_per_rev: [0, 1, 2].map(|s| p.counts_per_rev(s)),
            aligned: false,
            arm_pending: false,
            mode_reset: ModeReset::new(),
            identification: p.identification(),
        }
    }

    /// One rising edge with `inp`; the outputs after it.
    pub fn step(&mut self, inp: EccTopInputs) -> EccTopOutputs {
        let c = &inp.core;
        let before = self.core.outputs();
        // The core's reset and mode, from the same registered rule.
        let rst = self.mode_reset.rst();
        let shift = mode_shift(self.mode_reset.mode());
        self.mode_reset.step(c.reset, c.cfg_mode);
        let job = before.mt_strobe.then_some(MtJob {
            position: before.position,
            mt_m: before.mt_m,
            mt_t: before.mt_t,
            mt_negative: before.mt_negative,
            cfg_dt: before.dt_active,
            mode_shift: shift,
            coef_c: inp.ecc_c,
            coef_d: inp.ecc_d,
        });
        let n3_job = before.speed_strobe.then_some(N3Job {
            n3: before.speed_n3,
            position: before.speed_position,
            nep: before.speed_nep,
            ndt: before.speed_ndt,
            mode_shift: shift,
            coef_c: inp.ecc_c,
            coef_d: inp.ecc_d,
        });
        let mtc = self.mtc.step(rst, job);
        let n3c = self.n3c.step(rst, n3_job);
        let counts_per_rev = self.counts_per_rev[shift as usize];
        let tap = self
            .line_tap
            .outputs(before.position, before.direction, shift, counts_per_rev);
        // An arm before the aligning index waits for it (module docs).
        let arm_now = (inp.ident_arm || self.arm_pending) && (self.aligned || before.index);
        self.arm_pending = (inp.ident_arm || self.arm_pending) && !arm_now;
        self.aligned |= before.index;
        if rst {
            self.aligned = false;
            self.arm_pending = false;
        }
        let ident = self.gatherer.step(GatherInputs {
            reset: rst,
            arm: arm_now,
            index: before.index,
            line: tap.line,
            position: tap.line_position,
            period: tap.period,
        });
        self.line_tap.step(
            rst,
            before.position,
            before.direction,
            shift,
            counts_per_rev,
        );
        let core = self.core.step(inp.core);
        EccTopOutputs {
            core,
            speed_mtc: mtc.speed_mtc,
            mtc_strobe: mtc.valid,
            speed_n3c: n3c.n3c,
            n3c_strobe: n3c.valid,
            // Built without the identification: its ports read 0 (the gatherer runs on
            // here only so that the model stays one model).
            ident: if self.identification {
                ident
            } else {
                GatherOutputs::default()
            },
        }
    }
}

/// Per-cycle inputs of a run on an eccentric disc, one per cycle: the levels of `changes`
/// (from [`crate::eccentric::motion::EccentricDisc::clock_changes`]) for `cycles` cycles,
/// reset for the first 3, `config` giving the configuration and the coefficients held
/// throughout. An iterator, so that runs of 10^8 cycles need no storage.
pub fn disc_inputs(
    initial: crate::ideal::plant::Sample,
    changes: &[(u64, crate::ideal::plant::Sample)],
    cycles: u64,
    config: EccTopInputs,
) -> impl Iterator<Item = EccTopInputs> + '_ {
    let mut levels = initial;
    let mut next = 0;
    (0..cycles).map(move |k| {
        while next < changes.len() && changes[next].0 <= k {
            levels = changes[next].1;
            next += 1;
        }
        let mut i = config;
        i.core.reset = k < 3;
        i.core.enc_a = levels.a;
        i.core.enc_b = levels.b;
        i.core.enc_z = levels.z;
        i
    })
}

/// [`EccTopModel`] that raises `ident_arm` for one cycle `delay` cycles after its first
/// `index`, as the Verilator harness's event mode does (`None`: never by itself; an
/// `ident_arm` in the inputs is applied as well).
#[derive(Clone, Debug)]
pub struct ArmedModel {
    model: EccTopModel,
    delay: Option<u64>,
    arm_at: Option<u64>,
    cycle: u64,
}

impl ArmedModel {
    /// The model of `p` after reset, arming `delay` cycles after the first index.
    pub fn new(p: &Params, delay: Option<u64>) -> Self {
        Self {
            model: EccTopModel::new(p),
            delay,
            arm_at: None,
            cycle: 0,
        }
    }

    /// One edge with `inp` (its `ident_arm` or-ed with this model's own); the inputs as
    /// applied and the outputs.
    pub fn step(&mut self, mut inp: EccTopInputs) -> (EccTopInputs, EccTopOutputs) {
        inp.ident_arm |= self.arm_at == Some(self.cycle);
        let o = self.model.step(inp);
        if let (true, None, Some(delay)) = (o.core.index, self.arm_at, self.delay) {
            self.arm_at = Some(self.cycle + 1 + delay);
        }
        self.cycle += 1;
        (inp, o)
    }

    /// The cycle this model's own arm is (or was) raised in, once an index has come.
    pub fn arm_at(&self) -> Option<u64> {
        self.arm_at
    }
}

/// Why the results `g` are not those of one revolution of `lines` lines lasting
/// `rev_cycles` cycles at constant speed (done, no overflow, K lines, Σ T within one cycle
/// of the revolution: the two line-0 edges are each sampled within a cycle), or Ok.
pub fn check_revolution(g: &GatherOutputs, lines: u32, rev_cycles: f64) -> Result<(), String> {
    if !g.done || g.overflow || g.count != u64::from(lines) {
        return Err(format!("not one revolution of {lines} lines: {g:?}"));
    }
    if (g.sum_t as f64 - rev_cycles).abs() > 1.0 {
        return Err(format!("sum_t {} for {rev_cycles} cycles", g.sum_t));
    }
    Ok(())
}
