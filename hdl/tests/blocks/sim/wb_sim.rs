// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::sim::wb_sim`.

use golden::params::Params;
use golden::params::Spec;
use hdl::sim::wb_sim::*;
use rust_hdl::prelude::*;

fn small() -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: 200,
        counter_bits: 12,
        timeout_s: 20.0 * 200.0 / 1e6,
        ..Spec::default()
    })
    .unwrap()
}

#[test]
fn synthesises() {
    let v = build_wb(&small()).verilog("top");
    yosys_validate("encspeed_wb", &v).unwrap();
}

/// `verilator --lint-only -Wall` on the emitted top with its shipped waivers
/// ([`hdl::Top::waivers`]): any other warning fails.
#[test]
fn verilator_lint_is_clean_with_the_documented_waivers() {
    let waivers = hdl::Top::Wb.waivers();
    for p in [small(), Params::new(Spec::default()).unwrap()] {
        let v = build_wb(&p).verilog("encspeed_wb");
        let dir =
            tools::work_dir("block_lint", &format!("encspeed_wb-{}", p.counter_bits())).unwrap();
        tools::stage(&dir, &[("encspeed_wb.v", &v), ("waivers.vlt", &waivers)]).unwrap();
        tools::verilator_lint(&dir, "encspeed_wb", &["waivers.vlt", "encspeed_wb.v"]).unwrap();
    }
}
