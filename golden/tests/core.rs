// SPDX-License-Identifier: MIT OR Apache-2.0
//! Hand-checked behaviour of the bit-true core model (`golden::top::core::CoreModel`): counts in
//! x1/x2/x4, known speeds of every estimator on exact square waves, reversal, faults,
//! configuration defaults and latencies. Expected values are worked by hand in the
//! comments (Rairán eq. (11), Table 1 traces), not taken from the model.

use golden::params::{Params, Spec};
use golden::top::core::{CoreInputs, CoreModel, CoreOutputs};
use golden::top::ports::Latency;

const DT: u64 = 160;

/// 1 MHz clock, 100 lines, dt = 160 cycles, 16-bit counters, timeout 50 dt.
fn params() -> Params {
    params_dt(DT)
}

/// As [`params`] with dt = `dt` cycles.
fn params_dt(dt: u64) -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: dt,
        counter_bits: 16,
        timeout_s: 50.0 * dt as f64 / 1e6,
        ..Spec::default()
    })
    .unwrap()
}

/// Quadrature levels at cycle k of a wave of `period` cycles: A high for the first half,
/// B a quarter period behind A (forward), or ahead of it (backward).
fn quad(k: u64, period: u64, forward: bool) -> (bool, bool) {
    let m = k % period;
    let a = m < period / 2;
    let lag = if forward {
        period / 4
    } else {
        period - period / 4
    };
    let b = (m + period - lag) % period < period / 2;
    (a, b)
}

/// Edges the wave rests at its first level after the reset: more than the start-up hold
/// (2 synchroniser edges + 1 filter edge + the registered hold's edge), so that no
/// transition falls inside the hold, where it would not be a step.
const REST: u64 = 8;

/// Run `cycles` cycles of a constant quadrature wave after 3 cycles of reset and `REST`
/// cycles at rest.
fn run_wave(mode: u8, period: u64, forward: bool, cycles: u64) -> Vec<CoreOutputs> {
    let mut m = CoreModel::new(&params());
    (0..cycles + 3 + REST)
        .map(|k| {
            let (a, b) = quad(k.saturating_sub(REST), period, forward);
            m.step(CoreInputs {
                reset: k < 3,
                enc_a: a,
                enc_b: b,
                cfg_dt: DT,
                cfg_mode: mode,
                ..Default::default()
            })
        })
        .collect()
}

fn last_strobed(o: &[CoreOutputs], baseline: bool) -> CoreOutputs {
    *o.iter()
        .rev()
        .find(|o| {
            if baseline {
                o.baseline_strobe
            } else {
                o.speed_strobe
            }
        })
        .expect("a strobe")
}

#[test]
fn a_channel_high_at_reset_is_not_a_step() {
    let mut m = CoreModel::new(&params());
    for k in 0..50 {
        let o = m.step(CoreInputs {
            reset: k < 2,
            enc_a: true,
            enc_b: true,
            cfg_dt: DT,
            cfg_filter: 3,
            ..Default::default()
        });
        assert_eq!(o.position, 0, "cycle {k}");
        assert!(!o.fault_illegal && o.illegal_count == 0);
    }
}

#[test]
fn positions_count_one_two_and_four_steps_per_line() {
    // 20 periods of 16 cycles (the last one complete well before the end): 20 lines.
    for (mode, per_line) in [(0u8, 1u64), (1, 2), (2, 4)] {
        let o = run_wave(mode, 16, true, 20 * 16 + 2);
        let fwd = o.last().unwrap();
        assert_eq!(fwd.position, 20 * per_line, "mode {mode} forward");
        assert!(fwd.direction);
        let o = run_wave(mode, 16, false, 20 * 16 + 2);
        let back = o.last().unwrap();
        // Backward from 0 wraps to the end of the revolution: 100·per_line − 20·per_line.
        assert_eq!(back.position, 80 * per_line, "mode {mode} backward");
        assert!(!back.direction);
    }
}

