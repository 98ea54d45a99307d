//! The eccentricity-corrected M/T speed of each window the core's M/T counter closes: the
//! span of the window from its last step's position and its step count, δ of that span
//! ([`crate::EccDelta`]), and ±(m − δ)·dt·2^(F−s)/t ([`crate::EccMtSpeed`]). Bit-true model,
//! value, span rule and latency: [`golden::mt_corrector`].
//!
//! ```text
//! start ─ request ─ take ─ m mod R (N steps) ─ span ─ EccDelta (68) ─ EccMtSpeed (2N+F+4) ─ speed_mtc
//! ```
//!
//! One job at a time, so the two arithmetic blocks are always idle when started; a start
//! while busy waits in the one-deep request register (the latest wins), as everywhere in the
//! core. The remainder m mod R (R = steps per revolution) is a restoring subtraction of
//! R·2^k for k = N − 1 … 0, so windows of more than a revolution get their exact span.
//!
//! Ports: `clock`, `reset` (synchronous, active high), `start`, `position[31:0]` (the
//! window's last step), `mt_m`, `mt_t`, `cfg_dt` (N bits), `mt_negative`, `shift[1:0]`,
//! `counts_per_rev[31:0]` (R), `coef_c`, `coef_d` (Q15.16 lines) in; registered
//! `speed_mtc[S-1:0]` (held) and `valid` (one cycle) out.

use crate::ecc_delta::EccDelta;
use crate::ecc_mt_speed::EccMtSpeed;
use golden::params::POSITION_BITS;
use rust_hdl::prelude::*;

const C: usize = POSITION_BITS as usize;
/// Address bits of the sine table: every K ≤ 2^16 (the table has K entries).
pub const TABLE_A: usize = 16;
/// Width of the sine table's entries.
pub const TABLE_D: usize = golden::ecc_top::TABLE_DATA_BITS as usize;
const W: usize = 64;

/// The corrector for N-bit counters, F fractional bits, S = N + F + 1, CW = the corrected
/// count's width ([`crate::ecc_mt_speed::corrected_width`]).
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
    delta: EccDelta<TABLE_A, TABLE_D>,
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
    state: DFF<Bits<3>>,
    count: DFF<Bits<8>>,
    rem: DFF<Bits<W>>,
    div: DFF<Bits<W>>,
    out_speed: DFF<Bits<S>>,
    out_valid: DFF<Bit>,
    m_wide: Signal<Local, Bits<W>>,
    cpr_wide: Signal<Local, Bits<W>>,
    rem_low: Signal<Local, Bits<C>>,
    pos_33: Signal<Local, Bits<33>>,
    rem_33: Signal<Local, Bits<33>>,
    cpr_33: Signal<Local, Bits<33>>,
    down: Signal<Local, Bits<33>>,
    up: Signal<Local, Bits<33>>,
    lo: Signal<Local, Bits<33>>,
    hi: Signal<Local, Bits<33>>,
    st_idle: Constant<Bits<3>>,
    st_rem: Constant<Bits<3>>,
    st_span: Constant<Bits<3>>,
    st_delta: Constant<Bits<3>>,
    st_speed: Constant<Bits<3>>,
    n_steps: Constant<Bits<8>>,
    one8: Constant<Bits<8>>,
    sh_init: Constant<Bits<8>>,
    sh_one64: Constant<Bits<W>>,
    sh_one33: Constant<Bits<33>>,
    zero_s: Constant<Bits<S>>,
}

impl<const N: usize, const F: usize, const S: usize, const CW: usize> MtCorrector<N, F, S, CW> {
    /// The corrector for a disc of `lines` lines (a multiple of 4, 4..=65536: the sine
    /// table's rule, `golden::ecc_delta::check_params`).
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
            delta: EccDelta::new(lines),
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
            count: Default::default(),
            rem: Default::default(),
            div: Default::default(),
            out_speed: Default::default(),
            out_valid: Default::default(),
            m_wide: Default::default(),
            cpr_wide: Default::default(),
            rem_low: Default::default(),
            pos_33: Default::default(),
            rem_33: Default::default(),
            cpr_33: Default::default(),
            down: Default::default(),
            up: Default::default(),
            lo: Default::default(),
            hi: Default::default(),
            st_idle: Constant::new(0.into()),
            st_rem: Constant::new(1.into()),
            st_span: Constant::new(2.into()),
            st_delta: Constant::new(3.into()),
            st_speed: Constant::new(4.into()),
            n_steps: Constant::new((N as u64).into()),
            one8: Constant::new(1.into()),
            sh_init: Constant::new((N as u64 - 1).into()),
            sh_one64: Constant::new(1.into()),
            sh_one33: Constant::new(1.into()),
            zero_s: Constant::new(0.into()),
        }
    }
}

