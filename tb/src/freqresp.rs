// SPDX-License-Identifier: MIT OR Apache-2.0
//! The frequency response of the core's estimators measured on the emitted Verilog, and
//! Bode figures.
//!
//! [`measure_on_verilog`] runs the plan of a [`golden::freqresp::Experiment`] on the core
//! (n3, or PC, ET, M/T with [`golden::freqresp::Source::Hardware`]: the outputs
//! `speed_pc`, `speed_et`, `speed_mt` read at `baseline_strobe`) through the Verilog that
//! ships (`hdl::emit_core`, compiled by Verilator), checks that every cycle of every
//! output equals the bit-true model, and analyses the outputs with the same code as the
//! golden measurement; so the gain and phase are those of the hardware, and equal to the
//! golden ones bit for bit. [`draw_svg`] draws a Bode figure (gain and phase against log f, models
//! as lines, measurements as markers) with plotters' SVG backend (no fonts needed).

use crate::cosim::{first_mismatch, run_golden};
use crate::verilator::Verilated;
use golden::freqresp::{Experiment, FreqModel, Measurement};
use plotters::prelude::*;
use std::path::Path;

/// Compile the emitted Verilog of an experiment's core (cached by content).
pub fn verilated_for(exp: &Experiment) -> Result<Verilated, String> {
    let p = exp.core_params().ok_or_else(|| {
        format!(
            "{} on source {} has no core",
            exp.spec().estimator,
            exp.spec().source
        )
    })?;
    Verilated::build(&hdl::emit_core(p).verilog)
}

/// Measure an experiment on the core at `f_hz` on the emitted Verilog: the same per-cycle
/// inputs as the golden measurement (`cfg_mode` included), every output of every cycle
/// checked against the bit-true model (an error names the first differing cycle), then
/// the same reading of the outputs (cycle k·dt + `read_offset_cycles`) and the same
/// analysis. The result equals `exp.measure(f_hz)` exactly when the hardware is right.
pub fn measure_on_verilog(
    exp: &Experiment,
    sim: &Verilated,
    f_hz: f64,
) -> Result<Measurement, String> {
    let p = exp
        .core_params()
        .ok_or_else(|| "measure_on_verilog: the experiment is not on the core".to_string())?;
    let plan = exp.plan(f_hz).map_err(|e| e.to_string())?;
    let inputs = exp.core_inputs(&plan);
    let out = sim.run(&inputs, None)?;
    let golden = run_golden(p, &inputs);
    if let Some((k, e, g)) = first_mismatch(&golden, &out) {
        return Err(format!(
            "Verilator differs from the golden model at cycle {k} of {}: {e:?} vs {g:?}",
            inputs.len()
        ));
    }
    let y = exp.outputs_from_core(&plan, &out);
    Ok(exp.analyse(&plan, &y))
}

/// What a Bode figure shows.
#[derive(Clone, Debug)]
pub struct BodeFigure<'a> {
    /// Caption above the gain panel.
    pub title: String,
    /// The model the measurement is compared with (solid line).
    pub model: &'a FreqModel,
    /// Other models (dashed lines).
    pub others: &'a [FreqModel],
    /// Measured points (markers).
    pub measured: &'a [Measurement],
    /// Frequency axis from this (Hz) …
    pub fmin_hz: f64,
    /// … to this (Hz).
    pub fmax_hz: f64,
}

/// Lowest gain drawn (dB); anything below is drawn at this level.
pub const GAIN_FLOOR_DB: f64 = -60.0;

const COLOURS: [RGBColor; 4] = [
    RGBColor(0, 110, 60),
    RGBColor(230, 140, 0),
    RGBColor(120, 60, 170),
    RGBColor(110, 110, 110),
];

/// Draw `fig` into an SVG file at `path` (900 × 720 px): gain (dB) above, phase (°) below,
/// both against log f. Deterministic: the same figure gives the same bytes.
pub fn draw_svg(path: &Path, fig: &BodeFigure<'_>) -> Result<(), String> {
    if !(fig.fmin_hz > 0.0 && fig.fmax_hz > fig.fmin_hz) {
        return Err(format!(
            "draw_svg: frequency range {}..{} Hz",
            fig.fmin_hz, fig.fmax_hz
        ));
    }
    let svg = render(fig).map_err(|e| format!("draw_svg: {e}"))?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(path, svg).map_err(|e| format!("{}: {e}", path.display()))
}

type DrawResult<T> = Result<T, Box<dyn std::error::Error>>;

