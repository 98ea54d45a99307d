// SPDX-License-Identifier: MIT OR Apache-2.0
//! M/T counter (Ohmae 1982): per window of a free-running time base, m = steps since the
//! step that closed the previous measurement (the anchor) and T = cycles from the anchor to
//! the last of them; speed = m·dt/T (units of ω_lim), left to a divider downstream.
//! Bit-true model: [`golden::baselines::mt_counter::MtCounter`], whose module docs give the
//! semantics, latency and error bound in full.
//!
//! Per clock edge (N = counter width, 2..=32, max = 2^N − 1, x⁺ = min(x + 1, max)):
//! - time base: [`WindowTimer`](crate::baselines::window_timer::WindowTimer), as in
//!   [`crate::PcCounter`] (registered `tick`; a change of `cfg_dt` acts one edge later);
//! - rev = step of the other direction than the last step (a reversal), found as
//!   `first` ∧ (a step since reset): the decoder's registered `first` (the first step since
//!   reset, or a reversal) instead of a comparison of `forward` with the last direction here,
//!   which put the decoder's `forward` four logic levels from `anchored`'s enable (a
//!   critical path of the Wishbone top on the iCE40); cont = step ∧ ¬rev;
//! - the measurement including this edge: m' = cont ? m⁺ : m, span' = cont ? a⁺ : span,
//!   l' = cont ? 0 : l⁺ (a = cycles since the anchor, l = cycles since the last step);
//! - on a tick, if anchored: `strobe`, `m` ← m', `t` ← (m' ≠ 0 ? span' : l'),
//!   `negative` ← direction; if m' ≠ 0 the last step becomes the anchor (a ← l', m ← 0);
//!   after reset the first anchor is set this way without output, as in `golden::ideal::mt`;
//! - a reversal restarts the measurement on the reversing step (anchored, m = a = l = 0),
//!   after the tick of the same edge: no m ever mixes directions;
//! - `stalled` = (l = max).
//!
//! Ports: `clock`, `reset` (synchronous, active high), `step`, `forward`, `first`,
//! `cfg_dt[N-1:0]`. `first` must be the decoder's: high with `step` when no step has been
//! made since this block's reset or the step is against the last one (the core resets the
//! decoder whenever it resets this block, and no step passes between).
//! Registered outputs: `m[N-1:0]`, `t[N-1:0]` (cycles), `negative`, `strobe`, `stalled`.
//! Latency: the window's result is published by its closing tick edge. A window holds the
//! steps of the edges (tick, next tick]. Reset clears every register.

use rust_hdl::prelude::*;

/// M/T counter with N-bit time base, step count and cycle counters.
#[derive(LogicBlock)]
pub struct MtCounter<const N: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// One step of the decoder.
    pub step: Signal<In, Bit>,
    /// The step is forward.
    pub forward: Signal<In, Bit>,
    /// With `step`: the first step since reset, or a step against the last one.
    pub first: Signal<In, Bit>,
    /// Window length, clock cycles (0 counts as 1), used from the next cycle on.
    pub cfg_dt: Signal<In, Bits<N>>,
    /// Steps in the measurement (0: none since the anchor).
    pub m: Signal<Out, Bits<N>>,
    /// m ≠ 0: cycles from the anchor to the last step; m = 0: cycles since the last step.
    pub t: Signal<Out, Bits<N>>,
    /// The measurement is of backward steps.
    pub negative: Signal<Out, Bit>,
    /// One cycle per result written.
    pub strobe: Signal<Out, Bit>,
    /// No step for 2^N − 1 cycles or more.
    pub stalled: Signal<Out, Bit>,
    /// The window time base.
    timer: crate::baselines::window_timer::WindowTimer<N>,
    anchored: DFF<Bit>,
    have_dir: DFF<Bit>,
    dir: DFF<Bit>,
    m_count: DFF<Bits<N>>,
    /// m ≠ 0, kept beside `m_count` (set by a counted step, cleared where `m_count` is) so
    /// that no reduction of `m_count`'s N bits lies in front of the window-end decisions.
    m_nonzero: DFF<Bit>,
    age: DFF<Bits<N>>,
    span: DFF<Bits<N>>,
    last: DFF<Bits<N>>,
    m_reg: DFF<Bits<N>>,
    t_reg: DFF<Bits<N>>,
    neg_reg: DFF<Bit>,
    strobe_reg: DFF<Bit>,
    tick: Signal<Local, Bit>,
    rev: Signal<Local, Bit>,
    cont: Signal<Local, Bit>,
    m_inc: Signal<Local, Bits<N>>,
    age_inc: Signal<Local, Bits<N>>,
    last_inc: Signal<Local, Bits<N>>,
    m_now: Signal<Local, Bits<N>>,
    /// m' ≠ 0, from the `m_nonzero` flag or a counted step (not from m' itself: that
    /// would put the increment's carry chain in front of the window-end decisions).
    m_now_nonzero: Signal<Local, Bit>,
    span_now: Signal<Local, Bits<N>>,
    last_now: Signal<Local, Bits<N>>,
    zero: Constant<Bits<N>>,
    one: Constant<Bits<N>>,
    max: Constant<Bits<N>>,
}

