// SPDX-License-Identifier: MIT OR Apache-2.0
//! Layer-1 plant: shaft motion → exact A/B/Z edge instants → clock samples.
//!
//! Units throughout: angle in revolutions (rev), speed in rev/s, time in seconds, disc
//! position `x` in lines (`x = angle · K`, K = [`Disc::lines`]). The motion is a
//! [`Profile`] of analytic [`Segment`]s starting at t = 0; [`edges`] finds every edge of
//! A, B and Z to floating precision, and [`ClockSampler`] turns the edge list into the
//! per-cycle levels a synchronous input stage sees.
//!
//! Level convention (half-open everywhere, a function of `x` alone):
//! A high iff frac(x) ∈ [0, ½), B high iff frac(x) ∈ [¼, ¾) (B lags A by 90° for
//! positive speed), Z high iff (x mod K) ∈ [¼, ½) (gated index). Every level changes
//! only at a quarter-line level q = m/4: the value at x = q exactly is the one above q.

use serde::{Deserialize, Serialize};
use std::f64::consts::{PI, TAU};
use std::fmt;

/// Why a profile, disc or sampler was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum PlantError {
    /// A profile needs at least one segment.
    EmptyProfile,
    /// The initial angle (rev) is NaN or infinite.
    NonFiniteAngle(f64),
    /// A segment duration that is not finite and > 0.
    BadDuration {
        /// Position of the segment in the profile.
        index: usize,
        /// The offending duration (s).
        duration: f64,
    },
    /// A speed, mean or amplitude that is not finite.
    NonFiniteSpeed {
        /// Position of the segment in the profile.
        index: usize,
        /// The offending value (rev/s).
        value: f64,
    },
    /// A sine frequency that is not finite and > 0.
    BadFrequency {
        /// Position of the segment in the profile.
        index: usize,
        /// The offending frequency (Hz).
        freq_hz: f64,
    },
    /// A step instant outside (0, total).
    BadStepTime {
        /// Requested step instant (s).
        t_step: f64,
        /// Requested profile length (s).
        total: f64,
    },
    /// A disc needs at least one line per revolution.
    ZeroLines,
    /// The sampling clock (Hz) is not finite and > 0.
    BadClock(f64),
}

impl fmt::Display for PlantError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::EmptyProfile => write!(f, "profile has no segments"),
            Self::NonFiniteAngle(a) => write!(f, "initial angle {a} rev is not finite"),
            Self::BadDuration { index, duration } => {
                write!(
                    f,
                    "segment {index}: duration {duration} s must be finite and > 0"
                )
            }
            Self::NonFiniteSpeed { index, value } => {
                write!(f, "segment {index}: speed {value} rev/s is not finite")
            }
            Self::BadFrequency { index, freq_hz } => {
                write!(
                    f,
                    "segment {index}: frequency {freq_hz} Hz must be finite and > 0"
                )
            }
            Self::BadStepTime { t_step, total } => {
                write!(
                    f,
                    "step time {t_step} s must lie strictly inside (0, {total}) s"
                )
            }
            Self::ZeroLines => write!(f, "disc must have at least one line per revolution"),
            Self::BadClock(hz) => write!(f, "clock {hz} Hz must be finite and > 0"),
        }
    }
}

impl std::error::Error for PlantError {}

/// One analytic piece of shaft motion; τ is the time since the segment started (s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Segment {
    /// Constant speed.
    Constant {
        /// Speed (rev/s), any sign.
        speed: f64,
        /// Length (s), > 0.
        duration: f64,
    },
    /// Speed changing linearly; a ramp through zero is a reversal.
    Ramp {
        /// Speed at the start (rev/s).
        from: f64,
        /// Speed at the end (rev/s).
        to: f64,
        /// Length (s), > 0.
        duration: f64,
    },
    /// speed(τ) = mean + amplitude·sin(2π·freq_hz·τ); reverses whenever
    /// |amplitude| > |mean|.
    Sine {
        /// Mean speed (rev/s).
        mean: f64,
        /// Peak speed deviation (rev/s), any sign.
        amplitude: f64,
        /// Modulation frequency (Hz), > 0.
        freq_hz: f64,
        /// Length (s), > 0.
        duration: f64,
    },
    /// Standing still.
    Stop {
        /// Length (s), > 0.
        duration: f64,
    },
}

