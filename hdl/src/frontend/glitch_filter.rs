// SPDX-License-Identifier: MIT OR Apache-2.0
//! Programmable glitch filter of one synchronised encoder channel, with a counter of
//! rejected pulses. Bit-true model: [`golden::frontend::GlitchFilter`].
//!
//! A new level passes to `level_out` only after it has been sampled `cfg_filter` = L
//! consecutive cycles; a pulse shorter than that is dropped and counted in `glitches`. Per
//! clock edge (`run` counts the cycles in which the input has differed from `level_out`):
//! - input ≠ `level_out`: if run + 1 ≥ L then `level_out` = input and run = 0, else run + 1;
//! - input = `level_out`: if run ≠ 0, `glitches` + 1 (saturating at 2^G − 1); run = 0.
//!
//! Ports: `level_in` (synchronised channel), `cfg_filter[F-1:0]` (L; 0 and 1 pass every
//! change), `level_out` (filtered level, a register), `glitches[G-1:0]` (rejected pulses
//! since reset, a register).
//!
//! Latency: a level held for at least max(L, 1) cycles shows on `level_out` max(L, 1) clock
//! edges after the first edge that sampled it (L ≤ 1: that same edge, i.e. one register).
//!
//! The pass decision run + 1 ≥ L is made an edge ahead and registered (`ready`), so that
//! the output register's enable comes from a flip-flop and not from a carry chain: for the
//! run after an edge, run' + 1 ≥ L is L ≤ 1 when run' = 0 (a bit test) and run + 2 ≥ L
//! when run' = run + 1. The block keeps run + 2 mod 2^F with bit 1 inverted
//! (`plus_two_reg`) instead of the run, so that its power-up and reset value 0 is run = 0
//! and the comparison is one carry chain from a register. L is therefore the `cfg_filter`
//! of the edge before: a change acts one edge later (the model says the same). Since
//! run + 1 < L ≤ 2^F − 1 whenever run is incremented, run ≤ 2^F − 2, and run + 2 wraps only
//! at run = 2^F − 2, where `ready` is already set (2^F − 1 ≥ L), so the run after the edge
//! is 0 and the wrapped value is not compared.
//!
//! Reset (synchronous, active high): `level_out` = 0, run = 0, `glitches` = 0, `ready` =
//! (L ≤ 1). A channel that is high at reset therefore reaches `level_out` after max(L, 1)
//! edges: consumers must not take that for a transition (see `golden::frontend`, start-up).

use rust_hdl::prelude::*;

/// Glitch filter with an F-bit length `cfg_filter` and a G-bit glitch counter.
#[derive(LogicBlock)]
pub struct GlitchFilter<const F: usize, const G: usize> {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Channel level, synchronised to `clock`.
    pub level_in: Signal<In, Bit>,
    /// L: cycles a new level must be seen before it passes.
    pub cfg_filter: Signal<In, Bits<F>>,
    /// Filtered level.
    pub level_out: Signal<Out, Bit>,
    /// Rejected pulses since reset (saturating).
    pub glitches: Signal<Out, Bits<G>>,
    /// One cycle: a pulse was rejected at the last edge (also once `glitches` saturates).
    pub rejected: Signal<Out, Bit>,
    filtered: DFF<Bit>,
    rejected_reg: DFF<Bit>,
    /// run + 2 mod 2^F with bit 1 inverted (power-up and reset value 0 is run = 0).
    plus_two_reg: DFF<Bits<F>>,
    /// run + 1 ≥ L for this cycle's run and the L of the edge before.
    ready: DFF<Bit>,
    glitch_count: DFF<Bits<G>>,
    differs: Signal<Local, Bit>,
    /// run + 2 mod 2^F.
    plus_two: Signal<Local, Bits<F>>,
    /// L ≤ 1: every change passes (a test of the bits, no chain).
    filter_at_most_one: Signal<Local, Bit>,
    run_zero: Constant<Bits<F>>,
    run_one: Constant<Bits<F>>,
    run_two: Constant<Bits<F>>,
    /// Every bit but bit 0.
    above_one: Constant<Bits<F>>,
    count_zero: Constant<Bits<G>>,
    count_one: Constant<Bits<G>>,
    count_max: Constant<Bits<G>>,
}

impl<const F: usize, const G: usize> Default for GlitchFilter<F, G> {
    fn default() -> Self {
        assert!(
            (2..=32).contains(&F) && (1..=32).contains(&G),
            "widths: F 2..=32, G 1..=32"
        );
        Self {
            clock: Default::default(),
            reset: Default::default(),
            level_in: Default::default(),
            cfg_filter: Default::default(),
            level_out: Default::default(),
            glitches: Default::default(),
            rejected: Default::default(),
            filtered: Default::default(),
            rejected_reg: Default::default(),
            plus_two_reg: Default::default(),
            ready: Default::default(),
            glitch_count: Default::default(),
            differs: Default::default(),
            plus_two: Default::default(),
            filter_at_most_one: Default::default(),
            run_zero: Constant::new(0.into()),
            run_one: Constant::new(1.into()),
            run_two: Constant::new(2.into()),
            above_one: Constant::new((((1u64 << F) - 1) & !1).into()),
            count_zero: Constant::new(0.into()),
            count_one: Constant::new(1.into()),
            count_max: Constant::new(((1u64 << G) - 1).into()),
        }
    }
}

impl<const F: usize, const G: usize> Logic for GlitchFilter<F, G> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            filtered,
            plus_two_reg,
            ready,
            glitch_count,
            rejected_reg
        );
        // The input differs from the filtered level.
        self.differs.next = self.level_in.val() ^ self.filtered.q.val();
        self.plus_two.next = self.plus_two_reg.q.val() ^ self.run_two.val();
        self.filter_at_most_one.next =
            (self.cfg_filter.val() & self.above_one.val()) == self.run_zero.val();
        // By default the run after the edge is 0: the next decision is L ≤ 1.
        self.plus_two_reg.d.next = self.run_zero.val();
        self.ready.d.next = self.filter_at_most_one.val();
        self.rejected_reg.d.next = false;
        if self.differs.val() {
            if self.ready.q.val() {
                self.filtered.d.next = self.level_in.val();
            } else {
                // run' = run + 1: its run + 2 is this cycle's run + 3, and the next
                // decision run' + 1 ≥ L is run + 2 ≥ L.
                self.plus_two_reg.d.next =
                    (self.plus_two.val() + self.run_one.val()) ^ self.run_two.val();
                self.ready.d.next = self.plus_two.val() >= self.cfg_filter.val();
            }
        } else if self.plus_two_reg.q.val() != self.run_zero.val() {
            self.rejected_reg.d.next = true;
            if self.glitch_count.q.val() != self.count_max.val() {
                self.glitch_count.d.next = self.glitch_count.q.val() + self.count_one.val();
            }
        }
        if self.reset.val() {
            self.filtered.d.next = false;
            self.plus_two_reg.d.next = self.run_zero.val();
            self.ready.d.next = self.filter_at_most_one.val();
            self.glitch_count.d.next = self.count_zero.val();
            self.rejected_reg.d.next = false;
        }
        self.level_out.next = self.filtered.q.val();
        self.rejected.next = self.rejected_reg.q.val();
        self.glitches.next = self.glitch_count.q.val();
    }
}

/// The Verilog of a [`GlitchFilter`], top module named `module_name`.
pub fn glitch_filter_verilog<const F: usize, const G: usize>(module_name: &str) -> String {
    crate::verilog::default_block_verilog::<GlitchFilter<F, G>>(module_name)
}
