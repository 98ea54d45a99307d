// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::baselines::window_timer`.

use crate::support::verilator_lint;
use hdl::baselines::window_timer::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises() {
    let mut uut = WindowTimer::<24>::default();
    uut.connect_all();
    yosys_validate("encspeed_window_timer", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint("window_timer", &window_timer_verilog::<24>("window_timer"));
    verilator_lint("window_timer", &window_timer_verilog::<2>("window_timer"));
}