impl Segment {
    /// Length of the segment (s).
    pub fn duration(&self) -> f64 {
        match *self {
            Self::Constant { duration, .. }
            | Self::Ramp { duration, .. }
            | Self::Sine { duration, .. }
            | Self::Stop { duration } => duration,
        }
    }

    /// Angle travelled (rev) τ seconds after the segment start: the exact integral of
    /// [`Segment::speed_at`].
    pub fn delta_angle(&self, tau: f64) -> f64 {
        match *self {
            Self::Constant { speed, .. } => speed * tau,
            Self::Ramp { from, to, duration } => tau * (from + 0.5 * (to - from) * tau / duration),
            Self::Sine {
                mean,
                amplitude,
                freq_hz,
                ..
            } => {
                let w = TAU * freq_hz;
                // 1 − cos θ written as 2 sin²(θ/2): no cancellation for small θ.
                let s = (0.5 * w * tau).sin();
                mean * tau + amplitude * 2.0 * s * s / w
            }
            Self::Stop { .. } => 0.0,
        }
    }

    /// Speed (rev/s) τ seconds after the segment start.
    pub fn speed_at(&self, tau: f64) -> f64 {
        match *self {
            Self::Constant { speed, .. } => speed,
            Self::Ramp { from, to, duration } => from + (to - from) * tau / duration,
            Self::Sine {
                mean,
                amplitude,
                freq_hz,
                ..
            } => mean + amplitude * (TAU * freq_hz * tau).sin(),
            Self::Stop { .. } => 0.0,
        }
    }

    /// Instants τ ∈ (0, duration), ascending, where the speed changes sign. Tangential
    /// zeros (|amplitude| = |mean|) are not reported: the motion stays monotone there.
    pub fn sign_changes(&self) -> Vec<f64> {
        match *self {
            Self::Ramp { from, to, duration } if from * to < 0.0 => {
                vec![duration * from / (from - to)]
            }
            Self::Sine {
                mean,
                amplitude,
                freq_hz,
                duration,
            } if amplitude.abs() > mean.abs() => {
                let w = TAU * freq_hz;
                let phi = (-mean / amplitude).asin();
                let end = w * duration;
                let mut roots = Vec::new();
                // sin θ = −mean/amplitude at θ = φ + 2πk and θ = π − φ + 2πk.
                for base in [phi, PI - phi] {
                    let mut k = (-base / TAU).floor();
                    loop {
                        let theta = base + TAU * k;
                        if theta >= end {
                            break;
                        }
                        if theta > 0.0 {
                            roots.push(theta / w);
                        }
                        k += 1.0;
                    }
                }
                roots.sort_by(f64::total_cmp);
                roots.retain(|&tau| tau > 0.0 && tau < duration);
                roots
            }
            _ => Vec::new(),
        }
    }

    fn validate(&self, index: usize) -> Result<(), PlantError> {
        let d = self.duration();
        if !(d.is_finite() && d > 0.0) {
            return Err(PlantError::BadDuration { index, duration: d });
        }
        let speeds: &[f64] = match self {
            Self::Constant { speed, .. } => &[*speed],
            Self::Ramp { from, to, .. } => &[*from, *to],
            Self::Sine {
                mean,
                amplitude,
                freq_hz,
                ..
            } => {
                if !(freq_hz.is_finite() && *freq_hz > 0.0) {
                    return Err(PlantError::BadFrequency {
                        index,
                        freq_hz: *freq_hz,
                    });
                }
                &[*mean, *amplitude]
            }
            Self::Stop { .. } => &[],
        };
        match speeds.iter().find(|v| !v.is_finite()) {
            Some(&value) => Err(PlantError::NonFiniteSpeed { index, value }),
            None => Ok(()),
        }
    }
}

/// Shaft motion from t = 0: an initial angle (rev) followed by segments back to back.
///
/// Before t = 0 and after [`Profile::duration`] the shaft holds still (angle constant,
/// speed 0), so sampling past the end sees no further edges.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Profile {
    /// Angle at t = 0 (rev).
    pub initial_angle: f64,
    /// Motion segments, played in order.
    pub segments: Vec<Segment>,
}

