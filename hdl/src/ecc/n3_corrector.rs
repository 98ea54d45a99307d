// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's n3 corrected for the eccentricity of its span: at each `speed_strobe` of the
//! core, the span from `speed_position` and `speed_nep` ([`crate::SpanDelta`], in the
//! order of motion), then [`crate::EccN3`] (n3·(1 − δ) at Nep1 = 1, n3 − δ/2^s at
//! Nep1 ≥ 2 with Ndt1 = 1). Bit-true model, value and latency: [`golden::ecc::n3_corrector`].
//!
//! ```text
//! start ─ request ─ take ─ SpanDelta (N + 68) ─ EccN3 (20) ─ speed_n3c
//! ```
//!
//! Ports: `clock`, `reset`, `start`, `n3[S-1:0]` (`speed_n3`), `position[31:0]`,
//! `nep`, `ndt` (N bits), `shift[1:0]`, `counts_per_rev[31:0]`, `coef_c`, `coef_d` in;
//! registered `n3c[S-1:0]` (held) and `valid` out.

use crate::ecc::ecc_n3::EccN3;
use crate::ecc::span_delta::SpanDelta;
use golden::ecc::ecc_delta::DELTA_BITS;
use golden::params::POSITION_BITS;
use rust_hdl::prelude::*;

const C: usize = POSITION_BITS as usize;
const DW: usize = DELTA_BITS as usize;

/// The n3 corrector for N-bit counters and S-bit speeds.
#[derive(LogicBlock)]
pub struct N3Corrector<const N: usize, const S: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// A speed was published: latch the inputs.
    pub start: Signal<In, Bit>,
    /// `speed_n3` (lines per dt, two's complement, 16 fractional bits).
    pub n3: Signal<In, Bits<S>>,
    /// `speed_position`: the span's end (steps).
    pub position: Signal<In, Bits<C>>,
    /// `speed_nep`.
    pub nep: Signal<In, Bits<N>>,
    /// `speed_ndt`.
    pub ndt: Signal<In, Bits<N>>,
    /// log2 of steps per line.
    pub shift: Signal<In, Bits<2>>,
    /// R = lines·2^s.
    pub counts_per_rev: Signal<In, Bits<C>>,
    /// c = E·cos θ0, Q15.16 lines.
    pub coef_c: Signal<In, Bits<32>>,
    /// d = E·sin θ0, Q15.16 lines.
    pub coef_d: Signal<In, Bits<32>>,
    /// Corrected n3 (format of `speed_n3`).
    pub n3c: Signal<Out, Bits<S>>,
    /// One cycle: `n3c` was just written.
    pub valid: Signal<Out, Bit>,
    span: SpanDelta<N>,
    ecc: EccN3<S>,
    req_n3: DFF<Bits<S>>,
    req_pos: DFF<Bits<C>>,
    req_nep: DFF<Bits<N>>,
    req_ndt: DFF<Bits<N>>,
    req_shift: DFF<Bits<2>>,
    req_cpr: DFF<Bits<C>>,
    req_c: DFF<Bits<32>>,
    req_d: DFF<Bits<32>>,
    pending: DFF<Bit>,
    job_n3: DFF<Bits<S>>,
    job_pos: DFF<Bits<C>>,
    job_nep: DFF<Bits<N>>,
    job_ndt: DFF<Bits<N>>,
    job_shift: DFF<Bits<2>>,
    job_cpr: DFF<Bits<C>>,
    job_c: DFF<Bits<32>>,
    job_d: DFF<Bits<32>>,
    state: DFF<Bits<2>>,
    out_n3c: DFF<Bits<S>>,
    out_valid: DFF<Bit>,
    nep_le_one: Signal<Local, Bit>,
    delta_lines: Signal<Local, Bits<DW>>,
    st_idle: Constant<Bits<2>>,
    st_go: Constant<Bits<2>>,
    st_span: Constant<Bits<2>>,
    st_ecc: Constant<Bits<2>>,
    n_one: Constant<Bits<N>>,
    shift_one: Constant<Bits<2>>,
    shift_zero: Constant<Bits<2>>,
    one_d: Constant<Bits<DW>>,
    two_d: Constant<Bits<DW>>,
    sign_d: Constant<Bits<DW>>,
    zero_s: Constant<Bits<S>>,
    sign_s: Constant<Bits<S>>,
}

impl<const N: usize, const S: usize> N3Corrector<N, S> {
    /// The corrector for a disc of `lines` lines (a multiple of 4, 4..=65536).
    pub fn new(lines: u32) -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            n3: Default::default(),
            position: Default::default(),
            nep: Default::default(),
            ndt: Default::default(),
            shift: Default::default(),
            counts_per_rev: Default::default(),
            coef_c: Default::default(),
            coef_d: Default::default(),
            n3c: Default::default(),
            valid: Default::default(),
            span: SpanDelta::new(lines),
            ecc: Default::default(),
            req_n3: Default::default(),
            req_pos: Default::default(),
            req_nep: Default::default(),
            req_ndt: Default::default(),
            req_shift: Default::default(),
            req_cpr: Default::default(),
            req_c: Default::default(),
            req_d: Default::default(),
            pending: Default::default(),
            job_n3: Default::default(),
            job_pos: Default::default(),
            job_nep: Default::default(),
            job_ndt: Default::default(),
            job_shift: Default::default(),
            job_cpr: Default::default(),
            job_c: Default::default(),
            job_d: Default::default(),
            state: Default::default(),
            out_n3c: Default::default(),
            out_valid: Default::default(),
            nep_le_one: Default::default(),
            delta_lines: Default::default(),
            st_idle: Constant::new(0.into()),
            st_go: Constant::new(1.into()),
            st_span: Constant::new(2.into()),
            st_ecc: Constant::new(3.into()),
            n_one: Constant::new(1.into()),
            shift_one: Constant::new(1.into()),
            shift_zero: Constant::new(0.into()),
            one_d: Constant::new(1.into()),
            two_d: Constant::new(2.into()),
            sign_d: Constant::new((1u64 << (DW - 1)).into()),
            zero_s: Constant::new(0.into()),
            sign_s: Constant::new((1u64 << (S - 1)).into()),
        }
    }
}

