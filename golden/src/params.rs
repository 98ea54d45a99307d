// SPDX-License-Identifier: MIT OR Apache-2.0
//! The one validated parameter type of encspeed.
//!
//! A [`Spec`] is what a user writes (CLI options, a TOML file, a test); [`Params::new`]
//! validates it once and returns [`Params`], which the golden model, the HDL constructors
//! and the generated manifest all take. Nothing downstream re-checks or re-derives these
//! values, so a bad parameter is refused here with a message naming it, or not at all.

use serde::{Deserialize, Serialize};
use std::fmt;

/// Narrowest counter width the generator emits (bits).
pub const MIN_COUNTER_BITS: u32 = 8;
/// Widest counter width the generator emits (bits).
pub const MAX_COUNTER_BITS: u32 = 32;
/// Shortest dt the estimator accepts, in clock cycles (see [`ParamError::DtTooShort`]).
pub const MIN_DT_CYCLES: u64 = 2;
/// Fractional bits F of every speed output (`speed_frac_bits` in the manifest): a speed is
/// `raw · 2^−F` in units of ω_lim. Fixed so that the hardware's widths depend on one
/// generation parameter only (rust-hdl widths are const generics, one build per width).
pub const SPEED_FRAC_BITS: u32 = 16;
/// Width of the `cfg_filter` port (bits): glitch filters up to 65,535 clock cycles.
pub const FILTER_BITS: u32 = 16;
/// Width of the glitch, illegal-transition and revolution-error counters (bits); they
/// saturate at 65,535.
pub const ERROR_COUNT_BITS: u32 = 16;
/// Width of `position` and `z_latch` (bits); positions are below 4·lines.
pub const POSITION_BITS: u32 = 32;
/// Most lines per revolution: the x4 count of a revolution, 4·lines, must fit 32 bits.
pub const MAX_LINES: u32 = 1 << 30;

/// Most encoder channels behind one `encspeed_wb` window (`channels`): the channel is the
/// three address bits above a channel's 256-byte register window.
pub const MAX_CHANNELS: u32 = 8;

/// Parameters as a user states them. Units are in the field names' docs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Spec {
    /// Frequency of `clock` in Hz; one Table 1 step (ts) per clock cycle.
    pub clock_hz: f64,
    /// Lines (A pulses) per revolution of the encoder disc, K.
    pub lines: u32,
    /// Nominal dt in clock cycles: the value the user intends to drive on `cfg_dt`. It sets
    /// ω_lim in the manifest and the zero-speed timeout in dt intervals.
    pub dt_cycles: u64,
    /// Width of `cfg_dt`, of the ts counter and of the Cep/Cdt/Nep1/Ndt1 registers (bits).
    pub counter_bits: u32,
    /// Zero-speed timeout in seconds at the nominal dt: `stalled` rises when no encoder
    /// pulse has come for this long (rounded up to whole dt intervals). It is the value
    /// used while the `cfg_timeout` port is 0.
    pub timeout_s: f64,
    /// The speed outputs the core computes ([`SpeedOutput`]); each one left out reads 0
    /// and its hardware is not built. `n3` is always required.
    pub estimators: Vec<SpeedOutput>,
    /// Encoder channels of `encspeed_wb`, 1..=[`MAX_CHANNELS`]: each is a core with its own
    /// register window of [`crate::bus::regmap::SPAN_BYTES`] bytes, channel c at byte
    /// offset c · 0x100 (`crate::top::wb_channels`). The other tops have one channel.
    pub channels: u32,
    /// Whether the eccentricity tops (`encspeed_ecc`, `encspeed_ecc_wb`) build the online
    /// identification (the line tap and the gatherer of one revolution's sums, the
    /// `ident_*` ports and `IDENT_*` registers). Left out (`false`, `--no-identification`)
    /// those ports and registers read 0, `ident_arm` and `ECC_CTRL.IDENT_ARM` do nothing,
    /// and the correction runs on coefficients identified elsewhere (`encspeed identify`).
    /// The core and `encspeed_wb` have no identification and ignore it.
    pub identification: bool,
}