impl Profile {
    /// A validated profile.
    pub fn new(initial_angle: f64, segments: Vec<Segment>) -> Result<Self, PlantError> {
        let p = Self {
            initial_angle,
            segments,
        };
        p.validate()?;
        Ok(p)
    }

    /// Checks: at least one segment, finite angle and speeds, durations and frequencies
    /// finite and > 0.
    pub fn validate(&self) -> Result<(), PlantError> {
        if !self.initial_angle.is_finite() {
            return Err(PlantError::NonFiniteAngle(self.initial_angle));
        }
        if self.segments.is_empty() {
            return Err(PlantError::EmptyProfile);
        }
        self.segments
            .iter()
            .enumerate()
            .try_for_each(|(i, s)| s.validate(i))
    }

    /// Constant `speed` (rev/s) for `duration` (s), from angle 0.
    pub fn constant(speed: f64, duration: f64) -> Result<Self, PlantError> {
        Self::new(0.0, vec![Segment::Constant { speed, duration }])
    }

    /// Linear speed change `from` → `to` (rev/s) over `duration` (s), from angle 0.
    pub fn ramp(from: f64, to: f64, duration: f64) -> Result<Self, PlantError> {
        Self::new(0.0, vec![Segment::Ramp { from, to, duration }])
    }

    /// Speed step: `from` (rev/s) until `t_step` (s), then `to` until `total` (s).
    pub fn step(from: f64, to: f64, t_step: f64, total: f64) -> Result<Self, PlantError> {
        if !(t_step > 0.0 && t_step < total) {
            return Err(PlantError::BadStepTime { t_step, total });
        }
        let segments = vec![
            Segment::Constant {
                speed: from,
                duration: t_step,
            },
            Segment::Constant {
                speed: to,
                duration: total - t_step,
            },
        ];
        Self::new(0.0, segments)
    }

    /// Sinusoidal speed `mean` + `amplitude`·sin(2π·`freq_hz`·t) (rev/s) for `duration`.
    pub fn sine(
        mean: f64,
        amplitude: f64,
        freq_hz: f64,
        duration: f64,
    ) -> Result<Self, PlantError> {
        Self::new(
            0.0,
            vec![Segment::Sine {
                mean,
                amplitude,
                freq_hz,
                duration,
            }],
        )
    }

    /// Constant `speed` (rev/s) for `t_run` (s), then an abrupt stop held for `t_stop`.
    pub fn stop_after(speed: f64, t_run: f64, t_stop: f64) -> Result<Self, PlantError> {
        let segments = vec![
            Segment::Constant {
                speed,
                duration: t_run,
            },
            Segment::Stop { duration: t_stop },
        ];
        Self::new(0.0, segments)
    }

    /// Reversal: speed ramps from `speed` to −`speed` (rev/s) over `t_ramp` (s), turning
    /// at `t_ramp`/2 and ending back at the initial angle.
    pub fn reversal(speed: f64, t_ramp: f64) -> Result<Self, PlantError> {
        Self::ramp(speed, -speed, t_ramp)
    }

    /// This profile with one more segment appended (validated).
    pub fn then(mut self, segment: Segment) -> Result<Self, PlantError> {
        segment.validate(self.segments.len())?;
        self.segments.push(segment);
        Ok(self)
    }

    /// This profile starting from `angle` (rev) instead.
    pub fn with_initial_angle(mut self, angle: f64) -> Result<Self, PlantError> {
        self.initial_angle = angle;
        self.validate()?;
        Ok(self)
    }

    /// Total length (s).
    pub fn duration(&self) -> f64 {
        self.segments.iter().fold(0.0, |t, s| t + s.duration())
    }

    /// Angle (rev) at time `t` (s); constant outside [0, duration].
    pub fn angle(&self, t: f64) -> f64 {
        match self.locate(t) {
            Located::Inside { index, t0, a0 } => a0 + self.segments[index].delta_angle(t - t0),
            Located::Before => self.initial_angle,
            Located::After { angle } => angle,
        }
    }

    /// Speed (rev/s) at time `t` (s); 0 outside [0, duration). At a segment boundary the
    /// later segment's value applies.
    pub fn speed(&self, t: f64) -> f64 {
        match self.locate(t) {
            Located::Inside { index, t0, .. } => self.segments[index].speed_at(t - t0),
            _ => 0.0,
        }
    }

