// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of the whole `encspeed_core` (layer 2): the hardware's registers, clock
//! edge for clock edge, built from the bit-true models of its blocks.
//!
//! ```text
//! enc_a ─ sync ─ GlitchFilter ─┐
//! enc_b ─ sync ─ GlitchFilter ─┴─ QuadratureDecoder ─ step, forward ─┬─ PositionCounter ─ position, z_latch, index
//! enc_z ─ sync ─ GlitchFilter ──────────────────────────────────────┘│
//!                                     ┌────────────────────────────────┤
//!                                     ├─ Table1 (Rairán) ─ nep, ndt ─ SpeedCalc ─ speed_n1..n3
//!                                     └─ PcCounter, EtTimer, MtCounter ─ BaselineSpeeds ─ speed_pc, speed_et, speed_mt
//! ```
//!
//! Conventions as in [`crate::frontend`]: one [`CoreModel::step`] per rising clock edge with
//! the inputs applied during the cycle before it; every register is updated from the values
//! before the edge; `step` returns the outputs after the edge. Every output is a register
//! or a function of registers only.
//!
//! # Rules that are the core's own (the blocks' rules are in their modules)
//! - **Start-up.** The synchronisers and filters leave reset low. The decoder and the
//!   position counter are held in reset through the edge after the last one at which fewer
//!   than 2 + max(`cfg_filter`, 1) edges had passed since reset (`fill`): the rule is
//!   registered, so the hold lasts one edge longer than the filter needs. The first sample
//!   they take is then a filtered sample of the real channels: a channel already high at
//!   reset is not a step. The hold ends once for all: raising `cfg_filter` later does not
//!   bring it back.
//! - **Rairán's pulse** is a decoder step (x1, x2 or x4), of either direction. The estimator
//!   measures one direction at a time. The **first step of a direction** — the first after
//!   reset, or a **reversal** (a step whose direction differs from the previous step's) —
//!   resets Table 1 and counts that step as the first pulse of the new measurement (Cep = 1,
//!   the state a restart at that step leaves, with Nep1 and Ndt1 cleared), so the first
//!   window starts at a pulse as every later one does; it also resets the speed calculator
//!   and with it the speed registers (speeds 0, `valid` low). The estimator is **primed** by its
//!   first restart after that (a pulse after at least one dt tick, which writes an Ndt1
//!   measured between two steps); only then are its updates sent to the speed calculator.
//!   So no speed ever mixes the two directions, and none is computed from an Ndt1 or Nep1
//!   that was not measured from a step.
//! - **Mode scaling.** Table 1 counts decoder steps, 2^s per line (s = 0, 1, 2 in x1, x2,
//!   x4). The speed calculator computes n in steps per dt with F fractional bits and
//!   outputs n / 2^s in units of ω_lim (one line per dt), the shift latched with each
//!   request: the magnitude rounded to nearest, ties away from zero, then the sign. Error:
//!   ½ LSB in x1, ½ + ½/2^s LSB in x2 and x4 ([`mode_scale_error_lsb`](crate::estimator::speed_calc::mode_scale_error_lsb)). A change of mode
//!   resets the calculator, so every result uses the mode the core is in.
//! - **Configuration.** `cfg_dt` = 0 means the generation default dt, 1 is used as 2 and
//!   flags `cfg_error`; `cfg_timeout` = 0 means the generation default timeout; `cfg_mode` 3
//!   decodes as x4 and flags `cfg_error`. Every configuration input is registered
//!   once, at the core's edge, and the blocks read the registers (the glitch filters
//!   compare `cfg_filter` into a register an edge ahead, the same delay): a change of
//!   `cfg_filter` or `cfg_z_mode` acts from the edge after the one that samples it;
//!   `stalled` and `valid` show a new `cfg_timeout` from the edge after the one that
//!   samples it (they are registered, below). The effective dt is registered (`dt_active`,
//!   one edge later) and the time bases compare with that register an edge ahead, so a
//!   `cfg_dt` change moves the dt windows from two edges after it is sampled. A change of
//!   `cfg_mode` is registered with the mode ([`ModeReset`]): the edge after the one that
//!   sees it resets the whole core with the new mode in place (as `reset` does: position,
//!   estimators, counters and faults; a count in one mode means nothing in another), then
//!   the start-up hold runs again. `cfg_error` is registered from the inputs (one edge).
//! - **Reset.** `reset` is registered too ([`ModeReset`]): the core's registers reset at
//!   the edge after each edge that samples `reset` high
//!   ([`crate::top::ports::Latency::reset_to_effect`]), so that a flip-flop drives the
//!   core's widest fan-out. That register powers up high, so the first edge resets the
//!   core whatever `reset` is: [`CoreModel::new`]'s state is the state after it.
//! - **Faults.** `fault_illegal` (both channels changed between two samples),
//!   `fault_overspeed` (the A or B filter rejected a level shorter than `cfg_filter`
//!   cycles: a glitch, or edges closer than the filter passes) and `fault_revolution` (a
//!   revolution of one direction between two index edges had the wrong count) are sticky:
//!   set one edge after the event, cleared by reset or by `clear_faults` (an event in the
//!   same cycle wins). `glitch_count` counts the rejected pulses of A, B and Z,
//!   saturating.
//! - **valid** = a speed has been computed since reset or the last reversal, the shaft has
//!   moved within the timeout (`stalled` low) and the configuration is legal. Sticky faults
//!   do not clear it; they are reported beside it. `valid` and `stalled` are registers: each
//!   edge loads them with their conditions as the core's registers stood before it (0 at a
//!   reset edge), so the timeout's carry chain ends in a flip-flop and not in the logic
//!   that reads them (the register file's snapshot and status word).
//! - **Estimators left out** (`estimators`, [`SpeedOutput`]): a speed output that is not
//!   built reads 0 at every cycle (`speed_n1`, `speed_n2`, `speed_pc`, `speed_et`,
//!   `speed_mt`; without M/T also `mt_strobe`, `mt_m`, `mt_t`, `mt_negative`), and
//!   `baseline_strobe` stays low when none of PC, ET and M/T is built. Every other output is
//!   that of the full core, cycle for cycle: the built estimators' timing does not depend on
//!   the others.