/// A speed output of the core that a build may leave out (`estimators`): Rairán's n1, n2
/// and n3 and the three baselines. n1, n2 and n3 come out of one calculator, so leaving
/// out n1 or n2 only zeroes its port; leaving out `pc`, `et` or `mt` removes its counter,
/// and leaving out all three removes the baselines' converter as well.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SpeedOutput {
    /// n1 = Nep/Ndt (`speed_n1`).
    N1,
    /// n2, Rairán's eq. (6) (`speed_n2`).
    N2,
    /// n3, Rairán's eq. (11) (`speed_n3`): the synchronised estimator's result.
    N3,
    /// Pulse counting (`speed_pc`).
    Pc,
    /// Elapsed time (`speed_et`).
    Et,
    /// M/T (`speed_mt` and the `mt_*` outputs).
    Mt,
}

impl SpeedOutput {
    /// Every speed output, in port order.
    pub const ALL: [SpeedOutput; 6] = [
        SpeedOutput::N1,
        SpeedOutput::N2,
        SpeedOutput::N3,
        SpeedOutput::Pc,
        SpeedOutput::Et,
        SpeedOutput::Mt,
    ];

    /// The name in `estimators` (`n1`, ..., `mt`).
    pub fn name(self) -> &'static str {
        match self {
            SpeedOutput::N1 => "n1",
            SpeedOutput::N2 => "n2",
            SpeedOutput::N3 => "n3",
            SpeedOutput::Pc => "pc",
            SpeedOutput::Et => "et",
            SpeedOutput::Mt => "mt",
        }
    }
}

/// Which speed outputs a build computes, as a small `Copy` set (one flag per
/// [`SpeedOutput`]): what the core model and the HDL constructor ask on every use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EstimatorSet([bool; 6]);

impl EstimatorSet {
    /// The set of the outputs listed.
    pub fn of(list: &[SpeedOutput]) -> EstimatorSet {
        let mut flags = [false; 6];
        for &e in list {
            flags[e as usize] = true;
        }
        EstimatorSet(flags)
    }

    /// Whether speed output `e` is built; one left out reads 0.
    pub fn has(self, e: SpeedOutput) -> bool {
        self.0[e as usize]
    }

    /// Whether any baseline (PC, ET, M/T) is built: if none is, neither is their converter.
    pub fn has_baselines(self) -> bool {
        self.has(SpeedOutput::Pc) || self.has(SpeedOutput::Et) || self.has(SpeedOutput::Mt)
    }
}

impl Default for Spec {
    /// 100 MHz clock, 1024-line disc, dt = 1 ms (ω_lim = 0.9766 rev/s = 58.6 r/min),
    /// 24-bit counters (dt up to 167 ms), 1 s zero-speed timeout.
    fn default() -> Self {
        Spec {
            clock_hz: 100e6,
            lines: 1024,
            dt_cycles: 100_000,
            counter_bits: 24,
            timeout_s: 1.0,
            estimators: SpeedOutput::ALL.to_vec(),
            channels: 1,
            identification: true,
        }
    }
}

/// Why a [`Spec`] was refused. Each message names the parameter and the legal range.
#[derive(Clone, Debug, PartialEq)]
pub enum ParamError {
    /// `clock_hz` is NaN, infinite, zero or negative.
    ClockHz(f64),
    /// `lines` is zero.
    ZeroLines,
    /// `lines` is above [`MAX_LINES`].
    TooManyLines(u32),

    /// `dt_cycles` is below [`MIN_DT_CYCLES`].
    DtTooShort(u64),
    /// `counter_bits` is outside [`MIN_COUNTER_BITS`]..=[`MAX_COUNTER_BITS`].
    CounterBits(u32),
    /// `dt_cycles` does not fit the counters.
    DtTooWide { dt_cycles: u64, counter_bits: u32 },
    /// `timeout_s` is NaN, infinite, zero or negative.
    Timeout(f64),
    /// `timeout_s` is shorter than one dt interval, so it could never be measured.
    TimeoutShorterThanDt { timeout_s: f64, dt_s: f64 },
    /// The timeout, in dt intervals, does not fit the Cdt counter.
    TimeoutTooWide { timeout_dt: f64, counter_bits: u32 },
    /// `lines` cannot have the eccentricity corrector ([`Params::check_ecc`]).
    EccLines(u32),
    /// A sample time that is not a whole number of clock cycles ≥ [`MIN_DT_CYCLES`] below
    /// 2^31 ([`dt_cycles_for`]).
    DtNotWhole { ts_s: f64, clock_hz: f64 },
    /// `estimators` does not name n3, or names an output twice.
    Estimators(String),
    /// The eccentricity tops need the M/T estimator ([`Params::check_ecc`]).
    EccWithoutMt,
    /// `channels` is outside 1..=[`MAX_CHANNELS`].
    Channels(u32),
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParamError::ClockHz(v) => {
                write!(f, "clock_hz = {v}: must be a finite frequency > 0 Hz")
            }
            ParamError::ZeroLines => write!(f, "lines = 0: the disc needs at least one line"),
            ParamError::TooManyLines(v) => write!(
                f,
                "lines = {v}: at most {MAX_LINES} (the x4 count of a revolution must fit 32 bits)"
            ),

