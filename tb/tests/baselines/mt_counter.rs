// SPDX-License-Identifier: MIT OR Apache-2.0
//! `MtCounter` (the M/T baseline's steps and cycles per window) against its bit-true model
//! (`golden::baselines::mt_counter`), every cycle: the rust-hdl simulation (direct
//! drive) on proptest stimuli at N = 8, 24 and 2, and the emitted Verilog
//! in Icarus Verilog at N = 8 and 24 (a self-checking replay bench written under `target/`
//! at test time, ending in one `RESULT PASS`/`RESULT FAIL` line that the test asserts).
//!
//! Stimuli: `common::steps`, shared with the other baseline counters.

use crate::common::{
    self,
    steps::{self, long_stimulus, Cycle},
};
use golden::baselines::mt_counter::{MtCounter as MtModel, MtInputs, MtOutputs};
use hdl::{mt_counter_verilog, MtCounter};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn mt_step<const N: usize>(uut: &mut MtCounter<N>, c: &Cycle) -> MtOutputs {
    uut.reset.next = c.reset;
    uut.step.next = c.step;
    uut.forward.next = c.forward;
    uut.first.next = c.first;
    uut.cfg_dt.next = c.cfg_dt.into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    MtOutputs {
        m: uut.m.val().to_u64(),
        t: uut.t.val().to_u64(),
        negative: uut.negative.val(),
        strobe: uut.strobe.val(),
        stalled: uut.stalled.val(),
    }
}

fn mt_inputs(c: &Cycle) -> MtInputs {
    MtInputs {
        reset: c.reset,
        step: c.step,
        forward: c.forward,
        cfg_dt: c.cfg_dt,
    }
}

fn compare_mt<const N: usize>(cycles: &[Cycle]) -> Result<(), TestCaseError> {
    let mut uut = MtCounter::<N>::default();
    uut.connect_all();
    let mut model = MtModel::new(N as u32);
    steps::compare_each_edge(
        N,
        cycles,
        |c| mt_step(&mut uut, c),
        |c| model.step(mt_inputs(c)),
    )
}

steps::counter_proptests!(compare_mt);

fn mt_icarus<const N: usize>(seed: u64) {
    let mut model = MtModel::new(N as u32);
    let (mut vectors, mut strobes, mut negatives) = (String::new(), 0, 0);
    for c in long_stimulus(seed, N as u32, 40) {
        let o = model.step(mt_inputs(&c));
        strobes += usize::from(o.strobe);
        negatives += usize::from(o.strobe && o.negative && o.m > 0);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.step),
            u8::from(c.forward),
            u8::from(c.first),
            c.cfg_dt,
            o.m,
            o.t,
            u8::from(o.negative),
            u8::from(o.strobe),
            u8::from(o.stalled)
        );
    }
    assert!(negatives > 0, "the stimulus must cover reverse");
    let tb = common::replay_bench(
        "mt_counter",
        &[
            ("reset", 1),
            ("step", 1),
            ("forward", 1),
            ("first", 1),
            ("cfg_dt", N),
        ],
        &[
            ("m", N),
            ("t", N),
            ("negative", 1),
            ("strobe", 1),
            ("stalled", 1),
        ],
        "strobe",
    );
    let v = mt_counter_verilog::<N>("mt_counter");
    assert!(strobes > 50, "too few results in the stimulus");
    common::replay(
        "baseline_counters",
        &format!("mt_n{N}"),
        "mt_counter",
        &v,
        &tb,
        &vectors,
        strobes,
    );
}

#[test]
fn emitted_verilog_in_icarus_equals_model() {
    mt_icarus::<8>(0x37_0008);
    mt_icarus::<24>(0x37_0024);
}
