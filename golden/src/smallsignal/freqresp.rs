//! The paper's VCO experiment in simulation: the frequency response of the speed
//! estimators, measured on the golden models and set beside their small-signal models.
//!
//! Vázquez-Gutiérrez et al. (2019), Section III, drive a DSP's encoder peripheral with a
//! voltage-controlled oscillator whose frequency is modulated by a network analyser, and
//! compare the speed the DSP computes (written to a DAC every T_s) with the modulation.
//! Here the same experiment runs on the plant and estimator models:
//!
//! 1. **Input.** The shaft speed is n(t) = n̄ + ñ·sin(2πft), t from 0, in r/min at the
//!    interface ([`BodeSpec::rpm`], [`BodeSpec::amplitude`] = ñ/n̄) and in rev/s inside
//!    ([`Segment::Sine`]). The disc has `lines` lines; an estimator counts
//!    R = lines·`edges` transitions per revolution: `edges` = 1 counts rising edges of A,
//!    2 both edges of A, 4 every edge of A and B (quadrature ×4). The paper's R is this R
//!    (its Table I: 1, 2 or 4 times the lines).
//! 2. **Estimators**, each producing one value y_k per control sample t_k = k·T_s (k ≥ 1),
//!    in rev/s, the latest estimate at t_k as a sampled controller reads it (the float
//!    estimators and n3; the hardware PC, ET, M/T are read at their strobe, below):
//!    - [`Estimator::Pc`], fixed time: transitions counted in the window from t_(k−1)
//!      (included) to t_k (excluded) ([`ideal::fixed_time`]), divided by R·T_s.
//!    - [`Estimator::Et`], fixed space: the time between the last two transitions before
//!      t_k counted in periods of a clock of `clock_hz` ([`ideal::fixed_space`]).
//!    - [`Estimator::N3`], Rairán's synchronised estimator: the bit-true core
//!      ([`CoreModel`]) stepped at `clock_hz` with dt = T_s, fed with the levels of A
//!      (so R = lines, `edges` = 1); n3(Nep1, Ndt1)·ω_lim read at the clock edge of t_k.
//!    - [`Estimator::Mt`], M/T ([`mt::mt_estimates`]): transitions since the last
//!      measurement over the time between the first and last of them, timestamps
//!      quantised to the clock.
//! 3. **Analysis** ([`Experiment::plan`], [`Experiment::analyse`]). A settling transient
//!    of `settle` samples is discarded; the next N samples span exactly P periods of the
//!    modulation (the frequency is moved to f = P/(N·T_s), the nearest such frequency, and
//!    reported). The single DFT bin of the output at f is divided by the same bin of the
//!    input sampled at the same instants:
//!    H_sampled(f) = Σ y_k·e^(−j2πf·t_k) / Σ ñ·sin(2πf·t_k)·e^(−j2πf·t_k), the sums over
//!    the window, f·t_k = P·k/N reduced in integers. This is what a controller sampling at
//!    t_k sees: an estimate equal to the speed delayed by D measures e^(−j2πfD), so a pure
//!    delay of T_s/2 measures −180°·f·T_s.
//! 4. **Convention of the models.** The paper's models include the sample-and-hold of the
//!    control loop, ZOH(s, T_s) (eqs. 15, 16, 24), because its analyser compared the
//!    continuous DAC staircase with the continuous input. The Fourier coefficient at f of
//!    that staircase (y_k held from t_k to t_k + T_s) over the window, divided by the one
//!    of n(t), is exactly H(f) = H_sampled(f)·ZOH(j2πf, T_s). [`Measurement::h`] is this
//!    H and is what is compared with the models; [`Measurement::h_sampled`] is kept. The
//!    measured phase is reported on the model's branch (the difference wrapped into
//!    (−180°, 180°]).
//!
//! **On the hardware** ([`Source::Hardware`]; n3 always). The bit-true core
//! ([`CoreModel`]) is stepped at `clock_hz` on the sampled levels of A, B and Z (cycle c
//! carries the levels at t = c/f_clk; 3 cycles of reset; `cfg_dt` = dt = T_s·f_clk;
//! `cfg_mode` x1, x2, x4 for `edges` 1, 2, 4). PC, ET and M/T are the outputs
//! `speed_pc`, `speed_et`, `speed_mt` (Q(N).F in units of ω_lim, one line per dt), whose
//! windows are those of the free-running `cfg_dt` time base; they are **read at their
//! `baseline_strobe`**, the cycle k·dt + 3 + L ([`Experiment::read_offset_cycles`], L =
//! [`baseline_latency_cycles`]), not at k·T_s: the strobe is periodic with T_s, it is the
//! earliest instant the estimate exists, and a controller that takes its samples from it
//! sees exactly this; a controller sampling at other instants adds the age of the last
//! strobe, a pure delay it knows. The analysis puts each value at the instant it was read
//! (the bin is rotated by e^{−j2πf·c}, c the read offset), so the measurement is the
//! estimator's window response times the hardware's delay from window end to strobe,
//! D = [`window_to_strobe_cycles`] (about 70 cycles), and the model compared is the float
//! estimator's model × e^{−sD} ([`FreqModel::delayed`]). The clock quantises each
//! transition to the next clock edge: PC's window stays an exact interval of plant time
//! (no effect in expectation); ET's period and M/T's span are whole cycles, within one
//! cycle of the truth and unbiased when the encoder phase against the clock is uniform,
//! so what is left is an error of ±1 cycle per period (±1/P relative for a period of P
//! cycles), a pattern of the encoder phase against the clock, not white noise, whose
//! share in the DFT bin falls as 1/ñ. M/T on the hardware needs a step in
//! every window (an empty window gives `speed_mt` = 0): l·(1 − ñ/n̄) ≥ 1
//! ([`FreqRespError::MtEmptyWindows`]).
//!
//! **Asynchrony (why the mean speed is detuned).** The small-signal models describe the
//! response averaged over the phase of the encoder relative to the sample instants (the
//! paper's Appendix B and Fig. 5: a delay "uniformly distributed"). In the laboratory the
//! VCO and the DSP clock are independent, so that phase drifts. In a simulation with
//! l = n̄·R·T_s/60 an integer or a simple fraction (3600 r/min, R = 500, T_s = 1 ms is
//! exactly 30 transitions per sample) it does not: the phase is frozen, a PC count with
//! a position modulation below one transition never changes, and ET sees the age of the
//! last transition take a few values only. The mean speed is therefore simulated at
//! n̄·(1 + ε), ε = [`BodeSpec::detune`] (default [`DEFAULT_DETUNE`]): the encoder phase
//! slips against the sample grid by ε·l transitions per sample, and the window N is a
//! whole number of slips of one transition ([`Experiment::samples_per_slip`]), so that
//! every phase is visited equally (n3 at high speed also needs a long window:
//! [`Experiment::min_window`]). Every model is evaluated at the simulated speed.
//! ε = 0 reproduces the synchronous case.
//!
//! **Amplitude.** With the phase averaged, PC, ET and M/T are linear in expectation for
//! any ñ (their outputs are windowed means of the speed); ñ only has to stay well below n̄
//! (no reversal; the second-order terms, such as the choice of the last transition or the
//! decay rule of M/T, small) and well above the residual quantisation noise of a finite
//! window, which falls as 1/ñ. The default ñ/n̄ = 2 % does both; `golden/tests/freqresp.rs`
//! checks that the measurement moves by less than 0.5° from 0.5 % to 5 %. Rairán's n3 is
//! different: its windows start at encoder pulses, so its quantisation is never dithered
//! by asynchrony and its output is a quantiser of step ω_lim. Its gain depends on ñ/ω_lim
//! (a describing function), its phase hardly; hence a default of 20 %
//! ([`DEFAULT_AMPLITUDE_N3`]). docs/frequency-response.md has the figures.

