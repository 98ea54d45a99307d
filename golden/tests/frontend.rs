// SPDX-License-Identifier: MIT OR Apache-2.0
//! Front-end model tests. Truth comes from outside the code: hand-worked sequences (the
//! expected outputs are written out by hand below, with the reasoning in comments) and, for
//! the chain glitch filter → decoder → position counter, the shaft angle of the plant: the
//! decoded count must equal the number of quarter, half or whole lines the shaft crossed,
//! computed from its start and end angles, whatever the motion (reversals included).

use golden::frontend::{
    CounterInputs, CounterOutputs, DecoderInputs, DecoderOutputs, GlitchFilter, GlitchFilterInputs,
    PositionCounter, QuadratureDecoder, MODE_INVALID, MODE_X1, MODE_X2, MODE_X4, Z_MODE_IGNORE,
    Z_MODE_LATCH, Z_MODE_LATCH_RESET, Z_MODE_RESET,
};
use golden::ideal::plant::{edges, initial_levels, ClockSampler, Disc, Profile, Segment};
use proptest::prelude::*;

// ---------------------------------------------------------------------------------------
// Glitch filter
// ---------------------------------------------------------------------------------------

/// Reset at edge 0, then `input` at edges 1, 2, …: (level_out, glitches) after each edge
/// from edge 1 on.
fn filter_run(l: u64, glitch_bits: u32, input: &[u8]) -> Vec<(u8, u64)> {
    let mut f = GlitchFilter::new(8, glitch_bits);
    f.step(GlitchFilterInputs {
        reset: true,
        level_in: true,
        cfg_filter: l,
    });
    input
        .iter()
        .map(|&x| {
            let o = f.step(GlitchFilterInputs {
                reset: false,
                level_in: x == 1,
                cfg_filter: l,
            });
            (u8::from(o.level_out), o.glitches)
        })
        .collect()
}

#[test]
fn filter_rejects_a_3_cycle_pulse_at_l4_and_counts_it() {
    // L = 4. Edge 1: 0 = out. Edges 2-4: input 1 ≠ out, run = 1, 2, 3 (run + 1 < 4 each
    // time). Edge 5: input 0 = out with run = 3 ≠ 0: one glitch, run = 0. Out never moves.
    let got = filter_run(4, 8, &[0, 1, 1, 1, 0, 0]);
    assert_eq!(got, [(0, 0), (0, 0), (0, 0), (0, 0), (0, 1), (0, 1)]);
}

#[test]
fn filter_passes_a_3_cycle_pulse_at_l3_three_cycles_late() {
    // L = 3. Edges 2, 3: run = 1, 2. Edge 4: run + 1 = 3 ≥ 3: out = 1 (the 1 first sampled
    // at edge 2 appears after edge 4). Edges 5, 6: input 0 ≠ out, run = 1, 2; edge 7: out = 0.
    // No glitch: the pulse was long enough.
    let got = filter_run(3, 8, &[0, 1, 1, 1, 0, 0, 0, 0]);
    assert_eq!(
        got,
        [
            (0, 0),
            (0, 0),
            (0, 0),
            (1, 0),
            (1, 0),
            (1, 0),
            (0, 0),
            (0, 0)
        ]
    );
}

#[test]
fn filter_off_passes_every_change_at_the_next_edge() {
    // L = 0 and L = 1: run + 1 ≥ L always, so out after edge k is the input at edge k, even
    // for one-cycle pulses, and nothing is ever rejected.
    let input = [1, 0, 1, 1, 0, 1, 0, 0];
    for l in [0, 1] {
        let got = filter_run(l, 8, &input);
        let want: Vec<(u8, u64)> = input.iter().map(|&x| (x, 0)).collect();
        assert_eq!(got, want, "L = {l}");
    }
}

#[test]
fn filter_counts_a_chattering_edge_and_saturates() {
    // L = 3, input 1 0 1 1 1: edge 1 run = 1; edge 2 back to 0: glitch 1; edges 3, 4 run = 1,
    // 2; edge 5 passes (out = 1 after the 3rd consecutive 1).
    let got = filter_run(3, 8, &[1, 0, 1, 1, 1]);
    assert_eq!(got, [(0, 0), (0, 1), (0, 1), (0, 1), (1, 1)]);
    // L = 2 with a 2-bit counter: five one-cycle pulses are five glitches, counted 1, 2, 3,
    // 3, 3 (saturated at 2² − 1).
    let got = filter_run(2, 2, &[1, 0, 1, 0, 1, 0, 1, 0, 1, 0]);
    let counts: Vec<u64> = got.iter().map(|g| g.1).collect();
    assert_eq!(counts, [0, 1, 1, 2, 2, 3, 3, 3, 3, 3]);
    assert!(got.iter().all(|g| g.0 == 0));
}

