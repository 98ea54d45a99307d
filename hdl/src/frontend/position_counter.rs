// SPDX-License-Identifier: MIT OR Apache-2.0
//! Position counter modulo the counts per revolution, with index (Z) reset/latch and a
//! check of the count of every revolution. Bit-true model:
//! [`golden::frontend::PositionCounter`].
//!
//! Per clock edge (R = counts per revolution, 2^C allowed; the ports carry limit = R − 1,
//! R − 2 and R − 3, all mod 2^C, which the core has as constants for each decoding mode):
//! 1. Index: rise = z_delay ∧ ¬z_prev, where z_delay is `z` one edge ago and z_prev two. The
//!    extra delay matches the decoder's latency: `z` is taken in the timing of the decoder's
//!    `a`/`b` inputs, so the index edge and the step of the same encoder transition are
//!    processed at the same edge. Both flops reset high: no index edge is seen before two
//!    real samples of `z` have been compared.
//! 2. Stepped position p: forward from p = limit to 0, else p + 1; backward from p = 0 to
//!    limit, else p − 1. The wrap is the definition of the angle, not an overflow. R may
//!    change only at a reset edge (the core changes it only with the decoding mode, which
//!    resets the core), so p ≤ limit always holds. The two tests are registered flags
//!    (`at_zero`, `at_limit`) set for the next position from equalities on the registers
//!    (p = 1, p = R − 2, R = 1), so that no comparison's carry chain lies in front of the
//!    position's incrementer: the position register is one adder away from itself. The
//!    ±1 itself is two carry chains of half the width side by side: the low ⌈C/2⌉ bits,
//!    and the high bits plus the carry or minus the borrow of the low half, which are two
//!    more registered flags (low half all ones, low half 0) set the same way and added as
//!    the high half's second operand (selecting high + 1 or high − 1 after the chain put
//!    one more LUT level between the chain and the position's multiplexer). A 32-bit
//!    chain from a register that fans out across the core was the slowest path of the
//!    core on the iCE40. The positions after a forward and after a backward step, and
//!    their flags, are formed from registers only; the decoder's step and direction then
//!    enable the registers and pick one of the two (when the step was one input of a
//!    multiplexer tree shared with the index latch, the decoder's registers were five
//!    logic levels from the position register, the core's critical path).
//! 3. On rise: `cfg_z_mode` 2 or 3 latches p (this edge's step included) into `z_latch`;
//!    `cfg_z_mode` 1 or 3 sets the position to 0 instead of p; `index` is high after the edge.
//! 4. Revolution check. The steps since the last index edge are counted (saturating one
//!    past 2^C: a C-bit count of steps − 1 and an overflow bit) and a "mixed" bit, set by a
//!    step that is the decoder's `first` (a reversal) after an earlier step of the
//!    interval: a step against the interval's first direction makes one, and the decoder's
//!    register stands in for a comparison of `forward` with the first direction, which put
//!    the decoder's `forward` five logic levels from the error counter's enable (a critical
//!    path of `encspeed_wb`). The step of an index edge's cycle belongs to the interval that
//!    edge closes. At a rise after an earlier one (`armed`), with `cfg_z_mode` ≠ 0, an
//!    interval with steps of one direction only whose count is not R sets `rev_error`
//!    (sticky) and increments `rev_error_count` (saturating). An interval with a reversal is
//!    not checked (a shaft swinging back across the index), nor one without steps (index
//!    noise at rest); for a fault-free encoder a one-direction interval always has exactly
//!    R steps, because the index rises on entering the Z window from either side. The
//!    count's comparisons (= 2^C − 1, = limit, = limit − 1) are flags registered with it and
//!    set from comparisons on the registers a step earlier (which is why the block takes
//!    R − 3): the decoder's step only chooses among flags, a few logic levels from the error
//!    counter, where a C-bit comparison behind the step's multiplexer was the core's
//!    slowest path on the iCE40.
//!
//! Ports: `step`, `forward`, `first` (from the decoder: `first` is high with `step` when
//! no step has been made since this block's reset or the step is against the last one; the
//! core resets the decoder with this block), `z` (filtered index level, one cycle ahead
//! of `step`), `limit[C-1:0]` (R − 1), `limit_less_one[C-1:0]` (R − 2), `limit_less_two[C-1:0]` (R − 3), `cfg_z_mode[1:0]`
//! (0 ignore, 1 reset, 2 latch, 3 latch then reset). Registered outputs: `position[C-1:0]`, `z_latch[C-1:0]`, `index`
//! (one cycle per index edge processed), `rev_error` (sticky), `rev_error_count[G-1:0]`.
//!
//! Latency: a step is in `position` after the edge that samples it; an index level change
//! on `z` acts one edge later than a step sampled with it. Reset (synchronous, active
//! high): position, latch, flags and counters 0; z_delay and z_prev 1.

