// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_core`: the top of the IP. Its bit-true model is [`golden::top::core::CoreModel`],
//! whose module docs give the rules this file wires (start-up hold, reversal, priming, mode
//! scaling, configuration defaults, faults, `valid`).
//!
//! ```text
//! enc_a ─ TwoFlopSync ─ GlitchFilter ─┐                      ┌─ PositionCounter ─ position, z_latch, index
//! enc_b ─ TwoFlopSync ─ GlitchFilter ─┴─ QuadratureDecoder ──┤
//! enc_z ─ TwoFlopSync ─ GlitchFilter ────────────────────────┘ (z)
//!                          step, forward ─┬─ Timebase + SyncEstimator ─ nep, ndt ─ SpeedCalc ─ speed_n1..n3
//!                                         └─ PcCounter, EtTimer, MtCounter ─ BaselineSpeeds ─ speed_pc, speed_et, speed_mt
//! ModeReset (registered cfg_mode and the registered reset: `reset` or a mode change),
//! Startup (holds decoder and position counter through the filter delay), FaultFlags.
//! ```
//!
//! The port table, widths and latencies are in docs/architecture.md and in the generated
//! manifest; widths: N = `counter_bits`, S = N + F + 1 with F = 16 (`speed_frac_bits`),
//! P = 2N + 1 (the speed calculator's products).

use crate::baselines::baseline_speeds::BaselineSpeeds;
use crate::baselines::et_timer::EtTimer;
use crate::baselines::mt_counter::MtCounter;
use crate::baselines::pc_counter::PcCounter;
use crate::estimator::speed_calc::SpeedCalc;
use crate::estimator::sync_estimator::SyncEstimator;
use crate::estimator::timebase::Timebase;
use crate::frontend::glitch_filter::GlitchFilter;
use crate::frontend::position_counter::PositionCounter;
use crate::frontend::quadrature_decoder::QuadratureDecoder;
use crate::frontend::startup::Startup;
use crate::frontend::two_flop_sync::TwoFlopSync;
use crate::top::fault_flags::FaultFlags;
use crate::top::mode_reset::ModeReset;
use golden::params::{
    Params, SpeedOutput, ERROR_COUNT_BITS, FILTER_BITS, MIN_DT_CYCLES, POSITION_BITS,
    SPEED_FRAC_BITS,
};
use rust_hdl::prelude::*;

const F: usize = SPEED_FRAC_BITS as usize;
const FB: usize = FILTER_BITS as usize;
const G: usize = ERROR_COUNT_BITS as usize;
const C: usize = POSITION_BITS as usize;

