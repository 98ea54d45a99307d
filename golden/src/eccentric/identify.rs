// SPDX-License-Identifier: MIT OR Apache-2.0
//! Identification of e and θ0 from the K line periods between two Z pulses, at constant
//! speed.
//!
//! Input: `periods[m]` = time from line m to line m + 1 (m = 0..K, line 0 = the Z line,
//! x ≡ 0 mod K), in seconds or clock cycles (only ratios matter). Period m spans the
//! apparent phases [2πm/K, 2π(m+1)/K) + θ0, centre Φ_m = 2π(m + ½)/K.
//!
//! Three methods, each returning an [`Identified`] in this crate's convention (θ0 = the
//! apparent phase of the Z line, so the shortest period falls at Φ = −θ0):
//! - [`paper_identify`]: eqs. (17)–(20) exactly as printed;
//! - [`ratio_identify`]: e = (r − 1)/(r + 1), r = T_max/T_min (what eq. 20 reduces to once
//!   its cosines are taken at the phases of the extremes, which the printed form does not
//!   do), θ0 from the positions of both extremes;
//! - [`harmonic_fit`] (robust; [`identify`] is it with the default options): least squares
//!   of all K periods on the first (optionally second) harmonic, i.e. single DFT bins,
//!   optionally with a linear trend.

use super::{EccError, Model};
use crate::ideal::plant::{Channel, Edge};
use std::f64::consts::{PI, TAU};

/// An identified eccentricity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Identified {
    /// Relative eccentricity e.
    pub e: f64,
    /// Phase θ0 (rad, in [0, 2π)): the apparent phase of the Z line.
    pub theta0: f64,
}

/// `a − b` wrapped to (−π, π] (rad): the error between two phases.
pub fn phase_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    if d > PI {
        d - TAU
    } else {
        d
    }
}

/// The K line periods (s) of the first revolution in `edges` that starts at a Z pulse:
/// line 0 is the A rising edge just before a rising Z edge (Z rises a quarter line after
/// it), and the next K rising edges of A close the periods. With `clock_hz`, every edge
/// instant is first quantised to the first clock edge at or after it (what a capture
/// register sees), so each period is a whole number of clock periods.
pub fn revolution_periods(
    edges: &[Edge],
    lines: u32,
    clock_hz: Option<f64>,
) -> Result<Vec<f64>, EccError> {
    if let Some(hz) = clock_hz {
        if !(hz.is_finite() && hz > 0.0) {
            return Err(EccError::BadClock(hz));
        }
    }
    let stamp = |t: f64| match clock_hz {
        // Whole cycles first, then seconds: differences of the cycle counts are exact.
        Some(hz) => (t * hz).ceil(),
        None => t,
    };
    let unit = clock_hz.map_or(1.0, |hz| 1.0 / hz);
    let k = lines as usize;
    let mut last_a: Option<f64> = None;
    let mut rises = None;
    for (i, edge) in edges.iter().enumerate() {
        match (edge.channel, edge.rising) {
            (Channel::A, true) => last_a = Some(edge.t),
            (Channel::Z, true) if last_a.is_some() => {
                let mut times = vec![stamp(last_a.unwrap_or_default())];
                times.extend(
                    edges[i..]
                        .iter()
                        .filter(|e| e.channel == Channel::A && e.rising)
                        .take(k)
                        .map(|e| stamp(e.t)),
                );
                if times.len() == k + 1 {
                    rises = Some(times);
                    break;
                }
                return Err(EccError::NoRevolution);
            }
            _ => {}
        }
    }
    let rises = rises.ok_or(EccError::NoRevolution)?;
    Ok(rises.windows(2).map(|w| (w[1] - w[0]) * unit).collect())
}

fn check_periods(periods: &[f64]) -> Result<(), EccError> {
    if periods.len() < 8 {
        return Err(EccError::TooFewPeriods(periods.len()));
    }
    match periods
        .iter()
        .enumerate()
        .find(|(_, p)| !(p.is_finite() && **p > 0.0))
    {
        Some((index, &value)) => Err(EccError::BadPeriod { index, value }),
        None => Ok(()),
    }
}

/// Index and value of the longest and shortest period, first occurrence on ties (what a
/// `if T > T_max` capture loop records; ties are common once periods are whole cycles).
fn extremes(periods: &[f64]) -> ((usize, f64), (usize, f64)) {
    let (mut max, mut min) = ((0, periods[0]), (0, periods[0]));
    for (i, &p) in periods.iter().enumerate() {
        if p > max.1 {
            max = (i, p);
        }
        if p < min.1 {
            min = (i, p);
        }
    }
    (max, min)
}

