// SPDX-License-Identifier: MIT OR Apache-2.0
//! The correction of a line count, derived again (the printed eqs. 23/27 are not usable:
//! [`super::paper::f_eq27_printed`]).
//!
//! # Derivation
//! An estimator measures the disc angle between two edges, lines m_a and m_b, at apparent
//! phases ψ'_a = 2πm_a/K + θ0 and ψ'_b; what it should measure is the shaft angle between
//! them. Correct the position, not the speed: with the inverse map ψ = Γ⁻¹(ψ'),
//! Δθ = Γ⁻¹(ψ'_b) − Γ⁻¹(ψ'_a), exactly, whatever the estimator and however long the span.
//! - Rigid disc: Γ⁻¹(ψ') = ψ' − asin(e·sin ψ') = ψ' − e·sin ψ' − (e³/6)·sin³ψ' − …, so
//!   Δθ = (2π/K)(m_b − m_a) − e·(sin ψ'_b − sin ψ'_a) + O(e³): the e² terms cancel.
//! - Zhao's plant: Γ(ψ) = a·ψ + e·sin ψ + (e²/4)·sin 2ψ + O(e³), a = 1 − e²/2, whence
//!   Γ⁻¹(ψ') = [ψ' − e·sin ψ' + (e²/4)·sin 2ψ']/a + O(e³): a first harmonic, a second
//!   harmonic and a scale 1/a (the counts it loses per revolution).
//!
//! In lines: N_c = s·(ΔM − Σₖ Eₖ·(Sₖ\[m_b\] − Sₖ\[m_a\])), Sₖ\[m\] = sin(2πk·m/K + pₖ), a sine
//! table indexed by m mod K. First order (rigid disc): s = 1, E₁ = K·e/(2π), p₁ = θ0 (the
//! form S\[m\] = sin(2π(m + m0)/K), m0 = K·θ0/(2π), of
//! docs/design-decisions.md#ecc-correction). The estimator then divides N_c instead of ΔM
//! by its time; s is a constant gain that hardware folds into the output scale.

use super::identify::HarmonicFit;
use super::{Eccentricity, Model};
use std::f64::consts::TAU;

/// One harmonic of the correction: Eₖ·sin(2πk·m/K + pₖ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Term {
    /// Harmonic order k ≥ 1.
    pub order: u32,
    /// Eₖ (lines).
    pub amplitude: f64,
    /// pₖ (rad).
    pub phase: f64,
}

/// Which terms [`Correction::for_model`] includes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Terms {
    /// First harmonic only, s = 1 (the rigid disc's complete first-order correction).
    First,
    /// First harmonic and the scale s = 1/(mean disc angle per shaft angle).
    FirstAndScale,
    /// First and second harmonic and the scale.
    SecondAndScale,
}

/// A line-count correction N_c = s·(ΔM − Σₖ Eₖ·(Sₖ\[m_b\] − Sₖ\[m_a\])) (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Correction {
    /// Lines per revolution K.
    pub lines: u32,
    /// Scale s (dimensionless).
    pub scale: f64,
    /// Harmonics.
    pub terms: Vec<Term>,
}

impl Correction {
    /// No correction: N_c = ΔM.
    pub fn none(lines: u32) -> Self {
        Self {
            lines,
            scale: 1.0,
            terms: Vec::new(),
        }
    }

    /// First-order correction for eccentricity e at phase θ0 (rad): E₁ = K·e/(2π), p₁ = θ0.
    /// Residual on the rigid disc: (e³/6)·sin³ψ' of angle.
    pub fn first_order(lines: u32, e: f64, theta0: f64) -> Self {
        Self {
            lines,
            scale: 1.0,
            terms: vec![Term {
                order: 1,
                amplitude: f64::from(lines) * e / TAU,
                phase: theta0,
            }],
        }
    }

