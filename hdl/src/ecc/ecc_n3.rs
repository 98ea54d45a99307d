// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's n3 with the eccentricity correction of its span. Bit-true model:
//! [`golden::ecc::ecc_n3`], whose module docs give the rule (n3·(1 − δ) when Nep1 = 1, n3 − δ
//! when Nep1 ≥ 2 and Ndt1 = 1, n3 otherwise, on the magnitude, clamped, sign put back), the
//! timing and the hardware algorithm.
//!
//! Ports: `clock`, `reset` (synchronous, active high), `start`, `n3[S-1:0]` (two's
//! complement, units of 2^−16 decoder step per dt), `nep_is_one`, `ndt_is_one`,
//! `delta[39:0]` (two's complement, units of 2^−16 decoder step); registered outputs
//! `n3c[S-1:0]`, `valid` (one cycle), `busy`. Latency [`golden::ecc::ecc_n3::LATENCY_CYCLES`] =
//! 20 edges from a start while idle. S = N + 17 for N-bit counters (25..=49).
//!
//! Everything wider than S is done in 64-bit locals (|n3| < 2^48, |δ| < 2^39: no wrap), and
//! widths change by shifting bits in at the top (the style of `ecc_mt_speed.rs`): rust-hdl
//! emits casts between widths badly (docs/design-decisions.md#rust-hdl-rules, D7 and R3).

use golden::ecc::ecc_delta::DELTA_BITS;
use golden::ecc::ecc_n3::MUL_STEPS;
use rust_hdl::prelude::*;

const D: usize = DELTA_BITS as usize;
const Q: usize = MUL_STEPS as usize;

/// The corrector (module docs).
#[derive(LogicBlock)]
pub struct EccN3<const S: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Latch a request.
    pub start: Signal<In, Bit>,
    /// n3 from the speed calculator, steps per dt, 16 fractional bits, signed.
    pub n3: Signal<In, Bits<S>>,
    /// Nep1 = 1 for the registers n3 was computed from.
    pub nep_is_one: Signal<In, Bit>,
    /// Ndt1 = 1 for the registers n3 was computed from.
    pub ndt_is_one: Signal<In, Bit>,
    /// δ of the span in the order of motion, steps, 16 fractional bits, signed.
    pub delta: Signal<In, Bits<D>>,
    /// Corrected n3, same format as `n3`; held between results.
    pub n3c: Signal<Out, Bits<S>>,
    /// One cycle: `n3c` is new.
    pub valid: Signal<Out, Bit>,
    /// A computation runs or a request is pending.
    pub busy: Signal<Out, Bit>,
    req_n3: DFF<Bits<S>>,
    req_nep1: DFF<Bit>,
    req_ndt1: DFF<Bit>,
    req_delta: DFF<Bits<D>>,
    pending: DFF<Bit>,
    running: DFF<Bit>,
    count: DFF<Bits<5>>,
    w_neg: DFF<Bit>,
    w_zero: DFF<Bit>,
    w_mul: DFF<Bit>,
    w_sub: DFF<Bit>,
    w_mag: DFF<Bits<S>>,
    w_diff: DFF<Bits<S>>,
    mul_a: DFF<Bits<S>>,
    mul_q: DFF<Bits<Q>>,
    out_reg: DFF<Bits<S>>,
    valid_reg: DFF<Bit>,
    take: Signal<Local, Bit>,
    neg: Signal<Local, Bit>,
    mag_raw: Signal<Local, Bits<S>>,
    mag: Signal<Local, Bits<S>>,
    d_top: Signal<Local, Bits<64>>,
    d64: Signal<Local, Bits<64>>,
    dn64: Signal<Local, Bits<64>>,
    m_top: Signal<Local, Bits<64>>,
    m64: Signal<Local, Bits<64>>,
    diff64: Signal<Local, Bits<64>>,
    diff: Signal<Local, Bits<S>>,
    t64: Signal<Local, Bits<64>>,
    f: Signal<Local, Bits<Q>>,
    sum: Signal<Local, Bits<S>>,
    q_ext: Signal<Local, Bits<S>>,
    rounded: Signal<Local, Bits<S>>,
    product: Signal<Local, Bits<S>>,
    result: Signal<Local, Bits<S>>,
    s_zero: Constant<Bits<S>>,
    s_msb: Constant<Bits<S>>,
    s_max: Constant<Bits<S>>,
    s_quarter: Constant<Bits<S>>,
    s_half_lsb: Constant<Bits<S>>,
    w_zero64: Constant<Bits<64>>,
    w_msb: Constant<Bits<64>>,
    w_max: Constant<Bits<64>>,
    w_unit: Constant<Bits<64>>,
    w_two_units: Constant<Bits<64>>,
    q_zero: Constant<Bits<Q>>,
    q_msb: Constant<Bits<Q>>,
    q_two_units: Constant<Bits<Q>>,
    d_zero: Constant<Bits<D>>,
    d_msb: Constant<Bits<D>>,
    c_zero: Constant<Bits<5>>,
    c_one: Constant<Bits<5>>,
    c_steps: Constant<Bits<5>>,
    sh_one: Constant<Bits<8>>,
    sh_two: Constant<Bits<8>>,
    sh_sixteen: Constant<Bits<8>>,
    sh_m: Constant<Bits<8>>,
    sh_q: Constant<Bits<8>>,
}

