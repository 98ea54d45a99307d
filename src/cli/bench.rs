// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed bench`: simulation speed (cycles/s) of the golden model, rust-hdl and
//! Verilator on the same stimulus, and the speed of `encspeed check` on a VCD of it.

use clap::Args;
use golden::params::Params;
use golden::reference::bound::{check_bound, BoundOptions};
use golden::reference::expected::{run_stimulus, VcdExpected};
use golden::reference::stimulus::StimulusRow;
use golden::reference::verdict::{check_exact, CheckOptions};
use golden::reference::{RefTop, Reference};
use golden::top::core::CoreInputs;
use golden::top::port_fields::to_port_bits;
use golden::top::ports::{core_ports, cycle_inputs};
use std::time::Instant;

use super::spec::SpecArgs;
use super::Outcome;

/// Options of `encspeed bench`.
#[derive(Args)]
pub struct BenchArgs {
    #[command(flatten)]
    spec: SpecArgs,
    /// Cycles for the golden model and Verilator (rust-hdl runs a tenth of them).
    #[arg(long, default_value_t = 20_000_000)]
    cycles: u64,
}

/// `encspeed bench`.
pub fn run(args: &BenchArgs) -> Outcome {
    args.spec.run(|p| bench(p, args.cycles))
}

fn bench(p: &Params, cycles: u64) -> Outcome {
    // A square wave at 3.3 ω_lim: steady updates, the common case.
    let period = ((p.dt_cycles() as f64 / 3.3).round() as u64).max(2);
    let inputs = tb::stimulus::square_wave(period, 0, cycles as usize, p.dt_cycles());
    let t = Instant::now();
    let g = tb::cosim::run_golden(p, &inputs);
    let golden_rate = cycles as f64 / t.elapsed().as_secs_f64();
    let hdl_cycles = (cycles / 10) as usize;
    let t = Instant::now();
    let h = tb::cosim::run_hdl(p, &inputs[..hdl_cycles]);
    let hdl_rate = hdl_cycles as f64 / t.elapsed().as_secs_f64();
    if tb::cosim::first_mismatch(&g[..hdl_cycles], &h).is_some() {
        return Err((1, "rust-hdl differs from the golden model".into()));
    }
    let v = tb::verilator::Verilated::build(&hdl::emit_core(p).verilog).map_err(|e| (1, e))?;
    let verilator_rate = v.bench(cycles, period, p.dt_cycles()).map_err(|e| (1, e))?;
    println!(
        "configuration: {}-bit counters, dt = {} cycles, square wave of {period} cycles",
        p.counter_bits(),
        p.dt_cycles()
    );
    println!(
        "golden bit-true model        {:>12.0} cycles/s ({cycles} cycles)",
        golden_rate
    );
    println!(
        "rust-hdl direct drive        {:>12.0} cycles/s ({hdl_cycles} cycles)",
        hdl_rate
    );
    println!(
        "Verilator -O3 (emitted .v)   {:>12.0} cycles/s ({cycles} cycles)",
        verilator_rate
    );
    let check_cycles = cycles / 10;
    let (exact_rate, bound_rate, vcd_bytes) =
        check_rate(p, &inputs[..check_cycles as usize]).map_err(|e| (1, e))?;
    println!(
        "check --mode exact (VCD)     {:>12.0} cycles/s ({check_cycles} cycles, {:.0} MB VCD \
         of the ports)",
        exact_rate,
        vcd_bytes as f64 / 1e6
    );
    println!(
        "check --mode bound (VCD)     {:>12.0} cycles/s (the same VCD)",
        bound_rate
    );
    Ok(())
}

/// `encspeed check`'s speed: the model's own VCD of `inputs` (every port of the core, as
/// `encspeed vectors` writes it) under target/bench/, then the verdicts on it timed. Cycles/s
/// of exact and bound mode, and the VCD's size.
fn check_rate(p: &Params, inputs: &[CoreInputs]) -> Result<(f64, f64, u64), String> {
    let dir = tools::target_dir().join("bench");
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let path = dir.join("check.vcd");
    let mut model = Reference::new(p, RefTop::Core)?;
    let ports = cycle_inputs(&core_ports(p.counter_bits()));
    {
        let file = std::fs::File::create(&path).map_err(|e| e.to_string())?;
        let mut sink = VcdExpected::new(
            std::io::BufWriter::new(file),
            "encspeed_core",
            p.clock_hz(),
            model.inputs(),
            model.outputs(),
        )
        .map_err(|e| e.to_string())?;
        let rows = inputs.iter().enumerate().map(|(k, i)| {
            Ok(StimulusRow {
                cycle: k as u64,
                inputs: to_port_bits(i, &ports),
            })
        });
        run_stimulus(&mut model, rows, &mut sink).map_err(|e| format!("{e:?}"))?;
    }
    let bytes = std::fs::metadata(&path).map_err(|e| e.to_string())?.len();
    let mut model = Reference::new(p, RefTop::Core)?;
    let t = Instant::now();
    let file = std::fs::File::open(&path).map_err(|e| e.to_string())?;
    let v = check_exact(file, &mut model, &CheckOptions::default()).map_err(|e| e.0)?;
    let rate = v.cycles as f64 / t.elapsed().as_secs_f64();
    if v.mismatches != 0 {
        return Err(format!(
            "check found {} mismatches in the model's own VCD",
            v.mismatches
        ));
    }
    let t = Instant::now();
    let file = std::fs::File::open(&path).map_err(|e| e.to_string())?;
    let options = BoundOptions {
        scope: None,
        map: Vec::new(),
        frac_bits: golden::params::SPEED_FRAC_BITS,
        latency: 0,
        report: 0,
    };
    let b = check_bound(file, p, model.inputs(), model.outputs(), &options).map_err(|e| e.0)?;
    let bound_rate = b.cycles as f64 / t.elapsed().as_secs_f64();
    if b.violations() != 0 {
        return Err(format!(
            "check --mode bound found {} samples of the model outside their bounds",
            b.violations()
        ));
    }
    Ok((rate, bound_rate, bytes))
}
