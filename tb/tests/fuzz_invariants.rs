// SPDX-License-Identifier: MIT OR Apache-2.0
//! Fuzzing of the core's invariants on random and adversarial waveforms.
//!
//! The golden model (`golden::top::core::CoreModel`) is enough here: `random_cosim.rs` proves the
//! rust-hdl simulation and the emitted Verilog equal to it on every cycle of the same kind
//! of stimuli. Every waveform of every property goes through [`check_trace`], which asserts
//! on every cycle:
//! - counters never wrap: `glitch_count`, `illegal_count`, `rev_error_count` never decrease
//!   between resets and stay ≤ 65535; `nep`, `ndt` ≤ 2^N − 1; the position stays inside a
//!   revolution;
//! - the fault flags follow their events: a flag rises (or survives `clear_faults`) only
//!   with its event, every illegal transition and every revolution error raises its flag,
//!   reset clears everything;
//! - no speed outside the physically possible range: at most one decoder step per clock
//!   cycle, so |speed| ≤ dt / 2^s ω_lim, raw ≤ (dt << 16) >> s, for all six speeds;
//! - `speed_n3` has the sign of the direction of the steps it measured whenever `valid`;
//! - after a reversal (steps reconstructed from the position) the speeds are 0 and `valid`
//!   (a register of its conditions, one edge later) is low from the edge after until the
//!   next `speed_strobe`;
//! - after every mid-run reset the outputs equal those of a fresh model run on the inputs
//!   from that reset on (recovery is exactly a power-up).
//!
//! Dedicated properties build exact situations on top of random prefixes: an injected
//! illegal transition, a pulse shorter than the filter, `clear_faults`, recovery to a
//! valid and accurate speed after a reset, and a reversal from one constant speed to
//! another. Each prints its number of cases and cycles (`--nocapture`).
//!
//! Two findings of this fuzzing were fixed in the core and are kept as regression tests with
//! their minimal reproducers: `raising_cfg_filter_mid_run_keeps_position_and_counts` (the
//! start-up hold came back when `cfg_filter` was raised) and
//! `first_speeds_after_reset_are_within_budget` (the first speeds after reset came from a
//! time base that ran from reset, not from a step).

use golden::estimator::bounds::n3_error_budget;
use golden::estimator::speed_calc::latency_cycles;
use golden::estimator::speed_calc::mode_scale_error_lsb;
use golden::params::{Params, ERROR_COUNT_BITS};
use golden::top::core::{mode_shift, SYNC_CYCLES};
use golden::top::core::{CoreInputs, CoreModel, CoreOutputs};
use proptest::prelude::*;
use proptest::test_runner::{FileFailurePersistence, TestRunner};
use std::cell::{Cell, RefCell};
use std::time::Instant;
use tb::adversarial::{
    dt_eff, mode_changes_only_in_reset, modes_used, params12, params8, Case, Cfg, Channel, Knobs,
    Stim, Words,
};

/// Largest value of the 16-bit error counters.
const COUNT_MAX: u64 = (1 << ERROR_COUNT_BITS) - 1;
/// Fractional bits of every speed.
const F: u32 = golden::params::SPEED_FRAC_BITS;

/// What [`check_trace`] checked, summed over cases.
#[derive(Clone, Copy, Debug, Default)]
struct Seen {
    cases: u64,
    cycles: u64,
    /// Speed values compared with the physical range (six per strobe).
    speeds: u64,
    /// Cycles with `valid` and a non-zero n3 whose sign was checked.
    signs: u64,
    /// Reversals found from the position and checked.
    reversals: u64,
    /// Mid-run resets compared with a fresh model.
    resets: u64,
    /// Fault flag rises traced to their event.
    fault_rises: u64,
    /// `clear_faults` cycles with a flag up.
    clears: u64,
    /// Start-up holds re-entered by raising `cfg_filter` (see `check_trace`).
    reholds: u64,
    /// Property-specific events (injections, recoveries, …).
    events: u64,
    /// Largest latency observed for the property's event (cycles).
    max_latency: u64,
}

impl Seen {
    fn add(&mut self, o: &Seen) {
        self.cases += o.cases;
        self.cycles += o.cycles;
        self.speeds += o.speeds;
        self.signs += o.signs;
        self.reversals += o.reversals;
        self.resets += o.resets;
        self.fault_rises += o.fault_rises;
        self.clears += o.clears;
        self.reholds += o.reholds;
        self.events += o.events;
        self.max_latency = self.max_latency.max(o.max_latency);
    }
}

