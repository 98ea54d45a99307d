// SPDX-License-Identifier: MIT OR Apache-2.0
//! Shared sequential arithmetic.

pub mod seq_divider;
