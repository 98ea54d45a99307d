// SPDX-License-Identifier: MIT OR Apache-2.0
//! Identification gatherer: between two index (Z) pulses after `arm`, N, T_min, T_max and
//! their positions, Σ T, Σ T·sin(2πp/K) and Σ T·cos(2πp/K), with a sticky `done`. Bit-true
//! model: [`golden::ecc::ident_gatherer::IdentGatherer`], whose module docs give the semantics,
//! the widths (W = A + T + 24 accumulators, checked in the constructor) and the latency.
//!
//! Two stages, one line per clock at most (minimum line period: 1 cycle):
//! 1. edge j: `line`, `period` and `position` are registered; two [`SineRom`]s (24-bit,
//!    same contents) read S\[p\] (m0 = 0) and C\[p\] = S\[(p + K/4) mod K\] (m0 = K/4, so K
//!    must be a multiple of 4);
//! 2. edge j + 1: N, the extremes and the three sums are updated; `done` rises at the edge
//!    after the closing index.
//!
//! The two T × 24-bit signed multiply-adds are hand-written Verilog ([`IdentMac`] in `ident_mac.rs`, wider
//! than rust-hdl's 16-bit multiply) with a matching `update()`, like
//! [`EccDeltaArith`](crate::EccDeltaArith).
//!
//! Ports: `clock`, `reset` (synchronous, active high), `arm`, `index`, `line`,
//! `position[A-1:0]`, `period[T-1:0]`; registered outputs `done`, `overflow`,
//! `count[16:0]`, `t_min[T-1:0]`, `p_min[A-1:0]`, `t_max[T-1:0]`, `p_max[A-1:0]`,
//! `sum_t[W-1:0]`, `sum_sin[W-1:0]`, `sum_cos[W-1:0]`.

use crate::ecc::ident_mac::IdentMac;
use crate::ecc::sine_rom::SineRom;
use rust_hdl::prelude::*;

/// Identification gatherer with A-bit positions, T-bit periods and W = A + T + 24-bit sums
/// (module docs).
#[derive(LogicBlock)]
pub struct IdentGatherer<const A: usize, const T: usize, const W: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Start gathering at the next index.
    pub arm: Signal<In, Bit>,
    /// Z pulse (one cycle).
    pub index: Signal<In, Bit>,
    /// Line edge (one cycle).
    pub line: Signal<In, Bit>,
    /// Position of this line edge, < K.
    pub position: Signal<In, Bits<A>>,
    /// Cycles since the previous line edge.
    pub period: Signal<In, Bits<T>>,
    /// Results complete; sticky until `arm`.
    pub done: Signal<Out, Bit>,
    /// More than 2^A lines between the Z pulses (the extra lines are dropped).
    pub overflow: Signal<Out, Bit>,
    /// Lines gathered.
    pub count: Signal<Out, Bits<17>>,
    /// Shortest period.
    pub t_min: Signal<Out, Bits<T>>,
    /// Position of the edge that closed it.
    pub p_min: Signal<Out, Bits<A>>,
    /// Longest period.
    pub t_max: Signal<Out, Bits<T>>,
    /// Position of the edge that closed it.
    pub p_max: Signal<Out, Bits<A>>,
    /// Σ T, unsigned.
    pub sum_t: Signal<Out, Bits<W>>,
    /// Σ T·S, signed.
    pub sum_sin: Signal<Out, Bits<W>>,
    /// Σ T·C, signed.
    pub sum_cos: Signal<Out, Bits<W>>,
    rom_s: SineRom<A, 24>,
    rom_c: SineRom<A, 24>,
    mac: IdentMac<T, W>,
    state: DFF<Bits<2>>,
    fin: DFF<Bit>,
    pend: DFF<Bit>,
    t_reg: DFF<Bits<T>>,
    p_reg: DFF<Bits<A>>,
    done_r: DFF<Bit>,
    ovf: DFF<Bit>,
    cnt: DFF<Bits<17>>,
    tmin: DFF<Bits<T>>,
    pmin: DFF<Bits<A>>,
    tmax: DFF<Bits<T>>,
    pmax: DFF<Bits<A>>,
    st: DFF<Bits<W>>,
    ss: DFF<Bits<W>>,
    sc: DFF<Bits<W>>,
    idle_st: Constant<Bits<2>>,
    armed_st: Constant<Bits<2>>,
    gather_st: Constant<Bits<2>>,
    zero_a: Constant<Bits<A>>,
    quarter: Constant<Bits<A>>,
    zero_t: Constant<Bits<T>>,
    zero_w: Constant<Bits<W>>,
    zero17: Constant<Bits<17>>,
    one17: Constant<Bits<17>>,
    full17: Constant<Bits<17>>,
}

