// SPDX-License-Identifier: MIT OR Apache-2.0
//! Block benches of `hdl/src/board`, the UART-to-Wishbone bridge: the receiver and the
//! transmitter against the golden line model (`golden::board::uart`), and the whole bridge
//! against the golden protocol (`golden::board::protocol`) with a Wishbone slave model, in
//! rust-hdl and (its emitted Verilog) in Verilator, cycle for cycle. One module per block,
//! named like the block's file.

#[path = "../common/mod.rs"]
mod common;

mod uart_rx;
mod uart_tx;
mod uart_wishbone;
