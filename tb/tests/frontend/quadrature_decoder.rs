// SPDX-License-Identifier: MIT OR Apache-2.0
//! `QuadratureDecoder` against its bit-true model (`golden::frontend::quadrature_decoder`),
//! every cycle, on random walks of A/B with random resets and run-time changes of
//! `cfg_mode` (3 included):
//! - rust-hdl simulation (direct drive, as `hdl::sim::core_sim`) = model: property tests;
//! - emitted Verilog in Icarus = model: the same generator, many cases concatenated into one
//!   replay.
//!
//! Stimuli come from `common::knobs`. A 3-bit illegal-transition count, so that its
//! saturation is reached.

use crate::common::{
    self,
    knobs::{coverage_cases, icarus_cases, knobs, Knobs, Rng},
};
use golden::frontend::{DecoderInputs, DecoderOutputs, QuadratureDecoder as GoldDecoder};
use hdl::{quadrature_decoder_verilog, QuadratureDecoder};
use proptest::prelude::*;
use rust_hdl::prelude::*;

const ILLEGAL_BITS: usize = 3;

/// A random walk on the Gray cycle: holds, steps with direction persistence and reversals,
/// and illegal jumps (both channels at once); random decoding mode, 3 included.
fn stimulus(k: Knobs) -> Vec<DecoderInputs> {
    const GRAY: [(bool, bool); 4] = [(false, false), (true, false), (true, true), (false, true)];
    let mut r = Rng::new(k.seed);
    let hold = r.below(95);
    let illegal = r.below(6);
    let mut phase = r.below(4) as usize;
    let mut forward = true;
    let mut mode = r.below(4) as u8;
    (0..k.cycles)
        .map(|c| {
            if r.chance(1, k.cfg_every) {
                mode = r.below(4) as u8;
            }
            let roll = r.below(100);
            if roll < illegal {
                phase = (phase + 2) % 4;
            } else if roll >= illegal + hold {
                if r.chance(1, 20) {
                    forward = !forward;
                }
                phase = (phase + if forward { 1 } else { 3 }) % 4;
            }
            DecoderInputs {
                reset: c == 0 || r.chance(1, k.reset_every),
                a: GRAY[phase].0,
                b: GRAY[phase].1,
                cfg_mode: mode,
            }
        })
        .collect()
}

fn golden(stim: &[DecoderInputs]) -> Vec<DecoderOutputs> {
    let mut m = GoldDecoder::new(ILLEGAL_BITS as u32);
    stim.iter().map(|&i| m.step(i)).collect()
}

fn rust_hdl(stim: &[DecoderInputs]) -> Vec<DecoderOutputs> {
    let mut uut = QuadratureDecoder::<ILLEGAL_BITS>::default();
    uut.connect_all();
    stim.iter()
        .map(|i| {
            uut.reset.next = i.reset;
            uut.a.next = i.a;
            uut.b.next = i.b;
            uut.cfg_mode.next = u64::from(i.cfg_mode).into();
            common::edge(&mut uut, |u, v| u.clock.next = Clock { clk: v });
            DecoderOutputs {
                step: uut.step.val(),
                forward: uut.forward.val(),
                first: uut.first.val(),
                direction: uut.direction.val(),
                illegal: uut.illegal.val(),
                illegal_seen: uut.illegal_seen.val(),
                illegal_count: uut.illegal_count.val().to_u64(),
                mode_error: uut.mode_error.val(),
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

/// The generator reaches what it is meant to: steps of both signs, illegal transitions up
/// to saturation of their count, and the reserved mode.
#[test]
fn stimulus_covers_the_interesting_cases() {
    let (mut fwd, mut back, mut illegal_sat, mut mode_err) = (0, 0, 0, 0);
    for k in coverage_cases() {
        let o = golden(&stimulus(k));
        fwd += o.iter().filter(|o| o.step && o.forward).count();
        back += o.iter().filter(|o| o.step && !o.forward).count();
        illegal_sat += usize::from(o.iter().any(|o| o.illegal_count == 7));
        mode_err += usize::from(o.iter().any(|o| o.mode_error));
    }
    assert!(fwd > 10_000 && back > 10_000, "{fwd} {back}");
    assert!(
        illegal_sat > 50 && mode_err > 50,
        "{illegal_sat} {mode_err}"
    );
}

#[test]
fn emitted_verilog_equals_golden_in_icarus() {
    let stim: Vec<DecoderInputs> = icarus_cases().flat_map(stimulus).collect();
    let want: Vec<Vec<u64>> = golden(&stim)
        .iter()
        .map(|o| {
            vec![
                u64::from(o.step),
                u64::from(o.forward),
                u64::from(o.first),
                u64::from(o.direction),
                u64::from(o.illegal),
                u64::from(o.illegal_seen),
                o.illegal_count,
                u64::from(o.mode_error),
            ]
        })
        .collect();
    let vectors: Vec<Vec<u64>> = stim
        .iter()
        .map(|i| {
            vec![
                u64::from(i.reset),
                u64::from(i.a),
                u64::from(i.b),
                u64::from(i.cfg_mode),
            ]
        })
        .collect();
    let got = common::icarus_rows(
        "frontend_cosim",
        "quadrature_decoder",
        &quadrature_decoder_verilog::<ILLEGAL_BITS>("quadrature_decoder"),
        &[("reset", 1), ("a", 1), ("b", 1), ("cfg_mode", 2)],
        &[
            ("step", 1),
            ("forward", 1),
            ("first", 1),
            ("direction", 1),
            ("illegal", 1),
            ("illegal_seen", 1),
            ("illegal_count", ILLEGAL_BITS),
            ("mode_error", 1),
        ],
        &vectors,
    );
    common::compare_rows("quadrature_decoder", &got, &want);
}