            ParamError::DtTooShort(v) => write!(
                f,
                "dt_cycles = {v}: dt must be at least {MIN_DT_CYCLES} clock cycles \
                 (one ts step cannot hold both a pulse and a dt tick)"
            ),
            ParamError::CounterBits(v) => write!(
                f,
                "counter_bits = {v}: must be {MIN_COUNTER_BITS}..={MAX_COUNTER_BITS}"
            ),
            ParamError::DtTooWide {
                dt_cycles,
                counter_bits,
            } => write!(
                f,
                "dt_cycles = {dt_cycles} does not fit counter_bits = {counter_bits} \
                 (max {}); raise counter_bits to at least {}",
                max_value(*counter_bits),
                bits_for(*dt_cycles)
            ),
            ParamError::Timeout(v) => {
                write!(f, "timeout_s = {v}: must be a finite time > 0 s")
            }
            ParamError::TimeoutShorterThanDt { timeout_s, dt_s } => write!(
                f,
                "timeout_s = {timeout_s} is shorter than one dt interval ({dt_s} s)"
            ),
            ParamError::TimeoutTooWide {
                timeout_dt,
                counter_bits,
            } => write!(
                f,
                "timeout_s needs {timeout_dt} dt intervals, more than counter_bits = \
                 {counter_bits} can count (max {}); raise counter_bits to at least {} \
                 or shorten timeout_s",
                max_value(*counter_bits),
                bits_for(*timeout_dt as u64)
            ),
            ParamError::EccLines(v) => write!(
                f,
                "lines = {v}: the eccentricity corrector needs a multiple of 4 lines in \
                 {ECC_MIN_LINES}..={ECC_MAX_LINES} (a sine table of one entry per line, \
                 16-bit address)"
            ),
            ParamError::DtNotWhole { ts_s, clock_hz } => write!(
                f,
                "T_s = {ts_s} s at clock_hz = {clock_hz}: dt = T_s * clock_hz must be a whole \
                 number of cycles, {MIN_DT_CYCLES}..2^31"
            ),
            ParamError::Estimators(why) => write!(
                f,
                "estimators: {why} (choose from n1, n2, n3, pc, et, mt; n3 is required)"
            ),
            ParamError::EccWithoutMt => write!(
                f,
                "estimators: the eccentricity corrector corrects the M/T speed, so mt \
                 must be one of the estimators"
            ),
            ParamError::Channels(v) => write!(
                f,
                "channels = {v}: must be 1..={MAX_CHANNELS} (encoder channels behind one \
                 Wishbone window, {MAX_CHANNELS} windows of 256 bytes at most)"
            ),
        }
    }
}

impl std::error::Error for ParamError {}

/// Largest value of an unsigned register `bits` wide.
pub fn max_value(bits: u32) -> u64 {
    (1u64 << bits) - 1
}

/// dt in clock cycles for a sample time `ts_s` at `clock_hz`: refused unless it is a whole
/// number of cycles (within 1e-9 relative) from [`MIN_DT_CYCLES`] up to 2^31.
pub fn dt_cycles_for(clock_hz: f64, ts_s: f64) -> Result<u64, ParamError> {
    let cycles = ts_s * clock_hz;
    let dt = cycles.round();
    if dt >= MIN_DT_CYCLES as f64 && (cycles - dt).abs() <= 1e-9 * dt && dt < 2f64.powi(31) {
        Ok(dt as u64)
    } else {
        Err(ParamError::DtNotWhole { ts_s, clock_hz })
    }
}

