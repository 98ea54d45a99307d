// SPDX-License-Identifier: MIT OR Apache-2.0
//! The baseline counters' stimulus (`PcCounter`, `EtTimer`, `MtCounter`): a stream of
//! encoder steps in segments of 32..512 cycles, each with its own step rate (none at all,
//! for stalls that saturate the 8-bit counters, up to a step on every cycle), its own
//! reversal rate and sometimes a new `cfg_dt` (0, 1, 2, small, or up to 2^N − 1, which
//! saturates the PC count), with random resets.

use super::SplitMix;

/// One cycle of stimulus, shared by the three blocks (`EtTimer` ignores `cfg_dt`).
#[derive(Clone, Copy, Debug, Default)]
pub struct Cycle {
    /// Synchronous reset.
    pub reset: bool,
    /// A decoder step.
    pub step: bool,
    /// Its direction.
    pub forward: bool,
    /// With `step`, the decoder's `first`: no step since the last reset, or a step against
    /// the last one (set by [`mark_first`] from the cycles before).
    pub first: bool,
    /// dt in cycles (N bits).
    pub cfg_dt: u64,
}

/// A reproducible stimulus of `len` cycles for N = `bits` from `seed`.
pub fn stimulus(seed: u64, bits: u32, len: usize) -> Vec<Cycle> {
    let mut rng = SplitMix(seed);
    let max = (1u64 << bits) - 1;
    let mut out = Vec::with_capacity(len);
    let (mut rate, mut flip, mut dt, mut left, mut forward) = (0u64, 0u64, 5u64, 0u64, true);
    let reset_first = rng.next().is_multiple_of(2);
    while out.len() < len {
        if left == 0 {
            left = 32 + rng.next() % 480;
            rate = [0, 5, 50, 300, 700, 1000][(rng.next() % 6) as usize];
            flip = [0, 20, 500][(rng.next() % 3) as usize];
            if rng.next().is_multiple_of(3) || out.is_empty() {
                dt = match rng.next() % 8 {
                    0 => 0,
                    1 => 1,
                    2 => 2,
                    3 => max,
                    4 => max - rng.next() % 4,
                    5 => rng.next() & max,
                    _ => 2 + rng.next() % 40,
                } & max;
            }
        }
        left -= 1;
        let step = rng.next() % 1000 < rate;
        if step && rng.next() % 1000 < flip {
            forward = !forward;
        }
        out.push(Cycle {
            reset: (out.is_empty() && reset_first) || rng.next().is_multiple_of(1500),
            step,
            forward: if step {
                forward
            } else {
                rng.next().is_multiple_of(2)
            },
            cfg_dt: dt,
            first: false,
        });
    }
    mark_first(&mut out);
    out
}

/// The decoder's `first` for each cycle of (reset, step, forward): a step with no step since
/// the last reset, or against the direction of the last step. A reset cycle's step is not
/// made.
pub fn first_steps(cycles: impl IntoIterator<Item = (bool, bool, bool)>) -> Vec<bool> {
    let mut last: Option<bool> = None;
    cycles
        .into_iter()
        .map(|(reset, step, forward)| {
            let first = step && last != Some(forward);
            if reset {
                last = None;
            } else if step {
                last = Some(forward);
            }
            first
        })
        .collect()
}

/// Sets each cycle's `first` as the decoder makes it ([`first_steps`]).
pub fn mark_first(cycles: &mut [Cycle]) {
    let firsts = first_steps(cycles.iter().map(|c| (c.reset, c.step, c.forward)));
    for (c, first) in cycles.iter_mut().zip(firsts) {
        c.first = first;
    }
}

/// Many stimulus cases back to back (a reset between them).
pub fn long_stimulus(seed: u64, bits: u32, cases: u64) -> Vec<Cycle> {
    let mut out = vec![];
    for i in 0..cases {
        let mut s = stimulus(seed.wrapping_add(i), bits, 1500);
        s[0].reset = true;
        out.extend(s);
    }
    mark_first(&mut out);
    out
}

/// Drives a block (`hw`: one edge of the rust-hdl simulation) and its bit-true model
/// (`model`) with `cycles`, comparing their outputs after every edge; the first difference
/// fails with the counter width `bits`, the edge and its inputs.
pub fn compare_each_edge<O: PartialEq + std::fmt::Debug>(
    bits: usize,
    cycles: &[Cycle],
    mut hw: impl FnMut(&Cycle) -> O,
    mut model: impl FnMut(&Cycle) -> O,
) -> Result<(), proptest::test_runner::TestCaseError> {
    for (k, c) in cycles.iter().enumerate() {
        let want = model(c);
        proptest::prop_assert_eq!(hw(c), want, "N = {}, edge {}, {:?}", bits, k, c);
    }
    Ok(())
}

/// The rust-hdl runs of each baseline counter's bench, `$compare::<N>(&stimulus(..))` for
/// the bench's comparison function: 300 proptest cases at N = 8 (where the stimulus
/// saturates the counters), and 40 at N = 24 (the width the docs quote) and N = 2 (the
/// narrowest).
#[allow(unused_macros)]
macro_rules! counter_proptests {
    ($compare:ident) => {
        ::proptest::proptest! {
            #![proptest_config($crate::common::proptest_config(300))]

            #[test]
            fn rust_hdl_equals_model_n8(seed in ::proptest::prelude::any::<u64>(), len in 200usize..2000) {
                $compare::<8>(&$crate::common::steps::stimulus(seed, 8, len))?;
            }
        }

        ::proptest::proptest! {
            #![proptest_config($crate::common::proptest_config(40))]

            #[test]
            fn rust_hdl_equals_model_n24_and_n2(seed in ::proptest::prelude::any::<u64>(), len in 200usize..2000) {
                $compare::<24>(&$crate::common::steps::stimulus(seed, 24, len))?;
                $compare::<2>(&$crate::common::steps::stimulus(seed, 2, len))?;
            }
        }
    };
}
#[allow(unused_imports)]
pub(crate) use counter_proptests;