#[test]
fn filter_reset_clears_everything() {
    let mut f = GlitchFilter::new(4, 4);
    let inp = |reset, level_in| GlitchFilterInputs {
        reset,
        level_in,
        cfg_filter: 2,
    };
    // Two edges of 1 pass it (L = 2), a one-cycle 0 is a glitch.
    f.step(inp(false, true));
    f.step(inp(false, true));
    f.step(inp(false, false));
    let o = f.step(inp(false, true));
    assert!(o.level_out);
    assert_eq!(o.glitches, 1);
    let o = f.step(inp(true, true));
    assert!(!o.level_out);
    assert_eq!(o.glitches, 0);
    assert_eq!(f.state().run, 0);
}

// ---------------------------------------------------------------------------------------
// Quadrature decoder
// ---------------------------------------------------------------------------------------

/// Reset at edge 0, then the (A, B) samples at edges 1, 2, … (the first one primes).
/// Returns the signed step after each edge from edge 2 on: +1, −1 or 0.
fn decode(mode: u8, ab: &[(u8, u8)]) -> (Vec<i8>, QuadratureDecoder) {
    let mut d = QuadratureDecoder::new(8);
    d.step(DecoderInputs {
        reset: true,
        cfg_mode: mode,
        ..Default::default()
    });
    let mut steps = vec![];
    for (k, &(a, b)) in ab.iter().enumerate() {
        let o = d.step(DecoderInputs {
            reset: false,
            a: a == 1,
            b: b == 1,
            cfg_mode: mode,
        });
        assert!(!o.forward || o.step, "forward without a step");
        if k > 0 {
            steps.push(match (o.step, o.forward) {
                (false, _) => 0,
                (true, true) => 1,
                (true, false) => -1,
            });
        } else {
            assert!(!o.step && !o.illegal, "the priming edge makes no step");
        }
    }
    (steps, d)
}

/// The forward Gray cycle (B lags A): 00 → 10 → 11 → 01 → 00.
const FORWARD: [(u8, u8); 5] = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)];
/// The reverse cycle: 00 → 01 → 11 → 10 → 00.
const REVERSE: [(u8, u8); 5] = [(0, 0), (0, 1), (1, 1), (1, 0), (0, 0)];

#[test]
fn x4_counts_every_transition_with_its_sign() {
    // Each transition changes one channel: four steps per cycle. Forward check of the rule
    // "forward iff A_prev = B": 00→10 (A_prev 0, B 0), 10→11 (1, 1), 11→01 (1, 1),
    // 01→00 (0, 0): all forward. Reverse: 00→01 (0, 1), 01→11 (0, 1), 11→10 (1, 0),
    // 10→00 (1, 0): all backward.
    assert_eq!(decode(MODE_X4, &FORWARD).0, [1, 1, 1, 1]);
    assert_eq!(decode(MODE_X4, &REVERSE).0, [-1, -1, -1, -1]);
    // Mode 3 is decoded as x4.
    assert_eq!(decode(MODE_INVALID, &FORWARD).0, [1, 1, 1, 1]);
}

#[test]
fn x2_counts_the_a_edges() {
    // Forward: 00→10 (A↑) and 11→01 (A↓) count; the B changes do not.
    assert_eq!(decode(MODE_X2, &FORWARD).0, [1, 0, 1, 0]);
    // Reverse: 01→11 (A↑) and 10→00 (A↓).
    assert_eq!(decode(MODE_X2, &REVERSE).0, [0, -1, 0, -1]);
}

#[test]
fn x1_counts_one_physical_edge_per_line_in_both_directions() {
    // x1 counts the A change while B is low: 00→10 forward, 10→00 backward (the same
    // place on the disc, crossed the other way).
    assert_eq!(decode(MODE_X1, &FORWARD).0, [1, 0, 0, 0]);
    assert_eq!(decode(MODE_X1, &REVERSE).0, [0, 0, 0, -1]);
    // A shaft dithering on that edge: +1 −1 +1 −1, no drift.
    let dither = [(0, 0), (1, 0), (0, 0), (1, 0), (0, 0)];
    assert_eq!(decode(MODE_X1, &dither).0, [1, -1, 1, -1]);
    // Dithering on the other A edge (11 ↔ 01) counts nothing in x1.
    let dither = [(1, 1), (0, 1), (1, 1), (0, 1)];
    assert_eq!(decode(MODE_X1, &dither).0, [0, 0, 0]);
}

