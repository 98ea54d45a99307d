// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's synchronised estimator: time base, Table 1 registers, and n1/n2/n3 (scaled, tagged with their request and held).

pub mod speed_calc;
pub mod sync_estimator;
pub mod timebase;
