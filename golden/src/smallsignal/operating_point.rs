// SPDX-License-Identifier: MIT OR Apache-2.0
//! The operating point of the small-signal models: resolution, speed and sample time.

use super::error::SmallSignalError;

/// Seconds per minute: speeds are in r/min, times in s.
const S_PER_MIN: f64 = 60.0;

/// Speed range by the normalised speed l (paper, eq. 1 and the list after it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpeedRange {
    /// l < 1 tr./T_s: fewer than one encoder transition per sample; ET territory.
    Low,
    /// 1 ≤ l < 20 tr./T_s.
    Medium,
    /// l ≥ 20 tr./T_s. The paper writes l > 20 and leaves l = 20 itself unassigned; it is
    /// put here so that the three ranges cover every l > 0.
    High,
}

/// A validated operating point: effective resolution R, average speed n̄ and control sample
/// time T_s. Built once by [`OperatingPoint::new`] or [`OperatingPoint::from_lines`];
/// everything else (T_e, l, L̄, the average delays) is derived from it and needs no checks.
///
/// R is the paper's *effective* resolution (Table I): transitions (edges) counted per
/// revolution, i.e. 1, 2 or 4 times the number of lines of the disc. Section IV's "500 ppr"
/// is R = 500: it gives T_e = 60/(15·500) = 8 ms at 15 r/min, the value the issue quotes,
/// and the normalised speeds of Sections III and IV (30, 3, 0.83, 0.083, 0.42 and 0.0125
/// tr./T_s) all follow from R = 500.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OperatingPoint {
    r: u32,
    speed_rpm: f64,
    ts_s: f64,
}

impl OperatingPoint {
    /// Validates R (transitions per revolution, > 0), n̄ (r/min, finite, > 0) and T_s (s,
    /// finite, > 0), and that T_e and l are finite and non-zero.
    pub fn new(
        transitions_per_rev: u32,
        speed_rpm: f64,
        ts_s: f64,
    ) -> Result<Self, SmallSignalError> {
        if transitions_per_rev == 0 {
            return Err(SmallSignalError::ZeroResolution);
        }
        // `!(x > 0)` also refuses NaN.
        if !(speed_rpm.is_finite() && speed_rpm > 0.0) {
            return Err(SmallSignalError::Speed(speed_rpm));
        }
        if !(ts_s.is_finite() && ts_s > 0.0) {
            return Err(SmallSignalError::SampleTime(ts_s));
        }
        let op = OperatingPoint {
            r: transitions_per_rev,
            speed_rpm,
            ts_s,
        };
        // Extreme but finite inputs (1e-310 r/min, 1e300 s) can still overflow the derived
        // quantities; refuse them here so that no model ever sees an infinite time.
        let (te_s, l) = (op.te_s(), op.l());
        if !(te_s.is_finite() && te_s > 0.0 && l.is_finite() && l > 0.0) {
            return Err(SmallSignalError::Degenerate { te_s, l });
        }
        Ok(op)
    }

    /// From the number of lines of the disc and the edges counted per line (1, 2 or 4 for
    /// x1, x2 or quadrature x4 decoding): R = lines · edges_per_line. Speed in r/min, T_s
    /// in s, validated as in [`OperatingPoint::new`].
    pub fn from_lines(
        lines: u32,
        edges_per_line: u32,
        speed_rpm: f64,
        ts_s: f64,
    ) -> Result<Self, SmallSignalError> {
        if !matches!(edges_per_line, 1 | 2 | 4) {
            return Err(SmallSignalError::EdgesPerLine(edges_per_line));
        }
        let r = lines
            .checked_mul(edges_per_line)
            .ok_or(SmallSignalError::ResolutionOverflow {
                lines,
                edges_per_line,
            })?;
        Self::new(r, speed_rpm, ts_s)
    }

    /// Effective resolution R: encoder transitions per revolution (paper's Table I).
    pub fn transitions_per_rev(&self) -> u32 {
        self.r
    }

    /// Average speed n̄ in r/min.
    pub fn speed_rpm(&self) -> f64 {
        self.speed_rpm
    }

    /// Control sample time T_s in s.
    pub fn ts_s(&self) -> f64 {
        self.ts_s
    }

    /// Time between consecutive transitions at n̄, T_e = 60/(n̄·R), in s (Table I, eq. 24).
    pub fn te_s(&self) -> f64 {
        S_PER_MIN / (self.speed_rpm * f64::from(self.r))
    }

    /// Normalised speed l = n̄·(R/60)·T_s (eq. 1), in transitions per T_s.
    pub fn l(&self) -> f64 {
        self.speed_rpm * f64::from(self.r) / S_PER_MIN * self.ts_s
    }

    /// Average number of transitions per T_s, L̄ (Appendix B), dimensionless. It equals l:
    /// the count L of one sample is ⌊l⌋ or ⌈l⌉, and eq. (15) is evaluated at the real L̄,
    /// as Appendix B justifies.
    pub fn big_l(&self) -> f64 {
        self.l()
    }

    /// Speed range of eq. (1).
    pub fn speed_range(&self) -> SpeedRange {
        let l = self.l();
        if l < 1.0 {
            SpeedRange::Low
        } else if l < 20.0 {
            SpeedRange::Medium
        } else {
            SpeedRange::High
        }
    }

    /// The paper's average delay of the PC method, T_s + T_s/(2L̄), in s (Appendix B and
    /// the issue). Note: the low-frequency group delay of eq. (15) as printed is T_s, not
    /// this: the moving average of eq. (10) delays by (T_s − T_s/L̄)/2, the sawtooth term by
    /// T_s/(2L̄) and the S/H by T_s/2. See docs/small-signal.md.
    pub fn pc_average_delay_s(&self) -> f64 {
        self.ts_s + self.ts_s / (2.0 * self.big_l())
    }

    /// The paper's average delay of the ET method, T_e + T_s/2, in s (after eq. 24); it is
    /// also the exact low-frequency group delay of eq. (24).
    pub fn et_average_delay_s(&self) -> f64 {
        self.te_s() + self.ts_s / 2.0
    }
}
