// SPDX-License-Identifier: MIT OR Apache-2.0
//! The eccentricity correction δ of a span, in decoder steps, at fractional positions and
//! with the exact phase θ0 (it supersedes the first corrector, which rounded θ0 to a line
//! and knew only line positions):
//!
//! ```text
//! δ = 2^s · [ c·(S(x_b) − S(x_a)) + d·(C(x_b) − C(x_a)) ],  S = sin(2πx/K), C = cos(2πx/K)
//! ```
//!
//! with c = E·cos θ0, d = E·sin θ0, E = K·e/(2π) lines; the corrected count of a span of ΔM
//! steps is N_c = ΔM − δ. Bit-true model: [`golden::ecc::ecc_delta`], whose module docs are the
//! specification (exact arithmetic, width proofs, timing, error budget); this block
//! implements it cycle for cycle. Documentation page: docs/eccentricity-hardware.md.
//!
//! # Generation parameters
//! | parameter | meaning | range |
//! |---|---|---|
//! | `lines` (constructor) | K, lines per revolution | multiple of 4, 4 ≤ K ≤ 2^A |
//! | `A` | table address bits | 2..=16 |
//! | `D` | table width (the integration uses 24) | 8..=24 |
//!
//! # Ports
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | everything happens at its rising edge |
//! | `reset` | in | 1 | synchronous, active high; wins over `start` |
//! | `start` | in | 1 | request: latches the five inputs below |
//! | `p_a`, `p_b` | in | 33 | span ends in half-steps (position·2 + half), < K·2^(s+1) |
//! | `shift` | in | 2 | s: x1 0, x2 1, x4 2 (3 is taken as 2) |
//! | `coef_c`, `coef_d` | in | 32 | c, d: signed Q15.16 lines |
//! | `delta` | out | 40 | δ·2^16, signed (16 fractional bits, steps), rounded to nearest, ties up; never wraps |
//! | `valid` | out | 1 | one cycle: `delta` was just written |
//! | `busy` | out | 1 | a computation runs or a request is pending |
//!
//! # Timing
//! A `start` sampled at edge k while idle gives `valid` after edge k + 68
//! ([`golden::ecc::ecc_delta::latency_cycles`]) for every K, A, D and operand. A start while busy
//! latches into the one-deep request register (replacing a request that has not begun) and
//! is served at the edge after the current `valid`: the last start is always computed.
//! Starts ≥ 68 cycles apart each get their result.
//!
//! # Datapath (one addition per clock)
//! * Request: `p_a`, `p_b`, `shift` are decoded at `start` into line (A bits) and eighths
//!   (3 bits) per end, latched with the coefficients (2A + 72 flip-flops); the job copies
//!   them when it begins.
//! * Steps 0–8: one [`SineRom`] (one read per cycle, registered) reads, per end, sin at l and
//!   l + 1 (m0 = 0, 1), cos at l and l + 1 (m0 = K/4, K/4 + 1); each pair is interpolated
//!   exactly, 8·T\[l\] + t·(T\[l+1\] − T\[l\]), and subtracted (end a) or added (end b) into
//!   ΔS8 or ΔC8 (28 bits).
//! * Steps 9–64: shift-add multiplier over the 28 bits of ΔS8 (multiplicand c·2^s) then of
//!   ΔC8 (d·2^s), LSB first, the sign bit subtracted, into a 63-bit accumulator.
//! * Step 65: acc += acc >>> (D − 1) (the table's scale 1/Q = 2^−(D−1)/(1 − 2^−(D−1))).
//! * Step 66: acc += 2^(D+1) and `delta` = acc >>> (D + 2), `valid`.
//!
//! The arithmetic is the combinational [`EccDeltaArith`] (`Verilog::Custom`); the sequencer
//! and registers are `#[hdl_gen]`.
//!
//! # Resources (yosys 0.23 `synth_ice40`, `EccDelta<10, 24>`, K = 1024)
//! 1 161 SB_LUT4, 437 flip-flops, 189 SB_CARRY, and 6 SB_RAM40_4K for the 1024 × 24 table
//! (mapped to block RAM).
//!
//! # Error budget
//! [`golden::ecc::ecc_delta::error_budget`]: table ½ LSB per entry, linear interpolation
//! (t(1 − t)/2·|E|·(2π/K)² per end, 0 at whole lines), output rounding ½ LSB = 2^−17 step.
//! At K = 1024, D = 24, e = 0.35/30, the measured maximum over random spans is 2.55e-5 steps
//! in x1 (budget 2.59e-5), 7.7e-5 in x4 (8.05e-5).

