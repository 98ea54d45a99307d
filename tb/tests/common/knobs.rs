// SPDX-License-Identifier: MIT OR Apache-2.0
//! The front-end benches' stimulus knobs: a seeded xorshift generator (the proptest input is
//! the seed, the length and the knobs), so that one case is a few hundred to a few thousand
//! cycles without proptest holding a vector per cycle.

use proptest::prelude::*;

/// xorshift64* generator.
pub struct Rng(u64);

impl Rng {
    /// A generator seeded from `seed`.
    pub fn new(seed: u64) -> Rng {
        Rng(seed ^ 0x9e37_79b9_7f4a_7c15 | 1)
    }
    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in 0..n.
    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    /// True with probability num/den.
    pub fn chance(&mut self, num: u64, den: u64) -> bool {
        self.below(den) < num
    }
}

/// Knobs of one random case.
#[derive(Clone, Copy, Debug)]
pub struct Knobs {
    /// Seed of the case's [`Rng`].
    pub seed: u64,
    /// Length in cycles.
    pub cycles: usize,
    /// Mean cycles between random resets (after the reset at cycle 0).
    pub reset_every: u64,
    /// Mean cycles between configuration changes.
    pub cfg_every: u64,
}

/// Random knobs: 200..3000 cycles, resets every 100..3000, configuration changes every
/// 50..2000 cycles on average.
pub fn knobs() -> impl Strategy<Value = Knobs> {
    (any::<u64>(), 200usize..3000, 100u64..3000, 50u64..2000).prop_map(
        |(seed, cycles, reset_every, cfg_every)| Knobs {
            seed,
            cycles,
            reset_every,
            cfg_every,
        },
    )
}

/// The 200 cases of the coverage tests: 2000 cycles each, rare resets and changes.
pub fn coverage_cases() -> Vec<Knobs> {
    (0..200)
        .map(|seed| Knobs {
            seed,
            cycles: 2000,
            reset_every: 3000,
            cfg_every: 1000,
        })
        .collect()
}

/// Cases concatenated for one Icarus replay per block (each starts with a reset).
pub fn icarus_cases() -> impl Iterator<Item = Knobs> {
    (0..120u64).map(|seed| {
        let mut r = Rng::new(seed ^ 0x1ca2_0000);
        Knobs {
            seed: r.next(),
            cycles: 200 + r.below(2800) as usize,
            reset_every: 100 + r.below(2900),
            cfg_every: 50 + r.below(1950),
        }
    })
}
