// SPDX-License-Identifier: MIT OR Apache-2.0
//! Block benches of `hdl/src/ecc`: each block against its bit-true twin in
//! `golden/src/ecc`, every cycle, in rust-hdl and (its emitted Verilog) in Icarus. One module
//! per block, named like the block's file.

#[path = "../common/mod.rs"]
mod common;

mod ecc_delta;
mod ecc_mt_speed;
mod ecc_n3;
mod ident_gatherer;
mod mt_corrector;
mod n3_corrector;
mod sine_rom;
mod span_delta;
