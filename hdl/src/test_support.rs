// SPDX-License-Identifier: MIT OR Apache-2.0
//! Helpers for the blocks' unit tests.

/// `verilator --lint-only -Wall` on `verilog` (top module `top`) by [`tools::lint_verilog`]
/// (under `target/block_lint/`; DECLFILENAME waived, as rust-hdl names sub-modules by path);
/// panics on any other warning.
pub(crate) fn verilator_lint(top: &str, verilog: &str) {
    if let Err(e) = tools::lint_verilog(top, verilog) {
        panic!("{e}");
    }
}
