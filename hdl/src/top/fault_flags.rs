// SPDX-License-Identifier: MIT OR Apache-2.0
//! Sticky fault flags and the glitch counter of the core.
//!
//! Per edge: each flag is set by its event pulse (`illegal`; `rejected_a` or `rejected_b`
//! for over-speed; `rev_fault`), held, and cleared by `clear_faults` unless its event comes
//! in the same cycle (the event wins); `glitch_count` adds the rejected pulses of the A, B
//! and Z filters (0 to 3 per edge), saturating at 2^16 − 1. Reset clears everything. The
//! flags and the count are registers: they show an event one edge after the pulse that
//! reports it. Bit-true model: the fault rules of [`golden::top::core`].

use golden::params::ERROR_COUNT_BITS;
use rust_hdl::prelude::*;

const G: usize = ERROR_COUNT_BITS as usize;

/// Sticky fault flags and the saturating glitch counter.
#[derive(LogicBlock)]
pub struct FaultFlags {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Clear the three flags (not the counter).
    pub clear_faults: Signal<In, Bit>,
    /// Illegal transition (decoder pulse).
    pub illegal: Signal<In, Bit>,
    /// The A filter rejected a pulse.
    pub rejected_a: Signal<In, Bit>,
    /// The B filter rejected a pulse.
    pub rejected_b: Signal<In, Bit>,
    /// The Z filter rejected a pulse.
    pub rejected_z: Signal<In, Bit>,
    /// A revolution with the wrong count (position counter pulse).
    pub rev_fault: Signal<In, Bit>,
    /// Sticky illegal transition.
    pub fault_illegal: Signal<Out, Bit>,
    /// Sticky over-speed (A or B pulse shorter than the filter).
    pub fault_overspeed: Signal<Out, Bit>,
    /// Sticky revolution count error.
    pub fault_revolution: Signal<Out, Bit>,
    /// Rejected pulses of A, B and Z (saturating).
    pub glitch_count: Signal<Out, Bits<G>>,
    illegal_reg: DFF<Bit>,
    overspeed_reg: DFF<Bit>,
    revolution_reg: DFF<Bit>,
    count: DFF<Bits<G>>,
    /// Rejected pulses this cycle, 0..=3.
    rejected: Signal<Local, Bits<G>>,
    /// count + rejected (one carry chain).
    sum: Signal<Local, Bits<G>>,
    /// The low two bits of count plus rejected: bit 2 is their carry.
    low_sum: Signal<Local, Bits<G>>,
    zero: Constant<Bits<G>>,
    one: Constant<Bits<G>>,
    two: Constant<Bits<G>>,
    three: Constant<Bits<G>>,
    four: Constant<Bits<G>>,
    max: Constant<Bits<G>>,
}

impl Default for FaultFlags {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            clear_faults: Default::default(),
            illegal: Default::default(),
            rejected_a: Default::default(),
            rejected_b: Default::default(),
            rejected_z: Default::default(),
            rev_fault: Default::default(),
            fault_illegal: Default::default(),
            fault_overspeed: Default::default(),
            fault_revolution: Default::default(),
            glitch_count: Default::default(),
            illegal_reg: Default::default(),
            overspeed_reg: Default::default(),
            revolution_reg: Default::default(),
            count: Default::default(),
            rejected: Default::default(),
            sum: Default::default(),
            low_sum: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            two: Constant::new(2.into()),
            three: Constant::new(3.into()),
            four: Constant::new(4.into()),
            max: Constant::new(((1u64 << G) - 1).into()),
        }
    }
}

impl Logic for FaultFlags {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            illegal_reg,
            overspeed_reg,
            revolution_reg,
            count
        );
        self.illegal_reg.d.next =
            (self.illegal_reg.q.val() & !self.clear_faults.val()) | self.illegal.val();
        self.overspeed_reg.d.next = (self.overspeed_reg.q.val() & !self.clear_faults.val())
            | self.rejected_a.val()
            | self.rejected_b.val();
        self.revolution_reg.d.next =
            (self.revolution_reg.q.val() & !self.clear_faults.val()) | self.rev_fault.val();
        // Saturating add of 0..=3 with one carry chain: count + k exceeds the maximum
        // (all ones) exactly when count's bits above bit 1 are all ones and its low two bits
        // plus k carry out of bit 1 (k ≤ 3). (Three incrementers in series, each with its
        // own saturation test, were the core's critical path at 100 MHz.)
        self.rejected.next = self.zero.val();
        if self.rejected_a.val() ^ self.rejected_b.val() ^ self.rejected_z.val() {
            self.rejected.next = self.one.val();
        }
        if (self.rejected_a.val() & self.rejected_b.val())
            | (self.rejected_a.val() & self.rejected_z.val())
            | (self.rejected_b.val() & self.rejected_z.val())
        {
            self.rejected.next = self.rejected.val() | self.two.val();
        }
        self.sum.next = self.count.q.val() + self.rejected.val();
        self.low_sum.next = (self.count.q.val() & self.three.val()) + self.rejected.val();
        self.count.d.next = self.sum.val();
        if ((self.count.q.val() | self.three.val()) == self.max.val())
            & ((self.low_sum.val() & self.four.val()) != self.zero.val())
        {
            self.count.d.next = self.max.val();
        }
        if self.reset.val() {
            self.illegal_reg.d.next = false;
            self.overspeed_reg.d.next = false;
            self.revolution_reg.d.next = false;
            self.count.d.next = self.zero.val();
        }
        self.fault_illegal.next = self.illegal_reg.q.val();
        self.fault_overspeed.next = self.overspeed_reg.q.val();
        self.fault_revolution.next = self.revolution_reg.q.val();
        self.glitch_count.next = self.count.q.val();
    }
}