impl<const A: usize, const T: usize, const W: usize> IdentGatherer<A, T, W> {
    /// A gatherer for K = `lines` (a multiple of 4, 4 ≤ K ≤ 2^A; 2 ≤ A ≤ 16,
    /// 1 ≤ T ≤ 40, W = A + T + 24).
    pub fn new(lines: u32) -> Self {
        assert!((2..=16).contains(&A), "A = {A} outside 2..=16");
        assert!((1..=40).contains(&T), "T = {T} outside 1..=40");
        assert_eq!(W, A + T + 24, "W must be A + T + 24");
        assert!(
            lines >= 4 && lines.is_multiple_of(4) && u64::from(lines) <= 1 << A,
            "K = {lines}: need a multiple of 4 in 4..=2^A"
        );
        let c = |v: u64| Constant::new(v.into());
        Self {
            clock: Default::default(),
            reset: Default::default(),
            arm: Default::default(),
            index: Default::default(),
            line: Default::default(),
            position: Default::default(),
            period: Default::default(),
            done: Default::default(),
            overflow: Default::default(),
            count: Default::default(),
            t_min: Default::default(),
            p_min: Default::default(),
            t_max: Default::default(),
            p_max: Default::default(),
            sum_t: Default::default(),
            sum_sin: Default::default(),
            sum_cos: Default::default(),
            rom_s: SineRom::new(lines),
            rom_c: SineRom::new(lines),
            mac: Default::default(),
            state: Default::default(),
            fin: Default::default(),
            pend: Default::default(),
            t_reg: Default::default(),
            p_reg: Default::default(),
            done_r: Default::default(),
            ovf: Default::default(),
            cnt: Default::default(),
            tmin: Default::default(),
            pmin: Default::default(),
            tmax: Default::default(),
            pmax: Default::default(),
            st: Default::default(),
            ss: Default::default(),
            sc: Default::default(),
            idle_st: Constant::new(0u64.into()),
            armed_st: Constant::new(1u64.into()),
            gather_st: Constant::new(2u64.into()),
            zero_a: Constant::new(0u64.into()),
            quarter: Constant::new(u64::from(lines / 4).into()),
            zero_t: Constant::new(0u64.into()),
            zero_w: Constant::new(0u64.into()),
            zero17: c(0),
            one17: c(1),
            full17: c(1 << A),
        }
    }
}

