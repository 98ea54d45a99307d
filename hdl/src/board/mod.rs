// SPDX-License-Identifier: MIT OR Apache-2.0
//! The UART-to-Wishbone bridge of the board tops: a UART 8N1 receiver and transmitter, the
//! protocol engine that turns commands into Wishbone accesses, and the block wiring them.
//! Protocol and line timing: [`golden::board`]; docs/uart-bridge.md.

pub mod uart_rx;
pub mod uart_tx;
pub mod uart_wb_bridge;
pub mod uart_wishbone;
