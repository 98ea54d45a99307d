// SPDX-License-Identifier: MIT OR Apache-2.0
//! The elementary factors of the paper's transfer functions (ZOH, delay, moving average,
//! lead), each evaluated two ways: literally as printed, at any complex s
//! ([`Factor::eval`]), and in closed polar form on s = jω ([`Factor::polar`]), which gives
//! the phase without wrapping. The tests check that the two agree.

use super::bode::BodePoint;
use super::error::SmallSignalError;
use num_complex::Complex64;
use std::f64::consts::PI;

/// 1 − e^{−z}, accurate for small |z|. The naive form loses all digits as z → 0 (it is a
/// difference of two numbers near 1), and ZOH(s, T) must tend to 1 as f → 0. With w = −z =
/// a + jb: e^w − 1 = (expm1(a)·cos b − 2·sin²(b/2)) + j·e^a·sin b, which has no
/// cancellation.
fn one_minus_exp_neg(z: Complex64) -> Complex64 {
    let (a, b) = (-z.re, -z.im);
    let half = (b / 2.0).sin();
    let re = a.exp_m1() * b.cos() - 2.0 * half * half;
    let im = a.exp() * b.sin();
    -Complex64::new(re, im)
}

/// The zero-order hold ZOH(s, T) = (1 − e^{−sT})/(sT), s in rad/s (complex), T in s.
/// Unity at s = 0 (the limit, returned exactly). On s = jω it equals
/// e^{−jωT/2}·sin(ωT/2)/(ωT/2): an average over T, delay T/2.
pub fn zoh(s: Complex64, t_s: f64) -> Complex64 {
    let x = s * t_s;
    if x == Complex64::new(0.0, 0.0) {
        return Complex64::new(1.0, 0.0);
    }
    one_minus_exp_neg(x) / x
}

/// ZOH(j2πf, T): f in Hz, T in s. See [`zoh`].
pub fn zoh_at(f_hz: f64, t_s: f64) -> Complex64 {
    zoh(Complex64::new(0.0, 2.0 * PI * f_hz), t_s)
}

/// Eq. (10): (1/L)·(1 − e^{−sT_s})/(1 − e^{−sT_s/L}), unity at s = 0.
fn moving_average(s: Complex64, ts_s: f64, l: f64) -> Complex64 {
    let x = s * ts_s;
    if x == Complex64::new(0.0, 0.0) {
        return Complex64::new(1.0, 0.0);
    }
    one_minus_exp_neg(x) / (one_minus_exp_neg(x / l) * l)
}

/// sin(u)/u, 1 at u = 0.
fn sinc(u: f64) -> f64 {
    if u == 0.0 {
        1.0
    } else {
        u.sin() / u
    }
}

/// The real Dirichlet kernel sin(L·y)/(L·sin y), the amplitude of eq. (10) on s = jω
/// with y = ωT_s/(2L). Where sin y vanishes and so does sin(L·y) (y = kπ, integer L) the
/// limit cos(L·y)/cos(y) = ±1 is used (L'Hôpital); for a non-integer L the real-L
/// continuation of eq. (10) has a genuine pole there, returned as ±∞ or a huge value.
fn dirichlet(l: f64, y: f64) -> f64 {
    let den = y.sin();
    let num = (l * y).sin();
    // sin y ≈ ±δ near y = kπ; below 1e-12 the linear L'Hôpital step is exact to ~1e-24.
    if den.abs() < 1e-12 && num.abs() < 1e-12 * l {
        return (l * y).cos() / y.cos();
    }
    num / (l * den)
}

/// A transfer function on s = jω as a signed real amplitude times e^{jφ}, with φ (rad)
/// continuous in ω. [`Polar::to_bode_point`] turns it into gain and phase.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Polar {
    /// Signed real amplitude, dimensionless (negative past an odd number of zeros).
    pub amplitude: f64,
    /// Continuous phase in rad (delays' linear phase plus the lead's arctangents).
    pub phase_rad: f64,
}

impl Polar {
    /// amplitude · e^{j·phase}.
    pub fn to_complex(self) -> Complex64 {
        Complex64::from_polar(self.amplitude, self.phase_rad)
    }

    /// Gain |amplitude| (linear and dB) and phase in degrees, + 180° where the amplitude
    /// is negative (see [`BodePoint::phase_deg`]); `f_hz` is stored as given.
    pub fn to_bode_point(self, f_hz: f64) -> BodePoint {
        let gain = self.amplitude.abs();
        let flip = if self.amplitude < 0.0 { 180.0 } else { 0.0 };
        BodePoint {
            freq_hz: f_hz,
            gain,
            gain_db: 20.0 * gain.log10(),
            phase_deg: self.phase_rad.to_degrees() + flip,
        }
    }
}

