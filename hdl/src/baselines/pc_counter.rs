// SPDX-License-Identifier: MIT OR Apache-2.0
//! Fixed-time (PC) counter: net signed steps in consecutive windows of `cfg_dt` cycles of
//! a free-running time base. Bit-true model:
//! [`golden::baselines::pc_counter::PcCounter`], whose module docs give the semantics,
//! latency and error bound in full.
//!
//! Per clock edge (N = counter width, 2..=32):
//! - time base: [`WindowTimer`](crate::baselines::window_timer::WindowTimer), whose
//!   registered `tick` ends a window every max(`cfg_dt`, 1) edges; a change of `cfg_dt` acts
//!   one edge later. Steps never restart it (with a constant dt D the ticks are edges D,
//!   2D, … after reset);
//! - the net steps f − b of the window [tick, next tick) (forward minus backward): the step
//!   of a tick edge starts the next window (`golden::ideal::fixed_time`'s convention). A
//!   window is at most 2^N − 1 edges, so f − b fits N + 1 bits of two's complement: one
//!   up/down counter `net_lo` (N bits, one adder of ±1) and its top bit `net_hi`, which
//!   toggles on the carry (an up step from all ones) or the borrow (a down step from 0).
//!   Those two tests are flags registered with `net_lo` (`lo_all_ones`, and `lo_not_zero`
//!   stored inverted so that power-up and reset, net_lo = 0, are the flags' zero values),
//!   set from comparisons on the registers a step earlier, as the position counter does:
//!   the decoder's step is one logic level from `net_hi`'s enable (the N-bit comparisons
//!   behind the step were the core's critical path on HX8K on every seed tried);
//! - on a tick: `count` ← f − b clamped to N-bit two's complement [−2^(N−1), 2^(N−1) − 1]
//!   (`saturated` tells), `strobe` ← 1 for one cycle. The value fits when `net_hi` equals
//!   bit N − 1 of `net_lo`, else it is clamped towards its sign: the clamp needs no
//!   comparator and no negation (before, two counters, a comparison, a subtraction, a
//!   range check and a negation were chained in the tick cycle).
//!
//! Ports: `clock`, `reset` (synchronous, active high), `step`, `forward`, `backward` (from
//! the quadrature decoder; `backward` must be `step` ∧ ¬`forward`), `cfg_dt[N-1:0]`
//! (cycles; sampled at every edge, used from the next cycle on).
//! Registered outputs: `count[N-1:0]` (two's complement), `saturated`, `strobe`.
//! Latency: the count of a window is published by the window's closing tick edge (no
//! further stage). Reset clears every register.

use rust_hdl::prelude::*;

/// Fixed-time (pulse count) counter with N-bit time base and count.
#[derive(LogicBlock)]
pub struct PcCounter<const N: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// One step of the decoder.
    pub step: Signal<In, Bit>,
    /// The step is forward.
    pub forward: Signal<In, Bit>,
    /// The step is backward: `step` ∧ ¬`forward`, registered by the decoder (so that the
    /// ±1 adder's direction comes from a flip-flop, not a gate).
    pub backward: Signal<In, Bit>,
    /// Window length, clock cycles (0 counts as 1), used from the next cycle on.
    pub cfg_dt: Signal<In, Bits<N>>,
    /// Net steps of the last window, N-bit two's complement, saturating.
    pub count: Signal<Out, Bits<N>>,
    /// The last count was clamped.
    pub saturated: Signal<Out, Bit>,
    /// One cycle per window end (count written).
    pub strobe: Signal<Out, Bit>,
    /// The window time base.
    timer: crate::baselines::window_timer::WindowTimer<N>,
    /// f − b, low N bits.
    net_lo: DFF<Bits<N>>,
    /// f − b, bit N (the sign of the N + 1-bit value).
    net_hi: DFF<Bit>,
    /// `net_lo` is all ones: an up step carries into `net_hi`.
    lo_all_ones: DFF<Bit>,
    /// `net_lo` is not 0 (stored inverted): a down step borrows from `net_hi` when clear.
    lo_not_zero: DFF<Bit>,
    count_reg: DFF<Bits<N>>,
    sat_reg: DFF<Bit>,
    strobe_reg: DFF<Bit>,
    tick: Signal<Local, Bit>,
    up: Signal<Local, Bit>,
    down: Signal<Local, Bit>,
    /// +1 or −1 (all ones).
    delta: Signal<Local, Bits<N>>,
    /// `net_lo` in N-bit two's complement is `net_hi` sign-extended: f − b fits N bits.
    fits: Signal<Local, Bit>,
    zero: Constant<Bits<N>>,
    all_ones: Constant<Bits<N>>,
    /// The sign bit, and the most negative count (−2^(N−1)) a saturated window publishes.
    msb: Constant<Bits<N>>,
    one: Constant<Bits<N>>,
    /// 2^N − 2: after an up step from it, `net_lo` is all ones.
    all_ones_less_one: Constant<Bits<N>>,
    max_pos: Constant<Bits<N>>,
}

