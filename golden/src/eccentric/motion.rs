// SPDX-License-Identifier: MIT OR Apache-2.0
//! Exact A/B/Z edges of an eccentric disc under any shaft motion.
//!
//! The disc position is x(t) = K·φ(θ(t))/(2π) lines, φ the apparent angle of
//! [`Eccentricity::apparent_angle`] and θ(t) the shaft angle of a [`ShaftMotion`]. φ is
//! strictly increasing in θ for e < 1 (its slope is the rate, ≥ 1 − e for Zhao and
//! ≥ 1/(1 + e) for the rigid disc), so x(t) is monotone wherever θ(t) is, and the edges
//! follow [`crate::ideal::plant`]'s conventions exactly: A high iff frac(x) ∈ [0, ½), B high iff
//! frac(x) ∈ [¼, ¾), Z high iff (x mod K) ∈ [¼, ½); every level changes at a quarter line
//! q = m/4, and an edge instant t is the first float at which the new level holds. The
//! output is the plant's [`Edge`] list, so [`crate::ideal::plant::pulse_times`],
//! [`crate::ideal::plant::ClockSampler`] and every estimator take it unchanged.

use super::{EccError, Eccentricity};
use crate::ideal::plant::{Channel, Disc, Edge, Profile, Sample};
use crate::splitmix::SplitMix64;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// Shaft motion from t = 0 to [`ShaftMotion::duration`]; held still outside.
pub trait ShaftMotion {
    /// Shaft angle θ (rev) at time t (s).
    fn angle(&self, t: f64) -> f64;
    /// Shaft speed (rev/s) at time t (s).
    fn speed(&self, t: f64) -> f64;
    /// Length of the motion (s).
    fn duration(&self) -> f64;
    /// Instants in (0, duration), ascending, that cut the motion into pieces in each of
    /// which the angle is monotone (segment ends, speed reversals).
    fn breakpoints(&self) -> Vec<f64>;
}

impl ShaftMotion for Profile {
    fn angle(&self, t: f64) -> f64 {
        Profile::angle(self, t)
    }

    fn speed(&self, t: f64) -> f64 {
        Profile::speed(self, t)
    }

    fn duration(&self) -> f64 {
        Profile::duration(self)
    }

    fn breakpoints(&self) -> Vec<f64> {
        let mut out = Vec::new();
        let mut t0 = 0.0;
        for (i, seg) in self.segments.iter().enumerate() {
            out.extend(seg.sign_changes().into_iter().map(|tau| t0 + tau));
            t0 += seg.duration();
            if i + 1 < self.segments.len() {
                out.push(t0);
            }
        }
        out
    }
}

/// One sinusoidal component of [`JitterMotion`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Tone {
    /// Amplitude relative to the mean speed (dimensionless).
    pub rel_amplitude: f64,
    /// Frequency (Hz), > 0.
    pub freq_hz: f64,
    /// Phase at t = 0 (rad).
    pub phase: f64,
}

/// Forward rotation at a mean speed with a jitter of sinusoids:
/// speed(t) = mean·(1 + Σ aᵢ·sin(2π·fᵢ·t + pᵢ)), integrated exactly. Models the speed
/// noise of a motor held at a set speed (torque ripple, control noise) in identification
/// tests. Monotone when Σ|aᵢ| < 1, which [`JitterMotion::new`] enforces.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct JitterMotion {
    /// Angle at t = 0 (rev).
    pub initial_angle: f64,
    /// Mean speed (rev/s), > 0.
    pub mean: f64,
    /// Jitter components.
    pub tones: Vec<Tone>,
    /// Length (s), > 0.
    pub duration: f64,
}

impl JitterMotion {
    /// A validated jitter motion; `None` if mean or duration is not finite and > 0, a tone
    /// is not finite or has a frequency ≤ 0, or Σ|aᵢ| ≥ 1 (the shaft could stop).
    pub fn new(initial_angle: f64, mean: f64, tones: Vec<Tone>, duration: f64) -> Option<Self> {
        let ok_tone =
            |t: &Tone| t.rel_amplitude.is_finite() && t.phase.is_finite() && t.freq_hz.is_finite();
        let sum: f64 = tones.iter().map(|t| t.rel_amplitude.abs()).sum();
        let valid = initial_angle.is_finite()
            && mean.is_finite()
            && mean > 0.0
            && duration.is_finite()
            && duration > 0.0
            && tones.iter().all(|t| ok_tone(t) && t.freq_hz > 0.0)
            && sum < 1.0;
        valid.then_some(Self {
            initial_angle,
            mean,
            tones,
            duration,
        })
    }

