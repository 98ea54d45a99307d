// SPDX-License-Identifier: MIT OR Apache-2.0
//! The board tops: the boards and the parameters of their IP ([`boards`]), and the
//! UART-to-Wishbone bridge a board top puts in front of `encspeed_wb`: the serial protocol
//! a host speaks ([`protocol`]) and the UART 8N1 line timing ([`uart`]), as plain Rust for
//! the host program and the benches. Hardware: `hdl::board`; docs/boards.md and
//! docs/uart-bridge.md.

pub mod boards;
pub mod host;
pub mod protocol;
pub mod uart;