use crate::ecc::ecc_delta_arith::EccDeltaArith;
use crate::ecc::sine_rom::SineRom;
use rust_hdl::prelude::*;

/// The correction of a span, A-bit table address, D-bit table entries (module docs).
#[derive(LogicBlock)]
pub struct EccDelta<const A: usize, const D: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset (wins over `start`).
    pub reset: Signal<In, Bit>,
    /// Request: latches `p_a`, `p_b`, `shift`, `coef_c`, `coef_d`.
    pub start: Signal<In, Bit>,
    /// First span end, half-steps, unsigned.
    pub p_a: Signal<In, Bits<33>>,
    /// Second span end, half-steps, unsigned.
    pub p_b: Signal<In, Bits<33>>,
    /// Decoder shift s (x1 0, x2 1, x4 2; 3 = 2).
    pub shift: Signal<In, Bits<2>>,
    /// c = E·cos θ0, signed Q15.16 lines.
    pub coef_c: Signal<In, Bits<32>>,
    /// d = E·sin θ0, signed Q15.16 lines.
    pub coef_d: Signal<In, Bits<32>>,
    /// δ·2^16 (steps), signed.
    pub delta: Signal<Out, Bits<40>>,
    /// One cycle: `delta` was just written.
    pub valid: Signal<Out, Bit>,
    /// A computation runs or a request is pending.
    pub busy: Signal<Out, Bit>,
    rom: SineRom<A, D>,
    arith: EccDeltaArith<A, D>,
    // Request register.
    pend: DFF<Bit>,
    r_la: DFF<Bits<A>>,
    r_ta: DFF<Bits<3>>,
    r_lb: DFF<Bits<A>>,
    r_tb: DFF<Bits<3>>,
    r_s: DFF<Bits<2>>,
    r_c: DFF<Bits<32>>,
    r_d: DFF<Bits<32>>,
    // Job.
    run: DFF<Bit>,
    k: DFF<Bits<7>>,
    j_la: DFF<Bits<A>>,
    j_ta: DFF<Bits<3>>,
    j_lb: DFF<Bits<A>>,
    j_tb: DFF<Bits<3>>,
    j_s: DFF<Bits<2>>,
    j_c: DFF<Bits<32>>,
    j_d: DFF<Bits<32>>,
    // Datapath.
    v0: DFF<Bits<D>>,
    acc_s: DFF<Bits<28>>,
    acc_c: DFF<Bits<28>>,
    acc: DFF<Bits<63>>,
    mcand: DFF<Bits<63>>,
    out: DFF<Bits<40>>,
    valid_reg: DFF<Bit>,
    take: Signal<Local, Bit>,
    // Step numbers, 7 bits.
    k_0: Constant<Bits<7>>,
    k_1: Constant<Bits<7>>,
    k_5: Constant<Bits<7>>,
    k_8: Constant<Bits<7>>,
    k_9: Constant<Bits<7>>,
    k_36: Constant<Bits<7>>,
    k_64: Constant<Bits<7>>,
    k_65: Constant<Bits<7>>,
    k_66: Constant<Bits<7>>,
    // Table offsets m0, A bits.
    m0_zero: Constant<Bits<A>>,
    m0_one: Constant<Bits<A>>,
    m0_quarter: Constant<Bits<A>>,
    m0_quarter1: Constant<Bits<A>>,
    op_add: Constant<Bits<2>>,
    op_sub: Constant<Bits<2>>,
    op_scale: Constant<Bits<2>>,
    op_round: Constant<Bits<2>>,
    zero28: Constant<Bits<28>>,
    zero40: Constant<Bits<40>>,
    zero63: Constant<Bits<63>>,
    /// 2^(D+1): the rounding half.
    half: Constant<Bits<63>>,
}

