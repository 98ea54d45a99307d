// SPDX-License-Identifier: MIT OR Apache-2.0
//! The bit-true counters of the three baseline estimators — `golden::baselines::pc_counter` (fixed
//! time), `golden::baselines::et_timer` (fixed space), `golden::baselines::mt_counter` (M/T):
//! - hand-worked sequences (expected values by hand, in the comments);
//! - plant-driven pulse trains (`golden::ideal::plant`, x1 steps as the quadrature decoder makes
//!   them, each stamped at the first clock edge at or after its instant): the integer
//!   outputs equal the layer-1 float estimators (`golden::ideal::fixed_time`,
//!   `golden::ideal::fixed_space`, `golden::ideal::mt::mt_estimates`) on the stamped instants;
//! - the same measurements against the error bounds (max and RMS), at constant speed.

use golden::baselines::et_timer::{et_error_bound, EtInputs, EtOutputs, EtTimer};
use golden::baselines::mt_counter::{mt_error_bound_at_speed, MtCounter, MtInputs, MtOutputs};
use golden::baselines::pc_counter::{pc_error_bound, PcCounter, PcInputs, PcOutputs};
use golden::ideal::mt::mt_estimates;
use golden::ideal::plant::{edges, initial_levels, Channel, Disc, Profile};
use golden::ideal::{fixed_space, fixed_time};

const F: (bool, bool) = (true, true);
const B: (bool, bool) = (true, false);

/// Steps (edge index → forward) as a function of the edge index, from a list.
fn at(list: &[(u64, (bool, bool))], k: u64) -> (bool, bool) {
    list.iter()
        .find(|(j, _)| *j == k)
        .map_or((false, false), |x| x.1)
}

fn run_pc(
    bits: u32,
    dt: u64,
    edges_to: u64,
    steps: &[(u64, (bool, bool))],
) -> Vec<(u64, PcOutputs)> {
    let mut c = PcCounter::new(bits);
    let mut out = vec![];
    for k in 0..=edges_to {
        let (step, forward) = at(steps, k);
        let o = c.step(PcInputs {
            reset: k == 0,
            step,
            forward,
            cfg_dt: dt,
        });
        if o.strobe {
            out.push((k, o));
        }
    }
    out
}

#[test]
fn pc_by_hand() {
    // N = 4 (count −8..7), dt = 4: reset at edge 0, window ends at edges 4, 8, 12.
    // Window [0, 4): F at 1, 2 → +2. Window [4, 8): F at 4 (a window-end edge starts the
    // next window), B at 5, 6, 7 → 1 − 3 = −2. Window [8, 12): nothing → 0.
    let got = run_pc(4, 4, 12, &[(1, F), (2, F), (4, F), (5, B), (6, B), (7, B)]);
    let want: Vec<(u64, i64)> = vec![(4, 2), (8, -2), (12, 0)];
    assert_eq!(
        got.iter().map(|(k, o)| (*k, o.count)).collect::<Vec<_>>(),
        want
    );
    assert!(got.iter().all(|(_, o)| !o.saturated));
    // N = 3 (count −4..3), dt = 7: F at 1..=6 → 6, clamped to 3; B at 7..=13 → −7,
    // clamped to −4; then F at 14, B at 15 → 0, not saturated.
    let mut steps: Vec<(u64, (bool, bool))> = (1..=6).map(|k| (k, F)).collect();
    steps.extend((7..=13).map(|k| (k, B)));
    steps.extend([(14, F), (15, B)]);
    let got = run_pc(3, 7, 21, &steps);
    let want = vec![(7, 3, true), (14, -4, true), (21, 0, false)];
    assert_eq!(
        got.iter()
            .map(|(k, o)| (*k, o.count, o.saturated))
            .collect::<Vec<_>>(),
        want
    );
}