use crate::ideal::mt;
use crate::ideal::plant::{
    edges, initial_levels, Channel, ClockSampler, Disc, Edge, Profile, Segment,
};
use crate::ideal::{self, update_interval};
use crate::params::{bits_for, ParamError, Params, Spec, MAX_COUNTER_BITS, MIN_COUNTER_BITS};
use crate::smallsignal::{
    zoh_at, BodePoint, Complex64, Factor, Model, OperatingPoint, Polar, SmallSignalError,
};
use crate::top::core::{CoreInputs, CoreModel, CoreOutputs};
use std::f64::consts::PI;
use std::fmt;
use std::fmt::Write as _;
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

/// Where PC, ET and M/T are measured: on the float estimators of [`ideal`] and [`mt`], or
/// on the core's hardware outputs `speed_pc`, `speed_et`, `speed_mt` (the bit-true
/// [`CoreModel`], whose every cycle the Verilog is checked against in `tb::freqresp`).
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
fn latency_label(latency_s: f64) -> String {
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
fn mt_mixture(f_hz: f64, te_s: f64, ts_s: f64) -> Complex64 {
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

/// One measurement's timing: the frequency actually used and the sample counts.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// The frequency asked for, Hz.
    pub f_requested_hz: f64,
    /// The frequency simulated, f = P/(N·T_s), Hz.
    pub f_hz: f64,
    /// P: whole modulation periods in the analysis window.
    pub periods: u64,
    /// N: samples in the analysis window.
    pub samples: u64,
    /// Samples discarded before the window (settling).
    pub settle: u64,
    /// The shaft motion: n̄(1 + ε) + ñ·sin(2πft) rev/s from t = 0 to the last sample.
    pub profile: Profile,
}

impl Plan {
    /// Samples simulated in all, settle + N; sample k (1-based) is at t = k·T_s.
    pub fn total_samples(&self) -> u64 {
        self.settle + self.samples
    }
}

/// A measured point with its model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measurement {
    /// The frequency asked for, Hz.
    pub f_requested_hz: f64,
    /// The frequency measured, Hz (see [`Plan::f_hz`]).
    pub f_hz: f64,
    /// P.
    pub periods: u64,
    /// N.
    pub samples: u64,
    /// Output at the sample instants over input at the same instants (module docs, 3).
    pub h_sampled: Complex64,
    /// Held output over continuous input, H_sampled·ZOH(j2πf, T_s) (module docs, 4).
    pub h: Complex64,
    /// The model at f (including ZOH(T_s)).
    pub model: BodePoint,
    /// 20·log10|H|, dB.
    pub gain_db: f64,
    /// ∠H in degrees, on the model's branch: model phase + (∠H − model phase) wrapped
    /// into (−180°, 180°].
    pub phase_deg: f64,
}

