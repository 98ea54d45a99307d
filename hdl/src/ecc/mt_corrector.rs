// SPDX-License-Identifier: MIT OR Apache-2.0
//! The eccentricity-corrected M/T speed of each window the core's M/T counter closes: the
//! span of the window from its last step's position and its step count
//! ([`crate::SpanDelta`]: m mod R, the ends, `EccDelta`), then ±(m − δ)·dt·2^(F−s)/t
//! ([`crate::EccMtSpeed`]). Bit-true model, value, span rule and latency:
//! [`golden::ecc::mt_corrector`].
//!
//! ```text
//! start ─ request ─ take ─ SpanDelta (N + 68) ─ EccMtSpeed (2N + F + 4) ─ speed_mtc
//! ```
//!
//! One job at a time, so the arithmetic blocks are always idle when started; a start while
//! busy waits in the one-deep request register (the latest wins), as everywhere in the core.
//!
//! Ports: `clock`, `reset` (synchronous, active high), `start`, `position[31:0]` (the
//! window's last step), `mt_m`, `mt_t`, `cfg_dt` (N bits), `mt_negative`, `shift[1:0]`,
//! `counts_per_rev[31:0]` (R), `coef_c`, `coef_d` (Q15.16 lines) in; registered
//! `speed_mtc[S-1:0]` (held) and `valid` (one cycle) out.

use crate::ecc::ecc_mt_speed::EccMtSpeed;
use crate::ecc::span_delta::SpanDelta;
use golden::params::POSITION_BITS;
use rust_hdl::prelude::*;

const C: usize = POSITION_BITS as usize;

/// The corrector for N-bit counters, F fractional bits, S = N + F + 1, CW = the corrected
/// count's width ([`crate::ecc::ecc_mt_speed::corrected_width`]).
#[derive(LogicBlock)]
pub struct MtCorrector<const N: usize, const F: usize, const S: usize, const CW: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// A window closed: latch the inputs.
    pub start: Signal<In, Bit>,
    /// Position of the window's last step (steps, < R).
    pub position: Signal<In, Bits<C>>,
    /// Steps of the window.
    pub mt_m: Signal<In, Bits<N>>,
    /// Cycles spanning them.
    pub mt_t: Signal<In, Bits<N>>,
    /// The steps were backward.
    pub mt_negative: Signal<In, Bit>,
    /// dt in use.
    pub cfg_dt: Signal<In, Bits<N>>,
    /// log2 of steps per line.
    pub shift: Signal<In, Bits<2>>,
    /// R = lines·2^s.
    pub counts_per_rev: Signal<In, Bits<C>>,
    /// c = E·cos θ0, Q15.16 lines.
    pub coef_c: Signal<In, Bits<32>>,
    /// d = E·sin θ0, Q15.16 lines.
    pub coef_d: Signal<In, Bits<32>>,
    /// Corrected M/T speed (format of `speed_mt`).
    pub speed_mtc: Signal<Out, Bits<S>>,
    /// One cycle: `speed_mtc` was just written.
    pub valid: Signal<Out, Bit>,
    span: SpanDelta<N>,
    speed: EccMtSpeed<N, F, S, CW>,
    req_pos: DFF<Bits<C>>,
    req_m: DFF<Bits<N>>,
    req_t: DFF<Bits<N>>,
    req_neg: DFF<Bit>,
    req_dt: DFF<Bits<N>>,
    req_shift: DFF<Bits<2>>,
    req_cpr: DFF<Bits<C>>,
    req_c: DFF<Bits<32>>,
    req_d: DFF<Bits<32>>,
    pending: DFF<Bit>,
    job_pos: DFF<Bits<C>>,
    job_m: DFF<Bits<N>>,
    job_t: DFF<Bits<N>>,
    job_neg: DFF<Bit>,
    job_dt: DFF<Bits<N>>,
    job_shift: DFF<Bits<2>>,
    job_cpr: DFF<Bits<C>>,
    job_c: DFF<Bits<32>>,
    job_d: DFF<Bits<32>>,
    state: DFF<Bits<2>>,
    out_speed: DFF<Bits<S>>,
    out_valid: DFF<Bit>,
    st_idle: Constant<Bits<2>>,
    st_go: Constant<Bits<2>>,
    st_span: Constant<Bits<2>>,
    st_speed: Constant<Bits<2>>,
    zero_s: Constant<Bits<S>>,
}

