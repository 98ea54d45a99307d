// SPDX-License-Identifier: MIT OR Apache-2.0
//! Fixed-space (ET) timer: clock cycles between consecutive steps of one direction.
//! Bit-true model: [`golden::baselines::et_timer::EtTimer`], whose module docs give the semantics,
//! latency and error bound in full.
//!
//! Per clock edge (N = counter width, 2..=32, max = 2^N − 1; e⁺ = min(e + 1, max)):
//! - no step: e ← e⁺;
//! - a step of the direction of the previous one (`armed`): `period` ← e⁺ (cycles since that
//!   step, saturated at max = "at least max", zero speed), `negative` ← ¬`forward`,
//!   `strobe` ← 1; e ← 0;
//! - the first step after reset or a reversal: no period (no spike mixing two directions),
//!   the measurement restarts on it: `armed` ← 1, direction ← `forward`, e ← 0;
//! - `stalled` = (e = max).
//!
//! Ports: `clock`, `reset` (synchronous, active high), `step`, `forward`. Registered
//! outputs: `period[N-1:0]` (cycles), `negative`, `strobe`, `stalled`. Latency: a step
//! sampled at edge j gives its period and strobe after edge j. Reset clears every register.

use rust_hdl::prelude::*;

/// Elapsed-time timer with an N-bit saturating cycle counter.
#[derive(LogicBlock)]
pub struct EtTimer<const N: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// One step of the decoder.
    pub step: Signal<In, Bit>,
    /// The step is forward.
    pub forward: Signal<In, Bit>,
    /// Cycles between the last two steps of one direction (saturated at 2^N − 1).
    pub period: Signal<Out, Bits<N>>,
    /// The last period was measured backward.
    pub negative: Signal<Out, Bit>,
    /// One cycle per period written.
    pub strobe: Signal<Out, Bit>,
    /// No step for 2^N − 1 cycles or more.
    pub stalled: Signal<Out, Bit>,
    elapsed: DFF<Bits<N>>,
    armed: DFF<Bit>,
    dir: DFF<Bit>,
    period_reg: DFF<Bits<N>>,
    neg_reg: DFF<Bit>,
    strobe_reg: DFF<Bit>,
    e_inc: Signal<Local, Bits<N>>,
    zero: Constant<Bits<N>>,
    one: Constant<Bits<N>>,
    max: Constant<Bits<N>>,
}

impl<const N: usize> Default for EtTimer<N> {
    fn default() -> Self {
        assert!((2..=32).contains(&N), "N outside 2..=32");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            step: Default::default(),
            forward: Default::default(),
            period: Default::default(),
            negative: Default::default(),
            strobe: Default::default(),
            stalled: Default::default(),
            elapsed: Default::default(),
            armed: Default::default(),
            dir: Default::default(),
            period_reg: Default::default(),
            neg_reg: Default::default(),
            strobe_reg: Default::default(),
            e_inc: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            max: Constant::new(((1u64 << N) - 1).into()),
        }
    }
}

impl<const N: usize> Logic for EtTimer<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, elapsed, armed, dir, period_reg, neg_reg, strobe_reg);
        self.e_inc.next = self.elapsed.q.val() + self.one.val();
        if self.elapsed.q.val() == self.max.val() {
            self.e_inc.next = self.max.val();
        }
        self.strobe_reg.d.next = false;
        self.elapsed.d.next = self.e_inc.val();
        if self.step.val() {
            if self.armed.q.val() & !(self.forward.val() ^ self.dir.q.val()) {
                self.period_reg.d.next = self.e_inc.val();
                self.neg_reg.d.next = !self.forward.val();
                self.strobe_reg.d.next = true;
            }
            self.armed.d.next = true;
            self.dir.d.next = self.forward.val();
            self.elapsed.d.next = self.zero.val();
        }
        if self.reset.val() {
            self.elapsed.d.next = self.zero.val();
            self.armed.d.next = false;
            self.dir.d.next = false;
            self.period_reg.d.next = self.zero.val();
            self.neg_reg.d.next = false;
            self.strobe_reg.d.next = false;
        }
        self.period.next = self.period_reg.q.val();
        self.negative.next = self.neg_reg.q.val();
        self.strobe.next = self.strobe_reg.q.val();
        self.stalled.next = self.elapsed.q.val() == self.max.val();
    }
}

/// The Verilog of an [`EtTimer`], top module named `module_name`.
pub fn et_timer_verilog<const N: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<EtTimer<N>>(module_name)
}
