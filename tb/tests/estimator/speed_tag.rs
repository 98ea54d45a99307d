// SPDX-License-Identifier: MIT OR Apache-2.0
//! `SpeedTag` (the request tag carried beside the speed calculator) against its bit-true
//! model, every cycle: the `tag` of `golden::top::core::CoreModel`, a
//! `golden::arith::latest_request::LatestRequest` of the constructor's latency whose result
//! is the request itself, published into held registers (`tag_*`, not cleared by reset) with
//! a one-cycle `valid`. The rust-hdl simulation (direct drive) on proptest stimuli at N = 24
//! with latencies 2, 3, the core's 255, 511 and random ones, and at N = 8 and 32; the
//! emitted Verilog linted by Verilator and replayed in Icarus (a self-checking bench from
//! `common::replay_bench`, written under `target/` at test time); and the latency and the
//! "latest start wins" rule on hand-worked timelines.
//!
//! Stimuli: segments of 16..400 cycles, each with its own request rate (none, rare, about
//! one per latency, every cycle: starts while busy and back to back), positions and counts
//! random with their extremes, and random resets (also mid-computation).
//!
//! A reset on the very edge that would publish publishes nothing: `valid` stays low and
//! `tag_*` keep the previous tag, in the hardware as in the model
//! (`reset_on_the_publishing_edge_keeps_the_last_tag`, and the random stimuli, whose resets
//! fall on publishing edges too; the Icarus replay compares every output on every cycle).

use crate::common::{self, SplitMix};
use golden::arith::latest_request::LatestRequest;
use golden::estimator::speed_calc::SpeedFormat;
use hdl::verilog::named_verilog;
use hdl::SpeedTag;
use proptest::prelude::*;
use rust_hdl::prelude::*;

/// What a request carries: position, Nep1, Ndt1.
type Tag = (u64, u64, u64);

/// One cycle's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct In {
    reset: bool,
    start: bool,
    tag: Tag,
}

/// Outputs after an edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Out {
    tag: Tag,
    valid: bool,
}

/// The model: the core's `tag` and `tag_out` (`golden::top::core`), for one latency.
#[derive(Clone)]
struct Model {
    timing: LatestRequest<Tag, Tag>,
    latency: u32,
    out: Out,
}

impl Model {
    fn new(latency: u32) -> Self {
        Self {
            timing: LatestRequest::new(),
            latency,
            out: Out::default(),
        }
    }

    /// A reset on this edge abandons a request that would publish on it.
    fn reset_drops_a_result(&self, c: &In) -> bool {
        let mut probe = self.clone();
        c.reset && probe.step(&In { reset: false, ..*c }).valid
    }

    fn step(&mut self, c: &In) -> Out {
        self.out.valid = false;
        if let Some(t) = self
            .timing
            .edge(c.start.then_some(c.tag), c.reset, self.latency, |t| t)
        {
            self.out = Out {
                tag: t,
                valid: true,
            };
        }
        self.out
    }
}

fn mask(bits: usize) -> u64 {
    if bits == 64 {
        u64::MAX
    } else {
        (1u64 << bits) - 1
    }
}

/// A reproducible stimulus of `len` cycles for N = `bits` and `latency` from `seed`.
fn stimulus(seed: u64, bits: usize, latency: u32, len: usize) -> Vec<In> {
    let mut rng = SplitMix(seed);
    let n = mask(bits);
    let per_latency = (1000 / u64::from(latency)).max(1);
    let (mut rate, mut left) = (0u64, 0u64);
    let mut out = Vec::with_capacity(len);
    while out.len() < len {
        if left == 0 {
            left = 16 + rng.next() % 384;
            rate = [0, 3, per_latency, 300, 1000][(rng.next() % 5) as usize];
        }
        left -= 1;
        let mut count = || match rng.next() % 6 {
            0 => 0,
            1 => 1,
            2 => n,
            _ => rng.next() & n,
        };
        let (nep, ndt) = (count(), count());
        let position = match rng.next() % 4 {
            0 => u64::from(u32::MAX),
            1 => 0,
            _ => rng.next() & 0xffff_ffff,
        };
        out.push(In {
            // Resets rare against the latency, so that most requests publish.
            reset: rng.next().is_multiple_of(400.max(4 * u64::from(latency))),
            start: rng.next() % 1000 < rate,
            tag: (position, nep, ndt),
        });
    }
    out
}

