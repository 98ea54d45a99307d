// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed bode`: measured and model gain and phase of a speed estimator (the paper's VCO
//! experiment in simulation), CSV on stdout (and --csv), a summary on stderr, an SVG figure.

use clap::Args;
use std::path::{Path, PathBuf};
use std::time::Instant;

use super::Outcome;

/// Options of `encspeed bode`.
#[derive(Args)]
pub struct BodeArgs {
    /// pc (pulse count), et (elapsed time), n3 (Rairán, bit-true core) or mt (M/T).
    #[arg(long, value_parser = ["pc", "et", "n3", "mt"])]
    estimator: String,
    /// float: PC, ET, M/T as float estimators; hardware: the core's speed_pc,
    /// speed_et, speed_mt read at baseline_strobe (x1/x2/x4 as --edges, model delayed
    /// by the hardware latency) [default float; n3: hardware, its only source].
    #[arg(long, value_parser = ["float", "hardware"])]
    source: Option<String>,
    /// Lines of the disc.
    #[arg(long)]
    lines: u32,
    /// Edges counted per line, 1, 2 or 4 (R = lines·edges) [default 4; n3: 1].
    #[arg(long)]
    edges: Option<u32>,
    /// Mean speed, r/min.
    #[arg(long, allow_negative_numbers = true)]
    rpm: f64,
    /// Control sample time T_s, s (for n3 also dt).
    #[arg(long, allow_negative_numbers = true)]
    ts_s: f64,
    /// Clock of the float ET/M/T timestamps, or of the core (n3, --source hardware),
    /// Hz [default 100e6; on the core 10e6].
    #[arg(long, allow_negative_numbers = true)]
    clock_hz: Option<f64>,
    /// Modulation depth ñ/n̄ [default 0.02; n3: 0.2].
    #[arg(long, allow_negative_numbers = true)]
    amplitude: Option<f64>,
    /// Relative detuning ε of the simulated mean speed [default √2·10⁻³].
    #[arg(long, allow_negative_numbers = true)]
    detune: Option<f64>,
    /// Lowest frequency, Hz [default 1/(1000 T_s)].
    #[arg(long, allow_negative_numbers = true)]
    fmin: Option<f64>,
    /// Highest frequency, Hz, below 1/(2 T_s) [default 0.45/T_s].
    #[arg(long, allow_negative_numbers = true)]
    fmax: Option<f64>,
    /// Number of frequencies, log-spaced.
    #[arg(long, default_value_t = 25)]
    points: u32,
    /// Least number of samples in each analysis window [default 4000].
    #[arg(long)]
    min_samples: Option<u32>,
    /// Write the CSV here too.
    #[arg(long)]
    csv: Option<PathBuf>,
    /// Draw the Bode figure (SVG) here.
    #[arg(long)]
    svg: Option<PathBuf>,
    /// Caption of the figure [default: the operating point].
    #[arg(long)]
    title: Option<String>,
}

/// `encspeed bode`: the options as a `BodeSpec` and a frequency range, then the sweep.
pub fn run(args: BodeArgs) -> Outcome {
    use golden::freqresp::{BodeSpec, Source};
    let BodeArgs {
        estimator,
        source,
        lines,
        edges,
        rpm,
        ts_s,
        clock_hz,
        amplitude,
        detune,
        fmin,
        fmax,
        points,
        min_samples,
        csv,
        svg,
        title,
    } = args;
    let source = match source.as_deref().map(str::parse::<Source>).transpose() {
        Ok(s) => s,
        Err(e) => return Err((2, format!("bode: --{e}"))),
    };
    let mut spec = match (estimator.parse(), source) {
        (Ok(e), Some(Source::Hardware)) => BodeSpec::hardware(e, lines, rpm, ts_s),
        (Ok(e), Some(Source::Float)) => BodeSpec {
            source: Source::Float,
            ..BodeSpec::new(e, lines, rpm, ts_s)
        },
        (Ok(e), None) => BodeSpec::new(e, lines, rpm, ts_s),
        (Err(e), _) => return Err((2, format!("bode: --{e}"))),
    };
    spec.edges = edges.unwrap_or(spec.edges);
    spec.clock_hz = clock_hz.unwrap_or(spec.clock_hz);
    spec.amplitude = amplitude.unwrap_or(spec.amplitude);
    spec.detune = detune.unwrap_or(spec.detune);
    spec.min_samples = min_samples.unwrap_or(spec.min_samples);
    bode(
        spec,
        (
            fmin.unwrap_or(1e-3 / ts_s),
            fmax.unwrap_or(0.45 / ts_s),
            points,
        ),
        csv.as_deref(),
        svg.as_deref(),
        title,
    )
}

