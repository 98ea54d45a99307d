// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true models of the shipped tops, and their ports.

pub mod core;
pub mod ecc_top;
pub mod ecc_wb_top;
pub mod error_budget;
pub mod mode_reset;
pub mod port_fields;
pub mod ports;
pub mod wb_channels;
pub mod wb_top;
