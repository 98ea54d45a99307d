// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_ecc` on the emitted Verilog in Verilator:
//! - cycle for cycle against its bit-true model (`golden::top::ecc_top`) on eccentric discs in
//!   x1/x2/x4, forward, backward and through reversals, random and realistic coefficients;
//! - the once-per-revolution ripple of M/T before (`speed_mt`) and after (`speed_mtc`)
//!   correction, on the shipped `generated/encspeed_ecc.v`, with the rigid disc at
//!   e = 0.35/30 (K = 1024, θ0 = 50°, 100 MHz, dt = 1 ms, x1) at 30, 600 and 6000 r/min,
//!   every strobe of the Verilog equal to the model's, and each corrected estimate within
//!   its quantisation budget ([`tb::ecc_ripple`]);
//! - the same for n3 (`speed_n3`, `speed_n3c`) against Rairán's bound for the hardware;
//! - built without the identification (`--no-identification`): the model's `ident_*` read
//!   0 where the full top's gather a revolution, every other output equal to the full
//!   top's, and rust-hdl and the Verilog equal to that model;
//! - the identification the Verilog gathers (armed at the first index) against the disc's
//!   e and θ0 within `golden::ecc::ident_gatherer::error_budget`, equal to the model's, and the
//!   whole loop: identify, load the corrector, correct.
//!
//! Run with `--nocapture` for the figures of docs/eccentricity-hardware.md; the samples go
//! to target/ecc-ripple/ (CSV and SVG).

use golden::ecc::ecc_delta::coefficients;
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::ideal::plant::Profile;
use golden::params::{Params, Spec};
use golden::top::core::CoreInputs;
use golden::top::ecc_top::{check_revolution, disc_inputs, ArmedModel, EccTopInputs};
use hdl::sim::ecc_sim::build_ecc;
use proptest::prelude::*;
use std::f64::consts::TAU;
use tb::ecc_ripple::{
    draw_svg, figures, run_verilog, Identification, Ripple, RippleSetup, Stimulus,
};
use tb::ecc_verilator::{EccStrobe, EccVerilated, EventLog};

fn small(lines: u32) -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines,
        dt_cycles: 200,
        counter_bits: 12,
        timeout_s: 0.05,
        ..Spec::default()
    })
    .unwrap()
}

fn verilated(p: &Params) -> EccVerilated {
    let v = build_ecc(p).unwrap().verilog();
    EccVerilated::build(&v, p.speed_bits()).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]
    #[test]
    fn verilog_equals_golden(
        lines in prop::sample::select(vec![8u32, 16, 20, 64]),
        e in 0.0f64..0.2,
        theta0 in 0.0f64..TAU,
        lines_per_ms in 2.0f64..40.0,
        mode in 0u8..3,
        reverse in any::<bool>(),
        cfg_dt in prop::sample::select(vec![0u64, 90, 400, 3000]),
        coef in (-(1i64 << 31)..(1i64 << 31), -(1i64 << 31)..(1i64 << 31)),
        realistic in any::<bool>(),
        arm_delay in 0u64..3_000,
        // An early arm from edge 4: `disc_inputs` holds reset for edges 0..=2, and the
        // registered reset (reset_to_effect = 1) clears the top at edges 1..=3, an arm
        // sampled at edge 3 with it.
        early_arm in prop::option::of(4u64..200),
    ) {
        let p = small(lines);
        let disc = EccentricDisc::new(lines, Eccentricity::new(Model::Rigid, e, theta0).unwrap()).unwrap();
        let rps = lines_per_ms * 1000.0 / f64::from(lines);
        let cycles = 60_000u64;
        let duration = cycles as f64 / 1e6;
        let profile = if reverse {
            Profile::reversal(rps, duration).unwrap()
        } else {
            Profile::constant(rps, duration).unwrap()
        };
        let (initial, changes) = disc.clock_changes(&profile, 1e6);
        let (c, d) = if realistic { coefficients(lines, e, theta0) } else { coef };
        let config = EccTopInputs {
            core: CoreInputs { cfg_dt, cfg_mode: mode, cfg_z_mode: 1, ..Default::default() },
            ecc_c: c,
            ecc_d: d,
            ident_arm: false,
        };
        // The model first: it decides the arm's cycle.
        // Armed early (before the aligning index, which the top waits for) or after the first
        // index.
        let mut model = ArmedModel::new(&p, early_arm.is_none().then_some(arm_delay));
        let early = |k: usize, mut i: EccTopInputs| {
            i.ident_arm = early_arm == Some(k as u64);
            i
        };
        let (inputs, wanted): (Vec<_>, Vec<_>) =
            disc_inputs(initial, &changes, cycles, config)
                .enumerate()
                .map(|(k, i)| model.step(early(k, i)))
                .unzip();
        let got = verilated(&p).run(&inputs, None).unwrap();
        let (mut strobes, mut n3_strobes) = (0, 0);
        for (k, (g, want)) in got.iter().zip(&wanted).enumerate() {
            prop_assert_eq!(g, want, "cycle {}", k);
            strobes += usize::from(want.mtc_strobe);
            n3_strobes += usize::from(want.n3c_strobe);
        }
        prop_assert!(strobes > 0 && n3_strobes > 0);
        // A forward run armed for more than two revolutions has gathered one.
        let rev_cycles = 1e6 / rps;
        let armed_at = early_arm.or(model.arm_at());
        let armed_for = armed_at.map_or(0.0, |a| (cycles - a) as f64);
        let revs_needed = if early_arm.is_some() { 3.0 } else { 2.0 };
        if !reverse && armed_for > revs_needed * rev_cycles + 100.0 {
            prop_assert_eq!(check_revolution(&wanted[wanted.len() - 1].ident, lines, rev_cycles), Ok(()));
        }
    }
}

