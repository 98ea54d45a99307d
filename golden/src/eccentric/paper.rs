// SPDX-License-Identifier: MIT OR Apache-2.0
//! Zhao et al.'s speed model, eqs. (8) and (13)–(16), the data of Figs. 2–4, and the
//! printed discrete correction, eqs. (23)/(26)/(27), as printed and repaired.
//!
//! Speeds n (true) and n' (measured) are in rpm; θ is the shaft phase measured from the
//! largest pulse rate (the crate's ψ = θ + θ0 with θ0 = 0), in rad. The paper's constant
//! 9.55 is replaced by 60/(2π) ([`RPM_PER_RAD_S`]): 9.55 reads 74 ppm high, which would
//! shift every curve but not its shape.

use super::RPM_PER_RAD_S;
use std::f64::consts::{PI, TAU};

/// Lines per revolution of the paper's example (Figs. 2–4).
pub const LINES: u32 = 1024;
/// Shaft speed of the paper's example (rad/s): n = 10.9·60/(2π) ≈ 104.087 rpm.
pub const OMEGA: f64 = 10.9;
/// Offset of the disc centre in the paper's example (m).
pub const DELTA_R: f64 = 0.35e-3;
/// Disc (read) radius in the paper's example (m).
pub const RADIUS: f64 = 0.03;
/// The eccentricity the text names next to eq. (13) ("reaches 0.125 %"); Fig. 4's error
/// level fits this value, not ΔR/R.
pub const E_TEXT: f64 = 0.00125;

/// e = ΔR/R of the paper's example: 0.35/30 ≈ 1.1667 %.
pub fn e_example() -> f64 {
    DELTA_R / RADIUS
}

/// True speed (rpm) of the paper's example: 10.9 rad/s.
pub fn n_example() -> f64 {
    OMEGA * RPM_PER_RAD_S
}

/// Eq. (8) normalised: n'/n = g(θ) = (e·cos θ + √(1 − e²·sin²θ))·√(1 − e²·sin²θ).
/// Also Fig. 2's curve (f/f₀ at constant speed).
pub fn g_eq8(e: f64, theta: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    let root = (1.0 - e * e * s * s).sqrt();
    (e * c + root) * root
}

/// Eq. (8): measured speed n' (rpm) at true speed `n` (rpm), eccentricity e, phase θ (rad).
pub fn n_eq8(n: f64, e: f64, theta: f64) -> f64 {
    n * g_eq8(e, theta)
}

/// Eq. (15) (= eq. 14 with β = e·sin θ): n' ≈ n·(e·cos θ + 1 − e²·sin²θ) (rpm).
pub fn n_eq15(n: f64, e: f64, theta: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    n * (e * c + 1.0 - e * e * s * s)
}

/// Eq. (16): n' ≈ n·(e·cos θ + 1 − 0.25·e²) (rpm).
pub fn n_eq16(n: f64, e: f64, theta: f64) -> f64 {
    n * (e * theta.cos() + 1.0 - 0.25 * e * e)
}

/// The rigid disc's measured speed (rpm): n·(1 − e·cos θ)/(1 − 2e·cos θ + e²), the
/// physical counterpart of eq. (8).
pub fn n_rigid(n: f64, e: f64, theta: f64) -> f64 {
    let c = theta.cos();
    n * (1.0 - e * c) / (1.0 - 2.0 * e * c + e * e)
}

/// One abscissa of Figs. 2–4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FigurePoint {
    /// Shaft phase θ (degrees, 0–360).
    pub theta_deg: f64,
    /// Fig. 2: normalised output frequency f/f₀ = g(θ).
    pub f_norm: f64,
    /// Eq. (8): exact measured speed n' (rpm).
    pub n_exact: f64,
    /// Fig. 3: eq. (8) − eq. (15) (rpm).
    pub err_eq15: f64,
    /// Fig. 4: eq. (8) − eq. (16) (rpm).
    pub err_eq16: f64,
}

