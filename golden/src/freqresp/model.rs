// SPDX-License-Identifier: MIT OR Apache-2.0
//! The models a measurement is compared with: the paper's small-signal models and the
//! ones derived here for n3 and M/T, with the hardware's delay ([`FreqModel`]).

use super::spec::*;
use crate::ideal::update_interval;
use crate::params::Params;
use crate::smallsignal::{zoh_at, BodePoint, Complex64, Factor, Model, OperatingPoint, Polar};
use std::f64::consts::PI;

/// The model an experiment is compared with, including the S/H ZOH(s, T_s).
#[derive(Clone, Debug, PartialEq)]
pub enum FreqModel {
    /// A product of factors (PC eq. 15/16, ET eq. 24, the n3 model).
    Product(Model),
    /// The M/T model for l ≥ 1 (derived in the docs): a mixture of windows of ⌊l⌋ and
    /// ⌊l⌋ + 1 transition intervals ending at a transition of uniformly distributed age,
    /// times ZOH(s, T_s), times e^{−s·latency_s}.
    MtMixture {
        /// Time between transitions T_e, s.
        te_s: f64,
        /// T_s, s.
        ts_s: f64,
        /// A pure delay after the estimator (the hardware's latency), s; 0 for the float
        /// estimator.
        latency_s: f64,
    },
}

/// Label of the pure delay [`FreqModel::delayed`] appends.
pub(crate) fn latency_label(latency_s: f64) -> String {
    format!("e^(-s·{:.2} µs)", latency_s * 1e6)
}

impl FreqModel {
    /// Label for tables and plots.
    pub fn name(&self) -> String {
        match self {
            FreqModel::Product(m) => m.name().to_owned(),
            FreqModel::MtMixture { latency_s, .. } => {
                let mut s = "M/T (derived mixture) · ZOH(Ts)".to_owned();
                if *latency_s > 0.0 {
                    s = format!("{s} · {}", latency_label(*latency_s));
                }
                s
            }
        }
    }

    /// This model followed by the pure delay e^{−s·`latency_s`}, `latency_s` > 0: how a
    /// hardware estimator that publishes its result `latency_s` after the end of its
    /// window compares with the paper's model of the same window (module docs).
    pub fn delayed(&self, latency_s: f64) -> FreqModel {
        assert!(
            latency_s.is_finite() && latency_s > 0.0,
            "latency {latency_s}"
        );
        match self {
            FreqModel::Product(m) => FreqModel::Product(
                m.times(
                    &Model::new(
                        latency_label(latency_s),
                        vec![Factor::Delay { t_s: latency_s }],
                    )
                    .expect("a finite delay > 0"),
                ),
            ),
            FreqModel::MtMixture {
                te_s,
                ts_s,
                latency_s: l0,
            } => FreqModel::MtMixture {
                te_s: *te_s,
                ts_s: *ts_s,
                latency_s: l0 + latency_s,
            },
        }
    }

    /// H(j2πf), f in Hz.
    pub fn response(&self, f_hz: f64) -> Complex64 {
        match self {
            FreqModel::Product(m) => m.polar(f_hz).to_complex(),
            FreqModel::MtMixture {
                te_s,
                ts_s,
                latency_s,
            } => {
                mt_mixture(f_hz, *te_s, *ts_s)
                    * Complex64::from_polar(1.0, -2.0 * PI * f_hz * latency_s)
            }
        }
    }

    /// −dφ/dω at ω → 0, s.
    pub fn low_frequency_delay_s(&self) -> f64 {
        match self {
            FreqModel::Product(m) => m.low_frequency_delay_s(),
            FreqModel::MtMixture {
                te_s,
                ts_s,
                latency_s,
            } => ts_s + te_s / 2.0 + latency_s,
        }
    }

    /// Gain and phase at f (Hz), the phase continuous in f with the convention of
    /// [`crate::smallsignal::BodePoint::phase_deg`]. Both terms of the mixture have the
    /// phase −2πf·D, D = T_s + T_e/2 (+ the latency) (docs/frequency-response.md), so
    /// H·e^{j2πfD} is real and is the signed amplitude.
    pub fn at(&self, f_hz: f64) -> BodePoint {
        match self {
            FreqModel::Product(m) => m.at(f_hz),
            FreqModel::MtMixture { .. } => {
                let d = self.low_frequency_delay_s();
                let w = 2.0 * PI * f_hz;
                let real = self.response(f_hz) * Complex64::from_polar(1.0, w * d);
                debug_assert!(real.im.abs() <= 1e-9 * (1.0 + real.re.abs()));
                Polar {
                    amplitude: real.re,
                    phase_rad: -w * d,
                }
                .to_bode_point(f_hz)
            }
        }
    }
}

/// The M/T mixture for l = T_s/T_e ≥ 1, times ZOH(T_s) (see [`FreqModel::MtMixture`]):
/// ZOH(L₀T_e)·(1−g)·e^{−jωgT_e}·ZOH((1−g)T_e) + ZOH((L₀+1)T_e)·g·ZOH(gT_e), L₀ = ⌊l⌋,
/// g = l − L₀.
pub(crate) fn mt_mixture(f_hz: f64, te_s: f64, ts_s: f64) -> Complex64 {
    let l = ts_s / te_s;
    let l0 = l.floor();
    let g = l - l0;
    let w = 2.0 * PI * f_hz;
    // zoh_at returns exactly 1 for T = 0 (g = 0 or g = 1 − 0).
    let a = zoh_at(f_hz, l0 * te_s)
        * Complex64::from_polar(1.0 - g, -w * g * te_s)
        * zoh_at(f_hz, (1.0 - g) * te_s);
    let b = zoh_at(f_hz, (l0 + 1.0) * te_s) * g * zoh_at(f_hz, g * te_s);
    (a + b) * zoh_at(f_hz, ts_s)
}

