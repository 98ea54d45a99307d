//! Benches, scenarios and co-simulation for encspeed.
//!
//! Every hardware behaviour is checked three ways on the same per-cycle stimuli
//! ([`golden::bittrue::CoreInputs`]): the bit-true golden model, the rust-hdl simulation
//! ([`hdl::build_core`]) and the emitted Verilog in Verilator ([`verilator`]).

pub mod cosim;
pub mod icarus;
pub mod scenarios;
pub mod stimulus;
pub mod verilator;
pub mod waves;

/// Directory for build products and simulation output of this workspace (`target/`),
/// honouring `CARGO_TARGET_DIR`. Never the source tree.
pub fn target_dir() -> std::path::PathBuf {
    match std::env::var_os("CARGO_TARGET_DIR") {
        Some(d) => d.into(),
        None => std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target"),
    }
}
