//! Shared sequential arithmetic: the divider and the latest-request timing of the calculators.

pub mod latest_request;
pub mod seq_divider;
