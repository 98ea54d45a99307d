// SPDX-License-Identifier: MIT OR Apache-2.0
//! The frequency response of n3 and of the hardware PC, ET and M/T measured on the
//! emitted Verilog in Verilator: the same per-cycle inputs as the bit-true measurement
//! give the same outputs on every cycle, and therefore exactly the same gain and phase.
//! Also the Bode figure writer.
//!
//! n3: one core configuration for all cases (500 lines, 1 MHz clock, dt = T_s = 1 ms), so
//! that Verilator compiles once: r = 30 pulses per dt at 3600 r/min and r = 1/12 at
//! 10 r/min. PC, ET, M/T: one configuration too (125 lines x4, 1 MHz, dt = T_s = 1 ms,
//! 3600 r/min: 30 transitions per T_s, the paper's Figs. 8 and 10).

use golden::freqresp::{BodeSpec, Estimator, Experiment};
use std::f64::consts::PI;
use tb::freqresp::{draw_svg, measure_on_verilog, verilated_for, BodeFigure};

fn n3(rpm: f64, detune: f64) -> Experiment {
    Experiment::new(BodeSpec {
        clock_hz: 1e6,
        min_samples: 1000,
        detune,
        ..BodeSpec::new(Estimator::N3, 500, rpm, 1e-3)
    })
    .expect("valid n3 experiment")
}

/// n3 of `exp` at the modulation frequencies `freqs` on the emitted core (one configuration
/// for both speeds: the same Verilog serves them, compiled once): every cycle equal to the
/// bit-true measurement, the phase within 2° of the model.
fn n3_on_the_emitted_verilog_equals_the_bit_true_measurement(exp: &Experiment, freqs: &[f64]) {
    assert_eq!(exp.core_params(), n3_high_speed().core_params());
    let sim = verilated_for(exp).expect("verilator builds the emitted core");
    for &f in freqs {
        let hw = measure_on_verilog(exp, &sim, f).expect("Verilator = golden on every cycle");
        let golden = exp.measure(f).unwrap();
        assert_eq!(hw, golden, "{f} Hz");
        assert!(
            hw.phase_error_deg().abs() < 2.0,
            "{} r/min, {f} Hz: {hw:?}",
            exp.spec().rpm
        );
    }
}

/// High speed: r = 30, 20 % modulation, 6 counts of Nep1.
fn n3_high_speed() -> Experiment {
    n3(3600.0, 1.414e-3)
}

// The two speeds are two tests, so that they run side by side.

/// High speed at three frequencies up to f_s/4.
#[test]
fn n3_on_the_emitted_verilog_at_high_speed() {
    n3_on_the_emitted_verilog_equals_the_bit_true_measurement(
        &n3_high_speed(),
        &[25.0, 100.0, 250.0],
    );
}

/// Low speed (r = 1/12, pulse period 12 dt) at two frequencies: ε = 10⁻² makes one slip of
/// the encoder phase 1200 samples instead of 8485.
#[test]
fn n3_on_the_emitted_verilog_at_low_speed() {
    n3_on_the_emitted_verilog_equals_the_bit_true_measurement(&n3(10.0, 1e-2), &[5.0, 30.0]);
}

#[test]
fn hardware_pc_et_mt_on_the_emitted_verilog_equal_the_bit_true_measurement() {
    // speed_pc, speed_et, speed_mt read at baseline_strobe, x4 (cfg_mode = 2), against the
    // paper's models delayed by the hardware latency, within the 2°. A window of
    // 1000 samples (10⁶ cycles) keeps the co-simulation short; the count and period
    // quantisation noise, which does not grow with ñ, is kept small against the signal
    // with ñ = 10 % (PC, ET and M/T are linear in expectation at any depth).
    let hw = |est| {
        Experiment::new(BodeSpec {
            clock_hz: 1e6,
            amplitude: 0.1,
            min_samples: 1000,
            ..BodeSpec::hardware(est, 125, 3600.0, 1e-3)
        })
        .expect("valid hardware experiment")
    };
    let cases = [
        (hw(Estimator::Pc), 250.0),
        (hw(Estimator::Et), 100.0),
        (hw(Estimator::Mt), 250.0),
    ];
    assert_eq!(cases[0].0.cfg_mode(), 2);
    let sim = verilated_for(&cases[0].0).expect("verilator builds the emitted core");
    for (exp, f) in &cases {
        // One configuration: the same Verilog serves all three.
        assert_eq!(exp.core_params(), cases[0].0.core_params());
        let hw = measure_on_verilog(exp, &sim, *f).expect("Verilator = golden on every cycle");
        assert_eq!(
            hw,
            exp.measure(*f).unwrap(),
            "{} {f} Hz",
            exp.spec().estimator
        );
        assert!(
            hw.phase_error_deg().abs() < 2.0 && hw.gain_error_db().abs() < 0.25,
            "{} {f} Hz: {hw:?}",
            exp.spec().estimator
        );
        // The latency is in the measurement: about 69 µs, 6° at 250 Hz.
        let d = exp.hardware_latency_cycles().unwrap() as f64 * 1e-6;
        let h_without =
            hw.h * golden::smallsignal::Complex64::from_polar(1.0, 2.0 * PI * hw.f_hz * d);
        let paper = exp.comparison_models()[0].at(hw.f_hz);
        let err =
            (h_without.arg().to_degrees() - paper.phase_deg + 180.0).rem_euclid(360.0) - 180.0;
        assert!(err.abs() < 2.0, "{} {f} Hz: {err}", exp.spec().estimator);
    }
}

#[test]
fn core_inputs_are_those_of_the_plant_stimulus() {
    // The experiment's streaming inputs are tb::stimulus::from_profile's, cycle for cycle.
    let exp = n3(3600.0, 1.414e-3);
    let plan = exp.plan(100.0).unwrap();
    let p = exp.core_params().unwrap();
    let ours = exp.core_inputs(&plan);
    let theirs = tb::stimulus::from_profile(p, &plan.profile, p.dt_cycles()).unwrap();
    assert!(theirs.len() >= ours.len());
    assert_eq!(ours, theirs[..ours.len()]);
    assert_eq!(ours.len() as u64, exp.core_cycles(&plan));
}

#[test]
fn bode_figures_are_deterministic_svg() {
    let exp = Experiment::new(BodeSpec::new(Estimator::Et, 125, 3600.0, 1e-4)).unwrap();
    let sweep = exp.sweep(&[100.0, 1000.0, 2500.0]).unwrap();
    let others = exp.comparison_models();
    let fig = BodeFigure {
        title: "ET test".into(),
        model: exp.model(),
        others: &others,
        measured: &sweep,
        fmin_hz: 50.0,
        fmax_hz: 4000.0,
    };
    let dir = tools::target_dir().join("freqresp-test");
    let (a, b) = (dir.join("a.svg"), dir.join("b.svg"));
    draw_svg(&a, &fig).unwrap();
    draw_svg(&b, &fig).unwrap();
    let text = std::fs::read_to_string(&a).unwrap();
    assert_eq!(text, std::fs::read_to_string(&b).unwrap());
    assert!(text.starts_with("<svg") && text.trim_end().ends_with("</svg>"));
    // Three markers per panel, one legend marker; the legend names every model.
    assert_eq!(text.matches("<circle").count(), 2 * 3 + 1);
    for m in std::iter::once(exp.model()).chain(&others) {
        assert!(text.contains(&m.name()), "{}", m.name());
    }
    let bad = BodeFigure {
        fmin_hz: 10.0,
        fmax_hz: 10.0,
        ..fig
    };
    assert!(draw_svg(&a, &bad).is_err());
}