/// `encspeed bode`: sweep, CSV on stdout (and `csv`), summary on stderr, SVG to `svg`.
fn bode(
    spec: golden::freqresp::BodeSpec,
    (fmin, fmax, points): (f64, f64, u32),
    csv: Option<&Path>,
    svg: Option<&Path>,
    title: Option<String>,
) -> Outcome {
    use golden::freqresp::{log_spaced, to_csv, Estimator, Experiment};
    let bad = |e: golden::freqresp::FreqRespError| (2, format!("bode: --{e}"));
    let exp = Experiment::new(spec).map_err(bad)?;
    let freqs = log_spaced(fmin, fmax, points).map_err(bad)?;
    // Every frequency is validated before anything runs.
    for &f in &freqs {
        exp.plan(f).map_err(bad)?;
    }
    let t = Instant::now();
    let points = exp.sweep(&freqs).map_err(bad)?;
    let text = to_csv(&points);
    print!("{text}");
    let write = |path: &Path, what: &str, bytes: &str| -> Outcome {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|e| (1, format!("{}: {e}", dir.display())))?;
        }
        std::fs::write(path, bytes)
            .map_err(|e| (1, format!("cannot write {what} {}: {e}", path.display())))
    };
    if let Some(path) = csv {
        write(path, "CSV", &text)?;
    }
    let s = exp.spec();
    let op = exp.operating_point();
    let r_name = if s.estimator == Estimator::N3 {
        format!("{} lines, r = {:.4} pulses/dt", s.lines, op.l())
    } else {
        format!(
            "R = {} ({}x{}), l = {:.4} tr./Ts",
            op.transitions_per_rev(),
            s.lines,
            s.edges,
            op.l()
        )
    };
    // The hardware baselines: where they are read and how late (the model includes it).
    let hw = exp
        .hardware_latency_cycles()
        .map(|d| format!(" (hardware, {} MHz, latency {d} cycles)", s.clock_hz / 1e6));
    let caption = title.unwrap_or_else(|| {
        format!(
            "{}{}: {r_name}, {} r/min, Ts = {} ms",
            s.estimator.name().to_uppercase(),
            hw.as_deref().unwrap_or(""),
            s.rpm,
            s.ts_s * 1e3
        )
    });
    if let Some(path) = svg {
        let others = exp.comparison_models();
        let fig = tb::freqresp::BodeFigure {
            title: caption.clone(),
            model: exp.model(),
            others: &others,
            measured: &points,
            fmin_hz: fmin / 1.25,
            fmax_hz: fmax * 1.25,
        };
        tb::freqresp::draw_svg(path, &fig).map_err(|e| (1, e))?;
    }
    let quarter = 0.25 / s.ts_s;
    let max_abs = |it: &mut dyn Iterator<Item = f64>| it.fold(0.0f64, |a, v| a.max(v.abs()));
    let upto = |m: &&golden::freqresp::Measurement| m.f_hz <= quarter * (1.0 + 1e-9);
    eprintln!(
        "{caption}: model {}; simulated {:.4} r/min, amplitude {} of it, T_e = {:.6e} s; \
         {} points in {:.1} s; max |phase error| {:.3} deg up to fs/4 ({:.3} deg overall), \
         max |gain error| {:.3} dB up to fs/4",
        exp.model().name(),
        op.speed_rpm(),
        s.amplitude,
        op.te_s(),
        points.len(),
        t.elapsed().as_secs_f64(),
        max_abs(&mut points.iter().filter(upto).map(|m| m.phase_error_deg())),
        max_abs(&mut points.iter().map(|m| m.phase_error_deg())),
        max_abs(&mut points.iter().filter(upto).map(|m| m.gain_error_db())),
    );
    Ok(())
}
