// SPDX-License-Identifier: MIT OR Apache-2.0
//! A verdict on an implementation with another fixed-point format or latency: every speed
//! sample is compared with the true speed that the A/B edges imply, against the
//! estimator's proven error bound (docs/reference-model.md#bound-mode).
//!
//! - **Steps.** The A and B levels the VCD's rising clock edges sample are decoded as the
//!   core decodes them (x1, x2 or x4 by `cfg_mode`, [`QuadratureDecoder`]): a step at edge
//!   q_i.
//! - **Stretches of constant speed.** A pulse at instant t is seen at the first clock edge
//!   after it, so at a constant step period P (cycles) the seen steps satisfy
//!   |q_i − q_0 − i·P| < 1 for every i. A stretch is a run of steps of one direction for
//!   which some P satisfies all of these; each step narrows the open interval
//!   (P_lo, P_hi) of such P, and a step that would empty it (or a reversal, a reset, a change
//!   of `cfg_dt` or `cfg_mode`) ends the stretch. The true speed of a stretch lies in
//!   [dt/P_hi, dt/P_lo] steps per dt, divided by 2^s (s = 0, 1, 2 for x1, x2, x4) in lines
//!   per dt, the unit of every speed port.
//! - **Samples judged.** A sample is an output value at its strobe (`speed_strobe` for n1
//!   and n3, `baseline_strobe` for PC, ET and M/T; without the strobe in the VCD, every
//!   change of the value). It is judged when its stretch began at least
//!   W = 2·max(dt, ⌈P_hi⌉) + dt + `latency` cycles before it (the longest window any of the
//!   estimators measures, with a dt to spare for the update and the latency) and has a step
//!   after it, so everything the estimate can have measured lies in one constant-speed
//!   stretch. An M/T value of 0 is a window without a step, no estimate, and is counted
//!   apart (as the M/T definition says).
//! - **Error and bound.** The error is the distance from the sample (value/2^F lines per
//!   dt, signed) to the stretch's speed range (negative for a backward stretch), relative
//!   to the middle of that range. The bound is [`estimator_bound`] (the largest at the
//!   range's ends and middle) plus one LSB of the implementation's format relative to the
//!   speed, which covers rounding to nearest, truncation and the core's two roundings.
//!   A sample is within its bound when error ≤ bound.
//!
//! Memory does not grow with the VCD: a sample waits at most [`LOOKAHEAD_STEPS`] steps of
//! its stretch (or the stretch's end) for its verdict.

use super::vcd_cycles::{VcdCycles, VcdEdge, VcdError};
use super::RefPort;
use crate::estimator::bounds::{estimator_bound, Estimator};
use crate::frontend::quadrature_decoder::{DecoderInputs, QuadratureDecoder};
use crate::params::{Params, MIN_DT_CYCLES};
use crate::top::core::mode_shift;
use std::collections::VecDeque;
use std::io::Read;

/// The inputs `--mode bound` reads; `cfg_dt` and `cfg_mode` may be absent (run as 0: the
/// generation default dt, x1).
pub const BOUND_INPUTS: [&str; 5] = ["reset", "enc_a", "enc_b", "cfg_dt", "cfg_mode"];

/// The inputs the VCD must have.
pub const BOUND_REQUIRED: [&str; 3] = ["reset", "enc_a", "enc_b"];

/// Steps of its stretch a sample waits for before it is judged with the stretch's speed
/// range as it then stands (a longer wait narrows the range; this one bounds the memory).
pub const LOOKAHEAD_STEPS: u64 = 64;

/// How to read the VCD, the implementation's format, and how much to report.
#[derive(Clone, Debug)]
pub struct BoundOptions {
    /// The scope of the implementation's ports; None: found.
    pub scope: Option<String>,
    /// (their signal name, port name) for each signal named otherwise.
    pub map: Vec<(String, String)>,
    /// Fractional bits F of the speed outputs: a value v is v/2^F lines per dt.
    pub frac_bits: u32,
    /// Cycles the implementation's estimates may lag the window they measure, beyond the
    /// dt already allowed.
    pub latency: u64,
    /// Violations kept for the report (all are counted).
    pub report: usize,
}

