// SPDX-License-Identifier: MIT OR Apache-2.0
//! Eccentric encoder disc (Zhao et al.), layer 1: two plant models, the paper's
//! approximations, identification of the eccentricity from one revolution of line periods,
//! and the correction of the estimators' line counts.
//!
//! # Conventions
//! Angles in this module are in radians unless a name says otherwise (the plant's
//! [`crate::ideal::plant::Profile`] gives the shaft angle in revolutions; [`motion`] converts).
//! - θ: shaft angle (rad), the quantity every estimator is meant to measure.
//! - e = ΔR/R: relative eccentricity (disc centre ΔR off the shaft, head at radius R).
//! - θ0: eccentricity phase (rad); ψ = θ + θ0 is the shaft phase.
//! - ψ' = Γ(ψ): apparent phase, the angle the head reads on the disc, plus θ0. Γ(0) = 0 and
//!   the pulse rate dψ'/dψ is largest at ψ = ψ' = 0.
//! - φ = ψ' − θ0 = Γ(θ + θ0) − θ0: apparent disc angle (rad); disc position x = K·φ/(2π)
//!   lines, so line m (x = m) sits at apparent phase ψ' = 2πm/K + θ0. The Z line is x = 0.
//!
//! Hence θ0 is the apparent phase of the Z line, and the shortest line period (largest
//! pulse rate) falls at x ≡ −K·θ0/(2π) (mod K). The paper's eq. (19) returns instead the
//! position of the largest rate, i.e. −θ0 (mod 2π); [`identify::PaperId`] converts.
//!
//! # The two models
//! - [`Model::Zhao`], the paper's eq. (8): dψ'/dψ = g(ψ) = (e·cos ψ + s)·s with
//!   s = √(1 − e²·sin²ψ). Closed-form integral (u = e·sin ψ gives ∫√(1−u²) du):
//!   Γ(ψ) = (1 − e²/2)·ψ + (e²/4)·sin 2ψ + ½·(e·sin ψ·s + asin(e·sin ψ)).
//!   One shaft revolution gives 2π(1 − e²/2) of disc angle: K·e²/2 counts per revolution
//!   are lost (68 ppm at e = 0.35/30), which no rigid disc can do.
//! - [`Model::Rigid`], the physical reference: a rigid disc whose centre is ΔR off the
//!   shaft, read by a fixed head at radius R: Γ(ψ) = ψ + atan2(e·sin ψ, 1 − e·cos ψ)
//!   = ψ + Σₖ (eᵏ/k)·sin kψ, with the exact inverse ψ = ψ' − asin(e·sin ψ') (sine rule in
//!   the triangle shaft–disc centre–head) and rate (1 − e·cos ψ)/(1 − 2e·cos ψ + e²).
//!   Exactly K counts per revolution.
//!
//! To first order both are dψ'/dψ = 1 + e·cos ψ; they differ at e².
//!
//! # Submodules
//! [`paper`]: eqs. (8), (13)–(16) and the printed discrete correction (23)/(27), with the
//! data of Figs. 2–4. [`motion`]: exact A/B/Z edges of an eccentric disc under any shaft
//! motion. [`identify`]: e and θ0 from the line periods between two Z pulses (the paper's
//! eqs. 17–20 as printed, the ratio form, and a least-squares harmonic fit). [`correct`]:
//! the re-derived correction of a line count, N_c = ΔM − E·(S\[m_b\] − S\[m_a\]).
//! docs/eccentricity.md has the derivations and every discrepancy with the printed paper.

pub mod correct;
pub mod identify;
pub mod motion;
pub mod n3;
pub mod paper;

use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;
use std::fmt;

/// rpm per rad/s: 60/(2π) ≈ 9.5493. The paper rounds it to 9.55 in eqs. (7)–(8), which
/// reads 74 ppm high.
pub const RPM_PER_RAD_S: f64 = 60.0 / TAU;