/// The encoder interface core with N-bit counters (P = 2N + 1, S = N + 17).
#[derive(LogicBlock)]
pub struct EncspeedCore<const N: usize, const P: usize, const S: usize> {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Encoder channel A (asynchronous).
    pub enc_a: Signal<In, Bit>,
    /// Encoder channel B (asynchronous).
    pub enc_b: Signal<In, Bit>,
    /// Encoder index Z (asynchronous).
    pub enc_z: Signal<In, Bit>,
    /// dt in clock cycles (0: generation default; 1: used as 2 and `cfg_error`).
    pub cfg_dt: Signal<In, Bits<N>>,
    /// Zero-speed timeout in dt intervals (0: generation default).
    pub cfg_timeout: Signal<In, Bits<N>>,
    /// Glitch filter length, clock cycles (0: off).
    pub cfg_filter: Signal<In, Bits<FB>>,
    /// 0 = x1, 1 = x2, 2 = x4 (3: x4 and `cfg_error`).
    pub cfg_mode: Signal<In, Bits<2>>,
    /// 0 = ignore Z, 1 = Z resets the position, 2 = Z latches it, 3 = latch then reset.
    pub cfg_z_mode: Signal<In, Bits<2>>,
    /// Clear the sticky fault flags.
    pub clear_faults: Signal<In, Bit>,
    /// Position in steps, 0 .. lines·2^s − 1.
    pub position: Signal<Out, Bits<C>>,
    /// Position at the last index edge.
    pub z_latch: Signal<Out, Bits<C>>,
    /// One cycle per index edge.
    pub index: Signal<Out, Bit>,
    /// Direction of the last step (1 = forward).
    pub direction: Signal<Out, Bit>,
    /// Nep1 (decoder steps).
    pub nep: Signal<Out, Bits<N>>,
    /// Ndt1.
    pub ndt: Signal<Out, Bits<N>>,
    /// Nep1 or Ndt1 just written.
    pub update: Signal<Out, Bit>,
    /// n1, two's complement Q(N).16, ω_lim.
    pub speed_n1: Signal<Out, Bits<S>>,
    /// n2, two's complement Q(N).16, ω_lim.
    pub speed_n2: Signal<Out, Bits<S>>,
    /// n3, two's complement Q(N).16, ω_lim.
    pub speed_n3: Signal<Out, Bits<S>>,
    /// One cycle: `speed_n1..3` just written.
    pub speed_strobe: Signal<Out, Bit>,
    /// Fixed-time (PC) speed, two's complement Q(N).16, ω_lim.
    pub speed_pc: Signal<Out, Bits<S>>,
    /// Fixed-space (ET) speed, two's complement Q(N).16, ω_lim.
    pub speed_et: Signal<Out, Bits<S>>,
    /// M/T speed, two's complement Q(N).16, ω_lim.
    pub speed_mt: Signal<Out, Bits<S>>,
    /// One cycle: `speed_pc`, `speed_et`, `speed_mt` just written.
    pub baseline_strobe: Signal<Out, Bit>,
    /// `speed_n3` is a measurement of the current direction, not stalled, legal config.
    pub valid: Signal<Out, Bit>,
    /// No step for the zero-speed timeout.
    pub stalled: Signal<Out, Bit>,
    /// Sticky: illegal transition.
    pub fault_illegal: Signal<Out, Bit>,
    /// Sticky: an A or B pulse shorter than the filter (glitch or over-speed).
    pub fault_overspeed: Signal<Out, Bit>,
    /// Sticky: a revolution with the wrong count.
    pub fault_revolution: Signal<Out, Bit>,
    /// `cfg_dt` = 1 or `cfg_mode` = 3 (registered).
    pub cfg_error: Signal<Out, Bit>,
    /// Rejected pulses of A, B and Z (saturating).
    pub glitch_count: Signal<Out, Bits<G>>,
    /// Illegal transitions (saturating).
    pub illegal_count: Signal<Out, Bits<G>>,
    /// Revolutions with the wrong count (saturating).
    pub rev_error_count: Signal<Out, Bits<G>>,
    /// With `speed_strobe`: `position` at the update the speeds were computed from.
    pub speed_position: Signal<Out, Bits<C>>,
    /// With `speed_strobe`: the Nep1 the speeds were computed from.
    pub speed_nep: Signal<Out, Bits<N>>,
    /// With `speed_strobe`: the Ndt1 the speeds were computed from.
    pub speed_ndt: Signal<Out, Bits<N>>,
    /// One cycle: the M/T counter closed a window.
    pub mt_strobe: Signal<Out, Bit>,
    /// M/T steps of the last window.
    pub mt_m: Signal<Out, Bits<N>>,
    /// M/T cycles spanning them.
    pub mt_t: Signal<Out, Bits<N>>,
    /// The last M/T window's steps were backward.
    pub mt_negative: Signal<Out, Bit>,
    /// The dt in use (registered).
    pub dt_active: Signal<Out, Bits<N>>,
    sync_a: TwoFlopSync,
    sync_b: TwoFlopSync,
    sync_z: TwoFlopSync,
    startup: Startup,
    filter_a: GlitchFilter<FB, G>,
    filter_b: GlitchFilter<FB, G>,
    filter_z: GlitchFilter<FB, G>,
    decoder: QuadratureDecoder<G>,
    counter: PositionCounter<C, G>,
    pub(crate) timebase: Timebase<N>,
    table1: SyncEstimator<N>,
    calc: SpeedCalc<N, F, P, S>,
    window_last: DFF<Bits<C>>,
    restart_pos: DFF<Bits<C>>,
    position_before: DFF<Bits<C>>,
    restart_now: Signal<Local, Bits<C>>,
    window_now: Signal<Local, Bits<C>>,
    pc: PcCounter<N>,
    et: EtTimer<N>,
    mt: MtCounter<N>,
    baseline: BaselineSpeeds<N, F, S>,
    faults: FaultFlags,
    last_dir: DFF<Bit>,
    et_have: DFF<Bit>,
    /// The effective dt, powered up at the generation default (the window timers read it
    /// at every edge, reset included, and never see a dt below 2).
    dt_reg: DFFWithInit<Bits<N>>,
    timeout_reg: DFF<Bits<N>>,
    filter_reg: DFF<Bits<FB>>,
    z_mode_reg: DFF<Bits<2>>,
    cfg_error_reg: DFF<Bit>,
    /// `stalled` and `valid`, registered from their conditions (0 at a reset edge): the
    /// timeout's carry chain ends here, not in the register file's snapshot behind it.
    stalled_reg: DFF<Bit>,
    valid_reg: DFF<Bit>,
    mode_reset: ModeReset,
    /// `rst` or the decoder's `first`, as a register of its own (from their next values);
    /// high at power-up, as `rst` is.
    engine_reset_reg: DFFWithInit<Bit>,
    rst: Signal<Local, Bit>,
    front_reset: Signal<Local, Bit>,
    step_counted: Signal<Local, Bit>,
    engine_reset: Signal<Local, Bit>,
    dt_eff: Signal<Local, Bits<N>>,
    shift: Signal<Local, Bits<2>>,
    /// R − 1, R − 2 and R − 3 of the decoding mode, for the position counter.
    limit: Signal<Local, Bits<C>>,
    limit_less_one: Signal<Local, Bits<C>>,
    limit_less_two: Signal<Local, Bits<C>>,
    n_zero: Constant<Bits<N>>,
    n_one: Constant<Bits<N>>,
    min_dt: Constant<Bits<N>>,
    above_min_dt: Constant<Bits<N>>,
    default_dt: Constant<Bits<N>>,
    default_timeout: Constant<Bits<N>>,
    mode_x1: Constant<Bits<2>>,
    mode_x2: Constant<Bits<2>>,
    mode_invalid: Constant<Bits<2>>,
    shift_zero: Constant<Bits<2>>,
    shift_one: Constant<Bits<2>>,
    shift_two: Constant<Bits<2>>,
    limit_x1: Constant<Bits<C>>,
    limit_x2: Constant<Bits<C>>,
    limit_x4: Constant<Bits<C>>,
    limit_less_one_x1: Constant<Bits<C>>,
    limit_less_one_x2: Constant<Bits<C>>,
    limit_less_one_x4: Constant<Bits<C>>,
    limit_less_two_x1: Constant<Bits<C>>,
    limit_less_two_x2: Constant<Bits<C>>,
    limit_less_two_x4: Constant<Bits<C>>,
    /// Which speed outputs are built (`estimators`): a constant, so that synthesis removes
    /// the blocks of one left out, whose port is tied to 0 (`speed_zero`, `n_zero`).
    has_n1: Constant<Bit>,
    has_n2: Constant<Bit>,
    has_pc: Constant<Bit>,
    has_et: Constant<Bit>,
    has_mt: Constant<Bit>,
    /// At least one of PC, ET, M/T: else their converter is not built either.
    has_baselines: Constant<Bit>,
    speed_zero: Constant<Bits<S>>,
}