impl Measurement {
    /// Measured minus model phase, degrees, in (−180°, 180°].
    pub fn phase_error_deg(&self) -> f64 {
        self.phase_deg - self.model.phase_deg
    }

    /// Measured minus model gain, dB.
    pub fn gain_error_db(&self) -> f64 {
        self.gain_db - self.model.gain_db
    }
}

/// `x` wrapped into (−180, 180].
fn wrap_deg(x: f64) -> f64 {
    let y = x.rem_euclid(360.0);
    if y > 180.0 {
        y - 360.0
    } else {
        y
    }
}

/// A validated experiment: builds plans, runs the estimator, measures.
#[derive(Clone, Debug)]
pub struct Experiment {
    spec: BodeSpec,
    op: OperatingPoint,
    model: FreqModel,
    /// On the core: its parameters and dt in cycles.
    core: Option<(Params, u64)>,
    /// On the core: sample k is the output after cycle k·dt + this (0 for n3; the
    /// `baseline_strobe` for the hardware baselines).
    read_offset: u64,
}

impl Experiment {
    /// Validates `spec` once (each refusal names its parameter).
    pub fn new(spec: BodeSpec) -> Result<Experiment, FreqRespError> {
        if spec.lines == 0 {
            return Err(FreqRespError::Lines(0));
        }
        let n3 = spec.estimator == Estimator::N3;
        if n3 && spec.source == Source::Float {
            return Err(FreqRespError::FloatN3);
        }
        if (n3 && spec.edges != 1) || !matches!(spec.edges, 1 | 2 | 4) {
            return Err(FreqRespError::Edges {
                estimator: spec.estimator,
                edges: spec.edges,
            });
        }
        if !(spec.rpm.is_finite() && spec.rpm > 0.0) {
            return Err(FreqRespError::Rpm(spec.rpm));
        }
        if !(spec.ts_s.is_finite() && spec.ts_s > 0.0) {
            return Err(FreqRespError::TsS(spec.ts_s));
        }
        if !(spec.clock_hz.is_finite() && spec.clock_hz > 0.0) {
            return Err(FreqRespError::ClockHz(spec.clock_hz));
        }
        if !(spec.amplitude > 0.0 && spec.amplitude <= 0.5) {
            return Err(FreqRespError::Amplitude(spec.amplitude));
        }
        if !(spec.detune.is_finite() && spec.detune.abs() <= 0.01) {
            return Err(FreqRespError::Detune(spec.detune));
        }
        if spec.min_periods == 0 {
            return Err(FreqRespError::Window {
                name: "min-periods",
            });
        }
        if spec.min_samples == 0 {
            return Err(FreqRespError::Window {
                name: "min-samples",
            });
        }
        let r = spec
            .lines
            .checked_mul(spec.edges)
            .ok_or(FreqRespError::Lines(spec.lines))?;
        let sim_rpm = spec.rpm * (1.0 + spec.detune);
        let op =
            OperatingPoint::new(r, sim_rpm, spec.ts_s).map_err(FreqRespError::OperatingPoint)?;
        let te_max_s = op.te_s() / (1.0 - spec.amplitude);
        let core = if spec.on_core() {
            Some(core_params(&spec, te_max_s)?)
        } else {
            None
        };
        let mut model = paper_model(spec.estimator, &op);
        let mut read_offset = 0;
        if let (Some((p, dt)), false) = (&core, n3) {
            let l = baseline_latency_cycles(p);
            if *dt < l {
                return Err(FreqRespError::HardwareWindow {
                    dt_cycles: *dt,
                    latency_cycles: l,
                });
            }
            let l_min = op.l() * (1.0 - spec.amplitude);
            if spec.estimator == Estimator::Mt && l_min < 1.0 {
                return Err(FreqRespError::MtEmptyWindows { l_min });
            }
            let d = window_to_strobe_cycles(spec.estimator, p);
            model = model.delayed(d as f64 / spec.clock_hz);
            read_offset = RESET_CYCLES + l;
        }
        Ok(Experiment {
            spec,
            op,
            model,
            core,
            read_offset,
        })
    }

