// SPDX-License-Identifier: MIT OR Apache-2.0
//! `SpanDelta` (δ of a span given by its end and its length) against its bit-true model,
//! every cycle: `golden::ecc::span_delta` (the span's ends in half-steps, `half_steps`, and
//! its value, `span_delta`) with the timing its module docs give (the start edge and N − 1
//! more take r = count mod R, the next edge starts `EccDelta`), the `EccDelta` stage being
//! its cycle model `golden::ecc::ecc_delta::EccDelta`. The rust-hdl simulation (direct
//! drive) on proptest stimuli for N = 24, 8 and 32 and several K (1024, 1000, 4 and other
//! multiples of 4), the emitted Verilog linted by Verilator and replayed in Icarus (a
//! self-checking bench from `common::replay_bench`, under `target/`), and the latency
//! N + 68 on a hand-worked timeline.
//!
//! The block has no request register: a start comes only while it is idle, and the inputs
//! are held from the start to `valid` (its contract); between jobs they change at random.
//! Stimuli: every shift (0, 1, 2) with R = K·2^s, positions P < R with their ends, counts
//! with their corners (0, 1, R − 1, R, R + 1, whole revolutions, 2^N − 1: spans of many
//! revolutions), both directions, `half_end` and `motion_order` both ways, coefficients
//! random with their extremes, gaps between jobs from none to long, and random resets (also
//! mid-job).
//!
//! The lint waives what the shipped `encspeed_ecc` waives for this block
//! (`common::CORRECTOR_WAIVERS`): WIDTH on the masks of rust-hdl's `bit_cast`, and the
//! arithmetic blocks' unused `busy`.

use crate::common::{self, SplitMix};
use golden::ecc::ecc_delta::{EccDelta, Inputs as DeltaInputs, Request, DELTA_BITS};
use golden::ecc::span_delta::{half_steps, latency_cycles, span_delta, SpanRequest};
use golden::top::ecc_top::{TABLE_ADDRESS_BITS, TABLE_DATA_BITS};
use hdl::verilog::named_verilog;
use hdl::SpanDelta;
use proptest::prelude::*;
use rust_hdl::prelude::*;

const TABLE: (u32, u32) = (TABLE_ADDRESS_BITS, TABLE_DATA_BITS);

fn sext(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

/// One cycle's inputs.
#[derive(Clone, Copy, Debug, Default)]
struct In {
    reset: bool,
    start: bool,
    req: SpanRequest,
}

/// Outputs after an edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Out {
    delta: i64,
    valid: bool,
}

/// The cycle model (module docs): N edges of r = count mod R from the start edge, then the
/// golden `EccDelta` on the span's ends.
struct Model {
    lines: u32,
    bits: u32,
    /// Edges left to `EccDelta`'s start, and the job.
    job: Option<(u32, SpanRequest)>,
    delta: EccDelta,
}

impl Model {
    fn new(lines: u32, bits: u32) -> Self {
        Self {
            lines,
            bits,
            job: None,
            delta: EccDelta::new(lines, TABLE.0, TABLE.1),
        }
    }

    /// No job and `EccDelta` idle: a start is in contract.
    fn idle(&self) -> bool {
        self.job.is_none() && !self.delta.outputs().busy
    }

    fn step(&mut self, c: &In) -> Out {
        let mut go = None;
        if let Some((left, req)) = &mut self.job {
            *left -= 1;
            if *left == 0 {
                go = Some(*req);
                self.job = None;
            }
        }
        if c.start {
            self.job = Some((self.bits, c.req));
        }
        if c.reset {
            self.job = None;
        }
        let req = go.unwrap_or(c.req);
        let (p_a, p_b) = half_steps(self.lines, &req);
        let o = self.delta.step(DeltaInputs {
            reset: c.reset,
            start: go.is_some(),
            req: Request {
                p_a,
                p_b,
                shift: req.shift,
                coef_c: req.coef_c,
                coef_d: req.coef_d,
            },
        });
        Out {
            delta: o.delta,
            valid: o.valid,
        }
    }
}