impl<const N: usize, const P: usize, const S: usize> EncspeedCore<N, P, S> {
    /// Build the core for validated parameters. Panics if `N` is not the parameters'
    /// counter width (the dispatch in [`crate::build_core`] guarantees it).
    pub fn new(p: &Params) -> Self {
        assert_eq!(p.counter_bits() as usize, N, "counter width mismatch");
        assert!(P == 2 * N + 1 && S == N + F + 1, "derived widths");
        // R − 1, R − 2 and R − 3 (mod 2^C) of each decoding mode.
        let limits = |shift: u32| -> (Bits<C>, Bits<C>, Bits<C>) {
            let (l, l1, l2) =
                golden::frontend::position_counter::limits(p.counts_per_rev(shift), C as u32);
            (l.into(), l1.into(), l2.into())
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
            sync_a: Default::default(),
            sync_b: Default::default(),
            sync_z: Default::default(),
            startup: Default::default(),
            filter_a: Default::default(),
            filter_b: Default::default(),
            filter_z: Default::default(),
            decoder: Default::default(),
            counter: Default::default(),
            timebase: Default::default(),
            table1: Default::default(),
            calc: Default::default(),
            window_last: Default::default(),
            restart_pos: Default::default(),
            position_before: Default::default(),
            restart_now: Default::default(),
            window_now: Default::default(),
            pc: Default::default(),
            et: Default::default(),
            mt: Default::default(),
            baseline: Default::default(),
            faults: Default::default(),
            last_dir: Default::default(),
            et_have: Default::default(),
            dt_reg: DFFWithInit::new(p.dt_cycles().into()),
            timeout_reg: Default::default(),
            filter_reg: Default::default(),
            z_mode_reg: Default::default(),
            cfg_error_reg: Default::default(),
            stalled_reg: Default::default(),
            valid_reg: Default::default(),
            mode_reset: Default::default(),
            engine_reset_reg: DFFWithInit::new(true),
            rst: Default::default(),
            front_reset: Default::default(),
            step_counted: Default::default(),
            engine_reset: Default::default(),
            dt_eff: Default::default(),
            shift: Default::default(),
            limit: Default::default(),
            limit_less_one: Default::default(),
            limit_less_two: Default::default(),
            n_zero: Constant::new(0.into()),
            n_one: Constant::new(1.into()),
            min_dt: Constant::new(MIN_DT_CYCLES.into()),
            above_min_dt: Constant::new(crate::estimator::timebase::above_min_dt::<N>()),
            default_dt: Constant::new(p.dt_cycles().into()),
            default_timeout: Constant::new(p.timeout_dt().into()),
            mode_x1: Constant::new(u64::from(golden::frontend::MODE_X1).into()),
            mode_x2: Constant::new(u64::from(golden::frontend::MODE_X2).into()),
            mode_invalid: Constant::new(u64::from(golden::frontend::MODE_INVALID).into()),
            shift_zero: Constant::new(0.into()),
            shift_one: Constant::new(1.into()),
            shift_two: Constant::new(2.into()),
            limit_x1: Constant::new(limits(0).0),
            limit_x2: Constant::new(limits(1).0),
            limit_x4: Constant::new(limits(2).0),
            limit_less_one_x1: Constant::new(limits(0).1),
            limit_less_one_x2: Constant::new(limits(1).1),
            limit_less_one_x4: Constant::new(limits(2).1),
            limit_less_two_x1: Constant::new(limits(0).2),
            limit_less_two_x2: Constant::new(limits(1).2),
            limit_less_two_x4: Constant::new(limits(2).2),
            has_n1: Constant::new(p.has(SpeedOutput::N1)),
            has_n2: Constant::new(p.has(SpeedOutput::N2)),
            has_pc: Constant::new(p.has(SpeedOutput::Pc)),
            has_et: Constant::new(p.has(SpeedOutput::Et)),
            has_mt: Constant::new(p.has(SpeedOutput::Mt)),
            has_baselines: Constant::new(p.has_baselines()),
            speed_zero: Constant::new(0.into()),
        }
    }
}

