// SPDX-License-Identifier: MIT OR Apache-2.0
//! Sequential unsigned divider: restoring radix-2 division of a W-bit numerator by a W-bit
//! denominator, one quotient bit per clock, for the fixed-point speed estimates (n1, n2, n3,
//! PC, ET, M/T) of issue 3. A standalone block; its bit-true model is
//! [`golden::arith::seq_divider::SeqDividerModel`].
//!
//! # Ports and behaviour
//!
//! * `start` is sampled at a rising edge. When idle (`busy` low) the edge loads `numerator`
//!   and `denominator` and raises `busy`. **A start while busy is ignored** (not queued);
//!   `numerator`/`denominator` are read only at an accepted start and may change afterwards.
//! * The next W edges each bring down one numerator bit (most significant first) and produce
//!   one quotient bit. The W-th writes `quotient`, `remainder`, `div_by_zero`, lowers `busy`
//!   and raises `done` for one cycle.
//! * `quotient`, `remainder` and `div_by_zero` are registers, held until the next result.
//! * Division by zero: `quotient` = 2^W − 1, `remainder` = numerator, `div_by_zero` high
//!   (what the restoring recurrence gives by itself with a zero denominator; the flag tells
//!   it from a genuine all-ones quotient).
//! * `reset` (synchronous, active high) wins over `start`: `busy`, `done`, `quotient`,
//!   `remainder`, `div_by_zero` become 0 and a division in progress is abandoned without
//!   `done`. The working registers are not reset (they are reloaded at every start).
//!
//! # Latency and throughput
//!
//! Fixed: a start sampled at edge k gives `done` high after edge k + W, whatever the
//! operands ([`golden::arith::seq_divider::latency_cycles`]). `busy` is high after edges k … k + W − 1.
//! The `done` cycle is idle, so a start in that cycle is accepted at edge k + W + 1: one
//! division per W + 1 cycles at most.
//!
//! # Fixed point
//!
//! For F fractional bits the caller passes `num << F`, and gets ⌊num·2^F / den⌋. The caller
//! must make sure `num << F` fits W bits (nothing here detects a truncated numerator); see
//! [`golden::arith::seq_divider::fixed_quotient`] and [`golden::arith::seq_divider::shifted_numerator`].
//!
//! # Recurrence
//!
//! With partial remainder R (W bits, R < den) and the next numerator bit b, the trial value
//! 2R + b needs W + 1 bits. Its top bit is R's most significant bit (`carry`); the low W bits
//! are `shifted`. It is at least den iff `carry | shifted ≥ den`, and then 2R + b − den < den
//! fits W bits, so the W-bit wrapping `shifted − den` is exact: no (W + 1)-bit signal is
//! needed (rust-hdl cannot size one from a const generic).
//!
//! Registers: 5·W + 9 flops (partial remainder, numerator/quotient shift register,
//! denominator, quotient and remainder outputs, a 6-bit step counter, busy, done,
//! div_by_zero). W ranges over 2..=64 (checked at compile time).

use rust_hdl::prelude::*;

/// Width of the step counter: it holds W − 1 ≤ 63.
const COUNT_BITS: usize = 6;

/// Sequential restoring divider, W-bit operands, one quotient bit per clock.
#[derive(LogicBlock)]
pub struct SeqDivider<const W: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset (wins over `start`).
    pub reset: Signal<In, Bit>,
    /// Start a division; sampled at the rising edge, ignored while `busy`.
    pub start: Signal<In, Bit>,
    /// Dividend, read at an accepted start.
    pub numerator: Signal<In, Bits<W>>,
    /// Divisor, read at an accepted start.
    pub denominator: Signal<In, Bits<W>>,
    /// A division is in progress.
    pub busy: Signal<Out, Bit>,
    /// One-cycle strobe: `quotient`, `remainder`, `div_by_zero` were just written.
    pub done: Signal<Out, Bit>,
    /// ⌊numerator / denominator⌋ (2^W − 1 for a zero denominator), held.
    pub quotient: Signal<Out, Bits<W>>,
    /// numerator mod denominator (the numerator for a zero denominator), held.
    pub remainder: Signal<Out, Bits<W>>,
    /// The last result came from a zero denominator, held.
    pub div_by_zero: Signal<Out, Bit>,
    /// Partial remainder.
    part_rem: DFF<Bits<W>>,
    /// Numerator bits still to bring down (high end), quotient bits so far (low end).
    shift_quo: DFF<Bits<W>>,
    /// Denominator sampled at start.
    den: DFF<Bits<W>>,
    /// Steps left after the current one.
    count: DFF<Bits<COUNT_BITS>>,
    busy_reg: DFF<Bit>,
    done_reg: DFF<Bit>,
    quotient_reg: DFF<Bits<W>>,
    remainder_reg: DFF<Bits<W>>,
    dbz_reg: DFF<Bit>,
    /// One restoring division step.
    div: crate::arith::div_step::DivStep<W>,
    /// 2R + b ≥ den: the quotient bit.
    fits: Signal<Local, Bit>,
    next_rem: Signal<Local, Bits<W>>,
    next_quo: Signal<Local, Bits<W>>,
    zero: Constant<Bits<W>>,
    one: Constant<Bits<W>>,
    /// 2^(W − 1): selects the most significant bit (a constant index would need a
    /// clog2(W)-bit width that rust-hdl cannot derive from W).
    msb: Constant<Bits<W>>,
    count_zero: Constant<Bits<COUNT_BITS>>,
    count_one: Constant<Bits<COUNT_BITS>>,
    /// W − 1: loaded at start.
    count_first: Constant<Bits<COUNT_BITS>>,
}