impl<const A: usize, const D: usize> EccDelta<A, D> {
    /// A block for K = `lines`.
    ///
    /// # Panics
    /// If K, A or D break [`golden::ecc::ecc_delta::check_params`] (K a multiple of 4,
    /// 4 ≤ K ≤ 2^A, 2 ≤ A ≤ 16, 8 ≤ D ≤ 24).
    pub fn new(lines: u32) -> Self {
        golden::ecc::ecc_delta::check_params(lines, A as u32, D as u32)
            .unwrap_or_else(|e| panic!("{e}"));
        let k7 = |v: u64| Constant::new(v.into());
        let ma = |v: u32| Constant::new(u64::from(v).into());
        let op = |v: u64| Constant::new(v.into());
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            p_a: Default::default(),
            p_b: Default::default(),
            shift: Default::default(),
            coef_c: Default::default(),
            coef_d: Default::default(),
            delta: Default::default(),
            valid: Default::default(),
            busy: Default::default(),
            rom: SineRom::new(lines),
            arith: Default::default(),
            pend: Default::default(),
            r_la: Default::default(),
            r_ta: Default::default(),
            r_lb: Default::default(),
            r_tb: Default::default(),
            r_s: Default::default(),
            r_c: Default::default(),
            r_d: Default::default(),
            run: Default::default(),
            k: Default::default(),
            j_la: Default::default(),
            j_ta: Default::default(),
            j_lb: Default::default(),
            j_tb: Default::default(),
            j_s: Default::default(),
            j_c: Default::default(),
            j_d: Default::default(),
            v0: Default::default(),
            acc_s: Default::default(),
            acc_c: Default::default(),
            acc: Default::default(),
            mcand: Default::default(),
            out: Default::default(),
            valid_reg: Default::default(),
            take: Default::default(),
            k_0: k7(0),
            k_1: k7(1),
            k_5: k7(5),
            k_8: k7(8),
            k_9: k7(9),
            k_36: k7(36),
            k_64: k7(64),
            k_65: k7(65),
            k_66: k7(66),
            m0_zero: ma(0),
            m0_one: ma(1),
            m0_quarter: ma(lines / 4),
            m0_quarter1: ma(lines / 4 + 1),
            op_add: op(0),
            op_sub: op(1),
            op_scale: op(2),
            op_round: op(3),
            zero28: Constant::new(0u64.into()),
            zero40: Constant::new(0u64.into()),
            zero63: Constant::new(0u64.into()),
            half: Constant::new((1u64 << (D + 1)).into()),
        }
    }
}