/// Width of every speed output for `counter_bits`-bit counters: N + F + 1 (two's
/// complement; F = [`SPEED_FRAC_BITS`]).
pub fn speed_bits_for(counter_bits: u32) -> u32 {
    counter_bits + SPEED_FRAC_BITS + 1
}

/// Fewest bits that hold `v`.
pub fn bits_for(v: u64) -> u32 {
    (u64::BITS - v.leading_zeros()).max(1)
}

/// Fewest lines the eccentricity tops take (one quarter-wave of the sine table per line
/// quadrant).
pub const ECC_MIN_LINES: u32 = 4;
/// Most lines the eccentricity tops take: the sine table has one entry per line and a
/// 16-bit address.
pub const ECC_MAX_LINES: u32 = 1 << 16;

/// Validated parameters. Construct with [`Params::new`]; fields are private so that no
/// unvalidated value reaches the model or the hardware. Serialised as its [`Spec`], and
/// deserialised through [`Params::new`], so a file cannot carry an invalid value either.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "Spec", into = "Spec")]
pub struct Params {
    spec: Spec,
    timeout_dt: u64,
}

impl TryFrom<Spec> for Params {
    type Error = ParamError;
    fn try_from(spec: Spec) -> Result<Params, ParamError> {
        Params::new(spec)
    }
}

impl From<Params> for Spec {
    fn from(p: Params) -> Spec {
        p.spec
    }
}

impl Params {
    /// Validate a [`Spec`].
    pub fn new(mut spec: Spec) -> Result<Params, ParamError> {
        if !(spec.clock_hz.is_finite() && spec.clock_hz > 0.0) {
            return Err(ParamError::ClockHz(spec.clock_hz));
        }
        if spec.lines == 0 {
            return Err(ParamError::ZeroLines);
        }
        if spec.lines > MAX_LINES {
            return Err(ParamError::TooManyLines(spec.lines));
        }

        if spec.dt_cycles < MIN_DT_CYCLES {
            return Err(ParamError::DtTooShort(spec.dt_cycles));
        }
        if !(MIN_COUNTER_BITS..=MAX_COUNTER_BITS).contains(&spec.counter_bits) {
            return Err(ParamError::CounterBits(spec.counter_bits));
        }
        if spec.dt_cycles > max_value(spec.counter_bits) {
            return Err(ParamError::DtTooWide {
                dt_cycles: spec.dt_cycles,
                counter_bits: spec.counter_bits,
            });
        }
        if !(spec.timeout_s.is_finite() && spec.timeout_s > 0.0) {
            return Err(ParamError::Timeout(spec.timeout_s));
        }
        let dt_s = spec.dt_cycles as f64 / spec.clock_hz;
        // Rounded up to whole dt intervals; a ratio within 1e-9 of a whole number is that
        // number (so 1 s at dt = 1 ms is 1000 intervals, not 1001 from rounding noise).
        let ratio = spec.timeout_s * spec.clock_hz / spec.dt_cycles as f64;
        let timeout_dt = (ratio * (1.0 - 1e-9)).ceil();
        if timeout_dt < 1.0 || spec.timeout_s < dt_s {
            return Err(ParamError::TimeoutShorterThanDt {
                timeout_s: spec.timeout_s,
                dt_s,
            });
        }
        // Cdt saturates at max_value; the timeout must be reached strictly before that so
        // that `stalled` is a timeout and not an overflow.
        if timeout_dt >= max_value(spec.counter_bits) as f64 {
            return Err(ParamError::TimeoutTooWide {
                timeout_dt,
                counter_bits: spec.counter_bits,
            });
        }
        // Estimators: n3 required, none twice; kept in port order.
        let mut estimators = spec.estimators.clone();
        estimators.sort();
        if let Some(w) = estimators.windows(2).find(|w| w[0] == w[1]) {
            return Err(ParamError::Estimators(format!(
                "{} named twice",
                w[0].name()
            )));
        }
        if !estimators.contains(&SpeedOutput::N3) {
            return Err(ParamError::Estimators(
                "n3 is missing: it is the synchronised estimator's result, which valid, \
                 speed_strobe and the eccentricity corrector are defined on"
                    .to_string(),
            ));
        }
        spec.estimators = estimators;
        if !(1..=MAX_CHANNELS).contains(&spec.channels) {
            return Err(ParamError::Channels(spec.channels));
        }
        Ok(Params {
            spec,
            timeout_dt: timeout_dt as u64,
        })
    }