/// A random span request for K = `lines` and N = `bits`.
fn request(rng: &mut SplitMix, lines: u32, bits: u32) -> SpanRequest {
    let shift = (rng.next() % 3) as u32;
    let r = u64::from(lines) << shift;
    let max = (1u64 << bits) - 1;
    let count = match rng.next() % 10 {
        0 => 0,
        1 => 1,
        2 => r - 1,
        3 => r,
        4 => r + 1,
        5 => r * (1 + rng.next() % 3) + rng.next() % 3,
        6 => max,
        _ => rng.next() % (2 * r),
    } & max;
    let position = match rng.next() % 5 {
        0 => 0,
        1 => r - 1,
        _ => rng.next() % r,
    };
    let mut coef = || match rng.next() % 6 {
        0 => -(1i64 << 31),
        1 => (1i64 << 31) - 1,
        2 => 124_609,
        _ => sext(rng.next(), 32),
    };
    let (coef_c, coef_d) = (coef(), coef());
    SpanRequest {
        position,
        count,
        negative: rng.next().is_multiple_of(2),
        half_end: rng.next().is_multiple_of(2),
        motion_order: rng.next().is_multiple_of(2),
        shift,
        coef_c,
        coef_d,
    }
}

/// Drives `len` cycles (after a reset) from `seed` through `model` and `each`, starting jobs
/// only while the model is idle and holding their inputs until `valid`; then, if no result
/// came out (a reset can abandon the only job of a short run), without resets until one
/// does, at most `DRAIN` cycles more.
/// The most cycles `run` adds after `len` to see a result: an idle cycle starts a job with
/// probability at least 1/41 and a job lasts N + 68 ≤ 100 edges, so 2 000 cycles without a
/// result has odds below e^−45.
const DRAIN: usize = 2_000;

fn run(
    seed: u64,
    lines: u32,
    bits: u32,
    len: usize,
    model: &mut Model,
    mut each: impl FnMut(&In, Out) -> Result<(), TestCaseError>,
) -> Result<usize, TestCaseError> {
    let mut rng = SplitMix(seed);
    let first = In {
        reset: true,
        ..In::default()
    };
    each(&first, model.step(&first))?;
    let (mut held, mut busy, mut valids) = (None, false, 0);
    let mut gap = [0u64, 1, 5, 40][(rng.next() % 4) as usize];
    for k in 0..len + DRAIN {
        let draining = k >= len;
        if draining && valids > 0 {
            break;
        }
        let reset_draw = rng.next().is_multiple_of(500);
        let mut c = In {
            reset: reset_draw && !draining,
            start: false,
            req: request(&mut rng, lines, bits),
        };
        if busy {
            c.req = held.unwrap();
        } else if model.idle() && rng.next().is_multiple_of(gap + 1) {
            c.start = true;
            held = Some(c.req);
            busy = true;
            gap = [0u64, 1, 5, 40][(rng.next() % 4) as usize];
        }
        let o = model.step(&c);
        if o.valid {
            let want = span_delta(lines, TABLE, &held.unwrap());
            assert_eq!(o.delta, want, "the cycle model against span_delta");
        }
        valids += usize::from(o.valid);
        if o.valid || c.reset {
            busy = false;
        }
        each(&c, o)?;
    }
    Ok(valids)
}

fn step<const N: usize>(uut: &mut SpanDelta<N>, lines: u32, c: &In) -> Out {
    let r = &c.req;
    uut.reset.next = c.reset;
    uut.start.next = c.start;
    uut.position.next = r.position.into();
    uut.count.next = r.count.into();
    uut.negative.next = r.negative;
    uut.half_end.next = r.half_end;
    uut.motion_order.next = r.motion_order;
    uut.shift.next = u64::from(r.shift).into();
    uut.counts_per_rev.next = (u64::from(lines) << r.shift).into();
    uut.coef_c.next = ((r.coef_c as u64) & 0xffff_ffff).into();
    uut.coef_d.next = ((r.coef_d as u64) & 0xffff_ffff).into();
    common::edge(uut, |u, v| u.clock.next = Clock { clk: v });
    Out {
        delta: sext(uut.delta.val().to_u64(), DELTA_BITS),
        valid: uut.valid.val(),
    }
}

/// rust-hdl = model on `len` cycles from `seed`; the number of results.
fn compare<const N: usize>(seed: u64, lines: u32, len: usize) -> Result<usize, TestCaseError> {
    let mut uut = SpanDelta::<N>::new(lines);
    uut.connect_all();
    let mut model = Model::new(lines, N as u32);
    let mut k = 0;
    run(seed, lines, N as u32, len, &mut model, |c, want| {
        let got = step(&mut uut, lines, c);
        prop_assert_eq!(got, want, "N {} K {} edge {} {:?}", N, lines, k, c);
        k += 1;
        Ok(())
    })
}

/// A multiple of 4 in 4..=max, often max, 1000 or a small one.
fn some_k(pick: u32, max: u32) -> u32 {
    match pick % 5 {
        0 => max,
        1 => 1000.min(max),
        2 => 4 * (1 + pick / 5 % 4),
        _ => 4 * (1 + (pick / 5) % (max / 4)),
    }
}

