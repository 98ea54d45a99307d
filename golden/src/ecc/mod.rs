// SPDX-License-Identifier: MIT OR Apache-2.0
//! Eccentricity correction and identification, bit-true: sine table, span correction, corrected M/T and n3, identification gatherer.

pub mod ecc_delta;
pub mod ecc_mt_speed;
pub mod ecc_n3;
pub mod ident_gatherer;
pub mod line_tap;
pub mod mt_corrector;
pub mod n3_corrector;
pub mod sine_rom;
pub mod span_delta;
