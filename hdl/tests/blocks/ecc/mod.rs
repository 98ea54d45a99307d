// SPDX-License-Identifier: MIT OR Apache-2.0
mod ecc_delta;
mod ecc_mt_speed;
mod ecc_n3;
mod ident_gatherer;
mod line_tap;
mod sine_rom;
mod table_rom;
