// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_ecc`: `encspeed_core` with the eccentricity-corrected M/T speed of every
//! window ([`crate::MtCorrector`]) and n3 of every speed ([`crate::N3Corrector`]) from
//! runtime coefficients. Bit-true model:
//! [`golden::top::ecc_top::EccTopModel`], whose module docs give the timing.
//!
//! ```text
//! enc_a/b/z, cfg_* ─ EncspeedCore ─ every core output (unchanged)
//!                        │ mt_strobe, mt_m, mt_t, mt_negative, position, dt_active
//! ecc_c, ecc_d ─────── MtCorrector ─ speed_mtc, mtc_strobe
//!                        │ speed_strobe, speed_n3, speed_position, speed_nep, speed_ndt
//!                      N3Corrector ─ speed_n3c, n3c_strobe
//!                        │ position, direction, index
//! ident_arm ─ LineTap ─ IdentGatherer ─ ident_done, ident_count, ident_t_min … ident_sum_cos
//! ```
//!
//! Ports: those of `encspeed_core` (docs/ports.md) and `ecc_c[31:0]`, `ecc_d[31:0]` (c =
//! E·cos θ0, d = E·sin θ0, two's complement Q15.16 lines, sampled with each window),
//! `speed_mtc[S-1:0]` (format of `speed_mt`) and `mtc_strobe`, `speed_n3c[S-1:0]` (format
//! of `speed_n3`) and `n3c_strobe`; `ident_arm` and the gatherer's results `ident_*`
//! (docs/ports.md). An `ident_arm` before the first index since reset (or a change of
//! `cfg_mode`) is held until that index (`aligned`, `arm_pending`), as the model says.
//! Built without the identification (`--no-identification`), the `ident_*` ports read 0
//! and `ident_arm` does nothing (`has_ident`).

use crate::ecc::ident_gatherer::IdentGatherer;
use crate::ecc::line_tap::LineTap;
use crate::ecc::mt_corrector::MtCorrector;
use crate::ecc::n3_corrector::N3Corrector;
use crate::top::core::EncspeedCore;
use crate::top::mode_reset::ModeReset;
use golden::params::{Params, ERROR_COUNT_BITS, FILTER_BITS, POSITION_BITS};
use rust_hdl::prelude::*;

const FB: usize = FILTER_BITS as usize;
const G: usize = ERROR_COUNT_BITS as usize;
const C: usize = POSITION_BITS as usize;
/// Line number bits of the identification (`golden::ecc::line_tap::LINE_BITS`).
const LB: usize = 16;
/// Period bits of the identification (`golden::ecc::line_tap::PERIOD_BITS`).
const TB: usize = 32;
/// Width of the identification sums (`golden::top::ecc_top::IDENT_SUM_BITS`).
const WB: usize = LB + TB + 24;

