// SPDX-License-Identifier: MIT OR Apache-2.0
//! The eccentricity window's part of the snapshot (`encspeed_ecc_wb`; specified in
//! [`golden::bus::ecc_regmap`], modelled in [`golden::bus::ecc_regs::EccRegsModel`]): at an
//! edge where `take` is high it stores the corrected speeds `speed_mtc` and `speed_n3c` as
//! they stand before the edge, the same edge at which the core's register file stores
//! position and the six speeds ([`crate::bus::snapshot::Snapshot`]); the `seen_*` outputs
//! are the values the window reads: the snapshot while `sampled` is high, else the live
//! inputs.
//!
//! Ports: `clock`, `reset` (synchronous: the snapshot to 0); `take`, `sampled` (from the
//! core's register file: `take` = (`sample` & !`CTRL.HOLD`) | the `CTRL.TRIGGER` pulse,
//! `sampled` = `CTRL.SAMPLED`); `speed_mtc`, `speed_n3c` in (S bits, registers of
//! `encspeed_ecc`); `seen_mtc`, `seen_n3c` out (a 2:1 choice between a register and an
//! input). Why a block of its own: the window is a second slave with its own cells, and
//! `SNAP_COUNT` and the choice of what to snapshot stay in the core's file; this block
//! only follows its `take` and `sampled`, so one `sample` strobe stores all eight speeds
//! of one cycle.

use rust_hdl::prelude::*;

/// Snapshot of the two corrected speeds, S bits each.
#[derive(LogicBlock)]
pub struct EccSnapshot<const S: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset: the snapshot to 0.
    pub reset: Signal<In, Bit>,
    /// Store the live speeds at this edge.
    pub take: Signal<In, Bit>,
    /// Read the snapshot instead of the live speeds.
    pub sampled: Signal<In, Bit>,
    /// Corrected M/T speed, live.
    pub speed_mtc: Signal<In, Bits<S>>,
    /// Corrected n3, live.
    pub speed_n3c: Signal<In, Bits<S>>,
    /// `speed_mtc` as the window reads it.
    pub seen_mtc: Signal<Out, Bits<S>>,
    /// `speed_n3c` as the window reads it.
    pub seen_n3c: Signal<Out, Bits<S>>,
    mtc_q: DFF<Bits<S>>,
    n3c_q: DFF<Bits<S>>,
    /// A zero of the speeds' width (a literal would be emitted 32 bits wide).
    zero_s: Constant<Bits<S>>,
}

impl<const S: usize> Default for EccSnapshot<S> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            take: Default::default(),
            sampled: Default::default(),
            speed_mtc: Default::default(),
            speed_n3c: Default::default(),
            seen_mtc: Default::default(),
            seen_n3c: Default::default(),
            mtc_q: Default::default(),
            n3c_q: Default::default(),
            zero_s: Constant::new(0.into()),
        }
    }
}

impl<const S: usize> Logic for EccSnapshot<S> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, mtc_q, n3c_q);
        if self.take.val() {
            self.mtc_q.d.next = self.speed_mtc.val();
            self.n3c_q.d.next = self.speed_n3c.val();
        }
        if self.reset.val() {
            self.mtc_q.d.next = self.zero_s.val();
            self.n3c_q.d.next = self.zero_s.val();
        }
        if self.sampled.val() {
            self.seen_mtc.next = self.mtc_q.q.val();
            self.seen_n3c.next = self.n3c_q.q.val();
        } else {
            self.seen_mtc.next = self.speed_mtc.val();
            self.seen_n3c.next = self.speed_n3c.val();
        }
    }
}