use rust_hdl::prelude::*;

/// Width of the shift-amount constant.
const SHIFT_BITS: usize = 8;

/// Position counter with C-bit position and G-bit revolution-error counter.
#[derive(LogicBlock)]
pub struct PositionCounter<const C: usize, const G: usize> {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// A step of the decoder.
    pub step: Signal<In, Bit>,
    /// The step is forward.
    pub forward: Signal<In, Bit>,
    /// With `step`: the first step since reset, or a step against the last one.
    pub first: Signal<In, Bit>,
    /// Filtered index level, in the timing of the decoder's inputs.
    pub z: Signal<In, Bit>,
    /// R − 1 mod 2^C, R the counts per revolution (2^C − 1 for R = 2^C).
    pub limit: Signal<In, Bits<C>>,
    /// R − 2 mod 2^C (the core feeds the three limits as constants: no subtraction in the
    /// block).
    pub limit_less_one: Signal<In, Bits<C>>,
    /// R − 3 mod 2^C.
    pub limit_less_two: Signal<In, Bits<C>>,
    /// 0 ignore Z, 1 reset on Z, 2 latch on Z, 3 latch then reset.
    pub cfg_z_mode: Signal<In, Bits<2>>,
    /// Position, 0..R.
    pub position: Signal<Out, Bits<C>>,
    /// Position latched at the last index edge.
    pub z_latch: Signal<Out, Bits<C>>,
    /// One cycle per index edge processed.
    pub index: Signal<Out, Bit>,
    /// A checked revolution had a count other than R (sticky).
    pub rev_error: Signal<Out, Bit>,
    /// Revolutions with a wrong count (saturating).
    pub rev_error_count: Signal<Out, Bits<G>>,
    /// One cycle: the last edge found a bad revolution.
    pub rev_fault: Signal<Out, Bit>,
    pub(crate) position_reg: DFF<Bits<C>>,
    /// position ≠ 0 (stored inverted so that the power-up value agrees with position 0).
    not_zero: DFF<Bit>,
    /// position = limit.
    at_limit: DFF<Bit>,
    /// The low half of the position is all ones: the carry into the high half.
    low_all_ones: DFF<Bit>,
    /// The low half of the position is not 0 (stored inverted, like `not_zero`): no borrow
    /// from the high half.
    low_not_zero: DFF<Bit>,
    latch_reg: DFF<Bits<C>>,
    index_reg: DFF<Bit>,
    z_delay: DFF<Bit>,
    z_prev: DFF<Bit>,
    armed: DFF<Bit>,
    rev_any: DFF<Bit>,
    rev_more: DFF<Bits<C>>,
    rev_over: DFF<Bit>,
    rev_mixed: DFF<Bit>,
    /// `rev_more` = 2^C − 1: the next step overflows the count.
    rev_at_max: DFF<Bit>,
    /// `rev_more` = limit: the interval so far has R steps.
    rev_is_limit: DFF<Bit>,
    /// `rev_more` = limit − 1: one more step makes R.
    rev_is_limit_less_one: DFF<Bit>,
    error_reg: DFF<Bit>,
    error_count: DFF<Bits<G>>,
    fault_reg: DFF<Bit>,
    /// The interval's count equals R (more_now = limit), found without forming more_now.
    count_is_rev: Signal<Local, Bit>,
    /// The position with this cycle's step (for the index latch).
    stepped: Signal<Local, Bits<C>>,
    /// The position after a forward step, and its flags.
    up: Signal<Local, Bits<C>>,
    up_not_zero: Signal<Local, Bit>,
    up_at_limit: Signal<Local, Bit>,
    up_low_all_ones: Signal<Local, Bit>,
    up_low_not_zero: Signal<Local, Bit>,
    /// The position after a backward step, and its flags.
    down: Signal<Local, Bits<C>>,
    down_not_zero: Signal<Local, Bit>,
    down_at_limit: Signal<Local, Bit>,
    down_low_all_ones: Signal<Local, Bit>,
    down_low_not_zero: Signal<Local, Bit>,
    /// position + 1 and position − 1, each from two carry chains of half the width.
    plus_one: Signal<Local, Bits<C>>,
    minus_one: Signal<Local, Bits<C>>,
    /// 1 when the low half is all ones (the high half's carry in), else 0.
    carry: Signal<Local, Bits<C>>,
    /// 1 when the low half is 0 (the high half's borrow in), else 0.
    borrow: Signal<Local, Bits<C>>,
    /// The low and high halves of the position (the other half's bits 0).
    low: Signal<Local, Bits<C>>,
    high: Signal<Local, Bits<C>>,
    /// `limit`'s low half is all ones / is 0.
    limit_low_all_ones: Signal<Local, Bit>,
    limit_low_zero: Signal<Local, Bit>,
    /// R = 1: position 0 is also the limit.
    single: Signal<Local, Bit>,
    /// R = 2: a count of one step is one short of R.
    pair: Signal<Local, Bit>,
    /// This cycle's step adds one to `rev_more` (an interval already begun, not at its
    /// overflow).
    rev_counts: Signal<Local, Bit>,
    rise: Signal<Local, Bit>,
    any_now: Signal<Local, Bit>,
    more_now: Signal<Local, Bits<C>>,
    over_now: Signal<Local, Bit>,
    mixed_now: Signal<Local, Bit>,
    bad: Signal<Local, Bit>,
    pos_zero: Constant<Bits<C>>,
    pos_one: Constant<Bits<C>>,
    pos_max_less_one: Constant<Bits<C>>,
    /// The low half's bits, ⌈C/2⌉ of them.
    low_mask: Constant<Bits<C>>,
    /// The low half's largest value less one.
    low_max_less_one: Constant<Bits<C>>,
    /// ⌈C/2⌉: the shift that brings the high half down.
    low_width: Constant<Bits<SHIFT_BITS>>,
    mode_ignore: Constant<Bits<2>>,
    mode_reset: Constant<Bits<2>>,
    mode_latch: Constant<Bits<2>>,
    mode_both: Constant<Bits<2>>,
    count_zero: Constant<Bits<G>>,
    count_one: Constant<Bits<G>>,
    count_max: Constant<Bits<G>>,
}

