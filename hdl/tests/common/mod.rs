//! Shared by the block tests: where build products go, and Icarus runs.

// Each test binary includes this module and uses a subset of it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

/// The workspace's `target/` (honouring `CARGO_TARGET_DIR`): never the source tree.
pub fn target_dir() -> PathBuf {
    match std::env::var_os("CARGO_TARGET_DIR") {
        Some(d) => d.into(),
        None => PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../target")),
    }
}

/// Compile `sources` (in `dir`) with `iverilog -Wall -g2005` plus `extra` arguments,
/// asserting that it compiles without a single warning, run the result with `vvp`, and
/// return what it printed.
pub fn icarus_run(dir: &Path, extra: &[String], sources: &[String]) -> String {
    let compile = Command::new("iverilog")
        .current_dir(dir)
        .args(["-Wall", "-g2005", "-o", "tb.vvp"])
        .args(extra)
        .args(sources)
        .output()
        .expect("cannot run iverilog (install it: see .ci/run)");
    let warnings = String::from_utf8_lossy(&compile.stderr);
    assert!(
        compile.status.success() && warnings.trim().is_empty(),
        "iverilog -Wall:\n{warnings}"
    );
    let run = Command::new("vvp")
        .current_dir(dir)
        .args(["-n", "tb.vvp"])
        .output()
        .expect("cannot run vvp");
    String::from_utf8_lossy(&run.stdout).into_owned()
}

/// splitmix64: a fixed, reproducible stream of random numbers for the Icarus runs (each
/// test adds its own operand shapes on top of `next`).
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
}