impl<const A: usize, const D: usize> Logic for EccDelta<A, D> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, pend, r_la, r_ta, r_lb, r_tb, r_s, r_c, r_d, run, k, j_la, j_ta, j_lb,
            j_tb, j_s, j_c, j_d, v0, acc_s, acc_c, acc, mcand, out, valid_reg
        );
        self.rom.clock.next = self.clock.val();
        // Decoding of the request inputs.
        self.arith.h_a.next = self.p_a.val();
        self.arith.h_b.next = self.p_b.val();
        self.arith.shift.next = self.shift.val();
        // Request register.
        self.take.next = (!self.run.q.val()) & self.pend.q.val();
        if self.start.val() {
            self.r_la.d.next = self.arith.l_a.val();
            self.r_ta.d.next = self.arith.t_a.val();
            self.r_lb.d.next = self.arith.l_b.val();
            self.r_tb.d.next = self.arith.t_b.val();
            self.r_s.d.next = self.arith.s_eff.val();
            self.r_c.d.next = self.coef_c.val();
            self.r_d.d.next = self.coef_d.val();
            self.pend.d.next = true;
        } else if self.take.val() {
            self.pend.d.next = false;
        }
        if self.take.val() {
            self.j_la.d.next = self.r_la.q.val();
            self.j_ta.d.next = self.r_ta.q.val();
            self.j_lb.d.next = self.r_lb.q.val();
            self.j_tb.d.next = self.r_tb.q.val();
            self.j_s.d.next = self.r_s.q.val();
            self.j_c.d.next = self.r_c.q.val();
            self.j_d.d.next = self.r_d.q.val();
            self.run.d.next = true;
            self.k.d.next = self.k_0.val();
        }
        // Table reads (steps 0..=7): end a in 0..=3, end b in 4..=7; bit 1 = cosine,
        // bit 0 = the next line.
        self.rom.m.next = self.j_la.q.val();
        if self.k.q.val().get_bit(2) {
            self.rom.m.next = self.j_lb.q.val();
        }
        self.rom.m0.next = self.m0_zero.val();
        if self.k.q.val().get_bit(1) {
            if self.k.q.val().get_bit(0) {
                self.rom.m0.next = self.m0_quarter1.val();
            } else {
                self.rom.m0.next = self.m0_quarter.val();
            }
        } else if self.k.q.val().get_bit(0) {
            self.rom.m0.next = self.m0_one.val();
        }
        // Datapath operands.
        self.arith.coef.next = self.j_c.q.val();
        if self.k.q.val() == self.k_36.val() {
            self.arith.coef.next = self.j_d.q.val();
        }
        self.arith.coef_shift.next = self.j_s.q.val();
        self.arith.v0.next = self.v0.q.val();
        self.arith.v1.next = self.rom.data.val();
        self.arith.t.next = self.j_tb.q.val();
        self.arith.sub_t.next = false;
        if self.k.q.val() < self.k_5.val() {
            self.arith.t.next = self.j_ta.q.val();
            self.arith.sub_t.next = true;
        }
        self.arith.acc_t.next = self.acc_c.q.val();
        if self.k.q.val().get_bit(1) {
            self.arith.acc_t.next = self.acc_s.q.val();
        }
        self.arith.acc.next = self.acc.q.val();
        self.arith.mcand.next = self.mcand.q.val();
        self.arith.sx.next = self.acc_s.q.val();
        self.arith.cx.next = self.acc_c.q.val();
        self.arith.mul_bit.next = self.acc_c.q.val().get_bit(0);
        if self.k.q.val() <= self.k_36.val() {
            self.arith.mul_bit.next = self.acc_s.q.val().get_bit(0);
        }
        self.arith.op.next = self.op_add.val();
        if self.k.q.val() == self.k_36.val() {
            self.arith.op.next = self.op_sub.val();
        }
        if self.k.q.val() == self.k_64.val() {
            self.arith.op.next = self.op_sub.val();
        }
        if self.k.q.val() == self.k_65.val() {
            self.arith.op.next = self.op_scale.val();
        }
        if self.k.q.val() == self.k_66.val() {
            self.arith.op.next = self.op_round.val();
        }
        // Steps.
        self.valid_reg.d.next = false;
        if self.run.q.val() {
            self.k.d.next = self.k.q.val() + self.k_1.val();
            if self.k.q.val() == self.k_0.val() {
                self.acc.d.next = self.zero63.val();
                self.acc_s.d.next = self.zero28.val();
                self.acc_c.d.next = self.zero28.val();
                self.mcand.d.next = self.arith.mcand_load.val();
            }
            if (self.k.q.val() >= self.k_1.val()) && (self.k.q.val() <= self.k_8.val()) {
                if self.k.q.val().get_bit(0) {
                    self.v0.d.next = self.rom.data.val();
                } else if self.k.q.val().get_bit(1) {
                    self.acc_s.d.next = self.arith.acc_t_next.val();
                } else {
                    self.acc_c.d.next = self.arith.acc_t_next.val();
                }
            }
            if (self.k.q.val() >= self.k_9.val()) && (self.k.q.val() <= self.k_64.val()) {
                self.acc.d.next = self.arith.acc_next.val();
                self.mcand.d.next = self.arith.mcand_shl.val();
                if self.k.q.val() <= self.k_36.val() {
                    self.acc_s.d.next = self.arith.sx_shr.val();
                } else {
                    self.acc_c.d.next = self.arith.cx_shr.val();
                }
                if self.k.q.val() == self.k_36.val() {
                    self.mcand.d.next = self.arith.mcand_load.val();
                }
                if self.k.q.val() == self.k_64.val() {
                    self.mcand.d.next = self.half.val();
                }
            }
            if self.k.q.val() == self.k_65.val() {
                self.acc.d.next = self.arith.acc_next.val();
            }
            if self.k.q.val() == self.k_66.val() {
                self.acc.d.next = self.arith.acc_next.val();
                self.out.d.next = self.arith.delta_next.val();
                self.valid_reg.d.next = true;
                self.run.d.next = false;
            }
        }
        if self.reset.val() {
            self.pend.d.next = false;
            self.run.d.next = false;
            self.k.d.next = self.k_0.val();
            self.out.d.next = self.zero40.val();
            self.valid_reg.d.next = false;
        }
        self.delta.next = self.out.q.val();
        self.valid.next = self.valid_reg.q.val();
        self.busy.next = self.run.q.val() | self.pend.q.val();
    }
}

/// The Verilog of an [`EccDelta`] for K = `lines`, top module named `module_name`.
pub fn ecc_delta_verilog<const A: usize, const D: usize>(lines: u32, module_name: &str) -> String {
    let mut uut = EccDelta::<A, D>::new(lines);
    uut.connect_all();
    crate::verilog::named_verilog(&uut, module_name)
}
