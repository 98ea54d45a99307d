// SPDX-License-Identifier: MIT OR Apache-2.0
//! Frequency grids and the CSV the `bode` command writes.

use super::experiment::*;
use super::spec::*;
use std::fmt::Write as _;

/// `points` frequencies from `fmin_hz` to `fmax_hz`, logarithmically spaced, both ends
/// exact (one point when fmin = fmax).
pub fn log_spaced(fmin_hz: f64, fmax_hz: f64, points: u32) -> Result<Vec<f64>, FreqRespError> {
    let ok = fmin_hz.is_finite()
        && fmax_hz.is_finite()
        && fmin_hz > 0.0
        && fmax_hz >= fmin_hz
        && (1..=10_000).contains(&points)
        && ((fmax_hz > fmin_hz) == (points > 1));
    if !ok {
        return Err(FreqRespError::Sweep {
            fmin_hz,
            fmax_hz,
            points,
        });
    }
    if points == 1 {
        return Ok(vec![fmin_hz]);
    }
    let ratio = (fmax_hz / fmin_hz).ln();
    let last = f64::from(points - 1);
    let mut f: Vec<f64> = (0..points - 1)
        .map(|i| fmin_hz * (ratio * f64::from(i) / last).exp())
        .collect();
    f.push(fmax_hz);
    Ok(f)
}

/// First line of [`to_csv`].
pub const CSV_HEADER: &str = "f_hz,model_gain_db,model_phase_deg,measured_gain_db,\
measured_phase_deg,gain_error_db,phase_error_deg";

/// Formatted with a lone minus sign on a zero removed (deterministic text).
pub(crate) fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_owned(),
        _ => s,
    }
}

/// CSV of a sweep: [`CSV_HEADER`], then per point the measured frequency (Hz, 9
/// significant digits), the model's gain (dB) and phase (°), the measured gain and phase,
/// and their differences, 4 decimals; `\n` line ends.
pub fn to_csv(points: &[Measurement]) -> String {
    let mut out = String::from(CSV_HEADER);
    out.push('\n');
    for m in points {
        let _ = writeln!(
            out,
            "{:.8e},{},{},{},{},{},{}",
            m.f_hz,
            fixed(m.model.gain_db, 4),
            fixed(m.model.phase_deg, 4),
            fixed(m.gain_db, 4),
            fixed(m.phase_deg, 4),
            fixed(m.gain_error_db(), 4),
            fixed(m.phase_error_deg(), 4),
        );
    }
    out
}