/// The PC model: eq. (16), ZOH(s, T_s)², for every l. The expected count over a
/// uniformly distributed encoder phase is exactly the angle travelled in the window over
/// one transition, so the phase-averaged PC output is the mean speed over [t_{k−1}, t_k):
/// ZOH(T_s) at the sample instants, ZOH(T_s)² with the S/H. Eq. (15) has the same phase
/// and a gain larger by y/sin y, y = πf·T_s/l (docs/frequency-response.md shows the
/// measurement deciding for eq. 16 at l = 1.5).
pub fn pc_model(op: &OperatingPoint) -> Model {
    Model::new(
        "PC eq. (16)",
        vec![
            Factor::Zoh { t_s: op.ts_s() },
            Factor::Zoh { t_s: op.ts_s() },
        ],
    )
    .expect("T_s of a validated operating point")
}

/// The model for n3 with dt = T_s (derived in docs/frequency-response.md): the speed
/// averaged over a window W, updated every T_u (asynchronously to the samples), sampled
/// and held: ZOH(W)·ZOH(T_u)·ZOH(T_s). With r = n̄/ω_lim (pulses per dt) and T = dt/r the
/// pulse period: W = dt, T_u = (⌊r⌋+1)/r·dt for r ≥ 1 (Nep1 counts the pulses of a dt
/// window that starts at a pulse); W = T_u = T for r < 1 (Ndt1 times one pulse period).
pub fn n3_model(op: &OperatingPoint) -> Model {
    let dt = op.ts_s();
    let r = op.l();
    let window = if r >= 1.0 { dt } else { dt / r };
    let tu = update_interval(r) * dt;
    Model::new(
        "n3 ZOH(W)·ZOH(Tu)·ZOH(Ts)",
        vec![
            Factor::Zoh { t_s: window },
            Factor::Zoh { t_s: tu },
            Factor::Zoh { t_s: dt },
        ],
    )
    .expect("times of a validated operating point")
}

/// The M/T model (derived in docs/frequency-response.md), including ZOH(T_s): for l < 1,
/// ZOH(T_e)²·ZOH(T_s) (one transition interval of uniformly distributed age, as ET); for
/// l ≥ 1, [`FreqModel::MtMixture`].
pub fn mt_model(op: &OperatingPoint) -> FreqModel {
    let (te, ts) = (op.te_s(), op.ts_s());
    if op.l() < 1.0 {
        FreqModel::Product(
            Model::new(
                "M/T l<1: ZOH(Te)²·ZOH(Ts)",
                vec![
                    Factor::Zoh { t_s: te },
                    Factor::Zoh { t_s: te },
                    Factor::Zoh { t_s: ts },
                ],
            )
            .expect("times of a validated operating point"),
        )
    } else {
        FreqModel::MtMixture {
            te_s: te,
            ts_s: ts,
            latency_s: 0.0,
        }
    }
}

/// The model of the estimator's window at the sample (or strobe) instants, including the
/// S/H ZOH(T_s): PC eq. (16), ET eq. (24), and the derived n3 and M/T models.
pub(crate) fn paper_model(estimator: Estimator, op: &OperatingPoint) -> FreqModel {
    match estimator {
        Estimator::Pc => FreqModel::Product(pc_model(op)),
        Estimator::Et => FreqModel::Product(Model::et_eq24(op)),
        Estimator::N3 => FreqModel::Product(n3_model(op)),
        Estimator::Mt => mt_model(op),
    }
}

/// Clock edges from a `start` of the baseline speeds block to its `baseline_strobe`:
/// 4·(N + F + 1) + 4 ([`crate::baselines::baseline_speeds::latency_cycles`]).
pub fn baseline_latency_cycles(p: &Params) -> u64 {
    u64::from(crate::baselines::baseline_speeds::latency_cycles(
        p.counter_bits(),
        p.speed_frac_bits(),
    ))
}

/// Clock cycles from the end of the window a hardware baseline describes, in plant time,
/// to the `baseline_strobe` that publishes it: the latency the model is delayed by.
///
/// Cycle c samples the encoder at t = c/f_clk (an edge at t is seen first by cycle ⌈t·f⌉).
/// A level sampled at cycle c reaches the counters as a decoder step at cycle c + E,
/// E = [`crate::top::ports::Latency::edge_to_position`] (4 without the glitch filter). The
/// time base ticks at edge T. PC's window holds the steps at edges T − dt … T − 1 (the
/// tick's own step opens the next window), so it ends at the sampling cycle T − 1 − E;
/// ET's last period and M/T's measurement include the step at edge T: they end at
/// T − E. The block takes the `start` of the tick one edge later, T + 1, and publishes
/// [`baseline_latency_cycles`] L after that. So D = L + 1 + E + 1 for PC, L + 1 + E for
/// ET and M/T: with N = 13, F = 16 (dt = 1000 cycles at 3600 r/min), L = 64 and D = 70
/// and 69 cycles.
pub fn window_to_strobe_cycles(estimator: Estimator, p: &Params) -> u64 {
    let e = u64::from(crate::top::ports::Latency::new(p, 0).edge_to_position);
    let pc_extra = u64::from(estimator == Estimator::Pc);
    baseline_latency_cycles(p) + 1 + e + pc_extra
}
