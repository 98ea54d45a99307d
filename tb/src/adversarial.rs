// SPDX-License-Identifier: MIT OR Apache-2.0
//! Adversarial per-cycle stimuli for `encspeed_core`: quadrature motion at up to the
//! maximum edge rate, bursts with reversals, stops past the timeout, glitches on A/B/Z
//! shorter and longer than the filter, illegal transitions, index pulses at random and at
//! the revolution mark, configuration changes at run time, `clear_faults` pulses and
//! resets (the only time `cfg_mode` changes).
//!
//! Two layers:
//! - [`Stim`] writes a waveform step by step (`steps`, `glitch`, `illegal`, `reset`, …),
//!   keeping the quadrature state, so that a motion is a legal Gray sequence wherever the
//!   test did not ask for an illegal one. Tests use it to build exact situations.
//! - [`Case`] is a random stimulus: a starting configuration and a list of [`Chunk`]s, each
//!   decoded from a tuple of random words ([`Words`]) by [`Chunk::decode`]. The decoding
//!   is pure, so any source of random numbers can drive it; the property tests feed it
//!   proptest's `any::<Words>()`, whose shrinking (words towards 0, fewer chunks) then
//!   shrinks the stimulus (chunk kind 0 is the plainest one, a short stop). This module
//!   does not depend on proptest, which is a dev-dependency of this crate.
//!
//! Small parameter sets ([`params8`], [`params12`], [`params16`]) make every behaviour
//! (updates, replaced updates, the timeout, Cdt saturation, revolutions) happen within a
//! few thousand cycles.

use golden::params::{Params, Spec};
use golden::top::core::CoreInputs;

/// Cycles of reset at the start of every [`Stim`].
pub const START_RESET_CYCLES: usize = 3;

/// 8-bit counters, 16 lines (a revolution is 16/32/64 steps in x1/x2/x4), dt = 20 cycles,
/// timeout 12 dt: timeouts after 240 cycles, Cdt saturation after 255 dt, revolutions
/// within a few hundred cycles at full rate.
pub fn params8() -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 16,
        dt_cycles: 20,
        counter_bits: 8,
        timeout_s: 12.0 * 20.0 / 1e6,
        ..Spec::default()
    })
    .expect("valid 8-bit test parameters")
}

/// 12-bit counters, 25 lines, dt = 100 cycles, timeout 10 dt.
pub fn params12() -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 25,
        dt_cycles: 100,
        counter_bits: 12,
        timeout_s: 10.0 * 100.0 / 1e6,
        ..Spec::default()
    })
    .expect("valid 12-bit test parameters")
}

/// 16-bit counters, 50 lines, dt = 200 cycles, timeout 12 dt (plant-driven runs).
pub fn params16() -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 50,
        dt_cycles: 200,
        counter_bits: 16,
        timeout_s: 12.0 * 200.0 / 1e6,
        ..Spec::default()
    })
    .expect("valid 16-bit test parameters")
}

/// The effective dt (clock cycles) the core uses for a `cfg_dt` value: 0 is the
/// generation default, 1 is used as 2 (see `golden::top::core`).
pub fn dt_eff(p: &Params, cfg_dt: u64) -> u64 {
    match cfg_dt {
        0 => p.dt_cycles(),
        1 => 2,
        d => d,
    }
}

/// Ranges of the random values for one parameter set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Knobs {
    /// Lines per revolution (for the index at the revolution mark).
    pub lines: u32,
    /// Largest value of a counter (`cfg_dt` and `cfg_timeout` must fit).
    pub counter_max: u64,
    /// Largest ordinary `cfg_dt` drawn (besides 0, 1 and 2).
    pub max_dt: u64,
    /// Largest ordinary `cfg_timeout` drawn (besides 0 and the counter maximum).
    pub max_timeout: u64,
    /// Chunks are added until the stimulus is at least this long; then it stops.
    pub max_cycles: usize,
}

impl Knobs {
    /// Knobs for `p`: dt up to 300 cycles (so that updates come every few hundred cycles
    /// and, below the speed calculator's latency, replace each other), timeouts up to 20
    /// dt, stimuli of about `max_cycles` cycles.
    pub fn for_params(p: &Params, max_cycles: usize) -> Knobs {
        Knobs {
            lines: p.lines(),
            counter_max: p.counter_max(),
            max_dt: p.counter_max().min(300),
            max_timeout: p.counter_max().min(20),
            max_cycles,
        }
    }

