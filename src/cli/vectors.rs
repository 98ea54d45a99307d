// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed vectors`: the bit-true model on a stimulus (CSV or VCD), every output port of
//! the top written as CSV or as a VCD. The conventions are in docs/reference-model.md.

use clap::Args;
use golden::params::Params;
use golden::reference::expected::{run_stimulus, CsvExpected, ExpectedSink, VcdExpected};
use golden::reference::stimulus::{CsvStimulus, StimulusResult, VcdStimulus};
use golden::reference::{RefTop, Reference};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use super::check::{parse_map, VcdSelection};
use super::spec::SpecArgs;
use super::Outcome;

/// Options of `encspeed vectors`.
#[derive(Args)]
pub struct VectorsArgs {
    #[command(flatten)]
    spec: SpecArgs,
    /// The stimulus: a CSV (`cycle,reset,enc_a,...`, one row per change) or a VCD whose
    /// clock's rising edges sample the inputs (by the file's extension).
    #[arg(long, value_name = "FILE")]
    stimulus: PathBuf,
    /// The expected outputs: a CSV (a row at every change) or a VCD (by the extension).
    #[arg(long, value_name = "FILE")]
    out: PathBuf,
    /// The top whose outputs are written: core (encspeed_core) or ecc (encspeed_ecc).
    #[arg(long, default_value = "core", value_parser = ["core", "ecc"])]
    top: String,
    #[command(flatten)]
    vcd: VcdSelection,
}

/// A file's format, by its extension.
fn is_vcd(path: &Path) -> Result<bool, (u8, String)> {
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("vcd") => Ok(true),
        Some(e) if e.eq_ignore_ascii_case("csv") => Ok(false),
        _ => Err((2, format!("{}: give a .csv or a .vcd file", path.display()))),
    }
}

/// `encspeed vectors`.
pub fn run(args: &VectorsArgs) -> Outcome {
    args.spec.run(|p| vectors(p, args))
}

fn vectors(p: &Params, args: &VectorsArgs) -> Outcome {
    let top = RefTop::parse(&args.top).map_err(|e| (2, e))?;
    let mut model = Reference::new(p, top).map_err(|e| (2, e))?;
    let open = |path: &Path| File::open(path).map_err(|e| (2, format!("{}: {e}", path.display())));
    let stimulus_file = open(&args.stimulus)?;
    let stimulus: Box<dyn Iterator<Item = StimulusResult>> = if is_vcd(&args.stimulus)? {
        let map = parse_map(&args.vcd.map).map_err(|e| (2, e))?;
        let s = VcdStimulus::new(
            stimulus_file,
            model.inputs(),
            args.vcd.scope.as_deref(),
            &map,
        )
        .map_err(|e| (2, format!("{}: {e}", args.stimulus.display())))?;
        let (scope, defaulted) = s.found();
        eprintln!("stimulus: scope {scope}");
        if !defaulted.is_empty() {
            eprintln!(
                "stimulus: not in the VCD, run as 0: {}",
                defaulted.join(", ")
            );
        }
        Box::new(s)
    } else {
        Box::new(
            CsvStimulus::new(stimulus_file, model.inputs())
                .map_err(|e| (2, format!("{}: {e}", args.stimulus.display())))?,
        )
    };
    if let Some(dir) = args.out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| (1, format!("{}: {e}", dir.display())))?;
    }
    let out_err = |e: std::io::Error| (1, format!("{}: {e}", args.out.display()));
    let out = BufWriter::new(File::create(&args.out).map_err(out_err)?);
    let mut sink: Box<dyn ExpectedSink> = if is_vcd(&args.out)? {
        Box::new(
            VcdExpected::new(
                out,
                top.module(),
                p.clock_hz(),
                model.inputs(),
                model.outputs(),
            )
            .map_err(out_err)?,
        )
    } else {
        Box::new(CsvExpected::new(out, model.outputs()).map_err(out_err)?)
    };
    let cycles = run_stimulus(&mut model, stimulus, sink.as_mut()).map_err(|e| match e {
        Ok(msg) => (2, format!("{}: {msg}", args.stimulus.display())),
        Err(io) => out_err(io),
    })?;
    drop(sink);
    std::io::stdout().flush().ok();
    println!(
        "{}: {cycles} cycles of {} written to {}",
        args.stimulus.display(),
        top.module(),
        args.out.display()
    );
    Ok(())
}