#[test]
fn several_cycles_give_1_2_4_steps_per_cycle() {
    // Three forward cycles then two reverse cycles: net +1 cycle.
    let mut seq: Vec<(u8, u8)> = vec![(0, 0)];
    for _ in 0..3 {
        seq.extend_from_slice(&FORWARD[1..]);
    }
    for _ in 0..2 {
        seq.extend_from_slice(&REVERSE[1..]);
    }
    for (mode, per_cycle) in [(MODE_X1, 1), (MODE_X2, 2), (MODE_X4, 4)] {
        let (steps, d) = decode(mode, &seq);
        let fwd = steps.iter().filter(|&&s| s == 1).count();
        let back = steps.iter().filter(|&&s| s == -1).count();
        assert_eq!((fwd, back), (3 * per_cycle, 2 * per_cycle), "mode {mode}");
        // The last step was backward.
        assert!(!d.state().direction);
    }
}

#[test]
fn illegal_jump_is_flagged_and_not_counted() {
    // Prime on 00, jump to 11 (both changed): illegal, no step. Then 11→01 is a legal
    // forward step (A_prev 1 = B 1), 01→10 is illegal again, 10→10 nothing.
    let mut d = QuadratureDecoder::new(2);
    let mut run = |reset, a, b| {
        d.step(DecoderInputs {
            reset,
            a,
            b,
            cfg_mode: MODE_X4,
        })
    };
    run(true, false, false);
    run(false, false, false);
    let o = run(false, true, true);
    let want = DecoderOutputs {
        step: false,
        forward: false,
        first: false,
        direction: false,
        illegal: true,
        illegal_seen: true,
        illegal_count: 1,
        mode_error: false,
    };
    assert_eq!(o, want);
    let o = run(false, false, true);
    assert!(o.step && o.forward && o.direction && !o.illegal && o.illegal_seen);
    let o = run(false, true, false);
    assert!(!o.step && o.illegal && o.illegal_count == 2 && o.direction);
    let o = run(false, true, false);
    assert!(!o.step && !o.illegal && o.illegal_seen && o.illegal_count == 2);
    // 2-bit counter: two more illegal jumps saturate it at 3.
    run(false, false, true);
    let o = run(false, true, false);
    assert_eq!(o.illegal_count, 3);
    let o = run(true, true, false);
    assert!(!o.illegal_seen && o.illegal_count == 0 && !o.direction);
}

#[test]
fn first_marks_the_first_step_and_each_reversal_by_hand() {
    // x4 from 00: forward 00→10→11, back 11→10→00, forward 00→10, then a hold. By hand,
    // `first` is set on the first step (no direction yet) and on each step against the
    // last one: steps F F B B F → first 1 0 1 0 1; the hold makes no step and no `first`.
    let mut d = QuadratureDecoder::new(2);
    let levels = [
        (0, 0),
        (0, 0),
        (1, 0),
        (1, 1),
        (1, 0),
        (0, 0),
        (1, 0),
        (1, 0),
    ];
    let got: Vec<(bool, bool, bool)> = levels
        .iter()
        .enumerate()
        .map(|(k, &(a, b))| {
            let o = d.step(DecoderInputs {
                reset: k == 0,
                a: a == 1,
                b: b == 1,
                cfg_mode: MODE_X4,
            });
            (o.step, o.forward, o.first)
        })
        .skip(2)
        .collect();
    let want = [
        (true, true, true),
        (true, true, false),
        (true, false, true),
        (true, false, false),
        (true, true, true),
        (false, false, false),
    ];
    assert_eq!(got, want);
    // A reset forgets the direction: the next step is a first step again.
    d.step(DecoderInputs {
        reset: true,
        a: true,
        b: false,
        cfg_mode: MODE_X4,
    });
    let mut o = DecoderOutputs::default();
    for (a, b) in [(true, false), (true, true)] {
        o = d.step(DecoderInputs {
            reset: false,
            a,
            b,
            cfg_mode: MODE_X4,
        });
    }
    assert!(o.step && o.forward && o.first);
}