/// The strobe that marks a new sample of `est` in the core.
pub fn strobe_port(est: Estimator) -> &'static str {
    match est {
        Estimator::N1 | Estimator::N3 => "speed_strobe",
        Estimator::Pc | Estimator::Et | Estimator::Mt => "baseline_strobe",
    }
}

/// Statistics of one estimator's judged samples.
#[derive(Clone, Debug, PartialEq)]
pub struct EstimatorStat {
    /// The estimator.
    pub estimator: Estimator,
    /// Its width in the VCD.
    pub width: u32,
    /// Whether its strobe is in the VCD (else a sample is a change of the value).
    pub strobed: bool,
    /// Samples judged.
    pub samples: u64,
    /// Samples outside their bound.
    pub violations: u64,
    /// Largest relative error.
    pub max_err: f64,
    /// Sum of squared relative errors.
    pub sum_sq_err: f64,
    /// Largest error/bound.
    pub max_ratio: f64,
    /// Sum of squared error/bound.
    pub sum_sq_ratio: f64,
    /// M/T samples of 0 in judged places (windows without a step: no estimate).
    pub empty: u64,
    /// Samples not judged: their stretch too young, or no step after them.
    pub unjudged: u64,
}

impl EstimatorStat {
    fn new(estimator: Estimator, width: u32, strobed: bool) -> EstimatorStat {
        EstimatorStat {
            estimator,
            width,
            strobed,
            samples: 0,
            violations: 0,
            max_err: 0.0,
            sum_sq_err: 0.0,
            max_ratio: 0.0,
            sum_sq_ratio: 0.0,
            empty: 0,
            unjudged: 0,
        }
    }

    /// RMS relative error.
    pub fn rms_err(&self) -> f64 {
        (self.sum_sq_err / self.samples.max(1) as f64).sqrt()
    }

    /// RMS of error/bound.
    pub fn rms_ratio(&self) -> f64 {
        (self.sum_sq_ratio / self.samples.max(1) as f64).sqrt()
    }
}

/// One sample outside its bound.
#[derive(Clone, Debug, PartialEq)]
pub struct Violation {
    /// The rising edge before which the value was seen (edges counted from the VCD's first).
    pub cycle: u64,
    /// Its time, in the VCD's timescale.
    pub time: u64,
    /// The port.
    pub port: &'static str,
    /// The sample, lines per dt.
    pub got: f64,
    /// The true speed: the middle of the stretch's range, lines per dt (signed).
    pub speed: f64,
    /// Relative error.
    pub error: f64,
    /// Its bound.
    pub bound: f64,
}

/// What a bound comparison found.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundVerdict {
    /// The scope read.
    pub scope: String,
    /// The VCD's timescale.
    pub timescale: String,
    /// The first edge at which reset was 1.
    pub first_cycle: u64,
    /// Edges read from the first reset on.
    pub cycles: u64,
    /// Stretches of constant speed found (of two or more steps).
    pub stretches: u64,
    /// Per speed output the VCD has, in [`Estimator::ALL`]'s order.
    pub stats: Vec<EstimatorStat>,
    /// Speed outputs the VCD lacks.
    pub absent: Vec<&'static str>,
    /// The first violations (at most [`BoundOptions::report`]).
    pub first: Vec<Violation>,
}

impl BoundVerdict {
    /// Samples judged, all estimators.
    pub fn samples(&self) -> u64 {
        self.stats.iter().map(|s| s.samples).sum()
    }

    /// Violations, all estimators.
    pub fn violations(&self) -> u64 {
        self.stats.iter().map(|s| s.violations).sum()
    }
}

/// A run of same-direction steps consistent with one constant step period.
#[derive(Clone, Copy, Debug)]
struct Stretch {
    forward: bool,
    /// Edges of the first and the last step.
    first: u64,
    last: u64,
    /// Intervals (steps after the first).
    intervals: u64,
    /// The open interval of step periods (cycles) consistent with every step.
    p_lo: f64,
    p_hi: f64,
    /// Effective dt and log2 steps per line when it began.
    dt: u64,
    shift: u32,
}