    /// Broadband jitter: `n_tones` tones of equal amplitude, total rms `rms_rel` of the
    /// mean speed, frequencies uniform in [`nu_lo`, `nu_hi`] cycles per revolution of the
    /// mean motion, phases uniform; reproducible from `seed` (SplitMix64).
    #[allow(clippy::too_many_arguments)]
    pub fn broadband(
        initial_angle: f64,
        mean: f64,
        rms_rel: f64,
        nu_lo: f64,
        nu_hi: f64,
        n_tones: usize,
        seed: u64,
        duration: f64,
    ) -> Option<Self> {
        let mut rng = SplitMix64(seed);
        // rms of a sum of n tones of amplitude a with independent phases: a·√(n/2).
        let a = rms_rel * (2.0 / n_tones.max(1) as f64).sqrt();
        let tones = (0..n_tones)
            .map(|_| Tone {
                rel_amplitude: a,
                freq_hz: mean * (nu_lo + (nu_hi - nu_lo) * rng.unit()),
                phase: TAU * rng.unit(),
            })
            .collect();
        Self::new(initial_angle, mean, tones, duration)
    }
}

impl ShaftMotion for JitterMotion {
    fn angle(&self, t: f64) -> f64 {
        let t = t.clamp(0.0, self.duration);
        let wobble: f64 = self
            .tones
            .iter()
            .map(|tone| {
                let w = TAU * tone.freq_hz;
                // ∫₀ᵗ sin(wτ + p) dτ = (cos p − cos(wt + p))/w = 2·sin(wt/2 + p)·sin(wt/2)/w.
                tone.rel_amplitude * 2.0 * (0.5 * w * t + tone.phase).sin() * (0.5 * w * t).sin()
                    / w
            })
            .sum();
        self.initial_angle + self.mean * (t + wobble)
    }

    fn speed(&self, t: f64) -> f64 {
        if !(0.0..self.duration).contains(&t) {
            return 0.0;
        }
        let wobble: f64 = self
            .tones
            .iter()
            .map(|tone| tone.rel_amplitude * (TAU * tone.freq_hz * t + tone.phase).sin())
            .sum();
        self.mean * (1.0 + wobble)
    }

    fn duration(&self) -> f64 {
        self.duration
    }

    fn breakpoints(&self) -> Vec<f64> {
        Vec::new()
    }
}

/// One crossing of a quarter-line level q = quarter/4 (lines) by the disc position.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Crossing {
    /// Instant (s): the first float at which the position is on the new side.
    pub t: f64,
    /// Level index m: the level is q = m/4 lines; whole lines are m ≡ 0 (mod 4).
    pub quarter: i64,
    /// True when crossed upwards (x rises through q).
    pub forward: bool,
}

/// An encoder disc of K lines mounted with an [`Eccentricity`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EccentricDisc {
    /// The disc (K lines per revolution of the disc itself).
    pub disc: Disc,
    /// How it is mounted on the shaft.
    pub ecc: Eccentricity,
}

impl EccentricDisc {
    /// A disc of `lines` lines with eccentricity `ecc` (validated).
    pub fn new(lines: u32, ecc: Eccentricity) -> Result<Self, EccError> {
        ecc.validate()?;
        let disc = Disc::new(lines).map_err(|_| EccError::ZeroLines)?;
        Ok(Self { disc, ecc })
    }

    /// K as a float.
    fn k(&self) -> f64 {
        f64::from(self.disc.lines)
    }

    /// Disc position x (lines) seen by the head at shaft angle θ (rev).
    pub fn position(&self, shaft_angle_rev: f64) -> f64 {
        self.k() / TAU * self.ecc.apparent_angle(TAU * shaft_angle_rev)
    }

    /// Shaft angle θ (rev) at which the head sees disc position x (lines).
    pub fn shaft_angle_rev(&self, x: f64) -> f64 {
        self.ecc.shaft_angle(TAU * x / self.k()) / TAU
    }

    /// Disc position x (lines) at time t (s) of `motion`.
    pub fn position_at(&self, motion: &impl ShaftMotion, t: f64) -> f64 {
        self.position(motion.angle(t))
    }

    /// dx/dt (lines/s) at time t (s).
    fn velocity_at(&self, motion: &impl ShaftMotion, t: f64) -> f64 {
        let theta = TAU * motion.angle(t);
        self.k() * self.ecc.rate(theta + self.ecc.theta0) * motion.speed(t)
    }

    /// A/B/Z levels at t = 0.
    pub fn initial_levels(&self, motion: &impl ShaftMotion) -> Sample {
        self.disc.levels(self.position_at(motion, 0.0))
    }

    /// Every quarter-line crossing over the motion, in time order. Each monotone piece
    /// from x0 to x1 crosses the levels q with x0 < q ≤ x1 (forward) or x1 < q ≤ x0
    /// (backward), as in [`crate::ideal::plant::edges`]; each instant is found by Newton steps on
    /// dx/dt and finished by bisection down to adjacent floats.
    pub fn crossings(&self, motion: &impl ShaftMotion) -> Vec<Crossing> {
        let mut cuts = vec![0.0];
        cuts.extend(motion.breakpoints());
        cuts.push(motion.duration());
        let x = |t: f64| self.position_at(motion, t);
        let v = |t: f64| self.velocity_at(motion, t);
        let mut out = Vec::new();
        for w in cuts.windows(2) {
            let (t0, t1) = (w[0], w[1]);
            let (x0, x1) = (x(t0), x(t1));
            let m0 = (4.0 * x0).floor() as i64;
            let m1 = (4.0 * x1).floor() as i64;
            if m0 == m1 {
                continue;
            }
            let forward = m1 > m0;
            let levels: Box<dyn Iterator<Item = i64>> = if forward {
                Box::new(m0 + 1..=m1)
            } else {
                Box::new((m1 + 1..=m0).rev())
            };
            // Invariant: at `lo` the position is still on the old side of the next level.
            let (mut lo, mut xlo) = (t0, x0);
            for m in levels {
                let q = m as f64 * 0.25;
                let is_new = |xt: f64| if forward { xt >= q } else { xt < q };
                let (t, new_lo, new_xlo) = crossing(&x, &v, &is_new, q, (lo, xlo), t1);
                (lo, xlo) = (new_lo, new_xlo);
                out.push(Crossing {
                    t,
                    quarter: m,
                    forward,
                });
            }
        }
        out
    }