#[test]
fn decoder_start_up_makes_no_false_step() {
    // Channels high at reset: the first edge after reset only primes, then nothing moves.
    let (steps, _) = decode(MODE_X4, &[(1, 1), (1, 1), (1, 1)]);
    assert_eq!(steps, [0, 0]);
    // Mode error is combinational from cfg_mode.
    let mut d = QuadratureDecoder::new(4);
    for mode in 0..4 {
        let o = d.step(DecoderInputs {
            cfg_mode: mode,
            ..Default::default()
        });
        assert_eq!(o.mode_error, mode == MODE_INVALID);
    }
}

// ---------------------------------------------------------------------------------------
// Position counter
// ---------------------------------------------------------------------------------------

/// Reset at edge 0, then (step, forward, z) at edges 1, 2, …; outputs after each.
fn count(
    position_bits: u32,
    cpr: u64,
    z_mode: u8,
    ins: &[(u8, u8, u8)],
) -> (Vec<CounterOutputs>, PositionCounter) {
    let mut c = PositionCounter::new(position_bits, 2);
    c.step(CounterInputs {
        reset: true,
        z: true,
        counts_per_rev: cpr,
        cfg_z_mode: z_mode,
        ..Default::default()
    });
    let out = ins
        .iter()
        .map(|&(s, f, z)| {
            c.step(CounterInputs {
                reset: false,
                step: s == 1,
                forward: f == 1,
                z: z == 1,
                counts_per_rev: cpr,
                cfg_z_mode: z_mode,
            })
        })
        .collect();
    (out, c)
}

fn positions(out: &[CounterOutputs]) -> Vec<u64> {
    out.iter().map(|o| o.position).collect()
}

const F: (u8, u8, u8) = (1, 1, 0);
const B: (u8, u8, u8) = (1, 0, 0);
const IDLE: (u8, u8, u8) = (0, 0, 0);

#[test]
fn position_wraps_modulo_counts_per_rev() {
    // R = 5: forward 0→1→2→3→4→0→1; backward 1→0→4→3.
    let (out, _) = count(8, 5, Z_MODE_IGNORE, &[F, F, F, F, F, F, B, B, B, IDLE]);
    assert_eq!(positions(&out), [1, 2, 3, 4, 0, 1, 0, 4, 3, 3]);
    // counts_per_rev = 0 stands for 2^C: with C = 3 the position wraps at 8.
    let (out, _) = count(3, 0, Z_MODE_IGNORE, &[B, B, F, F, F]);
    assert_eq!(positions(&out), [7, 6, 7, 0, 1]);
    // A new R takes a reset (the core changes R only with the decoding mode, which
    // resets it): after it, R = 3 wraps 0→2 backward and 2→0 forward.
    let mut c = PositionCounter::new(8, 2);
    let mut go = |reset, step, forward, cpr| {
        c.step(CounterInputs {
            reset,
            step,
            forward,
            counts_per_rev: cpr,
            ..Default::default()
        })
        .position
    };
    for _ in 0..6 {
        go(false, true, true, 10);
    }
    assert_eq!(go(true, false, false, 3), 0);
    assert_eq!(go(false, true, false, 3), 2);
    assert_eq!(go(false, true, true, 3), 0);
}

/// R changed without a reset breaks the block's contract (p ≤ R − 1): the model refuses it.
#[test]
#[should_panic(expected = "without a reset")]
fn counts_per_rev_changes_only_with_a_reset() {
    let mut c = PositionCounter::new(8, 2);
    let inp = |cpr| CounterInputs {
        step: true,
        forward: true,
        counts_per_rev: cpr,
        ..Default::default()
    };
    c.step(inp(10));
    c.step(inp(3));
}

#[test]
fn z_resets_the_position_one_edge_after_the_level_rises() {
    // z rises at edge 4 (sampled with the decoder's inputs); the counter sees the rise at
    // edge 5 (z one edge ago = 1, two edges ago = 0) and the step of that edge is the one
    // the same encoder transition made: position := 0 instead of 4.
    // Edge:      1  2  3  4        5        6  7
    let ins = [F, F, F, (0, 0, 1), (1, 1, 1), F, F];
    let (out, _) = count(8, 100, Z_MODE_RESET, &ins);
    assert_eq!(positions(&out), [1, 2, 3, 3, 0, 1, 2]);
    let index: Vec<bool> = out.iter().map(|o| o.index).collect();
    assert_eq!(index, [false, false, false, false, true, false, false]);
    // Ignore mode: the same sequence just counts.
    let (out, _) = count(8, 100, Z_MODE_IGNORE, &ins);
    assert_eq!(positions(&out), [1, 2, 3, 3, 4, 5, 6]);
    assert!(out[4].index);
}

