//! The emitted Verilog replayed in Icarus Verilog against the golden model's outputs,
//! by the self-checking bench `tb/icarus/replay_tb.v` (a second, independent simulator).

use golden::top::core::{CoreInputs, CoreOutputs};

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
    speed_bits: u32,
    inputs: &[CoreInputs],
    expected: &[CoreOutputs],
) -> Result<Replay, String> {
    assert_eq!(inputs.len(), expected.len());
    let dir = tools::work_dir("icarus", tag)?;
    let w =
        |name: &str, text: &str| std::fs::write(dir.join(name), text).map_err(|e| e.to_string());
    w("encspeed_core.v", verilog)?;
    w("replay_tb.v", BENCH)?;
    let raw = |v: i64| (v as u64) & ((1u64 << speed_bits) - 1);
    let vectors: String = inputs
        .iter()
        .zip(expected)
        .map(|(i, o)| {
            let fields: [u64; 34] = [
                i.reset.into(),
                i.enc_a.into(),
                i.enc_b.into(),
                i.enc_z.into(),
                i.cfg_dt,
                i.cfg_timeout,
                i.cfg_filter,
                i.cfg_mode.into(),
                i.cfg_z_mode.into(),
                i.clear_faults.into(),
                o.position,
                o.z_latch,
                o.index.into(),
                o.direction.into(),
                o.nep,
                o.ndt,
                o.update.into(),
                raw(o.speed_n1),
                raw(o.speed_n2),
                raw(o.speed_n3),
                o.speed_strobe.into(),
                raw(o.speed_pc),
                raw(o.speed_et),
                raw(o.speed_mt),
                o.baseline_strobe.into(),
                o.valid.into(),
                o.stalled.into(),
                o.fault_illegal.into(),
                o.fault_overspeed.into(),
                o.fault_revolution.into(),
                o.cfg_error.into(),
                o.glitch_count,
                o.illegal_count,
                o.rev_error_count,
            ];
            let line: Vec<String> = fields.iter().map(u64::to_string).collect();
            line.join(" ") + "\n"
        })
        .collect();
    w("vectors.txt", &vectors)?;
    tools::iverilog(
        &dir,
        &[&format!("-DW={counter_bits}"), &format!("-DS={speed_bits}")],
        &["replay_tb.v", "encspeed_core.v"],
        "replay.vvp",
    )?;
    let text = tools::vvp(&dir, "replay.vvp", &[])?;
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