impl<const C: usize, const G: usize> Default for PositionCounter<C, G> {
    fn default() -> Self {
        // The low half: ⌈C/2⌉ bits, so that it is never empty.
        let low = C.div_ceil(2);
        assert!(
            (1..=32).contains(&C) && (1..=32).contains(&G),
            "widths 1..=32"
        );
        use golden::frontend::{Z_MODE_IGNORE, Z_MODE_LATCH, Z_MODE_LATCH_RESET, Z_MODE_RESET};
        Self {
            clock: Default::default(),
            reset: Default::default(),
            step: Default::default(),
            forward: Default::default(),
            first: Default::default(),
            z: Default::default(),
            limit: Default::default(),
            limit_less_one: Default::default(),
            limit_less_two: Default::default(),
            cfg_z_mode: Default::default(),
            position: Default::default(),
            z_latch: Default::default(),
            index: Default::default(),
            rev_error: Default::default(),
            rev_error_count: Default::default(),
            rev_fault: Default::default(),
            position_reg: Default::default(),
            not_zero: Default::default(),
            at_limit: Default::default(),
            low_all_ones: Default::default(),
            low_not_zero: Default::default(),
            latch_reg: Default::default(),
            index_reg: Default::default(),
            z_delay: Default::default(),
            z_prev: Default::default(),
            armed: Default::default(),
            rev_any: Default::default(),
            rev_more: Default::default(),
            rev_over: Default::default(),
            rev_mixed: Default::default(),
            rev_at_max: Default::default(),
            rev_is_limit: Default::default(),
            rev_is_limit_less_one: Default::default(),
            error_reg: Default::default(),
            error_count: Default::default(),
            fault_reg: Default::default(),
            count_is_rev: Default::default(),
            stepped: Default::default(),
            up: Default::default(),
            up_not_zero: Default::default(),
            up_at_limit: Default::default(),
            up_low_all_ones: Default::default(),
            up_low_not_zero: Default::default(),
            down: Default::default(),
            down_not_zero: Default::default(),
            down_at_limit: Default::default(),
            down_low_all_ones: Default::default(),
            down_low_not_zero: Default::default(),
            plus_one: Default::default(),
            minus_one: Default::default(),
            carry: Default::default(),
            borrow: Default::default(),
            low: Default::default(),
            high: Default::default(),
            limit_low_all_ones: Default::default(),
            limit_low_zero: Default::default(),
            single: Default::default(),
            pair: Default::default(),
            rev_counts: Default::default(),
            rise: Default::default(),
            any_now: Default::default(),
            more_now: Default::default(),
            over_now: Default::default(),
            mixed_now: Default::default(),
            bad: Default::default(),
            pos_zero: Constant::new(0.into()),
            pos_one: Constant::new(1.into()),
            pos_max_less_one: Constant::new(((1u64 << C) - 2).into()),
            low_mask: Constant::new(((1u64 << low) - 1).into()),
            low_max_less_one: Constant::new(((1u64 << low) - 2).into()),
            low_width: Constant::new((low as u64).into()),
            mode_ignore: Constant::new(u64::from(Z_MODE_IGNORE).into()),
            mode_reset: Constant::new(u64::from(Z_MODE_RESET).into()),
            mode_latch: Constant::new(u64::from(Z_MODE_LATCH).into()),
            mode_both: Constant::new(u64::from(Z_MODE_LATCH_RESET).into()),
            count_zero: Constant::new(0.into()),
            count_one: Constant::new(1.into()),
            count_max: Constant::new(((1u64 << G) - 1).into()),
        }
    }
}