/// Run the golden model on `inputs`, checking the invariants listed in the module docs on
/// every cycle; returns the outputs.
fn check_trace(p: &Params, inputs: &[CoreInputs], seen: &mut Seen) -> Vec<CoreOutputs> {
    let mut m = CoreModel::new(p);
    let mut outs: Vec<CoreOutputs> = Vec::with_capacity(inputs.len());
    let counter_max = p.counter_max();
    let lines = u64::from(p.lines());
    // Largest effective dt since the last reset (the power-up dt_reg is the default).
    let mut dt_max = p.dt_cycles();
    // Start-up hold: the decoder and position counter are held in reset while
    // fill < 2 + max(cfg_filter, 1). `released`: the hold has ended since the last reset;
    // `rehold`: it began again (cfg_filter raised above the edges counted since reset).
    let (mut released, mut rehold) = (false, false);
    // Steps reconstructed from the position: exact while the index never resets the
    // position (cfg_z_mode 0 or 2) and the hold never comes back.
    let mut tracked = true;
    let mut last_step: Option<bool> = None;
    // Between a reversal and the next speed_strobe.
    let mut zeroed = false;
    // The core's registers reset at edge k when `reset` was sampled at edge k − 1 (the core
    // registers its reset: reset_to_effect = 1), and at edge 0 (the register powers up high).
    let resets_at = |k: usize| k == 0 || inputs[k - 1].reset;
    for (k, inp) in inputs.iter().enumerate() {
        // The hold ends once for all after a reset (raising cfg_filter later does not bring
        // it back): `rehold` below can never be set, and is kept as an assertion of that.
        let hold = resets_at(k) || (!released && m.fill() < SYNC_CYCLES + inp.cfg_filter.max(1));
        if resets_at(k) {
            released = false;
            rehold = false;
            tracked = true;
            last_step = None;
            zeroed = false;
            dt_max = 0;
        } else if hold {
            if released && !rehold {
                rehold = true;
                seen.reholds += 1;
            }
        } else {
            released = true;
        }
        if inp.cfg_z_mode % 2 == 1 || rehold {
            tracked = false;
        }
        dt_max = dt_max.max(dt_eff(p, inp.cfg_dt));
        let o = m.step(*inp);
        // The decoding mode in use at edge k: the mode register, cfg_mode sampled at k − 1.
        let s = mode_shift(if k == 0 { 0 } else { inputs[k - 1].cfg_mode });
        let ctx = || format!("cycle {k}: in {inp:?}\n  out {o:?}");
        // A reversal at this edge: `valid` falls at the next.
        let mut reversal_now = false;

        // Counters never wrap: they saturate (the widths are the ports').
        assert!(o.nep <= counter_max && o.ndt <= counter_max, "{}", ctx());
        assert!(
            o.glitch_count <= COUNT_MAX
                && o.illegal_count <= COUNT_MAX
                && o.rev_error_count <= COUNT_MAX,
            "{}",
            ctx()
        );
        // The position is an angle: it stays within one revolution of lines·2^s steps.
        let rev = lines << s;
        assert!(o.position < rev && o.z_latch < rev, "{}", ctx());

        // No speed beyond one decoder step per clock cycle: at most dt steps per dt, i.e.
        // dt/2^s lines per dt, raw ≤ (dt << F) >> s. Every speed (Rairán n1..n3 from Nep1 ≤
        // dt; PC count ≤ steps in a window of ≤ dt cycles; ET dt/period with period ≥ 1;
        // M/T m·dt/t with m ≤ t) is measured over a window of at most the largest dt used
        // since the reset that cleared the speeds.
        let bound = (dt_max << F) >> s;
        for v in [
            o.speed_n1, o.speed_n2, o.speed_n3, o.speed_pc, o.speed_et, o.speed_mt,
        ] {
            assert!(
                v.unsigned_abs() <= bound,
                "speed {v} beyond the physical bound {bound} (dt_max {dt_max}, s {s})\n{}",
                ctx()
            );
        }
        if o.speed_strobe || o.baseline_strobe {
            seen.speeds += 6;
        }

        if resets_at(k) {
            // Reset clears every register the user reads.
            assert_eq!(
                (
                    o.fault_illegal,
                    o.fault_overspeed,
                    o.fault_revolution,
                    o.valid,
                    o.glitch_count,
                    o.illegal_count,
                    o.rev_error_count,
                    o.position,
                    o.speed_n3,
                    o.speed_mt
                ),
                (false, false, false, false, 0, 0, 0, 0, 0, 0),
                "{}",
                ctx()
            );
        } else if let Some(pv) = outs.last().copied() {
            // Error counters count events since reset: they never go down, so they can
            // never wrap. (The decoder and position counter also restart with the start-up
            // hold; see `rehold`.)
            assert!(o.glitch_count >= pv.glitch_count, "{}", ctx());
            // The illegal and revolution counts live in the decoder and the position
            // counter, which the start-up hold resets (documented in `golden::top::core`; that it
            // can come back mid-run is the finding of
            // `raising_cfg_filter_mid_run_keeps_position_and_counts`).
            if !hold {
                assert!(
                    o.illegal_count >= pv.illegal_count && o.rev_error_count >= pv.rev_error_count,
                    "{}",
                    ctx()
                );
            }
            // A step at most per edge: the position moves by one step or not at all,
            // modulo a revolution, unless the index resets it.
            if tracked && !hold {
                let fwd = (pv.position + 1) % rev == o.position;
                let back = (pv.position + rev - 1) % rev == o.position;
                assert!(
                    o.position == pv.position || fwd || back,
                    "position jumped from {}\n{}",
                    pv.position,
                    ctx()
                );
                if fwd || back {
                    // A reversal: Table 1, the calculator and the speeds restart, so no
                    // speed mixes the two directions.
                    if last_step == Some(!fwd) {
                        assert_eq!(
                            (o.speed_n1, o.speed_n2, o.speed_n3, o.nep, o.ndt),
                            (0, 0, 0, 0, 1),
                            "reversal at this edge\n{}",
                            ctx()
                        );
                        zeroed = true;
                        reversal_now = true;
                        seen.reversals += 1;
                    }
                    last_step = Some(fwd);
                }
                // The decoder's direction output is the direction of its last step, one
                // edge ahead of the position.
                if let Some(d) = last_step {
                    assert_eq!(pv.direction, d, "direction output\n{}", ctx());
                }
            }
            if zeroed {
                if o.speed_strobe {
                    zeroed = false;
                } else {
                    assert!(
                        o.speed_n1 == 0
                            && o.speed_n2 == 0
                            && o.speed_n3 == 0
                            && (!o.valid || reversal_now),
                        "speed or valid before the first strobe after a reversal\n{}",
                        ctx()
                    );
                }
            }
            // The sign of n3 is the direction of the steps it measured: a step of the other
            // direction is a reversal (one edge after the decoder's direction output
            // changed), which zeroes the speeds.
            if o.valid && o.speed_n3 != 0 && !rehold {
                assert_eq!(o.speed_n3 > 0, pv.direction, "sign of n3\n{}", ctx());
                assert!(
                    o.speed_n1.signum() * o.speed_n3.signum() >= 0
                        && o.speed_n2.signum() * o.speed_n3.signum() >= 0,
                    "{}",
                    ctx()
                );
                seen.signs += 1;
            }
            // Flags follow their events. Events: the decoder's illegal register and the
            // position counter's rev_fault register (their counts rose at the previous
            // edge), the A/B filters' rejected registers (glitch_count rises at the same
            // edge). A flag is set one edge after its event, the event wins over
            // clear_faults, and only an event sets it.
            if k >= 2 && !resets_at(k - 1) {
                let pp = outs[k - 2];
                let illegal_event = pv.illegal_count > pp.illegal_count;
                let rev_event = pv.rev_error_count > pp.rev_error_count;
                if illegal_event {
                    assert!(
                        o.fault_illegal,
                        "illegal transition without flag\n{}",
                        ctx()
                    );
                }
                if rev_event {
                    assert!(
                        o.fault_revolution,
                        "revolution error without flag\n{}",
                        ctx()
                    );
                }
                let fresh = |now: bool, before: bool| now && (!before || inp.clear_faults);
                if fresh(o.fault_illegal, pv.fault_illegal) {
                    assert!(
                        illegal_event || pv.illegal_count == COUNT_MAX,
                        "fault_illegal without an illegal transition\n{}",
                        ctx()
                    );
                    seen.fault_rises += 1;
                }
                if fresh(o.fault_revolution, pv.fault_revolution) {
                    assert!(
                        rev_event || pv.rev_error_count == COUNT_MAX,
                        "fault_revolution without a revolution error\n{}",
                        ctx()
                    );
                    seen.fault_rises += 1;
                }
                if fresh(o.fault_overspeed, pv.fault_overspeed) {
                    assert!(
                        o.glitch_count > pv.glitch_count || pv.glitch_count == COUNT_MAX,
                        "fault_overspeed without a rejected pulse\n{}",
                        ctx()
                    );
                    seen.fault_rises += 1;
                }
                if inp.clear_faults
                    && (pv.fault_illegal || pv.fault_overspeed || pv.fault_revolution)
                {
                    seen.clears += 1;
                }
            }
        }
        outs.push(o);
    }
    // Recovery: a reset leaves no trace of the past. From the edge at which every reset
    // burst acts on (the edge after the first one that samples it: reset_to_effect), the
    // outputs are those of a model powered up at that first edge with the same inputs
    // (whose power-up reset acts there, and which has sampled the same configuration).
    for r in 1..inputs.len() {
        if inputs[r].reset && !inputs[r - 1].reset {
            let mut fresh = CoreModel::new(p);
            for (j, inp) in inputs.iter().enumerate().skip(r) {
                let f = fresh.step(*inp);
                if j == r {
                    continue;
                }
                assert_eq!(
                    f, outs[j],
                    "cycle {j}: after the reset at cycle {r} the core differs from a fresh one"
                );
            }
            seen.resets += 1;
        }
    }
    seen.cases += 1;
    seen.cycles += inputs.len() as u64;
    outs
}

