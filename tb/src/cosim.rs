// SPDX-License-Identifier: MIT OR Apache-2.0
//! Run the golden model and the rust-hdl simulation on the same inputs, and compare.

use golden::params::Params;
use golden::top::core::{CoreInputs, CoreModel, CoreOutputs};

/// Outputs of the bit-true model, one per cycle.
pub fn run_golden(p: &Params, inputs: &[CoreInputs]) -> Vec<CoreOutputs> {
    let mut m = CoreModel::new(p);
    inputs.iter().map(|i| m.step(*i)).collect()
}

/// Outputs of the rust-hdl simulation (direct drive), one per cycle.
pub fn run_hdl(p: &Params, inputs: &[CoreInputs]) -> Vec<CoreOutputs> {
    let mut sim = hdl::build_core(p);
    inputs.iter().map(|i| sim.step(i)).collect()
}

/// The first cycle at which two output traces differ, with both values; a length
/// difference counts as a mismatch at the shorter length.
pub fn first_mismatch(
    expected: &[CoreOutputs],
    got: &[CoreOutputs],
) -> Option<(usize, Option<CoreOutputs>, Option<CoreOutputs>)> {
    let n = expected.len().max(got.len());
    (0..n).find_map(|k| {
        let (e, g) = (expected.get(k).copied(), got.get(k).copied());
        (e != g).then_some((k, e, g))
    })
}

/// Panic with a readable report if `got` differs from `expected` anywhere.
pub fn assert_same(
    what: &str,
    inputs: &[CoreInputs],
    expected: &[CoreOutputs],
    got: &[CoreOutputs],
) {
    if let Some((k, e, g)) = first_mismatch(expected, got) {
        let from = k.saturating_sub(4);
        let ctx: Vec<String> = (from..=k.min(inputs.len().saturating_sub(1)))
            .map(|j| {
                format!(
                    "  cycle {j}: in {:?}\n    golden {:?}\n    {what} {:?}",
                    inputs[j],
                    expected.get(j),
                    got.get(j)
                )
            })
            .collect();
        panic!(
            "{what} differs from the golden model at cycle {k}: expected {e:?}, got {g:?}\n{}",
            ctx.join("\n")
        );
    }
}