impl Stretch {
    fn new(forward: bool, at: u64, dt: u64, shift: u32) -> Stretch {
        Stretch {
            forward,
            first: at,
            last: at,
            intervals: 0,
            p_lo: 0.0,
            p_hi: f64::INFINITY,
            dt,
            shift,
        }
    }

    /// Adds the step at edge `q`; false (and no change) if no constant period fits it.
    fn extend(&mut self, q: u64) -> bool {
        let i = (self.intervals + 1) as f64;
        let span = (q - self.first) as f64;
        let lo = self.p_lo.max((span - 1.0) / i);
        let hi = self.p_hi.min((span + 1.0) / i);
        if lo >= hi {
            return false;
        }
        (self.p_lo, self.p_hi) = (lo, hi);
        self.intervals += 1;
        self.last = q;
        true
    }
}

/// A speed value waiting for its stretch to say what the true speed was.
#[derive(Clone, Copy, Debug)]
struct Sample {
    est: usize,
    cycle: u64,
    time: u64,
    value: f64,
    /// The stretch's intervals when the sample was seen.
    intervals: u64,
}

/// The judging state: the stretch, the waiting samples, the statistics.
struct Judge {
    latency: u64,
    lsb: f64,
    report: usize,
    stretch: Option<Stretch>,
    pending: VecDeque<Sample>,
    stretches: u64,
    stats: Vec<EstimatorStat>,
    first: Vec<Violation>,
}

impl Judge {
    /// Judges every waiting sample against the current stretch and forgets the stretch.
    fn end_stretch(&mut self) {
        if let Some(s) = self.stretch.take() {
            self.stretches += u64::from(s.intervals > 0);
            while let Some(x) = self.pending.pop_front() {
                self.judge(&s, x);
            }
        }
        // Samples seen before any stretch had a step.
        while let Some(x) = self.pending.pop_front() {
            self.stats[x.est].unjudged += 1;
        }
    }

    /// Judges the samples that have waited [`LOOKAHEAD_STEPS`] steps.
    fn judge_ripe(&mut self) {
        let Some(s) = self.stretch else { return };
        while self
            .pending
            .front()
            .is_some_and(|x| x.intervals + LOOKAHEAD_STEPS <= s.intervals)
        {
            let x = self.pending.pop_front().expect("checked");
            self.judge(&s, x);
        }
    }

    fn judge(&mut self, s: &Stretch, x: Sample) {
        let est = self.stats[x.est].estimator;
        let window = 2 * s.dt.max(s.p_hi.ceil() as u64) + s.dt + self.latency;
        if s.intervals == 0 || x.cycle >= s.last || x.cycle < s.first + window {
            self.stats[x.est].unjudged += 1;
            return;
        }
        if est == Estimator::Mt && x.value == 0.0 {
            self.stats[x.est].empty += 1;
            return;
        }
        // Steps per dt at the ends and the middle of the period range (a step per cycle at
        // most: the seen steps are whole cycles apart).
        let p_lo = s.p_lo.max(1.0);
        let p_mid = 0.5 * (p_lo + s.p_hi);
        let dt = s.dt as f64;
        let per_line = f64::from(1u32 << s.shift);
        let sign = if s.forward { 1.0 } else { -1.0 };
        let (slow, fast, mid) = (dt / s.p_hi, dt / p_lo, dt / p_mid);
        let speed = sign * mid / per_line;
        let (a, b) = (sign * slow / per_line, sign * fast / per_line);
        let (lo, hi) = (a.min(b), a.max(b));
        let distance = if x.value < lo {
            lo - x.value
        } else if x.value > hi {
            x.value - hi
        } else {
            0.0
        };
        let error = distance / speed.abs();
        let bound = [slow, mid, fast]
            .map(|rs| estimator_bound(est, rs, s.dt))
            .into_iter()
            .fold(0.0, f64::max)
            + self.lsb / speed.abs();
        let ratio = error / bound;
        let stat = &mut self.stats[x.est];
        stat.samples += 1;
        stat.max_err = stat.max_err.max(error);
        stat.sum_sq_err += error * error;
        stat.max_ratio = stat.max_ratio.max(ratio);
        stat.sum_sq_ratio += ratio * ratio;
        if error > bound {
            stat.violations += 1;
            if self.first.len() < self.report {
                self.first.push(Violation {
                    cycle: x.cycle,
                    time: x.time,
                    port: est.port(),
                    got: x.value,
                    speed,
                    error,
                    bound,
                });
            }
        }
    }
}