proptest! {
    #![proptest_config(common::proptest_config(48))]

    #[test]
    fn rust_hdl_equals_model_n24(seed in any::<u64>(), pick in any::<u32>(),
                                 len in 300usize..1500) {
        let results = compare::<24>(seed, some_k(pick, 1024), len)?;
        prop_assert!(results > 0);
    }
}

proptest! {
    #![proptest_config(common::proptest_config(16))]

    /// The narrowest counters (spans of many revolutions at small K) and the widest.
    #[test]
    fn rust_hdl_equals_model_n8_and_n32(seed in any::<u64>(), pick in any::<u32>()) {
        compare::<8>(seed, some_k(pick, 64), 800)?;
        compare::<32>(seed ^ 1, some_k(pick, 4096), 800)?;
    }
}

/// Hand-worked: a start while idle gives `valid` exactly N + 68 edges later (92 at N = 24,
/// 76 at N = 8), with δ = 0 for a span of whole revolutions (its ends coincide); a reset
/// mid-job abandons it.
#[test]
fn latency_whole_revolutions_and_reset_by_hand() {
    fn timeline<const N: usize>(lines: u32, latency: usize) {
        assert_eq!(latency_cycles(N as u32) as usize, latency);
        let job = SpanRequest {
            position: 10,
            count: 3,
            coef_c: 80_097,
            coef_d: 95_455,
            ..SpanRequest::default()
        };
        let whole = SpanRequest {
            count: 2 * u64::from(lines),
            ..job
        };
        let mut uut = SpanDelta::<N>::new(lines);
        uut.connect_all();
        let mut at = |c: In| step(&mut uut, lines, &c);
        at(In {
            reset: true,
            ..In::default()
        });
        // A job, then a job of two whole revolutions, then one reset 10 edges in.
        let mut valid_edges = vec![];
        let mut deltas = vec![];
        for (req, reset_at) in [(job, None), (whole, None), (job, Some(10))] {
            for k in 0..latency + 5 {
                let o = at(In {
                    reset: reset_at == Some(k),
                    start: k == 0,
                    req,
                });
                if o.valid {
                    valid_edges.push(k);
                    deltas.push(o.delta);
                }
            }
        }
        assert_eq!(valid_edges, [latency, latency], "N = {N}");
        assert_ne!(deltas[0], 0, "a 3-step span with E ≠ 0 has δ ≠ 0");
        assert_eq!(deltas[1], 0, "whole revolutions: δ = 0");
    }
    timeline::<24>(1024, 92);
    timeline::<8>(64, 76);
}

fn icarus<const N: usize>(lines: u32, seed: u64) {
    let mut model = Model::new(lines, N as u32);
    let mut vectors = String::new();
    let dmask = (1u64 << DELTA_BITS) - 1;
    let valids = run(seed, lines, N as u32, 12_000, &mut model, |c, o| {
        let r = &c.req;
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.start),
            r.position,
            r.count,
            u8::from(r.negative),
            u8::from(r.half_end),
            u8::from(r.motion_order),
            r.shift,
            u64::from(lines) << r.shift,
            (r.coef_c as u64) & 0xffff_ffff,
            (r.coef_d as u64) & 0xffff_ffff,
            (o.delta as u64) & dmask,
            u8::from(o.valid)
        );
        Ok(())
    })
    .unwrap();
    assert!(valids > 50, "too few results: {valids}");
    let tb = common::replay_bench(
        "span_delta",
        &[
            ("reset", 1),
            ("start", 1),
            ("position", 32),
            ("count", N),
            ("negative", 1),
            ("half_end", 1),
            ("motion_order", 1),
            ("shift", 2),
            ("counts_per_rev", 32),
            ("coef_c", 32),
            ("coef_d", 32),
        ],
        &[("delta", DELTA_BITS as usize), ("valid", 1)],
        "valid",
    );
    let mut uut = SpanDelta::<N>::new(lines);
    uut.connect_all();
    let v = named_verilog(&uut, "span_delta");
    common::lint_with_waivers("span_delta", &v, common::CORRECTOR_WAIVERS);
    common::replay(
        "span_delta",
        &format!("n{N}_k{lines}"),
        "span_delta",
        &v,
        &tb,
        &vectors,
        valids,
    );
}

#[test]
fn emitted_verilog_lints_and_equals_model_in_icarus() {
    icarus::<24>(1024, 0x5da_1024);
    icarus::<8>(12, 0x5da_0012);
    icarus::<32>(1000, 0x5da_1000);
}
