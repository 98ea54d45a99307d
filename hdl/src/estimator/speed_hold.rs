// SPDX-License-Identifier: MIT OR Apache-2.0
//! Output registers of the Rairán speeds: `speed_n1..3`, `speed_strobe` and the "a speed
//! has been computed" flag behind `valid`.
//!
//! Per edge: `clear` (reset or a reversal) zeroes the speeds, the strobe and the flag;
//! otherwise `load` (the speed calculator's `valid`) writes the three mode-scaled speeds,
//! raises `strobe` for one cycle and sets `have_speed`. A block of its own so that the
//! core's glue stays plain wiring (Verilator orders combinational logic per block; logic
//! that reads a block's output and drives the same block's reset, in one always block of
//! the core, would form a false combinational loop). Bit-true model: the speed registers of
//! [`golden::top::core::CoreModel`].

use rust_hdl::prelude::*;

/// The three held speeds, their strobe and `have_speed`.
#[derive(LogicBlock)]
pub struct SpeedHold<const S: usize> {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous clear (reset or reversal), wins over `load`.
    pub clear: Signal<In, Bit>,
    /// Write the three speeds.
    pub load: Signal<In, Bit>,
    /// n1 to hold.
    pub n1_in: Signal<In, Bits<S>>,
    /// n2 to hold.
    pub n2_in: Signal<In, Bits<S>>,
    /// n3 to hold.
    pub n3_in: Signal<In, Bits<S>>,
    /// Held n1.
    pub n1: Signal<Out, Bits<S>>,
    /// Held n2.
    pub n2: Signal<Out, Bits<S>>,
    /// Held n3.
    pub n3: Signal<Out, Bits<S>>,
    /// One cycle after a load.
    pub strobe: Signal<Out, Bit>,
    /// A load since the last clear.
    pub have_speed: Signal<Out, Bit>,
    n1_reg: DFF<Bits<S>>,
    n2_reg: DFF<Bits<S>>,
    n3_reg: DFF<Bits<S>>,
    strobe_reg: DFF<Bit>,
    have_reg: DFF<Bit>,
    zero: Constant<Bits<S>>,
}

impl<const S: usize> Default for SpeedHold<S> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            clear: Default::default(),
            load: Default::default(),
            n1_in: Default::default(),
            n2_in: Default::default(),
            n3_in: Default::default(),
            n1: Default::default(),
            n2: Default::default(),
            n3: Default::default(),
            strobe: Default::default(),
            have_speed: Default::default(),
            n1_reg: Default::default(),
            n2_reg: Default::default(),
            n3_reg: Default::default(),
            strobe_reg: Default::default(),
            have_reg: Default::default(),
            zero: Constant::new(0.into()),
        }
    }
}

impl<const S: usize> Logic for SpeedHold<S> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, n1_reg, n2_reg, n3_reg, strobe_reg, have_reg);
        self.strobe_reg.d.next = self.load.val();
        if self.load.val() {
            self.n1_reg.d.next = self.n1_in.val();
            self.n2_reg.d.next = self.n2_in.val();
            self.n3_reg.d.next = self.n3_in.val();
            self.have_reg.d.next = true;
        }
        if self.clear.val() {
            self.n1_reg.d.next = self.zero.val();
            self.n2_reg.d.next = self.zero.val();
            self.n3_reg.d.next = self.zero.val();
            self.strobe_reg.d.next = false;
            self.have_reg.d.next = false;
        }
        self.n1.next = self.n1_reg.q.val();
        self.n2.next = self.n2_reg.q.val();
        self.n3.next = self.n3_reg.q.val();
        self.strobe.next = self.strobe_reg.q.val();
        self.have_speed.next = self.have_reg.q.val();
    }
}
