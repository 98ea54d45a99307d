// SPDX-License-Identifier: MIT OR Apache-2.0
//! `PositionCounter` against its bit-true model (`golden::frontend::position_counter`),
//! every cycle, on a virtual shaft or random inputs, with random resets and run-time changes
//! of R and the index mode:
//! - rust-hdl simulation (direct drive, as `hdl::sim::core_sim`) = model: property tests;
//! - emitted Verilog in Icarus = model: the same generator, many cases concatenated into one
//!   replay.
//!
//! Stimuli come from `common::knobs`. A 4-bit position and a 2-bit error count, so that
//! wrap and saturation are reached.

use crate::common::{
    self,
    knobs::{coverage_cases, icarus_cases, knobs, Knobs, Rng},
};
use golden::frontend::position_counter::limits;
use golden::frontend::{CounterInputs, CounterOutputs, PositionCounter as GoldCounter};
use hdl::{position_counter_verilog, PositionCounter};
use proptest::prelude::*;
use rust_hdl::prelude::*;

const POSITION_BITS: usize = 4;
const REV_ERROR_BITS: usize = 2;

/// Either a virtual shaft (steps of a position modulo R with the index at position 0, `z`
/// one cycle ahead of the step into it, as the chain delivers it; some steps dropped and
/// some index samples flipped, so that good and bad revolutions both occur), or inputs
/// drawn at random. R (0..=15, 0 standing for 16) and the z mode change at run time; R
/// only with a reset, as the block requires (the core changes R only with the decoding
/// mode, which resets it).
fn stimulus(k: Knobs) -> Vec<CounterInputs> {
    let mut r = Rng::new(k.seed);
    let structured = r.chance(3, 4);
    let p_step = 1 + r.below(99);
    let p_drop = r.below(4);
    let max_r = (1u64 << POSITION_BITS) - 1;
    let mut cpr = r.below(max_r + 1);
    let mut z_mode = r.below(4) as u8;
    let mut forward = true;
    let mut shaft = 0u64;
    let mut z_level = false;
    // Moves first (the index level needs one cycle of look-ahead).
    let mut moves = Vec::with_capacity(k.cycles + 1);
    let mut shafts = Vec::with_capacity(k.cycles + 1);
    for _ in 0..=k.cycles {
        let rev = if cpr == 0 { max_r + 1 } else { cpr };
        let moved = r.below(100) < p_step;
        if moved {
            if r.chance(1, 15) {
                forward = !forward;
            }
            shaft = if forward {
                (shaft + 1) % rev
            } else {
                (shaft + rev - 1) % rev
            };
        }
        moves.push((moved, forward, cpr, z_mode));
        shafts.push(shaft);
        if r.chance(1, k.cfg_every) {
            cpr = r.below(max_r + 1);
            shaft = 0;
        }
        if r.chance(1, k.cfg_every) {
            z_mode = r.below(4) as u8;
        }
    }
    (0..k.cycles)
        .map(|c| {
            let (moved, fwd, cpr, z_mode) = moves[c];
            let (step, z) = if structured {
                let dropped = moved && r.below(100) < p_drop;
                let z = (shafts[c + 1] == 0) != r.chance(1, 200);
                (moved && !dropped, z)
            } else {
                if r.chance(1, 8) {
                    z_level = !z_level;
                }
                (moved, z_level)
            };
            let r_changed = c > 0 && moves[c - 1].2 != cpr;
            CounterInputs {
                reset: c == 0 || r_changed || r.chance(1, k.reset_every),
                step,
                forward: if structured { fwd } else { r.chance(1, 2) },
                z,
                counts_per_rev: cpr,
                cfg_z_mode: z_mode,
            }
        })
        .collect()
}

/// The decoder's `first` for each cycle, as the core feeds it: a step with no step since
/// the last reset, or against the last step (a reset cycle's step is not made).
fn firsts(stim: &[CounterInputs]) -> Vec<bool> {
    common::steps::first_steps(stim.iter().map(|i| (i.reset, i.step, i.forward)))
}

fn golden(stim: &[CounterInputs]) -> Vec<CounterOutputs> {
    let mut m = GoldCounter::new(POSITION_BITS as u32, REV_ERROR_BITS as u32);
    stim.iter().map(|&i| m.step(i)).collect()
}

