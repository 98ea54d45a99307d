// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_ecc`'s bit-true model on the rigid eccentric disc: the corrected M/T speed of
//! every window against the plant's constant shaft speed (the position aligned to the disc's
//! lines by the index, `cfg_z_mode` = 1), and the identification gathered by the same top
//! (armed at the end of reset: the top holds the arm until the index that aligns the
//! position) against the disc's e and θ0 within the budget of
//! `golden::ecc::ident_gatherer::error_budget`. The Verilog's figures: tb/tests/ecc_top.rs.

use golden::ecc::ecc_delta::coefficients;
use golden::ecc::ident_gatherer::{error_budget, identify_from_sums, GatherOutputs};
use golden::eccentric::correct::once_per_rev;
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::ideal::plant::{ClockSampler, Profile};
use golden::params::{Params, Spec};
use golden::top::core::CoreInputs;
use golden::top::ecc_top::{
    check_revolution, mtc_after_mt_strobe, n3c_after_speed_strobe, ArmedModel, EccTopInputs,
    IDENT_DONE_AFTER_INDEX,
};
use std::f64::consts::TAU;

const K: u32 = 1024;
const CLOCK: f64 = 100e6;
const DT: u64 = 100_000;

fn params() -> Params {
    Params::new(Spec {
        clock_hz: CLOCK,
        lines: K,
        dt_cycles: DT,
        counter_bits: 24,
        ..Default::default()
    })
    .unwrap()
}