/// The core with the corrected M/T speed (N-bit counters, P = 2N + 1, S = N + 17, CW the
/// corrected count's width).
#[derive(LogicBlock)]
pub struct EncspeedEcc<const N: usize, const P: usize, const S: usize, const CW: usize> {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Core input `enc_a` (docs/ports.md).
    pub enc_a: Signal<In, Bit>,
    /// Core input `enc_b` (docs/ports.md).
    pub enc_b: Signal<In, Bit>,
    /// Core input `enc_z` (docs/ports.md).
    pub enc_z: Signal<In, Bit>,
    /// Core input `cfg_dt` (docs/ports.md).
    pub cfg_dt: Signal<In, Bits<N>>,
    /// Core input `cfg_timeout` (docs/ports.md).
    pub cfg_timeout: Signal<In, Bits<N>>,
    /// Core input `cfg_filter` (docs/ports.md).
    pub cfg_filter: Signal<In, Bits<FB>>,
    /// Core input `cfg_mode` (docs/ports.md).
    pub cfg_mode: Signal<In, Bits<2>>,
    /// Core input `cfg_z_mode` (docs/ports.md).
    pub cfg_z_mode: Signal<In, Bits<2>>,
    /// Core input `clear_faults` (docs/ports.md).
    pub clear_faults: Signal<In, Bit>,
    /// Core output `position` (docs/ports.md).
    pub position: Signal<Out, Bits<C>>,
    /// Core output `z_latch` (docs/ports.md).
    pub z_latch: Signal<Out, Bits<C>>,
    /// Core output `index` (docs/ports.md).
    pub index: Signal<Out, Bit>,
    /// Core output `direction` (docs/ports.md).
    pub direction: Signal<Out, Bit>,
    /// Core output `nep` (docs/ports.md).
    pub nep: Signal<Out, Bits<N>>,
    /// Core output `ndt` (docs/ports.md).
    pub ndt: Signal<Out, Bits<N>>,
    /// Core output `update` (docs/ports.md).
    pub update: Signal<Out, Bit>,
    /// Core output `speed_n1` (docs/ports.md).
    pub speed_n1: Signal<Out, Bits<S>>,
    /// Core output `speed_n2` (docs/ports.md).
    pub speed_n2: Signal<Out, Bits<S>>,
    /// Core output `speed_n3` (docs/ports.md).
    pub speed_n3: Signal<Out, Bits<S>>,
    /// Core output `speed_strobe` (docs/ports.md).
    pub speed_strobe: Signal<Out, Bit>,
    /// Core output `speed_pc` (docs/ports.md).
    pub speed_pc: Signal<Out, Bits<S>>,
    /// Core output `speed_et` (docs/ports.md).
    pub speed_et: Signal<Out, Bits<S>>,
    /// Core output `speed_mt` (docs/ports.md).
    pub speed_mt: Signal<Out, Bits<S>>,
    /// Core output `baseline_strobe` (docs/ports.md).
    pub baseline_strobe: Signal<Out, Bit>,
    /// Core output `valid` (docs/ports.md).
    pub valid: Signal<Out, Bit>,
    /// Core output `stalled` (docs/ports.md).
    pub stalled: Signal<Out, Bit>,
    /// Core output `fault_illegal` (docs/ports.md).
    pub fault_illegal: Signal<Out, Bit>,
    /// Core output `fault_overspeed` (docs/ports.md).
    pub fault_overspeed: Signal<Out, Bit>,
    /// Core output `fault_revolution` (docs/ports.md).
    pub fault_revolution: Signal<Out, Bit>,
    /// Core output `cfg_error` (docs/ports.md).
    pub cfg_error: Signal<Out, Bit>,
    /// Core output `glitch_count` (docs/ports.md).
    pub glitch_count: Signal<Out, Bits<G>>,
    /// Core output `illegal_count` (docs/ports.md).
    pub illegal_count: Signal<Out, Bits<G>>,
    /// Core output `rev_error_count` (docs/ports.md).
    pub rev_error_count: Signal<Out, Bits<G>>,
    /// Core output `speed_position` (docs/ports.md).
    pub speed_position: Signal<Out, Bits<C>>,
    /// Core output `speed_nep` (docs/ports.md).
    pub speed_nep: Signal<Out, Bits<N>>,
    /// Core output `speed_ndt` (docs/ports.md).
    pub speed_ndt: Signal<Out, Bits<N>>,
    /// Core output `mt_strobe` (docs/ports.md).
    pub mt_strobe: Signal<Out, Bit>,
    /// Core output `mt_m` (docs/ports.md).
    pub mt_m: Signal<Out, Bits<N>>,
    /// Core output `mt_t` (docs/ports.md).
    pub mt_t: Signal<Out, Bits<N>>,
    /// Core output `mt_negative` (docs/ports.md).
    pub mt_negative: Signal<Out, Bit>,
    /// Core output `dt_active` (docs/ports.md).
    pub dt_active: Signal<Out, Bits<N>>,
    /// c = E·cos θ0, two's complement Q15.16 lines.
    pub ecc_c: Signal<In, Bits<32>>,
    /// d = E·sin θ0, two's complement Q15.16 lines.
    pub ecc_d: Signal<In, Bits<32>>,
    /// Corrected M/T speed (format of `speed_mt`), held.
    pub speed_mtc: Signal<Out, Bits<S>>,
    /// One cycle: `speed_mtc` was just written.
    pub mtc_strobe: Signal<Out, Bit>,
    /// Corrected n3 (format of `speed_n3`), held.
    pub speed_n3c: Signal<Out, Bits<S>>,
    /// One cycle: `speed_n3c` was just written.
    pub n3c_strobe: Signal<Out, Bit>,
    /// Gather the next revolution (index to index) for the identification.
    pub ident_arm: Signal<In, Bit>,
    /// The identification results are complete; sticky until `ident_arm`.
    pub ident_done: Signal<Out, Bit>,
    /// More than 2^16 lines between the index pulses (extra lines dropped).
    pub ident_overflow: Signal<Out, Bit>,
    /// Lines gathered.
    pub ident_count: Signal<Out, Bits<17>>,
    /// Shortest line period (cycles).
    pub ident_t_min: Signal<Out, Bits<TB>>,
    /// Line number of the edge that closed it.
    pub ident_p_min: Signal<Out, Bits<LB>>,
    /// Longest line period (cycles).
    pub ident_t_max: Signal<Out, Bits<TB>>,
    /// Line number of the edge that closed it.
    pub ident_p_max: Signal<Out, Bits<LB>>,
    /// Σ T, unsigned.
    pub ident_sum_t: Signal<Out, Bits<WB>>,
    /// Σ T·round(Q·sin(2πp/K)), signed.
    pub ident_sum_sin: Signal<Out, Bits<WB>>,
    /// Σ T·round(Q·cos(2πp/K)), signed.
    pub ident_sum_cos: Signal<Out, Bits<WB>>,
    pub(crate) core: EncspeedCore<N, P, S>,
    corrector: MtCorrector<N, 16, S, CW>,
    n3_corrector: N3Corrector<N, S>,
    line_tap: LineTap<C>,
    gatherer: IdentGatherer<LB, TB, WB>,
    aligned: DFF<Bit>,
    arm_pending: DFF<Bit>,
    arm_now: Signal<Local, Bit>,
    /// The reset of the corrector and the identification: the core's (`reset` or a mode
    /// change), from the same registered rule.
    ecc_reset: Signal<Local, Bit>,
    mode_reset: ModeReset,
    counts_per_rev: Signal<Local, Bits<C>>,
    shift: Signal<Local, Bits<2>>,
    mode_x1: Constant<Bits<2>>,
    mode_x2: Constant<Bits<2>>,
    shift_zero: Constant<Bits<2>>,
    shift_one: Constant<Bits<2>>,
    shift_two: Constant<Bits<2>>,
    lines_x1: Constant<Bits<C>>,
    lines_x2: Constant<Bits<C>>,
    lines_x4: Constant<Bits<C>>,
    /// `identification` (golden `Params::identification`): without it every `ident_*`
    /// port is tied to 0 and the gatherer's arm to 0, so that nothing reads the line tap
    /// and the gatherer and synthesis removes them (their tables and multipliers with them).
    has_ident: Constant<Bit>,
    count_zero: Constant<Bits<17>>,
    period_zero: Constant<Bits<TB>>,
    line_zero: Constant<Bits<LB>>,
    sum_zero: Constant<Bits<WB>>,
}

