// SPDX-License-Identifier: MIT OR Apache-2.0
//! `EccN3` against its bit-true model (`golden::ecc::ecc_n3`), every cycle: the rust-hdl
//! simulation on proptest stimuli at S = 25, 41 and 49 (N = 8, 24, 32), and the emitted
//! Verilog in Icarus (self-checking replay bench under `target/`, one `RESULT` line).
//!
//! Stimuli: starts sparse, back to back and while busy; n3 of every size and sign
//! (including 0, ±max and the most negative value); δ mostly within a few steps, sometimes
//! anywhere in its 40 bits; both flags; resets.

use crate::common;

use common::SplitMix;
use golden::ecc::ecc_delta::DELTA_BITS;
use golden::ecc::ecc_n3::{EccN3 as Model, EccN3Inputs, EccN3Outputs};
use hdl::ecc::ecc_n3::{ecc_n3_verilog, EccN3};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn sext(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

fn stimulus(seed: u64, s: u32, len: usize) -> Vec<EccN3Inputs> {
    let mut r = SplitMix(seed);
    let half = 1i64 << (s - 1);
    (0..len)
        .map(|_| {
            let n3 = match r.next() % 8 {
                0 => 0,
                1 => half - 1,
                2 => -half,
                3 => -(half - 1),
                4 => (r.next() % 65_536) as i64, // Nep1 = 1 territory
                _ => sext(r.next(), s),
            };
            let delta = match r.next() % 4 {
                0 => sext(r.next(), DELTA_BITS),
                _ => (r.next() % (1 << 20)) as i64 - (1 << 19),
            };
            EccN3Inputs {
                reset: r.next().is_multiple_of(97),
                start: r.next().is_multiple_of(5),
                n3,
                nep_is_one: r.next().is_multiple_of(2),
                ndt_is_one: r.next().is_multiple_of(2),
                delta,
            }
        })
        .collect()
}

fn hdl_step<const S: usize>(uut: &mut EccN3<S>, c: &EccN3Inputs) -> EccN3Outputs {
    let mask = |bits: u32| {
        if bits == 64 {
            u64::MAX
        } else {
            (1u64 << bits) - 1
        }
    };
    uut.reset.next = c.reset;
    uut.start.next = c.start;
    uut.n3.next = ((c.n3 as u64) & mask(S as u32)).into();
    uut.nep_is_one.next = c.nep_is_one;
    uut.ndt_is_one.next = c.ndt_is_one;
    uut.delta.next = ((c.delta as u64) & mask(DELTA_BITS)).into();
    common::edge(uut, |u, level| u.clock.next = Clock::from(level));
    EccN3Outputs {
        n3c: sext(uut.n3c.val().to_u64(), S as u32),
        valid: uut.valid.val(),
        busy: uut.busy.val(),
    }
}

fn compare<const S: usize>(seed: u64, len: usize) -> Result<(), TestCaseError> {
    let mut uut = EccN3::<S>::default();
    uut.connect_all();
    let mut model = Model::new(S as u32);
    let first = EccN3Inputs {
        reset: true,
        ..EccN3Inputs::default()
    };
    for (i, c) in std::iter::once(first)
        .chain(stimulus(seed, S as u32, len))
        .enumerate()
    {
        let want = model.step(c);
        let got = hdl_step(&mut uut, &c);
        prop_assert_eq!(got, want, "cycle {} inputs {:?}", i, c);
    }
    Ok(())
}

proptest! {
    #![proptest_config(common::proptest_config(24))]
    #[test]
    fn rust_hdl_equals_model_n24(seed in any::<u64>()) {
        compare::<41>(seed, 300)?;
    }

    #[test]
    fn rust_hdl_equals_model_n8_and_n32(seed in any::<u64>()) {
        compare::<25>(seed, 200)?;
        compare::<49>(seed, 200)?;
    }
}

fn icarus<const S: usize>(seed: u64) {
    let s = S as u32;
    let mut model = Model::new(s);
    let (mut vectors, mut valids) = (String::new(), 0);
    let smask = (1u64 << s) - 1;
    let dmask = (1u64 << DELTA_BITS) - 1;
    let first = EccN3Inputs {
        reset: true,
        ..EccN3Inputs::default()
    };
    for c in std::iter::once(first).chain(stimulus(seed, s, 6000)) {
        let o = model.step(c);
        valids += usize::from(o.valid);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.start),
            (c.n3 as u64) & smask,
            u8::from(c.nep_is_one),
            u8::from(c.ndt_is_one),
            (c.delta as u64) & dmask,
            (o.n3c as u64) & smask,
            u8::from(o.valid),
            u8::from(o.busy)
        );
    }
    assert!(valids > 100, "too few results: {valids}");
    let d = DELTA_BITS as usize;
    let tb = common::replay_bench(
        "ecc_n3",
        &[
            ("reset", 1),
            ("start", 1),
            ("n3", S),
            ("nep_is_one", 1),
            ("ndt_is_one", 1),
            ("delta", d),
        ],
        &[("n3c", S), ("valid", 1), ("busy", 1)],
        "valid",
    );
    let v = ecc_n3_verilog::<S>("ecc_n3");
    common::replay(
        "ecc_n3",
        &format!("s{S}"),
        "ecc_n3",
        &v,
        &tb,
        &vectors,
        valids,
    );
}

#[test]
fn emitted_verilog_in_icarus_equals_model() {
    icarus::<41>(0xe3_0041);
    icarus::<25>(0xe3_0025);
    icarus::<49>(0xe3_0049);
}