/// 400 log-spaced frequencies over the axis, for the model lines.
fn dense(fig: &BodeFigure<'_>) -> Vec<f64> {
    let (lo, hi) = (fig.fmin_hz.ln(), fig.fmax_hz.ln());
    (0..400)
        .map(|i| (lo + (hi - lo) * f64::from(i) / 399.0).exp())
        .collect()
}

/// Axis range around `values` with a margin, the lower end at least `floor`.
fn range(values: impl Iterator<Item = f64>, floor: f64, margin: f64) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite()) {
        lo = lo.min(v.max(floor));
        hi = hi.max(v.max(floor));
    }
    if !lo.is_finite() {
        return (-1.0, 1.0);
    }
    (lo - margin, hi + margin)
}

/// Frequency tick labels at 1, 2 and 5 times a power of ten only (the log axis has a
/// tick at every integer multiple), without trailing zeros.
fn tick_label(v: &f64) -> String {
    let decade = 10f64.powf(v.log10().floor());
    let mantissa = v / decade;
    if [1.0, 2.0, 5.0, 10.0]
        .iter()
        .any(|m| (mantissa - m).abs() < 1e-6)
    {
        let s = format!("{:.3}", v);
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        String::new()
    }
}

fn render(fig: &BodeFigure<'_>) -> DrawResult<String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 720)).into_drawing_area();
        root.fill(&WHITE)?;
        let (top, bottom) = root.split_vertically(340);
        let freqs = dense(fig);
        let models: Vec<&FreqModel> = std::iter::once(fig.model).chain(fig.others).collect();
        let curves: Vec<Vec<(f64, f64, f64)>> = models
            .iter()
            .map(|m| {
                freqs
                    .iter()
                    .map(|&f| {
                        let p = m.at(f);
                        (f, p.gain_db, p.phase_deg)
                    })
                    .collect()
            })
            .collect();
        // The axes follow the main model and the measurement; the other models are clipped.
        let gains = curves[0]
            .iter()
            .map(|c| c.1)
            .chain(fig.measured.iter().map(|m| m.gain_db));
        let (g_lo, g_hi) = range(gains, GAIN_FLOOR_DB, 2.0);
        let phases = curves[0]
            .iter()
            .map(|c| c.2)
            .chain(fig.measured.iter().map(|m| m.phase_deg));
        let (p_lo, p_hi) = range(phases, f64::NEG_INFINITY, 10.0);
        let x = (fig.fmin_hz..fig.fmax_hz).log_scale();
        let label = |m: &FreqModel| m.name();

        let mut gain = ChartBuilder::on(&top)
            .caption(&fig.title, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(60)
            .build_cartesian_2d(x.clone(), g_lo..g_hi)?;
        gain.configure_mesh()
            .light_line_style(WHITE)
            .x_label_formatter(&tick_label)
            .y_desc("gain (dB)")
            .x_desc("f (Hz)")
            .draw()?;
        let mut phase = ChartBuilder::on(&bottom)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x, p_lo..p_hi)?;
        phase
            .configure_mesh()
            .light_line_style(WHITE)
            .x_label_formatter(&tick_label)
            .y_desc("phase (deg)")
            .x_desc("f (Hz)")
            .draw()?;

        let clip = |v: f64, lo: f64, hi: f64| if v.is_finite() { v.clamp(lo, hi) } else { lo };
        for (i, (m, curve)) in models.iter().zip(&curves).enumerate() {
            let g: Vec<(f64, f64)> = curve.iter().map(|c| (c.0, clip(c.1, g_lo, g_hi))).collect();
            let p: Vec<(f64, f64)> = curve.iter().map(|c| (c.0, clip(c.2, p_lo, p_hi))).collect();
            if i == 0 {
                let style = BLUE.stroke_width(2);
                gain.draw_series(LineSeries::new(g, style))?
                    .label(label(m))
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
                phase.draw_series(LineSeries::new(p, style))?;
            } else {
                let c = COLOURS[(i - 1) % COLOURS.len()];
                let style = c.stroke_width(1);
                gain.draw_series(DashedLineSeries::new(g, 6, 4, style))?
                    .label(label(m))
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
                phase.draw_series(DashedLineSeries::new(p, 6, 4, style))?;
            }
        }
        let marker = RED.filled();
        gain.draw_series(
            fig.measured
                .iter()
                .map(|m| Circle::new((m.f_hz, clip(m.gain_db, g_lo, g_hi)), 3, marker)),
        )?
        .label("measured (simulation)")
        .legend(move |(x, y)| Circle::new((x + 10, y), 3, marker));
        phase.draw_series(
            fig.measured
                .iter()
                .map(|m| Circle::new((m.f_hz, clip(m.phase_deg, p_lo, p_hi)), 3, marker)),
        )?;
        gain.configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
    }
    Ok(svg)
}