    /// A `cfg_dt` from a random word: 0 (default), 1 (illegal, used as 2), 2, 3..=30, or
    /// up to `max_dt`.
    pub fn dt(&self, w: u16) -> u64 {
        let v = u64::from(w >> 3);
        match w % 8 {
            0 => 0,
            1 => 1,
            2 => 2,
            3 | 4 => 3 + v % 28,
            _ => 3 + v % (self.max_dt - 2),
        }
    }

    /// A `cfg_timeout` from a random word: 0 (default), 1, 2..=`max_timeout`, or the
    /// counter maximum (reached only when Cdt saturates).
    pub fn timeout(&self, w: u16) -> u64 {
        let v = u64::from(w >> 3);
        match w % 8 {
            0 | 1 => 0,
            2 => 1,
            7 => self.counter_max,
            _ => 2 + v % (self.max_timeout - 1),
        }
    }

    /// A `cfg_filter` from a random word: mostly 0..=8 (against motions with 1..=24
    /// cycles per state), sometimes up to 40, rarely up to 300.
    pub fn filter(&self, w: u16) -> u64 {
        let v = u64::from(w >> 4);
        match w % 16 {
            0..=5 => v % 4,
            6..=12 => v % 9,
            13 | 14 => v % 41,
            _ => v % 301,
        }
    }
}

/// `cfg_mode` from a random word: x1, x2, x4 three times in ten each, the invalid 3 once.
pub fn mode(w: u8) -> u8 {
    match w % 10 {
        0..=2 => 0,
        3..=5 => 1,
        6..=8 => 2,
        _ => 3,
    }
}

/// An encoder channel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channel {
    /// A.
    A,
    /// B.
    B,
    /// Index Z.
    Z,
}

/// The configuration ports other than `cfg_mode`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Cfg {
    /// `cfg_dt`.
    pub dt: u64,
    /// `cfg_timeout`.
    pub timeout: u64,
    /// `cfg_filter`.
    pub filter: u64,
    /// `cfg_z_mode`.
    pub z_mode: u8,
}

/// Writes a waveform cycle by cycle. The shaft angle is kept in quarter lines (the
/// quadrature state): forward is (A, B) = 10 → 11 → 01 → 00 → 10, as `golden::ideal::plant`;
/// the index at the revolution mark is high in quarter 1 of each revolution, also as the
/// plant.
#[derive(Clone, Debug)]
pub struct Stim {
    lines: i64,
    cur: CoreInputs,
    quarter: i64,
    auto_z: bool,
    out: Vec<CoreInputs>,
}

impl Stim {
    /// A waveform that begins with [`START_RESET_CYCLES`] of reset with `cfg_mode` =
    /// `mode`, configuration `cfg`, the shaft at quarter 0 (A high, B low) and the index
    /// low (`auto_z`: at the revolution mark).
    pub fn new(lines: u32, mode: u8, cfg: Cfg, auto_z: bool) -> Stim {
        let mut s = Stim {
            lines: i64::from(lines),
            cur: CoreInputs {
                cfg_dt: cfg.dt,
                cfg_timeout: cfg.timeout,
                cfg_filter: cfg.filter,
                cfg_mode: mode,
                cfg_z_mode: cfg.z_mode,
                ..CoreInputs::default()
            },
            quarter: 0,
            auto_z,
            out: vec![],
        };
        s.set_levels_from_quarter();
        s.reset_with_mode(START_RESET_CYCLES, mode);
        s
    }

    fn set_levels_from_quarter(&mut self) {
        let q = self.quarter.rem_euclid(4);
        self.cur.enc_a = q < 2;
        self.cur.enc_b = q == 1 || q == 2;
        if self.auto_z {
            self.cur.enc_z = self.quarter.rem_euclid(4 * self.lines) == 1;
        }
    }

    /// The quarter of the current A/B levels nearest to the tracked angle (after levels
    /// were forced, the angle follows them).
    fn resync_quarter(&mut self) {
        let q = match (self.cur.enc_a, self.cur.enc_b) {
            (true, false) => 0,
            (true, true) => 1,
            (false, true) => 2,
            (false, false) => 3,
        };
        let d = (q - self.quarter.rem_euclid(4)).rem_euclid(4);
        self.quarter += if d == 3 { -1 } else { d };
    }

    /// Cycles written so far.
    pub fn len(&self) -> usize {
        self.out.len()
    }

    /// Nothing written yet (never true after [`Stim::new`]).
    pub fn is_empty(&self) -> bool {
        self.out.is_empty()
    }

