//! The emitted `encspeed_ecc.v` (core + corrected M/T), compiled by Verilator with
//! `tb/verilator/ecc_harness.cpp`, in the pattern of [`crate::verilator`]: per-cycle
//! streaming for cycle-by-cycle comparison with [`golden::top::ecc_top::EccTopModel`], and an
//! event mode for revolutions of hundreds of millions of cycles. A missing `verilator` is
//! an error, never a skip: `.ci/run` installs it.

use crate::stream_harness;
use crate::verilator::{input_line, outputs_of_fields, signed};
use golden::ecc::ident_gatherer::GatherOutputs;
use golden::ideal::plant::Sample;
use golden::top::ecc_top::{EccTopInputs, EccTopOutputs, IDENT_SUM_BITS};
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

const HARNESS: &str = include_str!("../verilator/ecc_harness.cpp");
const MODULE: &str = "encspeed_ecc";

/// The waivers for `encspeed_ecc.v`: the core's, retargeted (the top contains the core
/// unchanged), the file-name rule for the top's sub-modules, and WIDTH for the masks that
/// rust-hdl's `bit_cast` emits (`x & 33'h1ffffffff` to widen, `(y & 32'hffffffff)` assigned
/// to narrow: Verilog zero-extends and truncates exactly as the cast means).
pub fn waivers() -> String {
    waivers_for(MODULE)
}

/// The waivers of [`waivers`] for a top `module` that contains `encspeed_ecc` (as
/// `encspeed_ecc_wb` does), retargeted to `module.v`.
pub fn waivers_for(module: &str) -> String {
    format!(
        "{}\nlint_off -rule DECLFILENAME -file \"*{module}.v\"\n\
         lint_off -rule WIDTH -file \"*{module}.v\" -match \"*Operator AND expects*\"\n\
         lint_off -rule WIDTH -file \"*{module}.v\" -match \"*Assign RHS's AND generates*\"\n",
        crate::verilator::WAIVERS.replace("*encspeed_core.v", &format!("*{module}.v"))
    )
}

/// A compiled simulator of one emitted `encspeed_ecc`.
pub struct EccVerilated {
    exe: PathBuf,
    speed_bits: u32,
}

/// One line of the event mode: a cycle with a strobe.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EccStrobe {
    /// Cycle (edge) index, from 0.
    pub cycle: u64,
    /// `speed_mt` if `baseline_strobe` was high.
    pub speed_mt: Option<i64>,
    /// `speed_mtc` if `mtc_strobe` was high.
    pub speed_mtc: Option<i64>,
    /// `speed_n3` if `speed_strobe` was high.
    pub speed_n3: Option<i64>,
    /// `speed_n3c` if `n3c_strobe` was high.
    pub speed_n3c: Option<i64>,
    /// `position` in that cycle.
    pub position: u64,
    /// `speed_nep` in that cycle (what the last n3 was computed from).
    pub speed_nep: u64,
    /// `speed_ndt` in that cycle.
    pub speed_ndt: u64,
}

impl EccStrobe {
    /// The event-mode line of the outputs `o` after edge `cycle`, as the harness prints
    /// it: `None` if no speed strobe is high.
    pub fn of(cycle: u64, o: &EccTopOutputs) -> Option<EccStrobe> {
        let c = &o.core;
        (c.baseline_strobe || o.mtc_strobe || c.speed_strobe || o.n3c_strobe).then_some(EccStrobe {
            cycle,
            speed_mt: c.baseline_strobe.then_some(c.speed_mt),
            speed_mtc: o.mtc_strobe.then_some(o.speed_mtc),
            speed_n3: c.speed_strobe.then_some(c.speed_n3),
            speed_n3c: o.n3c_strobe.then_some(o.speed_n3c),
            position: c.position,
            speed_nep: c.speed_nep,
            speed_ndt: c.speed_ndt,
        })
    }
}

/// The configuration of an event-mode run.
#[derive(Clone, Copy, Debug)]
pub struct EventRun {
    /// Cycles to run (reset for the first 3).
    pub cycles: u64,
    /// `cfg_dt`.
    pub cfg_dt: u64,
    /// `cfg_mode`.
    pub cfg_mode: u8,
    /// `cfg_z_mode`.
    pub cfg_z_mode: u8,
    /// `ecc_c`, Q15.16.
    pub ecc_c: i64,
    /// `ecc_d`, Q15.16.
    pub ecc_d: i64,
    /// Raise `ident_arm` this many cycles after the first `index` (the position is aligned
    /// from then on); `None`: never.
    pub arm_delay: Option<u64>,
}

/// What an event-mode run printed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EventLog {
    /// Every cycle with a speed strobe.
    pub strobes: Vec<EccStrobe>,
    /// (cycle, results) at each rise of `ident_done`.
    pub ident: Vec<(u64, GatherOutputs)>,
}

/// Fields of the identification in a harness line (IDENT in ecc_harness.cpp).
const IDENT_FIELDS: usize = 16;