impl<const N: usize, const S: usize> Logic for N3Corrector<N, S> {
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, span, ecc);
        dff_setup!(
            self, clock, req_n3, req_pos, req_nep, req_ndt, req_shift, req_cpr, req_c, req_d,
            pending, job_n3, job_pos, job_nep, job_ndt, job_shift, job_cpr, job_c, job_d, state,
            out_n3c, out_valid
        );
        self.out_valid.d.next = false;
        self.span.reset.next = self.reset.val();
        self.ecc.reset.next = self.reset.val();

        // The span, in the order of motion: one step (Nep1 ≤ 1) or Nep1 − 1 steps and a half.
        self.nep_le_one.next = self.job_nep.q.val() <= self.n_one.val();
        self.span.start.next = self.state.q.val() == self.st_go.val();
        self.span.position.next = self.job_pos.q.val();
        self.span.count.next = self.job_nep.q.val() - self.n_one.val();
        self.span.half_end.next = true;
        if self.nep_le_one.val() {
            self.span.count.next = self.n_one.val();
            self.span.half_end.next = false;
        }
        self.span.negative.next = (self.job_n3.q.val() & self.sign_s.val()) != self.zero_s.val();
        self.span.motion_order.next = true;
        self.span.shift.next = self.job_shift.q.val();
        self.span.counts_per_rev.next = self.job_cpr.q.val();
        self.span.coef_c.next = self.job_c.q.val();
        self.span.coef_d.next = self.job_d.q.val();

        // δ in steps for a one-step span, in lines (⌊δ/2^s⌋) for n3 − δ.
        self.delta_lines.next = self.span.delta.val();
        if self.job_shift.q.val() == self.shift_one.val() {
            self.delta_lines.next = (self.span.delta.val() >> self.one_d.val())
                | (self.span.delta.val() & self.sign_d.val());
        } else if self.job_shift.q.val() != self.shift_zero.val() {
            self.delta_lines.next = (self.span.delta.val() >> self.two_d.val())
                | ((self.span.delta.val() & self.sign_d.val()) >> self.one_d.val())
                | (self.span.delta.val() & self.sign_d.val());
        }
        self.ecc.start.next = (self.state.q.val() == self.st_span.val()) & self.span.valid.val();
        self.ecc.n3.next = self.job_n3.q.val();
        self.ecc.nep_is_one.next = self.job_nep.q.val() == self.n_one.val();
        self.ecc.ndt_is_one.next = self.job_ndt.q.val() == self.n_one.val();
        self.ecc.delta.next = self.delta_lines.val();
        if self.job_nep.q.val() == self.n_one.val() {
            self.ecc.delta.next = self.span.delta.val();
        }

        if self.state.q.val() == self.st_idle.val() {
            if self.pending.q.val() {
                self.job_n3.d.next = self.req_n3.q.val();
                self.job_pos.d.next = self.req_pos.q.val();
                self.job_nep.d.next = self.req_nep.q.val();
                self.job_ndt.d.next = self.req_ndt.q.val();
                self.job_shift.d.next = self.req_shift.q.val();
                self.job_cpr.d.next = self.req_cpr.q.val();
                self.job_c.d.next = self.req_c.q.val();
                self.job_d.d.next = self.req_d.q.val();
                self.pending.d.next = false;
                self.state.d.next = self.st_go.val();
            }
        } else if self.state.q.val() == self.st_go.val() {
            self.state.d.next = self.st_span.val();
        } else if self.state.q.val() == self.st_span.val() {
            if self.span.valid.val() {
                self.state.d.next = self.st_ecc.val();
            }
        } else if self.ecc.valid.val() {
            self.out_n3c.d.next = self.ecc.n3c.val();
            self.out_valid.d.next = true;
            self.state.d.next = self.st_idle.val();
        }
        if self.start.val() {
            self.req_n3.d.next = self.n3.val();
            self.req_pos.d.next = self.position.val();
            self.req_nep.d.next = self.nep.val();
            self.req_ndt.d.next = self.ndt.val();
            self.req_shift.d.next = self.shift.val();
            self.req_cpr.d.next = self.counts_per_rev.val();
            self.req_c.d.next = self.coef_c.val();
            self.req_d.d.next = self.coef_d.val();
            self.pending.d.next = true;
        }
        if self.reset.val() {
            self.pending.d.next = false;
            self.state.d.next = self.st_idle.val();
            self.out_valid.d.next = false;
            self.out_n3c.d.next = self.zero_s.val();
        }
        self.n3c.next = self.out_n3c.q.val();
        self.valid.next = self.out_valid.q.val();
    }
}