#[test]
fn pc_dt_changes_and_zero() {
    // cfg_dt = 0 counts as 1: a window end on every edge; the step of a window-end edge is
    // published one edge later.
    let mut c = PcCounter::new(8);
    c.step(PcInputs {
        reset: true,
        ..Default::default()
    });
    let o1 = c.step(PcInputs {
        step: true,
        forward: true,
        ..Default::default()
    });
    let o2 = c.step(PcInputs::default());
    assert!(o1.strobe && o2.strobe);
    assert_eq!((o1.count, o2.count), (0, 1));
    // dt = 10 for 6 edges (phase 6 after edge 6), then dt = 3, sampled at edge 7: the
    // phase after it, 7 ≥ 3 − 1, ends the window at edge 8 (a dt change acts one edge
    // later), then every 3 edges.
    let mut c = PcCounter::new(8);
    let mut ends = vec![];
    for k in 0..=12u64 {
        let o = c.step(PcInputs {
            reset: k == 0,
            cfg_dt: if k <= 6 { 10 } else { 3 },
            ..Default::default()
        });
        if o.strobe {
            ends.push(k);
        }
    }
    assert_eq!(ends, vec![8, 11]);
}

fn run_et(bits: u32, edges_to: u64, steps: &[(u64, (bool, bool))]) -> Vec<(u64, EtOutputs)> {
    let mut c = EtTimer::new(bits);
    (0..=edges_to)
        .map(|k| {
            let (step, forward) = at(steps, k);
            (
                k,
                c.step(EtInputs {
                    reset: k == 0,
                    step,
                    forward,
                }),
            )
        })
        .collect()
}

#[test]
fn et_by_hand() {
    // N = 3 (max 7). F at 2: first step, no period. F at 5: period 3. B at 6: reversal, no
    // period. B at 8: period 2, negative. Then nothing: e = 7 after edge 15 (8 + 7) →
    // stalled. B at 20: period saturated at 7.
    let trace = run_et(3, 22, &[(2, F), (5, F), (6, B), (8, B), (20, B)]);
    let strobes: Vec<(u64, u64, bool)> = trace
        .iter()
        .filter(|(_, o)| o.strobe)
        .map(|(k, o)| (*k, o.period, o.negative))
        .collect();
    assert_eq!(strobes, vec![(5, 3, false), (8, 2, true), (20, 7, true)]);
    let stalled: Vec<u64> = trace
        .iter()
        .filter(|(_, o)| o.stalled)
        .map(|x| x.0)
        .collect();
    // The step at 2 comes before e can reach 7; after the step at 8, e = 7 at edges 15..=19.
    assert_eq!(stalled, (15..=19).collect::<Vec<_>>());
}

fn run_mt(
    bits: u32,
    dt: u64,
    edges_to: u64,
    steps: &[(u64, (bool, bool))],
) -> Vec<(u64, MtOutputs)> {
    let mut c = MtCounter::new(bits);
    (0..=edges_to)
        .map(|k| {
            let (step, forward) = at(steps, k);
            (
                k,
                c.step(MtInputs {
                    reset: k == 0,
                    step,
                    forward,
                    cfg_dt: dt,
                }),
            )
        })
        .collect()
}

