// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bode data (frequency, gain, phase) and its CSV form.

use super::error::{SmallSignalError, MAX_FREQUENCIES};
use std::fmt::Write as _;

/// One frequency of a Bode plot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodePoint {
    /// Frequency f in Hz (s = j2πf).
    pub freq_hz: f64,
    /// |H(j2πf)|, dimensionless.
    pub gain: f64,
    /// 20·log10|H| in dB (−∞ at a zero of the gain).
    pub gain_db: f64,
    /// ∠H in degrees: the continuous phase of the model's factors plus 180° where their
    /// product of real amplitudes is negative. Never wrapped by 360°, so pure delays show
    /// their whole linear lag; a simple zero on the jω axis steps the phase by +180°.
    pub phase_deg: f64,
}

/// Gain and phase of one model over a frequency vector.
#[derive(Clone, Debug, PartialEq)]
pub struct Bode {
    /// The model's name (see [`super::Model::name`]).
    pub name: String,
    /// One point per frequency, in the order the frequencies were given.
    pub points: Vec<BodePoint>,
}

/// `format!` output with a lone minus sign on a zero removed, so that −0.0 and values
/// that round to zero print the same as +0.0 on every run.
fn normalise(s: String) -> String {
    if let Some(rest) = s.strip_prefix('-') {
        let mantissa = rest.split('e').next().unwrap_or(rest);
        if mantissa.chars().all(|c| c == '0' || c == '.') {
            return rest.to_owned();
        }
    }
    s
}

impl Bode {
    /// First line of [`Bode::to_csv`].
    pub const CSV_HEADER: &'static str = "f_hz,gain,gain_db,phase_deg";

    /// CSV: [`Bode::CSV_HEADER`], then one line per point: f (Hz) and the linear gain in
    /// scientific notation with 9 significant digits (`1.22500000e1`), gain in dB and
    /// phase in degrees with 6 decimals; `-inf` for the dB of a zero gain; '\n' line ends.
    /// Rust's float formatting is exact and locale-free, so the text is deterministic.
    pub fn to_csv(&self) -> String {
        let mut out = String::with_capacity(48 * (self.points.len() + 1));
        out.push_str(Self::CSV_HEADER);
        out.push('\n');
        for p in &self.points {
            // Writing to a String cannot fail.
            let _ = writeln!(
                out,
                "{},{},{},{}",
                normalise(format!("{:.8e}", p.freq_hz)),
                normalise(format!("{:.8e}", p.gain)),
                normalise(format!("{:.6}", p.gain_db)),
                normalise(format!("{:.6}", p.phase_deg)),
            );
        }
        out
    }
}

/// Logarithmically spaced frequencies from `lo_hz` to `hi_hz` (both included, exactly),
/// with at least `points_per_decade` points per decade: n = ⌈ppd·log10(hi/lo)⌉ intervals
/// of equal ratio. Refused if that is more than [`MAX_FREQUENCIES`] points.
pub fn log_frequencies(
    lo_hz: f64,
    hi_hz: f64,
    points_per_decade: u32,
) -> Result<Vec<f64>, SmallSignalError> {
    let ok = lo_hz.is_finite()
        && hi_hz.is_finite()
        && lo_hz > 0.0
        && hi_hz > lo_hz
        && points_per_decade >= 1;
    // Checked before allocating: 600 decades at u32::MAX per decade would not fit memory.
    let intervals = f64::from(points_per_decade) * (hi_hz / lo_hz).log10();
    if !ok || intervals.ceil() >= MAX_FREQUENCIES as f64 {
        return Err(SmallSignalError::FrequencyRange {
            lo_hz,
            hi_hz,
            points_per_decade,
        });
    }
    let decades = (hi_hz / lo_hz).log10();
    // Finite, ≥ 1 and < MAX_FREQUENCIES by the checks above.
    let n = intervals.ceil().max(1.0) as usize;
    let mut f: Vec<f64> = (0..n)
        .map(|k| lo_hz * 10f64.powf(decades * k as f64 / n as f64))
        .collect();
    // The last point is set rather than computed so that it is exactly hi_hz.
    f.push(hi_hz);
    Ok(f)
}