#[test]
fn z_latches_then_resets() {
    // Same sequence: at edge 5 the stepped position is 4.
    let ins = [F, F, F, (0, 0, 1), (1, 1, 1), F, F];
    let (out, _) = count(8, 100, Z_MODE_LATCH, &ins);
    assert_eq!(positions(&out), [1, 2, 3, 3, 4, 5, 6]);
    let latch: Vec<u64> = out.iter().map(|o| o.z_latch).collect();
    assert_eq!(latch, [0, 0, 0, 0, 4, 4, 4]);
    let (out, _) = count(8, 100, Z_MODE_LATCH_RESET, &ins);
    assert_eq!(positions(&out), [1, 2, 3, 3, 0, 1, 2]);
    assert_eq!(out[6].z_latch, 4);
}

#[test]
fn no_index_from_a_z_already_high_at_reset() {
    // z high from the first edge: the delay flops reset high, so no rise is ever seen.
    let (out, _) = count(8, 4, Z_MODE_RESET, &[(1, 1, 1); 6]);
    assert_eq!(positions(&out), [1, 2, 3, 0, 1, 2]);
    assert!(out.iter().all(|o| !o.index));
    // z low at the first edge then high: a real rise, seen at edge 3.
    let (out, _) = count(8, 100, Z_MODE_RESET, &[(1, 1, 0), (1, 1, 1), F, F]);
    assert_eq!(positions(&out), [1, 2, 0, 1]);
}

/// Encodes moves (step, forward, index) as counter inputs: `index` means the index edge
/// comes with this move (the same encoder transition). The counter takes `z` one sample
/// before the step it belongs to (the decoder's latency), so z is put on the previous
/// sample. Two idle samples are prepended: the first sample after reset is only a
/// reference for z (a z high there is taken as high since reset, not as a rise). Output
/// k + 2 is the one of move k.
fn moves(m: &[(u8, u8, bool)]) -> Vec<(u8, u8, u8)> {
    let mut v = vec![IDLE, IDLE];
    v.extend(m.iter().map(|&(s, f, _)| (s, f, 0)));
    for (i, mv) in m.iter().enumerate() {
        if mv.2 {
            v[i + 1].2 = 1;
        }
    }
    v
}

/// `n` moves in direction `forward`, the index edge with the first.
fn rev(n: usize, forward: u8) -> Vec<(u8, u8, bool)> {
    (0..n).map(|i| (1, forward, i == 0)).collect()
}

#[test]
fn a_revolution_with_a_missing_or_extra_step_is_flagged() {
    // R = 4, forward revolutions of 4, 4, 3, 5, 4 steps, the index with the first step of
    // each. Index edges at moves 0, 4, 8, 11, 16 (outputs 2, 6, 10, 13, 18). The first one
    // arms the check; the intervals it closes are moves 1..=4 (4 steps: ok), 5..=8 (4: ok),
    // 9..=11 (3: one missing, error), 12..=16 (5: one extra, error).
    let mut m = rev(4, 1);
    for n in [4, 3, 5, 4] {
        m.extend(rev(n, 1));
    }
    m.push((0, 0, false));
    let ins = moves(&m);
    let (out, _) = count(8, 4, Z_MODE_RESET, &ins);
    let index_edges: Vec<usize> = (0..out.len()).filter(|&k| out[k].index).collect();
    assert_eq!(index_edges, [2, 6, 10, 13, 18]);
    let errors: Vec<u64> = out.iter().map(|o| o.rev_error_count).collect();
    assert_eq!(errors[..13], [0; 13]);
    assert_eq!(errors[13..18], [1; 5]);
    assert_eq!(errors[18..], [2; 5]);
    assert!(!out[12].rev_error && out[13].rev_error && out[22].rev_error);
    // The position is reset with each index edge: 0 at the index, then 1, 2, 3, and the
    // 4th step wraps to 0 together with the next index.
    assert_eq!(positions(&out[2..7]), [0, 1, 2, 3, 0]);
    // Latch mode (no reset): the position counts from reset, 1 after move 0 and after
    // every good revolution (4 steps ≡ 0 mod 4), 0 after the short one (3 steps), 1 again
    // after the long one (5 steps); the latch takes it at each index edge.
    let (out, _) = count(8, 4, Z_MODE_LATCH, &ins);
    let latch: Vec<u64> = [2, 6, 10, 13, 18].iter().map(|&k| out[k].z_latch).collect();
    assert_eq!(latch, [1, 1, 1, 0, 1]);
    assert_eq!(out.last().unwrap().rev_error_count, 2);
    // The same sequence in ignore mode flags nothing.
    let (out, _) = count(8, 4, Z_MODE_IGNORE, &ins);
    assert!(out.iter().all(|o| !o.rev_error));
    // A 2-bit error counter saturates at 3: five short revolutions after the first.
    let mut m = rev(4, 1);
    for _ in 0..5 {
        m.extend(rev(3, 1));
    }
    m.extend(rev(1, 1));
    let (out, c) = count(8, 4, Z_MODE_LATCH_RESET, &moves(&m));
    assert_eq!(out.last().unwrap().rev_error_count, 3);
    assert!(c.state().rev_error);
}