/// Run `cases` cases of `strategy` through `check`, print what was checked and the time.
fn property<S: Strategy>(name: &str, cases: u32, strategy: S, check: impl Fn(S::Value, &mut Seen)) {
    let mut runner = TestRunner::new(ProptestConfig {
        cases,
        source_file: Some(file!()),
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        ..ProptestConfig::default()
    });
    let total = RefCell::new(Seen::default());
    let t0 = Instant::now();
    let result = runner.run(&strategy, |v| {
        let mut seen = Seen::default();
        check(v, &mut seen);
        total.borrow_mut().add(&seen);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{name}: {e}");
    }
    let t = total.into_inner();
    println!(
        "{name}: {} cases, {} cycles, {:.1} s; checked {} speeds, {} signs, {} reversals, \
         {} resets, {} fault rises, {} clears, {} re-entered holds; {} events, max latency {}",
        t.cases,
        t.cycles,
        t0.elapsed().as_secs_f64(),
        t.speeds,
        t.signs,
        t.reversals,
        t.resets,
        t.fault_rises,
        t.clears,
        t.reholds,
        t.events,
        t.max_latency
    );
}

fn cases(knobs: Knobs, max_chunks: usize) -> impl Strategy<Value = Case> {
    (
        any::<Words>(),
        prop::collection::vec(any::<Words>(), 1..max_chunks),
    )
        .prop_map(move |(head, body)| Case::decode(head, &body, knobs))
}

#[test]
fn adversarial_waveforms_keep_invariants() {
    for (name, p, n) in [
        ("adversarial 8-bit", params8(), 2000),
        ("adversarial 12-bit", params12(), 1000),
    ] {
        let knobs = Knobs::for_params(&p, 4000);
        let modes = Cell::new(0u8);
        property(name, n, cases(knobs, 64), |case, seen| {
            let inputs = case.inputs();
            assert!(mode_changes_only_in_reset(&inputs));
            modes.set(modes.get() | modes_used(&inputs));
            check_trace(&p, &inputs, seen);
        });
        assert_eq!(
            modes.get(),
            0b1111,
            "{name}: every cfg_mode must be exercised"
        );
    }
}

/// Random levels on A, B and Z, each held 1..8 cycles, with random configuration.
#[test]
fn random_waveforms_keep_invariants() {
    let p = params8();
    let knobs = Knobs::for_params(&p, 4000);
    let strategy = (
        any::<Words>(),
        prop::collection::vec((any::<u8>(), 1usize..8), 1..1500),
    );
    property(
        "random levels 8-bit",
        500,
        strategy,
        |(head, levels), seen| {
            let mut s = Case::decode(head, &[], knobs).start();
            for (l, n) in levels {
                s.levels(l & 1 == 1, l & 2 == 2, l & 4 == 4, n);
            }
            check_trace(&p, &s.finish(), seen);
        },
    );
}

/// A random prefix, then the levels held long enough for the synchronisers and the filter
/// (of length `filter`) to settle with no event in flight, a start-up hold that has ended,
/// and the fault flags cleared. Returns the stimulus.
fn settled(case: &Case, filter: u64) -> Stim {
    let mut s = case.stim();
    s.set_filter(filter);
    s.set_auto_z(false);
    s.hold(settle_cycles(filter));
    s.clear_faults(1);
    s.hold(2);
    s
}

/// Cycles after which a held level has passed the synchronisers and a filter of length
/// `filter`, the start-up hold is over and every rejected pulse has been counted.
fn settle_cycles(filter: u64) -> usize {
    (SYNC_CYCLES + filter.max(1) + 4) as usize
}

/// Short random prefixes (8-bit parameters).
fn prefixes() -> impl Strategy<Value = Case> {
    cases(Knobs::for_params(&params8(), 1500), 24)
}

#[test]
fn injected_illegal_transition_sets_the_flag_and_counts() {
    let p = params8();
    let strategy = (prefixes(), 0u64..13, 0usize..40);
    property(
        "injected illegal transition",
        1000,
        strategy,
        |(case, filter, extra), seen| {
            let mut s = settled(&case, filter);
            let t = s.len();
            // A and B toggled in the same cycle, held long enough to pass the filter.
            let l = filter.max(1) as usize;
            s.illegal(l + 8 + extra);
            // clear_faults on a quiet input clears the flag; the count stays.
            s.hold(settle_cycles(filter));
            let c = s.len();
            s.clear_faults(1);
            s.hold(settle_cycles(filter));
            let inputs = s.finish();
            let o = check_trace(&p, &inputs, seen);
            assert!(!o[t - 1].fault_illegal, "flag cleared before the injection");
            // Synchroniser (2 edges), filter (max(L, 1)), decoder (1): the count rises at
            // edge t + 2 + max(L, 1); the flag follows one edge later.
            let bound = t + 3 + l;
            let rose = (t..=bound).find(|&k| o[k].fault_illegal);
            let Some(k) = rose else {
                panic!("fault_illegal not set within {} cycles", bound - t)
            };
            seen.max_latency = seen.max_latency.max((k - t) as u64);
            assert_eq!(
                o[bound].illegal_count,
                (o[t - 1].illegal_count + 1).min(COUNT_MAX),
                "illegal_count must count the transition once"
            );
            assert!(o[c - 1].fault_illegal, "the flag is sticky");
            assert!(
                o[c..].iter().all(|x| !x.fault_illegal
                    && !x.fault_overspeed
                    && !x.fault_revolution
                    && x.illegal_count == o[c - 1].illegal_count),
                "clear_faults on a quiet input clears every flag and no count"
            );
            seen.events += 1;
        },
    );
}

#[test]
fn pulse_shorter_than_the_filter_is_a_glitch() {
    let p = params8();
    let strategy = (prefixes(), 2u64..41, any::<u16>(), 0u8..3);
    property(
        "pulse shorter than cfg_filter",
        1000,
        strategy,
        |(case, filter, w, ch), seen| {
            let width = 1 + usize::from(w) % (filter as usize - 1);
            let ch = [Channel::A, Channel::B, Channel::Z][usize::from(ch)];
            let mut s = settled(&case, filter);
            let t = s.len();
            s.glitch(ch, width, settle_cycles(filter));
            let c = s.len();
            s.clear_faults(1);
            s.hold(settle_cycles(filter));
            let inputs = s.finish();
            let o = check_trace(&p, &inputs, seen);
            assert!(!o[t - 1].fault_overspeed, "flag cleared before the pulse");
            // The filter sees the pulse 2 edges late, for `width` edges; the edge after
            // that rejects it; glitch_count and the flag take the rejection one edge later.
            let bound = t + width + 3;
            assert_eq!(
                o[bound].glitch_count,
                (o[t - 1].glitch_count + 1).min(COUNT_MAX),
                "the pulse is counted once (width {width}, filter {filter})"
            );
            let k = (t..=bound)
                .find(|&k| o[k].glitch_count > o[t - 1].glitch_count)
                .unwrap();
            seen.max_latency = seen.max_latency.max((k - t) as u64);
            // A or B too short is overspeed (or noise); the index is not a speed channel.
            let expect_flag = ch != Channel::Z;
            assert_eq!(o[bound].fault_overspeed, expect_flag, "channel {ch:?}");
            assert_eq!(o[c - 1].fault_overspeed, expect_flag, "the flag is sticky");
            assert!(
                o[c..]
                    .iter()
                    .all(|x| !x.fault_overspeed && !x.fault_illegal),
                "clear_faults on a quiet input clears the flags"
            );
            // The position and direction did not move: the pulse never passed.
            assert_eq!(o[c - 1].position, o[t - 1].position);
            seen.events += 1;
        },
    );
}

/// A clean quadrature motion: `count` state changes, `hold` cycles each.
#[derive(Clone, Copy, Debug)]
struct Motion {
    forward: bool,
    hold: usize,
}

impl Motion {
    /// Cycles between two decoder steps in mode shift `s` (4, 2, 1 state changes per step
    /// in x1, x2, x4).
    fn step_period(&self, s: u32) -> u64 {
        (4 * self.hold as u64) >> s
    }

    /// The true speed in lines per dt (ω_lim): a line is four state changes.
    fn lines_per_dt(&self, dt: u64) -> f64 {
        dt as f64 / (4.0 * self.hold as f64)
    }
}

/// Cycles from the end of a reset to the first `valid` at a clean constant speed, by the
/// core's rules (golden::top::core docs): the start-up hold (2 + max(L, 1) edges); the first
/// level change after it (≤ one line, 4·hold cycles) reaches the decoder's step 3 + max(L, 1)
/// edges later (synchroniser 2, filter max(L, 1), decoder 1) and restarts the estimator
/// there; the next dt tick comes dt later and the first step after it (≤ one line) primes it
/// with a restart; then 1 edge to the calculator's start and its latency 6(N + 17) + 10,
/// whose last edge writes the speed registers: the sum is
/// 2 + 3 + 2·max(L, 1) + 2·line + dt + L_calc + 1; and the core's reset acts one edge
/// after the last edge that samples `reset` (reset_to_effect).
fn valid_bound(p: &Params, filter: u64, hold: usize, dt: u64) -> u64 {
    let line = 4 * hold as u64;
    golden::top::ports::Latency::new(p, filter).reset_to_effect as u64
        + SYNC_CYCLES
        + 3
        + 2 * filter.max(1)
        + 2 * line
        + dt
        + u64::from(latency_cycles(p.counter_bits(), F))
        + 1
}

/// Does n3 (raw) lie within the Rairán budget of the true speed `r` (ω_lim)? The budget
/// is relative to the speed in steps (eq. (13) widened by the clock, at the n1 reported
/// beside it) plus the calculator's and the mode scaling's rounding.
fn within_budget(o: &CoreOutputs, r: f64, dt: u64, s: u32) -> Result<(), String> {
    let lsb = (-f64::from(F)).exp2();
    let n1_steps = o.speed_n1.unsigned_abs() as f64 * lsb * f64::from(1u32 << s);
    let n3 = o.speed_n3 as f64 * lsb;
    let budget = r * n3_error_budget(n1_steps, dt) + mode_scale_error_lsb(s) * lsb;
    let err = (n3.abs() - r).abs();
    if err <= budget * (1.0 + 1e-12) {
        Ok(())
    } else {
        Err(format!(
            "|n3| = {} vs true {r}: error {err} > budget {budget} (n1 = {n1_steps} steps/dt, dt {dt}, s {s})",
            n3.abs()
        ))
    }
}

/// Recovery: after a random prefix, a reset (mode possibly changed), then a clean constant
/// speed. The outputs from the reset on equal a fresh model's (checked by `check_trace`
/// for every reset); concretely, `valid` comes within [`valid_bound`] and stays, and from
/// every speed_strobe after the reset on n3 is within the Rairán budget of the true
/// speed, from the first speed_strobe on.
#[test]
fn recovery_after_reset_reaches_an_accurate_valid_speed() {
    let strategy = (
        prefixes(),
        (1usize..5, 0u8..3, any::<bool>(), any::<bool>()),
        (1usize..25, 20u64..256, any::<u16>(), 0u8..4, any::<bool>()),
    );
    let p = params8();
    property(
        "recovery after reset",
        600,
        strategy,
        |(case, (rc, mode, forward, timeout_default), (hold, dt, f, z_mode, auto_z)), seen| {
            let m = Motion { forward, hold };
            let s_ = mode_shift(mode);
            // A filter that passes the motion: each channel holds a level 2·hold cycles.
            let filter = u64::from(f) % (2 * hold as u64 + 1);
            let mut s = case.stim();
            let r0 = s.len();
            s.set_dt(dt);
            s.set_filter(filter);
            s.set_z_mode(z_mode);
            let need = m.step_period(s_).div_ceil(dt) + 2;
            s.set_timeout(if timeout_default && need < p.timeout_dt() {
                0
            } else {
                need.max(2)
            });
            s.set_auto_z(auto_z);
            s.reset_with_mode(rc, mode);
            let start = s.len();
            let vb = valid_bound(&p, filter, hold, dt);
            // Strobes are at least a calculator latency apart: room for several.
            let lc = u64::from(latency_cycles(p.counter_bits(), F));
            let run = vb + 6 * (lc + dt + 4 * hold as u64);
            s.steps(forward, hold, (run as usize).div_ceil(hold));
            let inputs = s.finish();
            let o = check_trace(&p, &inputs, seen);
            let first = (start..o.len())
                .find(|&k| o[k].valid)
                .unwrap_or_else(|| panic!("no valid after the reset at cycle {r0}"));
            let lat = (first - start) as u64;
            assert!(lat <= vb, "valid {lat} cycles after the reset, bound {vb}");
            seen.max_latency = seen.max_latency.max(lat);
            assert!(
                o[first..].iter().all(|x| x.valid),
                "valid dropped at a clean constant speed"
            );
            let r = m.lines_per_dt(dt);
            let strobes: Vec<usize> = (start..o.len()).filter(|&k| o[k].speed_strobe).collect();
            assert!(strobes.len() >= 4, "too few strobes: {}", strobes.len());
            for &k in &strobes {
                within_budget(&o[k], r, dt, s_)
                    .unwrap_or_else(|e| panic!("strobe at cycle {k}: {e}"));
                assert_eq!(o[k].speed_n3 > 0, forward, "sign at cycle {k}");
            }
            seen.events += strobes.len() as u64;
        },
    );
}

/// A reversal from one constant speed to another, after a reset: from the edge after the
/// decoder's first step of the new direction until the next speed_strobe, all three speeds
/// are 0 and `valid` is low (no speed mixes the two directions); every n3 after the
/// reversal has the new sign and a magnitude at most the new true speed plus its Rairán
/// budget, however fast the shaft turned before; `valid` comes back.
#[test]
fn reversal_zeroes_the_speed_and_never_overshoots() {
    let strategy = (
        (0u8..3, 20u64..256, 0u8..4),
        (any::<bool>(), 1usize..25, 1usize..25),
        (0usize..200, any::<u16>()),
    );
    let p = params8();
    property(
        "reversal",
        1000,
        strategy,
        |((mode, dt, z_mode), (forward, h1, h2), (extra, f)), seen| {
            let s_ = mode_shift(mode);
            let before = Motion { forward, hold: h1 };
            let after = Motion {
                forward: !forward,
                hold: h2,
            };
            // Each level is held at least min(h1, h2) cycles (the reversal undoes the last
            // change): a filter up to that passes the motion untouched.
            let filter = u64::from(f) % (h1.min(h2) as u64 + 1);
            let need = before
                .step_period(s_)
                .max(after.step_period(s_))
                .div_ceil(dt)
                + 2;
            let cfg = Cfg {
                dt,
                timeout: need,
                filter,
                z_mode,
            };
            let mut s = Stim::new(p.lines(), mode, cfg, true);
            let vb = valid_bound(&p, filter, h1.max(h2), dt);
            let t1 = vb + 4 * dt + extra as u64;
            s.steps(forward, h1, (t1 as usize).div_ceil(h1));
            let t_rev = s.len();
            let t2 = vb + 8 * dt + 16 * h2 as u64;
            s.steps(!forward, h2, (t2 as usize).div_ceil(h2));
            let inputs = s.finish();
            let o = check_trace(&p, &inputs, seen);
            // The decoder's first step of the new direction.
            let k_dir = (t_rev..o.len())
                .find(|&k| o[k].direction != forward)
                .expect("the reversal is decoded");
            let k = k_dir + 1;
            assert_eq!(
                (o[k].speed_n3, o[k].nep, o[k].ndt),
                (0, 0, 1),
                "reversal edge {k}"
            );
            assert!(
                !o[k + 1].valid,
                "valid low from the edge after the reversal"
            );
            let strobe = (k..o.len())
                .find(|&j| o[j].speed_strobe)
                .expect("a speed after the reversal");
            assert!(
                o[k..strobe]
                    .iter()
                    .all(|x| x.speed_n1 == 0 && x.speed_n2 == 0 && x.speed_n3 == 0)
                    && o[k + 1..strobe].iter().all(|x| !x.valid),
                "speeds 0 and valid low until the next strobe"
            );
            seen.max_latency = seen.max_latency.max((strobe - k) as u64);
            let r = after.lines_per_dt(dt);
            let lsb = (-f64::from(F)).exp2();
            for j in (k..o.len()).filter(|&j| o[j].speed_strobe) {
                let x = &o[j];
                assert!(
                    x.speed_n3 == 0 || (x.speed_n3 > 0) != forward,
                    "sign at {j}"
                );
                // Over the budget only if too fast; an early estimate from a partial window
                // may be low.
                let n1_steps = x.speed_n1.unsigned_abs() as f64 * lsb * f64::from(1u32 << s_);
                let limit =
                    r * (1.0 + n3_error_budget(n1_steps, dt)) + mode_scale_error_lsb(s_) * lsb;
                assert!(
                    x.speed_n3.unsigned_abs() as f64 * lsb <= limit * (1.0 + 1e-12),
                    "n3 {} ω_lim at cycle {j} exceeds the new speed {r} + budget ({limit})",
                    x.speed_n3.unsigned_abs() as f64 * lsb
                );
                seen.events += 1;
            }
            assert!(
                o.last().unwrap().valid,
                "valid comes back after the reversal"
            );
        },
    );
}

/// Regression (a finding of this fuzzing, fixed in the core): the start-up hold was
/// `fill < 2 + max(cfg_filter, 1)` with `fill` counting edges since reset (saturating only
/// at 2 + 65535). Raising `cfg_filter` at run time above the edges counted so far re-entered
/// the hold: without any `reset`, the decoder and the position counter were reset, so
/// `position`, `illegal_count` and `rev_error_count` dropped to 0. Now the hold ends once for
/// all (`Startup`'s `done` flag): `cfg_filter` only changes the filters.
#[test]
fn raising_cfg_filter_mid_run_keeps_position_and_counts() {
    let p = params8();
    let cfg = Cfg {
        dt: 20,
        timeout: 0,
        filter: 0,
        z_mode: 0,
    };
    // x4, filter off: 10 forward steps, an illegal transition, rest.
    let mut s = Stim::new(p.lines(), 2, cfg, false);
    s.hold(5);
    s.steps(true, 2, 10);
    s.illegal(4);
    s.hold(4);
    let t = s.len();
    // About 50 cycles after reset, cfg_filter = 100 with the shaft at rest.
    s.set_filter(100);
    s.hold(200);
    let inputs = s.finish();
    let o = golden::top::core::CoreModel::new(&p);
    let o: Vec<CoreOutputs> = inputs.iter().scan(o, |m, i| Some(m.step(*i))).collect();
    let before = o[t - 1];
    assert_eq!((before.position, before.illegal_count), (10, 1));
    for (k, x) in o.iter().enumerate().skip(t) {
        assert_eq!(
            (x.position, x.illegal_count, x.direction),
            (before.position, before.illegal_count, before.direction),
            "cycle {k} (cfg_filter raised at cycle {t})"
        );
    }
}

/// Regression (a finding of this fuzzing, fixed in the core): after a reset the estimator
/// was primed by its first restart, but its registers had not been measured from a step:
/// Ndt1 counted the ticks of a time base that ran from reset, and Nep1 was whatever the
/// first window held. With x1, dt = 68, a line every 84 cycles (0.81 ω_lim), after reset and
/// a rest of `d` cycles (d = 0..90), the first speed was 0 with `valid` high (first step
/// more than dt after reset) or 0.4 (−51 %, Ndt1 one too large). Now the first step of a
/// direction restarts the estimator at that step, after reset as after a reversal, and
/// every speed is within the budget.
#[test]
fn first_speeds_after_reset_are_within_budget() {
    let p = params8();
    let cfg = Cfg {
        dt: 68,
        timeout: 4,
        filter: 0,
        z_mode: 0,
    };
    let m = Motion {
        forward: false,
        hold: 21,
    };
    let mut bad = vec![];
    for d in 0..90 {
        let mut s = Stim::new(p.lines(), 0, cfg, false);
        s.hold(d);
        s.steps(m.forward, m.hold, 40);
        let inputs = s.finish();
        let mut model = CoreModel::new(&p);
        let o: Vec<CoreOutputs> = inputs.iter().map(|i| model.step(*i)).collect();
        for k in (0..o.len()).filter(|&k| o[k].speed_strobe).take(2) {
            if let Err(e) = within_budget(&o[k], m.lines_per_dt(68), 68, 0) {
                bad.push(format!(
                    "rest {d}, strobe at cycle {k} (valid {}): {e}",
                    o[k].valid
                ));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "{} strobes beyond the budget:\n{}",
        bad.len(),
        bad.join("\n")
    );
}
