// SPDX-License-Identifier: MIT OR Apache-2.0
//! The eccentricity correction δ of a span given by its end P and its length in steps:
//! r = count mod R by restoring subtraction (N steps, so a span of more than a revolution
//! gets its exact ends), the ends in half-steps, then [`crate::EccDelta`]. Bit-true model,
//! span rule and latency: [`golden::ecc::span_delta`].
//!
//! No request register: the caller (a corrector with its own) holds the inputs from `start`
//! until `valid`. The start edge takes the first subtraction; `valid` comes N + 68 edges
//! after it.
//!
//! Ports: `clock`, `reset`, `start`, `position[31:0]` (P), `count[N-1:0]`, `negative`,
//! `half_end`, `motion_order`, `shift[1:0]`, `counts_per_rev[31:0]` (R), `coef_c`,
//! `coef_d` (Q15.16 lines) in; `delta[39:0]` (Q.16 steps, held) and `valid` out.

use crate::ecc::ecc_delta::EccDelta;
use golden::ecc::ecc_delta::DELTA_BITS;
use golden::params::POSITION_BITS;
use rust_hdl::prelude::*;

const C: usize = POSITION_BITS as usize;
/// Address bits of the sine table: every K ≤ 2^16 (the table has K entries).
pub const TABLE_A: usize = golden::top::ecc_top::TABLE_ADDRESS_BITS as usize;
/// Width of the sine table's entries.
pub const TABLE_D: usize = golden::top::ecc_top::TABLE_DATA_BITS as usize;
const W: usize = 64;
const H: usize = C + 2;
const DW: usize = DELTA_BITS as usize;

/// δ of a span of up to 2^N − 1 steps.
#[derive(LogicBlock)]
pub struct SpanDelta<const N: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Begin (the block is idle; the inputs are held until `valid`).
    pub start: Signal<In, Bit>,
    /// P: the end of the span, steps (< R).
    pub position: Signal<In, Bits<C>>,
    /// Length of the span in steps.
    pub count: Signal<In, Bits<N>>,
    /// The motion was backward.
    pub negative: Signal<In, Bit>,
    /// The span ends half a step beyond P.
    pub half_end: Signal<In, Bit>,
    /// δ in the order of motion (else from the lower to the upper end).
    pub motion_order: Signal<In, Bit>,
    /// log2 of steps per line.
    pub shift: Signal<In, Bits<2>>,
    /// R = lines·2^s.
    pub counts_per_rev: Signal<In, Bits<C>>,
    /// c = E·cos θ0, Q15.16 lines.
    pub coef_c: Signal<In, Bits<32>>,
    /// d = E·sin θ0, Q15.16 lines.
    pub coef_d: Signal<In, Bits<32>>,
    /// δ, two's complement, 16 fractional bits (steps).
    pub delta: Signal<Out, Bits<DW>>,
    /// One cycle: `delta` was just written.
    pub valid: Signal<Out, Bit>,
    corr: EccDelta<TABLE_A, TABLE_D>,
    running: DFF<Bit>,
    steps: DFF<Bits<8>>,
    rem: DFF<Bits<W>>,
    div: DFF<Bits<W>>,
    go: DFF<Bit>,
    count_wide: Signal<Local, Bits<W>>,
    first_div: Signal<Local, Bits<W>>,
    cur_rem: Signal<Local, Bits<W>>,
    cur_div: Signal<Local, Bits<W>>,
    rem_low: Signal<Local, Bits<C>>,
    pos_h: Signal<Local, Bits<H>>,
    rem_h: Signal<Local, Bits<H>>,
    cpr_h: Signal<Local, Bits<H>>,
    down: Signal<Local, Bits<H>>,
    up: Signal<Local, Bits<H>>,
    lo: Signal<Local, Bits<H>>,
    hi: Signal<Local, Bits<H>>,
    lo_half: Signal<Local, Bits<H>>,
    hi_half: Signal<Local, Bits<H>>,
    twice_cpr: Signal<Local, Bits<H>>,
    n_steps: Constant<Bits<8>>,
    one8: Constant<Bits<8>>,
    sh_init: Constant<Bits<8>>,
    one64: Constant<Bits<W>>,
    one_h: Constant<Bits<H>>,
    zero_h: Constant<Bits<H>>,
}