use crate::baselines::baseline_speeds::{
    BaselineFormat, BaselineRequest, BaselineSpeedsInputs, BaselineSpeedsModel,
};
use crate::baselines::et_timer::{EtInputs, EtTimer};
use crate::baselines::mt_counter::{MtCounter, MtInputs};
use crate::baselines::pc_counter::{PcCounter, PcInputs};
use crate::estimator::speed_calc::{SpeedCalcInputs, SpeedCalcModel, SpeedFormat};
use crate::estimator::sync_estimator::Table1;
use crate::frontend::{
    CounterInputs, DecoderInputs, GlitchFilter, GlitchFilterInputs, PositionCounter,
    QuadratureDecoder, MODE_INVALID, MODE_X1, MODE_X2,
};
use crate::params::{
    max_value, EstimatorSet, Params, SpeedOutput, ERROR_COUNT_BITS, FILTER_BITS, MIN_DT_CYCLES,
    POSITION_BITS, SPEED_FRAC_BITS,
};
use crate::top::mode_reset::ModeReset;
use crate::top::port_fields::port_struct;
use serde::{Deserialize, Serialize};

/// Edges after reset before the synchronisers hold real samples.
pub const SYNC_CYCLES: u64 = 2;

port_struct! {
    /// Inputs of `encspeed_core` during one clock cycle (sampled at its rising edge).
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
    pub struct CoreInputs {
        /// Synchronous active-high reset.
        pub reset: bool,
        /// Encoder channel A (asynchronous).
        pub enc_a: bool,
        /// Encoder channel B (asynchronous).
        pub enc_b: bool,
        /// Encoder index Z (asynchronous).
        pub enc_z: bool,
        /// dt in clock cycles (0: the generation default; 1: used as 2, `cfg_error`).
        pub cfg_dt: u64,
        /// Zero-speed timeout in dt intervals (0: the generation default).
        pub cfg_timeout: u64,
        /// Glitch filter length in clock cycles (0: off).
        pub cfg_filter: u64,
        /// Decoding: 0 = x1, 1 = x2, 2 = x4 (3: x4 and `cfg_error`).
        pub cfg_mode: u8,
        /// Index: 0 = ignore, 1 = reset the position, 2 = latch it, 3 = latch then reset.
        pub cfg_z_mode: u8,
        /// Clear the sticky fault flags.
        pub clear_faults: bool,
    }
}

