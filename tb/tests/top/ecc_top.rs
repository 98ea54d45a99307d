// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_ecc` (corrected M/T and n3) in rust-hdl against its bit-true model (`golden::top::ecc_top`), cycle for
//! cycle, on an eccentric disc driven forward, backward and through reversals, in x1, x2
//! and x4, with random coefficients and dt short enough that windows queue in the
//! corrector (the latest wins), with the identification armed at a random cycle after the
//! first index or early, before it (the top holds the arm until the aligning index): on a
//! forward run long enough for the armed revolution, the gathered count is K and Σ T the
//! revolution's length in cycles to ±1 (worked from the speed, not by the code).

use crate::common;
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::ideal::plant::Profile;
use golden::params::{Params, Spec};
use golden::top::core::CoreInputs;
use golden::top::ecc_top::{check_revolution, disc_inputs, ArmedModel, EccTopInputs};
use hdl::sim::ecc_sim::build_ecc;
use proptest::prelude::*;
use std::f64::consts::TAU;

const CLOCK: f64 = 1e6;

fn params(lines: u32) -> Params {
    Params::new(Spec {
        clock_hz: CLOCK,
        lines,
        dt_cycles: 200,
        counter_bits: 12,
        timeout_s: 0.05,
        ..Spec::default()
    })
    .unwrap()
}

/// One random case of [`equals_golden`] (the direction is the test's).
#[derive(Clone, Debug)]
struct Case {
    lines: u32,
    e: f64,
    theta0: f64,
    lines_per_ms: f64,
    mode: u8,
    cfg_dt: u64,
    coef: (i64, i64),
    realistic: bool,
    arm_delay: u64,
    early_arm: Option<u64>,
}

fn cases() -> impl Strategy<Value = Case> {
    (
        prop::sample::select(vec![8u32, 16, 20, 64]),
        0.0f64..0.2,
        0.0f64..TAU,
        2.0f64..40.0,
        0u8..3,
        prop::sample::select(vec![0u64, 90, 400, 3000]),
        (-(1i64 << 31)..(1i64 << 31), -(1i64 << 31)..(1i64 << 31)),
        any::<bool>(),
        0u64..3_000,
        // An early arm from edge 4: `disc_inputs` holds reset for edges 0..=2, and the
        // registered reset (reset_to_effect = 1) clears the top at edges 1..=3, an arm
        // sampled at edge 3 with it.
        prop::option::of(4u64..200),
    )
        .prop_map(
            |(
                lines,
                e,
                theta0,
                lines_per_ms,
                mode,
                cfg_dt,
                coef,
                realistic,
                arm_delay,
                early_arm,
            )| {
                Case {
                    lines,
                    e,
                    theta0,
                    lines_per_ms,
                    mode,
                    cfg_dt,
                    coef,
                    realistic,
                    arm_delay,
                    early_arm,
                }
            },
        )
}

// Two tests of four cases, one per direction, so that libtest runs them side by side (one
// test of eight left a core idle for its two minutes).
proptest! {
    #![proptest_config(common::proptest_config(4))]
    #[test]
    fn rust_hdl_equals_golden_forward(case in cases()) {
        equals_golden(case, false)?;
    }

    #[test]
    fn rust_hdl_equals_golden_through_a_reversal(case in cases()) {
        equals_golden(case, true)?;
    }
}

/// The case on a disc driven forward, or through a reversal (`reverse`), every cycle of
/// rust-hdl equal to the bit-true model's.
fn equals_golden(case: Case, reverse: bool) -> Result<(), TestCaseError> {
    let Case {
        lines,
        e,
        theta0,
        lines_per_ms,
        mode,
        cfg_dt,
        coef,
        realistic,
        arm_delay,
        early_arm,
    } = case;
    let p = params(lines);
    let disc =
        EccentricDisc::new(lines, Eccentricity::new(Model::Rigid, e, theta0).unwrap()).unwrap();
    let rps = lines_per_ms * 1000.0 / f64::from(lines);
    let cycles = 24_000u64;
    let duration = cycles as f64 / CLOCK;
    let profile = if reverse {
        Profile::reversal(rps, duration).unwrap()
    } else {
        Profile::constant(rps, duration).unwrap()
    };
    let (initial, changes) = disc.clock_changes(&profile, CLOCK);
    let (c, d) = if realistic {
        golden::ecc::ecc_delta::coefficients(lines, e, theta0)
    } else {
        coef
    };
    let config = EccTopInputs {
        core: CoreInputs {
            cfg_dt,
            cfg_mode: mode,
            cfg_z_mode: 1,
            ..Default::default()
        },
        ecc_c: c,
        ecc_d: d,
        ident_arm: false,
    };
    // Armed early (before the aligning index, which the top waits for) or after the first
    // index.
    let mut model = ArmedModel::new(&p, early_arm.is_none().then_some(arm_delay));
    let early = |k: usize, mut i: EccTopInputs| {
        i.ident_arm = early_arm == Some(k as u64);
        i
    };
    let mut sim = build_ecc(&p).unwrap();
    let (mut strobes, mut n3_strobes) = (0, 0);
    let mut ident = Default::default();
    for (k, i) in disc_inputs(initial, &changes, cycles, config).enumerate() {
        let (i, want) = model.step(early(k, i));
        let got = sim.step(&i);
        prop_assert_eq!(got, want, "cycle {}", k);
        ident = want.ident;
        strobes += usize::from(want.mtc_strobe);
        n3_strobes += usize::from(want.n3c_strobe);
    }
    prop_assert!(
        strobes > 0 && n3_strobes > 0,
        "no corrected speed in {} cycles",
        cycles
    );
    // The armed revolution: from the first index after the arm (after the aligning one
    // for an early arm) to the next one, within two (three) revolutions of the arm.
    let rev_cycles = CLOCK / rps;
    let armed_at = early_arm.or(model.arm_at());
    let armed_for = armed_at.map_or(0.0, |a| (cycles - a) as f64);
    let revs_needed = if early_arm.is_some() { 3.0 } else { 2.0 };
    if !reverse && armed_for > revs_needed * rev_cycles + 100.0 {
        prop_assert_eq!(check_revolution(&ident, lines, rev_cycles), Ok(()));
    }
    Ok(())
}
