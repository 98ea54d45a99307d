//! n3's frequency response measured on the emitted Verilog in Verilator: the same
//! per-cycle inputs as the bit-true measurement give the same outputs on every cycle, and
//! therefore exactly the same gain and phase. Also the Bode figure writer.
//!
//! One core configuration for all cases (500 lines, 1 MHz clock, dt = T_s = 1 ms), so that
//! Verilator compiles once: r = 30 pulses per dt at 3600 r/min and r = 1/12 at 10 r/min.

use golden::freqresp::{BodeSpec, Estimator, Experiment};
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

#[test]
fn n3_on_the_emitted_verilog_equals_the_bit_true_measurement() {
    // High speed (r = 30, 20 % modulation, 6 counts of Nep1) at three frequencies up to
    // f_s/4, and low speed (r = 1/12, pulse period 12 dt) at two; at low speed ε = 10⁻²
    // makes one slip of the encoder phase 1200 samples instead of 8485.
    let cases = [
        (n3(3600.0, 1.414e-3), [25.0, 100.0, 250.0].as_slice()),
        (n3(10.0, 1e-2), &[5.0, 30.0]),
    ];
    let sim = verilated_for(&cases[0].0).expect("verilator builds the emitted core");
    for (exp, freqs) in &cases {
        // One configuration: the same Verilog serves both speeds.
        assert_eq!(exp.core_params(), cases[0].0.core_params());
        for &f in *freqs {
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
    let dir = tb::target_dir().join("freqresp-test");
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