#[test]
fn a_swing_back_across_the_index_is_not_an_error() {
    // R = 4; the index comes with the step into position 0 from either side.
    let mut m = rev(4, 1); // arms; positions 0 1 2 3
    m.extend(rev(4, 1)); // closes {F F F F}: ok
    m.extend(rev(1, 1)); // closes {F F F F}: ok; position 0
    m.push((1, 0, false)); // back out of the window: 3
    m.push((1, 1, true)); // and in again: closes {B F}, mixed: not checked; 0
    m.extend([(1, 0, false), (1, 0, false), (1, 1, false), (1, 1, true)]); // {B B F F}
    m.extend([(1, 1, false), (1, 1, false), (1, 1, false), (1, 1, true)]); // 4 F: ok
    m.extend([(0, 0, false), (0, 0, true)]); // index noise at rest: {} not checked
    m.extend([(1, 1, false), (1, 1, false), (1, 1, false), (1, 1, true)]); // 4 F: ok
    m.push((0, 0, false));
    let (out, _) = count(8, 4, Z_MODE_RESET, &moves(&m));
    assert_eq!(out.iter().filter(|o| o.index).count(), 8);
    assert!(out.iter().all(|o| !o.rev_error), "{out:?}");
    assert!(out.iter().all(|o| o.position < 4));
    assert_eq!(out.last().unwrap().position, 0);
    // Backward revolutions are checked too: 4, 4, 3, 4 steps between index edges.
    let mut m = rev(4, 0);
    for n in [4, 3, 4, 1] {
        m.extend(rev(n, 0));
    }
    let (out, _) = count(8, 4, Z_MODE_RESET, &moves(&m));
    assert_eq!(out.last().unwrap().rev_error_count, 1);
    // Backward from the index (position 0) the position runs 3, 2, 1, 0.
    assert_eq!(positions(&out[2..7]), [0, 3, 2, 1, 0]);
}

// ---------------------------------------------------------------------------------------
// The chain on the plant
// ---------------------------------------------------------------------------------------

/// One random motion segment with |speed| ≤ vmax everywhere (rev/s).
fn segment(vmax: f64) -> impl Strategy<Value = Segment> {
    let v = -vmax..vmax;
    prop_oneof![
        (v.clone(), 1e-4..3e-3).prop_map(|(speed, duration)| Segment::Constant { speed, duration }),
        (v.clone(), v.clone(), 1e-4..3e-3).prop_map(|(from, to, duration)| Segment::Ramp {
            from,
            to,
            duration
        }),
        (0.0..1.0f64, 0.0..1.0f64, 100.0..5000.0, 1e-4..3e-3).prop_map(
            move |(m, a, freq_hz, duration)| {
                // |mean| + |amplitude| ≤ vmax; reverses when the amplitude is larger.
                let mean = vmax * (2.0 * m - 1.0) * (1.0 - a);
                Segment::Sine {
                    mean,
                    amplitude: vmax * a,
                    freq_hz,
                    duration,
                }
            }
        ),
        (1e-5..1e-3).prop_map(|duration| Segment::Stop { duration }),
    ]
}

