// SPDX-License-Identifier: MIT OR Apache-2.0
mod baseline_speeds;
mod et_timer;
mod mt_counter;
mod pc_counter;
mod window_timer;
