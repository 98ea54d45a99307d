// SPDX-License-Identifier: MIT OR Apache-2.0
//! Block benches of `hdl/src/board`: the UART-to-Wishbone bridge's receiver and
//! transmitter against the golden line model (`golden::board::uart`), the whole bridge
//! against the golden protocol (`golden::board::protocol`) with a Wishbone slave model, and
//! the board top against the golden register model behind the bridge, in rust-hdl and (its
//! emitted Verilog) in Verilator, cycle for cycle; and the host program's protocol
//! (`monitor`) on the simulated board. One module per block, named like the block's file.

#[path = "../common/mod.rs"]
mod common;

mod board_top;
mod monitor;
mod uart_rx;
mod uart_tx;
mod uart_wishbone;
