// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true models of the quadrature front end: [`GlitchFilter`] (one per channel),
//! [`QuadratureDecoder`] and [`PositionCounter`].
//!
//! These are the golden models of the rust-hdl blocks `hdl::GlitchFilter`,
//! `hdl::QuadratureDecoder` and `hdl::PositionCounter`, cycle for cycle and in the
//! hardware's widths. Conventions (as [`crate::top::core::CoreModel`]): one `step` per rising
//! clock edge with the inputs applied during the cycle before it; every register is updated
//! from the values before the edge; `step` returns the outputs after the edge. Reset is
//! synchronous and active high. Counters saturate at 2^bits − 1, none wraps (the position
//! is an angle: its wrap at `counts_per_rev` is its definition, not an overflow).
//!
//! Intended chain (the core wires it; these blocks are standalone):
//!
//! ```text
//! sync A ─ GlitchFilter ─ a ─┐
//! sync B ─ GlitchFilter ─ b ─┴─ QuadratureDecoder ─ step, forward ─┐
//! sync Z ─ GlitchFilter ─ z ────────────────────────────────────────┴─ PositionCounter
//! ```
//!
//! `z` enters the [`PositionCounter`] in the same cycle as `a`, `b` enter the decoder; the
//! counter delays it by the decoder's latency (one cycle), so that an index edge and the
//! step made by the same encoder transition are processed at the same clock edge.
//!
//! # Start-up
//! A [`GlitchFilter`] leaves reset with its output low and passes a high input only after
//! max(`cfg_filter`, 1) edges, which the decoder would take for a transition. Whoever wires
//! the chain must therefore hold the decoder and the counter in reset until the filters'
//! outputs are real samples: through edge max(L, 1) counted from the filters' reset edge 0
//! (as `golden/tests/frontend.rs` does). Each block then ignores its own first edge after
//! reset: the decoder takes the inputs at that edge as the reference (`primed`), and the
//! counter sees no index edge before it has compared two real samples of `z` (its delay
//! flops reset high). The reference is then the level of the first sample after reset,
//! provided the channels hold it for L cycles (a level that changes sooner is a pulse, and
//! a glitch, to a filter that starts low).

pub mod config;
pub mod glitch_filter;
pub mod position_counter;
pub mod quadrature_decoder;

pub use config::{
    MAX_BITS, MODE_INVALID, MODE_X1, MODE_X2, MODE_X4, Z_MODE_IGNORE, Z_MODE_LATCH,
    Z_MODE_LATCH_RESET, Z_MODE_RESET,
};
pub use glitch_filter::{GlitchFilter, GlitchFilterInputs, GlitchFilterOutputs, GlitchFilterState};
pub use position_counter::{CounterInputs, CounterOutputs, CounterState, PositionCounter};
pub use quadrature_decoder::{DecoderInputs, DecoderOutputs, DecoderState, QuadratureDecoder};
