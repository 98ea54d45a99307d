// SPDX-License-Identifier: MIT OR Apache-2.0
//! Block benches of `hdl/src/arith`: each block against its bit-true twin in
//! `golden/src/arith`, every cycle, in rust-hdl and (its emitted Verilog) in Icarus. One
//! module per block, named like the block's file.

#[path = "../common/mod.rs"]
mod common;

mod seq_divider;
mod two_cycle_adder;