/// Lines, filter length, mode, z mode, profile.
fn chain_case() -> impl Strategy<Value = (u32, u64, u8, u8, Profile)> {
    (1u32..=16, 0u64..=3, 0u8..=2, 0u8..=3).prop_flat_map(|(lines, l, mode, z_mode)| {
        // Quarter-line period ≥ 2·(L + 2) cycles at the peak speed (1 MHz clock), so no two
        // edges of the plant fall within one filter window or one sample.
        let vmax = 1e6 / (4.0 * f64::from(lines) * 2.0 * (l as f64 + 2.0));
        (
            Just(lines),
            Just(l),
            Just(mode),
            Just(z_mode),
            (-3.0..3.0f64, prop::collection::vec(segment(vmax), 1..5)).prop_map(
                move |(a0, segs)| {
                    // Still for the first L + 2 cycles: a filter leaves reset low, so a level
                    // that changes within L cycles of reset is a (start-up) glitch to it and
                    // the reference sample would not be the first one.
                    let still = Segment::Stop {
                        duration: (l as f64 + 2.0) / CLOCK_HZ,
                    };
                    Profile::new(a0, [still].into_iter().chain(segs).collect()).unwrap()
                },
            ),
        )
    })
}

const CLOCK_HZ: f64 = 1e6;

/// What the chain did on a plant run.
struct ChainRun {
    /// Net decoded steps (+1 forward, −1 backward).
    net: i64,
    /// ⌊M·x⌋ at the reference sample (edge 1) and at the end, x in lines.
    x_ref: i64,
    x_end: i64,
    /// M · lines.
    r: i64,
    /// Index edges processed by the counter.
    indexes: usize,
    /// Edges with `illegal` or `rev_error` high.
    illegal_edges: usize,
    rev_error_edges: usize,
    /// Counter outputs at the end.
    last: CounterOutputs,
}

/// Glitch filters (L = `l`) on A, B, Z → decoder (`mode`) → counter (`z_mode`, R = M ·
/// lines), on the plant's samples at 1 MHz, every block stepped from the values before the
/// edge, with a tail of still samples to flush the pipeline.
fn run_chain(lines: u32, l: u64, mode: u8, z_mode: u8, profile: &Profile) -> ChainRun {
    let disc = Disc::new(lines).unwrap();
    let es = edges(profile, &disc);
    let tail = 10 + l;
    let n = (profile.duration() * CLOCK_HZ).floor() as u64 + 1 + tail;
    let sampler = ClockSampler::new(initial_levels(profile, &disc), &es, CLOCK_HZ, n).unwrap();
    let m = [1i64, 2, 4][mode as usize];
    let r = m * i64::from(lines);
    let mut fa = GlitchFilter::new(4, 8);
    let mut fb = GlitchFilter::new(4, 8);
    let mut fz = GlitchFilter::new(4, 8);
    let mut dec = QuadratureDecoder::new(8);
    let mut cnt = PositionCounter::new(16, 8);
    // The filters' outputs are real samples after max(L, 1) edges: hold the decoder and the
    // counter in reset until then (edges 0..=max(L, 1)).
    let hold = l.max(1);
    let (mut fo_a, mut fo_b, mut fo_z) = (false, false, false);
    let mut dec_o = DecoderOutputs::default();
    let mut run = ChainRun {
        net: 0,
        x_ref: 0,
        x_end: 0,
        r,
        indexes: 0,
        illegal_edges: 0,
        rev_error_edges: 0,
        last: CounterOutputs::default(),
    };
    for (k, s) in sampler.enumerate() {
        let k = k as u64;
        let held = k <= hold;
        // Every block updates from the values before the edge.
        let c = cnt.step(CounterInputs {
            reset: held,
            step: dec_o.step,
            forward: dec_o.forward,
            z: fo_z,
            counts_per_rev: r as u64,
            cfg_z_mode: z_mode,
        });
        let d = dec.step(DecoderInputs {
            reset: held,
            a: fo_a,
            b: fo_b,
            cfg_mode: mode,
        });
        let f = |filter: &mut GlitchFilter, x| {
            filter
                .step(GlitchFilterInputs {
                    reset: k == 0,
                    level_in: x,
                    cfg_filter: l,
                })
                .level_out
        };
        fo_a = f(&mut fa, s.a);
        fo_b = f(&mut fb, s.b);
        fo_z = f(&mut fz, s.z);
        if d.step {
            run.net += if d.forward { 1 } else { -1 };
        }
        run.illegal_edges += usize::from(d.illegal);
        run.rev_error_edges += usize::from(c.rev_error);
        run.indexes += usize::from(c.index);
        dec_o = d;
        run.last = c;
    }
    // Reference: the sample of edge 1 (the filters delay every sample alike, and the
    // decoder primes on the first filtered sample after the hold).
    let counted = |t: f64| (m as f64 * disc.position(profile.angle(t))).floor() as i64;
    run.x_ref = counted(1.0 / CLOCK_HZ);
    run.x_end = counted(profile.duration() + 1.0);
    run
}

