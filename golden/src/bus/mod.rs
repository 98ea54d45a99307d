// SPDX-License-Identifier: MIT OR Apache-2.0
//! Register maps as data and the cycle models of the Wishbone register files.

pub mod ecc_regmap;
pub mod ecc_regs;
pub mod reg_file;
pub mod regmap;
pub mod wb_regs;
