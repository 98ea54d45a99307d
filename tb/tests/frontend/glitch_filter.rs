// SPDX-License-Identifier: MIT OR Apache-2.0
//! `GlitchFilter` against its bit-true model (`golden::frontend::glitch_filter`), every cycle,
//! on random stimuli with random resets and run-time changes of `cfg_filter`:
//! - rust-hdl simulation (direct drive, as `hdl::sim::core_sim`) = model: property tests;
//! - emitted Verilog in Icarus = model: the same generator, many cases concatenated into one
//!   replay (a second, independent simulator of what ships).
//!
//! Stimuli come from `common::knobs` (the proptest input is the seed, the length and the
//! knobs). Widths under test are small, so that saturation, wrap and the 32-bit-literal
//! pitfalls of rust-hdl's Verilog are reached.

use crate::common::{
    self,
    knobs::{coverage_cases, icarus_cases, knobs, Knobs, Rng},
};
use golden::frontend::{GlitchFilter as GoldFilter, GlitchFilterInputs, GlitchFilterOutputs};
use hdl::{glitch_filter_verilog, GlitchFilter};
use proptest::prelude::*;
use rust_hdl::prelude::*;

const FILTER_BITS: usize = 4;
const GLITCH_BITS: usize = 3;

/// A channel made of runs of random lengths: short ones (around L, so that some pass and
/// some are rejected) and long ones.
fn stimulus(k: Knobs) -> Vec<GlitchFilterInputs> {
    let mut r = Rng::new(k.seed);
    let max_l = (1u64 << FILTER_BITS) - 1;
    let mut l = r.below(max_l + 1);
    let mut level = r.chance(1, 2);
    let mut left = 0;
    (0..k.cycles)
        .map(|c| {
            if r.chance(1, k.cfg_every) {
                l = r.below(max_l + 1);
            }
            if left == 0 {
                level = !level;
                left = if r.chance(1, 2) {
                    1 + r.below(l + 2)
                } else {
                    1 + r.below(40)
                };
            }
            left -= 1;
            GlitchFilterInputs {
                reset: c == 0 || r.chance(1, k.reset_every),
                level_in: level,
                cfg_filter: l,
            }
        })
        .collect()
}

fn golden(stim: &[GlitchFilterInputs]) -> Vec<GlitchFilterOutputs> {
    let mut m = GoldFilter::new(FILTER_BITS as u32, GLITCH_BITS as u32);
    stim.iter().map(|&i| m.step(i)).collect()
}

fn rust_hdl(stim: &[GlitchFilterInputs]) -> Vec<GlitchFilterOutputs> {
    let mut uut = GlitchFilter::<FILTER_BITS, GLITCH_BITS>::default();
    uut.connect_all();
    stim.iter()
        .map(|i| {
            uut.reset.next = i.reset;
            uut.level_in.next = i.level_in;
            uut.cfg_filter.next = i.cfg_filter.into();
            common::edge(&mut uut, |u, v| u.clock.next = Clock { clk: v });
            GlitchFilterOutputs {
                level_out: uut.level_out.val(),
                glitches: uut.glitches.val().to_u64(),
                rejected: uut.rejected.val(),
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

/// The generator reaches what it is meant to: rejections, saturation of the glitch count
/// and many passed edges.
#[test]
fn stimulus_covers_the_interesting_cases() {
    let (mut glitch_sat, mut passes) = (0, 0);
    for k in coverage_cases() {
        let o = golden(&stimulus(k));
        glitch_sat += usize::from(o.iter().any(|o| o.glitches == (1 << GLITCH_BITS) - 1));
        passes += o
            .windows(2)
            .filter(|w| w[0].level_out != w[1].level_out)
            .count();
    }
    assert!(glitch_sat > 50 && passes > 10_000, "{glitch_sat} {passes}");
}

#[test]
fn emitted_verilog_equals_golden_in_icarus() {
    let stim: Vec<GlitchFilterInputs> = icarus_cases().flat_map(stimulus).collect();
    let want: Vec<Vec<u64>> = golden(&stim)
        .iter()
        .map(|o| vec![u64::from(o.level_out), o.glitches, u64::from(o.rejected)])
        .collect();
    let vectors: Vec<Vec<u64>> = stim
        .iter()
        .map(|i| vec![u64::from(i.reset), u64::from(i.level_in), i.cfg_filter])
        .collect();
    let got = common::icarus_rows(
        "frontend_cosim",
        "glitch_filter",
        &glitch_filter_verilog::<FILTER_BITS, GLITCH_BITS>("glitch_filter"),
        &[("reset", 1), ("level_in", 1), ("cfg_filter", FILTER_BITS)],
        &[("level_out", 1), ("glitches", GLITCH_BITS), ("rejected", 1)],
        &vectors,
    );
    common::compare_rows("glitch_filter", &got, &want);
}
