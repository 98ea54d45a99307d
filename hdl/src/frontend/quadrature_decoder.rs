// SPDX-License-Identifier: MIT OR Apache-2.0
//! Quadrature decoder: x1, x2 or x4 steps with direction, and illegal-transition detection.
//! Bit-true model: [`golden::frontend::QuadratureDecoder`].
//!
//! At each clock edge, with da = `a` ⊕ a_prev and db = `b` ⊕ b_prev (the inputs at the
//! previous edge), once primed:
//! - illegal = da ∧ db: both channels changed, the direction is unknown, no step is made;
//! - a single-channel change is forward iff a_prev = `b` (forward Gray sequence, B lagging
//!   A by 90°: (A,B) = 00 → 10 → 11 → 01 → 00);
//! - a step is made in x4 on da ⊕ db, in x2 on da ∧ ¬db, in x1 on da ∧ ¬db ∧ ¬`b` (the A
//!   edge at which B is low: A rising forward, A falling backward, one physical place per
//!   line, so a shaft dithering on it does not drift).
//!
//! Ports: `a`, `b` (filtered channels), `cfg_mode[1:0]` (0 = x1, 1 = x2, 2 = x4, 3 = x4 and
//! `mode_error`). Registered outputs: `step`, `forward` and `backward` (one cycle per step;
//! `forward` and `backward` are low without a step), `first` (with `step`: the first step since reset, or a step against
//! the last one, a reversal; low without a step), `direction` (of the last step, 1 =
//! forward), `illegal` (one cycle),
//! `illegal_seen` (sticky), `illegal_count[G-1:0]` (saturating). `mode_error` is
//! combinational from `cfg_mode`.
//!
//! Latency: one clock edge: a change on `a`/`b` sampled at edge k shows on `step` after
//! edge k.
//!
//! Start-up: the first edge after reset only loads a_prev/b_prev and sets `primed`; it
//! makes no step and no illegal transition. Reset clears every register.

use rust_hdl::prelude::*;

/// Quadrature decoder with a G-bit illegal-transition counter.
#[derive(LogicBlock)]
pub struct QuadratureDecoder<const G: usize> {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Filtered channel A.
    pub a: Signal<In, Bit>,
    /// Filtered channel B.
    pub b: Signal<In, Bit>,
    /// Decoding mode: 0 = x1, 1 = x2, 2 = x4, 3 = x4 with `mode_error`.
    pub cfg_mode: Signal<In, Bits<2>>,
    /// One cycle per step.
    pub step: Signal<Out, Bit>,
    /// With `step`: the step is forward.
    pub forward: Signal<Out, Bit>,
    /// With `step`: the first step since reset, or one against the last step.
    pub first: Signal<Out, Bit>,
    /// A backward step (`step` ∧ ¬`forward`), a register of its own: the up/down counters
    /// add −1 on it straight from a flip-flop.
    pub backward: Signal<Out, Bit>,
    /// What `first` will be after the next edge (the core registers its estimator reset
    /// from it).
    pub first_next: Signal<Out, Bit>,
    /// Direction of the last step (1 = forward).
    pub direction: Signal<Out, Bit>,
    /// One cycle per illegal transition.
    pub illegal: Signal<Out, Bit>,
    /// An illegal transition since reset.
    pub illegal_seen: Signal<Out, Bit>,
    /// Illegal transitions since reset (saturating).
    pub illegal_count: Signal<Out, Bits<G>>,
    /// `cfg_mode` is 3 (combinational).
    pub mode_error: Signal<Out, Bit>,
    a_prev: DFF<Bit>,
    b_prev: DFF<Bit>,
    primed: DFF<Bit>,
    step_reg: DFF<Bit>,
    forward_reg: DFF<Bit>,
    backward_reg: DFF<Bit>,
    direction_reg: DFF<Bit>,
    /// A step since reset: `direction_reg` holds a real direction.
    have_step: DFF<Bit>,
    first_reg: DFF<Bit>,
    illegal_reg: DFF<Bit>,
    seen_reg: DFF<Bit>,
    count_reg: DFF<Bits<G>>,
    da: Signal<Local, Bit>,
    db: Signal<Local, Bit>,
    moved: Signal<Local, Bit>,
    step_now: Signal<Local, Bit>,
    illegal_now: Signal<Local, Bit>,
    forward_now: Signal<Local, Bit>,
    first_now: Signal<Local, Bit>,
    mode_x1: Constant<Bits<2>>,
    mode_x2: Constant<Bits<2>>,
    mode_invalid: Constant<Bits<2>>,
    count_zero: Constant<Bits<G>>,
    count_one: Constant<Bits<G>>,
    count_max: Constant<Bits<G>>,
}

