// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's synchronised estimator, bit-true: Table 1 as one step per clock, the speed calculator, and the error bounds and budget.

pub mod bounds;
pub mod speed_calc;
pub mod sync_estimator;
