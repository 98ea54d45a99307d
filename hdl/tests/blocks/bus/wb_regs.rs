// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::wb_regs`.

use golden::bus::regmap::MapParams;
use golden::bus::regmap::RegMap;
use golden::params::Params;
use hdl::bus::wb_regs::*;
use rust_hdl::prelude::*;

fn map(n: u32, f: u32, c: u32, fb: u32, g: u32) -> RegMap {
    RegMap::from_map_params(MapParams::for_widths(n, f, c, fb, g))
}

#[test]
fn synthesises() {
    let m = map(24, 16, 32, 16, 16);
    yosys_validate(
        "encspeed_wb_regs",
        &wb_regs_verilog::<24, 41, 32, 16, 16>(&m, "top"),
    )
    .unwrap();
    let m = map(8, 2, 4, 1, 1);
    yosys_validate(
        "encspeed_wb_regs_small",
        &wb_regs_verilog::<8, 11, 4, 1, 1>(&m, "top"),
    )
    .unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    let lint = |v: String| crate::support::verilator_lint("wb_regs", &v);
    lint(wb_regs_verilog::<24, 41, 32, 16, 16>(
        &map(24, 16, 32, 16, 16),
        "wb_regs",
    ));
    lint(wb_regs_verilog::<8, 11, 4, 1, 1>(
        &map(8, 2, 4, 1, 1),
        "wb_regs",
    ));
    lint(wb_regs_verilog::<32, 57, 32, 32, 32>(
        &map(32, 24, 32, 32, 32),
        "wb_regs",
    ));
}

#[test]
fn new_refuses_widths_other_than_the_parameters() {
    let p = Params::new(golden::params::Spec::default()).unwrap();
    let r = std::panic::catch_unwind(|| WbRegs::<8, 11, 4, 1, 1>::new(&p));
    assert!(r.is_err());
}
