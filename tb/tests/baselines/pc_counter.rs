// SPDX-License-Identifier: MIT OR Apache-2.0
//! `PcCounter` (the PC baseline's count of signed steps per dt window) against its bit-true
//! model (`golden::baselines::pc_counter`), every cycle: the rust-hdl simulation (direct
//! drive) on proptest stimuli at N = 8, 24 and 2, and the emitted Verilog
//! in Icarus Verilog at N = 8 and 24 (a self-checking replay bench written under `target/`
//! at test time, ending in one `RESULT PASS`/`RESULT FAIL` line that the test asserts).
//!
//! Stimuli: `common::steps`, shared with the other baseline counters.

use crate::common::{
    self,
    steps::{self, long_stimulus, Cycle},
};
use golden::baselines::pc_counter::{PcCounter as PcModel, PcInputs, PcOutputs};
use hdl::{pc_counter_verilog, PcCounter};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn pc_step<const N: usize>(uut: &mut PcCounter<N>, c: &Cycle) -> PcOutputs {
    uut.reset.next = c.reset;
    uut.step.next = c.step;
    uut.forward.next = c.forward;
    uut.backward.next = c.step && !c.forward;
    uut.cfg_dt.next = c.cfg_dt.into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    let raw = uut.count.val().to_u64();
    // Sign-extend the N-bit two's complement count.
    let count = ((raw << (64 - N)) as i64) >> (64 - N);
    PcOutputs {
        count,
        saturated: uut.saturated.val(),
        strobe: uut.strobe.val(),
    }
}

fn pc_inputs(c: &Cycle) -> PcInputs {
    PcInputs {
        reset: c.reset,
        step: c.step,
        forward: c.forward,
        cfg_dt: c.cfg_dt,
    }
}

fn compare_pc<const N: usize>(cycles: &[Cycle]) -> Result<(), TestCaseError> {
    let mut uut = PcCounter::<N>::default();
    uut.connect_all();
    let mut model = PcModel::new(N as u32);
    steps::compare_each_edge(
        N,
        cycles,
        |c| pc_step(&mut uut, c),
        |c| model.step(pc_inputs(c)),
    )
}

steps::counter_proptests!(compare_pc);

fn pc_icarus<const N: usize>(seed: u64) {
    let mut model = PcModel::new(N as u32);
    let (mut vectors, mut strobes) = (String::new(), 0);
    let (mut saturated_up, mut saturated_down) = (0, 0);
    let mask = (1u64 << N) - 1;
    for c in long_stimulus(seed, N as u32, 40) {
        let o = model.step(pc_inputs(&c));
        strobes += usize::from(o.strobe);
        saturated_up += usize::from(o.strobe && o.saturated && o.count > 0);
        saturated_down += usize::from(o.strobe && o.saturated && o.count < 0);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.step),
            u8::from(c.forward),
            u8::from(c.step && !c.forward),
            c.cfg_dt,
            (o.count as u64) & mask,
            u8::from(o.saturated),
            u8::from(o.strobe)
        );
    }
    if N == 8 {
        // Both clamps: the count's top bit is rebuilt from the carry and the borrow.
        assert!(
            saturated_up > 0,
            "the stimulus must saturate the count upwards"
        );
        assert!(
            saturated_down > 0,
            "the stimulus must saturate the count downwards"
        );
    }
    let tb = common::replay_bench(
        "pc_counter",
        &[
            ("reset", 1),
            ("step", 1),
            ("forward", 1),
            ("backward", 1),
            ("cfg_dt", N),
        ],
        &[("count", N), ("saturated", 1), ("strobe", 1)],
        "strobe",
    );
    let v = pc_counter_verilog::<N>("pc_counter");
    assert!(strobes > 50, "too few results in the stimulus");
    common::replay(
        "baseline_counters",
        &format!("pc_n{N}"),
        "pc_counter",
        &v,
        &tb,
        &vectors,
        strobes,
    );
}

#[test]
fn emitted_verilog_in_icarus_equals_model() {
    pc_icarus::<8>(0x9c_0008);
    pc_icarus::<24>(0x9c_0024);
}