#[test]
fn corrected_mt_on_the_rigid_disc() {
    let p = params();
    let (e, theta0) = (0.35 / 30.0, 50f64.to_radians());
    let (c, d) = coefficients(K, e, theta0);
    for rpm in [6000.0, 600.0] {
        let rps: f64 = rpm / 60.0;
        let revs = 3.3;
        let profile = Profile::constant(rps, revs / rps).unwrap();
        let disc =
            EccentricDisc::new(K, Eccentricity::new(Model::Rigid, e, theta0).unwrap()).unwrap();
        let edges = disc.edges(&profile);
        let n = (profile.duration() * CLOCK) as u64;
        let sampler = ClockSampler::new(disc.initial_levels(&profile), &edges, CLOCK, n).unwrap();
        let mut top = ArmedModel::new(&p, None);
        let r = rps * f64::from(K) * DT as f64 / CLOCK;
        let (mut before, mut after) = (vec![], vec![]);
        let (mut n3_before, mut n3_after) = (vec![], vec![]);
        let t0 = std::time::Instant::now();
        let mut aligned = false;
        let mut ident = GatherOutputs::default();
        let (mut last_index, mut done_at) = (0, None);
        // The edges that raised the last mt_strobe and speed_strobe, and how many corrected
        // strobes came the documented number of edges after them.
        let (mut last_mt, mut last_speed, mut mtc_timed, mut n3c_timed) = (0, 0, 0, 0);
        for (k, s) in sampler.enumerate() {
            let (_, o) = top.step(EccTopInputs {
                core: CoreInputs {
                    reset: k < 3,
                    enc_a: s.a,
                    enc_b: s.b,
                    enc_z: s.z,
                    cfg_z_mode: 1,
                    ..Default::default()
                },
                ecc_c: c,
                ecc_d: d,
                // Armed at the end of reset, before any index: the top holds the arm
                // until the index that aligns the position. The reset sampled at edges
                // 0..=2 acts at edges 1..=3, so edge 4 is the first one it does not clear.
                ident_arm: k == 4,
            });
            let k64 = k as u64;
            if o.mtc_strobe {
                assert_eq!(k64 - last_mt, mtc_after_mt_strobe(&p), "mtc_strobe at {k}");
                mtc_timed += 1;
            }
            if o.n3c_strobe {
                assert_eq!(
                    k64 - last_speed,
                    n3c_after_speed_strobe(&p),
                    "n3c_strobe at {k}"
                );
                n3c_timed += 1;
            }
            if o.core.mt_strobe {
                last_mt = k64;
            }
            if o.core.speed_strobe {
                last_speed = k64;
            }
            if o.ident.done && !ident.done {
                done_at = Some(k as u64 - last_index);
            }
            if o.core.index {
                last_index = k as u64;
            }
            ident = o.ident;
            let t = k as f64 / CLOCK;
            aligned |= o.core.index;
            if !aligned {
                continue;
            }
            if o.core.baseline_strobe && o.core.speed_mt != 0 {
                before.push((TAU * rps * t, o.core.speed_mt as f64 / 65536.0 / r - 1.0));
            }
            if o.core.speed_strobe && o.core.speed_n3 != 0 {
                n3_before.push((TAU * rps * t, o.core.speed_n3 as f64 / 65536.0 / r - 1.0));
            }
            if o.n3c_strobe && o.speed_n3c != 0 {
                n3_after.push((TAU * rps * t, o.speed_n3c as f64 / 65536.0 / r - 1.0));
            }
            if o.mtc_strobe && o.speed_mtc != 0 {
                after.push((TAU * rps * t, o.speed_mtc as f64 / 65536.0 / r - 1.0));
            }
        }
        let take_rev = |v: &[(f64, f64)]| -> Vec<(f64, f64)> {
            let a0 = v[0].0;
            v.iter().copied().filter(|x| x.0 < a0 + TAU).collect()
        };
        let (b, a) = (take_rev(&before), take_rev(&after));
        let (h_before, h_after) = (once_per_rev(&b), once_per_rev(&a));
        let (nb, na) = (take_rev(&n3_before), take_rev(&n3_after));
        let pp = |v: &[(f64, f64)]| {
            v.iter().map(|x| x.1).fold(f64::NEG_INFINITY, f64::max)
                - v.iter().map(|x| x.1).fold(f64::INFINITY, f64::min)
        };
        println!(
            "{rpm} rpm n3: {} / {} estimates; 1/rev before {:.1} ppm after {:.1} ppm; p-p {:.1} -> {:.1} ppm",
            nb.len(),
            na.len(),
            once_per_rev(&nb) * 1e6,
            once_per_rev(&na) * 1e6,
            pp(&nb) * 1e6,
            pp(&na) * 1e6
        );
        // The eccentricity's ripple is there before (about e), and the correction takes
        // more than 1000x of it away: M/T's quantisation is the floor.
        assert!(h_before > 0.9 * e, "{rpm} rpm: 1/rev before {h_before}");
        assert!(
            h_before / h_after > 1000.0,
            "{rpm} rpm: 1/rev {h_before} -> {h_after}"
        );
        println!(
            "{rpm} rpm: {} cycles in {:?}; {} / {} estimates; 1/rev before {:.1} ppm after {:.3} ppm",
            n,
            t0.elapsed(),
            b.len(),
            a.len(),
            once_per_rev(&b) * 1e6,
            once_per_rev(&a) * 1e6
        );
        // The identification of the first whole revolution: K lines, Σ T the revolution's
        // length (±1 cycle of sampling), e and θ0 within the budget.
        assert_eq!(
            check_revolution(&ident, K, CLOCK / rps),
            Ok(()),
            "{rpm} rpm"
        );
        // The documented latencies: from the closing index (docs/ports.md), and of every
        // corrected strobe from the strobe that raised its job (165 and 117 edges at N = 24,
        // as the independent bench of the eccentricity hardware measured).
        assert_eq!(done_at, Some(IDENT_DONE_AFTER_INDEX));
        assert!(mtc_timed > 10 && n3c_timed > 10, "{mtc_timed} {n3c_timed}");
        assert_eq!(
            (mtc_after_mt_strobe(&p), n3c_after_speed_strobe(&p)),
            (165, 117)
        );
        let got = identify_from_sums(K, ident.sum_t, ident.sum_sin, ident.sum_cos, Model::Rigid);
        let (de, dth) = error_budget(ident.sum_t as f64, e);
        let err_th =
            (got.theta0 - theta0 + std::f64::consts::PI).rem_euclid(TAU) - std::f64::consts::PI;
        println!(
            "{rpm} rpm identification: e {:.8} (error {:.2e}, budget {:.2e}), theta0 {:.5} deg (error {:.2e} deg, budget {:.2e} deg)",
            got.e,
            got.e - e,
            de,
            got.theta0.to_degrees(),
            err_th.to_degrees(),
            dth.to_degrees()
        );
        assert!((got.e - e).abs() <= de, "{rpm} rpm: e {} for {e}", got.e);
        assert!(err_th.abs() <= dth, "{rpm} rpm: theta0 error {err_th} rad");
    }
}

