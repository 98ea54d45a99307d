//! rust-hdl description of the encspeed core, one hardware block per file.
//!
//! | block | file | what it does |
//! |---|---|---|
//! | [`EncspeedCore`] | `core.rs` | top: wires the blocks below, ports of `encspeed_core` |
//! | [`TwoFlopSync`] | `two_flop_sync.rs` | two-flop synchroniser of `enc_a` |
//! | [`Startup`] | `startup.rs` | start-up sequencing after reset |
//! | [`RisingEdge`] | `rising_edge.rs` | rising-edge detector: the encoder pulse `lep` |
//! | [`Timebase`] | `timebase.rs` | ts/dt time base with runtime dt |
//! | [`SyncEstimator`] | `sync_estimator.rs` | Table 1 registers Cep, Cdt, Nep1, Ndt1 |
//!
//! [`build_core`] turns validated [`Params`](golden::params::Params) into a core of the right
//! counter width behind the [`CoreSim`] trait (rust-hdl widths are const generics).

pub mod core;
pub mod emit;
pub mod rising_edge;
pub mod sim;
pub mod startup;
pub mod sync_estimator;
pub mod timebase;
pub mod two_flop_sync;

pub use crate::core::EncspeedCore;
pub use emit::{emit_core, EmitInfo};
pub use rising_edge::RisingEdge;
pub use sim::{build_core, CoreSim};
pub use startup::Startup;
pub use sync_estimator::SyncEstimator;
pub use timebase::Timebase;
pub use two_flop_sync::TwoFlopSync;