port_struct! {
    /// Outputs of `encspeed_core` after a rising clock edge. Speeds are values in units of
    /// 2^−F ω_lim (F = [`SPEED_FRAC_BITS`]); the ports carry them as two's complement.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
    pub struct CoreOutputs {
        /// Position in steps, 0 .. lines·2^s.
        pub position: u64,
        /// Position latched at the last index edge.
        pub z_latch: u64,
        /// One cycle: an index edge was processed.
        pub index: bool,
        /// Direction of the last step (true = forward).
        pub direction: bool,
        /// Nep1 of Table 1 (decoder steps).
        pub nep: u64,
        /// Ndt1 of Table 1.
        pub ndt: u64,
        /// One cycle: Table 1 wrote Nep1 or Ndt1.
        pub update: bool,
        /// n1 = Nep/Ndt, ω_lim.
        pub speed_n1: i64,
        /// n2, eq. (6), ω_lim.
        pub speed_n2: i64,
        /// n3, eq. (11), ω_lim: the estimate to use.
        pub speed_n3: i64,
        /// One cycle: `speed_n1..3` were just written.
        pub speed_strobe: bool,
        /// Fixed-time (PC) speed of the last window, ω_lim.
        pub speed_pc: i64,
        /// Fixed-space (ET) speed at the last window end, ω_lim.
        pub speed_et: i64,
        /// M/T speed of the last window, ω_lim.
        pub speed_mt: i64,
        /// One cycle: `speed_pc`, `speed_et`, `speed_mt` were just written.
        pub baseline_strobe: bool,
        /// `speed_n3` holds a measurement of the current direction, not stalled, legal
        /// configuration.
        pub valid: bool,
        /// No step for the zero-speed timeout.
        pub stalled: bool,
        /// Sticky: an illegal transition.
        pub fault_illegal: bool,
        /// Sticky: the A or B filter rejected a pulse.
        pub fault_overspeed: bool,
        /// Sticky: a revolution had the wrong count.
        pub fault_revolution: bool,
        /// `cfg_dt` = 1 or `cfg_mode` = 3 at the last edge.
        pub cfg_error: bool,
        /// Pulses rejected by the A, B and Z filters (saturating).
        pub glitch_count: u64,
        /// Illegal transitions (saturating).
        pub illegal_count: u64,
        /// Revolutions with the wrong count (saturating).
        pub rev_error_count: u64,
        /// With `speed_strobe` (held until the next): the end of the span of disc the speeds
        /// measure, as a position: for Nep1 = 1 the restart pulse that wrote Ndt1, for
        /// Nep1 ≥ 2 the last pulse of the window that wrote Nep1 (which started Nep1 − 1 steps
        /// before it). The eccentricity correction of n3 needs it (`golden::top::ecc_top`).
        pub speed_position: u64,
        /// With `speed_strobe`: the Nep1 the speeds were computed from.
        pub speed_nep: u64,
        /// With `speed_strobe`: the Ndt1 the speeds were computed from.
        pub speed_ndt: u64,
        /// One cycle: the M/T counter closed a window (`mt_m`, `mt_t`, `mt_negative` just
        /// written; `position` in this cycle is the position of the window's last step).
        pub mt_strobe: bool,
        /// M/T steps of the last window.
        pub mt_m: u64,
        /// M/T cycles spanning them (`golden::baselines::mt_counter`).
        pub mt_t: u64,
        /// The last window's steps were backward.
        pub mt_negative: bool,
        /// The dt in use, clock cycles (cfg_dt after its default and minimum, registered).
        pub dt_active: u64,
    }
}

/// log2 of the steps per line for `cfg_mode` (x1: 0, x2: 1, x4 and 3: 2).
pub fn mode_shift(cfg_mode: u8) -> u32 {
    match cfg_mode {
        MODE_X1 => 0,
        MODE_X2 => 1,
        _ => 2,
    }
}

