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

/// Directory for build products and simulation output of this workspace (`target/`),
/// honouring `CARGO_TARGET_DIR`. Never the source tree.
pub fn target_dir() -> std::path::PathBuf {
    match std::env::var_os("CARGO_TARGET_DIR") {
        Some(d) => d.into(),
        None => std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target"),
    }
}

/// Run an external tool; its stdout and stderr on success, or an error that says which tool
/// failed and how (a missing tool names `.ci/run`, which installs it).
pub fn run_tool(cmd: &mut std::process::Command, what: &str) -> Result<String, String> {
    let out = cmd
        .output()
        .map_err(|e| format!("cannot run {what}: {e} (install it: see .ci/run)"))?;
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    if out.status.success() {
        Ok(text)
    } else {
        Err(format!("{what} failed ({}):\n{text}", out.status))
    }
}
