// SPDX-License-Identifier: MIT OR Apache-2.0
//! The register file's snapshot of `encspeed_core` (`sample` input, `CTRL.TRIGGER`,
//! `CTRL.SAMPLED`, `SNAP_COUNT`; specified in [`golden::bus::regmap`], modelled by
//! [`golden::bus::wb_regs::Snapshot`]): at an edge where `take` is high it stores
//! `position`, `nep`, `ndt`, the six speeds and `valid`, `stalled`, `direction` as they
//! stand before the edge, and counts it; the `seen_*` outputs are the values the register
//! file reads: the snapshot while `sampled` is high, else the live inputs.
//!
//! Ports: `clock`, `reset` (synchronous: snapshot and count to 0); `take`, `sampled`
//! (registers of the file: `take` = (`sample` & !`CTRL.HOLD`) | the `TRIGGER` pulse); the
//! live values in; `seen_*` out (a 2:1 choice between a register and an input, both
//! registers of the core); `count` (32, a register, modulo 2^32).

use rust_hdl::prelude::*;

/// A snapshot of the core's values: N-bit counters, S-bit speeds, C-bit position.
#[derive(LogicBlock)]
pub struct Snapshot<const N: usize, const S: usize, const C: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Store the live values at this edge.
    pub take: Signal<In, Bit>,
    /// Read the snapshot (`CTRL.SAMPLED`), else the live values.
    pub sampled: Signal<In, Bit>,
    /// Live `position`.
    pub position: Signal<In, Bits<C>>,
    /// Live `nep`.
    pub nep: Signal<In, Bits<N>>,
    /// Live `ndt`.
    pub ndt: Signal<In, Bits<N>>,
    /// Live speeds n1, n2, n3, PC, ET, M/T.
    pub speed_n1: Signal<In, Bits<S>>,
    /// Live `speed_n2`.
    pub speed_n2: Signal<In, Bits<S>>,
    /// Live `speed_n3`.
    pub speed_n3: Signal<In, Bits<S>>,
    /// Live `speed_pc`.
    pub speed_pc: Signal<In, Bits<S>>,
    /// Live `speed_et`.
    pub speed_et: Signal<In, Bits<S>>,
    /// Live `speed_mt`.
    pub speed_mt: Signal<In, Bits<S>>,
    /// Live `valid`.
    pub valid: Signal<In, Bit>,
    /// Live `stalled`.
    pub stalled: Signal<In, Bit>,
    /// Live `direction`.
    pub direction: Signal<In, Bit>,
    /// `position` as the file reads it.
    pub seen_position: Signal<Out, Bits<C>>,
    /// `nep` as the file reads it.
    pub seen_nep: Signal<Out, Bits<N>>,
    /// `ndt` as the file reads it.
    pub seen_ndt: Signal<Out, Bits<N>>,
    /// `speed_n1` as the file reads it.
    pub seen_n1: Signal<Out, Bits<S>>,
    /// `speed_n2` as the file reads it.
    pub seen_n2: Signal<Out, Bits<S>>,
    /// `speed_n3` as the file reads it.
    pub seen_n3: Signal<Out, Bits<S>>,
    /// `speed_pc` as the file reads it.
    pub seen_pc: Signal<Out, Bits<S>>,
    /// `speed_et` as the file reads it.
    pub seen_et: Signal<Out, Bits<S>>,
    /// `speed_mt` as the file reads it.
    pub seen_mt: Signal<Out, Bits<S>>,
    /// `valid` as the file reads it.
    pub seen_valid: Signal<Out, Bit>,
    /// `stalled` as the file reads it.
    pub seen_stalled: Signal<Out, Bit>,
    /// `direction` as the file reads it.
    pub seen_direction: Signal<Out, Bit>,
    /// Snapshots taken since reset, modulo 2^32.
    pub count: Signal<Out, Bits<32>>,
    position_q: DFF<Bits<C>>,
    nep_q: DFF<Bits<N>>,
    ndt_q: DFF<Bits<N>>,
    n1_q: DFF<Bits<S>>,
    n2_q: DFF<Bits<S>>,
    n3_q: DFF<Bits<S>>,
    pc_q: DFF<Bits<S>>,
    et_q: DFF<Bits<S>>,
    mt_q: DFF<Bits<S>>,
    valid_q: DFF<Bit>,
    stalled_q: DFF<Bit>,
    direction_q: DFF<Bit>,
    count_q: DFF<Bits<32>>,
    // Zeros of each width (a literal would be emitted 32 bits wide).
    zero_c: Constant<Bits<C>>,
    zero_n: Constant<Bits<N>>,
    zero_s: Constant<Bits<S>>,
    zero_32: Constant<Bits<32>>,
    one_32: Constant<Bits<32>>,
}

