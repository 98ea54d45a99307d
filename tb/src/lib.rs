// SPDX-License-Identifier: MIT OR Apache-2.0
//! Benches, scenarios and co-simulation for encspeed.
//!
//! Every hardware behaviour is checked three ways on the same per-cycle stimuli
//! ([`golden::top::core::CoreInputs`]): the bit-true golden model, the rust-hdl simulation
//! ([`hdl::build_core`]) and the emitted Verilog in Verilator ([`verilator`]; the shipped
//! core also in Icarus Verilog, [`icarus`]). The Verilator harnesses and the Icarus bench are
//! generated from the tops' port lists ([`golden::top::ports`]), and the per-cycle values
//! cross to them through [`golden::top::port_fields`]: no port is named twice.

pub mod accuracy;
pub mod adversarial;
pub mod cosim;
pub mod ecc_ripple;
pub mod ecc_verilator;
pub mod freqresp;
pub mod icarus;
pub mod scenarios;
pub mod stimulus;
pub mod verilator;
pub mod waves;