impl<const N: usize> Default for PcCounter<N> {
    fn default() -> Self {
        assert!((2..=32).contains(&N), "N outside 2..=32");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            step: Default::default(),
            forward: Default::default(),
            backward: Default::default(),
            cfg_dt: Default::default(),
            count: Default::default(),
            saturated: Default::default(),
            strobe: Default::default(),
            timer: Default::default(),
            net_lo: Default::default(),
            net_hi: Default::default(),
            lo_all_ones: Default::default(),
            lo_not_zero: Default::default(),
            count_reg: Default::default(),
            sat_reg: Default::default(),
            strobe_reg: Default::default(),
            tick: Default::default(),
            up: Default::default(),
            down: Default::default(),
            delta: Default::default(),
            fits: Default::default(),
            zero: Constant::new(0.into()),
            all_ones: Constant::new(((1u64 << N) - 1).into()),
            msb: Constant::new((1u64 << (N - 1)).into()),
            one: Constant::new(1.into()),
            all_ones_less_one: Constant::new(((1u64 << N) - 2).into()),
            max_pos: Constant::new(((1u64 << (N - 1)) - 1).into()),
        }
    }
}

impl<const N: usize> Logic for PcCounter<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            net_lo,
            net_hi,
            lo_all_ones,
            lo_not_zero,
            count_reg,
            sat_reg,
            strobe_reg
        );
        self.timer.clock.next = self.clock.val();
        self.timer.reset.next = self.reset.val();
        self.timer.cfg_dt.next = self.cfg_dt.val();
        self.tick.next = self.timer.tick.val();
        self.up.next = self.step.val() & self.forward.val();
        // `backward` is the decoder's own register of step ∧ ¬forward: the ±1 adder's
        // operand comes straight from a flip-flop.
        self.down.next = self.backward.val();
        self.delta.next = self.one.val();
        if self.down.val() {
            self.delta.next = self.all_ones.val();
        }
        self.fits.next =
            !(self.net_hi.q.val() ^ ((self.net_lo.q.val() & self.msb.val()) != self.zero.val()));
        self.strobe_reg.d.next = self.tick.val();
        if self.tick.val() {
            // Publish the window that ends now; the step of this edge starts the next one.
            self.count_reg.d.next = self.net_lo.q.val();
            self.sat_reg.d.next = !self.fits.val();
            if !self.fits.val() {
                self.count_reg.d.next = self.max_pos.val();
                if self.net_hi.q.val() {
                    self.count_reg.d.next = self.msb.val();
                }
            }
            self.net_lo.d.next = self.zero.val();
            self.net_hi.d.next = false;
            self.lo_all_ones.d.next = false;
            self.lo_not_zero.d.next = false;
            if self.up.val() {
                self.net_lo.d.next = self.one.val();
                self.lo_not_zero.d.next = true;
            }
            if self.down.val() {
                self.net_lo.d.next = self.all_ones.val();
                self.net_hi.d.next = true;
                self.lo_all_ones.d.next = true;
                self.lo_not_zero.d.next = true;
            }
        } else if self.step.val() {
            self.net_lo.d.next = self.net_lo.q.val() + self.delta.val();
            // The carry out of all ones, or the borrow from 0, flips bit N. The flags of the
            // new `net_lo` come from comparisons on the registers: after an up step it is
            // all ones when it was 2^N − 2 and not 0 unless it was all ones; after a down
            // step it is all ones when it was 0 and 0 when it was 1. (Read from the adder's
            // carry out, the wrap sat behind the whole carry chain and two more LUTs: 73-89
            // MHz on HX8K; compared in the step's cycle, five LUT levels behind the step.)
            if (self.up.val() & self.lo_all_ones.q.val())
                | (self.down.val() & !self.lo_not_zero.q.val())
            {
                self.net_hi.d.next = !self.net_hi.q.val();
            }
            if self.up.val() {
                self.lo_all_ones.d.next = self.net_lo.q.val() == self.all_ones_less_one.val();
                self.lo_not_zero.d.next = !self.lo_all_ones.q.val();
            } else {
                self.lo_all_ones.d.next = !self.lo_not_zero.q.val();
                self.lo_not_zero.d.next = self.net_lo.q.val() != self.one.val();
            }
        }
        if self.reset.val() {
            self.net_lo.d.next = self.zero.val();
            self.net_hi.d.next = false;
            self.lo_all_ones.d.next = false;
            self.lo_not_zero.d.next = false;
            self.count_reg.d.next = self.zero.val();
            self.sat_reg.d.next = false;
            self.strobe_reg.d.next = false;
        }
        self.count.next = self.count_reg.q.val();
        self.saturated.next = self.sat_reg.q.val();
        self.strobe.next = self.strobe_reg.q.val();
    }
}

/// The Verilog of a [`PcCounter`], top module named `module_name`.
pub fn pc_counter_verilog<const N: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<PcCounter<N>>(module_name)
}