/// The frame of the position in each decoding mode, as docs/reference-model.md states it
/// from the plant's waveform: in x1 and x2 line p's edge is A rising at x = p lines; in x4
/// the B step that comes with Z is absorbed into position 0, and line p's edge is B rising
/// at x = p + ¼. With the fitted T/T̄ = 1 − a1·cos(2πp/K + θ0) (docs/eccentricity-hardware.md,
/// "Sign"), a frame that puts line p a quarter line later finds θ0 + 2π/(4K). So the θ0
/// identified in x4 is π/(2K) above the one in x1 and x2 (which is the disc's own), each
/// within the identification's budget.
#[test]
fn identification_frame_of_x4_is_a_quarter_line_after_x1_and_x2() {
    use golden::frontend::config::{MODE_X1, MODE_X2, MODE_X4};
    let p = params();
    let (e, theta0) = (0.35 / 30.0, 50f64.to_radians());
    let rps: f64 = 100.0;
    let profile = Profile::constant(rps, 3.3 / rps).unwrap();
    let disc = EccentricDisc::new(K, Eccentricity::new(Model::Rigid, e, theta0).unwrap()).unwrap();
    let edges = disc.edges(&profile);
    let n = (profile.duration() * CLOCK) as u64;
    let identify = |mode: u8| {
        let sampler = ClockSampler::new(disc.initial_levels(&profile), &edges, CLOCK, n).unwrap();
        let mut top = ArmedModel::new(&p, None);
        let mut ident = GatherOutputs::default();
        for (k, s) in sampler.enumerate() {
            let (_, o) = top.step(EccTopInputs {
                core: CoreInputs {
                    reset: k < 3,
                    enc_a: s.a,
                    enc_b: s.b,
                    enc_z: s.z,
                    cfg_mode: mode,
                    cfg_z_mode: 1,
                    ..Default::default()
                },
                ident_arm: k == 4,
                ..Default::default()
            });
            ident = o.ident;
        }
        assert!(
            ident.done,
            "mode {mode}: no identification in 3.3 revolutions"
        );
        assert_eq!(
            check_revolution(&ident, K, CLOCK / rps),
            Ok(()),
            "mode {mode}"
        );
        let got = identify_from_sums(K, ident.sum_t, ident.sum_sin, ident.sum_cos, Model::Rigid);
        let (_, dth) = error_budget(ident.sum_t as f64, e);
        (got.theta0, dth)
    };
    let wrap = |a: f64| (a + std::f64::consts::PI).rem_euclid(TAU) - std::f64::consts::PI;
    let quarter_line = TAU / (4.0 * f64::from(K));
    for (mode, shift) in [(MODE_X1, 0.0), (MODE_X2, 0.0), (MODE_X4, quarter_line)] {
        let (got, dth) = identify(mode);
        let err = wrap(got - theta0 - shift);
        println!(
            "mode {mode}: theta0 {:.5} deg, expected {:.5} deg, error {:.2e} deg (budget {:.2e} deg)",
            got.to_degrees(),
            (theta0 + shift).to_degrees(),
            err.to_degrees(),
            dth.to_degrees()
        );
        assert!(
            err.abs() <= dth,
            "mode {mode}: theta0 error {err} rad, budget {dth}"
        );
        // The budget resolves the shift: a θ0 in the other frame would be outside it.
        assert!(
            dth < quarter_line,
            "budget {dth} rad vs a quarter line {quarter_line}"
        );
    }
}
