//! `encspeed_ecc` on the emitted Verilog in Verilator:
//! - cycle for cycle against its bit-true model (`golden::ecc_top`) on eccentric discs in
//!   x1/x2/x4, forward, backward and through reversals, random and realistic coefficients;
//! - the once-per-revolution ripple of M/T before (`speed_mt`) and after (`speed_mtc`)
//!   correction, on the shipped `generated/encspeed_ecc.v`, with the rigid disc at
//!   e = 0.35/30 (K = 1024, θ0 = 50°, 100 MHz, dt = 1 ms, x1) at 30, 600 and 6000 r/min,
//!   every strobe of the Verilog equal to the model's, and each corrected estimate within
//!   its quantisation budget ([`tb::ecc_ripple`]);
//! - the same for n3 (`speed_n3`, `speed_n3c`) against Rairán's bound for the hardware.
//!
//! Run with `--nocapture` for the figures of docs/eccentricity-hardware.md; the samples go
//! to target/ecc-ripple/ (CSV and SVG).

use golden::bittrue::CoreInputs;
use golden::ecc_delta::coefficients;
use golden::ecc_top::{disc_inputs, EccTopInputs, EccTopModel};
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::params::{Params, Spec};
use golden::plant::Profile;
use hdl::ecc_sim::build_ecc;
use proptest::prelude::*;
use std::f64::consts::TAU;
use tb::ecc_ripple::{draw_svg, figures, run_verilog, Ripple, RippleSetup};
use tb::ecc_verilator::{EccStrobe, EccVerilated};

fn small(lines: u32) -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines,
        dt_cycles: 200,
        counter_bits: 12,
        timeout_s: 0.05,
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
        };
        let inputs: Vec<EccTopInputs> = disc_inputs(initial, &changes, cycles, config).collect();
        let mut model = EccTopModel::new(&p);
        let got = verilated(&p).run(&inputs, None).unwrap();
        let (mut strobes, mut n3_strobes) = (0, 0);
        for (k, (i, g)) in inputs.iter().zip(&got).enumerate() {
            let want = model.step(*i);
            prop_assert_eq!(*g, want, "cycle {}", k);
            strobes += usize::from(want.mtc_strobe);
            n3_strobes += usize::from(want.n3c_strobe);
        }
        prop_assert!(strobes > 0 && n3_strobes > 0);
    }
}

/// The rigid disc at e = 0.35/30, θ0 = 50°, on the shipped `generated/encspeed_ecc.v`
/// (the default parameters: 100 MHz, K = 1024, dt = 1 ms, N = 24).
#[test]
fn corrected_ripple_on_verilog() {
    let p = Params::new(Spec::default()).unwrap();
    let shipped = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/encspeed_ecc.v"),
    )
    .expect("generated/encspeed_ecc.v");
    let sim = EccVerilated::build(&shipped, p.speed_bits()).unwrap();
    let dir = tb::target_dir().join("ecc-ripple");
    std::fs::create_dir_all(&dir).unwrap();
    for (rpm, revs) in [(30.0, 1.0), (600.0, 3.0), (6000.0, 20.0)] {
        let e = 0.35 / 30.0;
        let setup = RippleSetup {
            rpm,
            revs,
            e,
            theta0: 50f64.to_radians(),
        };
        let (got, stim) = run_verilog(&sim, &p, &setup).unwrap();
        // The model, cycle by cycle, the same strobes.
        let (c, d) = setup.coefficients(&p);
        let config = EccTopInputs {
            core: CoreInputs {
                cfg_z_mode: 1,
                ..Default::default()
            },
            ecc_c: c,
            ecc_d: d,
        };
        let mut model = EccTopModel::new(&p);
        let mut want = Vec::new();
        let mut first_index = None;
        for (k, i) in disc_inputs(stim.initial, &stim.changes, stim.cycles, config).enumerate() {
            let k = k as u64;
            let o = model.step(i);
            if o.core.index && first_index.is_none() {
                first_index = Some(k);
            }
            if o.core.baseline_strobe || o.mtc_strobe || o.core.speed_strobe || o.n3c_strobe {
                want.push(EccStrobe {
                    cycle: k,
                    speed_mt: o.core.baseline_strobe.then_some(o.core.speed_mt),
                    speed_mtc: o.mtc_strobe.then_some(o.speed_mtc),
                    speed_n3: o.core.speed_strobe.then_some(o.core.speed_n3),
                    speed_n3c: o.n3c_strobe.then_some(o.speed_n3c),
                    position: o.core.position,
                    speed_nep: o.core.speed_nep,
                    speed_ndt: o.core.speed_ndt,
                });
            }
        }
        assert_eq!(got.len(), want.len(), "{rpm} rpm: strobes");
        for (g, w) in got.iter().zip(&want) {
            assert_eq!(g, w, "{rpm} rpm: Verilog and model differ");
        }
        // The estimates kept count from line 0: the index was processed by then.
        assert!(
            first_index.expect("an index edge") <= stim.aligned_after,
            "{rpm} rpm: index at {first_index:?}, after {}",
            stim.aligned_after
        );
        let ripple = Ripple::new(&p, setup, &got, stim.aligned_after);
        println!("{}", ripple.summary());
        std::fs::write(dir.join(format!("rpm{rpm}.csv")), ripple.csv()).unwrap();
        draw_svg(
            &dir.join(format!("rpm{rpm}.svg")),
            &format!("encspeed_ecc.v in Verilator, {rpm} r/min"),
            &ripple,
        )
        .unwrap();
        let (b, a) = (figures(&ripple.mt_before), figures(&ripple.mt_after));
        assert!(
            b.h1_ppm > 0.9 * e * 1e6,
            "{rpm} rpm: 1/rev before {}",
            b.h1_ppm
        );
        assert!(
            a.worst_ppm <= ripple.mt_budget_ppm,
            "{rpm} rpm: worst {} ppm, budget {}",
            a.worst_ppm,
            ripple.mt_budget_ppm
        );
        assert!(
            b.h1_ppm / a.h1_ppm > 1000.0,
            "{rpm} rpm: ratio {}",
            b.h1_ppm / a.h1_ppm
        );
        // n3 against Rairán's bound for the hardware (eq. 13 with the clock's quantisation)
        // at each estimate's n1. Corrected, n3 is within its bound at every speed. Below
        // r = 1/(2e) (43 lines per dt here) n3's dead zone hides the eccentricity (no
        // dither: p-p 0) and the correction puts the true ripple back, inside the bound;
        // above it the eccentricity breaks the bound, the correction restores it and the
        // 1/rev ripple falls to n3's quantisation (docs/eccentricity-hardware.md).
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
    }
}
