// SPDX-License-Identifier: MIT OR Apache-2.0
//! Wishbone B4 register files.

pub mod ecc_regs;
pub mod wb_regs;