/// The identification results from the harness's IDENT fields.
fn ident_of_fields(f: &[u64]) -> GatherOutputs {
    let wide = |w: &[u64]| -> i128 {
        let raw = u128::from(w[0]) | u128::from(w[1]) << 32 | u128::from(w[2]) << 64;
        let shift = 128 - IDENT_SUM_BITS;
        ((raw << shift) as i128) >> shift
    };
    GatherOutputs {
        done: f[0] != 0,
        overflow: f[1] != 0,
        count: f[2],
        t_min: f[3],
        p_min: f[4],
        t_max: f[5],
        p_max: f[6],
        sum_t: wide(&f[7..10]),
        sum_sin: wide(&f[10..13]),
        sum_cos: wide(&f[13..16]),
    }
}

fn port32(v: i64) -> u64 {
    (v as u64) & 0xffff_ffff
}

impl EccVerilated {
    /// Compile `verilog` (module `encspeed_ecc`, speeds of `speed_bits` bits) with the
    /// harness, or reuse the build.
    pub fn build(verilog: &str, speed_bits: u32) -> Result<EccVerilated, String> {
        if !verilog.contains(&format!("module {MODULE}(")) {
            return Err(format!("the Verilog has no module {MODULE}"));
        }
        let exe = tools::verilator_build(
            "ecc-",
            MODULE,
            &[
                ("ecc_waivers.vlt", &waivers()),
                ("encspeed_ecc.v", verilog),
                ("ecc_harness.cpp", HARNESS),
            ],
        )?;
        Ok(EccVerilated { exe, speed_bits })
    }

    /// Run `inputs`, one edge each; optionally trace to `vcd`.
    pub fn run(
        &self,
        inputs: &[EccTopInputs],
        vcd: Option<&Path>,
    ) -> Result<Vec<EccTopOutputs>, String> {
        let text: String = inputs
            .iter()
            .map(|i| {
                format!(
                    "{} {} {} {}\n",
                    input_line(&i.core),
                    port32(i.ecc_c),
                    port32(i.ecc_d),
                    u8::from(i.ident_arm)
                )
            })
            .collect();
        let rows = stream_harness::stream(&self.exe, text, vcd, 36 + IDENT_FIELDS)?;
        Ok(rows
            .iter()
            .map(|f| EccTopOutputs {
                core: outputs_of_fields(f, self.speed_bits),
                speed_mtc: signed(f[32], self.speed_bits),
                mtc_strobe: f[33] != 0,
                speed_n3c: signed(f[34], self.speed_bits),
                n3c_strobe: f[35] != 0,
                ident: ident_of_fields(&f[36..]),
            })
            .collect())
    }

    /// Run `run.cycles` cycles of the levels `initial` then `changes` (cycle, levels from
    /// it on); the cycles with a strobe and the identifications.
    pub fn run_events(
        &self,
        run: &EventRun,
        initial: Sample,
        changes: &[(u64, Sample)],
    ) -> Result<EventLog, String> {
        let mut child = Command::new(&self.exe)
            .arg("--events")
            .args([
                run.cycles.to_string(),
                run.cfg_dt.to_string(),
                run.cfg_mode.to_string(),
                run.cfg_z_mode.to_string(),
                port32(run.ecc_c).to_string(),
                port32(run.ecc_d).to_string(),
                run.arm_delay.map_or(-1, |d| d as i64).to_string(),
            ])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot start {}: {e}", self.exe.display()))?;
        let mut text = String::new();
        let line = |k: u64, s: &Sample| format!("{k} {} {} {}\n", s.a as u8, s.b as u8, s.z as u8);
        text.push_str(&line(0, &initial));
        for (k, s) in changes {
            text.push_str(&line(*k, s));
        }
        let mut stdin = child.stdin.take().expect("piped stdin");
        let writer = std::thread::spawn(move || stdin.write_all(text.as_bytes()));
        let stdout = BufReader::new(child.stdout.take().expect("piped stdout"));
        let mut out = EventLog::default();
        for l in stdout.lines() {
            let l = l.map_err(|e| e.to_string())?;
            let (ident, fields) = match l.strip_prefix("I ") {
                Some(rest) => (true, rest),
                None => (false, l.as_str()),
            };
            let f: Vec<u64> = fields
                .split_whitespace()
                .map(|x| {
                    x.parse()
                        .map_err(|e| format!("bad harness output {l:?}: {e}"))
                })
                .collect::<Result<_, String>>()?;
            if ident {
                if f.len() != 1 + IDENT_FIELDS {
                    return Err(format!("bad harness output {l:?}"));
                }
                out.ident.push((f[0], ident_of_fields(&f[1..])));
                continue;
            }
            if f.len() != 12 {
                return Err(format!("bad harness output {l:?}"));
            }
            out.strobes.push(EccStrobe {
                cycle: f[0],
                speed_mt: (f[1] != 0).then(|| signed(f[2], self.speed_bits)),
                speed_mtc: (f[3] != 0).then(|| signed(f[4], self.speed_bits)),
                speed_n3: (f[5] != 0).then(|| signed(f[6], self.speed_bits)),
                speed_n3c: (f[7] != 0).then(|| signed(f[8], self.speed_bits)),
                position: f[9],
                speed_nep: f[10],
                speed_ndt: f[11],
            });
        }
        // The harness stops reading after the last cycle: a closed pipe is not an error.
        let _ = writer.join().expect("writer thread");
        let status = child.wait().map_err(|e| e.to_string())?;
        if !status.success() {
            return Err(format!("harness failed ({status})"));
        }
        Ok(out)
    }
}