    /// Whether the eccentricity tops (`encspeed_ecc`, `encspeed_ecc_wb`) can be built for
    /// these parameters: `lines` a multiple of 4 in [`ECC_MIN_LINES`]..=[`ECC_MAX_LINES`].
    /// The core and its Wishbone top take any `lines`.
    pub fn check_ecc(&self) -> Result<(), ParamError> {
        let k = self.spec.lines;
        if !((ECC_MIN_LINES..=ECC_MAX_LINES).contains(&k) && k.is_multiple_of(4)) {
            Err(ParamError::EccLines(k))
        } else if !self.has(SpeedOutput::Mt) {
            Err(ParamError::EccWithoutMt)
        } else {
            Ok(())
        }
    }

    /// The speed outputs the core computes (`estimators`), as a set.
    pub fn estimators(&self) -> EstimatorSet {
        EstimatorSet::of(&self.spec.estimators)
    }

    /// Whether the core computes speed output `e` (`estimators`); one left out reads 0.
    pub fn has(&self, e: SpeedOutput) -> bool {
        self.estimators().has(e)
    }

    /// Whether any baseline (PC, ET, M/T) is built: if none is, neither is their converter.
    pub fn has_baselines(&self) -> bool {
        self.estimators().has_baselines()
    }

    /// The estimators built, as `--estimators` takes them (`n1,n2,n3,pc,et,mt`).
    pub fn estimator_list(&self) -> String {
        let names: Vec<&str> = self.spec.estimators.iter().map(|e| e.name()).collect();
        names.join(",")
    }

    /// The parameters as the generated files' headers state them, one line (`channels`
    /// only when there are several, as [`crate::provenance::generate_command`] names it).
    pub fn summary(&self) -> String {
        let s = &self.spec;
        let mut line = format!(
            "clock_hz = {}, lines = {}, dt_cycles = {}, counter_bits = {}, timeout_s = {}, \
             estimators = {}",
            s.clock_hz,
            s.lines,
            s.dt_cycles,
            s.counter_bits,
            s.timeout_s,
            self.estimator_list()
        );
        if s.channels > 1 {
            line.push_str(&format!(", channels = {}", s.channels));
        }
        if !s.identification {
            line.push_str(", identification = false");
        }
        line
    }

    /// Whether the eccentricity tops build the online identification (`identification`;
    /// left out, its ports and registers read 0).
    pub fn identification(&self) -> bool {
        self.spec.identification
    }

    /// Encoder channels of `encspeed_wb` (`channels`, 1..=[`MAX_CHANNELS`]).
    pub fn channels(&self) -> u32 {
        self.spec.channels
    }