/// `encspeed_ecc` built without the identification (`Spec::identification` false): on an
/// eccentric disc armed after the first index, the full top's model gathers a revolution
/// (`ident_done` and the sums non-zero), while the reduced top's model reads 0 on every
/// `ident_*` output and equals the full one on every other output, cycle for cycle; rust-hdl
/// (the first 24 000 cycles: it is slow) and the emitted Verilog in Verilator (all of them)
/// equal the reduced model.
#[test]
fn identification_left_out_reads_zero_in_every_layer() {
    let full = small(16);
    let off = Params::new(Spec {
        identification: false,
        ..full.spec().clone()
    })
    .unwrap();
    assert!(full.identification() && !off.identification());
    let disc = EccentricDisc::new(16, Eccentricity::new(Model::Rigid, 0.1, 1.0).unwrap()).unwrap();
    // 12 lines per ms: a revolution of 16 lines is 1 333 cycles at 1 MHz.
    let rps = 12_000.0 / 16.0;
    let cycles = 30_000u64;
    let profile = Profile::constant(rps, cycles as f64 / 1e6).unwrap();
    let (initial, changes) = disc.clock_changes(&profile, 1e6);
    let (c, d) = coefficients(16, 0.1, 1.0);
    let config = EccTopInputs {
        core: CoreInputs {
            cfg_dt: 400,
            cfg_z_mode: 1,
            ..Default::default()
        },
        ecc_c: c,
        ecc_d: d,
        ident_arm: false,
    };
    let mut full_model = ArmedModel::new(&full, Some(700));
    let mut off_model = ArmedModel::new(&off, Some(700));
    let (mut done_cycles, mut strobes) = (0, 0);
    let (inputs, wanted): (Vec<_>, Vec<_>) = disc_inputs(initial, &changes, cycles, config)
        .enumerate()
        .map(|(k, i)| {
            let (i, with) = full_model.step(i);
            let (i_off, without) = off_model.step(i);
            assert_eq!(i_off, i, "cycle {k}: the same arm");
            done_cycles += usize::from(with.ident.done);
            strobes += usize::from(with.mtc_strobe) + usize::from(with.n3c_strobe);
            let mut expected = with;
            expected.ident = Default::default();
            assert_eq!(
                without, expected,
                "cycle {k}: the full top's with ident_* = 0"
            );
            (i, without)
        })
        .unzip();
    assert!(
        done_cycles > 0 && strobes > 0,
        "the full top gathered no revolution ({done_cycles} cycles done) or corrected \
         nothing ({strobes} strobes)"
    );
    let got = verilated(&off).run(&inputs, None).unwrap();
    assert_eq!(got.len(), wanted.len());
    for (k, (g, w)) in got.iter().zip(&wanted).enumerate() {
        assert_eq!(g, w, "Verilog, cycle {k}");
    }
    let mut sim = build_ecc(&off).unwrap();
    for (k, (i, w)) in inputs.iter().zip(&wanted).take(24_000).enumerate() {
        assert_eq!(&sim.step(i), w, "rust-hdl, cycle {k}");
    }
}

/// What the bit-true model gives for an event-mode run of `setup` (armed at the first
/// index, as the harness does), streamed: runs of 2·10^8 cycles need no storage.
struct ModelLog {
    strobes: Vec<EccStrobe>,
    ident: Vec<(u64, golden::ecc::ident_gatherer::GatherOutputs)>,
    first_index: u64,
}

