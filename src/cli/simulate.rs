// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed simulate`: run a scenario or a custom motion through the rust-hdl design,
//! check it against the golden model on every cycle and write a VCD of every signal;
//! optionally the same on the emitted Verilog in Verilator.

use clap::Args;
use golden::params::Params;
use golden::top::core::CoreInputs;
use std::path::{Path, PathBuf};

use super::spec::SpecArgs;
use super::Outcome;

/// Options of `encspeed simulate`.
#[derive(Args)]
pub struct SimulateArgs {
    #[command(flatten)]
    spec: SpecArgs,
    /// Named scenario (see --list).
    #[arg(long, conflicts_with = "motion")]
    scenario: Option<String>,
    /// Custom motion, speeds in ω_lim and times in dt: e.g. `rest:2,ramp:0:3:10,hold:3:5`
    /// (segments hold:R:N, ramp:R0:R1:N, sine:MEAN:AMP:PERIOD:N, rest:N).
    #[arg(long)]
    motion: Option<String>,
    /// VCD of the rust-hdl simulation.
    #[arg(long, default_value = "target/waves/encspeed.vcd")]
    vcd: PathBuf,
    /// Also run the emitted Verilog in Verilator, check it, and write its VCD here.
    #[arg(long)]
    verilator_vcd: Option<PathBuf>,
    /// List the named scenarios and exit.
    #[arg(long)]
    list: bool,
}

/// `encspeed simulate`: the scenarios with `--list`, else the simulation.
pub fn run(args: &SimulateArgs) -> Outcome {
    if args.list {
        for s in tb::scenarios::all() {
            println!("{:<16} {}", s.name, s.description);
        }
        Ok(())
    } else {
        args.spec.run(|p| {
            simulate(
                p,
                args.scenario.as_deref(),
                args.motion.as_deref(),
                &args.vcd,
                args.verilator_vcd.as_deref(),
            )
        })
    }
}

fn simulate(
    p: &Params,
    scenario: Option<&str>,
    motion: Option<&str>,
    vcd: &Path,
    verilator_vcd: Option<&Path>,
) -> Outcome {
    let (name, segments) = match (scenario, motion) {
        (Some(n), None) => {
            let s = tb::scenarios::find(n).ok_or_else(|| {
                (
                    2,
                    format!("scenario `{n}` is unknown; `encspeed simulate --list` lists them"),
                )
            })?;
            (n.to_string(), s.segments().to_vec())
        }
        (None, Some(m)) => (
            "motion".to_string(),
            tb::scenarios::parse_motion(m).map_err(|e| (2, format!("motion: {e}")))?,
        ),
        _ => {
            return Err((
                2,
                "give --scenario NAME or --motion SEGMENTS (or --list)".into(),
            ))
        }
    };
    let profile = tb::scenarios::profile(&segments, p).map_err(|e| (2, format!("motion: {e}")))?;
    let inputs: Vec<CoreInputs> = tb::stimulus::from_profile(p, &profile, p.dt_cycles())
        .map_err(|e| (2, format!("motion: {e}")))?;
    let golden = tb::cosim::run_golden(p, &inputs);
    let hdl_out = tb::waves::simulate_to_vcd(p, &inputs, vcd)
        .map_err(|e| (1, format!("{}: {e}", vcd.display())))?;
    if let Some((k, e, g)) = tb::cosim::first_mismatch(&golden, &hdl_out) {
        return Err((
            1,
            format!("rust-hdl differs from the golden model at cycle {k}: {e:?} vs {g:?}"),
        ));
    }
    println!(
        "{name}: {} cycles; rust-hdl = golden on every cycle; VCD {}",
        inputs.len(),
        vcd.display()
    );
    if let Some(path) = verilator_vcd {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(|e| (1, e.to_string()))?;
        }
        let v = tb::verilator::Verilated::build(&hdl::emit_core(p).verilog).map_err(|e| (1, e))?;
        let out = v.run(&inputs, Some(path)).map_err(|e| (1, e))?;
        if let Some((k, e, g)) = tb::cosim::first_mismatch(&golden, &out) {
            return Err((
                1,
                format!("Verilator differs from the golden model at cycle {k}: {e:?} vs {g:?}"),
            ));
        }
        println!(
            "{name}: Verilator = golden on every cycle; VCD {}",
            path.display()
        );
    }
    let updates = golden.iter().filter(|o| o.update).count();
    let last = golden.last().copied().unwrap_or_default();
    println!(
        "{updates} updates; final Nep1 = {}, Ndt1 = {}, n3 = {:.6} ω_lim, true speed {:.6} ω_lim{}",
        last.nep,
        last.ndt,
        golden::ideal::n3(last.nep, last.ndt),
        profile.speed(profile.duration() - p.ts_s()) / p.omega_lim_rps(),
        if last.stalled { " (stalled)" } else { "" }
    );
    Ok(())
}
