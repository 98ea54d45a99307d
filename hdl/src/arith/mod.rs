//! Shared sequential arithmetic.

pub mod seq_divider;
