// SPDX-License-Identifier: MIT OR Apache-2.0
mod speed_calc;
mod sync_estimator;
mod timebase;