/// Bit-true model of `encspeed_core`.
#[derive(Clone, Debug)]
pub struct CoreModel {
    default_dt: u64,
    default_timeout: u64,
    mode_reset: ModeReset,
    filter_reg: u64,
    z_mode_reg: u8,
    lines: u64,
    fill: u64,
    front_done: bool,
    /// The start-up hold, registered: the hold rule of the edge before.
    front_hold: bool,
    sync: [[bool; 2]; 3],
    filters: [GlitchFilter; 3],
    decoder: QuadratureDecoder,
    position: PositionCounter,
    have_dir: bool,
    last_dir: bool,
    dt_reg: u64,
    /// `dt_reg` one edge later: the dt Table 1's time base compares with (its `due` register
    /// is set an edge ahead from the dt register).
    dt_window: u64,
    timeout_reg: u64,
    engine: Table1,
    primed: bool,
    /// The speed calculator; its output registers are the core's `speed_n1..3`,
    /// `speed_strobe`, `speed_position/nep/ndt` and the "a speed since reset" of `valid`.
    calc: SpeedCalcModel,
    window_last: u64,
    restart_pos: u64,
    restart_seen: bool,
    cfg_error: bool,
    /// The `stalled` and `valid` outputs: registered from their conditions before the edge
    /// (0 at a reset edge), so that the timeout comparison ends in a flip-flop.
    stalled_out: bool,
    valid_out: bool,
    faults: [bool; 3],
    glitch_count: u64,
    pc: PcCounter,
    et: EtTimer,
    mt: MtCounter,
    et_have: bool,
    baseline: BaselineSpeedsModel,
    /// The speed outputs built (`estimators`); the others read 0.
    estimators: EstimatorSet,
}

/// Index of the channels in [`CoreModel`]'s arrays.
const A: usize = 0;
const B: usize = 1;
const Z: usize = 2;

impl CoreModel {
    /// A core model in the state the hardware has after reset.
    pub fn new(p: &Params) -> CoreModel {
        let format = SpeedFormat::new(p.counter_bits(), SPEED_FRAC_BITS)
            .expect("validated parameters give a legal speed format");
        CoreModel {
            default_dt: p.dt_cycles(),
            default_timeout: p.timeout_dt(),
            mode_reset: ModeReset::new(),
            filter_reg: 0,
            z_mode_reg: 0,
            lines: u64::from(p.lines()),
            fill: 0,
            front_done: false,
            front_hold: true,
            sync: [[false; 2]; 3],
            filters: std::array::from_fn(|_| GlitchFilter::new(FILTER_BITS, ERROR_COUNT_BITS)),
            decoder: QuadratureDecoder::new(ERROR_COUNT_BITS),
            position: PositionCounter::new(POSITION_BITS, ERROR_COUNT_BITS),
            have_dir: false,
            last_dir: false,
            dt_reg: p.dt_cycles(),
            dt_window: p.dt_cycles(),
            timeout_reg: p.timeout_dt(),
            engine: Table1::new(p),
            primed: false,
            calc: SpeedCalcModel::new(format),
            window_last: 0,
            restart_pos: 0,
            restart_seen: false,
            cfg_error: false,
            stalled_out: false,
            valid_out: false,
            faults: [false; 3],
            glitch_count: 0,
            pc: PcCounter::new(p.counter_bits()),
            et: EtTimer::new(p.counter_bits()),
            mt: MtCounter::new(p.counter_bits()),
            et_have: false,
            baseline: BaselineSpeedsModel::new(
                BaselineFormat::new(p.counter_bits(), SPEED_FRAC_BITS)
                    .expect("validated parameters give a legal baseline format"),
            ),
            estimators: p.estimators(),
        }
    }

    /// `v` if speed output `e` is built, else 0 (its port is tied low).
    fn built<T: Default>(&self, e: SpeedOutput, v: T) -> T {
        if self.estimators.has(e) {
            v
        } else {
            T::default()
        }
    }

    /// The Table 1 registers.
    pub fn engine(&self) -> &Table1 {
        &self.engine
    }

    /// Edges since reset (saturating), for the start-up hold.
    pub fn fill(&self) -> u64 {
        self.fill
    }

    /// The estimator has been primed since reset or the last reversal.
    pub fn primed(&self) -> bool {
        self.primed
    }

    /// The effective dt register (clock cycles), the value of `dt_active`.
    pub fn dt(&self) -> u64 {
        self.dt_reg
    }

    /// The effective dt for a `cfg_dt` value.
    fn dt_eff(&self, cfg_dt: u64) -> u64 {
        if cfg_dt == 0 {
            self.default_dt
        } else {
            cfg_dt.max(MIN_DT_CYCLES)
        }
    }