impl<const N: usize, const P: usize, const S: usize, const CW: usize> EncspeedEcc<N, P, S, CW> {
    /// The top for validated parameters. Panics where [`golden::top::ecc_top::check`] refuses
    /// them (the callers check first) or if `N` is not their counter width.
    pub fn new(p: &Params) -> Self {
        golden::top::ecc_top::check(p).unwrap_or_else(|e| panic!("{e}"));
        let lines = |shift: u32| -> Constant<Bits<C>> {
            Constant::new((p.counts_per_rev(shift) & ((1u64 << C) - 1)).into())
        };
        Self {
            clock: Default::default(),
            reset: Default::default(),
            enc_a: Default::default(),
            enc_b: Default::default(),
            enc_z: Default::default(),
            cfg_dt: Default::default(),
            cfg_timeout: Default::default(),
            cfg_filter: Default::default(),
            cfg_mode: Default::default(),
            cfg_z_mode: Default::default(),
            clear_faults: Default::default(),
            position: Default::default(),
            z_latch: Default::default(),
            index: Default::default(),
            direction: Default::default(),
            nep: Default::default(),
            ndt: Default::default(),
            update: Default::default(),
            speed_n1: Default::default(),
            speed_n2: Default::default(),
            speed_n3: Default::default(),
            speed_strobe: Default::default(),
            speed_pc: Default::default(),
            speed_et: Default::default(),
            speed_mt: Default::default(),
            baseline_strobe: Default::default(),
            valid: Default::default(),
            stalled: Default::default(),
            fault_illegal: Default::default(),
            fault_overspeed: Default::default(),
            fault_revolution: Default::default(),
            cfg_error: Default::default(),
            glitch_count: Default::default(),
            illegal_count: Default::default(),
            rev_error_count: Default::default(),
            speed_position: Default::default(),
            speed_nep: Default::default(),
            speed_ndt: Default::default(),
            mt_strobe: Default::default(),
            mt_m: Default::default(),
            mt_t: Default::default(),
            mt_negative: Default::default(),
            dt_active: Default::default(),
            ecc_c: Default::default(),
            ecc_d: Default::default(),
            speed_mtc: Default::default(),
            mtc_strobe: Default::default(),
            speed_n3c: Default::default(),
            n3c_strobe: Default::default(),
            ident_arm: Default::default(),
            ident_done: Default::default(),
            ident_overflow: Default::default(),
            ident_count: Default::default(),
            ident_t_min: Default::default(),
            ident_p_min: Default::default(),
            ident_t_max: Default::default(),
            ident_p_max: Default::default(),
            ident_sum_t: Default::default(),
            ident_sum_sin: Default::default(),
            ident_sum_cos: Default::default(),
            core: EncspeedCore::new(p),
            corrector: MtCorrector::new(p.lines()),
            n3_corrector: N3Corrector::new(p.lines()),
            line_tap: LineTap::default(),
            gatherer: IdentGatherer::new(p.lines()),
            aligned: Default::default(),
            arm_pending: Default::default(),
            arm_now: Default::default(),
            ecc_reset: Default::default(),
            mode_reset: Default::default(),
            counts_per_rev: Default::default(),
            shift: Default::default(),
            mode_x1: Constant::new(u64::from(golden::frontend::MODE_X1).into()),
            mode_x2: Constant::new(u64::from(golden::frontend::MODE_X2).into()),
            shift_zero: Constant::new(0.into()),
            shift_one: Constant::new(1.into()),
            shift_two: Constant::new(2.into()),
            lines_x1: lines(0),
            lines_x2: lines(1),
            lines_x4: lines(2),
            has_ident: Constant::new(p.identification()),
            count_zero: Constant::new(Bits::default()),
            period_zero: Constant::new(Bits::default()),
            line_zero: Constant::new(Bits::default()),
            // W = 72 > 64 bits: zero from the default, not from a u64.
            sum_zero: Constant::new(Bits::default()),
        }
    }
}

