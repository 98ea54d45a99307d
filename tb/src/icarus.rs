//! The emitted Verilog replayed in Icarus Verilog against the golden model's outputs,
//! by the self-checking bench `tb/icarus/replay_tb.v` (a second, independent simulator).

use golden::bittrue::{CoreInputs, CoreOutputs};
use std::process::Command;

const BENCH: &str = include_str!("../icarus/replay_tb.v");

/// Passed and failed cycles reported by the bench.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Replay {
    /// Cycles whose outputs matched.
    pub passed: u64,
    /// Cycles whose outputs differed.
    pub failed: u64,
}

/// Compile `verilog` with the bench (`iverilog -Wall`) and replay `inputs`, expecting
/// `expected` on every cycle. `tag` names the work directory under `target/icarus/`.
pub fn replay(
    tag: &str,
    verilog: &str,
    counter_bits: u32,
    inputs: &[CoreInputs],
    expected: &[CoreOutputs],
) -> Result<Replay, String> {
    assert_eq!(inputs.len(), expected.len());
    let dir = crate::target_dir().join("icarus").join(tag);
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let w =
        |name: &str, text: &str| std::fs::write(dir.join(name), text).map_err(|e| e.to_string());
    w("encspeed_core.v", verilog)?;
    w("replay_tb.v", BENCH)?;
    let vectors: String = inputs
        .iter()
        .zip(expected)
        .map(|(i, o)| {
            format!(
                "{} {} {} {} {} {} {} {} {} {}\n",
                i.reset as u8,
                i.enc_a as u8,
                i.enc_b as u8,
                i.enc_z as u8,
                i.cfg_dt,
                o.nep,
                o.ndt,
                o.update as u8,
                o.stalled as u8,
                o.cfg_error as u8
            )
        })
        .collect();
    w("vectors.txt", &vectors)?;
    let compile = Command::new("iverilog")
        .current_dir(&dir)
        .args([
            "-Wall",
            "-g2005",
            &format!("-DW={counter_bits}"),
            "-o",
            "replay.vvp",
        ])
        .args(["replay_tb.v", "encspeed_core.v"])
        .output()
        .map_err(|e| format!("cannot run iverilog: {e} (install it: see .ci/run)"))?;
    let warnings = String::from_utf8_lossy(&compile.stderr).to_string();
    if !compile.status.success() || !warnings.trim().is_empty() {
        return Err(format!("iverilog -Wall: {warnings}"));
    }
    let run = Command::new("vvp")
        .current_dir(&dir)
        .args(["-n", "replay.vvp"])
        .output()
        .map_err(|e| format!("cannot run vvp: {e}"))?;
    let text = String::from_utf8_lossy(&run.stdout).to_string();
    let last = text
        .lines()
        .rev()
        .find(|l| l.contains("passed,"))
        .ok_or_else(|| format!("no result line from vvp:\n{text}"))?;
    let nums: Vec<u64> = last
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|x| x.parse().ok())
        .collect();
    match nums.as_slice() {
        [passed, failed] => Ok(Replay {
            passed: *passed,
            failed: *failed,
        }),
        _ => Err(format!("bad result line {last:?}:\n{text}")),
    }
}
