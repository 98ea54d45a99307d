// SPDX-License-Identifier: MIT OR Apache-2.0
//! The paper's transfer functions as named products of [`Factor`]s: eqs. (15), (16), (24),
//! (27)–(29) and (33), built from a validated [`OperatingPoint`].

use super::bode::{Bode, BodePoint};
use super::error::SmallSignalError;
use super::factor::{Factor, Lead, Polar};
use super::operating_point::OperatingPoint;
use num_complex::Complex64;
use std::f64::consts::PI;

/// A transfer function: a named product of [`Factor`]s, every factor validated.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    name: String,
    factors: Vec<Factor>,
}

impl Model {
    /// Any product of factors, each validated. `name` labels the Bode output.
    pub fn new(name: impl Into<String>, factors: Vec<Factor>) -> Result<Self, SmallSignalError> {
        for f in &factors {
            f.validate()?;
        }
        Ok(Model {
            name: name.into(),
            factors,
        })
    }

    /// Factors taken from a validated [`OperatingPoint`], which are legal by construction.
    fn trusted(name: &str, factors: Vec<Factor>) -> Self {
        debug_assert!(factors.iter().all(|f| f.validate().is_ok()));
        Model {
            name: name.to_owned(),
            factors,
        }
    }

    /// ZOH(s, T) alone, T in s.
    pub fn zoh(t_s: f64) -> Result<Self, SmallSignalError> {
        Model::new("ZOH", vec![Factor::Zoh { t_s }])
    }

    /// PC method, eq. (15): moving average over L̄ = l transitions (eq. 10) · e^{−sT_s/(2L̄)}
    /// · ZOH(s, T_s). Valid for l ≥ 1 (refused below). On s = jω it equals eq. (16) times
    /// the real factor y/sin y, y = ωT_s/(2L̄): same phase −ωT_s below f = L̄/T_s.
    pub fn pc_eq15(op: &OperatingPoint) -> Result<Self, SmallSignalError> {
        let (ts_s, l) = (op.ts_s(), op.big_l());
        if l < 1.0 {
            return Err(SmallSignalError::PcBelowOneTransition { l });
        }
        Ok(Model::trusted(
            "PC eq. (15)",
            vec![
                Factor::MovingAverage { ts_s, l },
                Factor::Delay {
                    t_s: ts_s / (2.0 * l),
                },
                Factor::Zoh { t_s: ts_s },
            ],
        ))
    }

    /// PC method simplified for large L, eq. (16): ZOH(s, T_s)², delay T_s. Refused for
    /// l < 1 like eq. (15); the paper uses it for L ≥ 10.
    pub fn pc_eq16(op: &OperatingPoint) -> Result<Self, SmallSignalError> {
        let (ts_s, l) = (op.ts_s(), op.big_l());
        if l < 1.0 {
            return Err(SmallSignalError::PcBelowOneTransition { l });
        }
        Ok(Model::trusted(
            "PC eq. (16)",
            vec![Factor::Zoh { t_s: ts_s }, Factor::Zoh { t_s: ts_s }],
        ))
    }

    /// ET method, eq. (24): ZOH(s, T_e)² · ZOH(s, T_s), delay T_e + T_s/2. Valid at any
    /// speed (the paper, Section III).
    pub fn et_eq24(op: &OperatingPoint) -> Self {
        let (te, ts) = (op.te_s(), op.ts_s());
        Model::trusted(
            "ET eq. (24)",
            vec![
                Factor::Zoh { t_s: te },
                Factor::Zoh { t_s: te },
                Factor::Zoh { t_s: ts },
            ],
        )
    }

    /// H_Enc.2 of Section IV: eq. (24) without its S/H term ZOH(s, T_s), i.e. ZOH(s, T_e)²,
    /// because footnote 2 says that term is already in the measured loop gain.
    pub fn et_encoder_section_iv(op: &OperatingPoint) -> Self {
        let te = op.te_s();
        Model::trusted(
            "ET eq. (24) without S/H-Ts",
            vec![Factor::Zoh { t_s: te }, Factor::Zoh { t_s: te }],
        )
    }

    /// Literature PC model, eq. (27) (Bonert, ref. 23): e^{−sT_s/2}, unity gain. The converted
    /// text prints "I_s/2"; Bonert's half-sample delay is T_s/2.
    pub fn literature_pc_eq27(op: &OperatingPoint) -> Self {
        Model::trusted(
            "Literature PC eq. (27)",
            vec![Factor::Delay {
                t_s: op.ts_s() / 2.0,
            }],
        )
    }