/// Judges the speed outputs of the implementation in the VCD `reader` against their
/// bounds. `p` gives the default dt (for `cfg_dt` = 0 or absent). An unusable VCD is an
/// error, as for [`super::verdict::check_exact`]; so is a VCD with no speed output.
pub fn check_bound<R: Read>(
    reader: R,
    p: &Params,
    core_inputs: &[RefPort],
    core_outputs: &[RefPort],
    options: &BoundOptions,
) -> Result<BoundVerdict, VcdError> {
    let pick = |ports: &[RefPort], names: &[&str]| -> Vec<RefPort> {
        names
            .iter()
            .map(|n| {
                ports
                    .iter()
                    .find(|p| p.name == *n)
                    .expect("the core has every port bound mode reads")
                    .clone()
            })
            .collect()
    };
    let inputs = pick(core_inputs, &BOUND_INPUTS);
    // Outputs: the five speeds, then the two strobes.
    let mut names: Vec<&str> = Estimator::ALL.iter().map(|e| e.port()).collect();
    names.extend(["speed_strobe", "baseline_strobe"]);
    let outputs = pick(core_outputs, &names);
    let mut edges = VcdCycles::with_required(
        reader,
        &inputs,
        &outputs,
        options.scope.as_deref(),
        &options.map,
        &BOUND_REQUIRED,
    )?;
    let widths = edges.output_widths().to_vec();
    let strobe_slot = |est: Estimator| 5 + usize::from(strobe_port(est) == "baseline_strobe");
    let present: Vec<Estimator> = Estimator::ALL
        .into_iter()
        .filter(|e| widths[e.index()].is_some())
        .collect();
    if present.is_empty() {
        return Err(VcdError(format!(
            "--mode bound: the scope has none of {} (give --map where the names differ)",
            names[..5].join(", ")
        )));
    }
    let (n, unit) = edges.timescale();
    let mut judge = Judge {
        latency: options.latency,
        lsb: (-f64::from(options.frac_bits)).exp2(),
        report: options.report,
        stretch: None,
        pending: VecDeque::new(),
        stretches: 0,
        stats: present
            .iter()
            .map(|&e| {
                EstimatorStat::new(
                    e,
                    widths[e.index()].expect("present"),
                    widths[strobe_slot(e)].is_some(),
                )
            })
            .collect(),
        first: Vec::new(),
    };
    let mut verdict = BoundVerdict {
        scope: edges.scope().to_string(),
        timescale: format!("{n}{unit}"),
        first_cycle: 0,
        cycles: 0,
        stretches: 0,
        stats: Vec::new(),
        absent: Estimator::ALL
            .into_iter()
            .filter(|e| widths[e.index()].is_none())
            .map(|e| e.port())
            .collect(),
        first: Vec::new(),
    };
    let mut decoder = QuadratureDecoder::new(32);
    let mut started = false;
    let mut last_values: Vec<Option<u128>> = vec![None; present.len()];
    let mut edge = VcdEdge::default();
    let mut any_edge = false;
    while edges.read_edge(&mut edge)? {
        any_edge = true;
        let [reset, a, b, cfg_dt, cfg_mode] = [0, 1, 2, 3, 4].map(|k| edge.inputs[k]);
        if !started && reset == 1 {
            started = true;
            verdict.first_cycle = edge.cycle;
        }
        if !started {
            continue;
        }
        if let Some(name) = edge.unknown_input {
            return Err(VcdError(format!(
                "input {name} is x or z at the rising edge {} (time {}{}) after the first reset",
                edge.cycle, edge.time, verdict.timescale
            )));
        }
        verdict.cycles += 1;
        let dt = if cfg_dt == 0 {
            p.dt_cycles()
        } else {
            (cfg_dt.min(u128::from(u64::MAX)) as u64).max(MIN_DT_CYCLES)
        };
        let mode = cfg_mode.min(3) as u8;
        let shift = mode_shift(mode.min(2));
        let step = decoder.step(DecoderInputs {
            reset: reset == 1,
            a: a == 1,
            b: b == 1,
            cfg_mode: mode,
        });
        if reset == 1
            || mode == 3
            || judge
                .stretch
                .is_some_and(|s| (s.dt, s.shift) != (dt, shift))
        {
            judge.end_stretch();
            last_values.fill(None);
        }
        if reset == 1 {
            continue;
        }
        // The samples seen before this edge (outputs of the previous one).
        let intervals = judge.stretch.map_or(0, |s| s.intervals);
        for (k, &est) in present.iter().enumerate() {
            let Some(raw) = edge.outputs[est.index()] else {
                continue;
            };
            let sampled = if judge.stats[k].strobed {
                edge.outputs[strobe_slot(est)] == Some(1)
            } else {
                last_values[k] != Some(raw)
            };
            last_values[k] = Some(raw);
            if sampled {
                let width = judge.stats[k].width;
                judge.pending.push_back(Sample {
                    est: k,
                    cycle: edge.cycle,
                    time: edge.time,
                    value: signed(raw, width) * judge.lsb,
                    intervals,
                });
            }
        }
        if step.step && mode != 3 {
            let q = edge.cycle;
            match judge.stretch {
                Some(mut s) if s.forward == step.forward => {
                    if s.extend(q) {
                        judge.stretch = Some(s);
                        judge.judge_ripe();
                    } else {
                        // The speed changed: the new stretch starts at the last step, with
                        // the interval to this one.
                        judge.end_stretch();
                        let mut fresh = Stretch::new(step.forward, s.last, dt, shift);
                        fresh.extend(q);
                        judge.stretch = Some(fresh);
                    }
                }
                _ => {
                    judge.end_stretch();
                    judge.stretch = Some(Stretch::new(step.forward, q, dt, shift));
                }
            }
        }
    }
    if !any_edge {
        return Err(VcdError("the clock never rises in the VCD".into()));
    }
    if !started {
        return Err(VcdError(
            "reset is never 1 at a rising edge: the comparison starts at the first reset".into(),
        ));
    }
    judge.end_stretch();
    verdict.stretches = judge.stretches;
    verdict.stats = judge.stats;
    verdict.first = judge.first;
    Ok(verdict)
}