/// What eqs. (17)–(20) compute, as printed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperId {
    /// k1: counter value when T_max was captured (period m ends at count m + 1).
    pub k1: usize,
    /// k2: counter value when T_min was captured.
    pub k2: usize,
    /// Longest period T_max (input unit); f_min = 1/T_max (eq. 17).
    pub t_max: f64,
    /// Shortest period T_min (input unit); f_max = 1/T_min (eq. 17).
    pub t_min: f64,
    /// Eq. (18): θ1 = 2π·k1/K (rad).
    pub theta1: f64,
    /// Eq. (18): θ2 = 2π·k2/K (rad).
    pub theta2: f64,
    /// Eq. (19): θ0 = (θ2 + |π − θ1|)/2 (rad): the position of the largest rate seen from
    /// the Z line. Right only when that position is below π; otherwise it returns π.
    pub theta0_printed: f64,
    /// Eq. (20): e = |(f_max/f_min − 1)/(cos θ1 − cos θ2·f_max/f_min)|. θ1, θ2 are
    /// positions from the Z line, not phases from the largest rate, so this is
    /// ≈ e/|cos θ0|.
    pub e_printed: f64,
}

impl PaperId {
    /// The printed results in this crate's convention: e as printed, θ0 = −θ0_printed.
    pub fn identified(&self) -> Identified {
        Identified {
            e: self.e_printed,
            theta0: (-self.theta0_printed).rem_euclid(TAU),
        }
    }
}

/// The paper's identification, eqs. (17)–(20), exactly as printed.
pub fn paper_identify(periods: &[f64]) -> Result<PaperId, EccError> {
    check_periods(periods)?;
    let k = periods.len() as f64;
    let ((i_max, t_max), (i_min, t_min)) = extremes(periods);
    let (k1, k2) = (i_max + 1, i_min + 1);
    let theta1 = TAU * k1 as f64 / k;
    let theta2 = TAU * k2 as f64 / k;
    let r = (1.0 / t_min) / (1.0 / t_max);
    Ok(PaperId {
        k1,
        k2,
        t_max,
        t_min,
        theta1,
        theta2,
        theta0_printed: (theta2 + (PI - theta1).abs()) / 2.0,
        e_printed: ((r - 1.0) / (theta1.cos() - theta2.cos() * r)).abs(),
    })
}

/// The extremes method made consistent: e = (r − 1)/(r + 1) with r = T_max/T_min (exact
/// for both plants: their rates peak at 1 + e and 1 − e, or 1/(1 ∓ e)), and θ0 the
/// circular mean of the two readings of the extremes' centres: T_min at Φ = −θ0 and
/// T_max at Φ = π − θ0.
pub fn ratio_identify(periods: &[f64]) -> Result<Identified, EccError> {
    check_periods(periods)?;
    let k = periods.len() as f64;
    let ((i_max, t_max), (i_min, t_min)) = extremes(periods);
    let r = t_max / t_min;
    let centre = |i: usize| TAU * (i as f64 + 0.5) / k;
    let (a, b) = (-centre(i_min), PI - centre(i_max));
    Ok(Identified {
        e: (r - 1.0) / (r + 1.0),
        theta0: (a.sin() + b.sin()).atan2(a.cos() + b.cos()).rem_euclid(TAU),
    })
}

/// What [`harmonic_fit`] fits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FitOptions {
    /// Also fit the second harmonic (needed to correct Zhao's plant to a few ppm).
    pub second_harmonic: bool,
    /// Also fit a linear trend of the period over the revolution (absorbs a slow speed
    /// drift, which otherwise leaks into the sine term of the first harmonic).
    pub trend: bool,
}

/// Result of [`harmonic_fit`]. The normalised period is modelled as
/// T_m/T̄ = 1 − a1·cos(Φ + p1) − a2·cos(2Φ + p2) (+ trend), Φ the apparent phase from the Z
/// line, with the averaging over each line removed (÷ sinc(kπ/K)): a_k, p_k are then the
/// Fourier coefficients of dθ/dφ, which is what the line periods sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicFit {
    /// Mean line period T̄ (input unit).
    pub mean: f64,
    /// Fitted relative change of the period from the start to the end of the revolution
    /// (0 when not fitted).
    pub trend: f64,
    /// First-harmonic amplitude a1 (dimensionless, ≈ e).
    pub a1: f64,
    /// First-harmonic phase p1 (rad, [0, 2π), = θ0).
    pub p1: f64,
    /// Second-harmonic amplitude a2 (0 when not fitted).
    pub a2: f64,
    /// Second-harmonic phase p2 (rad, [0, 2π)).
    pub p2: f64,
}

impl HarmonicFit {
    /// e and θ0 read through a plant model: for the rigid disc a1 = b1(e) = e·(1 + e²/8 +
    /// …) ([`rigid_first_harmonic`]), inverted exactly; for Zhao's plant a1 = e + O(e³),
    /// taken as is (its periods relative to their mean are, to O(e³),
    /// 1 − e·cos(Φ + θ0) + (e²/2)·cos 2(Φ + θ0)). Both read θ0 = p1.
    pub fn identified(&self, model: Model) -> Identified {
        let e = match model {
            Model::Rigid => rigid_e_from_first_harmonic(self.a1),
            Model::Zhao => self.a1,
        };
        Identified { e, theta0: self.p1 }
    }
}