    /// One rising clock edge with `inp` applied; returns the outputs after the edge.
    pub fn step(&mut self, inp: CoreInputs) -> CoreOutputs {
        assert!(inp.cfg_mode <= MODE_INVALID, "cfg_mode = {}", inp.cfg_mode);
        // The configuration registers before the edge (module docs: Configuration).
        let rst = self.mode_reset.rst();
        let (stalled_now, valid_now) = self.stalled_and_valid();
        let mode = self.mode_reset.mode();
        let shift = mode_shift(mode);
        let (cfg_filter, cfg_z_mode) = (self.filter_reg, self.z_mode_reg);
        // Registered values before the edge.
        let filt = self.filters.each_ref().map(|f| f.outputs());
        let dec = self.decoder.state();
        let pos = self.position.outputs();
        let t1 = self.engine.outputs();
        let pc = self.pc.outputs();
        let et = self.et.outputs();
        let mt = self.mt.outputs();

        let settling = self.fill < SYNC_CYCLES + cfg_filter.max(1);
        // The hold applies one edge after the rule that sets it (a register: the rule's
        // comparison does not reach the reset of the decoder and the counter in one cycle).
        let front_reset = rst || self.front_hold;
        // The first step of a direction (after reset or a reversal) restarts the estimator
        // at that step; a reversal also clears the speeds.
        let reversal = dec.step && self.have_dir && dec.forward != self.last_dir;
        let first_step = dec.step && (!self.have_dir || reversal);
        let engine_reset = rst || first_step;
        let restart = !engine_reset && dec.step && self.engine.state().cdt != 0;
        let primed_before = self.primed;

        for (c, f) in self.filters.iter_mut().enumerate() {
            f.step(GlitchFilterInputs {
                reset: rst,
                level_in: self.sync[c][1],
                // The filters compare an edge ahead: they take the input, which acts one
                // edge later, as the filter register does.
                cfg_filter: inp.cfg_filter,
            });
        }
        self.decoder.step(DecoderInputs {
            reset: front_reset,
            a: filt[A].level_out,
            b: filt[B].level_out,
            cfg_mode: mode,
        });
        self.position.step(CounterInputs {
            reset: front_reset,
            step: dec.step,
            forward: dec.forward,
            z: filt[Z].level_out,
            counts_per_rev: (self.lines << shift) & max_value(POSITION_BITS),
            cfg_z_mode,
        });
        if engine_reset {
            self.engine.reset_with_pulse(dec.step && !rst);
        } else {
            self.engine.step(dec.step, self.dt_window);
        }
        self.primed = !engine_reset && (self.primed || restart);
        let calc_start = t1.update && primed_before;
        // Span ends (`speed_position`): the restart pulse is in `position` the edge after
        // its restart; the window's last pulse is `position` at the tick that writes Nep1
        // (a pulse on that tick is not in the window). The calculator carries the span end
        // of each request with it and publishes it with the request's speeds.
        let restart_now = if self.restart_seen {
            pos.position
        } else {
            self.restart_pos
        };
        self.calc.step(SpeedCalcInputs {
            reset: engine_reset,
            start: calc_start,
            nep: t1.nep,
            ndt: t1.ndt,
            negative: !self.last_dir,
            shift,
            position: if t1.nep == 1 {
                restart_now
            } else {
                self.window_last
            },
        });
        let written = self.engine.state();
        if engine_reset {
            self.window_last = 0;
            self.restart_pos = 0;
            self.restart_seen = false;
        } else {
            if written.wrote_nep {
                self.window_last = pos.position;
            }
            self.restart_pos = restart_now;
            self.restart_seen = written.restarted;
        }
        let (r, st, fw) = (rst, dec.step, dec.forward);
        self.pc.step(PcInputs {
            reset: r,
            step: st,
            forward: fw,
            cfg_dt: self.dt_reg,
        });
        self.et.step(EtInputs {
            reset: r,
            step: st,
            forward: fw,
        });
        self.mt.step(MtInputs {
            reset: r,
            step: st,
            forward: fw,
            cfg_dt: self.dt_reg,
        });
        self.baseline.step(BaselineSpeedsInputs {
            reset: rst,
            start: pc.strobe,
            req: BaselineRequest {
                pc_count: pc.count,
                et_period: et.period,
                et_negative: et.negative,
                et_valid: (self.et_have || et.strobe) && !et.stalled,
                mt_m: mt.m,
                mt_t: mt.t,
                mt_negative: mt.negative,
                cfg_dt: self.dt_reg,
                mode_shift: shift,
            },
        });
        self.et_have = !engine_reset && (self.et_have || et.strobe);
        let events = [
            dec.illegal,
            filt[A].rejected || filt[B].rejected,
            pos.rev_fault,
        ];
        for (f, e) in self.faults.iter_mut().zip(events) {
            *f = !rst && ((*f && !inp.clear_faults) || e);
        }
        let rejected: u64 = filt.iter().map(|f| u64::from(f.rejected)).sum();
        self.glitch_count = if rst {
            0
        } else {
            (self.glitch_count + rejected).min(max_value(ERROR_COUNT_BITS))
        };
        if rst {
            self.have_dir = false;
            self.last_dir = false;
        } else if dec.step {
            self.have_dir = true;
            self.last_dir = dec.forward;
        }
        (self.stalled_out, self.valid_out) = (stalled_now && !rst, valid_now && !rst);
        self.cfg_error = inp.cfg_dt == 1 || inp.cfg_mode == MODE_INVALID;
        self.dt_window = self.dt_reg;
        self.dt_reg = self.dt_eff(inp.cfg_dt);
        self.mode_reset.step(inp.reset, inp.cfg_mode);
        self.filter_reg = inp.cfg_filter;
        self.z_mode_reg = inp.cfg_z_mode;
        self.timeout_reg = if inp.cfg_timeout == 0 {
            self.default_timeout
        } else {
            inp.cfg_timeout
        };
        for (c, level) in [inp.enc_a, inp.enc_b, inp.enc_z].into_iter().enumerate() {
            self.sync[c] = if rst {
                [false; 2]
            } else {
                [level, self.sync[c][0]]
            };
        }
        self.front_hold = rst || (!self.front_done && settling);
        self.front_done = !rst && (self.front_done || !settling);
        self.fill = if rst {
            0
        } else {
            (self.fill + 1).min(SYNC_CYCLES + max_value(FILTER_BITS))
        };
        self.outputs()
    }

