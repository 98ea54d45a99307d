// SPDX-License-Identifier: MIT OR Apache-2.0
//! What a frequency-response measurement is asked for ([`BodeSpec`]), its limits and
//! defaults, why one is refused ([`FreqRespError`]), and the core parameters it runs with.

use crate::params::{
    bits_for, dt_cycles_for, ParamError, Params, Spec, MAX_COUNTER_BITS, MIN_COUNTER_BITS,
};
use crate::smallsignal::SmallSignalError;
use std::fmt;
use std::str::FromStr;

/// Default relative detuning ε of the simulated mean speed, n̄·(1 + ε): √2·10⁻³, an
/// irrational number so that the encoder phase at the sample instants never repeats.
pub const DEFAULT_DETUNE: f64 = std::f64::consts::SQRT_2 * 1e-3;
/// Default ñ/n̄ for PC, ET and M/T.
pub const DEFAULT_AMPLITUDE: f64 = 0.02;
/// Default ñ/n̄ for n3: large enough that the modulation spans several quantisation steps
/// of ω_lim at the operating points of the docs (see the module docs).
pub const DEFAULT_AMPLITUDE_N3: f64 = 0.2;
/// Default clock (Hz) of the ET and M/T timestamps.
pub const DEFAULT_CLOCK_HZ: f64 = 100e6;
/// Default clock (Hz) of the core, which is simulated cycle by cycle: n3 and every
/// [`Source::Hardware`] measurement.
pub const DEFAULT_CLOCK_HZ_N3: f64 = 10e6;
/// Default least number of modulation periods in the analysis window.
pub const DEFAULT_MIN_PERIODS: u32 = 8;
/// Default least number of samples in the analysis window.
pub const DEFAULT_MIN_SAMPLES: u32 = 4000;
/// Cycles of reset at the start of an n3 run (as `tb::stimulus::RESET_CYCLES`).
pub const RESET_CYCLES: u64 = 3;
/// Most control samples one measurement may take (settling and window).
pub const MAX_SAMPLES: u64 = 20_000_000;
/// Most encoder transitions one measurement may simulate.
pub const MAX_TRANSITIONS: f64 = 10e6;
/// Most clock cycles one n3 measurement may simulate.
pub const MAX_CORE_CYCLES: u64 = 4_000_000_000;

/// The speed estimators measured here.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Estimator {
    /// Fixed time (pulse count): transitions counted in each T_s.
    Pc,
    /// Fixed space (elapsed time): time between the last two transitions, in clock periods.
    Et,
    /// Rairán's synchronised estimator n3, the bit-true core with dt = T_s.
    N3,
    /// M/T: transitions over the clock-timed span between the first and last of them.
    Mt,
}

impl Estimator {
    /// All four, in the order of the docs.
    pub const ALL: [Estimator; 4] = [Estimator::Pc, Estimator::Et, Estimator::N3, Estimator::Mt];

    /// Short name: `pc`, `et`, `n3`, `mt`.
    pub fn name(self) -> &'static str {
        match self {
            Estimator::Pc => "pc",
            Estimator::Et => "et",
            Estimator::N3 => "n3",
            Estimator::Mt => "mt",
        }
    }
}

/// `Display` as `name()`, and `FromStr` finding the name among `ALL` (an unknown name is
/// the error `$unknown`), for the option enums of `encspeed bode`.
macro_rules! named_option {
    ($t:ident, $unknown:path) => {
        impl fmt::Display for $t {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(self.name())
            }
        }

        impl FromStr for $t {
            type Err = FreqRespError;
            fn from_str(s: &str) -> Result<Self, Self::Err> {
                $t::ALL
                    .into_iter()
                    .find(|e| e.name() == s)
                    .ok_or_else(|| $unknown(s.to_owned()))
            }
        }
    };
}

named_option!(Estimator, FreqRespError::UnknownEstimator);
named_option!(Source, FreqRespError::UnknownSource);

/// Where PC, ET and M/T are measured: on the float estimators of [`ideal`](crate::ideal) and [`mt`](crate::ideal::mt), or
/// on the core's hardware outputs `speed_pc`, `speed_et`, `speed_mt` (the bit-true
/// [`CoreModel`](crate::top::core::CoreModel), whose every cycle the Verilog is checked against in `tb::freqresp`).
/// n3 exists on the core only.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Source {
    /// The float estimators: exact transition instants, timestamps quantised to `clock_hz`,
    /// read at the sample instants, no computation latency.
    Float,
    /// The core's outputs (x1, x2 or x4 decoding as `edges` 1, 2, 4), window dt = T_s of
    /// the free-running `cfg_dt` time base, read at each `baseline_strobe` (module docs).
    Hardware,
}

