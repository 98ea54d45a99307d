// SPDX-License-Identifier: MIT OR Apache-2.0
//! The board tops ([`board_top`]: `encspeed_wb` behind a UART bridge, a power-on reset
//! and LEDs) and their UART-to-Wishbone bridge: a UART 8N1 receiver and transmitter, the
//! protocol engine that turns commands into Wishbone accesses, and the block wiring them.
//! Boards, protocol and line timing: [`golden::board`]; docs/boards.md, docs/uart-bridge.md.

pub mod board_top;
pub mod uart_rx;
pub mod uart_tx;
pub mod uart_wb_bridge;
pub mod uart_wishbone;
