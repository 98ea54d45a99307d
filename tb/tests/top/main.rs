// SPDX-License-Identifier: MIT OR Apache-2.0
//! Block benches of `hdl/src/top` that need rust-hdl alone: a top against its bit-true model
//! in `golden/src/top`, cycle for cycle. (The tops' co-simulations in Verilator, their
//! shipped files and firmware benches are the system benches `tb/tests/*.rs`.) One module per
//! top, named like the top's file.

#[path = "../common/mod.rs"]
mod common;

mod ecc_top;
