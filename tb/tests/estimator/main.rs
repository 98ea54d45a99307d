// SPDX-License-Identifier: MIT OR Apache-2.0
//! Block benches of `hdl/src/estimator`: each block against its bit-true twin (`golden/src/estimator`,
//! or the rule of `golden::top::core` it is modelled by), every cycle, in rust-hdl and (its
//! emitted Verilog) in Icarus. One module per block, named like the block's file.

#[path = "../common/mod.rs"]
mod common;

mod speed_calc;
