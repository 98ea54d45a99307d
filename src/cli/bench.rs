//! `encspeed bench`: simulation speed (cycles/s) of the golden model, rust-hdl and
//! Verilator on the same stimulus.

use clap::Args;
use golden::params::Params;
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
    Ok(())
}