    /// Segment containing `t` (start ≤ t < end). Start times and start angles are summed
    /// in exactly the order [`edges`] sums them, so both see bit-identical positions.
    fn locate(&self, t: f64) -> Located {
        if t < 0.0 {
            return Located::Before;
        }
        let (mut t0, mut a0) = (0.0, self.initial_angle);
        for (index, s) in self.segments.iter().enumerate() {
            let t1 = t0 + s.duration();
            if t < t1 {
                return Located::Inside { index, t0, a0 };
            }
            a0 += s.delta_angle(s.duration());
            t0 = t1;
        }
        Located::After { angle: a0 }
    }
}

enum Located {
    Before,
    Inside { index: usize, t0: f64, a0: f64 },
    After { angle: f64 },
}

/// Encoder disc: `lines` (K) lines per revolution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Disc {
    /// Lines per revolution (K ≥ 1).
    pub lines: u32,
}

impl Disc {
    /// A disc with `lines` ≥ 1 lines per revolution.
    pub fn new(lines: u32) -> Result<Self, PlantError> {
        if lines == 0 {
            return Err(PlantError::ZeroLines);
        }
        Ok(Self { lines })
    }

    /// Disc position x (lines) of a shaft angle (rev).
    pub fn position(&self, angle: f64) -> f64 {
        angle * f64::from(self.lines)
    }

    /// A/B/Z levels at disc position `x` (lines). Uses the quarter index ⌊4x⌋ (4x is
    /// exact), never frac(x), whose rounding could put tiny negative x at 1.0.
    pub fn levels(&self, x: f64) -> Sample {
        let m = (4.0 * x).floor() as i64;
        let quarter = m.rem_euclid(4);
        Sample {
            a: quarter < 2,
            b: quarter == 1 || quarter == 2,
            z: m.rem_euclid(4 * i64::from(self.lines)) == 1,
        }
    }
}

/// One encoder channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Channel {
    /// Quadrature channel A (leads B for positive speed).
    A,
    /// Quadrature channel B.
    B,
    /// Index channel Z (high for a quarter line once per revolution).
    Z,
}

/// A level change of one channel at time `t` (s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Edge {
    /// Instant of the change (s): the first time at which the new level holds.
    pub t: f64,
    /// Which channel changes.
    pub channel: Channel,
    /// True for low → high.
    pub rising: bool,
}

/// Levels of A, B, Z at one instant (true = high).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Sample {
    /// Channel A.
    pub a: bool,
    /// Channel B.
    pub b: bool,
    /// Channel Z.
    pub z: bool,
}

impl Sample {
    /// These levels after `edge`.
    pub fn apply(&mut self, edge: &Edge) {
        match edge.channel {
            Channel::A => self.a = edge.rising,
            Channel::B => self.b = edge.rising,
            Channel::Z => self.z = edge.rising,
        }
    }
}

/// Levels at t = 0 (those of the initial angle).
pub fn initial_levels(profile: &Profile, disc: &Disc) -> Sample {
    disc.levels(disc.position(profile.initial_angle))
}

/// A stretch [t0, t1] of one segment in which the speed keeps its sign. x0 and x1 are the
/// canonical positions (lines) at its ends: a boundary shared by two pieces has one value,
/// so an edge at the boundary is found in exactly one of them.
struct Piece {
    seg: Segment,
    seg_t0: f64,
    seg_a0: f64,
    t0: f64,
    x0: f64,
    t1: f64,
    x1: f64,
}

