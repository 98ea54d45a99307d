// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::ecc::ecc_delta`.

use crate::support::verilator_lint;
use hdl::ecc::ecc_delta::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises() {
    let mut uut = EccDelta::<10, 24>::new(1024);
    uut.connect_all();
    yosys_validate("encspeed_ecc_delta", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint("ecc_delta", &ecc_delta_verilog::<10, 24>(1024, "ecc_delta"));
    verilator_lint("ecc_delta", &ecc_delta_verilog::<10, 24>(1000, "ecc_delta"));
    verilator_lint("ecc_delta", &ecc_delta_verilog::<2, 8>(4, "ecc_delta"));
    verilator_lint("ecc_delta", &ecc_delta_verilog::<12, 16>(4096, "ecc_delta"));
}

#[test]
#[should_panic(expected = "multiple of 4")]
fn refuses_k_not_multiple_of_4() {
    let _ = EccDelta::<10, 24>::new(1022);
}