impl Source {
    /// Both, in the order of the docs.
    pub const ALL: [Source; 2] = [Source::Float, Source::Hardware];

    /// Short name: `float`, `hardware`.
    pub fn name(self) -> &'static str {
        match self {
            Source::Float => "float",
            Source::Hardware => "hardware",
        }
    }
}

/// Why an experiment or a frequency was refused. Each message starts with the name of the
/// parameter ([`FreqRespError::parameter`]) and gives the legal range.
#[derive(Clone, Debug, PartialEq)]
pub enum FreqRespError {
    /// Not one of `pc`, `et`, `n3`, `mt`.
    UnknownEstimator(String),
    /// Not one of `float`, `hardware`.
    UnknownSource(String),
    /// n3 exists on the core only: [`Source::Float`] is refused for it.
    FloatN3,
    /// `lines` is zero.
    Lines(u32),
    /// `edges` is not 1, 2 or 4, or not 1 for n3 (the core counts rising edges of A).
    Edges {
        /// The estimator.
        estimator: Estimator,
        /// Edges per line asked for.
        edges: u32,
    },
    /// `rpm` (the mean speed n̄, r/min) is not finite and > 0.
    Rpm(f64),
    /// `ts_s` (the control sample time T_s, s) is not finite and > 0.
    TsS(f64),
    /// `clock_hz` is not finite and > 0.
    ClockHz(f64),
    /// `amplitude` (ñ/n̄) is not in (0, 0.5].
    Amplitude(f64),
    /// `detune` (ε) is not finite with |ε| ≤ 0.01.
    Detune(f64),
    /// `min_periods` or `min_samples` is zero.
    Window {
        /// Which one.
        name: &'static str,
    },
    /// The operating point is out of the models' range.
    OperatingPoint(SmallSignalError),
    /// The core needs T_s to be a whole number ≥ 2 of clock periods (dt = T_s).
    DtCycles {
        /// T_s in s.
        ts_s: f64,
        /// The clock in Hz.
        clock_hz: f64,
    },
    /// The core cannot be built for these values.
    Core(ParamError),
    /// [`Source::Hardware`]: dt = T_s·clock is shorter than the baselines' computation
    /// latency, so windows would share a `baseline_strobe` (a start while busy replaces
    /// the pending request).
    HardwareWindow {
        /// dt, clock cycles.
        dt_cycles: u64,
        /// The latency of the baseline speeds block, clock cycles.
        latency_cycles: u64,
    },
    /// [`Source::Hardware`] M/T with fewer than one transition per window at the slowest
    /// speed: the core outputs `speed_mt` = 0 for a window without steps, which is no
    /// speed estimate (ET is the estimator for that range).
    MtEmptyWindows {
        /// Transitions per T_s at the slowest speed, l·(1 − ñ/n̄).
        l_min: f64,
    },
    /// A frequency (Hz) is not finite, > 0 and below the control Nyquist frequency 1/(2T_s).
    Frequency {
        /// The frequency asked for.
        f_hz: f64,
        /// 1/(2T_s).
        nyquist_hz: f64,
    },
    /// A frequency needs a longer simulation than the limits allow.
    TooLong {
        /// The frequency asked for.
        f_hz: f64,
        /// What ran over.
        what: String,
    },
    /// A logarithmic sweep that is not 0 < fmin ≤ fmax with 1 ≤ points ≤ 10 000
    /// (fmin = fmax needs points = 1).
    Sweep {
        /// Lowest frequency (Hz).
        fmin_hz: f64,
        /// Highest frequency (Hz).
        fmax_hz: f64,
        /// Number of frequencies.
        points: u32,
    },
}

impl FreqRespError {
    /// The parameter the error is about, as the `encspeed bode` option spells it without
    /// the dashes (`lines`, `edges`, `rpm`, `ts-s`, `clock-hz`, `amplitude`, `detune`,
    /// `fmin`, `fmax`, `points`, `estimator`, `source`).
    pub fn parameter(&self) -> &'static str {
        use FreqRespError as E;
        match self {
            E::UnknownEstimator(_) => "estimator",
            E::UnknownSource(_) | E::FloatN3 => "source",
            E::Lines(_) => "lines",
            E::Edges { .. } => "edges",
            E::Rpm(_) => "rpm",
            E::TsS(_) => "ts-s",
            E::ClockHz(_) | E::DtCycles { .. } => "clock-hz",
            E::Amplitude(_) => "amplitude",
            E::Detune(_) => "detune",
            E::Window { name } => name,
            E::OperatingPoint(_) => "rpm",
            E::Core(_) | E::HardwareWindow { .. } => "clock-hz",
            E::MtEmptyWindows { .. } => "rpm",
            E::Frequency { .. } => "fmax",
            E::Sweep {
                fmin_hz, points, ..
            } => {
                if !(1..=10_000).contains(points) {
                    "points"
                } else if !(fmin_hz.is_finite() && *fmin_hz > 0.0) {
                    "fmin"
                } else {
                    "fmax"
                }
            }
            E::TooLong { .. } => "fmin",
        }
    }
}

