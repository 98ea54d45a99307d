// SPDX-License-Identifier: MIT OR Apache-2.0
//! Fixed-time (PC) counter: net signed steps in consecutive windows of `cfg_dt` cycles of
//! a free-running time base. Bit-true model: [`golden::baselines::pc_counter::PcCounter`], whose module
//! docs give the semantics, latency and error bound in full.
//!
//! Per clock edge (N = counter width, 2..=32):
//! - time base: `tick` = phase ≥ max(`cfg_dt`, 1) − 1; phase ← 0 on a tick, else + 1. Steps
//!   never restart it (with a constant dt D the ticks are edges D, 2D, … after reset);
//! - unsigned counters f, b of forward and backward steps of the window [tick, next tick):
//!   the step of a tick edge starts the next window (`golden::ideal::fixed_time`'s
//!   convention). A window is at most 2^N − 1 edges, so f and b never overflow;
//! - on a tick: `count` ← f − b clamped to N-bit two's complement [−2^(N−1), 2^(N−1) − 1]
//!   (`saturated` tells), `strobe` ← 1 for one cycle.
//!
//! Ports: `clock`, `reset` (synchronous, active high), `step`, `forward` (from the
//! quadrature decoder), `cfg_dt[N-1:0]` (cycles; read combinationally every cycle).
//! Registered outputs: `count[N-1:0]` (two's complement), `saturated`, `strobe`.
//! Latency: the count of a window is published by the window's closing tick edge (no
//! further stage). Reset clears every register.

use rust_hdl::prelude::*;

/// Fixed-time (pulse count) counter with N-bit time base and count.
#[derive(LogicBlock)]
pub struct PcCounter<const N: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// One step of the decoder.
    pub step: Signal<In, Bit>,
    /// The step is forward.
    pub forward: Signal<In, Bit>,
    /// Window length, clock cycles (0 counts as 1).
    pub cfg_dt: Signal<In, Bits<N>>,
    /// Net steps of the last window, N-bit two's complement, saturating.
    pub count: Signal<Out, Bits<N>>,
    /// The last count was clamped.
    pub saturated: Signal<Out, Bit>,
    /// One cycle per window end (count written).
    pub strobe: Signal<Out, Bit>,
    phase: DFF<Bits<N>>,
    fwd: DFF<Bits<N>>,
    bwd: DFF<Bits<N>>,
    count_reg: DFF<Bits<N>>,
    sat_reg: DFF<Bit>,
    strobe_reg: DFF<Bit>,
    dt_limit: Signal<Local, Bits<N>>,
    tick: Signal<Local, Bit>,
    diff: Signal<Local, Bits<N>>,
    zero: Constant<Bits<N>>,
    one: Constant<Bits<N>>,
    max_pos: Constant<Bits<N>>,
    min_mag: Constant<Bits<N>>,
}

impl<const N: usize> Default for PcCounter<N> {
    fn default() -> Self {
        assert!((2..=32).contains(&N), "N outside 2..=32");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            step: Default::default(),
            forward: Default::default(),
            cfg_dt: Default::default(),
            count: Default::default(),
            saturated: Default::default(),
            strobe: Default::default(),
            phase: Default::default(),
            fwd: Default::default(),
            bwd: Default::default(),
            count_reg: Default::default(),
            sat_reg: Default::default(),
            strobe_reg: Default::default(),
            dt_limit: Default::default(),
            tick: Default::default(),
            diff: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            max_pos: Constant::new(((1u64 << (N - 1)) - 1).into()),
            min_mag: Constant::new((1u64 << (N - 1)).into()),
        }
    }
}

impl<const N: usize> Logic for PcCounter<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, phase, fwd, bwd, count_reg, sat_reg, strobe_reg);
        self.dt_limit.next = self.cfg_dt.val() - self.one.val();
        if self.cfg_dt.val() == self.zero.val() {
            self.dt_limit.next = self.zero.val();
        }
        self.tick.next = self.phase.q.val() >= self.dt_limit.val();
        self.phase.d.next = self.phase.q.val() + self.one.val();
        // |f − b| of the window that may end now.
        self.diff.next = self.bwd.q.val() - self.fwd.q.val();
        if self.fwd.q.val() >= self.bwd.q.val() {
            self.diff.next = self.fwd.q.val() - self.bwd.q.val();
        }
        self.strobe_reg.d.next = self.tick.val();
        if self.tick.val() {
            self.phase.d.next = self.zero.val();
            self.fwd.d.next = self.zero.val();
            self.bwd.d.next = self.zero.val();
            if self.step.val() & self.forward.val() {
                self.fwd.d.next = self.one.val();
            }
            if self.step.val() & !self.forward.val() {
                self.bwd.d.next = self.one.val();
            }
            self.sat_reg.d.next = false;
            if self.fwd.q.val() >= self.bwd.q.val() {
                self.count_reg.d.next = self.diff.val();
                if self.diff.val() > self.max_pos.val() {
                    self.count_reg.d.next = self.max_pos.val();
                    self.sat_reg.d.next = true;
                }
            } else {
                self.count_reg.d.next = self.zero.val() - self.diff.val();
                if self.diff.val() > self.min_mag.val() {
                    self.count_reg.d.next = self.min_mag.val();
                    self.sat_reg.d.next = true;
                }
            }
        } else {
            if self.step.val() & self.forward.val() {
                self.fwd.d.next = self.fwd.q.val() + self.one.val();
            }
            if self.step.val() & !self.forward.val() {
                self.bwd.d.next = self.bwd.q.val() + self.one.val();
            }
        }
        if self.reset.val() {
            self.phase.d.next = self.zero.val();
            self.fwd.d.next = self.zero.val();
            self.bwd.d.next = self.zero.val();
            self.count_reg.d.next = self.zero.val();
            self.sat_reg.d.next = false;
            self.strobe_reg.d.next = false;
        }
        self.count.next = self.count_reg.q.val();
        self.saturated.next = self.sat_reg.q.val();
        self.strobe.next = self.strobe_reg.q.val();
    }
}

/// The Verilog of a [`PcCounter`], top module named `module_name`.
pub fn pc_counter_verilog<const N: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<PcCounter<N>>(module_name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::verilator_lint;

    #[test]
    fn synthesises() {
        let mut uut = PcCounter::<24>::default();
        uut.connect_all();
        yosys_validate("encspeed_pc_counter", &generate_verilog(&uut)).unwrap();
    }

    #[test]
    fn verilator_lint_is_clean() {
        verilator_lint("pc_counter", &pc_counter_verilog::<24>("pc_counter"));
        verilator_lint("pc_counter", &pc_counter_verilog::<2>("pc_counter"));
    }
}
