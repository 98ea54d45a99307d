// SPDX-License-Identifier: MIT OR Apache-2.0
//! Shared sequential arithmetic.

pub mod div_step;
pub mod seq_divider;
pub mod two_cycle_adder;
