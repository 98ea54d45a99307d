//! The emitted `encspeed_wb.v` (core + Wishbone register file), compiled by Verilator with
//! the harness `tb/verilator/wb_harness.cpp`: the same pattern as [`crate::verilator`]
//! (build cached under `target/verilator/wb-<hash>/` by content, built in a private
//! directory per call and renamed into place, inputs and outputs streamed one line per
//! cycle). A missing `verilator` is an error, never a skip: `.ci/run` installs it.

use golden::wb_top::{WbTopInputs, WbTopOutputs, TOP_MODULE};
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

const HARNESS: &str = include_str!("../verilator/wb_harness.cpp");
/// The top's own lint waivers (each one explained in the file).
pub const WB_WAIVERS: &str = include_str!("../verilator/wb_waivers.vlt");

/// The waivers that apply to `encspeed_wb.v`: the core's ([`crate::verilator::WAIVERS`]),
/// retargeted from `encspeed_core.v` to this file (the top contains the core unchanged, so
/// the same block outputs are unused under the same names), then the top's own.
pub fn waivers() -> String {
    format!(
        "{}\n// ---- encspeed_wb's own (wb_waivers.vlt) ----\n{}",
        crate::verilator::WAIVERS.replace("*encspeed_core.v", "*encspeed_wb.v"),
        WB_WAIVERS.trim_start_matches("`verilator_config")
    )
}

fn fnv1a(parts: &[&str]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for p in parts {
        for b in p.bytes().chain([0u8]) {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

/// Write the emitted Verilog and the waivers into `dir` for a tool to read.
pub fn stage(dir: &Path, verilog: &str) -> std::io::Result<(PathBuf, PathBuf)> {
    std::fs::create_dir_all(dir)?;
    let v = dir.join(format!("{TOP_MODULE}.v"));
    let w = dir.join("wb_waivers.vlt");
    std::fs::write(&v, verilog)?;
    std::fs::write(&w, waivers())?;
    Ok((v, w))
}

/// `verilator --lint-only -Wall` on `encspeed_wb.v` with the documented waivers; Ok on a
/// clean lint (a warning fails the run).
pub fn lint(verilog: &str) -> Result<String, String> {
    let dir = crate::target_dir()
        .join("verilator")
        .join(format!("wb-lint-{:016x}", fnv1a(&[verilog, &waivers()])));
    let (v, w) = stage(&dir, verilog).map_err(|e| e.to_string())?;
    crate::run_tool(
        Command::new("verilator")
            .args(["--lint-only", "-Wall", "--top-module", TOP_MODULE])
            .arg(&w)
            .arg(&v),
        "verilator --lint-only",
    )
}

/// A compiled simulator of one emitted `encspeed_wb`.
pub struct VerilatedWb {
    exe: PathBuf,
}

impl VerilatedWb {
    /// Compile `verilog` (top module `encspeed_wb`) with the harness, or reuse the build.
    pub fn build(verilog: &str) -> Result<VerilatedWb, String> {
        if !verilog.contains(&format!("module {TOP_MODULE}(")) {
            return Err(format!("the Verilog has no module {TOP_MODULE}"));
        }
        let waivers = waivers();
        let hash = fnv1a(&[verilog, HARNESS, &waivers]);
        let root = crate::target_dir().join("verilator");
        let done = root.join(format!("wb-{hash:016x}"));
        let exe = done.join(format!("obj/V{TOP_MODULE}"));
        if exe.exists() {
            return Ok(VerilatedWb { exe });
        }
        // Private build directory per process and call, renamed into place when complete.
        static BUILDS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
        let build = BUILDS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let tmp = root.join(format!("wb-{hash:016x}.tmp{}-{build}", std::process::id()));
        let _ = std::fs::remove_dir_all(&tmp);
        let (v, w) = stage(&tmp, verilog).map_err(|e| e.to_string())?;
        let h = tmp.join("wb_harness.cpp");
        std::fs::write(&h, HARNESS).map_err(|e| e.to_string())?;
        crate::run_tool(
            Command::new("verilator")
                .current_dir(&tmp)
                .args(["--cc", "--exe", "--build", "-O3", "--trace", "-j", "2"])
                .args(["--top-module", TOP_MODULE, "-Mdir", "obj"])
                .arg(&w)
                .arg(&v)
                .arg(&h),
            "verilator --build",
        )?;
        if std::fs::rename(&tmp, &done).is_err() {
            // Another process won the race; its build is identical.
            let _ = std::fs::remove_dir_all(&tmp);
        }
        Ok(VerilatedWb { exe })
    }

    /// Path of the compiled harness.
    pub fn exe(&self) -> &Path {
        &self.exe
    }

    /// Run `inputs` through the compiled Verilog, one clock edge per input; optionally write
    /// a VCD of every signal to `vcd`.
    pub fn run(
        &self,
        inputs: &[WbTopInputs],
        vcd: Option<&Path>,
    ) -> Result<Vec<WbTopOutputs>, String> {
        let mut cmd = Command::new(&self.exe);
        if let Some(path) = vcd {
            cmd.arg("--vcd").arg(path);
        }
        let mut child = cmd
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot start {}: {e}", self.exe.display()))?;
        let mut stdin = child.stdin.take().expect("piped stdin");
        let text: String = inputs
            .iter()
            .map(|i| {
                let b = &i.bus;
                format!(
                    "{} {} {} {} {} {} {} {} {} {}\n",
                    u8::from(i.reset),
                    u8::from(i.enc_a),
                    u8::from(i.enc_b),
                    u8::from(i.enc_z),
                    u8::from(b.wb_cyc_i),
                    u8::from(b.wb_stb_i),
                    u8::from(b.wb_we_i),
                    b.wb_adr_i,
                    b.wb_dat_i,
                    b.wb_sel_i
                )
            })
            .collect();
        let writer = std::thread::spawn(move || stdin.write_all(text.as_bytes()));
        let stdout = BufReader::new(child.stdout.take().expect("piped stdout"));
        let mut outs = Vec::with_capacity(inputs.len());
        for line in stdout.lines() {
            let line = line.map_err(|e| e.to_string())?;
            let f: Vec<u64> = line
                .split_whitespace()
                .map(|x| {
                    x.parse::<u64>()
                        .map_err(|e| format!("bad harness output {line:?}: {e}"))
                })
                .collect::<Result<_, _>>()?;
            if f.len() != 3 || f[1] > u64::from(u32::MAX) {
                return Err(format!("bad harness output {line:?}"));
            }
            outs.push(WbTopOutputs {
                wb_ack_o: f[0] != 0,
                wb_dat_o: f[1] as u32,
                irq: f[2] != 0,
            });
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
        Ok(outs)
    }
}