#[test]
fn mt_by_hand() {
    // N = 4 (max 15), dt = 5: window ends at 5, 10, 15, … (windows (5k−5, 5k]).
    // F at 2, 4: end 5 sets the first anchor (step 4), no output.
    // F at 6, 9: end 10 → m = 2, T = 9 − 4 = 5.
    // F at 12, 15 (15 is a window end, included): end 15 → m = 2, T = 15 − 9 = 6.
    // Nothing: end 20 → m = 0, T = 20 − 15 = 5 (cycles since the last step).
    // F at 23: end 25 → m = 1, T = 23 − 15 = 8.
    // B at 27 (reversal: restarts on it, the old measurement is dropped), B at 29:
    // end 30 → m = 1, T = 29 − 27 = 2, negative.
    // Nothing: end 35 → m = 0, T = 35 − 29 = 6, negative.
    // 15 cycles after 29 (edge 44): stalled; end 45 → m = 0, T = 15 (saturated).
    // F at 50 (window end): the old measurement closes without it: m = 0, T = 15; the
    // reversal anchors on 50. F at 53: end 55 → m = 1, T = 3, forward.
    let steps = [
        (2, F),
        (4, F),
        (6, F),
        (9, F),
        (12, F),
        (15, F),
        (23, F),
        (27, B),
        (29, B),
        (50, F),
        (53, F),
    ];
    let trace = run_mt(4, 5, 55, &steps);
    let strobes: Vec<(u64, u64, u64, bool)> = trace
        .iter()
        .filter(|(_, o)| o.strobe)
        .map(|(k, o)| (*k, o.m, o.t, o.negative))
        .collect();
    assert_eq!(
        strobes,
        vec![
            (10, 2, 5, false),
            (15, 2, 6, false),
            (20, 0, 5, false),
            (25, 1, 8, false),
            (30, 1, 2, true),
            (35, 0, 6, true),
            (40, 0, 11, true),
            (45, 0, 15, true),
            (50, 0, 15, true),
            (55, 1, 3, false),
        ]
    );
    let stalled: Vec<u64> = trace
        .iter()
        .filter(|(_, o)| o.stalled)
        .map(|x| x.0)
        .collect();
    assert_eq!(stalled, (44..=49).collect::<Vec<_>>());
}

// ---------------------------------------------------------------------------------------
// Plant-driven
// ---------------------------------------------------------------------------------------

const CLOCK_HZ: f64 = 1e6;
const LINES: u32 = 100;
/// dt in clock cycles (1 ms): ω_lim = 1/(LINES·dt) = 10 rev/s.
const DT: u64 = 1000;
const OMEGA_LIM: f64 = CLOCK_HZ / (LINES as f64 * DT as f64);

/// A pulse of the plant: its instant in clock cycles, its stamp (sampling edge ⌈t⌉) and
/// direction. x1 decoding: a change of A while B is low is a step, forward iff A rises.
#[derive(Clone, Copy, Debug)]
struct Pulse {
    t: f64,
    edge: u64,
    forward: bool,
}

fn plant_pulses(profile: &Profile) -> Vec<Pulse> {
    let disc = Disc::new(LINES).unwrap();
    let mut levels = initial_levels(profile, &disc);
    let mut out: Vec<Pulse> = vec![];
    for e in edges(profile, &disc) {
        if e.channel == Channel::A && !levels.b {
            let t = e.t * CLOCK_HZ;
            let edge = t.ceil() as u64;
            assert!(edge >= 1, "a pulse on the reset edge");
            if let Some(p) = out.last() {
                assert!(edge > p.edge, "two pulses on one clock edge");
            }
            out.push(Pulse {
                t,
                edge,
                forward: e.rising,
            });
        }
        levels.apply(&e);
    }
    out
}

/// The three models driven through edges 0 (reset) ..= `last`; their strobed outputs.
struct Runs {
    pc: Vec<(u64, PcOutputs)>,
    et: Vec<(u64, EtOutputs)>,
    mt: Vec<(u64, MtOutputs)>,
}

fn run_all(pulses: &[Pulse], last: u64) -> Runs {
    let (mut pc, mut et, mut mt) = (PcCounter::new(24), EtTimer::new(24), MtCounter::new(24));
    let mut runs = Runs {
        pc: vec![],
        et: vec![],
        mt: vec![],
    };
    let mut next = pulses.iter().peekable();
    for k in 0..=last {
        let (step, forward) = match next.peek() {
            Some(p) if p.edge == k => (true, next.next().unwrap().forward),
            _ => (false, false),
        };
        let reset = k == 0;
        let o = pc.step(PcInputs {
            reset,
            step,
            forward,
            cfg_dt: DT,
        });
        if o.strobe {
            runs.pc.push((k, o));
        }
        let o = et.step(EtInputs {
            reset,
            step,
            forward,
        });
        if o.strobe {
            runs.et.push((k, o));
        }
        let o = mt.step(MtInputs {
            reset,
            step,
            forward,
            cfg_dt: DT,
        });
        if o.strobe {
            runs.mt.push((k, o));
        }
    }
    runs
}