impl<const N: usize, const S: usize, const C: usize> Default for Snapshot<N, S, C> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            take: Default::default(),
            sampled: Default::default(),
            position: Default::default(),
            nep: Default::default(),
            ndt: Default::default(),
            speed_n1: Default::default(),
            speed_n2: Default::default(),
            speed_n3: Default::default(),
            speed_pc: Default::default(),
            speed_et: Default::default(),
            speed_mt: Default::default(),
            valid: Default::default(),
            stalled: Default::default(),
            direction: Default::default(),
            seen_position: Default::default(),
            seen_nep: Default::default(),
            seen_ndt: Default::default(),
            seen_n1: Default::default(),
            seen_n2: Default::default(),
            seen_n3: Default::default(),
            seen_pc: Default::default(),
            seen_et: Default::default(),
            seen_mt: Default::default(),
            seen_valid: Default::default(),
            seen_stalled: Default::default(),
            seen_direction: Default::default(),
            count: Default::default(),
            position_q: Default::default(),
            nep_q: Default::default(),
            ndt_q: Default::default(),
            n1_q: Default::default(),
            n2_q: Default::default(),
            n3_q: Default::default(),
            pc_q: Default::default(),
            et_q: Default::default(),
            mt_q: Default::default(),
            valid_q: Default::default(),
            stalled_q: Default::default(),
            direction_q: Default::default(),
            count_q: Default::default(),
            zero_c: Constant::new(0.into()),
            zero_n: Constant::new(0.into()),
            zero_s: Constant::new(0.into()),
            zero_32: Constant::new(0.into()),
            one_32: Constant::new(1.into()),
        }
    }
}

impl<const N: usize, const S: usize, const C: usize> Logic for Snapshot<N, S, C> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            position_q,
            nep_q,
            ndt_q,
            n1_q,
            n2_q,
            n3_q,
            pc_q,
            et_q,
            mt_q,
            valid_q,
            stalled_q,
            direction_q,
            count_q
        );
        if self.take.val() {
            self.position_q.d.next = self.position.val();
            self.nep_q.d.next = self.nep.val();
            self.ndt_q.d.next = self.ndt.val();
            self.n1_q.d.next = self.speed_n1.val();
            self.n2_q.d.next = self.speed_n2.val();
            self.n3_q.d.next = self.speed_n3.val();
            self.pc_q.d.next = self.speed_pc.val();
            self.et_q.d.next = self.speed_et.val();
            self.mt_q.d.next = self.speed_mt.val();
            self.valid_q.d.next = self.valid.val();
            self.stalled_q.d.next = self.stalled.val();
            self.direction_q.d.next = self.direction.val();
            self.count_q.d.next = self.count_q.q.val() + self.one_32.val();
        }
        if self.reset.val() {
            self.position_q.d.next = self.zero_c.val();
            self.nep_q.d.next = self.zero_n.val();
            self.ndt_q.d.next = self.zero_n.val();
            self.n1_q.d.next = self.zero_s.val();
            self.n2_q.d.next = self.zero_s.val();
            self.n3_q.d.next = self.zero_s.val();
            self.pc_q.d.next = self.zero_s.val();
            self.et_q.d.next = self.zero_s.val();
            self.mt_q.d.next = self.zero_s.val();
            self.valid_q.d.next = false;
            self.stalled_q.d.next = false;
            self.direction_q.d.next = false;
            self.count_q.d.next = self.zero_32.val();
        }
        self.count.next = self.count_q.q.val();
        if self.sampled.val() {
            self.seen_position.next = self.position_q.q.val();
            self.seen_nep.next = self.nep_q.q.val();
            self.seen_ndt.next = self.ndt_q.q.val();
            self.seen_n1.next = self.n1_q.q.val();
            self.seen_n2.next = self.n2_q.q.val();
            self.seen_n3.next = self.n3_q.q.val();
            self.seen_pc.next = self.pc_q.q.val();
            self.seen_et.next = self.et_q.q.val();
            self.seen_mt.next = self.mt_q.q.val();
            self.seen_valid.next = self.valid_q.q.val();
            self.seen_stalled.next = self.stalled_q.q.val();
            self.seen_direction.next = self.direction_q.q.val();
        } else {
            self.seen_position.next = self.position.val();
            self.seen_nep.next = self.nep.val();
            self.seen_ndt.next = self.ndt.val();
            self.seen_n1.next = self.speed_n1.val();
            self.seen_n2.next = self.speed_n2.val();
            self.seen_n3.next = self.speed_n3.val();
            self.seen_pc.next = self.speed_pc.val();
            self.seen_et.next = self.speed_et.val();
            self.seen_mt.next = self.speed_mt.val();
            self.seen_valid.next = self.valid.val();
            self.seen_stalled.next = self.stalled.val();
            self.seen_direction.next = self.direction.val();
        }
    }
}