impl<const N: usize, const F: usize, const S: usize, const CW: usize> MtCorrector<N, F, S, CW> {
    /// The corrector for a disc of `lines` lines (a multiple of 4, 4..=65536: the sine
    /// table's rule, `golden::ecc::ecc_delta::check_params`).
    pub fn new(lines: u32) -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            position: Default::default(),
            mt_m: Default::default(),
            mt_t: Default::default(),
            mt_negative: Default::default(),
            cfg_dt: Default::default(),
            shift: Default::default(),
            counts_per_rev: Default::default(),
            coef_c: Default::default(),
            coef_d: Default::default(),
            speed_mtc: Default::default(),
            valid: Default::default(),
            span: SpanDelta::new(lines),
            speed: Default::default(),
            req_pos: Default::default(),
            req_m: Default::default(),
            req_t: Default::default(),
            req_neg: Default::default(),
            req_dt: Default::default(),
            req_shift: Default::default(),
            req_cpr: Default::default(),
            req_c: Default::default(),
            req_d: Default::default(),
            pending: Default::default(),
            job_pos: Default::default(),
            job_m: Default::default(),
            job_t: Default::default(),
            job_neg: Default::default(),
            job_dt: Default::default(),
            job_shift: Default::default(),
            job_cpr: Default::default(),
            job_c: Default::default(),
            job_d: Default::default(),
            state: Default::default(),
            out_speed: Default::default(),
            out_valid: Default::default(),
            st_idle: Constant::new(0.into()),
            st_go: Constant::new(1.into()),
            st_span: Constant::new(2.into()),
            st_speed: Constant::new(3.into()),
            zero_s: Constant::new(0.into()),
        }
    }
}

impl<const N: usize, const F: usize, const S: usize, const CW: usize> Logic
    for MtCorrector<N, F, S, CW>
{
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, span, speed);
        dff_setup!(
            self, clock, req_pos, req_m, req_t, req_neg, req_dt, req_shift, req_cpr, req_c, req_d,
            pending, job_pos, job_m, job_t, job_neg, job_dt, job_shift, job_cpr, job_c, job_d,
            state, out_speed, out_valid
        );
        self.out_valid.d.next = false;
        self.span.reset.next = self.reset.val();
        self.speed.reset.next = self.reset.val();

        // The window's span: m steps ending at P, δ from the lower to the upper end.
        self.span.start.next = self.state.q.val() == self.st_go.val();
        self.span.position.next = self.job_pos.q.val();
        self.span.count.next = self.job_m.q.val();
        self.span.negative.next = self.job_neg.q.val();
        self.span.half_end.next = false;
        self.span.motion_order.next = false;
        self.span.shift.next = self.job_shift.q.val();
        self.span.counts_per_rev.next = self.job_cpr.q.val();
        self.span.coef_c.next = self.job_c.q.val();
        self.span.coef_d.next = self.job_d.q.val();

        // δ in hand: the speed of the corrected count.
        self.speed.start.next = (self.state.q.val() == self.st_span.val()) & self.span.valid.val();
        self.speed.mt_m.next = self.job_m.q.val();
        self.speed.mt_t.next = self.job_t.q.val();
        self.speed.mt_negative.next = self.job_neg.q.val();
        self.speed.ecc_delta.next = self.span.delta.val();
        self.speed.cfg_dt.next = self.job_dt.q.val();
        self.speed.mode_shift.next = self.job_shift.q.val();

        if self.state.q.val() == self.st_idle.val() {
            if self.pending.q.val() {
                self.job_pos.d.next = self.req_pos.q.val();
                self.job_m.d.next = self.req_m.q.val();
                self.job_t.d.next = self.req_t.q.val();
                self.job_neg.d.next = self.req_neg.q.val();
                self.job_dt.d.next = self.req_dt.q.val();
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
                self.state.d.next = self.st_speed.val();
            }
        } else if self.speed.valid.val() {
            self.out_speed.d.next = self.speed.speed_mtc.val();
            self.out_valid.d.next = true;
            self.state.d.next = self.st_idle.val();
        }
        if self.start.val() {
            self.req_pos.d.next = self.position.val();
            self.req_m.d.next = self.mt_m.val();
            self.req_t.d.next = self.mt_t.val();
            self.req_neg.d.next = self.mt_negative.val();
            self.req_dt.d.next = self.cfg_dt.val();
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
            self.out_speed.d.next = self.zero_s.val();
        }
        self.speed_mtc.next = self.out_speed.q.val();
        self.valid.next = self.out_valid.q.val();
    }
}