/// Why an eccentricity, a period record or an identification was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum EccError {
    /// The relative eccentricity must be finite and in [0, 1).
    BadEccentricity(f64),
    /// The phase θ0 (rad) must be finite.
    NonFinitePhase(f64),
    /// ΔR must be finite and ≥ 0, R finite and > ΔR (m, or any one length unit).
    BadGeometry {
        /// Offset of the disc centre from the shaft.
        delta_r: f64,
        /// Read radius.
        radius: f64,
    },
    /// An identification needs at least this many line periods (one per line, ≥ 8).
    TooFewPeriods(usize),
    /// A line period (s, or cycles) that is not finite and > 0.
    BadPeriod {
        /// Position in the record.
        index: usize,
        /// The offending period.
        value: f64,
    },
    /// The edge list holds no Z pulse followed by a whole revolution of A rising edges.
    NoRevolution,
    /// The sampling clock (Hz) is not finite and > 0.
    BadClock(f64),
    /// A disc needs at least one line per revolution.
    ZeroLines,
}

impl fmt::Display for EccError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadEccentricity(e) => write!(f, "eccentricity {e} must be finite and in [0, 1)"),
            Self::NonFinitePhase(p) => write!(f, "phase {p} rad is not finite"),
            Self::BadGeometry { delta_r, radius } => write!(
                f,
                "offset {delta_r} and radius {radius}: need 0 <= offset < radius, both finite"
            ),
            Self::TooFewPeriods(n) => write!(f, "{n} line periods: need at least 8"),
            Self::BadPeriod { index, value } => {
                write!(f, "line period {index} = {value}: must be finite and > 0")
            }
            Self::NoRevolution => write!(
                f,
                "no Z pulse followed by a whole revolution of A rising edges"
            ),
            Self::BadClock(hz) => write!(f, "clock {hz} Hz must be finite and > 0"),
            Self::ZeroLines => write!(f, "disc must have at least one line per revolution"),
        }
    }
}

impl std::error::Error for EccError {}

/// Which law maps the shaft phase ψ to the apparent phase ψ' (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Model {
    /// The paper's eq. (8): loses K·e²/2 counts per revolution (not physical at e²).
    Zhao,
    /// Rigid disc off-centre on the shaft, fixed head: exactly K counts per revolution.
    Rigid,
}

/// An eccentric mounting: model, relative eccentricity e and phase θ0 (rad).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Eccentricity {
    /// Which plant law.
    pub model: Model,
    /// Relative eccentricity e = ΔR/R, in [0, 1).
    pub e: f64,
    /// Phase θ0 (rad): the apparent phase of the Z line (module docs).
    pub theta0: f64,
}

impl Eccentricity {
    /// A validated eccentricity: 0 ≤ e < 1, θ0 (rad) finite.
    pub fn new(model: Model, e: f64, theta0: f64) -> Result<Self, EccError> {
        let ecc = Self { model, e, theta0 };
        ecc.validate()?;
        Ok(ecc)
    }

    /// From the geometry: disc centre `delta_r` off the shaft, head at `radius` (same unit).
    pub fn from_geometry(
        model: Model,
        delta_r: f64,
        radius: f64,
        theta0: f64,
    ) -> Result<Self, EccError> {
        if !(delta_r.is_finite() && radius.is_finite() && delta_r >= 0.0 && radius > delta_r) {
            return Err(EccError::BadGeometry { delta_r, radius });
        }
        Self::new(model, delta_r / radius, theta0)
    }

    /// A centred disc (e = 0): apparent angle = shaft angle.
    pub fn centred() -> Self {
        Self {
            model: Model::Rigid,
            e: 0.0,
            theta0: 0.0,
        }
    }

    /// Checks 0 ≤ e < 1 and a finite θ0.
    pub fn validate(&self) -> Result<(), EccError> {
        if !(self.e.is_finite() && (0.0..1.0).contains(&self.e)) {
            return Err(EccError::BadEccentricity(self.e));
        }
        if !self.theta0.is_finite() {
            return Err(EccError::NonFinitePhase(self.theta0));
        }
        Ok(())
    }