impl<const W: usize> SeqDivider<W> {
    const WIDTH_OK: () = assert!(W >= 2 && W <= 64, "SeqDivider supports W in 2..=64");
}

impl<const W: usize> Default for SeqDivider<W> {
    fn default() -> Self {
        let () = Self::WIDTH_OK;
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            numerator: Default::default(),
            denominator: Default::default(),
            busy: Default::default(),
            done: Default::default(),
            quotient: Default::default(),
            remainder: Default::default(),
            div_by_zero: Default::default(),
            part_rem: Default::default(),
            shift_quo: Default::default(),
            den: Default::default(),
            count: Default::default(),
            busy_reg: Default::default(),
            done_reg: Default::default(),
            quotient_reg: Default::default(),
            remainder_reg: Default::default(),
            dbz_reg: Default::default(),
            div: Default::default(),
            fits: Default::default(),
            next_rem: Default::default(),
            next_quo: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            msb: Constant::new((1u64 << (W - 1)).into()),
            count_zero: Constant::new(0.into()),
            count_one: Constant::new(1.into()),
            count_first: Constant::new((W as u64 - 1).into()),
        }
    }
}

impl<const W: usize> Logic for SeqDivider<W> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            part_rem,
            shift_quo,
            den,
            count,
            busy_reg,
            done_reg,
            quotient_reg,
            remainder_reg,
            dbz_reg
        );
        // One restoring step (DivStep): bring down the next numerator bit, subtract if it
        // fits.
        self.div.rem.next = self.part_rem.q.val();
        self.div.bit_in.next = (self.shift_quo.q.val() & self.msb.val()) != self.zero.val();
        self.div.den.next = self.den.q.val();
        self.fits.next = self.div.fits.val();
        self.next_rem.next = self.div.next_rem.val();
        self.next_quo.next = self.shift_quo.q.val() << self.one.val();
        if self.fits.val() {
            self.next_quo.next = (self.shift_quo.q.val() << self.one.val()) | self.one.val();
        }
        self.done_reg.d.next = false;
        if self.busy_reg.q.val() {
            self.part_rem.d.next = self.next_rem.val();
            self.shift_quo.d.next = self.next_quo.val();
            self.count.d.next = self.count.q.val() - self.count_one.val();
            if self.count.q.val() == self.count_zero.val() {
                self.busy_reg.d.next = false;
                self.done_reg.d.next = true;
                self.quotient_reg.d.next = self.next_quo.val();
                self.remainder_reg.d.next = self.next_rem.val();
                self.dbz_reg.d.next = self.den.q.val() == self.zero.val();
            }
        } else if self.start.val() {
            self.part_rem.d.next = self.zero.val();
            self.shift_quo.d.next = self.numerator.val();
            self.den.d.next = self.denominator.val();
            self.count.d.next = self.count_first.val();
            self.busy_reg.d.next = true;
        }
        if self.reset.val() {
            self.busy_reg.d.next = false;
            self.done_reg.d.next = false;
            self.quotient_reg.d.next = self.zero.val();
            self.remainder_reg.d.next = self.zero.val();
            self.dbz_reg.d.next = false;
        }
        self.busy.next = self.busy_reg.q.val();
        self.done.next = self.done_reg.q.val();
        self.quotient.next = self.quotient_reg.q.val();
        self.remainder.next = self.remainder_reg.q.val();
        self.div_by_zero.next = self.dbz_reg.q.val();
    }
}

/// The Verilog of a `SeqDivider<W>` with its top module named `module_name`.
pub fn seq_divider_verilog<const W: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<SeqDivider<W>>(module_name)
}
