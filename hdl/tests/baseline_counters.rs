//! `PcCounter`, `EtTimer` and `MtCounter` against their bit-true models
//! (`golden::baselines::pc_counter`, `golden::baselines::et_timer`, `golden::baselines::mt_counter`), every cycle: the
//! rust-hdl simulation (direct drive) on proptest stimuli, and the emitted Verilog in Icarus
//! Verilog (a self-checking replay bench written under `target/` at test time, ending in
//! one `RESULT PASS`/`RESULT FAIL` line that the test asserts).
//!
//! Stimuli come in segments of 32..512 cycles, each with its own step rate (none at all,
//! for stalls that saturate the 8-bit counters, up to a step on every cycle), its own
//! reversal rate and sometimes a new `cfg_dt` (0, 1, 2, small, or up to 2^N − 1, which
//! saturates the PC count), with random resets.

mod common;

use common::SplitMix;
use golden::baselines::et_timer::{EtInputs, EtOutputs, EtTimer as EtModel};
use golden::baselines::mt_counter::{MtCounter as MtModel, MtInputs, MtOutputs};
use golden::baselines::pc_counter::{PcCounter as PcModel, PcInputs, PcOutputs};
use hdl::{
    et_timer_verilog, mt_counter_verilog, pc_counter_verilog, EtTimer, MtCounter, PcCounter,
};
use proptest::prelude::*;
use rust_hdl::prelude::*;

/// One cycle of stimulus, shared by the three blocks (`EtTimer` ignores `cfg_dt`).
#[derive(Clone, Copy, Debug, Default)]
struct Cycle {
    reset: bool,
    step: bool,
    forward: bool,
    cfg_dt: u64,
}

/// A reproducible stimulus of `len` cycles for N = `bits` from `seed`.
fn stimulus(seed: u64, bits: u32, len: usize) -> Vec<Cycle> {
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
        });
    }
    out
}

fn pc_step<const N: usize>(uut: &mut PcCounter<N>, c: &Cycle) -> PcOutputs {
    uut.reset.next = c.reset;
    uut.step.next = c.step;
    uut.forward.next = c.forward;
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

fn mt_step<const N: usize>(uut: &mut MtCounter<N>, c: &Cycle) -> MtOutputs {
    uut.reset.next = c.reset;
    uut.step.next = c.step;
    uut.forward.next = c.forward;
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

fn pc_inputs(c: &Cycle) -> PcInputs {
    PcInputs {
        reset: c.reset,
        step: c.step,
        forward: c.forward,
        cfg_dt: c.cfg_dt,
    }
}

fn et_inputs(c: &Cycle) -> EtInputs {
    EtInputs {
        reset: c.reset,
        step: c.step,
        forward: c.forward,
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

fn compare_pc<const N: usize>(cycles: &[Cycle]) -> Result<(), TestCaseError> {
    let mut uut = PcCounter::<N>::default();
    uut.connect_all();
    let mut model = PcModel::new(N as u32);
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(pc_inputs(c));
        prop_assert_eq!(pc_step(&mut uut, c), want, "N = {}, edge {}, {:?}", N, k, c);
    }
    Ok(())
}

fn compare_et<const N: usize>(cycles: &[Cycle]) -> Result<(), TestCaseError> {
    let mut uut = EtTimer::<N>::default();
    uut.connect_all();
    let mut model = EtModel::new(N as u32);
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(et_inputs(c));
        prop_assert_eq!(et_step(&mut uut, c), want, "N = {}, edge {}, {:?}", N, k, c);
    }
    Ok(())
}

fn compare_mt<const N: usize>(cycles: &[Cycle]) -> Result<(), TestCaseError> {
    let mut uut = MtCounter::<N>::default();
    uut.connect_all();
    let mut model = MtModel::new(N as u32);
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(mt_inputs(c));
        prop_assert_eq!(mt_step(&mut uut, c), want, "N = {}, edge {}, {:?}", N, k, c);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn pc_rust_hdl_equals_model_n8(seed in any::<u64>(), len in 200usize..2000) {
        compare_pc::<8>(&stimulus(seed, 8, len))?;
    }

    #[test]
    fn et_rust_hdl_equals_model_n8(seed in any::<u64>(), len in 200usize..2000) {
        compare_et::<8>(&stimulus(seed, 8, len))?;
    }

    #[test]
    fn mt_rust_hdl_equals_model_n8(seed in any::<u64>(), len in 200usize..2000) {
        compare_mt::<8>(&stimulus(seed, 8, len))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, ..ProptestConfig::default() })]

    /// N = 24 (the width quoted in the docs) and N = 2 (the narrowest).
    #[test]
    fn rust_hdl_equals_model_n24_and_n2(seed in any::<u64>(), len in 200usize..2000) {
        compare_pc::<24>(&stimulus(seed, 24, len))?;
        compare_et::<24>(&stimulus(seed, 24, len))?;
        compare_mt::<24>(&stimulus(seed, 24, len))?;
        compare_pc::<2>(&stimulus(seed, 2, len))?;
        compare_et::<2>(&stimulus(seed, 2, len))?;
        compare_mt::<2>(&stimulus(seed, 2, len))?;
    }
}

/// Many stimulus cases back to back (a reset between them).
fn long_stimulus(seed: u64, bits: u32, cases: u64) -> Vec<Cycle> {
    let mut out = vec![];
    for i in 0..cases {
        let mut s = stimulus(seed.wrapping_add(i), bits, 1500);
        s[0].reset = true;
        out.extend(s);
    }
    out
}

fn pc_icarus<const N: usize>(seed: u64) {
    let mut model = PcModel::new(N as u32);
    let (mut vectors, mut strobes, mut saturated) = (String::new(), 0, 0);
    let mask = (1u64 << N) - 1;
    for c in long_stimulus(seed, N as u32, 40) {
        let o = model.step(pc_inputs(&c));
        strobes += usize::from(o.strobe);
        saturated += usize::from(o.strobe && o.saturated);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.step),
            u8::from(c.forward),
            c.cfg_dt,
            (o.count as u64) & mask,
            u8::from(o.saturated),
            u8::from(o.strobe)
        );
    }
    if N == 8 {
        assert!(saturated > 0, "the stimulus must saturate the count");
    }
    let tb = common::replay_bench(
        "pc_counter",
        &[("reset", 1), ("step", 1), ("forward", 1), ("cfg_dt", N)],
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

fn mt_icarus<const N: usize>(seed: u64) {
    let mut model = MtModel::new(N as u32);
    let (mut vectors, mut strobes, mut negatives) = (String::new(), 0, 0);
    for c in long_stimulus(seed, N as u32, 40) {
        let o = model.step(mt_inputs(&c));
        strobes += usize::from(o.strobe);
        negatives += usize::from(o.strobe && o.negative && o.m > 0);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.step),
            u8::from(c.forward),
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
        &[("reset", 1), ("step", 1), ("forward", 1), ("cfg_dt", N)],
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
fn pc_emitted_verilog_in_icarus_equals_model() {
    pc_icarus::<8>(0x9c_0008);
    pc_icarus::<24>(0x9c_0024);
}

#[test]
fn et_emitted_verilog_in_icarus_equals_model() {
    et_icarus::<8>(0xe7_0008);
    et_icarus::<24>(0xe7_0024);
}

#[test]
fn mt_emitted_verilog_in_icarus_equals_model() {
    mt_icarus::<8>(0x37_0008);
    mt_icarus::<24>(0x37_0024);
}