impl<const S: usize> Default for EccN3<S> {
    fn default() -> Self {
        assert!((25..=49).contains(&S), "EccN3: S = {S} outside 25..=49");
        let max = (1u64 << (S - 1)) - 1;
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            n3: Default::default(),
            nep_is_one: Default::default(),
            ndt_is_one: Default::default(),
            delta: Default::default(),
            n3c: Default::default(),
            valid: Default::default(),
            busy: Default::default(),
            req_n3: Default::default(),
            req_nep1: Default::default(),
            req_ndt1: Default::default(),
            req_delta: Default::default(),
            pending: Default::default(),
            running: Default::default(),
            count: Default::default(),
            w_neg: Default::default(),
            w_zero: Default::default(),
            w_mul: Default::default(),
            w_sub: Default::default(),
            w_mag: Default::default(),
            w_diff: Default::default(),
            mul_a: Default::default(),
            mul_q: Default::default(),
            out_reg: Default::default(),
            valid_reg: Default::default(),
            take: Default::default(),
            neg: Default::default(),
            mag_raw: Default::default(),
            mag: Default::default(),
            d_top: Default::default(),
            d64: Default::default(),
            dn64: Default::default(),
            m_top: Default::default(),
            m64: Default::default(),
            diff64: Default::default(),
            diff: Default::default(),
            t64: Default::default(),
            f: Default::default(),
            sum: Default::default(),
            q_ext: Default::default(),
            rounded: Default::default(),
            product: Default::default(),
            result: Default::default(),
            s_zero: Constant::new(0.into()),
            s_msb: Constant::new((1u64 << (S - 1)).into()),
            s_max: Constant::new(max.into()),
            // 4·A overflows the magnitude from A = 2^(S−3) on.
            s_quarter: Constant::new((1u64 << (S - 3)).into()),
            s_half_lsb: Constant::new((1u64 << 15).into()),
            w_zero64: Constant::new(0.into()),
            w_msb: Constant::new((1u64 << 63).into()),
            w_max: Constant::new(max.into()),
            w_unit: Constant::new((1u64 << 16).into()),
            w_two_units: Constant::new((1u64 << 17).into()),
            q_zero: Constant::new(0.into()),
            q_msb: Constant::new((1u64 << (Q - 1)).into()),
            q_two_units: Constant::new((1u64 << 17).into()),
            d_zero: Constant::new(0.into()),
            d_msb: Constant::new((1u64 << (D - 1)).into()),
            c_zero: Constant::new(0.into()),
            c_one: Constant::new(1.into()),
            c_steps: Constant::new((Q as u64).into()),
            sh_one: Constant::new(1.into()),
            sh_two: Constant::new(2.into()),
            sh_sixteen: Constant::new(16.into()),
            sh_m: Constant::new(((64 - S) as u64).into()),
            sh_q: Constant::new(((S - Q) as u64).into()),
        }
    }
}

