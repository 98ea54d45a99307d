// SPDX-License-Identifier: MIT OR Apache-2.0
//! Direct-drive simulations of the tops behind width-independent interfaces.

pub mod board_sim;
pub mod core_sim;
pub mod ecc_sim;
pub mod ecc_wb_sim;
pub mod wb_channels_sim;
pub mod wb_sim;