/// The checks of the chain property; the index window starts at ¼ line, ⌊M/4⌋ counted
/// edges after the line boundary.
fn check_chain(run: &ChainRun, mode: u8, z_mode: u8) -> Result<(), TestCaseError> {
    let m = [1i64, 2, 4][mode as usize];
    let z_off = m / 4;
    prop_assert_eq!(run.illegal_edges, 0);
    prop_assert_eq!(run.rev_error_edges, 0);
    prop_assert_eq!(run.net, run.x_end - run.x_ref);
    let resets = z_mode == Z_MODE_RESET || z_mode == Z_MODE_LATCH_RESET;
    let want_position = if resets && run.indexes > 0 {
        (run.x_end - z_off).rem_euclid(run.r)
    } else {
        (run.x_end - run.x_ref).rem_euclid(run.r)
    };
    prop_assert_eq!(run.last.position as i64, want_position);
    if z_mode == Z_MODE_LATCH && run.indexes > 0 {
        prop_assert_eq!(
            run.last.z_latch as i64,
            (z_off - run.x_ref).rem_euclid(run.r)
        );
    }
    if z_mode == Z_MODE_LATCH_RESET && run.indexes > 1 {
        prop_assert_eq!(run.last.z_latch, 0);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// Glitch filters (L = 0..3) → decoder → counter, on a clean plant signal with random
    /// speeds and reversals: the decoded net count is exactly the number of counted edges
    /// the shaft crossed between the reference sample (the first after reset) and the end,
    /// ⌊M·x_end⌋ − ⌊M·x_ref⌋ with x in lines and M = 1, 2, 4. No illegal transition, no
    /// revolution error; after an index edge the position is the count from the Z window,
    /// whatever the direction; the latch holds the same count at every index edge.
    #[test]
    fn chain_counts_the_lines_the_plant_crossed((lines, l, mode, z_mode, profile) in chain_case()) {
        let run = run_chain(lines, l, mode, z_mode, &profile);
        check_chain(&run, mode, z_mode)?;
    }
}

#[test]
fn chain_on_a_long_reversing_run() {
    // A guard on the property above: a run that crosses the index often in both directions
    // (4 lines, a sine of mean 0 swinging ±2.4 rev, then 10 forward revolutions at the
    // highest speed the stimulus allows, 7812.5 rev/s at L = 0), in every mode.
    let profile = Profile::new(
        0.1,
        vec![
            Segment::Sine {
                mean: 0.0,
                amplitude: 3000.0,
                freq_hz: 200.0,
                duration: 0.01,
            },
            Segment::Constant {
                speed: 7812.5,
                duration: 10.0 / 7812.5,
            },
        ],
    )
    .unwrap();
    for mode in [MODE_X1, MODE_X2, MODE_X4] {
        for z_mode in 0..4 {
            let run = run_chain(4, 0, mode, z_mode, &profile);
            assert!(run.indexes > 20, "{} index edges", run.indexes);
            check_chain(&run, mode, z_mode).unwrap();
        }
    }
}

#[test]
fn filter_length_change_acts_one_edge_later() {
    // Reset at edge 0 with L = 4, input 1 from edge 1, L = 1 first sampled at edge 2. By hand:
    // edge 1: run 0 → 1, and the decision for edge 2 uses edge 1's L = 4 (1 + 1 ≥ 4: no);
    // edge 2: not ready, run 2, and the decision for edge 3 uses L = 1 (2 + 1 ≥ 1); edge 3:
    // the 1 passes. A comparison with the same edge's L would have passed it at edge 2.
    let mut f = GlitchFilter::new(8, 8);
    let ls = [4u64, 4, 1, 1, 1];
    let out: Vec<bool> = ls
        .iter()
        .enumerate()
        .map(|(k, &l)| {
            f.step(GlitchFilterInputs {
                reset: k == 0,
                level_in: k > 0,
                cfg_filter: l,
            })
            .level_out
        })
        .collect();
    assert_eq!(out, [false, false, false, true, true]);
}