#[test]
fn known_speeds_of_every_estimator_at_ten_lines_per_dt() {
    // Period 16 cycles, dt = 160: r = 10 ω_lim exactly.
    // x1: one step per 16 cycles. Table 1 (hand trace): a window restarted at a step holds
    // the steps at 0, 16, …, 144; the step at 160 falls on the tick, is counted then
    // cleared, so Nep1 = 10; Ndt1 = 1. n3 = 2·10·9/(1·19) = 180/19 = 9.47368 ω_lim
    // → 9.47368·65536 = 620867.4 → 620867. n1 = 10 → 655360.
    let o = run_wave(0, 16, true, 40 * DT);
    let s = last_strobed(&o, false);
    assert_eq!((s.nep, s.ndt), (10, 1));
    assert_eq!(s.speed_n3, 620_867);
    assert_eq!(s.speed_n1, 655_360);
    assert!(s.valid);
    // PC: 10 steps in every window of 160; ET: 160/16 = 10; M/T: 10 steps over 160 cycles.
    let b = last_strobed(&o, true);
    assert_eq!(
        (b.speed_pc, b.speed_et, b.speed_mt),
        (655_360, 655_360, 655_360)
    );

    // x4: a step every 4 cycles, 40 per dt: Nep1 = 40, n3 = 2·40·39/79 steps per dt =
    // 39.49367 → 2588257 (2^−16 units), then ÷4 with rounding: (2588257 + 2) >> 2 = 647064
    // = 9.87341 ω_lim — the finer count cuts the error from 5.3 % to 1.3 %.
    let o = run_wave(2, 16, true, 40 * DT);
    let s = last_strobed(&o, false);
    assert_eq!((s.nep, s.ndt), (40, 1));
    assert_eq!(s.speed_n3, 647_064);
    let b = last_strobed(&o, true);
    assert_eq!(
        (b.speed_pc, b.speed_et, b.speed_mt),
        (655_360, 655_360, 655_360)
    );

    // Backward: the mirror image.
    let o = run_wave(2, 16, false, 40 * DT);
    let s = last_strobed(&o, false);
    assert_eq!(s.speed_n3, -647_064);
    let b = last_strobed(&o, true);
    assert_eq!(
        (b.speed_pc, b.speed_et, b.speed_mt),
        (-655_360, -655_360, -655_360)
    );
}

#[test]
fn a_reversal_zeroes_the_speed_until_a_new_measurement() {
    // Forward for 30 dt, then backward, x4, period 64 (r = 2.5).
    let p = params();
    let mut m = CoreModel::new(&p);
    let turn = 30 * DT;
    let mut outs = vec![];
    for k in 0..(60 * DT) {
        let (a, b) = if k < turn {
            quad(k, 64, true)
        } else {
            // Continue from the same levels, backward: mirror the phase at the turn.
            quad(2 * turn - k, 64, true)
        };
        outs.push(m.step(CoreInputs {
            reset: k < 3,
            enc_a: a,
            enc_b: b,
            cfg_dt: DT,
            cfg_mode: 2,
            ..Default::default()
        }));
    }
    let before = last_strobed(&outs[..turn as usize], false);
    assert!(before.speed_n3 > 0 && before.valid);
    // Find the cycle where the output direction flips, then the first strobe after it.
    let flip = (turn as usize..outs.len())
        .find(|&k| !outs[k].direction)
        .unwrap();
    let first = (flip..outs.len()).find(|&k| outs[k].speed_strobe).unwrap();
    for o in &outs[flip + 1..first] {
        assert_eq!(o.speed_n3, 0);
    }
    // `valid` is a register of its conditions: low from the edge after.
    for o in &outs[flip + 2..first] {
        assert!(!o.valid);
    }
    // Every speed after the reversal is negative and no larger in magnitude than the
    // forward one (same true speed): no spike.
    for o in outs[first..].iter().filter(|o| o.speed_strobe) {
        assert!(o.speed_n3 < 0 && o.speed_n3.abs() <= before.speed_n3 * 101 / 100);
    }
    assert_eq!(last_strobed(&outs, false).speed_n3, -before.speed_n3);
}

#[test]
fn faults_are_raised_counted_and_cleared() {
    let p = params();
    let mut m = CoreModel::new(&p);
    let mut step = |reset: bool, a: bool, b: bool, filter: u64, clear: bool| {
        m.step(CoreInputs {
            reset,
            enc_a: a,
            enc_b: b,
            cfg_dt: DT,
            cfg_filter: filter,
            clear_faults: clear,
            ..Default::default()
        })
    };
    step(true, false, false, 0, false);
    for _ in 0..10 {
        step(false, false, false, 0, false);
    }
    // Both channels change at once: illegal.
    let mut last = step(false, true, true, 0, false);
    for _ in 0..10 {
        last = step(false, true, true, 0, false);
    }
    assert!(last.fault_illegal);
    assert_eq!(last.illegal_count, 1);
    assert_eq!(last.position, 0, "an illegal transition makes no step");
    for _ in 0..3 {
        last = step(false, true, true, 0, true);
    }
    assert!(!last.fault_illegal);
    assert_eq!(last.illegal_count, 1, "clearing the flag keeps the count");
    // With a 4-cycle filter, a 2-cycle low pulse on A is rejected: one glitch, over-speed.
    for _ in 0..10 {
        last = step(false, true, true, 4, false);
    }
    for _ in 0..2 {
        step(false, false, true, 4, false);
    }
    for _ in 0..10 {
        last = step(false, true, true, 4, false);
    }
    assert_eq!(last.glitch_count, 1);
    assert!(last.fault_overspeed);
    assert_eq!(last.position, 0);
}

