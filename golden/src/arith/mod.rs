// SPDX-License-Identifier: MIT OR Apache-2.0
//! Shared sequential arithmetic: the divider and the latest-request timing of the calculators.

pub mod div_step;
pub mod latest_request;
pub mod seq_divider;
pub mod two_cycle_adder;
