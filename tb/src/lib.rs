//! Benches, scenarios and co-simulation for encspeed.
//!
//! Every hardware behaviour is checked three ways on the same per-cycle stimuli
//! ([`golden::top::core::CoreInputs`]): the bit-true golden model, the rust-hdl simulation
//! ([`hdl::build_core`]) and the emitted Verilog in Verilator ([`verilator`]).

pub mod accuracy;
pub mod adversarial;
pub mod cosim;
pub mod ecc_ripple;
pub mod ecc_verilator;
pub mod freqresp;
pub mod icarus;
pub mod scenarios;
pub mod stimulus;
pub mod stream_harness;
pub mod verilator;
pub mod waves;
pub mod wb_verilator;
