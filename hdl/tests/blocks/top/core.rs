// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::top::core`.

use golden::params::Params;
use hdl::top::core::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises() {
    let p = Params::new(golden::params::Spec {
        counter_bits: 12,
        dt_cycles: 1000,
        timeout_s: 1e-3,
        ..Default::default()
    })
    .unwrap();
    let mut uut = EncspeedCore::<12, 25, 29>::new(&p);
    uut.connect_all();
    yosys_validate("encspeed_core", &generate_verilog(&uut)).unwrap();
}
