//! Property tests: on random stimuli, the rust-hdl simulation and the emitted Verilog (in
//! Verilator) equal the bit-true golden model on every cycle.
//!
//! Two families of stimuli:
//! - adversarial waveforms: random levels on A/B/Z held for 1 cycle (glitches, the fastest
//!   pulse train the edge detector passes) up to thousands of cycles (long enough for the
//!   8-bit Cdt to saturate), resets at random points, `cfg_dt` changed at run time
//!   (including the illegal 0 and 1, and values below the current ts count);
//! - shaft motions from the plant (constant, ramps through zero, sine, rests) at random
//!   speeds, dt and phases, sampled at the clock.

use golden::bittrue::CoreInputs;
use golden::params::{Params, Spec};
use proptest::prelude::*;
use std::sync::OnceLock;
use tb::cosim::{assert_same, run_golden, run_hdl};
use tb::scenarios::{profile, Seg};
use tb::verilator::Verilated;

/// 8-bit counters, timeout 20 dt at the nominal dt = 10: saturation and timeout within a
/// few thousand cycles.
fn params8() -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: 10,
        counter_bits: 8,
        timeout_s: 20.0 * 10.0 / 1e6,
    })
    .unwrap()
}

/// 16-bit counters for plant-driven runs (dt up to 400 cycles).
fn params16() -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: 100,
        counter_bits: 16,
        timeout_s: 40.0 * 100.0 / 1e6,
    })
    .unwrap()
}

fn verilated(which: &'static OnceLock<Verilated>, p: &Params) -> &'static Verilated {
    which.get_or_init(|| Verilated::build(&hdl::emit_core(p).verilog).expect("verilator build"))
}

static V8: OnceLock<Verilated> = OnceLock::new();
static V16: OnceLock<Verilated> = OnceLock::new();

/// Run one stimulus through all three layers and compare.
fn check_all_layers(p: &Params, v: &Verilated, inputs: &[CoreInputs]) {
    let golden = run_golden(p, inputs);
    assert_same("rust-hdl", inputs, &golden, &run_hdl(p, inputs));
    assert_same(
        "verilator",
        inputs,
        &golden,
        &v.run(inputs, None).expect("verilator run"),
    );
}

#[derive(Clone, Debug)]
enum Chunk {
    /// Hold these levels for `cycles`.
    Levels {
        a: bool,
        b: bool,
        z: bool,
        cycles: u16,
    },
    /// Assert reset for `cycles`.
    Reset { cycles: u8 },
    /// Change cfg_dt.
    Dt(u64),
}

fn chunk() -> impl Strategy<Value = Chunk> {
    prop_oneof![
        // Short runs: glitches and maximum-rate pulse trains.
        12 => (any::<bool>(), any::<bool>(), any::<bool>(), 1u16..4)
            .prop_map(|(a, b, z, cycles)| Chunk::Levels { a, b, z, cycles }),
        // Ordinary pulse widths.
        8 => (any::<bool>(), any::<bool>(), any::<bool>(), 4u16..80)
            .prop_map(|(a, b, z, cycles)| Chunk::Levels { a, b, z, cycles }),
        // Long stops: Cdt climbs to the timeout and to saturation.
        1 => (any::<bool>(), 500u16..3000)
            .prop_map(|(a, cycles)| Chunk::Levels { a, b: a, z: false, cycles }),
        1 => (1u8..5).prop_map(|cycles| Chunk::Reset { cycles }),
        2 => prop_oneof![0u64..2, 2u64..40, 40u64..256].prop_map(Chunk::Dt),
    ]
}

fn expand(start_dt: u64, chunks: &[Chunk]) -> Vec<CoreInputs> {
    let mut out = vec![];
    let mut dt = start_dt;
    let mut last = CoreInputs {
        reset: true,
        cfg_dt: dt,
        ..Default::default()
    };
    // Always begin from reset, as a user would.
    out.extend(std::iter::repeat_n(last, 3));
    last.reset = false;
    for c in chunks {
        match *c {
            Chunk::Levels { a, b, z, cycles } => {
                last = CoreInputs {
                    reset: false,
                    enc_a: a,
                    enc_b: b,
                    enc_z: z,
                    cfg_dt: dt,
                };
                out.extend(std::iter::repeat_n(last, cycles as usize));
            }
            Chunk::Reset { cycles } => {
                out.extend(std::iter::repeat_n(
                    CoreInputs {
                        reset: true,
                        ..last
                    },
                    cycles as usize,
                ));
            }
            Chunk::Dt(d) => {
                dt = d;
                last.cfg_dt = d;
            }
        }
    }
    out
}

fn motion_segment() -> impl Strategy<Value = Seg> {
    prop_oneof![
        (-12.0f64..12.0, 0.5f64..6.0).prop_map(|(r, n)| Seg::Hold(r, n)),
        (-6.0f64..6.0, -6.0f64..6.0, 1.0f64..8.0).prop_map(|(a, b, n)| Seg::Ramp(a, b, n)),
        (-4.0f64..4.0, 0.0f64..5.0, 1.0f64..10.0, 1.0f64..8.0)
            .prop_map(|(m, a, per, n)| Seg::Sine(m, a, per, n)),
        (0.5f64..4.0).prop_map(Seg::Rest),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    #[test]
    fn adversarial_waveforms_are_bit_exact(start_dt in 0u64..60, chunks in prop::collection::vec(chunk(), 1..120)) {
        let p = params8();
        let inputs = expand(start_dt, &chunks);
        check_all_layers(&p, verilated(&V8, &p), &inputs);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn plant_motions_are_bit_exact(
        cfg_dt in 2u64..400,
        phase in 0.0f64..1.0,
        segments in prop::collection::vec(motion_segment(), 1..5),
    ) {
        let p = params16();
        // Speeds and durations are in units of the cfg_dt being driven.
        let at_dt = Params::new(Spec { dt_cycles: cfg_dt, ..p.spec().clone() }).unwrap();
        let prof = profile(&segments, &at_dt).unwrap().with_initial_angle(phase).unwrap();
        let inputs = tb::stimulus::from_profile(&p, &prof, cfg_dt).unwrap();
        check_all_layers(&p, verilated(&V16, &p), &inputs);
    }
}

static V_SHIPPED: OnceLock<Verilated> = OnceLock::new();

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// The file that ships (default parameters, 24-bit counters) on the same adversarial
    /// waveforms.
    #[test]
    fn shipped_verilog_on_adversarial_waveforms(start_dt in 0u64..60, chunks in prop::collection::vec(chunk(), 1..120)) {
        let p = Params::new(Spec::default()).unwrap();
        let v = V_SHIPPED.get_or_init(|| {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/encspeed_core.v");
            Verilated::build(&std::fs::read_to_string(path).unwrap()).unwrap()
        });
        let inputs = expand(start_dt, &chunks);
        let golden = run_golden(&p, &inputs);
        assert_same("verilator (shipped)", &inputs, &golden, &v.run(&inputs, None).unwrap());
    }
}