    /// Every edge of A, B and Z over the motion, in time order (ties: A/B before Z).
    pub fn edges(&self, motion: &impl ShaftMotion) -> Vec<Edge> {
        edges_of(&self.crossings(motion), self.disc.lines)
    }

    /// The A/B/Z levels at t = 0 and every change as a clock of `clock_hz` samples them:
    /// (k, levels from cycle k on), cycle k sampling t_k = k/clock_hz, an edge at t being
    /// seen from the first t_k ≥ t (as [`crate::ideal::plant::ClockSampler`]); edges in the same
    /// cycle are merged. The compact form of a long run (a revolution at 30 r/min is
    /// 2·10^8 cycles at 100 MHz).
    pub fn clock_changes(
        &self,
        motion: &impl ShaftMotion,
        clock_hz: f64,
    ) -> (Sample, Vec<(u64, Sample)>) {
        let initial = self.initial_levels(motion);
        let mut levels = initial;
        let mut out: Vec<(u64, Sample)> = Vec::new();
        for e in self.edges(motion) {
            let mut k = (e.t * clock_hz).ceil().max(0.0) as u64;
            while (k as f64 / clock_hz) < e.t {
                k += 1;
            }
            while k > 0 && ((k - 1) as f64 / clock_hz) >= e.t {
                k -= 1;
            }
            levels.apply(&e);
            match out.last_mut() {
                Some(last) if last.0 == k => last.1 = levels,
                _ => out.push((k, levels)),
            }
        }
        (initial, out)
    }

    /// (line index m, instant t (s)) of every forward crossing of a whole line x = m.
    /// For a forward motion these are the rising edges of A, with their line numbers.
    pub fn line_crossings(&self, motion: &impl ShaftMotion) -> Vec<(i64, f64)> {
        self.crossings(motion)
            .into_iter()
            .filter(|c| c.forward && c.quarter.rem_euclid(4) == 0)
            .map(|c| (c.quarter.div_euclid(4), c.t))
            .collect()
    }
}

/// The A/B/Z edges of a list of quarter-line crossings on a disc of `lines` lines, with
/// the polarities of [`crate::ideal::plant::edges`]: forward by quarter m ≡ 0 A↑, 1 B↑, 2 A↓,
/// 3 B↓ (backward inverts), Z rising at m ≡ 1 and falling at m ≡ 2 (mod 4K) forwards.
pub fn edges_of(crossings: &[Crossing], lines: u32) -> Vec<Edge> {
    let zperiod = 4 * i64::from(lines);
    let mut out = Vec::with_capacity(crossings.len() + crossings.len() / (2 * lines as usize));
    for c in crossings {
        let (channel, up) = match c.quarter.rem_euclid(4) {
            0 => (Channel::A, true),
            1 => (Channel::B, true),
            2 => (Channel::A, false),
            _ => (Channel::B, false),
        };
        out.push(Edge {
            t: c.t,
            channel,
            rising: up == c.forward,
        });
        match c.quarter.rem_euclid(zperiod) {
            1 => out.push(Edge {
                t: c.t,
                channel: Channel::Z,
                rising: c.forward,
            }),
            2 => out.push(Edge {
                t: c.t,
                channel: Channel::Z,
                rising: !c.forward,
            }),
            _ => {}
        }
    }
    out
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
    {
        let mut probe = |t: f64, lo: &mut f64, xlo: &mut f64| -> Option<f64> {
            if !(t > *lo && t < hi) {
                return None;
            }
            let xt = x(t);
            if is_new(xt) {
                hi = t;
            } else {
                (*lo, *xlo) = (t, xt);
            }
            Some(xt)
        };
        // Two Newton steps from lo put the root within a few ulps; probing both sides of
        // it then leaves only a few bisection steps.
        let mut t = lo + (q - xlo) / v(lo);
        let mut step = f64::INFINITY;
        for _ in 0..2 {
            let Some(xt) = probe(t, &mut lo, &mut xlo) else {
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
            probe(t - d, &mut lo, &mut xlo);
            probe(t + d, &mut lo, &mut xlo);
        }
    }
    loop {
        let mid = lo + 0.5 * (hi - lo);
        if mid <= lo || mid >= hi {
            return (hi, lo, xlo);
        }
        let xm = x(mid);
        if is_new(xm) {
            hi = mid;
        } else {
            (lo, xlo) = (mid, xm);
        }
    }
}