/// First Fourier (cosine) coefficient of d/dψ asin(e·sin ψ) = e·cos ψ/√(1 − e²·sin²ψ):
/// the first harmonic of the rigid disc's dθ/dφ, e·(1 + e²/8 + 3e⁴/64 + …). Trapezoid rule
/// on 512 points (spectrally accurate for this periodic analytic integrand at e ≤ 0.9).
pub fn rigid_first_harmonic(e: f64) -> f64 {
    const N: usize = 512;
    let sum: f64 = (0..N)
        .map(|i| {
            let (s, c) = (TAU * i as f64 / N as f64).sin_cos();
            e * c * c / (1.0 - e * e * s * s).sqrt()
        })
        .sum();
    2.0 * sum / N as f64
}

/// The e whose [`rigid_first_harmonic`] is `a1` (0 ≤ a1 < 0.9), by fixed-point iteration
/// on e = a1·e/b1(e).
pub fn rigid_e_from_first_harmonic(a1: f64) -> f64 {
    let mut e = a1;
    for _ in 0..60 {
        if e == 0.0 {
            return 0.0;
        }
        let next = a1 * e / rigid_first_harmonic(e);
        if (next - e).abs() <= 2.0 * f64::EPSILON * e {
            return next;
        }
        e = next;
    }
    e
}

/// The default identification: [`harmonic_fit`] of the first harmonic alone, read
/// through `model` ([`HarmonicFit::identified`]).
pub fn identify(periods: &[f64], model: Model) -> Result<Identified, EccError> {
    Ok(harmonic_fit(periods, FitOptions::default())?.identified(model))
}

/// Least-squares fit of the line periods on 1, cos Φ, sin Φ (and optionally cos 2Φ,
/// sin 2Φ and a linear trend), Φ_m = 2π(m + ½)/K. Without the trend the basis is
/// orthogonal on the K equally spaced phases, so each coefficient is a single DFT bin
/// (what the hardware accumulates); with it, the normal equations are solved.
pub fn harmonic_fit(periods: &[f64], opts: FitOptions) -> Result<HarmonicFit, EccError> {
    check_periods(periods)?;
    let n = periods.len();
    let k = n as f64;
    let mean = periods.iter().sum::<f64>() / k;
    let basis = |m: usize| {
        let phi = TAU * (m as f64 + 0.5) / k;
        let mut row = vec![1.0, phi.cos(), phi.sin()];
        if opts.second_harmonic {
            row.extend([(2.0 * phi).cos(), (2.0 * phi).sin()]);
        }
        if opts.trend {
            row.push((m as f64 + 0.5) / k - 0.5);
        }
        row
    };
    let cols = basis(0).len();
    let mut ata = vec![vec![0.0; cols]; cols];
    let mut aty = vec![0.0; cols];
    for (m, &p) in periods.iter().enumerate() {
        let row = basis(m);
        let y = p / mean;
        for ((ata_i, aty_i), &ri) in ata.iter_mut().zip(aty.iter_mut()).zip(&row) {
            *aty_i += ri * y;
            for (x, &rj) in ata_i.iter_mut().zip(&row) {
                *x += ri * rj;
            }
        }
    }
    let c = solve(ata, aty);
    // Cosine/sine coefficients → amplitude and phase of −a·cos(jΦ + p), with the
    // averaging over one line (sinc(jπ/K)) removed.
    let harmonic = |j: f64, alpha: f64, beta: f64| {
        let x = j * PI / k;
        let sinc = x.sin() / x;
        let (alpha, beta) = (alpha / c[0] / sinc, beta / c[0] / sinc);
        (alpha.hypot(beta), beta.atan2(-alpha).rem_euclid(TAU))
    };
    let (a1, p1) = harmonic(1.0, c[1], c[2]);
    let (a2, p2) = if opts.second_harmonic {
        harmonic(2.0, c[3], c[4])
    } else {
        (0.0, 0.0)
    };
    Ok(HarmonicFit {
        mean: c[0] * mean,
        trend: if opts.trend { c[cols - 1] / c[0] } else { 0.0 },
        a1,
        p1,
        a2,
        p2,
    })
}

/// Solves the small symmetric system a·x = b by Gaussian elimination with partial
/// pivoting (at most 6 unknowns here).
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            .unwrap_or(col);
        a.swap(col, pivot);
        b.swap(col, pivot);
        let (pivot_row, pivot_b) = (a[col].clone(), b[col]);
        for (r, br) in a.iter_mut().zip(b.iter_mut()).skip(col + 1) {
            let f = r[col] / pivot_row[col];
            for (x, p) in r[col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= f * p;
            }
            *br -= f * pivot_b;
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|j| a[row][j] * x[j]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x
}
