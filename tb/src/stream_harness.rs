//! What every Verilator harness of this crate shares: a run that streams one line of inputs
//! per clock edge in and one line of outputs per edge out.
//!
//! The harnesses (`tb/verilator/*.cpp`) read whitespace-separated decimal inputs, one line
//! per cycle, and print whitespace-separated decimal outputs, one line per cycle; `--vcd
//! PATH` makes them trace every signal. [`tools::verilator_build`] compiles a harness with
//! its Verilog once per content under `target/verilator/<prefix><hash>/`; [`stream`] runs
//! it. A missing `verilator` is an error, never a skip: `.ci/run` installs it.

use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Command, Stdio};

/// Run the harness `exe` on `input` (one line per cycle); optionally trace to `vcd`. Each
/// output line must hold exactly `fields` decimal numbers; they are returned in order.
pub fn stream(
    exe: &Path,
    input: String,
    vcd: Option<&Path>,
    fields: usize,
) -> Result<Vec<Vec<u64>>, String> {
    let mut cmd = Command::new(exe);
    if let Some(path) = vcd {
        cmd.arg("--vcd").arg(path);
    }
    let mut child = cmd
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot start {}: {e}", exe.display()))?;
    let mut stdin = child.stdin.take().expect("piped stdin");
    // Write from another thread: the harness answers each line as it reads it, and both
    // pipes would fill up if one thread did both.
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let stdout = BufReader::new(child.stdout.take().expect("piped stdout"));
    let mut rows = Vec::new();
    for line in stdout.lines() {
        let line = line.map_err(|e| e.to_string())?;
        let f: Vec<u64> = line
            .split_whitespace()
            .map(|x| {
                x.parse::<u64>()
                    .map_err(|e| format!("bad harness output {line:?}: {e}"))
            })
            .collect::<Result<_, _>>()?;
        if f.len() != fields {
            return Err(format!(
                "bad harness output {line:?}: {} fields, expected {fields}",
                f.len()
            ));
        }
        rows.push(f);
    }
    writer
        .join()
        .expect("writer thread")
        .map_err(|e| format!("writing to the harness: {e}"))?;
    let out = child.wait_with_output().map_err(|e| e.to_string())?;
    if !out.status.success() {
        return Err(format!(
            "harness failed ({}): {}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(rows)
}
