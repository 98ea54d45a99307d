// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::ecc::ecc_n3`.

use crate::support::verilator_lint;
use hdl::ecc::ecc_n3::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises_and_lints() {
    let mut uut = EccN3::<41>::default();
    uut.connect_all();
    yosys_validate("encspeed_ecc_n3", &generate_verilog(&uut)).unwrap();
    verilator_lint("ecc_n3", &ecc_n3_verilog::<41>("ecc_n3"));
}
