// SPDX-License-Identifier: MIT OR Apache-2.0
//! The PC, ET and M/T baseline estimators and their speeds.

pub mod baseline_speeds;
pub mod et_timer;
pub mod mt_counter;
pub mod pc_counter;
pub mod window_timer;