impl<const A: usize, const T: usize, const W: usize> Logic for IdentGatherer<A, T, W> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, state, fin, pend, t_reg, p_reg, done_r, ovf, cnt, tmin, pmin, tmax, pmax,
            st, ss, sc
        );
        self.rom_s.clock.next = self.clock.val();
        self.rom_c.clock.next = self.clock.val();
        self.rom_s.m.next = self.position.val();
        self.rom_s.m0.next = self.zero_a.val();
        self.rom_c.m.next = self.position.val();
        self.rom_c.m0.next = self.quarter.val();
        self.mac.t.next = self.t_reg.q.val();
        self.mac.s.next = self.rom_s.data.val();
        self.mac.c.next = self.rom_c.data.val();
        self.mac.acc_t.next = self.st.q.val();
        self.mac.acc_s.next = self.ss.q.val();
        self.mac.acc_c.next = self.sc.q.val();
        // Stage 2.
        if self.pend.q.val() {
            if self.cnt.q.val() == self.full17.val() {
                self.ovf.d.next = true;
            } else {
                if (self.cnt.q.val() == self.zero17.val())
                    | (self.t_reg.q.val() < self.tmin.q.val())
                {
                    self.tmin.d.next = self.t_reg.q.val();
                    self.pmin.d.next = self.p_reg.q.val();
                }
                if (self.cnt.q.val() == self.zero17.val())
                    | (self.t_reg.q.val() > self.tmax.q.val())
                {
                    self.tmax.d.next = self.t_reg.q.val();
                    self.pmax.d.next = self.p_reg.q.val();
                }
                self.cnt.d.next = self.cnt.q.val() + self.one17.val();
                self.st.d.next = self.mac.nxt_t.val();
                self.ss.d.next = self.mac.nxt_s.val();
                self.sc.d.next = self.mac.nxt_c.val();
            }
        }
        if self.fin.q.val() {
            self.done_r.d.next = true;
        }
        // Stage 1.
        self.pend.d.next = self.line.val() & (self.state.q.val() == self.gather_st.val());
        self.t_reg.d.next = self.period.val();
        self.p_reg.d.next = self.position.val();
        self.fin.d.next = false;
        // Control.
        if self.arm.val() {
            self.state.d.next = self.armed_st.val();
            self.done_r.d.next = false;
        } else if self.index.val() {
            if self.state.q.val() == self.armed_st.val() {
                self.state.d.next = self.gather_st.val();
                self.ovf.d.next = false;
                self.cnt.d.next = self.zero17.val();
                self.tmin.d.next = self.zero_t.val();
                self.pmin.d.next = self.zero_a.val();
                self.tmax.d.next = self.zero_t.val();
                self.pmax.d.next = self.zero_a.val();
                self.st.d.next = self.zero_w.val();
                self.ss.d.next = self.zero_w.val();
                self.sc.d.next = self.zero_w.val();
            }
            if self.state.q.val() == self.gather_st.val() {
                self.state.d.next = self.idle_st.val();
                self.fin.d.next = true;
            }
        }
        if self.reset.val() {
            self.state.d.next = self.idle_st.val();
            self.fin.d.next = false;
            self.pend.d.next = false;
            self.t_reg.d.next = self.zero_t.val();
            self.p_reg.d.next = self.zero_a.val();
            self.done_r.d.next = false;
            self.ovf.d.next = false;
            self.cnt.d.next = self.zero17.val();
            self.tmin.d.next = self.zero_t.val();
            self.pmin.d.next = self.zero_a.val();
            self.tmax.d.next = self.zero_t.val();
            self.pmax.d.next = self.zero_a.val();
            self.st.d.next = self.zero_w.val();
            self.ss.d.next = self.zero_w.val();
            self.sc.d.next = self.zero_w.val();
        }
        self.done.next = self.done_r.q.val();
        self.overflow.next = self.ovf.q.val();
        self.count.next = self.cnt.q.val();
        self.t_min.next = self.tmin.q.val();
        self.p_min.next = self.pmin.q.val();
        self.t_max.next = self.tmax.q.val();
        self.p_max.next = self.pmax.q.val();
        self.sum_t.next = self.st.q.val();
        self.sum_sin.next = self.ss.q.val();
        self.sum_cos.next = self.sc.q.val();
    }
}

/// The Verilog of an [`IdentGatherer`] for K = `lines`, top module named `module_name`.
pub fn ident_gatherer_verilog<const A: usize, const T: usize, const W: usize>(
    lines: u32,
    module_name: &str,
) -> String {
    let mut uut = IdentGatherer::<A, T, W>::new(lines);
    uut.connect_all();
    crate::verilog::named_verilog(&uut, module_name)
}
