// SPDX-License-Identifier: MIT OR Apache-2.0
//! Block benches of `hdl/src/baselines`: each block against its bit-true twin in
//! `golden/src/baselines`, every cycle, in rust-hdl and (its emitted Verilog) in Icarus. One
//! module per block, named like the block's file.

#[path = "../common/mod.rs"]
mod common;

mod baseline_speeds;
mod et_timer;
mod mt_counter;
mod pc_counter;