impl<const C: usize, const G: usize> Logic for PositionCounter<C, G> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            position_reg,
            not_zero,
            at_limit,
            low_all_ones,
            low_not_zero,
            latch_reg,
            index_reg,
            z_delay,
            z_prev,
            armed,
            rev_any,
            rev_more,
            rev_over,
            rev_mixed,
            rev_at_max,
            rev_is_limit,
            rev_is_limit_less_one,
            error_reg,
            error_count,
            fault_reg
        );
        self.rise.next = self.z_delay.q.val() & !self.z_prev.q.val();
        self.z_delay.d.next = self.z.val();
        self.z_prev.d.next = self.z_delay.q.val();

        // The stepped position, modulo R, and its flags.
        self.single.next = self.limit.val() == self.pos_zero.val();
        self.pair.next = self.limit_less_one.val() == self.pos_zero.val();
        // p ± 1 in two halves: the high half adds the registered carry (low half all ones)
        // or subtracts the registered borrow (low half 0), so each carry chain is half as
        // long and the two run side by side.
        self.low.next = self.position_reg.q.val() & self.low_mask.val();
        self.high.next = self.position_reg.q.val() >> self.low_width.val();
        // The low half wraps by itself (all ones + 1 is 0 and 0 − 1 is all ones in ⌈C/2⌉
        // bits); the registered carry and borrow are the high half's second operand, a
        // flip-flop straight into its chain, so no multiplexer follows either chain.
        self.carry.next = self.pos_zero.val();
        if self.low_all_ones.q.val() {
            self.carry.next = self.pos_one.val();
        }
        self.borrow.next = self.pos_zero.val();
        if !self.low_not_zero.q.val() {
            self.borrow.next = self.pos_one.val();
        }
        self.plus_one.next = ((self.low.val() + self.pos_one.val()) & self.low_mask.val())
            | ((self.high.val() + self.carry.val()) << self.low_width.val());
        self.minus_one.next = ((self.low.val() - self.pos_one.val()) & self.low_mask.val())
            | ((self.high.val() - self.borrow.val()) << self.low_width.val());
        self.limit_low_all_ones.next =
            (self.limit.val() & self.low_mask.val()) == self.low_mask.val();
        self.limit_low_zero.next = (self.limit.val() & self.low_mask.val()) == self.pos_zero.val();
        // The position after a forward step and after a backward step, with their flags,
        // from registers only: a whole cycle for the carry chains and the comparisons. The
        // step and its direction, which arrive from the decoder's registers, then only
        // choose between them (and enable the registers), one logic level in front of them.
        self.up.next = self.plus_one.val();
        self.up_not_zero.next = true;
        self.up_at_limit.next = self.position_reg.q.val() == self.limit_less_one.val();
        self.up_low_all_ones.next = self.low.val() == self.low_max_less_one.val();
        self.up_low_not_zero.next = !self.low_all_ones.q.val();
        if self.at_limit.q.val() {
            self.up.next = self.pos_zero.val();
            self.up_not_zero.next = false;
            self.up_at_limit.next = self.single.val();
            self.up_low_all_ones.next = false;
            self.up_low_not_zero.next = false;
        }
        self.down.next = self.minus_one.val();
        self.down_not_zero.next = self.position_reg.q.val() != self.pos_one.val();
        self.down_at_limit.next = false;
        self.down_low_all_ones.next = !self.low_not_zero.q.val();
        self.down_low_not_zero.next = self.low.val() != self.pos_one.val();
        if !self.not_zero.q.val() {
            self.down.next = self.limit.val();
            self.down_not_zero.next = !self.single.val();
            self.down_at_limit.next = true;
            self.down_low_all_ones.next = self.limit_low_all_ones.val();
            self.down_low_not_zero.next = !self.limit_low_zero.val();
        }
        // The position with this cycle's step, for the index latch.
        self.stepped.next = self.position_reg.q.val();
        if self.step.val() {
            if self.forward.val() {
                self.stepped.next = self.up.val();
            } else {
                self.stepped.next = self.down.val();
            }
        }

        // The interval since the last index edge, this cycle's step included: count − 1 in
        // `more` (with `over` once it passes 2^C − 1), and whether it mixes directions.
        self.any_now.next = self.rev_any.q.val();
        self.more_now.next = self.rev_more.q.val();
        self.over_now.next = self.rev_over.q.val();
        self.mixed_now.next = self.rev_mixed.q.val();
        self.rev_counts.next = self.step.val() & self.rev_any.q.val() & !self.rev_at_max.q.val();
        if self.rev_counts.val() {
            self.more_now.next = self.rev_more.q.val() + self.pos_one.val();
        }
        if self.step.val() {
            if self.rev_any.q.val() {
                if self.rev_at_max.q.val() {
                    self.over_now.next = true;
                }
                // A reversal after a step of this interval: the interval mixes directions.
                if self.first.val() {
                    self.mixed_now.next = true;
                }
            } else {
                self.any_now.next = true;
                self.more_now.next = self.pos_zero.val();
                self.over_now.next = false;
                self.mixed_now.next = false;
            }
        }
        // more_now = limit, from flags registered with `rev_more` (its comparisons with
        // limit, limit − 1 and 2^C − 1 made a cycle early, on the registers), so that no
        // C-bit comparison lies between the decoder's step and the error counter: an
        // increment makes more + 1 = limit exactly when more = limit − 1 (all ones does not
        // increment: it overflows); a first step makes more 0, which is limit when R = 1.
        self.count_is_rev.next = self.rev_is_limit.q.val();
        if self.rev_counts.val() {
            self.count_is_rev.next = self.rev_is_limit_less_one.q.val();
        }
        if self.step.val() & !self.rev_any.q.val() {
            self.count_is_rev.next = self.single.val();
        }
        // The flags of the next `rev_more`: after an increment, more + 1 = limit − 1 is
        // more = limit − 2 and more + 1 = 2^C − 1 is more = 2^C − 2; when it restarts at 0
        // (first step, index edge, reset), 0 = limit is R = 1, 0 = limit − 1 is R = 2, and
        // 0 is not 2^C − 1.
        if self.rev_counts.val() {
            self.rev_is_limit.d.next = self.rev_is_limit_less_one.q.val();
            self.rev_is_limit_less_one.d.next = self.rev_more.q.val() == self.limit_less_two.val();
            self.rev_at_max.d.next = self.rev_more.q.val() == self.pos_max_less_one.val();
        }
        if (self.step.val() & !self.rev_any.q.val()) | self.rise.val() | self.reset.val() {
            self.rev_is_limit.d.next = self.single.val();
            self.rev_is_limit_less_one.d.next = self.pair.val();
            self.rev_at_max.d.next = false;
        }
        // A checked interval whose count is not R.
        self.bad.next = self.armed.q.val()
            & (self.cfg_z_mode.val() != self.mode_ignore.val())
            & self.any_now.val()
            & !self.mixed_now.val()
            & (self.over_now.val() | !self.count_is_rev.val());

        // Written here rather than copied from `stepped`, so that each register's input is
        // its own multiplexer with the register's output as one leaf: synthesis turns
        // that into a clock enable (the step) instead of a multiplexer after the choice.
        if self.step.val() {
            if self.forward.val() {
                self.position_reg.d.next = self.up.val();
                self.not_zero.d.next = self.up_not_zero.val();
                self.at_limit.d.next = self.up_at_limit.val();
                self.low_all_ones.d.next = self.up_low_all_ones.val();
                self.low_not_zero.d.next = self.up_low_not_zero.val();
            } else {
                self.position_reg.d.next = self.down.val();
                self.not_zero.d.next = self.down_not_zero.val();
                self.at_limit.d.next = self.down_at_limit.val();
                self.low_all_ones.d.next = self.down_low_all_ones.val();
                self.low_not_zero.d.next = self.down_low_not_zero.val();
            }
        }
        self.index_reg.d.next = self.rise.val();
        self.fault_reg.d.next = false;
        self.rev_any.d.next = self.any_now.val();
        self.rev_more.d.next = self.more_now.val();
        self.rev_over.d.next = self.over_now.val();
        self.rev_mixed.d.next = self.mixed_now.val();
        if self.rise.val() {
            if (self.cfg_z_mode.val() == self.mode_latch.val())
                | (self.cfg_z_mode.val() == self.mode_both.val())
            {
                self.latch_reg.d.next = self.stepped.val();
            }
            if (self.cfg_z_mode.val() == self.mode_reset.val())
                | (self.cfg_z_mode.val() == self.mode_both.val())
            {
                self.position_reg.d.next = self.pos_zero.val();
                self.not_zero.d.next = false;
                self.at_limit.d.next = self.single.val();
                self.low_all_ones.d.next = false;
                self.low_not_zero.d.next = false;
            }
            if self.bad.val() {
                self.error_reg.d.next = true;
                self.fault_reg.d.next = true;
                if self.error_count.q.val() != self.count_max.val() {
                    self.error_count.d.next = self.error_count.q.val() + self.count_one.val();
                }
            }
            self.armed.d.next = true;
            self.rev_any.d.next = false;
            self.rev_more.d.next = self.pos_zero.val();
            self.rev_over.d.next = false;
            self.rev_mixed.d.next = false;
        }
        if self.reset.val() {
            self.position_reg.d.next = self.pos_zero.val();
            self.not_zero.d.next = false;
            self.at_limit.d.next = self.single.val();
            self.low_all_ones.d.next = false;
            self.low_not_zero.d.next = false;
            self.latch_reg.d.next = self.pos_zero.val();
            self.index_reg.d.next = false;
            self.z_delay.d.next = true;
            self.z_prev.d.next = true;
            self.armed.d.next = false;
            self.rev_any.d.next = false;
            self.rev_more.d.next = self.pos_zero.val();
            self.rev_over.d.next = false;
            self.rev_mixed.d.next = false;
            self.error_reg.d.next = false;
            self.error_count.d.next = self.count_zero.val();
            self.fault_reg.d.next = false;
        }
        self.position.next = self.position_reg.q.val();
        self.z_latch.next = self.latch_reg.q.val();
        self.index.next = self.index_reg.q.val();
        self.rev_error.next = self.error_reg.q.val();
        self.rev_error_count.next = self.error_count.q.val();
        self.rev_fault.next = self.fault_reg.q.val();
    }
}

/// The Verilog of a [`PositionCounter`], top module named `module_name`.
pub fn position_counter_verilog<const C: usize, const G: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<PositionCounter<C, G>>(module_name)
}