impl<const N: usize, const P: usize, const S: usize> Logic for EncspeedCore<N, P, S> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(
            self, clock, sync_a, sync_b, sync_z, startup, filter_a, filter_b, filter_z, decoder,
            counter, timebase, table1, calc, pc, et, mt, baseline, faults, mode_reset
        );
        dff_setup!(
            self,
            clock,
            last_dir,
            et_have,
            dt_reg,
            timeout_reg,
            filter_reg,
            z_mode_reg,
            cfg_error_reg,
            stalled_reg,
            valid_reg,
            window_last,
            restart_pos,
            position_before,
            engine_reset_reg
        );

        // Configuration, registered once here: the blocks read registers (the glitch filters
        // compare cfg_filter into a register an edge ahead), so an input reaches at most one
        // carry chain before a register (docs/ports.md gives when a change acts). A change of
        // cfg_mode resets the core as `reset` does, at the edge after the one that sees it,
        // with the new mode in place (ModeReset).
        self.mode_reset.reset.next = self.reset.val();
        self.mode_reset.cfg_mode.next = self.cfg_mode.val();
        self.rst.next = self.mode_reset.rst.val();
        self.filter_reg.d.next = self.cfg_filter.val();
        self.z_mode_reg.d.next = self.cfg_z_mode.val();

        // Defaults for 0, dt below 2 used as 2 (tested on the bits, no comparator); log2 of
        // steps per line.
        self.dt_eff.next = self.cfg_dt.val();
        if self.cfg_dt.val() == self.n_zero.val() {
            self.dt_eff.next = self.default_dt.val();
        } else if (self.cfg_dt.val() & self.above_min_dt.val()) == self.n_zero.val() {
            self.dt_eff.next = self.min_dt.val();
        }
        self.dt_reg.d.next = self.dt_eff.val();
        self.timeout_reg.d.next = self.cfg_timeout.val();
        if self.cfg_timeout.val() == self.n_zero.val() {
            self.timeout_reg.d.next = self.default_timeout.val();
        }
        self.cfg_error_reg.d.next = (self.cfg_dt.val() == self.n_one.val())
            | (self.cfg_mode.val() == self.mode_invalid.val());
        self.shift.next = self.shift_two.val();
        self.limit.next = self.limit_x4.val();
        self.limit_less_one.next = self.limit_less_one_x4.val();
        self.limit_less_two.next = self.limit_less_two_x4.val();
        if self.mode_reset.mode.val() == self.mode_x1.val() {
            self.shift.next = self.shift_zero.val();
            self.limit.next = self.limit_x1.val();
            self.limit_less_one.next = self.limit_less_one_x1.val();
            self.limit_less_two.next = self.limit_less_two_x1.val();
        } else if self.mode_reset.mode.val() == self.mode_x2.val() {
            self.shift.next = self.shift_one.val();
            self.limit.next = self.limit_x2.val();
            self.limit_less_one.next = self.limit_less_one_x2.val();
            self.limit_less_two.next = self.limit_less_two_x2.val();
        }

        // Front end.
        self.sync_a.reset.next = self.rst.val();
        self.sync_b.reset.next = self.rst.val();
        self.sync_z.reset.next = self.rst.val();
        self.sync_a.level_in.next = self.enc_a.val();
        self.sync_b.level_in.next = self.enc_b.val();
        self.sync_z.level_in.next = self.enc_z.val();
        self.startup.reset.next = self.rst.val();
        self.startup.cfg_filter.next = self.filter_reg.q.val();
        self.front_reset.next = self.startup.front_reset.val();
        self.filter_a.reset.next = self.rst.val();
        self.filter_b.reset.next = self.rst.val();
        self.filter_z.reset.next = self.rst.val();
        self.filter_a.level_in.next = self.sync_a.level_out.val();
        self.filter_b.level_in.next = self.sync_b.level_out.val();
        self.filter_z.level_in.next = self.sync_z.level_out.val();
        // The filters compare an edge ahead with the L they are given: the input acts in
        // them one edge later, as the filter register does in the start-up hold.
        self.filter_a.cfg_filter.next = self.cfg_filter.val();
        self.filter_b.cfg_filter.next = self.cfg_filter.val();
        self.filter_z.cfg_filter.next = self.cfg_filter.val();
        self.decoder.reset.next = self.front_reset.val();
        self.decoder.a.next = self.filter_a.level_out.val();
        self.decoder.b.next = self.filter_b.level_out.val();
        self.decoder.cfg_mode.next = self.mode_reset.mode.val();
        self.counter.reset.next = self.front_reset.val();
        self.counter.step.next = self.decoder.step.val();
        self.counter.forward.next = self.decoder.forward.val();
        self.counter.first.next = self.decoder.first.val();
        self.counter.z.next = self.filter_z.level_out.val();
        self.counter.limit.next = self.limit.val();
        self.counter.limit_less_one.next = self.limit_less_one.val();
        self.counter.limit_less_two.next = self.limit_less_two.val();
        self.counter.cfg_z_mode.next = self.z_mode_reg.q.val();

        // The first step of a direction (after reset or a reversal) restarts the estimator
        // at that step, counted as its first pulse. The decoder finds it as a register (its
        // resets include every core reset, and no step passes its start-up hold), so the
        // estimator's reset is `rst` or that register, itself one register here, loaded with
        // the next values of the two (so that it drives its fan-out from a flip-flop).
        self.engine_reset_reg.d.next =
            self.mode_reset.rst_next.val() | self.decoder.first_next.val();
        self.engine_reset.next = self.engine_reset_reg.q.val();
        self.step_counted.next = self.decoder.step.val() & !self.rst.val();
        if self.decoder.step.val() {
            self.last_dir.d.next = self.decoder.forward.val();
        }
        if self.rst.val() {
            self.last_dir.d.next = false;
        }

        // Rairán: Table 1 on decoder steps, primed by its first restart.
        self.timebase.reset.next = self.engine_reset.val();
        self.timebase.lep.next = self.decoder.step.val();
        self.timebase.dt.next = self.dt_reg.q.val();
        self.timebase.timeout.next = self.timeout_reg.q.val();
        self.table1.reset.next = self.engine_reset.val();
        self.table1.lep.next = self.step_counted.val();
        self.table1.tick.next = self.timebase.tick.val();
        self.table1.restart.next = self.timebase.restart.val();
        self.table1.cdt.next = self.timebase.cdt.val();
        self.calc.reset.next = self.engine_reset.val();
        self.calc.start.next = self.table1.update.val() & self.table1.primed.val();
        self.calc.nep.next = self.table1.nep.val();
        self.calc.ndt.next = self.table1.ndt.val();
        self.calc.negative.next = !self.last_dir.q.val();
        self.calc.mode_shift.next = self.shift.val();
        // What each speed was computed from, carried with the request and published with
        // its speeds (`speed_position`, `speed_nep`, `speed_ndt`). Span ends
        // (golden::top::core::CoreOutputs::speed_position), from registered flags of Table 1
        // (reading its combinational ones here would close a combinational loop through
        // this block): the restart pulse shows in `position` the edge after its
        // restart; the window's last pulse is `position` before the tick that wrote Nep1
        // (a pulse on that tick is not in the window), kept one edge in `position_before`.
        self.position_before.d.next = self.counter.position.val();
        self.restart_now.next = self.restart_pos.q.val();
        if self.table1.restarted.val() {
            self.restart_now.next = self.counter.position.val();
        }
        self.window_now.next = self.window_last.q.val();
        if self.table1.wrote_nep.val() {
            self.window_now.next = self.position_before.q.val();
        }
        self.restart_pos.d.next = self.restart_now.val();
        self.window_last.d.next = self.window_now.val();
        if self.engine_reset.val() {
            self.window_last.d.next = 0.into();
            self.restart_pos.d.next = 0.into();
        }
        self.calc.position.next = self.window_now.val();
        if self.table1.nep.val() == self.n_one.val() {
            self.calc.position.next = self.restart_now.val();
        }

        // Baselines: PC, ET, M/T on the same steps, converted at each window end.
        self.pc.reset.next = self.rst.val();
        self.et.reset.next = self.rst.val();
        self.mt.reset.next = self.rst.val();
        self.pc.step.next = self.decoder.step.val();
        self.et.step.next = self.decoder.step.val();
        self.mt.step.next = self.decoder.step.val();
        self.pc.forward.next = self.decoder.forward.val();
        self.pc.backward.next = self.decoder.backward.val();
        self.et.forward.next = self.decoder.forward.val();
        self.mt.forward.next = self.decoder.forward.val();
        self.mt.first.next = self.decoder.first.val();
        // The time bases read the dt register: a dt change shows in dt_active one edge after
        // it is sampled and moves the windows from the edge after that.
        self.pc.cfg_dt.next = self.dt_reg.q.val();
        self.mt.cfg_dt.next = self.dt_reg.q.val();
        self.et_have.d.next =
            !self.engine_reset.val() & (self.et_have.q.val() | self.et.strobe.val());
        self.baseline.reset.next = self.rst.val();
        self.baseline.start.next = self.pc.strobe.val();
        self.baseline.pc_count.next = self.pc.count.val();
        self.baseline.et_period.next = self.et.period.val();
        self.baseline.et_negative.next = self.et.negative.val();
        self.baseline.et_valid.next =
            (self.et_have.q.val() | self.et.strobe.val()) & !self.et.stalled.val();
        self.baseline.mt_m.next = self.mt.m.val();
        self.baseline.mt_t.next = self.mt.t.val();
        self.baseline.mt_negative.next = self.mt.negative.val();
        self.baseline.cfg_dt.next = self.dt_reg.q.val();
        self.baseline.mode_shift.next = self.shift.val();
        // Estimators left out: their inputs to the converter are 0 (its results for them
        // are not used), so that nothing reads their counters and synthesis removes them.
        if !self.has_pc.val() {
            self.baseline.pc_count.next = self.n_zero.val();
        }
        if !self.has_et.val() {
            self.baseline.et_period.next = self.n_zero.val();
            self.baseline.et_negative.next = false;
            self.baseline.et_valid.next = false;
        }
        if !self.has_mt.val() {
            self.baseline.mt_m.next = self.n_zero.val();
            self.baseline.mt_t.next = self.n_zero.val();
            self.baseline.mt_negative.next = false;
        }
        if !self.has_baselines.val() {
            self.baseline.start.next = false;
        }

        // Faults.
        self.faults.reset.next = self.rst.val();
        self.faults.clear_faults.next = self.clear_faults.val();
        self.faults.illegal.next = self.decoder.illegal.val();
        self.faults.rejected_a.next = self.filter_a.rejected.val();
        self.faults.rejected_b.next = self.filter_b.rejected.val();
        self.faults.rejected_z.next = self.filter_z.rejected.val();
        self.faults.rev_fault.next = self.counter.rev_fault.val();

        // Outputs.
        self.position.next = self.counter.position.val();
        self.z_latch.next = self.counter.z_latch.val();
        self.index.next = self.counter.index.val();
        self.direction.next = self.decoder.direction.val();
        self.nep.next = self.table1.nep.val();
        self.ndt.next = self.table1.ndt.val();
        self.update.next = self.table1.update.val();
        self.speed_n1.next = self.calc.speed_n1.val();
        self.speed_n2.next = self.calc.speed_n2.val();
        self.speed_n3.next = self.calc.speed_n3.val();
        self.speed_strobe.next = self.calc.valid.val();
        self.speed_pc.next = self.baseline.speed_pc.val();
        self.speed_et.next = self.baseline.speed_et.val();
        self.speed_mt.next = self.baseline.speed_mt.val();
        self.baseline_strobe.next = self.baseline.valid.val();
        self.stalled_reg.d.next = self.timebase.stalled.val() & !self.rst.val();
        self.valid_reg.d.next = self.calc.have_speeds.val()
            & !self.timebase.stalled.val()
            & !self.cfg_error_reg.q.val()
            & !self.rst.val();
        self.stalled.next = self.stalled_reg.q.val();
        self.valid.next = self.valid_reg.q.val();
        self.fault_illegal.next = self.faults.fault_illegal.val();
        self.fault_overspeed.next = self.faults.fault_overspeed.val();
        self.fault_revolution.next = self.faults.fault_revolution.val();
        self.cfg_error.next = self.cfg_error_reg.q.val();
        self.glitch_count.next = self.faults.glitch_count.val();
        self.illegal_count.next = self.decoder.illegal_count.val();
        self.rev_error_count.next = self.counter.rev_error_count.val();
        self.speed_position.next = self.calc.speed_position.val();
        self.speed_nep.next = self.calc.speed_nep.val();
        self.speed_ndt.next = self.calc.speed_ndt.val();
        self.mt_strobe.next = self.mt.strobe.val();
        self.mt_m.next = self.mt.m.val();
        self.mt_t.next = self.mt.t.val();
        self.mt_negative.next = self.mt.negative.val();
        self.dt_active.next = self.dt_reg.q.val();
        // Speed outputs left out read 0 (CoreModel's rule).
        if !self.has_n1.val() {
            self.speed_n1.next = self.speed_zero.val();
        }
        if !self.has_n2.val() {
            self.speed_n2.next = self.speed_zero.val();
        }
        if !self.has_pc.val() {
            self.speed_pc.next = self.speed_zero.val();
        }
        if !self.has_et.val() {
            self.speed_et.next = self.speed_zero.val();
        }
        if !self.has_mt.val() {
            self.speed_mt.next = self.speed_zero.val();
            self.mt_strobe.next = false;
            self.mt_m.next = self.n_zero.val();
            self.mt_t.next = self.n_zero.val();
            self.mt_negative.next = false;
        }
        if !self.has_baselines.val() {
            self.baseline_strobe.next = false;
        }
    }
}
