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

/// Clean under `encspeed_wb`'s shipped waivers, of which one concerns the file itself: bits
/// 7:4 of `CTRL` are reserved, so the `CTRL` cell's word has four bits nobody reads.
#[test]
fn verilator_lint_is_clean() {
    let waivers = hdl::emit::waivers::waivers(hdl::emit::tops::Top::Wb);
    let lint = |name: &str, v: String| {
        let dir = tools::work_dir("block_lint", &format!("wb_regs_{name}")).unwrap();
        tools::stage(
            &dir,
            &[("encspeed_wb.vlt", &waivers), ("encspeed_wb.v", &v)],
        )
        .unwrap();
        tools::verilator_lint(&dir, "encspeed_wb", &["encspeed_wb.vlt", "encspeed_wb.v"])
            .unwrap_or_else(|e| panic!("{name}: {e}"));
    };
    lint(
        "default",
        wb_regs_verilog::<24, 41, 32, 16, 16>(&map(24, 16, 32, 16, 16), "encspeed_wb"),
    );
    lint(
        "small",
        wb_regs_verilog::<8, 11, 4, 1, 1>(&map(8, 2, 4, 1, 1), "encspeed_wb"),
    );
    lint(
        "widest",
        wb_regs_verilog::<32, 57, 32, 32, 32>(&map(32, 24, 32, 32, 32), "encspeed_wb"),
    );
}

#[test]
fn new_refuses_widths_other_than_the_parameters() {
    let p = Params::new(golden::params::Spec::default()).unwrap();
    let r = std::panic::catch_unwind(|| WbRegs::<8, 11, 4, 1, 1>::new(&p));
    assert!(r.is_err());
}
