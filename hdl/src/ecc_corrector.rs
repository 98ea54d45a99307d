//! First-harmonic eccentricity corrector of a line count. Bit-true model:
//! [`golden::ecc_corrector::EccCorrector`], whose module docs give the formats, the
//! latency and the error budget.
//!
//! Two stages:
//! 1. edge j: two [`SineRom`]s (24-bit entries) read S\[m_a\] and S\[m_b\] (phase `m0`), and
//!    `delta_m`, `e_coef` and `start` are registered;
//! 2. edge j + 1: N_c·2^24 = ΔM·2^24 − ⌊(E_reg·(S_b − S_a) + 2^11)/2^12⌋ is written to
//!    `n_c` (49-bit signed Q25.24) with `valid` high for one cycle.
//!
//! The arithmetic of stage 2 is a small hand-written Verilog block ([`EccArith`] in `ecc_arith.rs`, one
//! signed multiply E_reg·(S_b − S_a) of 16 × 25 bits, an arithmetic shift and a sign-extending concatenation, none of which
//! `#[hdl_gen]` emits with the right widths) with a matching `update()`; both simulators
//! are checked against the golden model.
//!
//! Ports: `clock`, `reset` (synchronous, active high), `start`, `delta_m[23:0]`,
//! `m_a[A-1:0]`, `m_b[A-1:0]`, `m0[A-1:0]`, `e_coef[15:0]`; registered outputs
//! `n_c[48:0]`, `valid`.

use crate::ecc_arith::EccArith;
use crate::sine_rom::SineRom;
use rust_hdl::prelude::*;

/// First-harmonic corrector with A-bit positions (module docs).
#[derive(LogicBlock)]
pub struct EccCorrector<const A: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// A correction request this cycle.
    pub start: Signal<In, Bit>,
    /// ΔM, lines, signed.
    pub delta_m: Signal<In, Bits<24>>,
    /// Position of the first edge.
    pub m_a: Signal<In, Bits<A>>,
    /// Position of the second edge.
    pub m_b: Signal<In, Bits<A>>,
    /// Phase offset m0.
    pub m0: Signal<In, Bits<A>>,
    /// E_reg (golden::ecc_corrector::e_register), signed.
    pub e_coef: Signal<In, Bits<16>>,
    /// N_c·2^24, signed (Q25.24).
    pub n_c: Signal<Out, Bits<49>>,
    /// One cycle per result.
    pub valid: Signal<Out, Bit>,
    rom_a: SineRom<A, 24>,
    rom_b: SineRom<A, 24>,
    arith: EccArith,
    busy: DFF<Bit>,
    dm: DFF<Bits<24>>,
    e: DFF<Bits<16>>,
    nc_reg: DFF<Bits<49>>,
    valid_reg: DFF<Bit>,
    zero24: Constant<Bits<24>>,
    zero16: Constant<Bits<16>>,
    zero49: Constant<Bits<49>>,
}

impl<const A: usize> EccCorrector<A> {
    /// A corrector for K = `lines` (2 ≤ K ≤ 2^A).
    pub fn new(lines: u32) -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            delta_m: Default::default(),
            m_a: Default::default(),
            m_b: Default::default(),
            m0: Default::default(),
            e_coef: Default::default(),
            n_c: Default::default(),
            valid: Default::default(),
            rom_a: SineRom::new(lines),
            rom_b: SineRom::new(lines),
            arith: Default::default(),
            busy: Default::default(),
            dm: Default::default(),
            e: Default::default(),
            nc_reg: Default::default(),
            valid_reg: Default::default(),
            zero24: Constant::new(0u64.into()),
            zero16: Constant::new(0u64.into()),
            zero49: Constant::new(0u64.into()),
        }
    }
}

impl<const A: usize> Logic for EccCorrector<A> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, busy, dm, e, nc_reg, valid_reg);
        self.rom_a.clock.next = self.clock.val();
        self.rom_b.clock.next = self.clock.val();
        self.rom_a.m.next = self.m_a.val();
        self.rom_a.m0.next = self.m0.val();
        self.rom_b.m.next = self.m_b.val();
        self.rom_b.m0.next = self.m0.val();
        self.busy.d.next = self.start.val();
        self.dm.d.next = self.delta_m.val();
        self.e.d.next = self.e_coef.val();
        self.arith.delta_m.next = self.dm.q.val();
        self.arith.e_coef.next = self.e.q.val();
        self.arith.s_a.next = self.rom_a.data.val();
        self.arith.s_b.next = self.rom_b.data.val();
        self.valid_reg.d.next = self.busy.q.val();
        if self.busy.q.val() {
            self.nc_reg.d.next = self.arith.n_c.val();
        }
        if self.reset.val() {
            self.busy.d.next = false;
            self.dm.d.next = self.zero24.val();
            self.e.d.next = self.zero16.val();
            self.nc_reg.d.next = self.zero49.val();
            self.valid_reg.d.next = false;
        }
        self.n_c.next = self.nc_reg.q.val();
        self.valid.next = self.valid_reg.q.val();
    }
}

/// The Verilog of an [`EccCorrector`] for K = `lines`, top module named `module_name`.
pub fn ecc_corrector_verilog<const A: usize>(lines: u32, module_name: &str) -> String {
    let mut uut = EccCorrector::<A>::new(lines);
    uut.connect_all();
    crate::emit::named_verilog(&uut, module_name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::verilator_lint;

    #[test]
    fn synthesises() {
        let mut uut = EccCorrector::<10>::new(1024);
        uut.connect_all();
        yosys_validate("encspeed_ecc_corrector", &generate_verilog(&uut)).unwrap();
    }

    #[test]
    fn verilator_lint_is_clean() {
        verilator_lint(
            "ecc_corrector",
            &ecc_corrector_verilog::<10>(1024, "ecc_corrector"),
        );
        verilator_lint(
            "ecc_corrector",
            &ecc_corrector_verilog::<10>(1000, "ecc_corrector"),
        );
    }
}