fn model_log(p: &Params, setup: &RippleSetup, stim: &Stimulus) -> ModelLog {
    let (c, d) = setup.coefficients(p);
    let config = EccTopInputs {
        core: CoreInputs {
            cfg_z_mode: 1,
            ..Default::default()
        },
        ecc_c: c,
        ecc_d: d,
        ident_arm: false,
    };
    let mut model = ArmedModel::new(p, Some(0));
    let mut log = ModelLog {
        strobes: Vec::new(),
        ident: Vec::new(),
        first_index: u64::MAX,
    };
    let mut was_done = false;
    for (k, i) in disc_inputs(stim.initial, &stim.changes, stim.cycles, config).enumerate() {
        let k = k as u64;
        let (_, o) = model.step(i);
        if o.core.index {
            log.first_index = log.first_index.min(k);
        }
        if o.ident.done && !was_done {
            log.ident.push((k, o.ident));
        }
        was_done = o.ident.done;
        log.strobes.extend(EccStrobe::of(k, &o));
    }
    log
}

/// The shipped `generated/encspeed_ecc.v` (default parameters `p`), compiled.
fn shipped(p: &Params) -> EccVerilated {
    let shipped = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/encspeed_ecc.v"),
    )
    .expect("generated/encspeed_ecc.v");
    EccVerilated::build(&shipped, p.speed_bits()).unwrap()
}

/// The rigid disc at e = 0.35/30, θ0 = 50°, at `rpm` for `revs` revolutions, on the shipped
/// `generated/encspeed_ecc.v` (the default parameters: 100 MHz, K = 1024, dt = 1 ms,
/// N = 24), the corrector loaded with the disc's own coefficients: every strobe and the
/// identification equal to the bit-true model's, the ripple of M/T and n3 before and after
/// correction within their budgets. The model runs on a thread of its own beside Verilator
/// (a revolution at 30 r/min is 2·10^8 cycles). Returns the Verilog's identification (armed
/// at the first index; none in runs of two revolutions or less).
fn corrected_ripple_on_verilog(rpm: f64, revs: f64) -> Option<Identification> {
    let p = Params::new(Spec::default()).unwrap();
    let sim = shipped(&p);
    let dir = tools::target_dir().join("ecc-ripple");
    std::fs::create_dir_all(&dir).unwrap();
    let e = 0.35 / 30.0;
    let setup = RippleSetup {
        rpm,
        revs,
        e,
        theta0: 50f64.to_radians(),
        loaded: None,
    };
    let (verilog, model) = std::thread::scope(|s| {
        let model = s.spawn(|| {
            let stim = setup.stimulus(&p).unwrap();
            model_log(&p, &setup, &stim)
        });
        (
            run_verilog(&sim, &p, &setup).unwrap(),
            model.join().unwrap(),
        )
    });
    let (log, stim) = verilog;
    let want = model;
    assert_eq!(log.strobes.len(), want.strobes.len(), "{rpm} rpm: strobes");
    for (g, w) in log.strobes.iter().zip(&want.strobes) {
        assert_eq!(g, w, "{rpm} rpm: Verilog and model differ");
    }
    assert_eq!(log.ident, want.ident, "{rpm} rpm: identification");
    // The estimates kept count from line 0: the index was processed by then.
    assert!(
        want.first_index <= stim.aligned_after,
        "{rpm} rpm: index at {}, after {}",
        want.first_index,
        stim.aligned_after
    );
    let ripple = Ripple::new(&p, setup, &log.strobes, stim.aligned_after);
    println!("{}", ripple.summary());
    // The identification armed at the first index: one revolution gathered in the runs of
    // more than two, e and θ0 within their budget.
    let id = Identification::of(&p, &setup, &log);
    match id {
        Some(id) => {
            println!("{}", id.summary());
            assert_eq!(
                check_revolution(&id.gathered, p.lines(), 1e8 * 60.0 / rpm),
                Ok(())
            );
            assert_eq!(id.within_budget(), Ok(()), "{rpm} rpm");
        }
        None => assert!(
            revs < 2.1,
            "{rpm} rpm: no identification in {revs} revolutions"
        ),
    }
    std::fs::write(dir.join(format!("rpm{rpm}.csv")), ripple.csv()).unwrap();
    draw_svg(
        &dir.join(format!("rpm{rpm}.svg")),
        &format!("encspeed_ecc.v in Verilator, {rpm} r/min"),
        &ripple,
    )
    .unwrap();
    let b = figures(&ripple.mt_before);
    assert!(
        b.h1_ppm > 0.9 * e * 1e6,
        "{rpm} rpm: 1/rev before {}",
        b.h1_ppm
    );
    assert_mt_corrected(rpm, &ripple, 0.0);
    // n3 against Rairán's bound for the hardware (eq. 13 with the clock's quantisation) at
    // each estimate's n1. Corrected, n3 is within its bound at every speed. Below
    // r = 1/(2e) (43 lines per dt here) n3's dead zone hides the eccentricity (no dither:
    // p-p 0) and the correction puts the true ripple back, inside the bound; above it the
    // eccentricity breaks the bound, the correction restores it and the 1/rev ripple falls
    // to n3's quantisation (docs/eccentricity-hardware.md).
    let (worst_b, worst_a) = (
        Ripple::worst_over_bound(&ripple.n3_before),
        Ripple::worst_over_bound(&ripple.n3_after),
    );
    let (fb, fa) = (
        figures(&Ripple::errors(&ripple.n3_before)),
        figures(&Ripple::errors(&ripple.n3_after)),
    );
    assert!(
        worst_a <= 1.0,
        "{rpm} rpm: corrected n3 beyond its bound: {worst_a}"
    );
    if ripple.r < 0.5 / e {
        assert_eq!(fb.pp_ppm, 0.0, "{rpm} rpm: n3 dithers in its dead zone");
        assert!(worst_b <= 1.0);
    } else {
        assert!(
            worst_b > 1.0,
            "{rpm} rpm: the eccentricity should break eq. (13)"
        );
        assert!(
            fb.h1_ppm / fa.h1_ppm > 20.0,
            "{rpm} rpm: n3 1/rev {} -> {}",
            fb.h1_ppm,
            fa.h1_ppm
        );
    }
    id
}

