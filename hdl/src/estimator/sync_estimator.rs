// SPDX-License-Identifier: MIT OR Apache-2.0
//! The synchronised Nep/Ndt registers of Rairán's Table 1: Cep, Nep1, Ndt1.
//!
//! Cep counts pulses since the last dt tick. At a tick, Nep1 takes Cep if it is non-zero
//! (line 8-9) and Cep is cleared (line 13); at a restart (a pulse after at least one tick),
//! Ndt1 takes Cdt from the time base (line 5-6). A pulse in the same cycle as a tick is
//! counted and then cleared with Cep, as in the paper's order of lines 10-13. Cep saturates
//! at 2^N − 1 instead of wrapping.
//!
//! All outputs are registers. Reset: Cep = Nep1 = 0, Ndt1 = 1.

use rust_hdl::prelude::*;

/// Table 1 registers Cep, Nep1, Ndt1 and the update strobe.
#[derive(LogicBlock)]
pub struct SyncEstimator<const N: usize> {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset (Table 1 line 1).
    pub reset: Signal<In, Bit>,
    /// Encoder pulse (one cycle per rising edge of A).
    pub lep: Signal<In, Bit>,
    /// dt tick from the time base.
    pub tick: Signal<In, Bit>,
    /// Restart from the time base (a pulse after at least one tick).
    pub restart: Signal<In, Bit>,
    /// Cdt from the time base.
    pub cdt: Signal<In, Bits<N>>,
    /// Nep1: pulses in the last dt window that started at a pulse.
    pub nep: Signal<Out, Bits<N>>,
    /// Ndt1: whole dt intervals between the last two pulses.
    pub ndt: Signal<Out, Bits<N>>,
    /// High for the cycle after a clock edge that wrote Nep1 or Ndt1.
    pub update: Signal<Out, Bit>,
    /// Ndt1 has been measured (a restart) since reset: the estimator is primed.
    pub primed: Signal<Out, Bit>,
    /// The last edge wrote Nep1 (a tick with Cep ≠ 0).
    pub wrote_nep: Signal<Out, Bit>,
    /// The last edge was a restart (it wrote Ndt1).
    pub restarted: Signal<Out, Bit>,
    wrote_nep_reg: DFF<Bit>,
    restarted_reg: DFF<Bit>,
    nep_write: Signal<Local, Bit>,
    pub cep: DFF<Bits<N>>,
    /// Cep ≠ 0, set with Cep: the tick's write and the count's enable do not wait for a
    /// reduction of all N bits of Cep (it was a critical path of the Wishbone top).
    cep_nonzero: DFF<Bit>,
    /// Cep = 2^N − 1 (saturated), set with Cep.
    cep_saturated: DFF<Bit>,
    nep1: DFF<Bits<N>>,
    ndt1: DFF<Bits<N>>,
    update_reg: DFF<Bit>,
    primed_reg: DFF<Bit>,
    zero: Constant<Bits<N>>,
    one: Constant<Bits<N>>,
    saturated: Constant<Bits<N>>,
    /// 2^N − 2: an increment from here saturates.
    saturated_less_one: Constant<Bits<N>>,
}

impl<const N: usize> Default for SyncEstimator<N> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            lep: Default::default(),
            tick: Default::default(),
            restart: Default::default(),
            cdt: Default::default(),
            nep: Default::default(),
            ndt: Default::default(),
            update: Default::default(),
            primed: Default::default(),
            cep: Default::default(),
            cep_nonzero: Default::default(),
            cep_saturated: Default::default(),
            nep1: Default::default(),
            ndt1: Default::default(),
            update_reg: Default::default(),
            primed_reg: Default::default(),
            wrote_nep: Default::default(),
            restarted: Default::default(),
            wrote_nep_reg: Default::default(),
            restarted_reg: Default::default(),
            nep_write: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            saturated: Constant::new(((1u64 << N) - 1).into()),
            saturated_less_one: Constant::new(((1u64 << N) - 2).into()),
        }
    }
}

impl<const N: usize> Logic for SyncEstimator<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            cep,
            cep_nonzero,
            cep_saturated,
            nep1,
            ndt1,
            update_reg,
            primed_reg,
            wrote_nep_reg,
            restarted_reg
        );
        self.nep_write.next = self.tick.val() & self.cep_nonzero.q.val();
        if self.nep_write.val() {
            self.nep1.d.next = self.cep.q.val();
        }
        if self.restart.val() {
            self.ndt1.d.next = self.cdt.val();
        }
        // Line 10-11 (saturating), then line 13.
        if self.lep.val() & !self.cep_saturated.q.val() {
            self.cep.d.next = self.cep.q.val() + self.one.val();
            self.cep_nonzero.d.next = true;
            self.cep_saturated.d.next = self.cep.q.val() == self.saturated_less_one.val();
        }
        if self.tick.val() {
            self.cep.d.next = self.zero.val();
            self.cep_nonzero.d.next = false;
            self.cep_saturated.d.next = false;
        }
        self.update_reg.d.next = self.nep_write.val() | self.restart.val();
        self.wrote_nep_reg.d.next = self.nep_write.val();
        self.restarted_reg.d.next = self.restart.val();
        self.primed_reg.d.next = self.primed_reg.q.val() | self.restart.val();
        if self.reset.val() {
            // A pulse in the reset cycle is the first of the new measurement (the core
            // resets the estimator at the first step of a direction and counts that step,
            // as a restart would): the window starts at a pulse.
            self.primed_reg.d.next = false;
            self.cep.d.next = self.zero.val();
            self.cep_nonzero.d.next = false;
            self.cep_saturated.d.next = false;
            if self.lep.val() {
                self.cep.d.next = self.one.val();
                self.cep_nonzero.d.next = true;
                // N = 1: Cep = 1 is already saturated.
                self.cep_saturated.d.next = self.one.val() == self.saturated.val();
            }
            self.nep1.d.next = self.zero.val();
            self.ndt1.d.next = self.one.val();
            self.update_reg.d.next = false;
            self.wrote_nep_reg.d.next = false;
            self.restarted_reg.d.next = false;
        }
        self.nep.next = self.nep1.q.val();
        self.ndt.next = self.ndt1.q.val();
        self.update.next = self.update_reg.q.val();
        self.primed.next = self.primed_reg.q.val();
        self.wrote_nep.next = self.wrote_nep_reg.q.val();
        self.restarted.next = self.restarted_reg.q.val();
    }
}