/// Every edge of A, B and Z over the profile, in time order (ties: A/B before Z).
///
/// Each monotone piece that moves from x0 to x1 crosses the quarter levels q = m/4 with
/// x0 < q ≤ x1 (forward) or x1 < q ≤ x0 (backward), matching the half-open level
/// convention; each crossing time is bracketed, narrowed by Newton steps on the analytic
/// speed and finished by bisection down to adjacent floats: the returned t shows the new
/// level and the float just before it the old one (per the same position formula as
/// [`Profile::angle`]). Memory and time are O(edges); 1e7 edges take about 1 s (constant
/// speed) to 2.5 s (sine) in release builds.
///
/// # Panics
/// If the profile or disc is invalid ([`Profile::validate`], `lines` = 0).
pub fn edges(profile: &Profile, disc: &Disc) -> Vec<Edge> {
    if let Err(e) = profile.validate() {
        panic!("edges: invalid profile: {e}");
    }
    assert!(disc.lines > 0, "edges: {}", PlantError::ZeroLines);
    let k = f64::from(disc.lines);
    let mut pieces = Vec::new();
    let (mut t0, mut a0) = (0.0, profile.initial_angle);
    for &seg in &profile.segments {
        let t1 = t0 + seg.duration();
        let a1 = a0 + seg.delta_angle(seg.duration());
        let mut start = (t0, k * a0);
        let turns = seg
            .sign_changes()
            .into_iter()
            .map(|tau| (t0 + tau, k * (a0 + seg.delta_angle(tau))));
        for end in turns.chain(std::iter::once((t1, k * a1))) {
            let (x0, x1) = (start.1, end.1);
            pieces.push(Piece {
                seg,
                seg_t0: t0,
                seg_a0: a0,
                t0: start.0,
                x0,
                t1: end.0,
                x1,
            });
            start = end;
        }
        (t0, a0) = (t1, a1);
    }
    let quarters = |p: &Piece| ((4.0 * p.x1).floor() - (4.0 * p.x0).floor()).abs();
    let crossings: f64 = pieces.iter().map(quarters).sum();
    // Z adds two edges per 4K quarters; reserving once avoids a doubling copy at 1e7 edges.
    let mut out = Vec::with_capacity((crossings * (1.0 + 0.5 / k)) as usize + 2);
    for p in &pieces {
        piece_edges(p, k, i64::from(disc.lines) * 4, &mut out);
    }
    out
}

fn piece_edges(p: &Piece, k: f64, zperiod: i64, out: &mut Vec<Edge>) {
    let m0 = (4.0 * p.x0).floor() as i64;
    let m1 = (4.0 * p.x1).floor() as i64;
    if m0 == m1 {
        return;
    }
    let forward = m1 > m0;
    let x = |t: f64| k * (p.seg_a0 + p.seg.delta_angle(t - p.seg_t0));
    let v = |t: f64| k * p.seg.speed_at(t - p.seg_t0);
    // Invariant: at `lo` the position is still on the old side of the next level.
    let (mut lo, mut xlo) = (p.t0, p.x0);
    let levels: Box<dyn Iterator<Item = i64>> = if forward {
        Box::new(m0 + 1..=m1)
    } else {
        Box::new((m1 + 1..=m0).rev())
    };
    for m in levels {
        let q = m as f64 * 0.25;
        let is_new = |xt: f64| if forward { xt >= q } else { xt < q };
        let (t, new_lo, new_xlo) = crossing(&x, &v, &is_new, q, (lo, xlo), p.t1);
        (lo, xlo) = (new_lo, new_xlo);
        // Forward polarity by quarter: m ≡ 0 A↑, 1 B↑, 2 A↓, 3 B↓; backward inverts it.
        let (channel, up) = match m.rem_euclid(4) {
            0 => (Channel::A, true),
            1 => (Channel::B, true),
            2 => (Channel::A, false),
            _ => (Channel::B, false),
        };
        out.push(Edge {
            t,
            channel,
            rising: up == forward,
        });
        match m.rem_euclid(zperiod) {
            1 => out.push(Edge {
                t,
                channel: Channel::Z,
                rising: forward,
            }),
            2 => out.push(Edge {
                t,
                channel: Channel::Z,
                rising: !forward,
            }),
            _ => {}
        }
    }
}

