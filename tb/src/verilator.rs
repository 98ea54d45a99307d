//! The emitted Verilog, compiled by Verilator with the harness in `tb/verilator/`.
//!
//! [`Verilated::build`] compiles a Verilog text once per content (cached under
//! `target/verilator/<hash>/`); [`Verilated::run`] streams per-cycle inputs through it and
//! returns per-cycle outputs in the same form as the golden model. A missing `verilator` is
//! an error, never a skip: `.ci/run` installs it.

use crate::stream_harness;
use golden::top::core::{CoreInputs, CoreOutputs};
use std::path::{Path, PathBuf};
use std::process::Command;

const HARNESS: &str = include_str!("../verilator/harness.cpp");
/// Lint waivers for the emitted Verilog (each one explained in the file).
pub const WAIVERS: &str = include_str!("../verilator/waivers.vlt");

/// A compiled simulator of one emitted `encspeed_core`.
pub struct Verilated {
    exe: PathBuf,
    speed_bits: u32,
}

/// The width of the speed ports, read from the header the generator writes into every
/// emitted file (`output speed_n3[S-1:0]: …`).
fn speed_bits_of(verilog: &str) -> Result<u32, String> {
    let tag = "output speed_n3[";
    let at = verilog
        .find(tag)
        .ok_or("the Verilog has no encspeed port header (output speed_n3[..])")?;
    let rest = &verilog[at + tag.len()..];
    let msb: u32 = rest
        .split(':')
        .next()
        .and_then(|x| x.parse().ok())
        .ok_or("bad speed_n3 width in the header")?;
    Ok(msb + 1)
}

/// The two's complement value of the low `bits` bits of `raw`.
pub fn signed(raw: u64, bits: u32) -> i64 {
    let sh = 64 - bits;
    ((raw << sh) as i64) >> sh
}

/// One harness input line (no newline): the core's inputs in the order of harness.cpp.
pub fn input_line(i: &CoreInputs) -> String {
    format!(
        "{} {} {} {} {} {} {} {} {} {}",
        i.reset as u8,
        i.enc_a as u8,
        i.enc_b as u8,
        i.enc_z as u8,
        i.cfg_dt,
        i.cfg_timeout,
        i.cfg_filter,
        i.cfg_mode,
        i.cfg_z_mode,
        i.clear_faults as u8
    )
}

/// The core's outputs from the first 32 fields a harness printed (order of harness.cpp),
/// speeds sign-extended from `speed_bits`.
pub fn outputs_of_fields(f: &[u64], speed_bits: u32) -> CoreOutputs {
    let sp = |raw: u64| signed(raw, speed_bits);
    CoreOutputs {
        position: f[0],
        z_latch: f[1],
        index: f[2] != 0,
        direction: f[3] != 0,
        nep: f[4],
        ndt: f[5],
        update: f[6] != 0,
        speed_n1: sp(f[7]),
        speed_n2: sp(f[8]),
        speed_n3: sp(f[9]),
        speed_strobe: f[10] != 0,
        speed_pc: sp(f[11]),
        speed_et: sp(f[12]),
        speed_mt: sp(f[13]),
        baseline_strobe: f[14] != 0,
        valid: f[15] != 0,
        stalled: f[16] != 0,
        fault_illegal: f[17] != 0,
        fault_overspeed: f[18] != 0,
        fault_revolution: f[19] != 0,
        cfg_error: f[20] != 0,
        glitch_count: f[21],
        illegal_count: f[22],
        rev_error_count: f[23],
        speed_position: f[24],
        speed_nep: f[25],
        speed_ndt: f[26],
        mt_strobe: f[27] != 0,
        mt_m: f[28],
        mt_t: f[29],
        mt_negative: f[30] != 0,
        dt_active: f[31],
    }
}

/// `verilator --lint-only -Wall` with the documented waivers; Ok on a clean lint.
pub fn lint(verilog: &str) -> Result<String, String> {
    let dir = tools::work_dir(
        "verilator",
        &format!("lint-{:016x}", tools::content_hash(&[verilog])),
    )?;
    tools::stage(
        &dir,
        &[("encspeed_core.v", verilog), ("waivers.vlt", WAIVERS)],
    )?;
    tools::verilator_lint(&dir, "encspeed_core", &["waivers.vlt", "encspeed_core.v"])
}

impl Verilated {
    /// Compile `verilog` (top module `encspeed_core`) with the harness, or reuse the build.
    pub fn build(verilog: &str) -> Result<Verilated, String> {
        let speed_bits = speed_bits_of(verilog)?;
        let exe = tools::verilator_build(
            "",
            "encspeed_core",
            &[
                ("waivers.vlt", WAIVERS),
                ("encspeed_core.v", verilog),
                ("harness.cpp", HARNESS),
            ],
        )?;
        Ok(Verilated { exe, speed_bits })
    }

    /// Path of the compiled harness.
    pub fn exe(&self) -> &Path {
        &self.exe
    }

    /// Run `inputs` through the compiled Verilog, one clock edge per input; optionally write
    /// a VCD of every signal to `vcd`.
    pub fn run(
        &self,
        inputs: &[CoreInputs],
        vcd: Option<&Path>,
    ) -> Result<Vec<CoreOutputs>, String> {
        let text: String = inputs.iter().map(|i| input_line(i) + "\n").collect();
        let rows = stream_harness::stream(&self.exe, text, vcd, 32)?;
        let outs = rows
            .iter()
            .map(|f| outputs_of_fields(f, self.speed_bits))
            .collect();
        Ok(outs)
    }

    /// Benchmark: cycles per second of the compiled Verilog on a square wave of `period`
    /// cycles with dt = `dt` (see the harness's `--bench`).
    pub fn bench(&self, cycles: u64, period: u64, dt: u64) -> Result<f64, String> {
        let out = tools::run(
            Command::new(&self.exe).args([
                "--bench",
                &cycles.to_string(),
                &period.to_string(),
                &dt.to_string(),
            ]),
            "harness --bench",
        )?;
        out.split_whitespace()
            .nth(2)
            .and_then(|x| x.parse().ok())
            .ok_or_else(|| format!("bad bench output {out:?}"))
    }
}