    /// Literature ET model 1, eq. (28) (Bonert, ref. 23): e^{−sT_e}, unity gain.
    pub fn literature_et1_eq28(op: &OperatingPoint) -> Self {
        Model::trusted(
            "Literature ET-1 eq. (28)",
            vec![Factor::Delay { t_s: op.te_s() }],
        )
    }

    /// Literature ET model 2, eq. (29) (Bascetta et al., ref. 24): ZOH(s, T_e), delay T_e/2.
    pub fn literature_et2_eq29(op: &OperatingPoint) -> Self {
        Model::trusted(
            "Literature ET-2 eq. (29)",
            vec![Factor::Zoh { t_s: op.te_s() }],
        )
    }

    /// Lead compensator, eq. (33): (1 + sT_e/α)/(1 + sT_e/β) with T_e = 60/(R·n*) of the
    /// operating point (n* its speed). Maximum lead asin((β−α)/(β+α)) at ω = √(αβ)/T_e.
    pub fn lead_eq33(op: &OperatingPoint, lead: Lead) -> Self {
        Model::trusted(
            "Lead eq. (33)",
            vec![Factor::Lead {
                te_s: op.te_s(),
                alpha: lead.alpha(),
                beta: lead.beta(),
            }],
        )
    }

    /// The product self · other, named "self · other".
    pub fn times(&self, other: &Model) -> Model {
        let mut factors = self.factors.clone();
        factors.extend_from_slice(&other.factors);
        Model {
            name: format!("{} · {}", self.name, other.name),
            factors,
        }
    }

    /// Label used in the Bode output.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The factors, in order.
    pub fn factors(&self) -> &[Factor] {
        &self.factors
    }

    /// The transfer function as printed, at complex s (rad/s). Ill-conditioned exactly at
    /// f = k·L/T_s for eq. (15) (0/0 in eq. 10); use [`Model::polar`] there.
    pub fn eval(&self, s: Complex64) -> Complex64 {
        self.factors
            .iter()
            .fold(Complex64::new(1.0, 0.0), |acc, f| acc * f.eval(s))
    }

    /// [`Model::eval`] at s = j2πf, f in Hz.
    pub fn eval_at(&self, f_hz: f64) -> Complex64 {
        self.eval(Complex64::new(0.0, 2.0 * PI * f_hz))
    }

    /// Closed polar form on s = j2πf (f in Hz): amplitudes multiply, phases add.
    pub fn polar(&self, f_hz: f64) -> Polar {
        self.factors.iter().fold(
            Polar {
                amplitude: 1.0,
                phase_rad: 0.0,
            },
            |acc, f| {
                let p = f.polar(f_hz);
                Polar {
                    amplitude: acc.amplitude * p.amplitude,
                    phase_rad: acc.phase_rad + p.phase_rad,
                }
            },
        )
    }

    /// Gain and phase at one frequency f in Hz (not validated: NaN in, NaN out).
    pub fn at(&self, f_hz: f64) -> BodePoint {
        self.polar(f_hz).to_bode_point(f_hz)
    }

    /// Gain and phase over a frequency vector (Hz, each finite and ≥ 0, any order).
    pub fn bode(&self, freqs_hz: &[f64]) -> Result<Bode, SmallSignalError> {
        if let Some(&bad) = freqs_hz.iter().find(|f| !(f.is_finite() && **f >= 0.0)) {
            return Err(SmallSignalError::Frequency(bad));
        }
        Ok(Bode {
            name: self.name.clone(),
            points: freqs_hz.iter().map(|&f| self.at(f)).collect(),
        })
    }

    /// −dφ/dω at ω → 0 in s: the average delay the model imposes on slow signals (the
    /// sum of the factors' delays; the lead counts negative).
    pub fn low_frequency_delay_s(&self) -> f64 {
        self.factors.iter().map(Factor::low_frequency_delay_s).sum()
    }
}

/// Phase margin (degrees) after multiplying a loop of margin `pm_deg` at crossover
/// `crossover_hz` by `added`, assuming the crossover does not move: pm_deg + ∠added(j2πf_c).
/// This is exact only if |added(j2πf_c)| = 1; otherwise the crossover shifts and the
/// loop's own phase at the new crossover is needed, which the paper does not give.
pub fn phase_margin_at_fixed_crossover(pm_deg: f64, crossover_hz: f64, added: &Model) -> f64 {
    pm_deg + added.at(crossover_hz).phase_deg
}
