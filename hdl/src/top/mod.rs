// SPDX-License-Identifier: MIT OR Apache-2.0
//! The shipped tops and the core's fault flags.

pub mod core;
pub mod ecc_top;
pub mod ecc_wb_top;
pub mod fault_flags;
pub mod mode_reset;
pub mod wb_channels;
pub mod wb_top;