/// The IP's whole loop on the shipped Verilog, after [`corrected_ripple_on_verilog`] at
/// `rpm` gave the identification `id` (one revolution gathered, armed at the first index;
/// the same as `identify_on_verilog`'s run of 2.1 revolutions, whose stimulus is the first
/// part of this one's): e and θ0 follow from the sums, the corrector is loaded with them,
/// and the once-per-revolution ripple of M/T falls more than 1000× as with the disc's true
/// coefficients, every estimate within its budget plus the ripple the identification's
/// error leaves (|Δe| + e·|Δθ0| of the speed).
fn identified_then_corrected_on_verilog(rpm: f64, revs: f64, id: Identification) {
    let p = Params::new(Spec::default()).unwrap();
    let sim = shipped(&p);
    let e = 0.35 / 30.0;
    // The goal, by a wide margin: e within 1 %, θ0 within 1°.
    assert!(id.e_error.abs() < 0.01 * e && id.theta0_error.abs() < 1f64.to_radians());
    let setup = RippleSetup {
        rpm,
        revs,
        e,
        theta0: 50f64.to_radians(),
        loaded: Some((id.identified.e, id.identified.theta0)),
    };
    let (log, stim): (EventLog, _) = run_verilog(&sim, &p, &setup).unwrap();
    let ripple = Ripple::new(&p, setup, &log.strobes, stim.aligned_after);
    println!(
        "{rpm} r/min, corrected with the identified e and theta0:\n{}",
        ripple.summary()
    );
    let left = (id.e_error.abs() + e * id.theta0_error.abs()) * 1e6;
    assert_mt_corrected(rpm, &ripple, left);
}

/// Corrected M/T: every estimate within its budget plus `left` ppm, and the
/// once-per-revolution ripple down more than 1000×.
fn assert_mt_corrected(rpm: f64, ripple: &Ripple, left: f64) {
    let (b, a) = (figures(&ripple.mt_before), figures(&ripple.mt_after));
    assert!(
        a.worst_ppm <= ripple.mt_budget_ppm + left,
        "{rpm} rpm: worst {} ppm, budget {} + {left}",
        a.worst_ppm,
        ripple.mt_budget_ppm
    );
    assert!(
        b.h1_ppm / a.h1_ppm > 1000.0,
        "{rpm} rpm: ratio {}",
        b.h1_ppm / a.h1_ppm
    );
}

/// 30 r/min, one revolution (0.512 lines per dt: most windows see no edge).
#[test]
fn corrected_ripple_on_verilog_30_rpm() {
    assert!(corrected_ripple_on_verilog(30.0, 1.0).is_none());
}

/// 600 r/min, three revolutions, then the whole loop.
#[test]
fn corrected_ripple_then_whole_loop_on_verilog_600_rpm() {
    let id = corrected_ripple_on_verilog(600.0, 3.0).expect("identification at 600 r/min");
    identified_then_corrected_on_verilog(600.0, 3.0, id);
}

/// 6000 r/min, twenty revolutions, then the whole loop.
#[test]
fn corrected_ripple_then_whole_loop_on_verilog_6000_rpm() {
    let id = corrected_ripple_on_verilog(6000.0, 20.0).expect("identification at 6000 r/min");
    identified_then_corrected_on_verilog(6000.0, 20.0, id);
}