fn rust_hdl(stim: &[CounterInputs]) -> Vec<CounterOutputs> {
    let mut uut = PositionCounter::<POSITION_BITS, REV_ERROR_BITS>::default();
    uut.connect_all();
    stim.iter()
        .zip(firsts(stim))
        .map(|(i, first)| {
            uut.reset.next = i.reset;
            uut.step.next = i.step;
            uut.forward.next = i.forward;
            uut.first.next = first;
            uut.z.next = i.z;
            let (limit, limit_less_one, limit_less_two) =
                limits(i.counts_per_rev, POSITION_BITS as u32);
            uut.limit.next = limit.into();
            uut.limit_less_one.next = limit_less_one.into();
            uut.limit_less_two.next = limit_less_two.into();
            uut.cfg_z_mode.next = u64::from(i.cfg_z_mode).into();
            common::edge(&mut uut, |u, v| u.clock.next = Clock { clk: v });
            CounterOutputs {
                position: uut.position.val().to_u64(),
                z_latch: uut.z_latch.val().to_u64(),
                index: uut.index.val(),
                rev_error: uut.rev_error.val(),
                rev_error_count: uut.rev_error_count.val().to_u64(),
                rev_fault: uut.rev_fault.val(),
            }
        })
        .collect()
}

proptest! {
    #![proptest_config(common::proptest_config(1000))]

    #[test]
    fn rust_hdl_equals_golden(k in knobs()) {
        let stim = stimulus(k);
        common::first_mismatch(&stim, &rust_hdl(&stim), &golden(&stim))?;
    }
}

/// The generator reaches what it is meant to: index edges, latched index positions, and
/// good and bad checked revolutions (the error count saturated).
#[test]
fn stimulus_covers_the_interesting_cases() {
    let (mut index, mut errors, mut clean, mut latched) = (0, 0, 0, 0);
    for k in coverage_cases() {
        let o = golden(&stimulus(k));
        index += o.iter().filter(|o| o.index).count();
        errors += usize::from(o.iter().any(|o| o.rev_error_count == 3));
        latched += usize::from(o.iter().any(|o| o.z_latch != 0));
        // Cases with many index edges and no error at all: good revolutions were checked.
        clean +=
            usize::from(o.iter().filter(|o| o.index).count() > 20 && !o[o.len() - 1].rev_error);
    }
    assert!(
        index > 5_000 && errors > 30 && clean > 10 && latched > 50,
        "{index} {errors} {clean} {latched}"
    );
}

#[test]
fn emitted_verilog_equals_golden_in_icarus() {
    let stim: Vec<CounterInputs> = icarus_cases().flat_map(stimulus).collect();
    let want: Vec<Vec<u64>> = golden(&stim)
        .iter()
        .map(|o| {
            vec![
                o.position,
                o.z_latch,
                u64::from(o.index),
                u64::from(o.rev_error),
                o.rev_error_count,
                u64::from(o.rev_fault),
            ]
        })
        .collect();
    let vectors: Vec<Vec<u64>> = stim
        .iter()
        .zip(firsts(&stim))
        .map(|(i, first)| {
            vec![
                u64::from(i.reset),
                u64::from(i.step),
                u64::from(i.forward),
                u64::from(first),
                u64::from(i.z),
                limits(i.counts_per_rev, POSITION_BITS as u32).0,
                limits(i.counts_per_rev, POSITION_BITS as u32).1,
                limits(i.counts_per_rev, POSITION_BITS as u32).2,
                u64::from(i.cfg_z_mode),
            ]
        })
        .collect();
    let got = common::icarus_rows(
        "frontend_cosim",
        "position_counter",
        &position_counter_verilog::<POSITION_BITS, REV_ERROR_BITS>("position_counter"),
        &[
            ("reset", 1),
            ("step", 1),
            ("forward", 1),
            ("first", 1),
            ("z", 1),
            ("limit", POSITION_BITS),
            ("limit_less_one", POSITION_BITS),
            ("limit_less_two", POSITION_BITS),
            ("cfg_z_mode", 2),
        ],
        &[
            ("position", POSITION_BITS),
            ("z_latch", POSITION_BITS),
            ("index", 1),
            ("rev_error", 1),
            ("rev_error_count", REV_ERROR_BITS),
            ("rev_fault", 1),
        ],
        &vectors,
    );
    common::compare_rows("position_counter", &got, &want);
}