    /// [`Source::Hardware`] PC, ET and M/T: clock cycles from the end of the window the
    /// estimate describes to the `baseline_strobe` that publishes it
    /// ([`window_to_strobe_cycles`]); `None` otherwise.
    pub fn hardware_latency_cycles(&self) -> Option<u64> {
        match (&self.core, self.spec.estimator) {
            (Some((p, _)), e) if e != Estimator::N3 => Some(window_to_strobe_cycles(e, p)),
            _ => None,
        }
    }

    /// On the core: sample k is the core's output after cycle k·dt + this many cycles
    /// (0 for n3, read at the sample instants; [`RESET_CYCLES`] + the baseline block's
    /// latency for the hardware baselines, the cycle of their `baseline_strobe`).
    pub fn read_offset_cycles(&self) -> u64 {
        self.read_offset
    }

    /// The specification.
    pub fn spec(&self) -> &BodeSpec {
        &self.spec
    }

    /// The operating point simulated: R, n̄·(1 + ε) and T_s. The models use it.
    pub fn operating_point(&self) -> &OperatingPoint {
        &self.op
    }

    /// The model compared with the measurement.
    pub fn model(&self) -> &FreqModel {
        &self.model
    }

    /// Other models to draw beside [`Experiment::model`], as the paper's figures do: for PC
    /// eq. (15) (l ≥ 1) and the literature's e^{−sT_s/2} (eq. 27); for ET the literature's
    /// e^{−sT_e} and ZOH(T_e) (eqs. 28, 29); for n3 and M/T the paper's PC and ET models at
    /// the same operating point (eqs. 16, 24). For the hardware baselines the model
    /// without the hardware latency comes first (the float estimator's model).
    pub fn comparison_models(&self) -> Vec<FreqModel> {
        let op = &self.op;
        let product = FreqModel::Product;
        let mut v = Vec::new();
        if self.hardware_latency_cycles().is_some() {
            v.push(paper_model(self.spec.estimator, op));
        }
        v.extend(match self.spec.estimator {
            Estimator::Pc => {
                let mut v: Vec<FreqModel> = Model::pc_eq15(op).into_iter().map(product).collect();
                v.push(product(Model::literature_pc_eq27(op)));
                v
            }
            Estimator::Et => vec![
                product(Model::literature_et1_eq28(op)),
                product(Model::literature_et2_eq29(op)),
            ],
            Estimator::N3 | Estimator::Mt => {
                vec![product(pc_model(op)), product(Model::et_eq24(op))]
            }
        });
        v
    }

    /// The core's parameters (`None` for [`Source::Float`]): lines, dt = T_s in clock
    /// cycles, counters wide enough for dt and a timeout of 1000 dt (and for the hardware
    /// baselines, for the ET period and M/T span at the slowest speed).
    pub fn core_params(&self) -> Option<&Params> {
        self.core.as_ref().map(|(p, _)| p)
    }

    /// Mean speed simulated, rev/s.
    fn mean_rps(&self) -> f64 {
        self.op.speed_rpm() / 60.0
    }

    /// ñ, rev/s.
    fn amplitude_rps(&self) -> f64 {
        self.spec.amplitude * self.mean_rps()
    }

    /// Samples over which the detuning moves the encoder phase by one whole transition
    /// against the sample grid, 1/(|ε|·l) with l the nominal transitions per sample
    /// (pulses per dt for n3); infinite for ε = 0. The window N is a whole number of
    /// these slips (module docs, asynchrony).
    pub fn samples_per_slip(&self) -> f64 {
        let l_nominal = self.op.l() / (1.0 + self.spec.detune);
        1.0 / (self.spec.detune.abs() * l_nominal)
    }

