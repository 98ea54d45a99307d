// SPDX-License-Identifier: MIT OR Apache-2.0
mod glitch_filter;
mod position_counter;
mod quadrature_decoder;
mod startup;
mod two_flop_sync;