    /// Pulse-rate factor dψ'/dψ at shaft phase ψ (rad): the measured speed over the true
    /// one. Zhao: g(ψ) of eq. (8); rigid: (1 − e·cos ψ)/(1 − 2e·cos ψ + e²).
    pub fn rate(&self, psi: f64) -> f64 {
        let e = self.e;
        let (s, c) = psi.sin_cos();
        match self.model {
            Model::Zhao => {
                let root = (1.0 - e * e * s * s).sqrt();
                (e * c + root) * root
            }
            Model::Rigid => (1.0 - e * c) / (1.0 - 2.0 * e * c + e * e),
        }
    }

    /// Γ(ψ) − ψ (rad): the periodic part of the apparent phase for the rigid disc, and the
    /// part of Zhao's that excludes the −(e²/2)·ψ drift. Written without ψ so that large
    /// angles keep their precision.
    fn wobble(&self, psi: f64) -> f64 {
        let e = self.e;
        let (s, c) = psi.sin_cos();
        match self.model {
            Model::Zhao => {
                let u = e * s;
                let root = (1.0 - u * u).sqrt();
                0.25 * e * e * (2.0 * psi).sin() + 0.5 * (u * root + u.asin())
            }
            Model::Rigid => (e * s).atan2(1.0 - e * c),
        }
    }

    /// Mean disc angle per shaft angle: 1 for the rigid disc, 1 − e²/2 for Zhao's plant.
    pub fn apparent_per_rev(&self) -> f64 {
        match self.model {
            Model::Zhao => 1.0 - 0.5 * self.e * self.e,
            Model::Rigid => 1.0,
        }
    }

    /// Apparent phase ψ' = Γ(ψ) (rad) of the shaft phase ψ (rad).
    pub fn phase(&self, psi: f64) -> f64 {
        self.apparent_angle(psi - self.theta0) + self.theta0
    }

    /// Apparent disc angle φ = Γ(θ + θ0) − θ0 (rad) of the shaft angle θ (rad).
    pub fn apparent_angle(&self, theta: f64) -> f64 {
        let psi = theta + self.theta0;
        match self.model {
            Model::Zhao => theta - 0.5 * self.e * self.e * psi + self.wobble(psi),
            Model::Rigid => theta + self.wobble(psi),
        }
    }

    /// Shaft angle θ (rad) whose apparent angle is φ (rad): the inverse of
    /// [`Eccentricity::apparent_angle`]. Rigid: θ = φ − asin(e·sin(φ + θ0)), exact.
    /// Zhao: safeguarded Newton on the closed form, to a few ulps.
    pub fn shaft_angle(&self, phi: f64) -> f64 {
        let e = self.e;
        match self.model {
            Model::Rigid => phi - (e * (phi + self.theta0).sin()).asin(),
            Model::Zhao => {
                let a = self.apparent_per_rev();
                // φ = a·θ − (e²/2)·θ0 + wobble with |wobble| ≤ e²/4 + ½(½ + π/2) < 1.5:
                // a bracket around the drift-only guess.
                let guess = (phi + 0.5 * e * e * self.theta0) / a;
                let (mut lo, mut hi) = (guess - 1.5 / a, guess + 1.5 / a);
                let mut th = guess;
                for _ in 0..200 {
                    let f = self.apparent_angle(th) - phi;
                    if f == 0.0 {
                        return th;
                    }
                    if f < 0.0 {
                        lo = th;
                    } else {
                        hi = th;
                    }
                    let newton = th - f / self.rate(th + self.theta0);
                    // Newton while it stays inside the bracket, bisection otherwise.
                    let next = if newton > lo && newton < hi {
                        newton
                    } else {
                        lo + 0.5 * (hi - lo)
                    };
                    if (next - th).abs() <= 2.0 * f64::EPSILON * th.abs().max(1.0) {
                        return next;
                    }
                    th = next;
                }
                th
            }
        }
    }
}
