// SPDX-License-Identifier: MIT OR Apache-2.0
//! Helpers for the blocks' unit tests.

/// `verilator --lint-only -Wall` on `verilog` (top module `top`) by [`tools::lint_verilog`]
/// (under `target/block_lint/`; DECLFILENAME waived, as rust-hdl names sub-modules by path);
/// panics on any other warning.
pub fn verilator_lint(top: &str, verilog: &str) {
    if let Err(e) = tools::lint_verilog(top, verilog) {
        panic!("{e}");
    }
}

/// `uut`, connected, emitted as module `top` of `name`, passes yosys and the Verilator lint.
pub fn synthesises_and_lints<B: rust_hdl::prelude::Block>(name: &str, mut uut: B) {
    uut.connect_all();
    let v = hdl::verilog::named_verilog(&uut, "top");
    rust_hdl::prelude::yosys_validate(name, &v).unwrap();
    verilator_lint("top", &v);
}

/// The default parameters' core register map and eccentricity window (S = 41).
pub fn maps() -> (
    golden::bus::regmap::RegMap,
    Vec<golden::bus::regmap::Register>,
) {
    let p = golden::params::Params::new(golden::params::Spec::default()).unwrap();
    (
        golden::bus::regmap::RegMap::new(&p),
        golden::bus::ecc_regmap::registers(41),
    )
}
