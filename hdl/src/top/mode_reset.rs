// SPDX-License-Identifier: MIT OR Apache-2.0
//! The decoding mode register and the reset a change of mode causes; bit-true model
//! [`golden::top::mode_reset::ModeReset`], whose docs give the rule.
//!
//! Both the mode and the change are registered, so that the core's reset is `reset` ORed
//! with one flip-flop: the mode comparator does not sit in front of the reset's fan-out
//! (every register of the core), and the decoder and the speed scaling read a register.
//! Latency: a new `cfg_mode` is in `mode` one edge after the edge that samples it, with
//! `rst` high in that same cycle. A change sampled at a `reset` edge raises no second
//! reset (that edge resets the core already), so a reset leaves no trace of the old mode.

use rust_hdl::prelude::*;

/// Registered `cfg_mode` and the reset its change causes.
#[derive(LogicBlock, Default)]
pub struct ModeReset {
    /// Core clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset of the core.
    pub reset: Signal<In, Bit>,
    /// The decoding mode input.
    pub cfg_mode: Signal<In, Bits<2>>,
    /// The reset of the core's registers: `reset`, or a mode change seen at the edge before.
    pub rst: Signal<Out, Bit>,
    /// The decoding mode in use (`cfg_mode` one edge later).
    pub mode: Signal<Out, Bits<2>>,
    mode_reg: DFF<Bits<2>>,
    changed: DFF<Bit>,
}

impl Logic for ModeReset {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, mode_reg, changed);
        self.mode_reg.d.next = self.cfg_mode.val();
        self.changed.d.next = !self.reset.val() & (self.cfg_mode.val() != self.mode_reg.q.val());
        self.rst.next = self.reset.val() | self.changed.q.val();
        self.mode.next = self.mode_reg.q.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_change_resets_at_the_next_edge_with_the_new_mode() {
        let mut uut = ModeReset::default();
        uut.connect_all();
        // By hand (the model's test): cfg_mode 0, 0, 2, 2, 2, 1 at edges 0..5; rst and mode
        // after each edge.
        let cfg = [0u64, 0, 2, 2, 2, 1];
        let expect = [
            (false, 0),
            (false, 0),
            (true, 2),
            (false, 2),
            (false, 2),
            (true, 1),
        ];
        for (k, (&c, &(rst, mode))) in cfg.iter().zip(&expect).enumerate() {
            uut.cfg_mode.next = c.into();
            uut.reset.next = false;
            uut.clock.next = Clock { clk: false };
            assert!(simulate(&mut uut, 10));
            uut.clock.next = Clock { clk: true };
            assert!(simulate(&mut uut, 10));
            assert_eq!(uut.rst.val(), rst, "rst after edge {k}");
            assert_eq!(uut.mode.val(), Bits::<2>::from(mode), "mode after edge {k}");
        }
        uut.reset.next = true;
        assert!(simulate(&mut uut, 10));
        assert!(uut.rst.val(), "reset passes straight through");
        // A change sampled with reset (1 → 2): the mode follows, no second reset.
        uut.cfg_mode.next = 2.into();
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
        uut.reset.next = false;
        assert!(simulate(&mut uut, 10));
        assert!(!uut.rst.val(), "no reset after a change sampled with reset");
        assert_eq!(uut.mode.val(), Bits::<2>::from(2));
    }

    #[test]
    fn synthesises() {
        let mut uut = ModeReset::default();
        uut.connect_all();
        yosys_validate("encspeed_mode_reset", &generate_verilog(&uut)).unwrap();
    }
}