    /// The analytic correction of a known eccentricity to second order (module docs).
    /// Rigid disc: the first-order correction whatever `terms` (its scale is 1 and its
    /// second harmonic 0). Zhao: s = 1/(1 − e²/2), E₁ = K·e/(2π), E₂ = K·e²/(8π) at phase
    /// 2θ0 + π, as selected.
    pub fn for_model(lines: u32, ecc: &Eccentricity, terms: Terms) -> Self {
        let mut c = Self::first_order(lines, ecc.e, ecc.theta0);
        if ecc.model == Model::Zhao {
            if terms != Terms::First {
                c.scale = 1.0 / ecc.apparent_per_rev();
            }
            if terms == Terms::SecondAndScale {
                c.terms.push(Term {
                    order: 2,
                    amplitude: f64::from(lines) * ecc.e * ecc.e / (4.0 * TAU),
                    phase: 2.0 * ecc.theta0 + std::f64::consts::PI,
                });
            }
        }
        c
    }

    /// The correction measured by [`super::identify::harmonic_fit`]: Eₖ = K·aₖ/(2πk),
    /// pₖ as fitted (the second harmonic only if fitted), with scale `scale` (1 for the rigid
    /// disc; the scale cannot be identified from the periods, which only see ratios).
    pub fn from_fit(lines: u32, fit: &HarmonicFit, scale: f64) -> Self {
        let k = f64::from(lines);
        let mut terms = vec![Term {
            order: 1,
            amplitude: k * fit.a1 / TAU,
            phase: fit.p1,
        }];
        if fit.a2 != 0.0 {
            terms.push(Term {
                order: 2,
                amplitude: k * fit.a2 / (2.0 * TAU),
                phase: fit.p2,
            });
        }
        Self {
            lines,
            scale,
            terms,
        }
    }

    /// Sine-table value Sₖ\[m\] = sin(2π·((k·m) mod K)/K + pₖ) of `term` at line m: the
    /// ROM is indexed by position mod K.
    pub fn sine(&self, term: &Term, m: i64) -> f64 {
        let k = i64::from(self.lines);
        let idx = (i64::from(term.order) * m.rem_euclid(k)).rem_euclid(k);
        (TAU * idx as f64 / k as f64 + term.phase).sin()
    }

    /// Corrected line count N_c (lines) between lines m_a and m_b.
    pub fn count(&self, m_a: i64, m_b: i64) -> f64 {
        let wobble: f64 = self
            .terms
            .iter()
            .map(|t| t.amplitude * (self.sine(t, m_b) - self.sine(t, m_a)))
            .sum();
        self.scale * ((m_b - m_a) as f64 - wobble)
    }

    /// Σₖ Eₖ·(Sₖ(x_b) − Sₖ(x_a)) (lines) between fractional positions x_a and x_b (lines),
    /// Sₖ(x) = sin(2πk·x/K + pₖ): the part of a span's count that is eccentricity, for spans
    /// whose ends are not lines (e.g. half a line past a pulse, [`super::n3`]).
    pub fn wobble(&self, x_a: f64, x_b: f64) -> f64 {
        let k = f64::from(self.lines);
        let s = |t: &Term, x: f64| (TAU * f64::from(t.order) * x.rem_euclid(k) / k + t.phase).sin();
        self.terms
            .iter()
            .map(|t| t.amplitude * (s(t, x_b) - s(t, x_a)))
            .sum()
    }

    /// Corrected shaft angle (rad) between lines m_a and m_b: 2π·N_c/K.
    pub fn angle(&self, m_a: i64, m_b: i64) -> f64 {
        TAU * self.count(m_a, m_b) / f64::from(self.lines)
    }
}

/// One speed estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedSample {
    /// Instant the estimate refers to: its last edge (s).
    pub t: f64,
    /// First and last line of the measurement.
    pub lines: (i64, i64),
    /// Estimated shaft speed (rad/s).
    pub speed: f64,
}

