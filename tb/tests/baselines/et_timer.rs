// SPDX-License-Identifier: MIT OR Apache-2.0
//! `EtTimer` (the ET baseline's period between steps) against its bit-true model
//! (`golden::baselines::et_timer`), every cycle: the rust-hdl simulation (direct
//! drive) on proptest stimuli at N = 8, 24 and 2, and the emitted Verilog
//! in Icarus Verilog at N = 8 and 24 (a self-checking replay bench written under `target/`
//! at test time, ending in one `RESULT PASS`/`RESULT FAIL` line that the test asserts).
//!
//! Stimuli: `common::steps`, shared with the other baseline counters.

use crate::common::{
    self,
    steps::{self, long_stimulus, Cycle},
};
use golden::baselines::et_timer::{EtInputs, EtOutputs, EtTimer as EtModel};
use hdl::{et_timer_verilog, EtTimer};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn et_step<const N: usize>(uut: &mut EtTimer<N>, c: &Cycle) -> EtOutputs {
    uut.reset.next = c.reset;
    uut.step.next = c.step;
    uut.forward.next = c.forward;
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    EtOutputs {
        period: uut.period.val().to_u64(),
        negative: uut.negative.val(),
        strobe: uut.strobe.val(),
        stalled: uut.stalled.val(),
    }
}

fn et_inputs(c: &Cycle) -> EtInputs {
    EtInputs {
        reset: c.reset,
        step: c.step,
        forward: c.forward,
    }
}

fn compare_et<const N: usize>(cycles: &[Cycle]) -> Result<(), TestCaseError> {
    let mut uut = EtTimer::<N>::default();
    uut.connect_all();
    let mut model = EtModel::new(N as u32);
    steps::compare_each_edge(
        N,
        cycles,
        |c| et_step(&mut uut, c),
        |c| model.step(et_inputs(c)),
    )
}

steps::counter_proptests!(compare_et);

fn et_icarus<const N: usize>(seed: u64) {
    let mut model = EtModel::new(N as u32);
    let (mut vectors, mut strobes, mut stalls) = (String::new(), 0, 0);
    for c in long_stimulus(seed, N as u32, 40) {
        let o = model.step(et_inputs(&c));
        strobes += usize::from(o.strobe);
        stalls += usize::from(o.stalled);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.step),
            u8::from(c.forward),
            o.period,
            u8::from(o.negative),
            u8::from(o.strobe),
            u8::from(o.stalled)
        );
    }
    if N == 8 {
        assert!(stalls > 0, "the stimulus must stall");
    }
    let tb = common::replay_bench(
        "et_timer",
        &[("reset", 1), ("step", 1), ("forward", 1)],
        &[
            ("period", N),
            ("negative", 1),
            ("strobe", 1),
            ("stalled", 1),
        ],
        "strobe",
    );
    let v = et_timer_verilog::<N>("et_timer");
    assert!(strobes > 50, "too few results in the stimulus");
    common::replay(
        "baseline_counters",
        &format!("et_n{N}"),
        "et_timer",
        &v,
        &tb,
        &vectors,
        strobes,
    );
}

#[test]
fn emitted_verilog_in_icarus_equals_model() {
    et_icarus::<8>(0xe7_0008);
    et_icarus::<24>(0xe7_0024);
}
