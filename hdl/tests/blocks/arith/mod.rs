// SPDX-License-Identifier: MIT OR Apache-2.0
mod div_step;
mod seq_divider;
mod two_cycle_adder;