impl<const N: usize, const P: usize, const S: usize, const CW: usize> Logic
    for EncspeedEcc<N, P, S, CW>
{
    #[hdl_gen]
    fn update(&mut self) {
        clock!(
            self,
            clock,
            core,
            corrector,
            n3_corrector,
            line_tap,
            gatherer,
            mode_reset
        );
        dff_setup!(self, clock, aligned, arm_pending);
        self.core.reset.next = self.reset.val();
        self.core.enc_a.next = self.enc_a.val();
        self.core.enc_b.next = self.enc_b.val();
        self.core.enc_z.next = self.enc_z.val();
        self.core.cfg_dt.next = self.cfg_dt.val();
        self.core.cfg_timeout.next = self.cfg_timeout.val();
        self.core.cfg_filter.next = self.cfg_filter.val();
        self.core.cfg_mode.next = self.cfg_mode.val();
        self.core.cfg_z_mode.next = self.cfg_z_mode.val();
        self.core.clear_faults.next = self.clear_faults.val();
        self.position.next = self.core.position.val();
        self.z_latch.next = self.core.z_latch.val();
        self.index.next = self.core.index.val();
        self.direction.next = self.core.direction.val();
        self.nep.next = self.core.nep.val();
        self.ndt.next = self.core.ndt.val();
        self.update.next = self.core.update.val();
        self.speed_n1.next = self.core.speed_n1.val();
        self.speed_n2.next = self.core.speed_n2.val();
        self.speed_n3.next = self.core.speed_n3.val();
        self.speed_strobe.next = self.core.speed_strobe.val();
        self.speed_pc.next = self.core.speed_pc.val();
        self.speed_et.next = self.core.speed_et.val();
        self.speed_mt.next = self.core.speed_mt.val();
        self.baseline_strobe.next = self.core.baseline_strobe.val();
        self.valid.next = self.core.valid.val();
        self.stalled.next = self.core.stalled.val();
        self.fault_illegal.next = self.core.fault_illegal.val();
        self.fault_overspeed.next = self.core.fault_overspeed.val();
        self.fault_revolution.next = self.core.fault_revolution.val();
        self.cfg_error.next = self.core.cfg_error.val();
        self.glitch_count.next = self.core.glitch_count.val();
        self.illegal_count.next = self.core.illegal_count.val();
        self.rev_error_count.next = self.core.rev_error_count.val();
        self.speed_position.next = self.core.speed_position.val();
        self.speed_nep.next = self.core.speed_nep.val();
        self.speed_ndt.next = self.core.speed_ndt.val();
        self.mt_strobe.next = self.core.mt_strobe.val();
        self.mt_m.next = self.core.mt_m.val();
        self.mt_t.next = self.core.mt_t.val();
        self.mt_negative.next = self.core.mt_negative.val();
        self.dt_active.next = self.core.dt_active.val();
        // The corrector resets with the core (reset or a change of cfg_mode) and takes the
        // decoder's steps per line and revolution as the core does.
        self.mode_reset.reset.next = self.reset.val();
        self.mode_reset.cfg_mode.next = self.cfg_mode.val();
        self.ecc_reset.next = self.mode_reset.rst.val();
        self.shift.next = self.shift_two.val();
        self.counts_per_rev.next = self.lines_x4.val();
        if self.mode_reset.mode.val() == self.mode_x1.val() {
            self.shift.next = self.shift_zero.val();
            self.counts_per_rev.next = self.lines_x1.val();
        } else if self.mode_reset.mode.val() == self.mode_x2.val() {
            self.shift.next = self.shift_one.val();
            self.counts_per_rev.next = self.lines_x2.val();
        }
        self.corrector.reset.next = self.ecc_reset.val();
        self.corrector.start.next = self.core.mt_strobe.val();
        self.corrector.position.next = self.core.position.val();
        self.corrector.mt_m.next = self.core.mt_m.val();
        self.corrector.mt_t.next = self.core.mt_t.val();
        self.corrector.mt_negative.next = self.core.mt_negative.val();
        self.corrector.cfg_dt.next = self.core.dt_active.val();
        self.corrector.shift.next = self.shift.val();
        self.corrector.counts_per_rev.next = self.counts_per_rev.val();
        self.corrector.coef_c.next = self.ecc_c.val();
        self.corrector.coef_d.next = self.ecc_d.val();
        self.n3_corrector.reset.next = self.ecc_reset.val();
        self.n3_corrector.start.next = self.core.speed_strobe.val();
        self.n3_corrector.n3.next = self.core.speed_n3.val();
        self.n3_corrector.position.next = self.core.speed_position.val();
        self.n3_corrector.nep.next = self.core.speed_nep.val();
        self.n3_corrector.ndt.next = self.core.speed_ndt.val();
        self.n3_corrector.shift.next = self.shift.val();
        self.n3_corrector.counts_per_rev.next = self.counts_per_rev.val();
        self.n3_corrector.coef_c.next = self.ecc_c.val();
        self.n3_corrector.coef_d.next = self.ecc_d.val();
        self.speed_n3c.next = self.n3_corrector.n3c.val();
        self.n3c_strobe.next = self.n3_corrector.valid.val();
        self.speed_mtc.next = self.corrector.speed_mtc.val();
        self.mtc_strobe.next = self.corrector.valid.val();
        // Identification: the core's line edges, gathered index to index after an arm. The
        // gatherer needs the position aligned by an index: an arm before the aligning index
        // waits for it (golden::top::ecc_top).
        self.arm_now.next = (self.ident_arm.val() | self.arm_pending.q.val())
            & (self.aligned.q.val() | self.core.index.val());
        self.arm_pending.d.next =
            (self.ident_arm.val() | self.arm_pending.q.val()) & !self.arm_now.val();
        self.aligned.d.next = self.aligned.q.val() | self.core.index.val();
        if self.ecc_reset.val() {
            self.arm_pending.d.next = false;
            self.aligned.d.next = false;
        }
        self.line_tap.reset.next = self.ecc_reset.val();
        self.line_tap.position.next = self.core.position.val();
        self.line_tap.forward.next = self.core.direction.val();
        self.line_tap.shift.next = self.shift.val();
        self.line_tap.counts_per_rev.next = self.counts_per_rev.val();
        self.gatherer.reset.next = self.ecc_reset.val();
        self.gatherer.arm.next = self.arm_now.val();
        self.gatherer.index.next = self.core.index.val();
        self.gatherer.line.next = self.line_tap.line.val();
        self.gatherer.position.next = self.line_tap.line_position.val();
        self.gatherer.period.next = self.line_tap.period.val();
        self.ident_done.next = self.gatherer.done.val();
        self.ident_overflow.next = self.gatherer.overflow.val();
        self.ident_count.next = self.gatherer.count.val();
        self.ident_t_min.next = self.gatherer.t_min.val();
        self.ident_p_min.next = self.gatherer.p_min.val();
        self.ident_t_max.next = self.gatherer.t_max.val();
        self.ident_p_max.next = self.gatherer.p_max.val();
        self.ident_sum_t.next = self.gatherer.sum_t.val();
        self.ident_sum_sin.next = self.gatherer.sum_sin.val();
        self.ident_sum_cos.next = self.gatherer.sum_cos.val();
        // Built without the identification: its ports read 0 (the field's docs).
        if !self.has_ident.val() {
            self.gatherer.arm.next = false;
            self.ident_done.next = false;
            self.ident_overflow.next = false;
            self.ident_count.next = self.count_zero.val();
            self.ident_t_min.next = self.period_zero.val();
            self.ident_p_min.next = self.line_zero.val();
            self.ident_t_max.next = self.period_zero.val();
            self.ident_p_max.next = self.line_zero.val();
            self.ident_sum_t.next = self.sum_zero.val();
            self.ident_sum_sin.next = self.sum_zero.val();
            self.ident_sum_cos.next = self.sum_zero.val();
        }
    }
}