impl fmt::Display for FreqRespError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use FreqRespError as E;
        match self {
            E::UnknownEstimator(s) => {
                write!(f, "estimator `{s}` is unknown: use pc, et, n3 or mt")
            }
            E::UnknownSource(s) => {
                write!(f, "source `{s}` is unknown: use float or hardware")
            }
            E::FloatN3 => write!(
                f,
                "source = float: n3 exists on the core only (use source hardware)"
            ),
            E::Lines(v) => write!(f, "lines = {v}: the disc needs at least one line"),
            E::Edges { estimator, edges } => match estimator {
                Estimator::N3 => write!(
                    f,
                    "edges = {edges}: n3 runs on the core, which counts rising edges of A \
                     only (edges = 1)"
                ),
                _ => write!(f, "edges = {edges}: must be 1, 2 or 4 edges per line"),
            },
            E::Rpm(v) => write!(f, "rpm = {v}: the mean speed must be finite and > 0 r/min"),
            E::TsS(v) => write!(f, "ts-s = {v}: the sample time must be finite and > 0 s"),
            E::ClockHz(v) => write!(f, "clock-hz = {v}: must be finite and > 0 Hz"),
            E::Amplitude(v) => write!(
                f,
                "amplitude = {v}: the relative modulation depth n~/n must be in (0, 0.5]"
            ),
            E::Detune(v) => write!(f, "detune = {v}: must be finite with |detune| <= 0.01"),
            E::Window { name } => write!(f, "{name} = 0: must be at least 1"),
            E::OperatingPoint(e) => write!(f, "rpm: {e}"),
            E::DtCycles { ts_s, clock_hz } => write!(
                f,
                "clock-hz = {clock_hz}: the core needs ts-s x clock-hz = {} to be a whole \
                 number >= 2 of clock cycles (dt = T_s = {ts_s} s)",
                ts_s * clock_hz
            ),
            E::Core(e) => write!(f, "clock-hz: the core cannot be built: {e}"),
            E::HardwareWindow {
                dt_cycles,
                latency_cycles,
            } => write!(
                f,
                "clock-hz: dt = ts-s x clock-hz = {dt_cycles} cycles is shorter than the \
                 baseline speeds' latency of {latency_cycles} cycles; every window needs \
                 its own baseline_strobe"
            ),
            E::MtEmptyWindows { l_min } => write!(
                f,
                "rpm: M/T on the hardware needs at least one transition per T_s at the \
                 slowest speed, rpm x (1 - amplitude), which has {l_min:.4}: the core \
                 outputs speed_mt = 0 for a window without steps (measure et there)"
            ),
            E::Frequency { f_hz, nyquist_hz } => write!(
                f,
                "fmax: frequency {f_hz} Hz must be finite, > 0 and below the control Nyquist \
                 frequency 1/(2 T_s) = {nyquist_hz} Hz"
            ),
            E::TooLong { f_hz, what } => write!(
                f,
                "fmin: measuring at {f_hz} Hz needs {what}; raise the frequency or shorten \
                 the window"
            ),
            E::Sweep {
                fmin_hz,
                fmax_hz,
                points,
            } => write!(
                f,
                "{}: sweep fmin = {fmin_hz} Hz, fmax = {fmax_hz} Hz, points = {points}: need \
                 0 < fmin <= fmax, 1 <= points <= 10000, and points = 1 when fmin = fmax",
                self.parameter()
            ),
        }
    }
}

impl std::error::Error for FreqRespError {}

/// An experiment as a user states it. Speeds in r/min, times in s, frequencies in Hz.
#[derive(Clone, Debug, PartialEq)]
pub struct BodeSpec {
    /// Which estimator.
    pub estimator: Estimator,
    /// Float estimators or the core's outputs; n3 is [`Source::Hardware`] only.
    pub source: Source,
    /// Lines of the disc.
    pub lines: u32,
    /// Edges counted per line: 1 (A rising), 2 (A both) or 4 (A and B both); R = lines·edges.
    /// n3 accepts 1 only.
    pub edges: u32,
    /// Nominal mean speed n̄, r/min (> 0).
    pub rpm: f64,
    /// Control sample time T_s, s; on the core also dt.
    pub ts_s: f64,
    /// Clock of the float ET/M/T timestamps (float PC ignores it), or of the core, Hz.
    pub clock_hz: f64,
    /// Modulation depth ñ/n̄, in (0, 0.5].
    pub amplitude: f64,
    /// Relative detuning ε of the simulated mean speed n̄·(1 + ε), |ε| ≤ 0.01.
    pub detune: f64,
    /// Least number of modulation periods P in the analysis window (≥ 1).
    pub min_periods: u32,
    /// Least number of samples N in the analysis window (≥ 1).
    pub min_samples: u32,
}