/// One elementary factor of a [`Model`](super::Model). Times in s; L and α, β dimensionless.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Factor {
    /// ZOH(s, T) = (1 − e^{−sT})/(sT): a sample-and-hold with period T, or an average
    /// over T. Delay T/2.
    Zoh {
        /// T in s.
        t_s: f64,
    },
    /// A pure delay e^{−sT}.
    Delay {
        /// T in s.
        t_s: f64,
    },
    /// Eq. (10): the L-transition counter as a moving average, (1/L)·(1 − e^{−sT_s})/(1 −
    /// e^{−sT_s/L}); an FIR of L taps spaced T_s/L, delay (T_s − T_s/L)/2.
    MovingAverage {
        /// T_s in s.
        ts_s: f64,
        /// L, transitions per T_s (real, ≥ 1; Appendix B).
        l: f64,
    },
    /// Eq. (33): the lead compensator (1 + sT_e/α)/(1 + sT_e/β): zero at α/T_e rad/s,
    /// pole at β/T_e rad/s.
    Lead {
        /// T_e in s at the reference speed.
        te_s: f64,
        /// α, dimensionless.
        alpha: f64,
        /// β, dimensionless.
        beta: f64,
    },
}

/// `Err` unless `value` is a finite time > 0 s.
fn check_time(name: &'static str, value: f64) -> Result<(), SmallSignalError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(SmallSignalError::Time { name, value })
    }
}

impl Factor {
    /// Checks the factor's numbers (see [`SmallSignalError`]).
    pub fn validate(&self) -> Result<(), SmallSignalError> {
        match *self {
            Factor::Zoh { t_s } | Factor::Delay { t_s } => check_time("t_s", t_s),
            Factor::MovingAverage { ts_s, l } => {
                check_time("ts_s", ts_s)?;
                if l.is_finite() && l >= 1.0 {
                    Ok(())
                } else {
                    Err(SmallSignalError::MovingAverageLength(l))
                }
            }
            Factor::Lead { te_s, alpha, beta } => {
                check_time("te_s", te_s)?;
                Lead::new(alpha, beta).map(|_| ())
            }
        }
    }

    /// The factor as printed in the paper, at complex s (rad/s).
    pub fn eval(&self, s: Complex64) -> Complex64 {
        match *self {
            Factor::Zoh { t_s } => zoh(s, t_s),
            Factor::Delay { t_s } => (-s * t_s).exp(),
            Factor::MovingAverage { ts_s, l } => moving_average(s, ts_s, l),
            Factor::Lead { te_s, alpha, beta } => {
                (1.0 + s * (te_s / alpha)) / (1.0 + s * (te_s / beta))
            }
        }
    }

    /// The factor on s = j2πf (f in Hz) in closed polar form.
    pub fn polar(&self, f_hz: f64) -> Polar {
        let w = 2.0 * PI * f_hz;
        let (amplitude, phase_rad) = match *self {
            Factor::Zoh { t_s } => (sinc(w * t_s / 2.0), -w * t_s / 2.0),
            Factor::Delay { t_s } => (1.0, -w * t_s),
            Factor::MovingAverage { ts_s, l } => (
                dirichlet(l, w * ts_s / (2.0 * l)),
                -w * (ts_s - ts_s / l) / 2.0,
            ),
            Factor::Lead { te_s, alpha, beta } => {
                let (a, b) = (w * te_s / alpha, w * te_s / beta);
                (((1.0 + a * a) / (1.0 + b * b)).sqrt(), a.atan() - b.atan())
            }
        };
        Polar {
            amplitude,
            phase_rad,
        }
    }

    /// −dφ/dω at ω → 0, in s (negative for the lead: it advances).
    pub fn low_frequency_delay_s(&self) -> f64 {
        match *self {
            Factor::Zoh { t_s } => t_s / 2.0,
            Factor::Delay { t_s } => t_s,
            Factor::MovingAverage { ts_s, l } => (ts_s - ts_s / l) / 2.0,
            Factor::Lead { te_s, alpha, beta } => -(te_s / alpha - te_s / beta),
        }
    }
}

/// Validated coefficients of the lead compensator of eq. (33): 0 < α < β, dimensionless.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lead {
    alpha: f64,
    beta: f64,
}

impl Lead {
    /// The paper's Section IV choice, α = 0.8, β = 10.
    pub const PAPER: Lead = Lead {
        alpha: 0.8,
        beta: 10.0,
    };

    /// Refuses anything but 0 < α < β, both finite (α ≥ β would be a lag network).
    pub fn new(alpha: f64, beta: f64) -> Result<Self, SmallSignalError> {
        if alpha.is_finite() && beta.is_finite() && alpha > 0.0 && alpha < beta {
            Ok(Lead { alpha, beta })
        } else {
            Err(SmallSignalError::LeadCoefficients { alpha, beta })
        }
    }

    /// α (zero at α/T_e rad/s).
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// β (pole at β/T_e rad/s).
    pub fn beta(&self) -> f64 {
        self.beta
    }
}