impl<const N: usize> SpanDelta<N> {
    /// For a disc of `lines` lines (a multiple of 4, 4..=65536).
    pub fn new(lines: u32) -> Self {
        assert!((2..=32).contains(&N), "N outside 2..=32");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            position: Default::default(),
            count: Default::default(),
            negative: Default::default(),
            half_end: Default::default(),
            motion_order: Default::default(),
            shift: Default::default(),
            counts_per_rev: Default::default(),
            coef_c: Default::default(),
            coef_d: Default::default(),
            delta: Default::default(),
            valid: Default::default(),
            corr: EccDelta::new(lines),
            running: Default::default(),
            steps: Default::default(),
            rem: Default::default(),
            div: Default::default(),
            go: Default::default(),
            count_wide: Default::default(),
            first_div: Default::default(),
            cur_rem: Default::default(),
            cur_div: Default::default(),
            rem_low: Default::default(),
            pos_h: Default::default(),
            rem_h: Default::default(),
            cpr_h: Default::default(),
            down: Default::default(),
            up: Default::default(),
            lo: Default::default(),
            hi: Default::default(),
            lo_half: Default::default(),
            hi_half: Default::default(),
            twice_cpr: Default::default(),
            n_steps: Constant::new((N as u64).into()),
            one8: Constant::new(1.into()),
            sh_init: Constant::new((N as u64 - 1).into()),
            one64: Constant::new(1.into()),
            one_h: Constant::new(1.into()),
            zero_h: Constant::new(0.into()),
        }
    }
}

impl<const N: usize> Logic for SpanDelta<N> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, corr);
        dff_setup!(self, clock, running, steps, rem, div, go);
        self.corr.reset.next = self.reset.val();

        // r = count mod R: subtract R·2^k where it fits, k = N − 1 … 0; the start edge
        // takes k = N − 1 from the inputs, the next N − 1 edges the rest.
        self.count_wide.next = bit_cast::<W, N>(self.count.val());
        self.first_div.next = bit_cast::<W, C>(self.counts_per_rev.val()) << self.sh_init.val();
        self.cur_rem.next = self.rem.q.val();
        self.cur_div.next = self.div.q.val();
        if self.start.val() {
            self.cur_rem.next = self.count_wide.val();
            self.cur_div.next = self.first_div.val();
        }
        self.go.d.next = false;
        if self.start.val() | self.running.q.val() {
            self.rem.d.next = self.cur_rem.val();
            if self.cur_rem.val() >= self.cur_div.val() {
                self.rem.d.next = self.cur_rem.val() - self.cur_div.val();
            }
            self.div.d.next = self.cur_div.val() >> self.one64.val();
            self.steps.d.next = self.steps.q.val() - self.one8.val();
            self.running.d.next = true;
            if self.start.val() {
                self.steps.d.next = self.n_steps.val() - self.one8.val();
            }
            if (self.steps.q.val() == self.one8.val()) & !self.start.val() {
                self.running.d.next = false;
                self.go.d.next = true;
            }
        }
        if self.start.val() & (self.n_steps.val() == self.one8.val()) {
            self.running.d.next = false;
            self.go.d.next = true;
        }
        if self.reset.val() {
            self.running.d.next = false;
            self.go.d.next = false;
        }

        // The ends in half-steps (golden::ecc::span_delta), from r and the held inputs.
        self.rem_low.next = bit_cast::<C, W>(self.rem.q.val());
        self.pos_h.next = bit_cast::<H, C>(self.position.val());
        self.rem_h.next = bit_cast::<H, C>(self.rem_low.val());
        self.cpr_h.next = bit_cast::<H, C>(self.counts_per_rev.val());
        self.down.next = (self.pos_h.val() + self.cpr_h.val()) - self.rem_h.val();
        if self.pos_h.val() >= self.rem_h.val() {
            self.down.next = self.pos_h.val() - self.rem_h.val();
        }
        self.up.next = self.pos_h.val() + self.rem_h.val();
        if self.up.val() >= self.cpr_h.val() {
            self.up.next = self.up.val() - self.cpr_h.val();
        }
        self.twice_cpr.next = self.cpr_h.val() << self.one_h.val();
        // Forward: (2·down, 2P + half); backward: (2P − half mod 2R, 2·up).
        self.lo.next = self.down.val() << self.one_h.val();
        self.hi.next = self.pos_h.val() << self.one_h.val();
        if self.half_end.val() {
            self.hi.next = (self.pos_h.val() << self.one_h.val()) + self.one_h.val();
        }
        if self.negative.val() {
            self.lo.next = self.pos_h.val() << self.one_h.val();
            if self.half_end.val() {
                self.lo.next = (self.pos_h.val() << self.one_h.val()) - self.one_h.val();
                if self.pos_h.val() == self.zero_h.val() {
                    self.lo.next = self.twice_cpr.val() - self.one_h.val();
                }
            }
            self.hi.next = self.up.val() << self.one_h.val();
        }
        self.lo_half.next = self.lo.val();
        self.hi_half.next = self.hi.val();
        if self.motion_order.val() & self.negative.val() {
            self.lo_half.next = self.hi.val();
            self.hi_half.next = self.lo.val();
        }
        self.corr.start.next = self.go.q.val();
        self.corr.p_a.next = bit_cast::<33, H>(self.lo_half.val());
        self.corr.p_b.next = bit_cast::<33, H>(self.hi_half.val());
        self.corr.shift.next = self.shift.val();
        self.corr.coef_c.next = self.coef_c.val();
        self.corr.coef_d.next = self.coef_d.val();
        self.delta.next = self.corr.delta.val();
        self.valid.next = self.corr.valid.val();
    }
}
