// SPDX-License-Identifier: MIT OR Apache-2.0
//! Why a small-signal quantity was refused.

use std::fmt;

/// Most points [`log_frequencies`](super::log_frequencies) returns.
pub const MAX_FREQUENCIES: usize = 1_000_000;

/// Why a small-signal quantity was refused. Each message names the parameter and the
/// legal range.
#[derive(Clone, Debug, PartialEq)]
pub enum SmallSignalError {
    /// The resolution R (transitions per revolution) is zero.
    ZeroResolution,
    /// Edges counted per line is not 1, 2 or 4 (x1, x2 or quadrature x4 decoding).
    EdgesPerLine(u32),
    /// lines · edges_per_line does not fit R (u32).
    ResolutionOverflow {
        /// Lines of the disc.
        lines: u32,
        /// Edges counted per line.
        edges_per_line: u32,
    },
    /// The speed n̄ (r/min) is NaN, infinite, zero or negative. The models linearise around
    /// a moving shaft; direction is irrelevant to them, so pass |n̄|.
    Speed(f64),
    /// The control sample time T_s (s) is NaN, infinite, zero or negative.
    SampleTime(f64),
    /// The values are legal one by one but T_e = 60/(n̄·R) or l = n̄·R·T_s/60 overflows to
    /// infinity or underflows to zero.
    Degenerate {
        /// T_e in seconds as computed.
        te_s: f64,
        /// l in transitions per T_s as computed.
        l: f64,
    },
    /// The PC model (eq. 15) is valid for L ≥ 1 transition per T_s only (the paper, after
    /// eq. 15); below that the PC estimator reads zero in most samples.
    PcBelowOneTransition {
        /// l in transitions per T_s.
        l: f64,
    },
    /// A time constant of a [`Factor`](super::Factor) (s) is NaN, infinite, zero or negative.
    Time {
        /// Which time constant.
        name: &'static str,
        /// Its value in seconds.
        value: f64,
    },
    /// The moving-average length L of a [`Factor::MovingAverage`](super::Factor::MovingAverage) is NaN, infinite or < 1.
    MovingAverageLength(f64),
    /// The lead coefficients do not satisfy 0 < α < β (both finite).
    LeadCoefficients {
        /// α (zero at α/T_e rad/s).
        alpha: f64,
        /// β (pole at β/T_e rad/s).
        beta: f64,
    },
    /// A frequency (Hz) is NaN, infinite or negative.
    Frequency(f64),
    /// A logarithmic frequency range is not 0 < lo < hi (finite) with ≥ 1 point per decade
    /// and fewer than [`MAX_FREQUENCIES`] points in all.
    FrequencyRange {
        /// Lowest frequency (Hz).
        lo_hz: f64,
        /// Highest frequency (Hz).
        hi_hz: f64,
        /// Points per decade.
        points_per_decade: u32,
    },
}

impl fmt::Display for SmallSignalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use SmallSignalError as E;
        match self {
            E::ZeroResolution => write!(
                f,
                "resolution R = 0: need at least one transition per revolution"
            ),
            E::EdgesPerLine(v) => write!(f, "edges_per_line = {v}: must be 1, 2 or 4"),
            E::ResolutionOverflow {
                lines,
                edges_per_line,
            } => write!(
                f,
                "lines = {lines} x edges_per_line = {edges_per_line} overflows R (u32)"
            ),
            E::Speed(v) => write!(
                f,
                "speed = {v} r/min: must be a finite speed > 0 (pass |n|; the model \
                 linearises around a moving shaft)"
            ),
            E::SampleTime(v) => write!(f, "ts = {v} s: must be a finite time > 0 s"),
            E::Degenerate { te_s, l } => write!(
                f,
                "operating point out of range: T_e = {te_s} s, l = {l} tr./T_s (both must be \
                 finite and > 0)"
            ),
            E::PcBelowOneTransition { l } => write!(
                f,
                "PC model needs l >= 1 transition per T_s (paper, after eq. 15); here l = {l}"
            ),
            E::Time { name, value } => {
                write!(f, "{name} = {value} s: must be a finite time > 0 s")
            }
            E::MovingAverageLength(v) => {
                write!(f, "moving-average length L = {v}: must be finite and >= 1")
            }
            E::LeadCoefficients { alpha, beta } => write!(
                f,
                "lead coefficients alpha = {alpha}, beta = {beta}: need 0 < alpha < beta, \
                 both finite"
            ),
            E::Frequency(v) => write!(f, "frequency = {v} Hz: must be finite and >= 0 Hz"),
            E::FrequencyRange {
                lo_hz,
                hi_hz,
                points_per_decade,
            } => write!(
                f,
                "frequency range {lo_hz}..{hi_hz} Hz with {points_per_decade} points per \
                 decade: need 0 < lo < hi, both finite, >= 1 point per decade and fewer than \
                 {MAX_FREQUENCIES} points"
            ),
        }
    }
}

impl std::error::Error for SmallSignalError {}