    /// The inputs the next cycle would carry.
    pub fn current(&self) -> CoreInputs {
        self.cur
    }

    /// The shaft angle in quarter lines (forward positive).
    pub fn quarter(&self) -> i64 {
        self.quarter
    }

    /// The waveform so far.
    pub fn inputs(&self) -> &[CoreInputs] {
        &self.out
    }

    /// The waveform.
    pub fn finish(self) -> Vec<CoreInputs> {
        self.out
    }

    /// Hold the current inputs for `cycles` cycles.
    pub fn hold(&mut self, cycles: usize) {
        self.out.extend(std::iter::repeat_n(self.cur, cycles));
    }

    /// `reset` high for `cycles` cycles, levels and configuration held.
    pub fn reset(&mut self, cycles: usize) {
        let m = self.cur.cfg_mode;
        self.reset_with_mode(cycles, m);
    }

    /// `reset` high for `cycles` ≥ 1 cycles with `cfg_mode` changed to `mode` from the first
    /// of them (the core's rule: change the mode only while reset is high).
    pub fn reset_with_mode(&mut self, cycles: usize, mode: u8) {
        assert!(cycles >= 1, "a mode change needs at least one reset cycle");
        self.cur.cfg_mode = mode;
        let r = CoreInputs {
            reset: true,
            ..self.cur
        };
        self.out.extend(std::iter::repeat_n(r, cycles));
    }

    /// `count` quadrature state changes in one direction, each held `hold` ≥ 1 cycles
    /// (`hold` = 1: the maximum edge rate, a state change every cycle).
    pub fn steps(&mut self, forward: bool, hold: usize, count: usize) {
        for _ in 0..count {
            self.quarter += if forward { 1 } else { -1 };
            self.set_levels_from_quarter();
            self.hold(hold.max(1));
        }
    }

    /// Quadrature state changes with their own directions and hold times.
    pub fn burst(&mut self, moves: &[(bool, usize)]) {
        for &(forward, hold) in moves {
            self.steps(forward, hold, 1);
        }
    }

    /// An illegal transition: A and B toggled in the same cycle (the angle moves two
    /// quarters forward), then held `hold` cycles.
    pub fn illegal(&mut self, hold: usize) {
        self.quarter += 2;
        self.set_levels_from_quarter();
        self.hold(hold.max(1));
    }

    /// Invert `ch` for `width` cycles, restore it, hold `after` cycles.
    pub fn glitch(&mut self, ch: Channel, width: usize, after: usize) {
        let saved = self.cur;
        match ch {
            Channel::A => self.cur.enc_a = !self.cur.enc_a,
            Channel::B => self.cur.enc_b = !self.cur.enc_b,
            Channel::Z => self.cur.enc_z = !self.cur.enc_z,
        }
        self.hold(width);
        self.cur.enc_a = saved.enc_a;
        self.cur.enc_b = saved.enc_b;
        self.cur.enc_z = saved.enc_z;
        self.hold(after);
    }

    /// The index high for `width` cycles, then low for `after` cycles (the shaft at rest).
    pub fn z_pulse(&mut self, width: usize, after: usize) {
        self.cur.enc_z = true;
        self.hold(width);
        self.cur.enc_z = false;
        self.hold(after);
        if self.auto_z {
            self.set_levels_from_quarter();
        }
    }

    /// Arbitrary levels held `cycles` cycles (the angle follows A/B where it can; an index
    /// at the revolution mark is suspended until the next motion).
    pub fn levels(&mut self, a: bool, b: bool, z: bool, cycles: usize) {
        self.cur.enc_a = a;
        self.cur.enc_b = b;
        self.cur.enc_z = z;
        self.resync_quarter();
        self.hold(cycles);
    }

    /// The index follows the revolution mark (true) or stays where it is and is driven only
    /// by [`Stim::z_pulse`], [`Stim::glitch`] and [`Stim::levels`] (false).
    pub fn set_auto_z(&mut self, on: bool) {
        self.auto_z = on;
        if on {
            self.set_levels_from_quarter();
        }
    }

    /// Set `cfg_dt` from the next cycle on.
    pub fn set_dt(&mut self, v: u64) {
        self.cur.cfg_dt = v;
    }

    /// Set `cfg_timeout` from the next cycle on.
    pub fn set_timeout(&mut self, v: u64) {
        self.cur.cfg_timeout = v;
    }