/// `raw` as a two's-complement number of `width` bits.
fn signed(raw: u128, width: u32) -> f64 {
    if width == 0 || width >= 128 || raw >> (width - 1) & 1 == 0 {
        raw as i128 as f64
    } else {
        (raw as i128 - (1i128 << width)) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_constant_period_stays_one_stretch_and_a_change_ends_it() {
        // Steps at ⌈0.3 + 7.25·i⌉: period 7.25 cycles seen on whole cycles.
        let mut s = Stretch::new(true, 1, 100, 0);
        for i in 1..200u64 {
            let q = (0.3 + 7.25 * i as f64).ceil() as u64;
            assert!(s.extend(q), "step {i} at {q}");
        }
        assert!(s.p_lo < 7.25 && 7.25 < s.p_hi && s.p_hi - s.p_lo < 2.0 / 199.0);
        // A period 1 % longer is refused within a few hundred cycles.
        let mut refused = false;
        for i in 200..260u64 {
            let q = (0.3 + 7.25 * 199.0 + 7.3225 * (i - 199) as f64).ceil() as u64;
            refused |= !s.extend(q);
        }
        assert!(refused);
    }

    #[test]
    fn signed_values_by_hand() {
        assert_eq!(signed(0xff, 8), -1.0);
        assert_eq!(signed(0x7f, 8), 127.0);
        assert_eq!(signed(1, 1), -1.0);
        assert_eq!(signed(3, 2), -1.0);
    }
}
