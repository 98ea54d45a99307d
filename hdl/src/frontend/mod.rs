// SPDX-License-Identifier: MIT OR Apache-2.0
//! The quadrature front end: synchronisers, glitch filters, start-up hold, decoder, position.

pub mod glitch_filter;
pub mod position_counter;
pub mod quadrature_decoder;
pub mod startup;
pub mod two_flop_sync;
