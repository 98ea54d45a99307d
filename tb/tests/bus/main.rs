// SPDX-License-Identifier: MIT OR Apache-2.0
//! Block benches of `hdl/src/bus`: each register file against its cycle model in
//! `golden/src/bus`, every cycle, in rust-hdl and (`WbRegs`' emitted Verilog) in Icarus. One
//! module per block, named like the block's file.

#[path = "../common/mod.rs"]
mod common;

mod ecc_regs;
mod wb_regs;