impl BodeSpec {
    /// The defaults for `estimator`: `edges` 4 (1 for n3), clock [`DEFAULT_CLOCK_HZ`]
    /// ([`DEFAULT_CLOCK_HZ_N3`] for n3), amplitude [`DEFAULT_AMPLITUDE`]
    /// ([`DEFAULT_AMPLITUDE_N3`] for n3), [`DEFAULT_DETUNE`], [`DEFAULT_MIN_PERIODS`],
    /// [`DEFAULT_MIN_SAMPLES`].
    /// PC, ET and M/T are [`Source::Float`] here, n3 [`Source::Hardware`].
    pub fn new(estimator: Estimator, lines: u32, rpm: f64, ts_s: f64) -> BodeSpec {
        let n3 = estimator == Estimator::N3;
        BodeSpec {
            estimator,
            source: if n3 { Source::Hardware } else { Source::Float },
            lines,
            edges: if n3 { 1 } else { 4 },
            rpm,
            ts_s,
            clock_hz: if n3 {
                DEFAULT_CLOCK_HZ_N3
            } else {
                DEFAULT_CLOCK_HZ
            },
            amplitude: if n3 {
                DEFAULT_AMPLITUDE_N3
            } else {
                DEFAULT_AMPLITUDE
            },
            detune: DEFAULT_DETUNE,
            min_periods: DEFAULT_MIN_PERIODS,
            min_samples: DEFAULT_MIN_SAMPLES,
        }
    }

    /// [`BodeSpec::new`] measured on the core's outputs: [`Source::Hardware`] with the
    /// core's clock [`DEFAULT_CLOCK_HZ_N3`]; `edges` 4 (x4, `cfg_mode` = 2) for PC, ET and
    /// M/T. For n3 the same as [`BodeSpec::new`].
    pub fn hardware(estimator: Estimator, lines: u32, rpm: f64, ts_s: f64) -> BodeSpec {
        BodeSpec {
            source: Source::Hardware,
            clock_hz: DEFAULT_CLOCK_HZ_N3,
            ..BodeSpec::new(estimator, lines, rpm, ts_s)
        }
    }

    /// The experiment runs on the core (n3, or any estimator on [`Source::Hardware`]).
    pub fn on_core(&self) -> bool {
        self.source == Source::Hardware
    }
}

/// The core's parameters for `spec` and dt in cycles. `te_max_s` is the longest time
/// between transitions at the slowest speed (hardware baselines only: the ET period and
/// the M/T span must fit the counters).
pub(crate) fn core_params(spec: &BodeSpec, te_max_s: f64) -> Result<(Params, u64), FreqRespError> {
    let dt = dt_cycles_for(spec.clock_hz, spec.ts_s).map_err(|_| FreqRespError::DtCycles {
        ts_s: spec.ts_s,
        clock_hz: spec.clock_hz,
    })?;
    // Timeout: 1000 dt, far beyond any pulse period measured here (ñ ≤ n̄/2).
    let timeout_dt = 1000u64;
    let mut bits = (bits_for(dt).max(bits_for(timeout_dt)) + 1).max(MIN_COUNTER_BITS);
    if bits > MAX_COUNTER_BITS {
        return Err(FreqRespError::DtCycles {
            ts_s: spec.ts_s,
            clock_hz: spec.clock_hz,
        });
    }
    if spec.estimator != Estimator::N3 {
        // The ET period (one transition interval P) must stay below 2^N − 1, where the
        // timer saturates and reads as stalled, and the M/T span (at most dt + P) must
        // fit: twice dt + P, with room for the clock's rounding. n3's width is unchanged.
        let p_max = (te_max_s * spec.clock_hz).ceil() + 2.0;
        let need = 2.0 * (dt as f64 + p_max);
        let need_bits = if need < 2f64.powi(63) {
            bits_for(need as u64) + 1
        } else {
            u64::BITS
        };
        // Params::new refuses a width beyond MAX_COUNTER_BITS with its reason.
        bits = bits.max(need_bits);
    }
    let p = Params::new(Spec {
        clock_hz: spec.clock_hz,
        lines: spec.lines,
        dt_cycles: dt,
        counter_bits: bits,
        timeout_s: timeout_dt as f64 * dt as f64 / spec.clock_hz,
        ..Spec::default()
    })
    .map_err(FreqRespError::Core)?;
    Ok((p, dt))
}
