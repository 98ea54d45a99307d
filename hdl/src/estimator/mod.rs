// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's synchronised estimator: time base, Table 1 registers, tagging, n1/n2/n3 and their scaling and hold.

pub mod speed_calc;
pub mod speed_hold;
pub mod speed_tag;
pub mod sync_estimator;
pub mod timebase;
