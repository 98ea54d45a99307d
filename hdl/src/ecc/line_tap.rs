// SPDX-License-Identifier: MIT OR Apache-2.0
//! The line edges of `encspeed_ecc`'s identification: from the core's registered `position`
//! and `direction`, a `line` pulse at the first step of each line of forward motion, its
//! line number and the clock cycles since the previous one. Bit-true model:
//! [`golden::ecc::line_tap::LineTap`], whose module docs give the rules and the latency.
//!
//! Ports: `clock`, `reset` (synchronous, active high), `position[C-1:0]`, `forward` (the
//! core's `direction`), `shift[1:0]` (s: 0, 1, 2; 3 is taken as 2), `counts_per_rev[C-1:0]`
//! (R); outputs, combinational
//! from the registers and the inputs: `line`, `line_position[15:0]` (position / 2^s, mod
//! 2^16), `period[31:0]` (saturating).

use rust_hdl::prelude::*;

/// Line edges from a C-bit position (module docs).
#[derive(LogicBlock)]
pub struct LineTap<const C: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// The core's position (steps, mod R).
    pub position: Signal<In, Bits<C>>,
    /// The last step was forward.
    pub forward: Signal<In, Bit>,
    /// s: log2 of steps per line.
    pub shift: Signal<In, Bits<2>>,
    /// R: steps per revolution (the position's modulus).
    pub counts_per_rev: Signal<In, Bits<C>>,
    /// A forward line edge this cycle.
    pub line: Signal<Out, Bit>,
    /// Its line number.
    pub line_position: Signal<Out, Bits<16>>,
    /// Cycles since the previous line edge, saturating.
    pub period: Signal<Out, Bits<32>>,
    last_position: DFF<Bits<C>>,
    since: DFF<Bits<32>>,
    first_step: Signal<Local, Bit>,
    is_line: Signal<Local, Bit>,
    after: Signal<Local, Bits<C>>,
    zero_c: Constant<Bits<C>>,
    zero32: Constant<Bits<32>>,
    one32: Constant<Bits<32>>,
    one_c: Constant<Bits<C>>,
}

impl<const C: usize> Default for LineTap<C> {
    fn default() -> Self {
        assert!(
            C >= 18,
            "the position needs 16 line bits above a shift of 2"
        );
        Self {
            clock: Default::default(),
            reset: Default::default(),
            position: Default::default(),
            forward: Default::default(),
            shift: Default::default(),
            counts_per_rev: Default::default(),
            line: Default::default(),
            line_position: Default::default(),
            period: Default::default(),
            last_position: Default::default(),
            since: Default::default(),
            first_step: Default::default(),
            is_line: Default::default(),
            after: Default::default(),
            zero_c: Constant::new(0u64.into()),
            zero32: Constant::new(0u64.into()),
            one32: Constant::new(1u64.into()),
            one_c: Constant::new(1u64.into()),
        }
    }
}

impl<const C: usize> Logic for LineTap<C> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, last_position, since);
        // One step per line is its first: position mod 2^s = 0.
        self.first_step.next = true;
        self.line_position.next = self.position.val().get_bits::<16>(0);
        if self.shift.val().get_bit(0) & !self.shift.val().get_bit(1) {
            self.first_step.next = !self.position.val().get_bit(0);
            self.line_position.next = self.position.val().get_bits::<16>(1);
        }
        if self.shift.val().get_bit(1) {
            self.first_step.next =
                !self.position.val().get_bit(0) & !self.position.val().get_bit(1);
            self.line_position.next = self.position.val().get_bits::<16>(2);
        }
        // One forward step: last + 1, or the wrap from R − 1 to 0 (an index edge may reset
        // the position in the same cycle; an index that moves it from elsewhere is no step).
        self.after.next = self.last_position.q.val() + self.one_c.val();
        self.is_line.next = ((self.position.val() == self.after.val())
            | ((self.position.val() == self.zero_c.val())
                & (self.after.val() == self.counts_per_rev.val())))
            & self.forward.val()
            & self.first_step.val();
        self.line.next = self.is_line.val();
        self.period.next = self.since.q.val();
        self.last_position.d.next = self.position.val();
        if self.since.q.val().all() {
            self.since.d.next = self.since.q.val();
        } else {
            self.since.d.next = self.since.q.val() + self.one32.val();
        }
        if self.is_line.val() {
            self.since.d.next = self.one32.val();
        }
        if self.reset.val() {
            self.last_position.d.next = self.zero_c.val();
            self.since.d.next = self.zero32.val();
        }
    }
}
