// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::baselines::et_timer`.

use crate::support::verilator_lint;
use hdl::baselines::et_timer::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises() {
    let mut uut = EtTimer::<24>::default();
    uut.connect_all();
    yosys_validate("encspeed_et_timer", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint("et_timer", &et_timer_verilog::<24>("et_timer"));
    verilator_lint("et_timer", &et_timer_verilog::<2>("et_timer"));
}
