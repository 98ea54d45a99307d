// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed accuracy`: the constant-speed accuracy sweep of every estimator of the
//! bit-true core, CSV on stdout, a summary on stderr, the figure as SVG.

use clap::Args;
use std::path::{Path, PathBuf};
use std::time::Instant;

use super::Outcome;

/// Options of `encspeed accuracy`.
#[derive(Args)]
pub struct AccuracyArgs {
    /// Number of speeds, log-spaced from 0.01 to 1000 ω_lim, both ends included.
    #[arg(long, default_value_t = tb::accuracy::DEFAULT_POINTS)]
    points: usize,
    /// Decoding of the core: x1, x2 or x4.
    #[arg(long, default_value = "x1", value_parser = ["x1", "x2", "x4"])]
    mode: String,
    /// Draw the figure (SVG) here.
    #[arg(long, default_value = "target/figures/accuracy_estimators.svg")]
    svg: PathBuf,
    /// Worker threads [default: the machine's parallelism].
    #[arg(long)]
    threads: Option<usize>,
}

/// `encspeed accuracy`.
pub fn run(args: &AccuracyArgs) -> Outcome {
    accuracy(args.points, &args.mode, &args.svg, args.threads)
}

/// `encspeed accuracy`: the constant-speed sweep of `tb::accuracy`, CSV on stdout, a
/// summary on stderr, the figure to `svg`.
fn accuracy(points: usize, mode: &str, svg: &Path, threads: Option<usize>) -> Outcome {
    use tb::accuracy::{
        default_threads, draw_svg, log_speeds, sweep, to_csv, worst, Setup, R_MAX, R_MIN,
    };
    if points < 2 {
        return Err((2, format!("accuracy: --points = {points}: at least 2")));
    }
    if threads == Some(0) {
        return Err((2, "accuracy: --threads = 0: at least 1".into()));
    }
    let cfg_mode = match mode {
        "x1" => 0,
        "x2" => 1,
        _ => 2,
    };
    let setup = Setup::standard(cfg_mode);
    let speeds = log_speeds(points, R_MIN, R_MAX);
    let t = Instant::now();
    let results = sweep(&setup, &speeds, threads.unwrap_or_else(default_threads));
    let secs = t.elapsed().as_secs_f64();
    print!("{}", to_csv(&setup, &results));
    let title = format!(
        "Max relative error at constant speed, {} ({} MHz clock, {} lines, dt = {} cycles, F = 16)",
        setup.mode_name(),
        setup.clock_hz / 1e6,
        setup.lines,
        setup.dt_cycles
    );
    draw_svg(svg, &title, &setup, &results).map_err(|e| (1, e))?;
    let cycles: u64 = results.iter().map(|p| p.cycles).sum();
    eprintln!(
        "{} speeds {R_MIN}..{R_MAX} ω_lim ({} r/min per ω_lim), {}: {cycles} cycles in {secs:.1} s; figure {}",
        results.len(),
        setup.omega_lim_rps() * 60.0,
        setup.mode_name(),
        svg.display()
    );
    for w in worst(&results) {
        eprintln!(
            "  {:<3} max relative error {:.3e} (r = {:.4}), max error/bound {:.4} (r = {:.4})",
            w.est.name(),
            w.max_err,
            w.max_err_r,
            w.max_ratio,
            w.max_ratio_r
        );
    }
    Ok(())
}