    /// The conditions of `stalled` (Cdt has reached the timeout) and `valid` (a speed since
    /// reset or the last reversal, not stalled, legal configuration) as the registers stand.
    fn stalled_and_valid(&self) -> (bool, bool) {
        let stalled = self.engine.state().cdt >= self.timeout_reg;
        let valid = self.calc.outputs().have_speeds && !stalled && !self.cfg_error;
        (stalled, valid)
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> CoreOutputs {
        let t1 = self.engine.outputs();
        let dec = self.decoder.state();
        let pos = self.position.outputs();
        let calc = self.calc.outputs();
        CoreOutputs {
            position: pos.position,
            z_latch: pos.z_latch,
            index: pos.index,
            direction: dec.direction,
            nep: t1.nep,
            ndt: t1.ndt,
            update: t1.update,
            speed_n1: self.built(SpeedOutput::N1, calc.speeds.n1),
            speed_n2: self.built(SpeedOutput::N2, calc.speeds.n2),
            speed_n3: calc.speeds.n3,
            speed_strobe: calc.valid,
            speed_pc: self.built(SpeedOutput::Pc, self.baseline.outputs().speeds.pc),
            speed_et: self.built(SpeedOutput::Et, self.baseline.outputs().speeds.et),
            speed_mt: self.built(SpeedOutput::Mt, self.baseline.outputs().speeds.mt),
            // No converter without a baseline.
            baseline_strobe: self.baseline.outputs().valid && self.estimators.has_baselines(),
            valid: self.valid_out,
            stalled: self.stalled_out,
            fault_illegal: self.faults[0],
            fault_overspeed: self.faults[1],
            fault_revolution: self.faults[2],
            cfg_error: self.cfg_error,
            glitch_count: self.glitch_count,
            illegal_count: dec.illegal_count,
            rev_error_count: pos.rev_error_count,
            speed_position: calc.tag.position,
            speed_nep: calc.tag.nep,
            speed_ndt: calc.tag.ndt,
            mt_strobe: self.built(SpeedOutput::Mt, self.mt.outputs().strobe),
            mt_m: self.built(SpeedOutput::Mt, self.mt.outputs().m),
            mt_t: self.built(SpeedOutput::Mt, self.mt.outputs().t),
            mt_negative: self.built(SpeedOutput::Mt, self.mt.outputs().negative),
            dt_active: self.dt_reg,
        }
    }
}