impl<const G: usize> Default for QuadratureDecoder<G> {
    fn default() -> Self {
        assert!((1..=32).contains(&G), "width 1..=32");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            a: Default::default(),
            b: Default::default(),
            cfg_mode: Default::default(),
            step: Default::default(),
            forward: Default::default(),
            first: Default::default(),
            backward: Default::default(),
            backward_reg: Default::default(),
            first_next: Default::default(),
            first_now: Default::default(),
            direction: Default::default(),
            illegal: Default::default(),
            illegal_seen: Default::default(),
            illegal_count: Default::default(),
            mode_error: Default::default(),
            a_prev: Default::default(),
            b_prev: Default::default(),
            primed: Default::default(),
            step_reg: Default::default(),
            forward_reg: Default::default(),
            direction_reg: Default::default(),
            have_step: Default::default(),
            first_reg: Default::default(),
            illegal_reg: Default::default(),
            seen_reg: Default::default(),
            count_reg: Default::default(),
            da: Default::default(),
            db: Default::default(),
            moved: Default::default(),
            step_now: Default::default(),
            illegal_now: Default::default(),
            forward_now: Default::default(),
            mode_x1: Constant::new(u64::from(golden::frontend::MODE_X1).into()),
            mode_x2: Constant::new(u64::from(golden::frontend::MODE_X2).into()),
            mode_invalid: Constant::new(u64::from(golden::frontend::MODE_INVALID).into()),
            count_zero: Constant::new(0.into()),
            count_one: Constant::new(1.into()),
            count_max: Constant::new(((1u64 << G) - 1).into()),
        }
    }
}

impl<const G: usize> Logic for QuadratureDecoder<G> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            a_prev,
            b_prev,
            primed,
            step_reg,
            forward_reg,
            backward_reg,
            direction_reg,
            have_step,
            first_reg,
            illegal_reg,
            seen_reg,
            count_reg
        );
        self.da.next = self.a.val() ^ self.a_prev.q.val();
        self.db.next = self.b.val() ^ self.b_prev.q.val();
        // x4 (and the invalid mode 3): exactly one channel changed.
        self.moved.next = self.da.val() ^ self.db.val();
        if self.cfg_mode.val() == self.mode_x2.val() {
            self.moved.next = self.da.val() & !self.db.val();
        }
        if self.cfg_mode.val() == self.mode_x1.val() {
            self.moved.next = self.da.val() & !self.db.val() & !self.b.val();
        }
        self.step_now.next = self.primed.q.val() & self.moved.val();
        self.illegal_now.next = self.primed.q.val() & self.da.val() & self.db.val();
        // Forward iff a_prev = b.
        self.forward_now.next = !(self.a_prev.q.val() ^ self.b.val());
        self.a_prev.d.next = self.a.val();
        self.b_prev.d.next = self.b.val();
        self.primed.d.next = true;
        self.step_reg.d.next = self.step_now.val();
        self.forward_reg.d.next = self.step_now.val() & self.forward_now.val();
        self.backward_reg.d.next = self.step_now.val() & !self.forward_now.val();
        // `first` is found here, a register, rather than by the core from `step` and
        // `forward`: it restarts the estimator, the widest fan-out after the reset.
        self.first_now.next = self.step_now.val()
            & (!self.have_step.q.val() | (self.forward_now.val() ^ self.direction_reg.q.val()))
            & !self.reset.val();
        self.first_reg.d.next = self.first_now.val();
        if self.step_now.val() {
            self.direction_reg.d.next = self.forward_now.val();
            self.have_step.d.next = true;
        }
        self.illegal_reg.d.next = self.illegal_now.val();
        if self.illegal_now.val() {
            self.seen_reg.d.next = true;
            if self.count_reg.q.val() != self.count_max.val() {
                self.count_reg.d.next = self.count_reg.q.val() + self.count_one.val();
            }
        }
        if self.reset.val() {
            self.a_prev.d.next = false;
            self.b_prev.d.next = false;
            self.primed.d.next = false;
            self.step_reg.d.next = false;
            self.forward_reg.d.next = false;
            self.backward_reg.d.next = false;
            self.direction_reg.d.next = false;
            self.have_step.d.next = false;
            self.illegal_reg.d.next = false;
            self.seen_reg.d.next = false;
            self.count_reg.d.next = self.count_zero.val();
        }
        self.step.next = self.step_reg.q.val();
        self.forward.next = self.forward_reg.q.val();
        self.backward.next = self.backward_reg.q.val();
        self.first.next = self.first_reg.q.val();
        self.first_next.next = self.first_now.val();
        self.direction.next = self.direction_reg.q.val();
        self.illegal.next = self.illegal_reg.q.val();
        self.illegal_seen.next = self.seen_reg.q.val();
        self.illegal_count.next = self.count_reg.q.val();
        self.mode_error.next = self.cfg_mode.val() == self.mode_invalid.val();
    }
}

/// The Verilog of a [`QuadratureDecoder`], top module named `module_name`.
pub fn quadrature_decoder_verilog<const G: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<QuadratureDecoder<G>>(module_name)
}
