//! What every Verilator harness of this crate shares: a build cached by content, and a run
//! that streams one line of inputs per clock edge in and one line of outputs per edge out.
//!
//! The harnesses (`tb/verilator/*.cpp`) read whitespace-separated decimal inputs, one line
//! per cycle, and print whitespace-separated decimal outputs, one line per cycle; `--vcd
//! PATH` makes them trace every signal. [`build_cached`] compiles a set of files once per
//! content under `target/verilator/<prefix><hash>/`, building in a directory private to the
//! process and the call and renaming it into place, so that parallel tests never see or
//! write into a half-built harness. [`stream`] runs it. A missing `verilator` is an error,
//! never a skip: `.ci/run` installs it.

use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// FNV-1a over the parts, each followed by a zero byte: the content key of a build.
pub fn fnv1a(parts: &[&str]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for p in parts {
        for b in p.bytes().chain([0u8]) {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

/// Write `files` (name, contents) into `dir`; their paths, in order.
pub fn stage(dir: &Path, files: &[(&str, &str)]) -> std::io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)?;
    files
        .iter()
        .map(|(name, text)| {
            let path = dir.join(name);
            std::fs::write(&path, text)?;
            Ok(path)
        })
        .collect()
}

/// The executable of `verilator --cc --exe --build` on `files` (waivers, Verilog and the C++
/// harness, in the order Verilator should read them) with top module `top`, built once per
/// content under `target/verilator/<prefix><hash>/`.
pub fn build_cached(prefix: &str, top: &str, files: &[(&str, &str)]) -> Result<PathBuf, String> {
    let mut parts: Vec<&str> = vec![top];
    for (name, text) in files {
        parts.push(name);
        parts.push(text);
    }
    let hash = fnv1a(&parts);
    let root = crate::target_dir().join("verilator");
    let done = root.join(format!("{prefix}{hash:016x}"));
    let exe = done.join(format!("obj/V{top}"));
    if exe.exists() {
        return Ok(exe);
    }
    static BUILDS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let build = BUILDS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let tmp = root.join(format!(
        "{prefix}{hash:016x}.tmp{}-{build}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&tmp);
    let paths = stage(&tmp, files).map_err(|e| e.to_string())?;
    crate::run_tool(
        Command::new("verilator")
            .current_dir(&tmp)
            .args(["--cc", "--exe", "--build", "-O3", "--trace", "-j", "2"])
            .args(["--top-module", top, "-Mdir", "obj"])
            .args(&paths),
        "verilator --build",
    )?;
    if std::fs::rename(&tmp, &done).is_err() {
        // Another process won the race; its build is identical.
        let _ = std::fs::remove_dir_all(&tmp);
    }
    Ok(exe)
}

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
