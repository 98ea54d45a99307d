// SPDX-License-Identifier: MIT OR Apache-2.0
mod ecc_wb_sim;
mod wb_sim;
