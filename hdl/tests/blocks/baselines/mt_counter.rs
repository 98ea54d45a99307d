// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::baselines::mt_counter`.

use crate::support::verilator_lint;
use hdl::baselines::mt_counter::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises() {
    let mut uut = MtCounter::<24>::default();
    uut.connect_all();
    yosys_validate("encspeed_mt_counter", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint("mt_counter", &mt_counter_verilog::<24>("mt_counter"));
    verilator_lint("mt_counter", &mt_counter_verilog::<2>("mt_counter"));
}