#[test]
fn configuration_zero_means_the_generation_default() {
    let p = params();
    let run = |cfg_dt: u64, cfg_timeout: u64| {
        let mut m = CoreModel::new(&p);
        (0..20 * DT)
            .map(|k| {
                let (a, b) = quad(k, 40, true);
                m.step(CoreInputs {
                    reset: k < 3,
                    enc_a: a,
                    enc_b: b,
                    cfg_dt,
                    cfg_timeout,
                    ..Default::default()
                })
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(run(0, 0), run(DT, p.timeout_dt()));
    let bad = run(1, 0);
    assert!(bad.iter().skip(1).all(|o| o.cfg_error && !o.valid));
}

#[test]
fn index_resets_and_latches_the_position() {
    let p = params();
    let mut m = CoreModel::new(&p);
    let mut last = CoreOutputs::default();
    // 30 lines forward (x1), Z high for one quarter period at line 25.
    for k in 0..(30 * 16 + 20) {
        let (a, b) = quad(k, 16, true);
        let z = (25 * 16..25 * 16 + 4).contains(&k);
        last = m.step(CoreInputs {
            reset: k < 3,
            enc_a: a,
            enc_b: b,
            enc_z: z,
            cfg_dt: DT,
            cfg_z_mode: 3,
            ..Default::default()
        });
    }
    // Steps come at k = 16, 32, … (A is already high at reset, so k = 0 is not one): the
    // index rises with the 25th step (k = 400), which the latch includes: 25. The position
    // is then reset to 0 and the steps at k = 416, 432, 448, 464, 480 (< 500) make it 5.
    assert_eq!(last.z_latch, 25);
    assert_eq!(last.position, 5);
}

#[test]
fn latencies_are_as_documented() {
    // r = 0.5 (period 2·dt, x1): every step restarts Table 1, so each A rising edge (B low)
    // leads to exactly one speed_strobe, edge_to_speed_strobe edges later. dt = 480 is at
    // least the calculator's min_lossless_dt (2·208 − 1 = 415 at N = 16, F = 16), so no
    // update is replaced before it is computed.
    const DT_LONG: u64 = 480;
    const PERIOD: u64 = 2 * DT_LONG;
    for filter in [0u64, 1, 5] {
        let p = params_dt(DT_LONG);
        assert!(
            DT_LONG
                >= u64::from(golden::estimator::speed_calc::min_lossless_dt(
                    16,
                    p.speed_frac_bits()
                ))
        );
        let lat = Latency::new(&p, filter);
        let mut m = CoreModel::new(&p);
        let mut outs = vec![];
        let mut rises = vec![];
        let mut prev_a = false;
        for k in 0..(20 * PERIOD) {
            let (a, b) = quad(k, PERIOD, true);
            if a && !prev_a && k > 3 {
                rises.push(k as usize);
            }
            prev_a = a;
            outs.push(m.step(CoreInputs {
                reset: k < 3,
                enc_a: a,
                enc_b: b,
                cfg_dt: DT_LONG,
                cfg_filter: filter,
                ..Default::default()
            }));
        }
        // Position: one more after each rise, edge_to_position edges later (and not before).
        for &k in &rises[..rises.len() - 1] {
            let d = lat.edge_to_position as usize;
            assert_eq!(
                outs[k + d].position,
                outs[k + d - 1].position + 1,
                "L = {filter}"
            );
        }
        // Speed strobes: from the third rise on (the first primes the estimator... the
        // first restart is the second step), each rise is followed by a strobe exactly
        // edge_to_speed_strobe later.
        let strobes: Vec<usize> = (0..outs.len()).filter(|&k| outs[k].speed_strobe).collect();
        let d = lat.edge_to_speed_strobe as usize;
        for &k in &rises[2..rises.len() - 1] {
            assert!(
                strobes.contains(&(k + d)),
                "L = {filter}: rise {k}, strobes {strobes:?}"
            );
        }
    }
}

#[test]
fn baseline_strobe_follows_the_window_end_by_the_block_latency() {
    // N = 16, F = 16: the baseline block takes 1 + 2·33 + 1 + 2·33 + 1 + 1 = 136 edges from
    // the edge that samples its start (each of the 33 ET and 33 M/T divider steps takes two
    // edges), and samples the window end (PC's strobe, which rises with mt_strobe: one time
    // base) one edge after the edge that raised it: 137.
    assert_eq!(Latency::new(&params(), 0).window_to_baseline_strobe, 137);
    let o = run_wave(2, 16, true, 10 * DT);
    let windows: Vec<usize> = (0..o.len()).filter(|&k| o[k].mt_strobe).collect();
    let baselines: Vec<usize> = (0..o.len()).filter(|&k| o[k].baseline_strobe).collect();
    assert!(windows.len() >= 8, "{windows:?}");
    for w in &windows {
        if w + 137 < o.len() {
            assert!(
                baselines.contains(&(w + 137)),
                "window end {w}: {baselines:?}"
            );
        }
    }
    // Nothing else raises it (PC's window ends before M/T has its first anchor raise it
    // too, without an mt_strobe).
    assert!(baselines
        .iter()
        .filter(|&&b| b > windows[0] + 137)
        .all(|b| windows.contains(&(b - 137))));
}

#[test]
fn configuration_inputs_act_after_the_documented_edges() {
    // The latencies by hand: the core registers its configuration inputs once.
    let lat = Latency::new(&params(), 0);
    assert_eq!(
        (
            lat.reset_to_effect,
            lat.config_to_effect,
            lat.cfg_dt_to_window
        ),
        (1, 1, 2)
    );

    // reset: move the shaft, stop, then raise reset first sampled at edge K (held 2 edges):
    // the core counts at edge K as if nothing happened, and its registers reset at edges
    // K + 1 and K + 2; the start-up hold then runs again (no step while the shaft stands).
    const R: usize = 600;
    let mut m = CoreModel::new(&params());
    let outs: Vec<CoreOutputs> = (0..R as u64 + 6)
        .map(|k| {
            let (a, b) = quad(k.min(400), 16, true);
            m.step(CoreInputs {
                reset: k < 3 || (R as u64..R as u64 + 2).contains(&k),
                enc_a: a,
                enc_b: b,
                cfg_dt: DT,
                cfg_mode: 2,
                ..Default::default()
            })
        })
        .collect();
    assert!(
        outs[R].position > 50,
        "edge R only samples it: {}",
        outs[R].position
    );
    assert_eq!(outs[R + 1].position, 0, "the reset acts at edge R + 1");
    assert!(!outs[R + 1].valid && !outs[R + 2].valid);
    assert!(outs[R + 3..].iter().all(|o| o.position == 0));

    // cfg_mode: move the shaft, stop, then change the mode first sampled at edge K. The reset
    // it causes acts at edge K + 1: the position is still counted after edge K, 0 after K + 1.
    const K: usize = 600;
    let mut m = CoreModel::new(&params());
    let outs: Vec<CoreOutputs> = (0..K as u64 + 4)
        .map(|k| {
            let (a, b) = quad(k.min(400), 16, true);
            m.step(CoreInputs {
                reset: k < 3,
                enc_a: a,
                enc_b: b,
                cfg_dt: DT,
                cfg_mode: if k < K as u64 { 2 } else { 1 },
                ..Default::default()
            })
        })
        .collect();
    assert!(outs[K - 1].position > 50, "{}", outs[K - 1].position);
    assert_eq!(
        outs[K].position,
        outs[K - 1].position,
        "edge K still counts"
    );
    assert_eq!(outs[K + 1].position, 0, "the reset acts at edge K + 1");

    // cfg_dt: the window that ends at edge E compares at edge E − 1 with the dt register,
    // loaded at edge E − 2. Raising dt first sampled at edge E − 2 cancels that window end;
    // first sampled at E − 1, it does not. Window ends are read at baseline_strobe, which
    // follows each by window_to_baseline_strobe (shorter than dt = 200, so none is skipped).
    const DT_W: u64 = 200;
    let lat = Latency::new(&params_dt(DT_W), 0);
    let bl = lat.window_to_baseline_strobe as usize;
    let run = |change_at: usize| -> Vec<usize> {
        let mut m = CoreModel::new(&params_dt(DT_W));
        (0..2000)
            .map(|k| {
                m.step(CoreInputs {
                    reset: k < 3,
                    cfg_dt: if k < change_at { DT_W } else { 60_000 },
                    ..Default::default()
                })
            })
            .enumerate()
            .filter(|(_, o)| o.baseline_strobe)
            .map(|(k, _)| k - bl)
            .collect()
    };
    let ends = run(usize::MAX);
    let e1 = ends[2];
    assert_eq!(ends[3] - e1, DT_W as usize, "{ends:?}");
    let e = e1 + DT_W as usize;
    let late = run(e - 1);
    let early = run(e - lat.cfg_dt_to_window as usize);
    assert!(
        late.contains(&e),
        "sampled at E − 1: the end at E stays: {late:?}"
    );
    assert!(
        !early.contains(&e),
        "sampled at E − 2: no end at E: {early:?}"
    );
    assert!(early.contains(&e1), "{early:?}");
}