    /// Set `cfg_filter` from the next cycle on.
    pub fn set_filter(&mut self, v: u64) {
        self.cur.cfg_filter = v;
    }

    /// Set `cfg_z_mode` from the next cycle on.
    pub fn set_z_mode(&mut self, v: u8) {
        self.cur.cfg_z_mode = v;
    }

    /// `clear_faults` high for `cycles` cycles, everything else held.
    pub fn clear_faults(&mut self, cycles: usize) {
        let c = CoreInputs {
            clear_faults: true,
            ..self.cur
        };
        self.out.extend(std::iter::repeat_n(c, cycles));
    }
}

/// Four random words, decoded into one [`Chunk`] (or a case header).
pub type Words = (u8, u16, u16, u16);

/// One piece of a random stimulus.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Chunk {
    /// Hold everything for `cycles` (long ones pass the timeout and saturate Cdt).
    Stop { cycles: usize },
    /// `count` state changes in one direction, `hold` cycles each (1 = maximum rate).
    Move {
        forward: bool,
        hold: usize,
        count: usize,
    },
    /// State changes of random direction and 1..=4 cycles each: reversals at full rate.
    Burst(Vec<(bool, usize)>),
    /// A pulse of `width` cycles on one channel, then `after` cycles of rest.
    Glitch {
        ch: Channel,
        width: usize,
        after: usize,
    },
    /// A and B toggled together, then held.
    Illegal { hold: usize },
    /// An index pulse at rest.
    ZPulse { width: usize, after: usize },
    /// The index at the revolution mark on or off.
    AutoZ(bool),
    /// Arbitrary levels held `cycles`.
    Levels {
        a: bool,
        b: bool,
        z: bool,
        cycles: usize,
    },
    /// New `cfg_filter`.
    Filter(u64),
    /// New `cfg_z_mode`.
    ZMode(u8),
    /// New `cfg_dt`.
    Dt(u64),
    /// New `cfg_timeout`.
    Timeout(u64),
    /// `clear_faults` for `cycles`.
    Clear { cycles: usize },
    /// Reset for `cycles`, with a new `cfg_mode` if given.
    Reset { cycles: usize, mode: Option<u8> },
}

impl Chunk {
    /// Decode one chunk from random words. `k` selects the kind with these weights (out of
    /// 256): stop 20, move 60, burst 25, glitch 35, illegal 15, index pulse 10, index mode 8,
    /// raw levels 20, `cfg_filter` 12, `cfg_z_mode` 8, `cfg_dt` 15, `cfg_timeout` 10,
    /// `clear_faults` 10, reset 8.
    pub fn decode(w: Words, knobs: &Knobs) -> Chunk {
        let (k, x, y, z) = w;
        let (xu, yu, zu) = (usize::from(x), usize::from(y), usize::from(z));
        match k {
            0..=19 => Chunk::Stop {
                cycles: if x % 4 == 3 {
                    200 + zu % 4000
                } else {
                    1 + zu % 64
                },
            },
            20..=79 => {
                let (hold, count) = match x % 8 {
                    0 | 1 => (1, 1 + zu % 128),
                    2..=5 => (1 + yu % 8, 1 + zu % 64),
                    6 => (1 + yu % 24, 1 + zu % 64),
                    _ => (24 + yu % 150, 1 + zu % 16),
                };
                Chunk::Move {
                    forward: x & 8 == 0,
                    hold,
                    count,
                }
            }
            80..=104 => Chunk::Burst(
                (0..1 + xu % 16)
                    .map(|i| ((y >> i) & 1 == 1, 1 + ((zu >> (2 * (i % 8))) & 3)))
                    .collect(),
            ),
            105..=139 => Chunk::Glitch {
                ch: match x % 3 {
                    0 => Channel::A,
                    1 => Channel::B,
                    _ => Channel::Z,
                },
                width: 1 + yu % 12,
                after: zu % 64,
            },
            140..=154 => Chunk::Illegal { hold: 1 + yu % 50 },
            155..=164 => Chunk::ZPulse {
                width: 1 + yu % 8,
                after: zu % 32,
            },
            165..=172 => Chunk::AutoZ(x % 2 == 0),
            173..=192 => Chunk::Levels {
                a: x & 1 == 1,
                b: x & 2 == 2,
                z: x & 4 == 4,
                cycles: if y % 2 == 0 { 1 + zu % 4 } else { 1 + zu % 80 },
            },
            193..=204 => Chunk::Filter(knobs.filter(y)),
            205..=212 => Chunk::ZMode((y % 4) as u8),
            213..=227 => Chunk::Dt(knobs.dt(y)),
            228..=237 => Chunk::Timeout(knobs.timeout(y)),
            238..=247 => Chunk::Clear { cycles: 1 + yu % 3 },
            _ => Chunk::Reset {
                cycles: 1 + yu % 4,
                mode: (x % 4 == 0).then(|| mode((z % 256) as u8)),
            },
        }
    }

