// SPDX-License-Identifier: MIT OR Apache-2.0
//! A W-bit adder whose carry chain is cut in two by a register: at each rising edge the sum
//! of the low L = ⌈W/2⌉ bits (with its carry) and the high W − L bits of both operands are
//! registered; in the next cycle the high bits are added with the registered carry. So
//! `sum` is a + b + `carry_in` (mod 2^W) of the inputs at the last edge: a pipelined adder
//! of latency one, with no path through more than ⌈W/2⌉ + 1 carry cells, and no
//! combinational path from its inputs to its output (a block that drives the inputs and
//! reads the sum in its one `always` block is no false loop for Verilator, rule R6 of
//! docs/design-decisions.md). On the iCE40 a 49-bit chain alone takes about
//! 10.5 ns of the 10 ns of a 100 MHz cycle (docs/design-decisions.md, "Timing closure on
//! the iCE40"); the divider and the multiplier of `SpeedCalc` run on these.
//!
//! Bit-true model: [`golden::arith::two_cycle_adder::TwoCycleAdderModel`].
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | the inputs are taken at its rising edge |
//! | `a`, `b` | in | W | addends (unsigned, or two's complement: the sum is the same bits) |
//! | `carry_in` | in | 1 | added at bit 0 (with `b` inverted, a − b) |
//! | `sum` | out | W | a + b + carry_in mod 2^W of the inputs at the last edge |
//!
//! Both halves use a spare bottom bit for the carry in: ({x, c} + {y, 1}) >> 1 = x + y + c
//! (bit 0 is c + 1, whose carry is c), one adder with no carry-in port (a three-operand sum
//! would be two chains in series). The spare bit of the second operand is the constant 1,
//! not c again: with the same net on both operands the bottom carry cell's LUT had it on
//! two of its inputs, and nextpnr-ice40 0.4's router then looped forever on most
//! placements, alternating the net between the LUT's two input pins (router1, and router2
//! left the wires overused).
//! W: 4..=127.

use rust_hdl::prelude::*;

/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// W-bit adder with a registered low half.
#[derive(LogicBlock)]
pub struct TwoCycleAdder<const W: usize> {
    /// Clock: the low half is registered at its rising edge.
    pub clock: Signal<In, Clock>,
    /// First addend.
    pub a: Signal<In, Bits<W>>,
    /// Second addend.
    pub b: Signal<In, Bits<W>>,
    /// Carry into bit 0.
    pub carry_in: Signal<In, Bit>,
    /// a + b + carry_in mod 2^W of the inputs at the last edge.
    pub sum: Signal<Out, Bits<W>>,
    /// {a_low, c} + {b_low, 1} of the last edge: the low sum at bits 1..=L, its carry at
    /// bit L + 1.
    low: DFF<Bits<W>>,
    /// The high W − L bits of a and b at the last edge, shifted down.
    high_a_reg: DFF<Bits<W>>,
    high_b_reg: DFF<Bits<W>>,
    low_a: Signal<Local, Bits<W>>,
    low_b: Signal<Local, Bits<W>>,
    /// The registered carry into bit L.
    mid_carry: Signal<Local, Bit>,
    high_a: Signal<Local, Bits<W>>,
    high_b: Signal<Local, Bits<W>>,
    /// {a_high, c} + {b_high, 1}: the high sum at bits 1..=W − L.
    high_sum: Signal<Local, Bits<W>>,
    zero: Constant<Bits<W>>,
    one: Constant<Bits<W>>,
    /// 2^L − 1.
    low_mask: Constant<Bits<W>>,
    /// 2^(L + 1): the low half's carry.
    low_carry: Constant<Bits<W>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    /// L.
    sh_low: Constant<Bits<SHIFT_BITS>>,
}

impl<const W: usize> Default for TwoCycleAdder<W> {
    fn default() -> Self {
        assert!(
            (4..=127).contains(&W),
            "TwoCycleAdder supports W in 4..=127"
        );
        let l = W.div_ceil(2);
        let mut low_mask = Bits::<W>::default();
        for i in 0..l {
            low_mask = low_mask.replace_bit(i, true);
        }
        Self {
            clock: Default::default(),
            a: Default::default(),
            b: Default::default(),
            carry_in: Default::default(),
            sum: Default::default(),
            low: Default::default(),
            high_a_reg: Default::default(),
            high_b_reg: Default::default(),
            low_a: Default::default(),
            low_b: Default::default(),
            mid_carry: Default::default(),
            high_a: Default::default(),
            high_b: Default::default(),
            high_sum: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            low_mask: Constant::new(low_mask),
            // W can exceed 64: single bits built with replace_bit rather than from a u64.
            low_carry: Constant::new(Bits::<W>::default().replace_bit(l + 1, true)),
            sh_one: Constant::new(1.into()),
            sh_low: Constant::new(u64::try_from(l).unwrap().into()),
        }
    }
}

impl<const W: usize> Logic for TwoCycleAdder<W> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, low, high_a_reg, high_b_reg);
        self.low_a.next = (self.a.val() & self.low_mask.val()) << self.sh_one.val();
        if self.carry_in.val() {
            self.low_a.next =
                ((self.a.val() & self.low_mask.val()) << self.sh_one.val()) | self.one.val();
        }
        self.low_b.next =
            ((self.b.val() & self.low_mask.val()) << self.sh_one.val()) | self.one.val();
        self.low.d.next = self.low_a.val() + self.low_b.val();
        self.mid_carry.next = (self.low.q.val() & self.low_carry.val()) != self.zero.val();
        self.high_a_reg.d.next = self.a.val() >> self.sh_low.val();
        self.high_b_reg.d.next = self.b.val() >> self.sh_low.val();
        self.high_a.next = self.high_a_reg.q.val() << self.sh_one.val();
        if self.mid_carry.val() {
            self.high_a.next = (self.high_a_reg.q.val() << self.sh_one.val()) | self.one.val();
        }
        self.high_b.next = (self.high_b_reg.q.val() << self.sh_one.val()) | self.one.val();
        self.high_sum.next = self.high_a.val() + self.high_b.val();
        self.sum.next = ((self.high_sum.val() >> self.sh_one.val()) << self.sh_low.val())
            | ((self.low.q.val() >> self.sh_one.val()) & self.low_mask.val());
    }
}

/// The Verilog of a `TwoCycleAdder<W>` with its top module named `module_name`.
pub fn two_cycle_adder_verilog<const W: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<TwoCycleAdder<W>>(module_name)
}