/// The data of Figs. 2–4 at true speed `n` (rpm) and eccentricity `e`: `points` phases
/// θ = 360°·i/points, i = 0..points.
pub fn figures(n: f64, e: f64, points: usize) -> Vec<FigurePoint> {
    (0..points)
        .map(|i| {
            let theta = TAU * i as f64 / points as f64;
            let exact = n_eq8(n, e, theta);
            FigurePoint {
                theta_deg: theta.to_degrees(),
                f_norm: g_eq8(e, theta),
                n_exact: exact,
                err_eq15: exact - n_eq15(n, e, theta),
                err_eq16: exact - n_eq16(n, e, theta),
            }
        })
        .collect()
}

/// Extremes of the figures' curves over one revolution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FigureSummary {
    /// Smallest exact n' (rpm).
    pub n_min: f64,
    /// Largest exact n' (rpm).
    pub n_max: f64,
    /// max |eq. (8) − eq. (15)| (rpm): Fig. 3's peak.
    pub max_err_eq15: f64,
    /// max |eq. (8) − eq. (16)| (rpm): Fig. 4's peak.
    pub max_err_eq16: f64,
}

/// [`FigureSummary`] of [`figures`]`(n, e, points)`.
pub fn summary(n: f64, e: f64, points: usize) -> FigureSummary {
    figures(n, e, points).iter().fold(
        FigureSummary {
            n_min: f64::INFINITY,
            n_max: f64::NEG_INFINITY,
            max_err_eq15: 0.0,
            max_err_eq16: 0.0,
        },
        |s, p| FigureSummary {
            n_min: s.n_min.min(p.n_exact),
            n_max: s.n_max.max(p.n_exact),
            max_err_eq15: s.max_err_eq15.max(p.err_eq15.abs()),
            max_err_eq16: s.max_err_eq16.max(p.err_eq16.abs()),
        },
    )
}

/// The eccentricity at which Fig. 4's peak error max|eq. (8) − eq. (16)| equals `err_rpm`
/// at speed `n` (rpm), by bisection on e ∈ (0, 0.5) over a 3600-point sweep. Near
/// 0.75·e²·n = err (the peak is at θ = 90°, where eq. 16 drops e²·sin²θ − e²/4).
pub fn e_for_eq16_peak(n: f64, err_rpm: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 0.5);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if summary(n, mid, 3600).max_err_eq16 < err_rpm {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Eq. (27) exactly as printed: the "disturbance" F(k) between counts `m_a` = M(k) and
/// `m_b` = M(k+1) on a disc of `lines` lines, sampling period `ts` (s):
/// F = (e/Ts)(sin θ_b − sin θ_a) − (π·e²/(Ts·K))(M_b − M_a) + (e²/(4Ts))(sin 2θ_b − sin 2θ_a),
/// θ = 2πM/K. It omits the integral of the constant term (2π·ΔM/K) and divides by Ts,
/// so n''/F (eq. 26) is not a speed: F changes sign twice per revolution.
pub fn f_eq27_printed(e: f64, lines: u32, m_a: i64, m_b: i64, ts: f64) -> f64 {
    let k = f64::from(lines);
    let th = |m: i64| TAU * m as f64 / k;
    let (ta, tb) = (th(m_a), th(m_b));
    e / ts * (tb.sin() - ta.sin()) - PI * e * e / (ts * k) * (m_b - m_a) as f64
        + e * e / (4.0 * ts) * ((2.0 * tb).sin() - (2.0 * ta).sin())
}

/// Eq. (27) repaired: the ratio of counted angle to true angle that eq. (21) means,
/// F = ∫(1 + e·cos θ − e²·sin²θ)dθ / (θ_b − θ_a), evaluated (as the paper does) at the
/// counted positions θ = 2πM/K + θ0 (rad; the paper has no θ0: it counts from the largest
/// rate). Dimensionless; n = n''/F. Being evaluated at apparent rather than shaft
/// positions, it leaves an e² residual that [`super::correct`] does not.
pub fn f_eq27_repaired(e: f64, theta0: f64, lines: u32, m_a: i64, m_b: i64) -> f64 {
    let k = f64::from(lines);
    let th = |m: i64| TAU * m as f64 / k + theta0;
    let (ta, tb) = (th(m_a), th(m_b));
    let span = TAU * (m_b - m_a) as f64 / k;
    let integral = span * (1.0 - 0.5 * e * e)
        + e * (tb.sin() - ta.sin())
        + 0.25 * e * e * ((2.0 * tb).sin() - (2.0 * ta).sin());
    integral / span
}
