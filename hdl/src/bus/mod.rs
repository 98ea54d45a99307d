//! Wishbone B4 register files.

pub mod ecc_regs;
pub mod wb_regs;