    /// Append this chunk to `s`.
    pub fn apply(&self, s: &mut Stim) {
        match self {
            Chunk::Stop { cycles } => s.hold(*cycles),
            Chunk::Move {
                forward,
                hold,
                count,
            } => s.steps(*forward, *hold, *count),
            Chunk::Burst(moves) => s.burst(moves),
            Chunk::Glitch { ch, width, after } => s.glitch(*ch, *width, *after),
            Chunk::Illegal { hold } => s.illegal(*hold),
            Chunk::ZPulse { width, after } => s.z_pulse(*width, *after),
            Chunk::AutoZ(on) => s.set_auto_z(*on),
            Chunk::Levels { a, b, z, cycles } => s.levels(*a, *b, *z, *cycles),
            Chunk::Filter(v) => s.set_filter(*v),
            Chunk::ZMode(v) => s.set_z_mode(*v),
            Chunk::Dt(v) => s.set_dt(*v),
            Chunk::Timeout(v) => s.set_timeout(*v),
            Chunk::Clear { cycles } => s.clear_faults(*cycles),
            Chunk::Reset { cycles, mode } => match mode {
                Some(m) => s.reset_with_mode(*cycles, *m),
                None => s.reset(*cycles),
            },
        }
    }
}

/// A random stimulus: the mode and configuration at the first reset, and the chunks.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Case {
    /// `cfg_mode` at the start (resets may change it).
    pub mode: u8,
    /// Configuration at the start.
    pub cfg: Cfg,
    /// The index starts at the revolution mark.
    pub auto_z: bool,
    /// The chunks, in order.
    pub chunks: Vec<Chunk>,
    /// The knobs the case was decoded with.
    pub knobs: Knobs,
}

impl Case {
    /// Decode a case: `head` gives the mode (its first word), `cfg_dt`, `cfg_timeout`,
    /// `cfg_filter`, `cfg_z_mode` and the index mode; `body` gives the chunks. Chunks past
    /// `knobs.max_cycles` are dropped (so a case never runs far beyond it).
    pub fn decode(head: Words, body: &[Words], knobs: Knobs) -> Case {
        let (m, dt, timeout, f) = head;
        let mut case = Case {
            mode: mode(m),
            cfg: Cfg {
                dt: knobs.dt(dt),
                timeout: knobs.timeout(timeout),
                filter: knobs.filter(f),
                z_mode: ((f >> 12) % 4) as u8,
            },
            auto_z: (m / 10) % 2 == 0,
            chunks: body.iter().map(|w| Chunk::decode(*w, &knobs)).collect(),
            knobs,
        };
        // Drop the chunks that would start past max_cycles.
        let mut s = case.start();
        let keep = case
            .chunks
            .iter()
            .take_while(|c| {
                let more = s.len() < knobs.max_cycles;
                c.apply(&mut s);
                more
            })
            .count();
        case.chunks.truncate(keep);
        case
    }

    /// The stimulus before the first chunk: reset with the starting configuration.
    pub fn start(&self) -> Stim {
        Stim::new(self.knobs.lines, self.mode, self.cfg, self.auto_z)
    }

    /// The stimulus after all chunks, to be continued.
    pub fn stim(&self) -> Stim {
        let mut s = self.start();
        for c in &self.chunks {
            c.apply(&mut s);
        }
        s
    }

    /// The per-cycle inputs.
    pub fn inputs(&self) -> Vec<CoreInputs> {
        self.stim().finish()
    }
}

/// Which `cfg_mode` values appear in `inputs` (bit m set for mode m).
pub fn modes_used(inputs: &[CoreInputs]) -> u8 {
    inputs.iter().fold(0, |acc, i| acc | (1 << i.cfg_mode))
}

/// True if `cfg_mode` changes only in cycles with `reset` high (the core's rule).
pub fn mode_changes_only_in_reset(inputs: &[CoreInputs]) -> bool {
    inputs
        .windows(2)
        .all(|w| w[1].cfg_mode == w[0].cfg_mode || w[1].reset)
}