/// Bit-true counters = float estimators on the stamped instants, for a one-direction
/// profile (speed > 0).
fn check_against_floats(pulses: &[Pulse], last: u64, runs: &Runs) {
    let stamps: Vec<f64> = pulses.iter().map(|p| p.edge as f64).collect();
    let ft = fixed_time(&stamps, DT as f64, last as f64).unwrap();
    assert_eq!(runs.pc.len(), ft.len());
    for ((k, o), e) in runs.pc.iter().zip(&ft) {
        assert_eq!((*k as f64, o.count as f64), (e.t, e.n), "PC");
    }
    let fs = fixed_space(&stamps, DT as f64, 1.0).unwrap();
    assert_eq!(runs.et.len(), fs.len());
    for ((k, o), e) in runs.et.iter().zip(&fs) {
        assert_eq!((*k as f64, DT as f64 / o.period as f64), (e.t, e.n), "ET");
    }
    // mt_estimates stamps the raw instants itself (q = 1 cycle).
    let raw: Vec<f64> = pulses.iter().map(|p| p.t).collect();
    let me = mt_estimates(&raw, DT as f64, 1.0, last as f64);
    assert_eq!(runs.mt.len(), me.len());
    for ((k, o), e) in runs.mt.iter().zip(&me) {
        assert_eq!((*k as f64, o.m, o.t as f64), (e.t, e.m, e.span), "M/T");
    }
}

#[derive(Default)]
struct Stats {
    n: usize,
    max: f64,
    sum_sq: f64,
    /// Largest error/bound ratio.
    worst: f64,
}

impl Stats {
    fn add(&mut self, err: f64, bound: f64) {
        // Strictly below in exact arithmetic; equal up to rounding when a pulse period is
        // a whole number of cycles.
        assert!(
            err <= bound * (1.0 + 1e-9),
            "error {err} above bound {bound}"
        );
        self.n += 1;
        self.max = self.max.max(err);
        self.sum_sq += err * err;
        self.worst = self.worst.max(err / bound);
    }
    fn rms(&self) -> f64 {
        (self.sum_sq / self.n as f64).sqrt()
    }
}

#[test]
fn plant_constant_speed_sweep_equals_floats_and_stays_within_bounds() {
    // r from 0.02 to 450 ω_lim (pulse period 50 000 to 2.2 cycles), log-spaced, plus whole
    // numbers of pulses per window and whole numbers of cycles per pulse.
    let mut speeds: Vec<f64> = (0..36)
        .map(|i| 0.02 * (450.0f64 / 0.02).powf(i as f64 / 35.0))
        .collect();
    speeds.extend([1.0, 2.0, 10.0, 0.5, 0.25, 125.0]);
    eprintln!("r | PC max/rms/bound | ET max/rms/bound | M/T max/rms/bound");
    let (mut worst_pc, mut worst_et, mut worst_mt) = (0.0f64, 0.0f64, 0.0f64);
    for &r in &speeds {
        let period = DT as f64 / r;
        // At least 120 windows and 25 pulses.
        let cycles = (120.0 * DT as f64).max(25.0 * period);
        let profile = Profile::constant(r * OMEGA_LIM, cycles / CLOCK_HZ)
            .unwrap()
            .with_initial_angle(0.0137)
            .unwrap();
        let pulses = plant_pulses(&profile);
        let last = cycles as u64;
        let runs = run_all(&pulses, last);
        check_against_floats(&pulses, last, &runs);

        // The plant's instants carry float rounding (~1e-11 cycles): where a bound jumps (a
        // whole number of cycles per pulse, or of pulses per window) evaluate it on both
        // sides, at r·(1 ± 1e-9).
        let et_bound = et_error_bound(period * (1.0 - 1e-9));
        let mt_bound = mt_error_bound_at_speed(r * (1.0 + 1e-9), DT)
            .max(mt_error_bound_at_speed(r * (1.0 - 1e-9), DT));
        let (mut pc, mut et, mut mt) = (Stats::default(), Stats::default(), Stats::default());
        for (_, o) in &runs.pc {
            pc.add((o.count as f64 - r).abs() / r, pc_error_bound(r));
        }
        for (_, o) in &runs.et {
            let est = DT as f64 / o.period as f64;
            et.add((est - r).abs() / r, et_bound);
        }
        for (_, o) in runs.mt.iter().filter(|(_, o)| o.m > 0) {
            let est = o.m as f64 * DT as f64 / o.t as f64;
            mt.add((est - r).abs() / r, mt_bound);
        }
        assert!(
            et.n >= 20 && mt.n >= 1 && pc.n >= 100,
            "r = {r}: too few outputs"
        );
        for (s, b) in [(&pc, pc_error_bound(r)), (&et, et_bound), (&mt, mt_bound)] {
            assert!(s.rms() <= b, "r = {r}: RMS {} above bound {b}", s.rms());
        }
        worst_pc = worst_pc.max(pc.worst);
        worst_et = worst_et.max(et.worst);
        worst_mt = worst_mt.max(mt.worst);
        eprintln!(
            "{r:.4} | {:.3e} {:.3e} {:.3e} | {:.3e} {:.3e} {:.3e} | {:.3e} {:.3e} {:.3e}",
            pc.max,
            pc.rms(),
            pc_error_bound(r),
            et.max,
            et.rms(),
            et_bound,
            mt.max,
            mt.rms(),
            mt_bound
        );
    }
    eprintln!("worst max/bound: PC {worst_pc:.4}, ET {worst_et:.4}, M/T {worst_mt:.4}");
    // The bounds are tight: some point of the sweep comes close to each.
    assert!(worst_pc > 0.9 && worst_et > 0.5 && worst_mt > 0.5);
}