fn step<const N: usize>(uut: &mut SpeedTag<N>, c: &In) -> Out {
    uut.reset.next = c.reset;
    uut.start.next = c.start;
    uut.position.next = c.tag.0.into();
    uut.nep.next = c.tag.1.into();
    uut.ndt.next = c.tag.2.into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    Out {
        tag: (
            uut.tag_position.val().to_u64(),
            uut.tag_nep.val().to_u64(),
            uut.tag_ndt.val().to_u64(),
        ),
        valid: uut.valid.val(),
    }
}

/// Runs `cycles` (after a reset) through both; the number of tags published.
fn compare<const N: usize>(latency: u32, cycles: &[In]) -> Result<usize, TestCaseError> {
    let mut uut = SpeedTag::<N>::new(latency);
    uut.connect_all();
    let mut model = Model::new(latency);
    let first = In {
        reset: true,
        ..In::default()
    };
    let mut valids = 0;
    for (k, c) in std::iter::once(&first).chain(cycles).enumerate() {
        let want = model.step(c);
        valids += usize::from(want.valid);
        let got = step(&mut uut, c);
        prop_assert!(
            got == want,
            "N {} latency {} edge {} {:?}: got {:?}, model {:?}",
            N,
            latency,
            k,
            c,
            got,
            want
        );
    }
    Ok(valids)
}

/// The core's latency at N = 24, F = 16: the speed calculator's 3(N + F + 1) + 5.
fn core_latency() -> u32 {
    SpeedFormat::new(24, 16).unwrap().latency_cycles()
}

proptest! {
    #![proptest_config(common::proptest_config(64))]

    #[test]
    fn rust_hdl_equals_model_n24(seed in any::<u64>(), pick in 0u32..6, random in 2u32..=255,
                                 len in 200usize..1500) {
        let latency = [2, 3, core_latency(), 511, random, random][pick as usize];
        compare::<24>(latency, &stimulus(seed, 24, latency, len))?;
    }
}

proptest! {
    #![proptest_config(common::proptest_config(24))]

    #[test]
    fn rust_hdl_equals_model_n8_and_n32(seed in any::<u64>(), latency in 2u32..=255) {
        compare::<8>(latency, &stimulus(seed, 8, latency, 800))?;
        compare::<32>(latency, &stimulus(seed ^ 1, 32, latency, 800))?;
    }
}

/// Hand-worked timelines at latency 5: a lone start is published exactly 5 edges after the
/// edge that latched it; starts while busy wait, and only the last of them is computed; a
/// reset abandons the running and the pending request and publishes nothing, and leaves the
/// published tag as it was.
#[test]
fn latency_latest_wins_and_reset_by_hand() {
    const L: u32 = 5;
    let t = |p: u64| (p, p + 1, p + 2);
    let mut cycles = vec![In::default(); 60];
    // Edge 1 latches A: published at edge 1 + 5 = 6.
    cycles[1] = In {
        start: true,
        tag: t(10),
        ..In::default()
    };
    // Edge 10 latches B (it begins at 11, out at 15); C and D arrive while B runs (edges 12,
    // 13): D replaces C, begins at edge 16, the edge after B is out, and is out at 20.
    for (edge, p) in [(10, 20), (12, 30), (13, 40)] {
        cycles[edge] = In {
            start: true,
            tag: t(p),
            ..In::default()
        };
    }
    // E at edge 30, reset at edge 32: nothing more.
    cycles[30] = In {
        start: true,
        tag: t(50),
        ..In::default()
    };
    cycles[32].reset = true;
    let mut want = vec![Out::default(); 60];
    let mut held = Out::default();
    for (k, w) in want.iter_mut().enumerate() {
        let published = match k {
            6 => Some(t(10)),
            15 => Some(t(20)),
            20 => Some(t(40)),
            _ => None,
        };
        if let Some(tag) = published {
            held.tag = tag;
        }
        *w = Out {
            tag: held.tag,
            valid: published.is_some(),
        };
    }
    let mut uut = SpeedTag::<24>::new(L);
    uut.connect_all();
    step(
        &mut uut,
        &In {
            reset: true,
            ..In::default()
        },
    );
    let got: Vec<Out> = cycles.iter().map(|c| step(&mut uut, c)).collect();
    for (k, (g, w)) in got.iter().zip(&want).enumerate() {
        assert_eq!(g, w, "edge {k}");
    }
    // The model agrees with the hand timeline too.
    let mut model = Model::new(L);
    model.step(&In {
        reset: true,
        ..In::default()
    });
    let modelled: Vec<Out> = cycles.iter().map(|c| model.step(c)).collect();
    assert_eq!(modelled, want);
}