impl<const S: usize> Logic for EccN3<S> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, req_n3, req_nep1, req_ndt1, req_delta, pending, running, count, w_neg,
            w_zero, w_mul, w_sub, w_mag, w_diff, mul_a, mul_q, out_reg, valid_reg
        );
        self.take.next = self.pending.q.val() & !self.running.q.val();

        // The request's magnitude m (the most negative value saturates to max).
        self.neg.next = (self.req_n3.q.val() & self.s_msb.val()) != self.s_zero.val();
        self.mag_raw.next = self.req_n3.q.val();
        if self.neg.val() {
            self.mag_raw.next = self.s_zero.val() - self.req_n3.q.val();
        }
        self.mag.next = self.mag_raw.val();
        if self.mag_raw.val() > self.s_max.val() {
            self.mag.next = self.s_max.val();
        }
        // d = ±δ in 64 bits: δ's bits shifted in at the top, then copies of its sign.
        self.d_top.next = self.w_zero64.val();
        for i in 0..D {
            if self.req_delta.q.val().get_bit(i) {
                self.d_top.next = (self.d_top.val() >> self.sh_one.val()) | self.w_msb.val();
            } else {
                self.d_top.next = self.d_top.val() >> self.sh_one.val();
            }
        }
        self.d64.next = self.d_top.val();
        for _i in 0..(64 - D) {
            if (self.req_delta.q.val() & self.d_msb.val()) != self.d_zero.val() {
                self.d64.next = (self.d64.val() >> self.sh_one.val()) | self.w_msb.val();
            } else {
                self.d64.next = self.d64.val() >> self.sh_one.val();
            }
        }
        self.dn64.next = self.d64.val();
        if self.neg.val() {
            self.dn64.next = self.w_zero64.val() - self.d64.val();
        }
        // m in 64 bits.
        self.m_top.next = self.w_zero64.val();
        for i in 0..S {
            if self.mag.val().get_bit(i) {
                self.m_top.next = (self.m_top.val() >> self.sh_one.val()) | self.w_msb.val();
            } else {
                self.m_top.next = self.m_top.val() >> self.sh_one.val();
            }
        }
        self.m64.next = self.m_top.val() >> self.sh_m.val();
        // Nep1 ≥ 2, Ndt1 = 1: clamp(m − d, 0, max), back to S bits.
        self.diff64.next = self.m64.val() - self.dn64.val();
        if (self.diff64.val() & self.w_msb.val()) != self.w_zero64.val() {
            self.diff64.next = self.w_zero64.val();
        } else if self.diff64.val() > self.w_max.val() {
            self.diff64.next = self.w_max.val();
        }
        self.diff.next = self.s_zero.val();
        for i in 0..S {
            if self.diff64.val().get_bit(i) {
                self.diff.next = (self.diff.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.diff.next = self.diff.val() >> self.sh_one.val();
            }
        }
        // Nep1 = 1: the factor f = clamp(2^16 − d, 0, 2^17) in Q bits.
        self.t64.next = self.w_unit.val() - self.dn64.val();
        self.f.next = self.q_zero.val();
        for i in 0..Q {
            if self.t64.val().get_bit(i) {
                self.f.next = (self.f.val() >> self.sh_one.val()) | self.q_msb.val();
            } else {
                self.f.next = self.f.val() >> self.sh_one.val();
            }
        }
        if (self.t64.val() & self.w_msb.val()) != self.w_zero64.val() {
            self.f.next = self.q_zero.val();
        } else if self.t64.val() > self.w_two_units.val() {
            self.f.next = self.q_two_units.val();
        }

        // Multiplier step: {A, Q} ← ({A + (Q bit 0 ? m : 0)} : Q) >> 1 (A + m < 2^S).
        self.sum.next = self.mul_a.q.val();
        if self.mul_q.q.val().get_bit(0) {
            self.sum.next = self.mul_a.q.val() + self.w_mag.q.val();
        }
        // Finish: 4·A + ⌊(Q + 2^15)/2^16⌋, saturated.
        self.q_ext.next = self.s_zero.val();
        for i in 0..Q {
            if self.mul_q.q.val().get_bit(i) {
                self.q_ext.next = (self.q_ext.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.q_ext.next = self.q_ext.val() >> self.sh_one.val();
            }
        }
        self.rounded.next = ((self.q_ext.val() >> self.sh_q.val()) + self.s_half_lsb.val())
            >> self.sh_sixteen.val();
        self.product.next = (self.mul_a.q.val() << self.sh_two.val()) + self.rounded.val();
        if (self.mul_a.q.val() >= self.s_quarter.val()) | (self.product.val() > self.s_max.val()) {
            self.product.next = self.s_max.val();
        }
        self.result.next = self.w_mag.q.val();
        if self.w_zero.q.val() {
            self.result.next = self.s_zero.val();
        } else if self.w_mul.q.val() {
            self.result.next = self.product.val();
        } else if self.w_sub.q.val() {
            self.result.next = self.w_diff.q.val();
        }

        self.valid_reg.d.next = false;
        if self.running.q.val() {
            if self.count.q.val() == self.c_zero.val() {
                self.out_reg.d.next = self.result.val();
                if self.w_neg.q.val() {
                    self.out_reg.d.next = self.s_zero.val() - self.result.val();
                }
                self.valid_reg.d.next = true;
                self.running.d.next = false;
            } else {
                self.mul_a.d.next = self.sum.val() >> self.sh_one.val();
                self.mul_q.d.next = self.mul_q.q.val() >> self.sh_one.val();
                if self.sum.val().get_bit(0) {
                    self.mul_q.d.next =
                        (self.mul_q.q.val() >> self.sh_one.val()) | self.q_msb.val();
                }
                self.count.d.next = self.count.q.val() - self.c_one.val();
            }
        }
        if self.take.val() {
            self.running.d.next = true;
            self.count.d.next = self.c_steps.val();
            self.w_neg.d.next = self.neg.val();
            self.w_zero.d.next = self.mag.val() == self.s_zero.val();
            self.w_mul.d.next = self.req_nep1.q.val();
            self.w_sub.d.next = self.req_ndt1.q.val();
            self.w_mag.d.next = self.mag.val();
            self.w_diff.d.next = self.diff.val();
            self.mul_a.d.next = self.s_zero.val();
            self.mul_q.d.next = self.f.val();
        }
        self.pending.d.next = self.pending.q.val() & !self.take.val();
        if self.start.val() {
            self.req_n3.d.next = self.n3.val();
            self.req_nep1.d.next = self.nep_is_one.val();
            self.req_ndt1.d.next = self.ndt_is_one.val();
            self.req_delta.d.next = self.delta.val();
            self.pending.d.next = true;
        }
        if self.reset.val() {
            self.pending.d.next = false;
            self.running.d.next = false;
            self.out_reg.d.next = self.s_zero.val();
            self.valid_reg.d.next = false;
        }
        self.n3c.next = self.out_reg.q.val();
        self.valid.next = self.valid_reg.q.val();
        self.busy.next = self.pending.q.val() | self.running.q.val();
    }
}

/// The Verilog of an [`EccN3`], top module named `module_name`.
pub fn ecc_n3_verilog<const S: usize>(module_name: &str) -> String {
    let mut uut = EccN3::<S>::default();
    uut.connect_all();
    crate::verilog::named_verilog(&uut, module_name)
}
