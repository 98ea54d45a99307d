// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::ecc::ident_gatherer`.

use crate::support::verilator_lint;
use hdl::ecc::ident_gatherer::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises() {
    let mut uut = IdentGatherer::<10, 32, 66>::new(1024);
    uut.connect_all();
    yosys_validate("encspeed_ident_gatherer", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint(
        "ident_gatherer",
        &ident_gatherer_verilog::<10, 32, 66>(1024, "ident_gatherer"),
    );
    verilator_lint(
        "ident_gatherer",
        &ident_gatherer_verilog::<2, 8, 34>(4, "ident_gatherer"),
    );
}