/// The replay of one stimulus; how many of its resets fell on a publishing edge.
fn icarus<const N: usize>(latency: u32, seed: u64) -> usize {
    let mut model = Model::new(latency);
    let (mut vectors, mut valids, mut dropped) = (String::new(), 0, 0);
    let first = In {
        reset: true,
        ..In::default()
    };
    for c in std::iter::once(first).chain(stimulus(
        seed,
        N,
        latency,
        30_000.max(300 * latency as usize),
    )) {
        dropped += usize::from(model.reset_drops_a_result(&c));
        let o = model.step(&c);
        valids += usize::from(o.valid);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.start),
            c.tag.0,
            c.tag.1,
            c.tag.2,
            o.tag.0,
            o.tag.1,
            o.tag.2,
            u8::from(o.valid)
        );
    }
    assert!(valids > 50, "too few tags published: {valids}");
    let tb = common::replay_bench(
        "speed_tag",
        &[
            ("reset", 1),
            ("start", 1),
            ("position", 32),
            ("nep", N),
            ("ndt", N),
        ],
        &[
            ("tag_position", 32),
            ("tag_nep", N),
            ("tag_ndt", N),
            ("valid", 1),
        ],
        "valid",
    );
    let mut uut = SpeedTag::<N>::new(latency);
    uut.connect_all();
    let v = named_verilog(&uut, "speed_tag");
    tools::lint_verilog("speed_tag", &v).unwrap();
    common::replay(
        "speed_tag",
        &format!("n{N}_l{latency}"),
        "speed_tag",
        &v,
        &tb,
        &vectors,
        valids,
    );
    dropped
}

#[test]
fn emitted_verilog_lints_and_equals_model_in_icarus() {
    let dropped = icarus::<24>(core_latency(), 0x7a9_0024)
        + icarus::<8>(2, 0x7a9_0008)
        + icarus::<32>(511, 0x7a9_0032);
    // Resets on a publishing edge are in the replayed stimuli: the held tag is compared
    // across them too.
    assert!(dropped > 0, "no reset fell on a publishing edge");
}

/// A reset on the edge that would publish request B publishes nothing: `valid` stays low
/// and `tag_*` keep A, the last tag published, until the next publication.
#[test]
fn reset_on_the_publishing_edge_keeps_the_last_tag() {
    const L: u32 = 3;
    let (a, b) = ((1, 2, 3), (4, 5, 6));
    let start = |tag: Tag| In {
        start: true,
        tag,
        ..In::default()
    };
    let idle = In::default();
    let mut cycles = vec![
        In {
            reset: true,
            ..In::default()
        },
        start(a),
    ];
    cycles.extend([idle; 8]);
    cycles.push(start(b));
    cycles.extend([idle; 8]);
    // The edge that publishes B, from the timing the hand timeline above checks.
    let mut probe = Model::new(L);
    let publish_b = cycles
        .iter()
        .position(|c| {
            probe.step(c)
                == Out {
                    tag: b,
                    valid: true,
                }
        })
        .expect("B is published");
    cycles[publish_b].reset = true;
    let mut uut = SpeedTag::<24>::new(L);
    uut.connect_all();
    let mut model = Model::new(L);
    for (k, c) in cycles.iter().enumerate() {
        let (got, want) = (step(&mut uut, c), model.step(c));
        assert_eq!(got, want, "edge {k}");
        if k >= publish_b {
            assert_eq!(
                got,
                Out {
                    tag: a,
                    valid: false
                },
                "edge {k}"
            );
        }
    }
}