/// Exact-time M/T over every single line period: speed = corrected angle of (m, m + 1)
/// over the exact time between the two crossings. `line_times` = (line, instant (s)) of
/// consecutive forward line crossings, e.g. [`super::motion::EccentricDisc::line_crossings`].
pub fn line_period_speeds(line_times: &[(i64, f64)], corr: &Correction) -> Vec<SpeedSample> {
    line_times
        .windows(2)
        .map(|w| SpeedSample {
            t: w[1].1,
            lines: (w[0].0, w[1].0),
            speed: corr.angle(w[0].0, w[1].0) / (w[1].1 - w[0].1),
        })
        .collect()
}

/// Exact-time M/T on a free-running grid of period `dt` (s), as in [`crate::ideal::mt`]: at each
/// sample k·dt the estimate spans from the last line crossed before the previous estimate
/// to the last line crossed before this sample, with the exact time between them; samples
/// with no new line give no estimate.
///
/// # Panics
/// If `dt` is not finite and > 0, or the instants are not finite and ascending.
pub fn mt_speeds(line_times: &[(i64, f64)], dt: f64, corr: &Correction) -> Vec<SpeedSample> {
    assert!(dt.is_finite() && dt > 0.0, "mt_speeds: bad dt {dt}");
    assert!(
        line_times.iter().all(|l| l.1.is_finite())
            && line_times.windows(2).all(|w| w[0].1 <= w[1].1),
        "mt_speeds: crossing instants must be finite and in time order"
    );
    let mut out = Vec::new();
    let mut next = 0usize;
    let mut anchor: Option<(i64, f64)> = None;
    // Runs until the first sample that has seen the last crossing.
    for k in 1u64.. {
        if next == line_times.len() {
            break;
        }
        let ts = k as f64 * dt;
        while next < line_times.len() && line_times[next].1 <= ts {
            next += 1;
        }
        let Some(&last) = next.checked_sub(1).map(|i| &line_times[i]) else {
            continue;
        };
        match anchor {
            Some(a) if last.0 != a.0 => {
                out.push(SpeedSample {
                    t: last.1,
                    lines: (a.0, last.0),
                    speed: corr.angle(a.0, last.0) / (last.1 - a.1),
                });
                anchor = Some(last);
            }
            Some(_) => {}
            None => anchor = Some(last),
        }
    }
    out
}

/// Once-per-revolution ripple of a set of estimates against the true speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ripple {
    /// Largest deviation max|v/v_true − 1| (relative; ×1e6 for ppm).
    pub peak: f64,
    /// Peak to peak (max v − min v)/v_true (relative).
    pub peak_to_peak: f64,
    /// Mean of v/v_true − 1 (relative).
    pub mean: f64,
}

/// [`Ripple`] of `speeds` against `truth` (same unit). Panics on an empty slice.
pub fn ripple(speeds: &[f64], truth: f64) -> Ripple {
    assert!(!speeds.is_empty(), "ripple of no estimates");
    let rel: Vec<f64> = speeds.iter().map(|v| v / truth - 1.0).collect();
    let max = rel.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let min = rel.iter().copied().fold(f64::INFINITY, f64::min);
    Ripple {
        peak: max.abs().max(min.abs()),
        peak_to_peak: max - min,
        mean: rel.iter().sum::<f64>() / rel.len() as f64,
    }
}

/// Amplitude of the once-per-revolution component of `samples` = (shaft angle (rad),
/// value): 2/n·|Σ (v − v̄)·e^(−jθ)|, the single DFT bin at one cycle per revolution.
/// Exact for samples spread evenly over whole revolutions, an estimate otherwise. Panics
/// on an empty slice.
pub fn once_per_rev(samples: &[(f64, f64)]) -> f64 {
    assert!(!samples.is_empty(), "once_per_rev of no samples");
    let n = samples.len() as f64;
    let mean = samples.iter().map(|s| s.1).sum::<f64>() / n;
    let (c, s) = samples.iter().fold((0.0, 0.0), |(c, s), &(a, v)| {
        (c + (v - mean) * a.cos(), s + (v - mean) * a.sin())
    });
    2.0 / n * c.hypot(s)
}
