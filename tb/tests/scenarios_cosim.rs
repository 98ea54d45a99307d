// SPDX-License-Identifier: MIT OR Apache-2.0
//! Named scenarios through all three layers: the bit-true golden model, the rust-hdl
//! simulation and the emitted Verilog in Verilator must agree on every cycle.

use golden::params::{Params, Spec};
use tb::cosim::{assert_same, run_golden, run_hdl};
use tb::scenarios;
use tb::verilator::Verilated;

/// Small parameters so that every scenario is a few thousand cycles: dt = 200 cycles,
/// 16-bit counters, timeout 12 dt (the `stop` scenario rests for 20 dt and must stall).
fn test_params() -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: 200,
        counter_bits: 16,
        timeout_s: 12.0 * 200.0 / 1e6,
        ..Spec::default()
    })
    .unwrap()
}

#[test]
fn every_scenario_is_bit_exact_in_rust_hdl_and_verilator() {
    let p = test_params();
    let v = Verilated::build(&hdl::emit_core(&p).verilog).unwrap();
    for s in scenarios::all() {
        let inputs = s.inputs(&p).unwrap();
        let golden = run_golden(&p, &inputs);
        assert_same(
            &format!("{} rust-hdl", s.name),
            &inputs,
            &golden,
            &run_hdl(&p, &inputs),
        );
        let verilog = v.run(&inputs, None).unwrap();
        assert_same(&format!("{} verilator", s.name), &inputs, &golden, &verilog);
        let updates = golden.iter().filter(|o| o.update).count();
        assert!(
            updates > 3,
            "{}: only {updates} updates in {} cycles",
            s.name,
            inputs.len()
        );
        println!(
            "{}: {} cycles, {} updates, identical",
            s.name,
            inputs.len(),
            updates
        );
    }
}