    /// Least window N in samples: [`BodeSpec::min_samples`], [`BodeSpec::min_periods`]
    /// periods of `f_hz`, and for n3 at r ≥ 1 pulses per dt also 100·r. n3's updates are
    /// timed by the pulses: each comes the ceiling's residue of a pulse period (half of
    /// one on average) later against the sample grid than the one before, so the age of
    /// the last update at the sample instants sweeps its range once in about 2r samples;
    /// 100·r samples give 50 sweeps.
    pub fn min_window(&self, f_hz: f64) -> f64 {
        let mut n = f64::from(self.spec.min_samples)
            .max((f64::from(self.spec.min_periods) / (f_hz * self.spec.ts_s)).ceil());
        if self.spec.estimator == Estimator::N3 && self.op.l() >= 1.0 {
            n = n.max((100.0 * self.op.l()).ceil());
        }
        n
    }

    /// The timing of a measurement at `f_hz` (module docs, 3).
    pub fn plan(&self, f_hz: f64) -> Result<Plan, FreqRespError> {
        let ts = self.spec.ts_s;
        let nyquist_hz = 0.5 / ts;
        if !(f_hz.is_finite() && f_hz > 0.0 && f_hz < nyquist_hz) {
            return Err(FreqRespError::Frequency { f_hz, nyquist_hz });
        }
        let too_long = |what: String| FreqRespError::TooLong { f_hz, what };
        // N: at least the least window, and a whole number of slips of the encoder phase
        // against the sample grid (module docs).
        let min_n = self.min_window(f_hz);
        let slip = self.samples_per_slip();
        let mut samples = if slip.is_finite() {
            ((min_n / slip).ceil() * slip).round()
        } else {
            min_n
        };
        let periods = (f_hz * samples * ts).round().max(1.0);
        // f < 1/(2 T_s) keeps N > 2P; rounding can land on N = 2P (f exactly Nyquist).
        if samples <= 2.0 * periods {
            samples = 2.0 * periods + 1.0;
        }
        // Settling: the estimators' memory is at most a few transition intervals or
        // update intervals (≤ 2 T_s); 4 intervals at the slowest speed plus 10 samples.
        let te_slow = self.op.te_s() / (1.0 - self.spec.amplitude);
        let settle = (10.0 + 4.0 * te_slow / ts).ceil();
        let total = settle + samples;
        if total > MAX_SAMPLES as f64 {
            return Err(too_long(format!("{total} samples (at most {MAX_SAMPLES})")));
        }
        let duration = total * ts;
        let transitions = duration * self.mean_rps() * f64::from(self.op.transitions_per_rev());
        if transitions > MAX_TRANSITIONS {
            return Err(too_long(format!(
                "{transitions:.3e} encoder transitions (at most {MAX_TRANSITIONS:e})"
            )));
        }
        if let Some((_, dt)) = &self.core {
            let cycles = total * *dt as f64;
            if cycles > MAX_CORE_CYCLES as f64 {
                return Err(too_long(format!(
                    "{cycles:.3e} clock cycles (at most {MAX_CORE_CYCLES:e})"
                )));
            }
        }
        let (periods, samples, settle) = (periods as u64, samples as u64, settle as u64);
        let f_sim = periods as f64 / (samples as f64 * ts);
        let profile = Profile::new(
            0.0,
            vec![Segment::Sine {
                mean: self.mean_rps(),
                amplitude: self.amplitude_rps(),
                freq_hz: f_sim,
                // One more sample's worth, so that every sample instant is inside.
                duration: (total + 1.0) * ts,
            }],
        )
        .expect("validated speeds and frequency");
        Ok(Plan {
            f_requested_hz: f_hz,
            f_hz: f_sim,
            periods,
            samples,
            settle,
            profile,
        })
    }

    /// Instants (s) of the transitions the estimator counts (module docs, 1).
    pub fn transitions(&self, plan: &Plan) -> Vec<f64> {
        let disc = Disc {
            lines: self.spec.lines,
        };
        let edges_per_line = self.spec.edges;
        edges(&plan.profile, &disc)
            .into_iter()
            .filter(|e| match edges_per_line {
                1 => e.channel == Channel::A && e.rising,
                2 => e.channel == Channel::A,
                _ => e.channel != Channel::Z,
            })
            .map(|e| e.t)
            .collect()
    }

