// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed check`: a verdict on another implementation's VCD against the bit-true model.
//! Exit 0 with `PASS`, 1 with the first mismatches, 2 for a VCD that cannot be checked.

use clap::Args;
use golden::params::Params;
use golden::reference::verdict::{check_exact, CheckOptions};
use golden::reference::{RefTop, Reference};
use std::fs::File;
use std::path::PathBuf;

use super::spec::SpecArgs;
use super::Outcome;

/// Where the ports are in a VCD, shared by `check` and `vectors --stimulus X.vcd`.
#[derive(Args)]
pub struct VcdSelection {
    /// The VCD scope of the implementation's ports, e.g. `tb.dut` (default: the scope that
    /// holds the clock, reset, enc_a, enc_b and enc_z and the most other ports).
    #[arg(long)]
    pub scope: Option<String>,
    /// Their names where they differ from the ports': `clk=clock,rst=reset,...`.
    #[arg(long, value_name = "THEIRS=PORT,...")]
    pub map: Option<String>,
}

/// The pairs (their name, port) of `--map`.
pub fn parse_map(map: &Option<String>) -> Result<Vec<(String, String)>, String> {
    let Some(text) = map else {
        return Ok(Vec::new());
    };
    text.split(',')
        .map(|pair| match pair.split_once('=') {
            Some((theirs, port)) if !theirs.trim().is_empty() && !port.trim().is_empty() => {
                Ok((theirs.trim().to_string(), port.trim().to_string()))
            }
            _ => Err(format!("--map: `{pair}` is not THEIRS=PORT")),
        })
        .collect()
}

/// Options of `encspeed check`.
#[derive(Args)]
pub struct CheckArgs {
    #[command(flatten)]
    spec: SpecArgs,
    /// The VCD of the implementation under test (any timescale; other signals may be there).
    #[arg(long, value_name = "FILE")]
    vcd: PathBuf,
    #[command(flatten)]
    selection: VcdSelection,
    /// exact: every output the VCD has, bit for bit against this core from the first reset.
    #[arg(long, default_value = "exact", value_parser = ["exact"])]
    mode: String,
    /// The top the implementation stands for: core or ecc.
    #[arg(long, default_value = "core", value_parser = ["core", "ecc"])]
    top: String,
    /// Mismatches listed on failure (all are counted).
    #[arg(long, default_value_t = 10)]
    report: usize,
}

/// `encspeed check`.
pub fn run(args: &CheckArgs) -> Outcome {
    args.spec.run(|p| check(p, args))
}

fn check(p: &Params, args: &CheckArgs) -> Outcome {
    let top = RefTop::parse(&args.top).map_err(|e| (2, e))?;
    let mut model = Reference::new(p, top).map_err(|e| (2, e))?;
    let options = CheckOptions {
        scope: args.selection.scope.clone(),
        map: parse_map(&args.selection.map).map_err(|e| (2, e))?,
        report: args.report,
    };
    let file = File::open(&args.vcd).map_err(|e| (2, format!("{}: {e}", args.vcd.display())))?;
    let v = check_exact(file, &mut model, &options)
        .map_err(|e| (2, format!("{}: {e}", args.vcd.display())))?;
    eprintln!(
        "{}: scope {}, timescale {}, compared from the first reset (edge {})",
        args.vcd.display(),
        v.scope,
        v.timescale,
        v.first_cycle
    );
    if !v.defaulted_inputs.is_empty() {
        eprintln!(
            "not in the VCD, run as 0: {}",
            v.defaulted_inputs.join(", ")
        );
    }
    if !v.not_compared.is_empty() {
        eprintln!(
            "not in the VCD, not compared: {}",
            v.not_compared.join(", ")
        );
    }
    if v.mismatches == 0 {
        println!("PASS: {} cycles, {} values compared", v.cycles, v.values);
        return Ok(());
    }
    println!(
        "FAIL: {} of {} values differ over {} cycles; the first:",
        v.mismatches, v.values, v.cycles
    );
    println!(
        "{:>10} {:>16} {:<18} {:>22} {:>22}",
        "cycle",
        format!("time ({})", v.timescale),
        "port",
        "expected",
        "got"
    );
    for m in &v.first {
        println!(
            "{:>10} {:>16} {:<18} {:>22} {:>22}",
            m.cycle, m.time, m.port, m.expected, m.got
        );
    }
    Err((1, format!("{} mismatches against the model", v.mismatches)))
}
