// SPDX-License-Identifier: MIT OR Apache-2.0
//! Per-cycle input sequences for the core: from the plant (a shaft motion profile sampled
//! at the clock) or from random waveforms.

use golden::ideal::plant::{edges, ClockSampler, Disc, PlantError, Profile};
use golden::params::Params;
use golden::top::core::CoreInputs;

/// Cycles of reset applied at the start of every plant-driven run.
pub const RESET_CYCLES: usize = 3;

/// The inputs that a disc of `p.lines()` lines moving as `profile` produces at every clock
/// cycle, with `cfg_dt` held at `cfg_dt` and reset for the first [`RESET_CYCLES`] cycles.
/// Cycle k carries the levels at t = k / clock_hz.
pub fn from_profile(
    p: &Params,
    profile: &Profile,
    cfg_dt: u64,
) -> Result<Vec<CoreInputs>, PlantError> {
    let disc = Disc::new(p.lines())?;
    let e = edges(profile, &disc);
    let sampler = ClockSampler::for_profile(profile, &disc, &e, p.clock_hz())?;
    Ok(sampler
        .enumerate()
        .map(|(k, s)| CoreInputs {
            reset: k < RESET_CYCLES,
            enc_a: s.a,
            enc_b: s.b,
            enc_z: s.z,
            cfg_dt,
            ..CoreInputs::default()
        })
        .collect())
}

/// A square wave on A of exactly `period` cycles (high for the first half), B a quarter
/// period behind, after [`RESET_CYCLES`] of reset: a constant speed of dt/period × ω_lim
/// with pulse instants on exact clock edges, for hand-checkable known answers.
pub fn square_wave(period: u64, phase: u64, cycles: usize, cfg_dt: u64) -> Vec<CoreInputs> {
    assert!(period >= 2, "period must be at least 2 cycles");
    (0..cycles)
        .map(|k| {
            let m = (k as u64 + phase) % period;
            CoreInputs {
                reset: k < RESET_CYCLES,
                enc_a: m < period / 2,
                enc_b: (m + period - period / 4) % period < period / 2,
                enc_z: false,
                cfg_dt,
                ..CoreInputs::default()
            }
        })
        .collect()
}