    /// The estimator's output at t_k = k·T_s for k = 1 ..= settle + N, rev/s; on the
    /// core, the output after cycle k·dt + [`Experiment::read_offset_cycles`].
    pub fn outputs(&self, plan: &Plan) -> Vec<f64> {
        if self.core.is_some() {
            let mut y = Vec::with_capacity(plan.total_samples() as usize);
            let mut c = 0u64;
            let mut core = CoreModel::new(self.core_params().expect("on the core"));
            self.for_each_core_input(plan, |inp| {
                let o = core.step(inp);
                if let Some(k) = self.sample_of_cycle(c) {
                    debug_assert_eq!(k, y.len() as u64 + 1);
                    y.push(self.core_rps(&o));
                }
                c += 1;
            });
            return y;
        }
        let ts = self.spec.ts_s;
        let k_total = plan.total_samples() as usize;
        let t_end = k_total as f64 * ts;
        let r = f64::from(self.op.transitions_per_rev());
        let q = 1.0 / self.spec.clock_hz;
        match self.spec.estimator {
            Estimator::Pc => {
                let tr = self.transitions(plan);
                let est = ideal::fixed_time(&tr, ts, t_end).expect("sorted transitions");
                let mut y: Vec<f64> = est.iter().map(|e| e.n / (r * ts)).collect();
                y.resize(k_total, 0.0);
                y
            }
            Estimator::Et => {
                let tr = self.transitions(plan);
                let est = ideal::fixed_space(&tr, 1.0, q).expect("sorted transitions");
                let mut y = Vec::with_capacity(k_total);
                let (mut i, mut last) = (0usize, 0.0);
                for k in 1..=k_total {
                    let tk = k as f64 * ts;
                    while i < est.len() && est[i].t <= tk {
                        last = est[i].n / r;
                        i += 1;
                    }
                    y.push(last);
                }
                y
            }
            Estimator::Mt => {
                let tr = self.transitions(plan);
                let mut y = vec![0.0; k_total];
                for e in mt::mt_estimates(&tr, ts, q, t_end) {
                    let k = (e.t / ts).round() as usize;
                    if (1..=k_total).contains(&k) {
                        y[k - 1] = e.r / (r * ts);
                    }
                }
                y
            }
            Estimator::N3 => unreachable!("n3 runs on the core"),
        }
    }

    /// On the core: the sample k ≥ 1 whose value is read from the output after cycle `c`,
    /// if any (c = k·dt + [`Experiment::read_offset_cycles`]).
    fn sample_of_cycle(&self, c: u64) -> Option<u64> {
        let (_, dt) = self.core.as_ref().expect("on the core");
        let c = c.checked_sub(self.read_offset)?;
        (c > 0 && c.is_multiple_of(*dt)).then_some(c / dt)
    }

    /// The estimate in one core output, rev/s: n3(Nep1, Ndt1)·ω_lim for n3 (the float n3
    /// of the registers, as the accuracy pages use it); `speed_pc`, `speed_et` or
    /// `speed_mt`·2^−F·ω_lim for the baselines, which must be read at their strobe.
    fn core_rps(&self, o: &CoreOutputs) -> f64 {
        let (p, _) = self.core.as_ref().expect("on the core");
        let raw = match self.spec.estimator {
            Estimator::N3 => return ideal::n3(o.nep, o.ndt) * p.omega_lim_rps(),
            Estimator::Pc => o.speed_pc,
            Estimator::Et => o.speed_et,
            Estimator::Mt => o.speed_mt,
        };
        assert!(
            o.baseline_strobe,
            "a hardware baseline read off its baseline_strobe: the timing of \
             window_to_strobe_cycles no longer holds"
        );
        raw as f64 * 0.5f64.powi(p.speed_frac_bits() as i32) * p.omega_lim_rps()
    }

    /// On the core: clock cycles simulated, (settle + N)·dt + [`Experiment::read_offset_cycles`]
    /// + 1 (cycle 0 is t = 0).
    pub fn core_cycles(&self, plan: &Plan) -> u64 {
        let (_, dt) = self.core.as_ref().expect("on the core");
        plan.total_samples() * dt + self.read_offset + 1
    }

    /// `cfg_mode` of the core: x1, x2, x4 for `edges` 1, 2, 4 (n3: x1).
    pub fn cfg_mode(&self) -> u8 {
        match self.spec.edges {
            1 => 0,
            2 => 1,
            _ => 2,
        }
    }

    /// On the core: its inputs, cycle c carrying the plant's levels at t = c/clock_hz,
    /// reset for the first [`RESET_CYCLES`], `cfg_dt` = dt, `cfg_mode` =
    /// [`Experiment::cfg_mode`] (for n3 exactly `tb::stimulus::from_profile`).
    pub fn for_each_core_input(&self, plan: &Plan, mut f: impl FnMut(CoreInputs)) {
        let (_, dt) = self.core.as_ref().expect("on the core");
        let cfg_mode = self.cfg_mode();
        let disc = Disc {
            lines: self.spec.lines,
        };
        let e: Vec<Edge> = edges(&plan.profile, &disc);
        let sampler = ClockSampler::new(
            initial_levels(&plan.profile, &disc),
            &e,
            self.spec.clock_hz,
            self.core_cycles(plan),
        )
        .expect("validated clock");
        for (c, s) in sampler.enumerate() {
            f(CoreInputs {
                reset: (c as u64) < RESET_CYCLES,
                enc_a: s.a,
                enc_b: s.b,
                enc_z: s.z,
                cfg_dt: *dt,
                cfg_mode,
                ..CoreInputs::default()
            });
        }
    }

