// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed check`: a verdict on another implementation's VCD against the bit-true model.
//! Exit 0 with `PASS`, 1 with the first mismatches, 2 for a VCD that cannot be checked.

use clap::Args;
use golden::params::Params;
use golden::reference::bound::{check_bound, BoundOptions, BoundVerdict};
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
    /// exact: every output the VCD has, bit for bit against this core from the first
    /// reset. bound: each speed sample against the true speed the A/B edges imply, within
    /// the estimator's proven error bound (other formats and latencies pass).
    #[arg(long, default_value = "exact", value_parser = ["exact", "bound"])]
    mode: String,
    /// bound: fractional bits of the speed outputs (a value v is v/2^F lines per dt).
    #[arg(long, default_value_t = golden::params::SPEED_FRAC_BITS, value_parser = clap::value_parser!(u32).range(0..=64))]
    frac_bits: u32,
    /// bound: cycles the estimates may lag the window they measure, beyond one dt.
    #[arg(long, default_value_t = 0, value_name = "CYCLES")]
    latency: u64,
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
    if args.mode == "bound" {
        return bound(p, &model, args);
    }
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

/// `encspeed check --mode bound`.
fn bound(p: &Params, model: &Reference, args: &CheckArgs) -> Outcome {
    let options = BoundOptions {
        scope: args.selection.scope.clone(),
        map: parse_map(&args.selection.map).map_err(|e| (2, e))?,
        frac_bits: args.frac_bits,
        latency: args.latency,
        report: args.report,
    };
    let file = File::open(&args.vcd).map_err(|e| (2, format!("{}: {e}", args.vcd.display())))?;
    let v = check_bound(file, p, model.inputs(), model.outputs(), &options)
        .map_err(|e| (2, format!("{}: {e}", args.vcd.display())))?;
    eprintln!(
        "{}: scope {}, timescale {}, from the first reset (edge {}); {} stretches of constant speed",
        args.vcd.display(),
        v.scope,
        v.timescale,
        v.first_cycle,
        v.stretches
    );
    if !v.absent.is_empty() {
        eprintln!("not in the VCD, not judged: {}", v.absent.join(", "));
    }
    print_bound_table(&v);
    if v.samples() == 0 {
        return Err((
            2,
            "no speed sample lies in a stretch of constant speed long enough to judge it \
             (see docs/reference-model.md#bound-mode)"
                .into(),
        ));
    }
    if v.violations() == 0 {
        println!(
            "PASS: {} cycles, {} samples within their bounds",
            v.cycles,
            v.samples()
        );
        return Ok(());
    }
    println!(
        "FAIL: {} of {} samples outside their bounds; the first:",
        v.violations(),
        v.samples()
    );
    println!(
        "{:>10} {:>16} {:<10} {:>14} {:>14} {:>11} {:>11}",
        "cycle",
        format!("time ({})", v.timescale),
        "port",
        "got",
        "true speed",
        "error",
        "bound"
    );
    for m in &v.first {
        println!(
            "{:>10} {:>16} {:<10} {:>14.6} {:>14.6} {:>11.3e} {:>11.3e}",
            m.cycle, m.time, m.port, m.got, m.speed, m.error, m.bound
        );
    }
    Err((
        1,
        format!("{} samples outside their bounds", v.violations()),
    ))
}

/// Per estimator: samples, max and RMS relative error, max and RMS error/bound.
fn print_bound_table(v: &BoundVerdict) {
    println!(
        "{:<10} {:>8} {:>8} {:>11} {:>11} {:>10} {:>10} {:>8} {:>8}",
        "port", "sampled", "judged", "max err", "rms err", "max e/b", "rms e/b", "outside", "empty"
    );
    for s in &v.stats {
        println!(
            "{:<10} {:>8} {:>8} {:>11.3e} {:>11.3e} {:>10.4} {:>10.4} {:>8} {:>8}",
            s.estimator.port(),
            if s.strobed { "strobe" } else { "change" },
            s.samples,
            s.max_err,
            s.rms_err(),
            s.max_ratio,
            s.rms_ratio(),
            s.violations,
            s.empty
        );
    }
}