impl<const N: usize> Default for MtCounter<N> {
    fn default() -> Self {
        assert!((2..=32).contains(&N), "N outside 2..=32");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            step: Default::default(),
            forward: Default::default(),
            first: Default::default(),
            cfg_dt: Default::default(),
            m: Default::default(),
            t: Default::default(),
            negative: Default::default(),
            strobe: Default::default(),
            stalled: Default::default(),
            timer: Default::default(),
            anchored: Default::default(),
            have_dir: Default::default(),
            dir: Default::default(),
            m_count: Default::default(),
            m_nonzero: Default::default(),
            age: Default::default(),
            span: Default::default(),
            last: Default::default(),
            m_reg: Default::default(),
            t_reg: Default::default(),
            neg_reg: Default::default(),
            strobe_reg: Default::default(),
            tick: Default::default(),
            rev: Default::default(),
            cont: Default::default(),
            m_inc: Default::default(),
            age_inc: Default::default(),
            last_inc: Default::default(),
            m_now: Default::default(),
            m_now_nonzero: Default::default(),
            span_now: Default::default(),
            last_now: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            max: Constant::new(((1u64 << N) - 1).into()),
        }
    }
}

impl<const N: usize> Logic for MtCounter<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, anchored, have_dir, dir, m_count, m_nonzero, age, span, last, m_reg,
            t_reg, neg_reg, strobe_reg
        );
        self.timer.clock.next = self.clock.val();
        self.timer.reset.next = self.reset.val();
        self.timer.cfg_dt.next = self.cfg_dt.val();
        self.tick.next = self.timer.tick.val();
        // Saturating increments.
        self.m_inc.next = self.m_count.q.val() + self.one.val();
        if self.m_count.q.val() == self.max.val() {
            self.m_inc.next = self.max.val();
        }
        self.age_inc.next = self.age.q.val() + self.one.val();
        if self.age.q.val() == self.max.val() {
            self.age_inc.next = self.max.val();
        }
        self.last_inc.next = self.last.q.val() + self.one.val();
        if self.last.q.val() == self.max.val() {
            self.last_inc.next = self.max.val();
        }
        // The measurement including this edge (a reversing step is not part of it).
        self.rev.next = self.first.val() & self.have_dir.q.val();
        self.cont.next = self.step.val() & !self.rev.val();
        self.m_now.next = self.m_count.q.val();
        self.span_now.next = self.span.q.val();
        self.last_now.next = self.last_inc.val();
        if self.cont.val() {
            self.m_now.next = self.m_inc.val();
            self.span_now.next = self.age_inc.val();
            self.last_now.next = self.zero.val();
        }
        self.m_now_nonzero.next = self.m_nonzero.q.val() | self.cont.val();
        // Window end, or not.
        self.strobe_reg.d.next = self.tick.val() & self.anchored.q.val();
        self.m_count.d.next = self.m_now.val();
        // A saturating increment never returns to 0: m' ≠ 0 exactly when m_now_nonzero.
        self.m_nonzero.d.next = self.m_now_nonzero.val();
        self.span.d.next = self.span_now.val();
        self.age.d.next = self.age_inc.val();
        if self.tick.val() {
            if self.anchored.q.val() {
                self.m_reg.d.next = self.m_now.val();
                self.t_reg.d.next = self.last_now.val();
                if self.m_now_nonzero.val() {
                    self.t_reg.d.next = self.span_now.val();
                }
                self.neg_reg.d.next = !self.dir.q.val();
            }
            self.m_count.d.next = self.zero.val();
            self.m_nonzero.d.next = false;
            self.span.d.next = self.zero.val();
            if self.m_now_nonzero.val() {
                self.anchored.d.next = true;
                self.age.d.next = self.last_now.val();
            }
        }
        self.last.d.next = self.last_now.val();
        // A reversal restarts the measurement on the reversing step.
        if self.rev.val() {
            self.anchored.d.next = true;
            self.m_count.d.next = self.zero.val();
            self.m_nonzero.d.next = false;
            self.age.d.next = self.zero.val();
            self.span.d.next = self.zero.val();
            self.last.d.next = self.zero.val();
        }
        if self.step.val() {
            self.have_dir.d.next = true;
            self.dir.d.next = self.forward.val();
        }
        if self.reset.val() {
            self.anchored.d.next = false;
            self.have_dir.d.next = false;
            self.dir.d.next = false;
            self.m_count.d.next = self.zero.val();
            self.m_nonzero.d.next = false;
            self.age.d.next = self.zero.val();
            self.span.d.next = self.zero.val();
            self.last.d.next = self.zero.val();
            self.m_reg.d.next = self.zero.val();
            self.t_reg.d.next = self.zero.val();
            self.neg_reg.d.next = false;
            self.strobe_reg.d.next = false;
        }
        self.m.next = self.m_reg.q.val();
        self.t.next = self.t_reg.q.val();
        self.negative.next = self.neg_reg.q.val();
        self.strobe.next = self.strobe_reg.q.val();
        self.stalled.next = self.last.q.val() == self.max.val();
    }
}

/// The Verilog of an [`MtCounter`], top module named `module_name`.
pub fn mt_counter_verilog<const N: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<MtCounter<N>>(module_name)
}