/// First float t in (lo, hi] at which `is_new(x(t))`, given that lo is old and hi new.
/// Returns (t, final lo, x(final lo)); the final lo is old for every later level too.
fn crossing(
    x: &impl Fn(f64) -> f64,
    v: &impl Fn(f64) -> f64,
    is_new: &impl Fn(f64) -> bool,
    q: f64,
    (mut lo, mut xlo): (f64, f64),
    mut hi: f64,
) -> (f64, f64, f64) {
    let probe = |t: f64, lo: &mut f64, xlo: &mut f64, hi: &mut f64| -> Option<f64> {
        if !(t > *lo && t < *hi) {
            return None;
        }
        let xt = x(t);
        if is_new(xt) {
            *hi = t;
        } else {
            (*lo, *xlo) = (t, xt);
        }
        Some(xt)
    };
    // Newton from lo, then once more from the guess: the root is then known to a few
    // ulps, and probing both sides of it leaves only a few bisection steps.
    let mut t = lo + (q - xlo) / v(lo);
    let mut step = f64::INFINITY;
    for _ in 0..2 {
        let Some(xt) = probe(t, &mut lo, &mut xlo, &mut hi) else {
            break;
        };
        step = (q - xt) / v(t);
        if !step.is_finite() {
            break;
        }
        t += step;
    }
    if step.is_finite() {
        let d = 2.0 * step.abs() + 4.0 * f64::EPSILON * t.abs();
        probe(t - d, &mut lo, &mut xlo, &mut hi);
        probe(t + d, &mut lo, &mut xlo, &mut hi);
    }
    loop {
        let mid = lo + 0.5 * (hi - lo);
        if mid <= lo || mid >= hi {
            return (hi, lo, xlo);
        }
        probe(mid, &mut lo, &mut xlo, &mut hi);
    }
}

/// Instants (s) of the edges of `channel` with the given polarity (`rising`), in order.
/// The encoder pulses of the estimators are `pulse_times(edges, Channel::A, true)`.
pub fn pulse_times(edges: &[Edge], channel: Channel, rising: bool) -> Vec<f64> {
    edges
        .iter()
        .filter(|e| e.channel == channel && e.rising == rising)
        .map(|e| e.t)
        .collect()
}

/// Streaming sampler: cycle k yields the levels at t_k = k / clock_hz (s).
///
/// An edge at time t is visible at every t_k ≥ t; edges are applied in list order, so the
/// samples agree with the edge list by construction. No per-cycle allocation.
#[derive(Debug, Clone)]
pub struct ClockSampler<'a> {
    edges: &'a [Edge],
    next_edge: usize,
    levels: Sample,
    clock_hz: f64,
    cycle: u64,
    n_cycles: u64,
}

impl<'a> ClockSampler<'a> {
    /// Sampler over cycles 0..`n_cycles` of a `clock_hz` (Hz) clock, starting from the
    /// levels `initial` at t = 0 and the time-ordered `edges`.
    pub fn new(
        initial: Sample,
        edges: &'a [Edge],
        clock_hz: f64,
        n_cycles: u64,
    ) -> Result<Self, PlantError> {
        if !(clock_hz.is_finite() && clock_hz > 0.0) {
            return Err(PlantError::BadClock(clock_hz));
        }
        Ok(Self {
            edges,
            next_edge: 0,
            levels: initial,
            clock_hz,
            cycle: 0,
            n_cycles,
        })
    }

    /// Sampler over every cycle with t_k ≤ profile duration, from the profile's initial
    /// levels; `edges` must be `edges(profile, disc)`.
    pub fn for_profile(
        profile: &Profile,
        disc: &Disc,
        edges: &'a [Edge],
        clock_hz: f64,
    ) -> Result<Self, PlantError> {
        let n_cycles = (profile.duration() * clock_hz).floor() as u64 + 1;
        Self::new(initial_levels(profile, disc), edges, clock_hz, n_cycles)
    }

    /// Instant t_k (s) of cycle `k`.
    pub fn cycle_time(&self, k: u64) -> f64 {
        k as f64 / self.clock_hz
    }
}

impl Iterator for ClockSampler<'_> {
    type Item = Sample;

    fn next(&mut self) -> Option<Sample> {
        if self.cycle >= self.n_cycles {
            return None;
        }
        let t = self.cycle_time(self.cycle);
        while let Some(e) = self.edges.get(self.next_edge) {
            if e.t > t {
                break;
            }
            self.levels.apply(e);
            self.next_edge += 1;
        }
        self.cycle += 1;
        Some(self.levels)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = usize::try_from(self.n_cycles - self.cycle).unwrap_or(usize::MAX);
        (left, Some(left))
    }
}

impl ExactSizeIterator for ClockSampler<'_> {}
