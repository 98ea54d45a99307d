// SPDX-License-Identifier: MIT OR Apache-2.0
//! The experiment: its plan at one frequency ([`Plan`]), the run on the plant and the
//! estimators, and the analysis into a [`Measurement`] ([`Experiment`]).

use super::model::*;
use super::spec::*;
use crate::ideal::mt;
use crate::ideal::plant::{
    edges, initial_levels, Channel, ClockSampler, Disc, Edge, Profile, Segment,
};
use crate::ideal::{self};
use crate::params::Params;
use crate::smallsignal::{zoh_at, BodePoint, Complex64, Model, OperatingPoint};
use crate::top::core::{CoreInputs, CoreModel, CoreOutputs};
use std::f64::consts::PI;

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
pub(crate) fn wrap_deg(x: f64) -> f64 {
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
            // The core's time base starts at the last reset edge, which is the edge after
            // the last one that samples `reset` (reset_to_effect).
            read_offset =
                RESET_CYCLES + u64::from(crate::top::ports::Latency::new(p, 0).reset_to_effect) + l;
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
    /// (0 for n3, read at the sample instants; [`RESET_CYCLES`] + the reset's own edge + the
    /// baseline block's latency for the hardware baselines, the cycle of their
    /// `baseline_strobe`).
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