impl<const N: usize, const F: usize, const S: usize, const CW: usize> Logic
    for MtCorrector<N, F, S, CW>
{
    #[hdl_gen]
    fn update(&mut self) {
        clock!(self, clock, delta, speed);
        dff_setup!(
            self, clock, req_pos, req_m, req_t, req_neg, req_dt, req_shift, req_cpr, req_c, req_d,
            pending, job_pos, job_m, job_t, job_neg, job_dt, job_shift, job_cpr, job_c, job_d,
            state, count, rem, div, out_speed, out_valid
        );
        self.out_valid.d.next = false;
        self.delta.reset.next = self.reset.val();
        self.speed.reset.next = self.reset.val();

        // The span of the job (valid in the span state): positions increase from lo to hi.
        self.rem_low.next = bit_cast::<C, W>(self.rem.q.val());
        self.pos_33.next = bit_cast::<33, C>(self.job_pos.q.val());
        self.rem_33.next = bit_cast::<33, C>(self.rem_low.val());
        self.cpr_33.next = bit_cast::<33, C>(self.job_cpr.q.val());
        self.down.next = (self.pos_33.val() + self.cpr_33.val()) - self.rem_33.val();
        if self.pos_33.val() >= self.rem_33.val() {
            self.down.next = self.pos_33.val() - self.rem_33.val();
        }
        self.up.next = self.pos_33.val() + self.rem_33.val();
        if self.up.val() >= self.cpr_33.val() {
            self.up.next = self.up.val() - self.cpr_33.val();
        }
        self.lo.next = self.down.val();
        self.hi.next = self.pos_33.val();
        if self.job_neg.q.val() {
            self.lo.next = self.pos_33.val();
            self.hi.next = self.up.val();
        }
        self.delta.start.next = self.state.q.val() == self.st_span.val();
        self.delta.p_a.next = self.lo.val() << self.sh_one33.val();
        self.delta.p_b.next = self.hi.val() << self.sh_one33.val();
        self.delta.shift.next = self.job_shift.q.val();
        self.delta.coef_c.next = self.job_c.q.val();
        self.delta.coef_d.next = self.job_d.q.val();

        // δ in hand: the speed of the corrected count.
        self.speed.start.next =
            (self.state.q.val() == self.st_delta.val()) & self.delta.valid.val();
        self.speed.mt_m.next = self.job_m.q.val();
        self.speed.mt_t.next = self.job_t.q.val();
        self.speed.mt_negative.next = self.job_neg.q.val();
        self.speed.ecc_delta.next = self.delta.delta.val();
        self.speed.cfg_dt.next = self.job_dt.q.val();
        self.speed.mode_shift.next = self.job_shift.q.val();

        self.m_wide.next = bit_cast::<W, N>(self.job_m.q.val());
        self.cpr_wide.next = bit_cast::<W, C>(self.job_cpr.q.val());
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
                self.count.d.next = self.n_steps.val();
                self.state.d.next = self.st_rem.val();
            }
        } else if self.state.q.val() == self.st_rem.val() {
            // m mod R: subtract R·2^k where it fits, k = N − 1 … 0 (first step: load).
            if self.count.q.val() == self.n_steps.val() {
                self.rem.d.next = self.m_wide.val();
                self.div.d.next = self.cpr_wide.val() << self.sh_init.val();
                if self.m_wide.val() >= (self.cpr_wide.val() << self.sh_init.val()) {
                    self.rem.d.next =
                        self.m_wide.val() - (self.cpr_wide.val() << self.sh_init.val());
                }
            } else {
                if self.rem.q.val() >= self.div.q.val() {
                    self.rem.d.next = self.rem.q.val() - self.div.q.val();
                }
            }
            self.div.d.next = self.div.q.val() >> self.sh_one64.val();
            if self.count.q.val() == self.n_steps.val() {
                self.div.d.next =
                    (self.cpr_wide.val() << self.sh_init.val()) >> self.sh_one64.val();
            }
            self.count.d.next = self.count.q.val() - self.one8.val();
            if self.count.q.val() == self.one8.val() {
                self.state.d.next = self.st_span.val();
            }
        } else if self.state.q.val() == self.st_span.val() {
            self.state.d.next = self.st_delta.val();
        } else if self.state.q.val() == self.st_delta.val() {
            if self.delta.valid.val() {
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