    /// The specification these parameters were validated from.
    pub fn spec(&self) -> &Spec {
        &self.spec
    }
    /// Clock frequency, Hz.
    pub fn clock_hz(&self) -> f64 {
        self.spec.clock_hz
    }
    /// Lines per revolution, K.
    pub fn lines(&self) -> u32 {
        self.spec.lines
    }
    /// Nominal dt, clock cycles.
    pub fn dt_cycles(&self) -> u64 {
        self.spec.dt_cycles
    }
    /// Counter width, bits.
    pub fn counter_bits(&self) -> u32 {
        self.spec.counter_bits
    }
    /// Largest value any counter holds: counters saturate here rather than wrap.
    pub fn counter_max(&self) -> u64 {
        max_value(self.spec.counter_bits)
    }
    /// Zero-speed timeout in dt intervals: `stalled` = (Cdt >= timeout_dt).
    pub fn timeout_dt(&self) -> u64 {
        self.timeout_dt
    }
    /// Clock period ts, seconds.
    pub fn ts_s(&self) -> f64 {
        1.0 / self.spec.clock_hz
    }
    /// Nominal dt, seconds.
    pub fn dt_s(&self) -> f64 {
        self.spec.dt_cycles as f64 / self.spec.clock_hz
    }
    /// Speed limit ω_lim = 1/(K·dt) in rev/s at the nominal dt (Rairán): the speed at
    /// which one pulse comes every dt. Estimates n1, n2, n3 are in units of ω_lim.
    pub fn omega_lim_rps(&self) -> f64 {
        omega_lim_rps(self.spec.clock_hz, self.spec.lines, self.spec.dt_cycles)
    }
    /// Fractional bits F of the speed outputs ([`SPEED_FRAC_BITS`]).
    pub fn speed_frac_bits(&self) -> u32 {
        SPEED_FRAC_BITS
    }
    /// Width of every speed output: N + F + 1 (two's complement, [`speed_bits_for`]).
    pub fn speed_bits(&self) -> u32 {
        speed_bits_for(self.spec.counter_bits)
    }
    /// Width of `cfg_filter` ([`FILTER_BITS`]).
    pub fn filter_bits(&self) -> u32 {
        FILTER_BITS
    }
    /// Width of the fault counters ([`ERROR_COUNT_BITS`]).
    pub fn error_count_bits(&self) -> u32 {
        ERROR_COUNT_BITS
    }
    /// Width of `position` and `z_latch` ([`POSITION_BITS`]).
    pub fn position_bits(&self) -> u32 {
        POSITION_BITS
    }
    /// Counts per revolution in a decoding mode of `mode_shift` = log2(steps per line):
    /// lines · 2^mode_shift.
    pub fn counts_per_rev(&self, mode_shift: u32) -> u64 {
        u64::from(self.spec.lines) << mode_shift
    }
}

/// ω_lim = f_clk / (K · dt_cycles), rev/s, for any dt (e.g. a runtime `cfg_dt`).
pub fn omega_lim_rps(clock_hz: f64, lines: u32, dt_cycles: u64) -> f64 {
    clock_hz / (lines as f64 * dt_cycles as f64)
}

#[cfg(test)]
mod tests {

    #[test]
    fn params_serialise_as_their_spec_and_deserialise_only_when_valid() {
        let p = Params::new(Spec::default()).unwrap();
        let text = toml::to_string(&p).unwrap();
        assert_eq!(toml::from_str::<Spec>(&text).unwrap(), Spec::default());
        assert_eq!(toml::from_str::<Params>(&text).unwrap(), p);
        let bad = text.replace("lines = 1024", "lines = 0");
        assert_ne!(bad, text);
        let e = toml::from_str::<Params>(&bad).unwrap_err().to_string();
        assert!(e.contains(&ParamError::ZeroLines.to_string()), "{e}");
    }

    #[test]
    fn a_cycles_inputs_and_outputs_round_trip_through_serde() {
        use crate::top::core::{CoreInputs, CoreOutputs};
        let i = CoreInputs {
            enc_a: true,
            cfg_dt: 1234,
            cfg_mode: 2,
            ..Default::default()
        };
        assert_eq!(
            toml::from_str::<CoreInputs>(&toml::to_string(&i).unwrap()).unwrap(),
            i
        );
        let o = CoreOutputs {
            speed_n3: -65536,
            valid: true,
            ..Default::default()
        };
        assert_eq!(
            toml::from_str::<CoreOutputs>(&toml::to_string(&o).unwrap()).unwrap(),
            o
        );
    }
    use super::*;

    fn with(f: impl FnOnce(&mut Spec)) -> Result<Params, ParamError> {
        let mut s = Spec::default();
        f(&mut s);
        Params::new(s)
    }

    #[test]
    fn default_is_valid_and_derived_values_are_hand_checked() {
        let p = Params::new(Spec::default()).unwrap();
        // 100e6 / (1024 * 100_000) = 0.9765625 rev/s
        assert_eq!(p.omega_lim_rps(), 0.9765625);
        // 1 s / 1 ms = 1000 intervals
        assert_eq!(p.timeout_dt(), 1000);
        assert_eq!(p.counter_max(), 16_777_215);
        // 24 + 16 + 1
        assert_eq!(p.speed_bits(), 41);
        assert_eq!(p.counts_per_rev(2), 4096);
    }