#[test]
fn plant_reversal_pc_signed_counts_and_no_mixed_measurements() {
    // 3·ω_lim·… forward, ramping through zero to the same speed backward.
    let profile = Profile::reversal(7.3 * OMEGA_LIM, 0.08)
        .unwrap()
        .with_initial_angle(0.0137)
        .unwrap();
    let pulses = plant_pulses(&profile);
    assert!(pulses.iter().any(|p| p.forward) && pulses.iter().any(|p| !p.forward));
    let last = (profile.duration() * CLOCK_HZ) as u64;
    let runs = run_all(&pulses, last);
    // PC = fixed_time(forward) − fixed_time(backward) on the stamps.
    let stamps = |fwd: bool| -> Vec<f64> {
        pulses
            .iter()
            .filter(|p| p.forward == fwd)
            .map(|p| p.edge as f64)
            .collect()
    };
    let f = fixed_time(&stamps(true), DT as f64, last as f64).unwrap();
    let b = fixed_time(&stamps(false), DT as f64, last as f64).unwrap();
    assert_eq!(runs.pc.len(), f.len());
    for (i, (_, o)) in runs.pc.iter().enumerate() {
        assert_eq!(o.count as f64, f[i].n - b[i].n);
    }
    assert!(runs.pc.iter().any(|(_, o)| o.count < 0));
    // ET: every period is between two steps of its own direction; its sign is theirs.
    let dir_at = |k: u64| pulses.iter().find(|p| p.edge == k).unwrap().forward;
    for (k, o) in &runs.et {
        assert_eq!(!o.negative, dir_at(*k));
        assert_eq!(
            dir_at(k - o.period),
            dir_at(*k),
            "a period across a reversal"
        );
    }
    // M/T: each m counts steps of one direction, the measurement's sign.
    // (A reversing step on the window-end edge itself belongs to the next measurement.)
    for (k, o) in runs.mt.iter().filter(|(_, o)| o.m > 0) {
        let mut seen: Vec<&Pulse> = pulses.iter().filter(|p| p.edge <= *k).collect();
        if seen
            .last()
            .is_some_and(|p| p.edge == *k && p.forward == o.negative)
        {
            seen.pop();
        }
        assert!(seen
            .iter()
            .rev()
            .take(o.m as usize)
            .all(|p| p.forward != o.negative));
    }
    assert!(runs.mt.iter().any(|(_, o)| o.negative && o.m > 0));
}