    /// On the core: [`Experiment::for_each_core_input`] collected (for co-simulation).
    pub fn core_inputs(&self, plan: &Plan) -> Vec<CoreInputs> {
        let mut v = Vec::with_capacity(self.core_cycles(plan) as usize);
        self.for_each_core_input(plan, |i| v.push(i));
        v
    }

    /// On the core: the per-sample outputs (rev/s) from per-cycle core outputs, as
    /// [`Experiment::outputs`] takes them: cycle k·dt + [`Experiment::read_offset_cycles`]
    /// for k = 1 ..= settle + N.
    pub fn outputs_from_core(&self, plan: &Plan, per_cycle: &[CoreOutputs]) -> Vec<f64> {
        let (_, dt) = self.core.as_ref().expect("on the core");
        (1..=plan.total_samples())
            .map(|k| self.core_rps(&per_cycle[(k * dt + self.read_offset) as usize]))
            .collect()
    }

    /// Gain and phase from the outputs `y` (rev/s, k = 1 ..= settle + N) of `plan`.
    pub fn analyse(&self, plan: &Plan, y: &[f64]) -> Measurement {
        assert_eq!(
            y.len() as u64,
            plan.total_samples(),
            "one output per sample"
        );
        let (p, n) = (plan.periods, plan.samples);
        let window = &y[plan.settle as usize..];
        let mean = window.iter().sum::<f64>() / n as f64;
        let amp = self.amplitude_rps();
        let (mut s_out, mut s_in) = (Complex64::new(0.0, 0.0), Complex64::new(0.0, 0.0));
        for (i, &v) in window.iter().enumerate() {
            let k = plan.settle + 1 + i as u64;
            // f·t_k = P·k/N exactly: reduce in integers before going to floating point.
            let theta = 2.0 * PI * ((p * k) % n) as f64 / n as f64;
            let e = Complex64::from_polar(1.0, -theta);
            s_out += e * (v - mean);
            s_in += e * (amp * theta.sin());
        }
        let mut h_sampled = s_out / s_in;
        if self.read_offset > 0 {
            // Sample k is read at t_k + c, c = read_offset cycles: its bin at the instants
            // it was read is e^{−j2πf·c} times the one computed at t_k, and the input's bin
            // does not move (whole periods; module docs).
            let c = self.read_offset as f64 / self.spec.clock_hz;
            h_sampled *= Complex64::from_polar(1.0, -2.0 * PI * plan.f_hz * c);
        }
        let h = h_sampled * zoh_at(plan.f_hz, self.spec.ts_s);
        let model = self.model.at(plan.f_hz);
        let gain_db = 20.0 * h.norm().log10();
        let phase_deg = model.phase_deg + wrap_deg(h.arg().to_degrees() - model.phase_deg);
        Measurement {
            f_requested_hz: plan.f_requested_hz,
            f_hz: plan.f_hz,
            periods: p,
            samples: n,
            h_sampled,
            h,
            model,
            gain_db,
            phase_deg,
        }
    }

    /// Plan, simulate and analyse one frequency.
    pub fn measure(&self, f_hz: f64) -> Result<Measurement, FreqRespError> {
        let plan = self.plan(f_hz)?;
        Ok(self.analyse(&plan, &self.outputs(&plan)))
    }

    /// [`Experiment::measure`] at every frequency, on all cores; the result does not
    /// depend on the number of threads. Every frequency is planned (validated) first.
    pub fn sweep(&self, freqs_hz: &[f64]) -> Result<Vec<Measurement>, FreqRespError> {
        let plans: Vec<Plan> = freqs_hz
            .iter()
            .map(|&f| self.plan(f))
            .collect::<Result<_, _>>()?;
        let threads = std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .min(plans.len().max(1));
        let next = std::sync::atomic::AtomicUsize::new(0);
        let mut out: Vec<Option<Measurement>> = vec![None; plans.len()];
        let results: Vec<Vec<(usize, Measurement)>> = std::thread::scope(|s| {
            let workers: Vec<_> = (0..threads)
                .map(|_| {
                    s.spawn(|| {
                        let mut done = Vec::new();
                        loop {
                            let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                            let Some(plan) = plans.get(i) else { break };
                            done.push((i, self.analyse(plan, &self.outputs(plan))));
                        }
                        done
                    })
                })
                .collect();
            workers
                .into_iter()
                .map(|w| w.join().expect("measurement thread"))
                .collect()
        });
        for (i, m) in results.into_iter().flatten() {
            out[i] = Some(m);
        }
        Ok(out
            .into_iter()
            .map(|m| m.expect("every plan measured"))
            .collect())
    }
}

