// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::baselines::pc_counter`.

use crate::support::verilator_lint;
use hdl::baselines::pc_counter::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises() {
    let mut uut = PcCounter::<24>::default();
    uut.connect_all();
    yosys_validate("encspeed_pc_counter", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint("pc_counter", &pc_counter_verilog::<24>("pc_counter"));
    verilator_lint("pc_counter", &pc_counter_verilog::<2>("pc_counter"));
}