    #[test]
    fn every_bad_parameter_is_refused_with_its_name() {
        let cases: Vec<(Result<Params, ParamError>, &str)> = vec![
            (with(|s| s.clock_hz = f64::NAN), "clock_hz"),
            (with(|s| s.clock_hz = -1.0), "clock_hz"),
            (with(|s| s.clock_hz = 0.0), "clock_hz"),
            (with(|s| s.clock_hz = f64::INFINITY), "clock_hz"),
            (with(|s| s.lines = 0), "lines"),
            (with(|s| s.lines = MAX_LINES + 1), "lines"),
            (with(|s| s.dt_cycles = 1), "dt_cycles"),
            (with(|s| s.dt_cycles = 0), "dt_cycles"),
            (with(|s| s.counter_bits = 7), "counter_bits"),
            (with(|s| s.counter_bits = 33), "counter_bits"),
            (with(|s| s.counter_bits = 16), "dt_cycles"),
            (with(|s| s.timeout_s = f64::NAN), "timeout_s"),
            (with(|s| s.timeout_s = -1.0), "timeout_s"),
            (with(|s| s.timeout_s = 1e-4), "timeout_s"),
            (with(|s| s.timeout_s = 1e6), "timeout_s"),
            (with(|s| s.estimators = vec![SpeedOutput::Mt]), "estimators"),
            (with(|s| s.estimators = vec![]), "estimators"),
            (
                with(|s| s.estimators = vec![SpeedOutput::N3, SpeedOutput::Et, SpeedOutput::N3]),
                "estimators",
            ),
        ];
        for (r, name) in cases {
            let e = r.expect_err(name);
            assert!(e.to_string().contains(name), "{e} should name {name}");
        }
    }

    #[test]
    fn width_limits_are_exact() {
        // 255 is the largest 8-bit value: accepted; 256 is not.
        let ok = with(|s| {
            s.counter_bits = 8;
            s.dt_cycles = 255;
            s.timeout_s = 254.0 * 255.0 / 100e6;
        });
        assert!(ok.is_ok(), "{ok:?}");
        let too_wide = with(|s| {
            s.counter_bits = 8;
            s.dt_cycles = 256;
        });
        assert!(matches!(too_wide, Err(ParamError::DtTooWide { .. })));
        // 255 dt intervals would reach the saturation value itself: refused.
        let sat = with(|s| {
            s.counter_bits = 8;
            s.dt_cycles = 255;
            s.timeout_s = 255.0 * 255.0 / 100e6;
        });
        assert!(matches!(sat, Err(ParamError::TimeoutTooWide { .. })));
    }

    #[test]
    fn bits_for_is_exact() {
        assert_eq!(bits_for(255), 8);
        assert_eq!(bits_for(256), 9);
        assert_eq!(bits_for(0), 1);
    }

    #[test]
    fn estimators_are_kept_in_port_order_and_read_back() {
        use SpeedOutput::*;
        let p = with(|s| s.estimators = vec![Mt, N3, Et]).unwrap();
        assert_eq!(p.spec().estimators, [N3, Et, Mt]);
        assert!(p.has(N3) && p.has(Et) && p.has(Mt));
        assert!(!p.has(N1) && !p.has(N2) && !p.has(Pc));
        assert!(p.has_baselines());
        assert!(!with(|s| s.estimators = vec![N1, N3])
            .unwrap()
            .has_baselines());
        // As a file names them; an unknown name is refused by the file's type.
        let text = toml::to_string(p.spec()).unwrap();
        assert!(
            text.contains(r#"estimators = ["n3", "et", "mt"]"#),
            "{text}"
        );
        let bad = text.replace(r#""et""#, r#""rpm""#);
        assert!(toml::from_str::<Spec>(&bad).is_err());
    }

    #[test]
    fn the_eccentricity_tops_need_mt() {
        use SpeedOutput::*;
        assert_eq!(
            with(|s| s.estimators = vec![N3, Pc]).unwrap().check_ecc(),
            Err(ParamError::EccWithoutMt)
        );
        assert_eq!(
            with(|s| s.estimators = vec![N3, Mt]).unwrap().check_ecc(),
            Ok(())
        );
        assert!(ParamError::EccWithoutMt.to_string().contains("estimators"));
    }
}
