// SPDX-License-Identifier: MIT OR Apache-2.0
//! Named scenarios: shaft motions stated in units of the estimator, so that one scenario
//! means the same thing at any clock, line count and dt.
//!
//! Speeds are in units of ω_lim (r = ω/ω_lim: r > 1 is Rairán's "high speed"), times in
//! units of the nominal dt. Each scenario starts at an angle that is not on a line edge, so
//! the first pulse comes at an arbitrary phase of the dt time base.

use golden::ideal::plant::{PlantError, Profile, Segment};
use golden::params::Params;
use golden::top::core::CoreInputs;

/// A named shaft motion.
pub struct Scenario {
    /// Name used on the command line.
    pub name: &'static str,
    /// One line for `encspeed simulate --list`.
    pub description: &'static str,
    /// Segments in (speed in ω_lim, duration in dt) units.
    segments: &'static [Seg],
}

/// A segment in estimator units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seg {
    /// r for n dt.
    Hold(f64, f64),
    /// r0 → r1 linearly over n dt.
    Ramp(f64, f64, f64),
    /// mean r, amplitude r, period in dt, for n dt.
    Sine(f64, f64, f64, f64),
    /// Standing still for n dt.
    Rest(f64),
}

/// Initial angle, in lines: a third of the way into a line, so no edge falls on t = 0.
const START_PHASE_LINES: f64 = 0.3;

const ALL: &[Scenario] = &[
    Scenario {
        name: "constant-high",
        description: "constant speed 3.3 ω_lim (Nep1 = 4, Ndt1 = 1) for 12 dt",
        segments: &[Seg::Hold(3.3, 12.0)],
    },
    Scenario {
        name: "constant-low",
        description: "constant speed 0.4 ω_lim (Nep1 = 1, Ndt1 = 2) for 16 dt",
        segments: &[Seg::Hold(0.4, 16.0)],
    },
    Scenario {
        name: "start-from-rest",
        description: "at rest for 3 dt, ramp 0 → 2.5 ω_lim over 10 dt, hold 5 dt",
        segments: &[
            Seg::Rest(3.0),
            Seg::Ramp(0.0, 2.5, 10.0),
            Seg::Hold(2.5, 5.0),
        ],
    },
    Scenario {
        name: "stop",
        description: "2.5 ω_lim for 5 dt, abrupt stop, at rest for 20 dt",
        segments: &[Seg::Hold(2.5, 5.0), Seg::Rest(20.0)],
    },
    Scenario {
        name: "speed-steps",
        description: "steps 0.5 → 3 → 1.5 → 8 → 0.2 ω_lim, 6 dt each",
        segments: &[
            Seg::Hold(0.5, 6.0),
            Seg::Hold(3.0, 6.0),
            Seg::Hold(1.5, 6.0),
            Seg::Hold(8.0, 6.0),
            Seg::Hold(0.2, 6.0),
        ],
    },
    Scenario {
        name: "reversal",
        description: "2 ω_lim ramping through zero to −2 ω_lim over 12 dt, hold 4 dt",
        segments: &[
            Seg::Hold(2.0, 4.0),
            Seg::Ramp(2.0, -2.0, 12.0),
            Seg::Hold(-2.0, 4.0),
        ],
    },
    Scenario {
        name: "sine",
        description: "3 ± 1 ω_lim, period 10 dt, for 30 dt",
        segments: &[Seg::Sine(3.0, 1.0, 10.0, 30.0)],
    },
];

/// Every named scenario.
pub fn all() -> &'static [Scenario] {
    ALL
}

/// The scenario called `name`.
pub fn find(name: &str) -> Option<&'static Scenario> {
    ALL.iter().find(|s| s.name == name)
}

/// Parse a motion given on the command line: comma-separated segments
/// `hold:R:N`, `ramp:R0:R1:N`, `sine:MEAN:AMP:PERIOD:N`, `rest:N`, with speeds in ω_lim and
/// times in dt (e.g. `rest:2,ramp:0:3:10,hold:3:5`).
pub fn parse_motion(text: &str) -> Result<Vec<Seg>, String> {
    text.split(',')
        .map(|part| {
            let f: Vec<&str> = part.trim().split(':').collect();
            let nums: Vec<f64> = f[1..]
                .iter()
                .map(|x| {
                    x.parse::<f64>()
                        .map_err(|_| format!("`{x}` in `{part}` is not a number"))
                })
                .collect::<Result<_, _>>()?;
            let seg = match (f[0], nums.as_slice()) {
                ("hold", [r, n]) => Seg::Hold(*r, *n),
                ("ramp", [a, b, n]) => Seg::Ramp(*a, *b, *n),
                ("sine", [m, a, per, n]) => Seg::Sine(*m, *a, *per, *n),
                ("rest", [n]) => Seg::Rest(*n),
                _ => {
                    return Err(format!(
                    "`{part}`: expected hold:R:N, ramp:R0:R1:N, sine:MEAN:AMP:PERIOD:N or rest:N"
                ))
                }
            };
            Ok(seg)
        })
        .collect()
}

/// The shaft motion of `segments` for parameters `p` (rev/s and s). Invalid durations or
/// speeds are reported by the plant.
pub fn profile(segments: &[Seg], p: &Params) -> Result<Profile, PlantError> {
    let w = p.omega_lim_rps();
    let dt = p.dt_s();
    let segments = segments
        .iter()
        .map(|s| match *s {
            Seg::Hold(r, n) => Segment::Constant {
                speed: r * w,
                duration: n * dt,
            },
            Seg::Ramp(r0, r1, n) => Segment::Ramp {
                from: r0 * w,
                to: r1 * w,
                duration: n * dt,
            },
            Seg::Sine(m, a, period, n) => Segment::Sine {
                mean: m * w,
                amplitude: a * w,
                freq_hz: 1.0 / (period * dt),
                duration: n * dt,
            },
            Seg::Rest(n) => Segment::Stop { duration: n * dt },
        })
        .collect();
    Profile::new(START_PHASE_LINES / p.lines() as f64, segments)
}

impl Scenario {
    /// The motion in estimator units.
    pub fn segments(&self) -> &'static [Seg] {
        self.segments
    }

    /// The shaft motion for parameters `p` (rev/s and s).
    pub fn profile(&self, p: &Params) -> Result<Profile, PlantError> {
        profile(self.segments, p)
    }

    /// Per-cycle inputs of this scenario at the nominal dt.
    pub fn inputs(&self, p: &Params) -> Result<Vec<CoreInputs>, PlantError> {
        crate::stimulus::from_profile(p, &self.profile(p)?, p.dt_cycles())
    }
}