/// The model of the estimator's window at the sample (or strobe) instants, including the
/// S/H ZOH(T_s): PC eq. (16), ET eq. (24), and the derived n3 and M/T models.
fn paper_model(estimator: Estimator, op: &OperatingPoint) -> FreqModel {
    match estimator {
        Estimator::Pc => FreqModel::Product(pc_model(op)),
        Estimator::Et => FreqModel::Product(Model::et_eq24(op)),
        Estimator::N3 => FreqModel::Product(n3_model(op)),
        Estimator::Mt => mt_model(op),
    }
}

/// Clock edges from a `start` of the baseline speeds block to its `baseline_strobe`:
/// 2·(N + F + 1) + 3 ([`crate::baselines::baseline_speeds::latency_cycles`]).
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
/// ET and M/T: with N = 13, F = 16 (dt = 1000 cycles at 3600 r/min), L = 63 and D = 69
/// and 68 cycles.
pub fn window_to_strobe_cycles(estimator: Estimator, p: &Params) -> u64 {
    let e = u64::from(crate::top::ports::Latency::new(p, 0).edge_to_position);
    let pc_extra = u64::from(estimator == Estimator::Pc);
    baseline_latency_cycles(p) + 1 + e + pc_extra
}

/// The core's parameters for `spec` and dt in cycles. `te_max_s` is the longest time
/// between transitions at the slowest speed (hardware baselines only: the ET period and
/// the M/T span must fit the counters).
fn core_params(spec: &BodeSpec, te_max_s: f64) -> Result<(Params, u64), FreqRespError> {
    let cycles = spec.ts_s * spec.clock_hz;
    let dt = cycles.round();
    if !(dt >= 2.0 && (cycles - dt).abs() <= 1e-9 * dt && dt < 2f64.powi(31)) {
        return Err(FreqRespError::DtCycles {
            ts_s: spec.ts_s,
            clock_hz: spec.clock_hz,
        });
    }
    let dt = dt as u64;
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
    })
    .map_err(FreqRespError::Core)?;
    Ok((p, dt))
}

/// `points` frequencies from `fmin_hz` to `fmax_hz`, logarithmically spaced, both ends
/// exact (one point when fmin = fmax).
pub fn log_spaced(fmin_hz: f64, fmax_hz: f64, points: u32) -> Result<Vec<f64>, FreqRespError> {
    let ok = fmin_hz.is_finite()
        && fmax_hz.is_finite()
        && fmin_hz > 0.0
        && fmax_hz >= fmin_hz
        && (1..=10_000).contains(&points)
        && ((fmax_hz > fmin_hz) == (points > 1));
    if !ok {
        return Err(FreqRespError::Sweep {
            fmin_hz,
            fmax_hz,
            points,
        });
    }
    if points == 1 {
        return Ok(vec![fmin_hz]);
    }
    let ratio = (fmax_hz / fmin_hz).ln();
    let last = f64::from(points - 1);
    let mut f: Vec<f64> = (0..points - 1)
        .map(|i| fmin_hz * (ratio * f64::from(i) / last).exp())
        .collect();
    f.push(fmax_hz);
    Ok(f)
}

/// First line of [`to_csv`].
pub const CSV_HEADER: &str = "f_hz,model_gain_db,model_phase_deg,measured_gain_db,\
measured_phase_deg,gain_error_db,phase_error_deg";

/// Formatted with a lone minus sign on a zero removed (deterministic text).
fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_owned(),
        _ => s,
    }
}

/// CSV of a sweep: [`CSV_HEADER`], then per point the measured frequency (Hz, 9
/// significant digits), the model's gain (dB) and phase (°), the measured gain and phase,
/// and their differences, 4 decimals; `\n` line ends.
pub fn to_csv(points: &[Measurement]) -> String {
    let mut out = String::from(CSV_HEADER);
    out.push('\n');
    for m in points {
        let _ = writeln!(
            out,
            "{:.8e},{},{},{},{},{},{}",
            m.f_hz,
            fixed(m.model.gain_db, 4),
            fixed(m.model.phase_deg, 4),
            fixed(m.gain_db, 4),
            fixed(m.phase_deg, 4),
            fixed(m.gain_error_db(), 4),
            fixed(m.phase_error_deg(), 4),
        );
    }
    out
}
