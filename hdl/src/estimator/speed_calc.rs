// SPDX-License-Identifier: MIT OR Apache-2.0
//! Speed calculator: Rairán's n1, n2 and n3 from the registers Nep1 and Ndt1, as signed
//! fixed-point speeds, by a sequential divider and a sequential shift-add multiplier.
//! `encspeed_core` starts one at each Table 1 update, and its output registers are the
//! core's speed outputs; its bit-true model is [`golden::estimator::speed_calc::SpeedCalcModel`], whose module docs
//! state the values, the rounding rule and the timing this block implements.
//!
//! # Generation parameters
//!
//! | parameter | meaning | range |
//! |---|---|---|
//! | `N` | counter width: `nep`, `ndt` (as `counter_bits` of the core) | 8..=32 |
//! | `F` | fractional bits of the speeds (`speed_frac_bits`) | 0..=24 |
//! | `P` | must be 2·N + 1: products, denominator, partial remainder | derived |
//! | `S` | must be N + F + 1: width of each speed output | derived |
//!
//! rust-hdl widths are const generics and stable Rust cannot compute `2 * N + 1` from a
//! generic `N`, so the derived widths are parameters too, checked at compile time. Name the
//! type with [`speed_calc_type!`](crate::speed_calc_type): `speed_calc_type!(24, 16)` is
//! `SpeedCalc<24, 16, 49, 41>`.
//!
//! # Ports
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | clock; everything happens at its rising edge |
//! | `reset` | in | 1 | synchronous, active high; wins over `start` |
//! | `start` | in | 1 | request a computation (the core's `update`); latches the four inputs below |
//! | `nep` | in | N | Nep1 (pulses), unsigned |
//! | `ndt` | in | N | Ndt1 (dt intervals), unsigned |
//! | `negative` | in | 1 | direction: 1 = reverse, the speeds come out negative |
//! | `mode_shift` | in | 2 | log2 of the decoder steps per line (0 = x1, 1 = x2, 2 = x4; 3 acts as 2), latched with `start` |
//! | `position` | in | 32 | carried with the request (the core's span end), latched with `start` |
//! | `speed_n1` | out | N+F+1 | n1 = Nep/Ndt, eq. (5) |
//! | `speed_n2` | out | N+F+1 | n2, eq. (6) |
//! | `speed_n3` | out | N+F+1 | n3, eq. (11): the estimate to use |
//! | `speed_position` | out | 32 | `position` of the request the speeds were computed from |
//! | `speed_nep` | out | N | `nep` of that request |
//! | `speed_ndt` | out | N | `ndt` of that request |
//! | `valid` | out | 1 | one cycle: the three speeds and the tag were just written (together) |
//! | `have_speeds` | out | 1 | a result has been published since reset |
//! | `busy` | out | 1 | a computation runs or a request is pending |
//!
//! Speeds are two's complement, Q(N).F in units of ω_lim (lines per dt): the value is
//! `raw · 2^−F`. Each is the exact value in steps per dt rounded to nearest (ties away from
//! zero) in magnitude, error ≤ 2^−(F+1) ω_lim
//! ([`golden::estimator::speed_calc::speed_lsb_error`]), then divided by 2^`mode_shift` and
//! rounded again the same way ([`golden::estimator::speed_calc::mode_scale`]), then negated
//! if `negative`. Nep = 0 gives 0; Ndt = 0 (never produced by the core) gives
//! ±(2^(N+F) − 1) >> s, rounded, for Nep ≥ 1.
//!
//! # Timing
//!
//! A `start` sampled at edge k while idle gives `valid` after edge k + L, with
//! L = 6·(N + F + 1) + 10 ([`golden::estimator::speed_calc::latency_cycles`]; 256 for N = 24, F = 16),
//! whatever the operands. `busy` is high after edges k … k + L − 1. A `start` while busy
//! latches its inputs into the one-deep request register (replacing a request that has not
//! begun) and is served at the edge after the current `valid`, so the values of the last
//! start are always computed. With the core's update pattern no update is lost when
//! dt ≥ 2·L − 1 cycles ([`golden::estimator::speed_calc::min_lossless_dt`]).
//!
//! # Datapath
//!
//! Schedule after a request is taken (edge k + 1): a set-up and S = N + F + 1 divider
//! steps for each of n1, n2 and n3, then the publication. The state register walks
//! IDLE → SETUP → STEP ×S → SETUP → … → FINISH → IDLE, and every state but IDLE and FINISH
//! lasts two cycles (`second`): each wide addition is a [`TwoCycleAdder`](crate::TwoCycleAdder),
//! whose low half is registered in the first cycle and whose high half and carry out are
//! ready in the second, so no path crosses more than about half a carry chain. FINISH lasts
//! three (`publish` marks the third): the rounding adder's sum stands from the second on and
//! the outputs are written at the third's edge, one edge later than the sum allows, because
//! these registers are the core's speed outputs: the core used to copy them into a second
//! rank of registers one edge later (`SpeedHold`), and the request's tag travelled in a
//! second request machine beside this one (`SpeedTag`); the request's position now rides in
//! the request and working registers with Nep1 and Ndt1, so both blocks are gone
//! (L = 1 + 3·(2 + 2S) + 3). The operands of each addition are registers that change only
//! at the second cycle's edge.
//!
//! * **Divider** (non-restoring, radix 2, shared by the three divisions). For num/den with
//!   num < den·2^N, the partial remainder R is preloaded with num >> N (< den), the low N
//!   bits of num wait at the top of a shift register, and each step brings down one bit
//!   (zeros once the N bits are used), so S steps give ⌊num·2^(F+1)/den⌋ without forming
//!   num·2^(F+1). Then the magnitude (q + 1) >> 1 is the value rounded to nearest, ties up.
//!   The quotient is that of the restoring algorithm,
//!   [`golden::estimator::speed_calc::long_division`]; only the remainder is kept
//!   differently. A step from R ≥ 0 gives 2R + b − den, a step from R < 0 gives
//!   2R + b + den, and the quotient bit is 1 when the new R is ≥ 0. Where restoring division
//!   holds a remainder R_r, this one holds R_r or R_r − den, and 2(R_r − den) + b + den =
//!   2R_r + b − den: the same next remainder and the same bit. Every denominator is below
//!   2^(P−1) (n1, n2 and the low-speed n3: at most 2^(N+1) − 1; the high-speed n3:
//!   Ndt·(2·Nep − 1) with Ndt ≤ ⌊Nep/2⌋ < 2^(N−1)), so R ∈ [−den, den) is a P-bit two's
//!   complement value and the sum taken mod 2^P is exact even when 2R + b is not. The new
//!   remainder is the adder's sum as it is and the quotient bit its top bit inverted: no
//!   comparator and no multiplexer behind the carry chain (the restoring form's "fits"
//!   selected all P remainder bits at the end of the chain, a critical path on the HX8K).
//!   The quotient register does not take that bit from the chain either: each step shifts
//!   in the bit of the step before, read from the sign of `part_rem` (a register), so the
//!   high half's chain ends at `part_rem` alone (its top bit into the quotient register
//!   through a LUT was the worst path of the HX8K on three seeds out of four). After the S
//!   steps the register holds a spurious 1 (the sign of the non-negative preload) above
//!   q >> 1, and the last bit r is the sign of the last remainder: h is the register with
//!   its top bit cleared, r the inverted top bit of `part_rem`, both registers as before.
//! * **Multiplier** (shift-add, MSB first, during the first N + 1 steps of the n1 division).
//!   With X = 2·Nep − 1 (odd, N + 1 bits): Ndt·(2·Nep − 1) = Ndt·X and
//!   2·Nep·(Nep − 1) = Nep·(X − 1), where X − 1 is X with bit 0 cleared: both accumulate
//!   over the bits of the same X, the first skipping bit 0. Both products fit P bits.
//! * **Selection**: n2 and n3 use the high-speed forms when Nep ≥ 2·Ndt (compared as
//!   Ndt ≤ ⌊Nep/2⌋ at N bits and registered when the request is taken, so that the set-up's
//!   operand (Nep − 1 or Ndt + 1) is the only carry chain before the divider's registers),
//!   else (Nep, Ndt + 1) and (2·Nep, 2·Ndt + 1).
//!
//! Widths never change inside an expression (rust-hdl emits literals 32 bits wide and
//! casts as masks that Verilator flags), so the N-bit request is widened to P bits by a
//! shift-in loop (wires after synthesis) and every constant is a `Constant` of its
//! operand's width. The divider's subtraction is 2R + b + ~den + 1 on the two-cycle adder,
//! its addition 2R + b + den + 0: the sign register picks den or ~den and the carry in.
//!
//! # Rounding, mode scaling and sign in one adder
//!
//! With q the last quotient, h = q >> 1 and r = q & 1, the magnitude in steps per dt is
//! m = h + r. Scaled by 2^s with the second rounding it is (m + ⌊2^(s−1)⌋) >> s
//! = (h + e) >> s with e = r, 1 + r, 2 + r for s = 0, 1, 2 (adding the even 2^s to the odd
//! numerator before the first halving commutes with it). Its negation uses
//! −⌊y/2^s⌋ = ⌊(−y + 2^s − 1)/2^s⌋ and −y = ~h + 1 − e: the result is
//! (~h + f) >>> s with f = 1 − r, 1 − r, 2 − r (arithmetic shift). So one adder
//! (h or ~h) + (e or f) and a shift by 0, 1 or 2 give the signed, scaled speed: the scaling
//! costs no carry chain of its own (before, the core had three S-bit scalers, each a
//! negate, a rounding add and a negate, on its critical path). The positive sum stays
//! below 2^S (m ≤ 2^(N+F) − 1, e ≤ 3), so its shift fills zeros; a negative request fills
//! ones when the sum's top bit is set (a sum of 0 or 1 is a speed that rounds to 0).
//! e and f for r = 0 and for r = 1 depend only on the request (its mode shift, sign and
//! special cases), so both are registered when the request is taken and r alone picks
//! one: the rounding adder is one logic level behind the quotient register (three before,
//! on a near-critical path of `encspeed_wb` on the iCE40).
//!
//! # Resources
//!
//! Registers: the request (2N + 4, and the carried position, 32), its working copy
//! (2N + 6, and 32), Nep − 1 and Ndt + 1 (2P, of which yosys keeps about 2N + 2: the high
//! bits of Ndt + 1 are constant), the divider (3P + S), the multiplier (3P), staging and
//! outputs (5S), the published tag (32 + 2N), a 6-bit step counter, 12 control bits, the
//! rounding increment for r = 0 and 1 (2 × 2 bits), and in the four two-cycle adders the
//! low sums and the high operands (about 2P each for the divider and the multiplier, 2S
//! for the rounding), and the multiplier's two registered operands (2N: their high bits
//! are constant 0). The tag registers only load (flip-flops with an enable, no LUT). For
//! N = 24, F = 16, yosys 0.23 `synth_ice40` maps the block (as it sits in the generated
//! `encspeed_core`) to 1 072 flip-flops, 874 LUT4 and 278 carry cells (1 026, 921 and 278
//! before the quotient bit came from `part_rem`'s sign and the multiplier's operands were
//! registered; 880, 919 and 278
//! before it carried the tag and became the core's output registers; the core's
//! `SpeedTag`, a second request machine of 250 flip-flops, and `SpeedHold`, a second rank
//! of 123 output flip-flops, went with it; 826, 914 and 282 with the restoring divider
//! and n2's operands formed at the set-up; 608, 867 and 278 with one-cycle 49- and 41-bit
//! additions). The split took the block off the critical path of `encspeed_wb` on the
//! iCE40 HX8K: before, the divider's 49-bit trial subtraction was 10.5 ns of an 18 ns path
//! (docs/design-decisions.md, "Timing closure on the iCE40").

use golden::params::POSITION_BITS;
use rust_hdl::prelude::*;

/// Width of the carried position (the core's `position`).
const C: usize = POSITION_BITS as usize;
/// Width of the step counter: it holds S − 1 ≤ 56.
const COUNT_BITS: usize = 6;
/// Width of the state and phase registers.
const STATE_BITS: usize = 2;
/// Width of the shift-amount constants (every shift is by less than 2^8).
const SHIFT_BITS: usize = 8;

/// The `SpeedCalc` type for counter width `$n` and `$f` fractional bits (literals or
/// constants), with the derived widths filled in: `speed_calc_type!(24, 16)` is
/// `SpeedCalc<24, 16, 49, 41>`.
#[macro_export]
macro_rules! speed_calc_type {
    ($n:expr, $f:expr) => {
        $crate::estimator::speed_calc::SpeedCalc<{ $n }, { $f }, { 2 * $n + 1 }, { $n + $f + 1 }>
    };
}

/// Speed calculator: n1, n2, n3 of Rairán's estimator as signed Q(N).F fixed point.
#[derive(LogicBlock)]
pub struct SpeedCalc<const N: usize, const F: usize, const P: usize, const S: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset (wins over `start`).
    pub reset: Signal<In, Bit>,
    /// Request a computation; latches `nep`, `ndt`, `negative`.
    pub start: Signal<In, Bit>,
    /// Nep1 (pulses).
    pub nep: Signal<In, Bits<N>>,
    /// Ndt1 (dt intervals).
    pub ndt: Signal<In, Bits<N>>,
    /// Direction: 1 = reverse (negative speeds).
    pub negative: Signal<In, Bit>,
    /// log2 of the decoder steps per line: 0 = x1, 1 = x2, 2 = x4 (3 acts as 2).
    pub mode_shift: Signal<In, Bits<2>>,
    /// Carried with the request and published with its speeds (the core's span end).
    pub position: Signal<In, Bits<C>>,
    /// n1 = Nep/Ndt, Q(N).F two's complement, units of ω_lim.
    pub speed_n1: Signal<Out, Bits<S>>,
    /// n2, eq. (6), Q(N).F two's complement, units of ω_lim.
    pub speed_n2: Signal<Out, Bits<S>>,
    /// n3, eq. (11), Q(N).F two's complement, units of ω_lim.
    pub speed_n3: Signal<Out, Bits<S>>,
    /// `position` of the request the speeds were computed from.
    pub speed_position: Signal<Out, Bits<C>>,
    /// `nep` of the request the speeds were computed from.
    pub speed_nep: Signal<Out, Bits<N>>,
    /// `ndt` of the request the speeds were computed from.
    pub speed_ndt: Signal<Out, Bits<N>>,
    /// One-cycle strobe: the three speeds and the tag were just written.
    pub valid: Signal<Out, Bit>,
    /// A result has been published since reset.
    pub have_speeds: Signal<Out, Bit>,
    /// A computation runs or a request is pending.
    pub busy: Signal<Out, Bit>,
    // Request register.
    req_position: DFF<Bits<C>>,
    req_nep: DFF<Bits<N>>,
    req_ndt: DFF<Bits<N>>,
    req_neg: DFF<Bit>,
    req_shift: DFF<Bits<2>>,
    pending: DFF<Bit>,
    // Working copy of the request.
    w_position: DFF<Bits<C>>,
    w_nep: DFF<Bits<N>>,
    w_ndt: DFF<Bits<N>>,
    /// Nep ≥ 2·Ndt (n1 ≥ 2): the high-speed forms of n2 and n3.
    w_high: DFF<Bit>,
    w_neg: DFF<Bit>,
    w_shift: DFF<Bits<2>>,
    /// Nep = 0: all speeds 0.
    w_nep_zero: DFF<Bit>,
    /// Ndt = 0: all speeds saturate (unless Nep = 0).
    w_ndt_zero: DFF<Bit>,
    // Sequencer.
    state: DFF<Bits<STATE_BITS>>,
    phase: DFF<Bits<STATE_BITS>>,
    count: DFF<Bits<COUNT_BITS>>,
    /// The second cycle of a state: every state lasts two cycles, the first lets the
    /// adders' registered low halves take their operands.
    second: DFF<Bit>,
    /// The third cycle of FINISH: the outputs are written at its edge.
    publish: DFF<Bit>,
    /// The multiplier steps (the first N + 1 steps of the n1 division).
    mul_on: DFF<Bit>,
    /// `count` = F, the last multiplier step (set with `count`, from its set-up on): a
    /// register, so that no decode of `count` is in front of the multiplier's adders.
    mul_last: DFF<Bit>,
    // Divider.
    part_rem: DFF<Bits<P>>,
    num_shift: DFF<Bits<P>>,
    den: DFF<Bits<P>>,
    /// The quotient bits of the steps before the last, one step late (module docs:
    /// Datapath): after the S steps, bit S − 1 is a spurious 1 and bits S − 2..0 are
    /// q >> 1.
    quo: DFF<Bits<S>>,
    // Multiplier.
    mul_x: DFF<Bits<P>>,
    acc_num: DFF<Bits<P>>,
    acc_den: DFF<Bits<P>>,
    /// The accumulations' second operands for the step that runs, registered when the
    /// step before it ends (or at the set-up): Ndt, and Nep (0 at the last step, X − 1),
    /// if the step's bit of X is 1, else 0. Decoding the bit and the last step in front of
    /// the adders put two logic levels before their carry chains (the worst path of
    /// `encspeed_core` on one HX8K seed).
    op_num: DFF<Bits<P>>,
    op_den: DFF<Bits<P>>,
    // Results.
    stage_n1: DFF<Bits<S>>,
    stage_n2: DFF<Bits<S>>,
    out_n1: DFF<Bits<S>>,
    out_n2: DFF<Bits<S>>,
    out_n3: DFF<Bits<S>>,
    out_position: DFF<Bits<C>>,
    out_nep: DFF<Bits<N>>,
    out_ndt: DFF<Bits<N>>,
    valid_reg: DFF<Bit>,
    have_reg: DFF<Bit>,
    // Combinational.
    /// The working Nep and Ndt widened to P bits.
    nep_wide: Signal<Local, Bits<P>>,
    ndt_wide: Signal<Local, Bits<P>>,
    /// Nep − 1 and Ndt + 1 at P bits, registered at every edge from the working copy
    /// (steady from the request's take to the second set-up, which reads them): the
    /// operands of n2 come out of a multiplexer, with no carry chain in front of the
    /// divider's registers. (One register chosen by the high-speed test would save about
    /// N + 1 flip-flops but cost a P-bit multiplexer: about 50 LUT4 more.)
    nep_less_one: DFF<Bits<P>>,
    ndt_plus_one: DFF<Bits<P>>,
    num_sel: Signal<Local, Bits<P>>,
    den_sel: Signal<Local, Bits<P>>,
    /// The divider's trial subtraction 2R + b − den (as 2R + b + ~den + 1), over two cycles.
    div_sub: crate::arith::two_cycle_adder::TwoCycleAdder<P>,
    /// 2R + b: the partial remainder shifted, with the numerator bit brought down.
    shifted: Signal<Local, Bits<P>>,
    /// R < 0 (R's top bit, a register): this step adds den instead of subtracting it.
    rem_negative: Signal<Local, Bit>,
    /// X = 2·Nep − 1, loaded into `mul_x` at the first set-up.
    x_first: Signal<Local, Bits<P>>,
    /// The next step's bit of X (bit N of `x_first` at the set-up, bit N − 1 of `mul_x`
    /// at a step) and whether the next step is the last multiplier step.
    x_next: Signal<Local, Bit>,
    mul_last_next: Signal<Local, Bit>,
    /// The multiplier's accumulations acc·2 + (Ndt or 0) and acc·2 + (Nep or 0), over two
    /// cycles each.
    mul_den: crate::arith::two_cycle_adder::TwoCycleAdder<P>,
    mul_num: crate::arith::two_cycle_adder::TwoCycleAdder<P>,
    /// The rounding, scaling and sign adder, over two cycles.
    round_add: crate::arith::two_cycle_adder::TwoCycleAdder<S>,
    /// Quotient >> 1 (`quo` without its spurious top bit), or a special value.
    half: Signal<Local, Bits<S>>,
    /// The last quotient bit r: the last remainder is not negative.
    last_bit: Signal<Local, Bit>,
    /// The rounding adder's small operand for a last quotient bit r = 0 and r = 1,
    /// registered when the request is taken (module docs: Rounding).
    inc_r0: DFF<Bits<S>>,
    inc_r1: DFF<Bits<S>>,
    inc_base: Signal<Local, Bits<S>>,
    inc_plus: Signal<Local, Bits<S>>,
    /// The request's mode shift is 1 / is 2 or 3.
    req_by_two: Signal<Local, Bit>,
    req_by_four: Signal<Local, Bit>,
    /// Mode scaling by 2 (s = 1) or by 4 (s = 2).
    by_two: Signal<Local, Bit>,
    by_four: Signal<Local, Bit>,
    /// h or ~h.
    addend: Signal<Local, Bits<S>>,
    /// e or f (0 to 3).
    increment: Signal<Local, Bits<S>>,
    sum: Signal<Local, Bits<S>>,
    sum_negative: Signal<Local, Bit>,
    /// The signed, scaled speed.
    rounded: Signal<Local, Bits<S>>,
    // Constants, each of the width it is used at.
    n_zero: Constant<Bits<N>>,
    c_zero: Constant<Bits<C>>,
    p_zero: Constant<Bits<P>>,
    p_one: Constant<Bits<P>>,
    /// 2^(P − 1): the partial remainder's carry bit and the numerator bit brought down.
    p_msb: Constant<Bits<P>>,
    /// 2^N: the multiplier bit (X has N + 1 bits).
    p_x_msb: Constant<Bits<P>>,
    /// 2^(N − 1): the multiplier bit of the next step.
    p_x_next: Constant<Bits<P>>,
    s_zero: Constant<Bits<S>>,
    s_one: Constant<Bits<S>>,
    s_two: Constant<Bits<S>>,
    s_three: Constant<Bits<S>>,
    /// The two sign bits that an arithmetic shift by 2 fills in.
    s_fill_two: Constant<Bits<S>>,
    /// 2^(S − 1): the sum's top bit, and the sign bit an arithmetic shift by 1 fills in.
    s_msb: Constant<Bits<S>>,
    /// 2^(S − 1) − 1: `quo` without its top bit.
    s_half_mask: Constant<Bits<S>>,
    m_zero: Constant<Bits<2>>,
    m_one: Constant<Bits<2>>,
    m_two: Constant<Bits<2>>,
    /// 2^(N+F) − 1: the saturated magnitude.
    s_max: Constant<Bits<S>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    sh_two: Constant<Bits<SHIFT_BITS>>,
    /// N: shift from num to its preloaded remainder num >> N.
    sh_n: Constant<Bits<SHIFT_BITS>>,
    /// P − N = N + 1: shift that puts the low N bits of num at the top.
    sh_low: Constant<Bits<SHIFT_BITS>>,
    count_zero: Constant<Bits<COUNT_BITS>>,
    count_one: Constant<Bits<COUNT_BITS>>,
    /// S − 1: loaded at each set-up.
    count_first: Constant<Bits<COUNT_BITS>>,
    /// S − N − 1 + 1 = F + 1: the count of the step before the last multiplier step.
    count_before_mul_last: Constant<Bits<COUNT_BITS>>,
    st_idle: Constant<Bits<STATE_BITS>>,
    st_setup: Constant<Bits<STATE_BITS>>,
    st_step: Constant<Bits<STATE_BITS>>,
    st_finish: Constant<Bits<STATE_BITS>>,
    ph_one: Constant<Bits<STATE_BITS>>,
    ph_two: Constant<Bits<STATE_BITS>>,
    ph_three: Constant<Bits<STATE_BITS>>,
}

impl<const N: usize, const F: usize, const P: usize, const S: usize> SpeedCalc<N, F, P, S> {
    const PARAMS_OK: () = {
        assert!(N >= 8 && N <= 32, "SpeedCalc supports N in 8..=32");
        assert!(F <= 24, "SpeedCalc supports F in 0..=24");
        assert!(P == 2 * N + 1, "SpeedCalc needs P = 2N + 1");
        assert!(S == N + F + 1, "SpeedCalc needs S = N + F + 1");
    };
}

impl<const N: usize, const F: usize, const P: usize, const S: usize> Default
    for SpeedCalc<N, F, P, S>
{
    fn default() -> Self {
        let () = Self::PARAMS_OK;
        let c = |v: usize| -> u64 { v.try_into().unwrap() };
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            nep: Default::default(),
            ndt: Default::default(),
            negative: Default::default(),
            mode_shift: Default::default(),
            position: Default::default(),
            speed_n1: Default::default(),
            speed_n2: Default::default(),
            speed_n3: Default::default(),
            speed_position: Default::default(),
            speed_nep: Default::default(),
            speed_ndt: Default::default(),
            valid: Default::default(),
            have_speeds: Default::default(),
            busy: Default::default(),
            req_position: Default::default(),
            req_nep: Default::default(),
            req_ndt: Default::default(),
            req_neg: Default::default(),
            req_shift: Default::default(),
            pending: Default::default(),
            w_position: Default::default(),
            w_nep: Default::default(),
            w_ndt: Default::default(),
            w_high: Default::default(),
            w_neg: Default::default(),
            w_shift: Default::default(),
            w_nep_zero: Default::default(),
            w_ndt_zero: Default::default(),
            state: Default::default(),
            phase: Default::default(),
            count: Default::default(),
            second: Default::default(),
            publish: Default::default(),
            mul_on: Default::default(),
            mul_last: Default::default(),
            part_rem: Default::default(),
            num_shift: Default::default(),
            den: Default::default(),
            quo: Default::default(),
            mul_x: Default::default(),
            acc_num: Default::default(),
            acc_den: Default::default(),
            op_num: Default::default(),
            op_den: Default::default(),
            stage_n1: Default::default(),
            stage_n2: Default::default(),
            out_n1: Default::default(),
            out_n2: Default::default(),
            out_n3: Default::default(),
            out_position: Default::default(),
            out_nep: Default::default(),
            out_ndt: Default::default(),
            valid_reg: Default::default(),
            have_reg: Default::default(),
            nep_wide: Default::default(),
            ndt_wide: Default::default(),
            nep_less_one: Default::default(),
            ndt_plus_one: Default::default(),
            num_sel: Default::default(),
            den_sel: Default::default(),
            div_sub: Default::default(),
            shifted: Default::default(),
            rem_negative: Default::default(),
            x_first: Default::default(),
            x_next: Default::default(),
            mul_last_next: Default::default(),
            mul_den: Default::default(),
            mul_num: Default::default(),
            round_add: Default::default(),
            half: Default::default(),
            last_bit: Default::default(),
            inc_r0: Default::default(),
            inc_r1: Default::default(),
            inc_base: Default::default(),
            inc_plus: Default::default(),
            req_by_two: Default::default(),
            req_by_four: Default::default(),
            by_two: Default::default(),
            by_four: Default::default(),
            addend: Default::default(),
            increment: Default::default(),
            sum: Default::default(),
            sum_negative: Default::default(),
            rounded: Default::default(),
            n_zero: Constant::new(0.into()),
            c_zero: Constant::new(0.into()),
            p_zero: Constant::new(0.into()),
            p_one: Constant::new(1.into()),
            // P can be 65: build 2^(P−1) bit by bit rather than from a u64.
            p_msb: Constant::new(Bits::<P>::default().replace_bit(P - 1, true)),
            p_x_msb: Constant::new(Bits::<P>::default().replace_bit(N, true)),
            p_x_next: Constant::new(Bits::<P>::default().replace_bit(N - 1, true)),
            s_zero: Constant::new(0.into()),
            s_one: Constant::new(1.into()),
            s_two: Constant::new(2.into()),
            s_three: Constant::new(3.into()),
            s_fill_two: Constant::new(
                Bits::<S>::default()
                    .replace_bit(S - 1, true)
                    .replace_bit(S - 2, true),
            ),
            s_msb: Constant::new(Bits::<S>::default().replace_bit(S - 1, true)),
            s_half_mask: Constant::new(((1u64 << (S - 1)) - 1).into()),
            m_zero: Constant::new(0.into()),
            m_one: Constant::new(1.into()),
            m_two: Constant::new(2.into()),
            s_max: Constant::new(((1u64 << (N + F)) - 1).into()),
            sh_one: Constant::new(1.into()),
            sh_two: Constant::new(2.into()),
            sh_n: Constant::new(c(N).into()),
            sh_low: Constant::new(c(P - N).into()),
            count_zero: Constant::new(0.into()),
            count_one: Constant::new(1.into()),
            count_first: Constant::new(c(S - 1).into()),
            count_before_mul_last: Constant::new(c(S - N).into()),
            st_idle: Constant::new(0.into()),
            st_setup: Constant::new(1.into()),
            st_step: Constant::new(2.into()),
            st_finish: Constant::new(3.into()),
            ph_one: Constant::new(1.into()),
            ph_two: Constant::new(2.into()),
            ph_three: Constant::new(3.into()),
        }
    }
}

impl<const N: usize, const F: usize, const P: usize, const S: usize> Logic
    for SpeedCalc<N, F, P, S>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            req_position,
            req_nep,
            req_ndt,
            req_neg,
            req_shift,
            pending,
            w_position,
            w_nep,
            w_ndt,
            w_high,
            w_neg,
            w_shift,
            w_nep_zero,
            w_ndt_zero,
            state,
            phase,
            count,
            second,
            publish,
            mul_on,
            mul_last,
            part_rem,
            num_shift,
            den,
            quo,
            mul_x,
            acc_num,
            acc_den,
            op_num,
            op_den,
            stage_n1,
            stage_n2,
            out_n1,
            out_n2,
            out_n3,
            out_position,
            out_nep,
            out_ndt,
            valid_reg,
            have_reg,
            nep_less_one,
            ndt_plus_one,
            inc_r0,
            inc_r1
        );
        clock!(self, clock, div_sub, mul_den, mul_num, round_add);
        // Widen the working Nep and Ndt to P bits: shift their bits in at the top, LSB
        // first, then move them down (a cast would be emitted as a mask of another width).
        self.nep_wide.next = self.p_zero.val();
        self.ndt_wide.next = self.p_zero.val();
        for i in 0..N {
            if self.w_nep.q.val().get_bit(i) {
                self.nep_wide.next = (self.nep_wide.val() >> self.sh_one.val()) | self.p_msb.val();
            } else {
                self.nep_wide.next = self.nep_wide.val() >> self.sh_one.val();
            }
            if self.w_ndt.q.val().get_bit(i) {
                self.ndt_wide.next = (self.ndt_wide.val() >> self.sh_one.val()) | self.p_msb.val();
            } else {
                self.ndt_wide.next = self.ndt_wide.val() >> self.sh_one.val();
            }
        }
        self.nep_wide.next = self.nep_wide.val() >> self.sh_low.val();
        self.ndt_wide.next = self.ndt_wide.val() >> self.sh_low.val();

        // Operands of the next division (no carry chain: the high-speed test was registered
        // when the request was taken, Nep − 1 and Ndt + 1 an edge after it).
        self.nep_less_one.d.next = self.nep_wide.val() - self.p_one.val();
        self.ndt_plus_one.d.next = self.ndt_wide.val() + self.p_one.val();
        self.num_sel.next = self.nep_wide.val();
        self.den_sel.next = self.ndt_wide.val();
        if self.phase.q.val() == self.ph_two.val() {
            if self.w_high.q.val() {
                self.num_sel.next = self.nep_less_one.q.val();
            } else {
                self.den_sel.next = self.ndt_plus_one.q.val();
            }
        }
        if self.phase.q.val() == self.ph_three.val() {
            if self.w_high.q.val() {
                self.num_sel.next = self.acc_num.q.val();
                self.den_sel.next = self.acc_den.q.val();
            } else {
                self.num_sel.next = self.nep_wide.val() << self.sh_one.val();
                self.den_sel.next = (self.ndt_wide.val() << self.sh_one.val()) | self.p_one.val();
            }
        }

        // One non-restoring division step over two cycles: bring down the next numerator
        // bit, then subtract den if R ≥ 0 or add it if R < 0 (R's top bit, a register), so
        // the new remainder is the sum itself, with no multiplexer behind the carry chain.
        // Its sign is the quotient bit (module docs: Datapath). The operands are registers
        // held for the step's two cycles, so in the second the sum is theirs.
        self.shifted.next = self.part_rem.q.val() << self.sh_one.val();
        if (self.num_shift.q.val() & self.p_msb.val()) != self.p_zero.val() {
            self.shifted.next = (self.part_rem.q.val() << self.sh_one.val()) | self.p_one.val();
        }
        self.rem_negative.next = (self.part_rem.q.val() & self.p_msb.val()) != self.p_zero.val();
        self.div_sub.a.next = self.shifted.val();
        self.div_sub.b.next = !self.den.q.val();
        self.div_sub.carry_in.next = true;
        if self.rem_negative.val() {
            self.div_sub.b.next = self.den.q.val();
            self.div_sub.carry_in.next = false;
        }

        // The multiplier's two accumulations, acc·2 + (operand if the bit of X is 1): the
        // operands are registers chosen when the step before ended (`op_num`, `op_den`).
        self.mul_den.a.next = self.acc_den.q.val() << self.sh_one.val();
        self.mul_den.b.next = self.op_den.q.val();
        self.mul_den.carry_in.next = false;
        self.mul_num.a.next = self.acc_num.q.val() << self.sh_one.val();
        self.mul_num.b.next = self.op_num.q.val();
        self.mul_num.carry_in.next = false;
        self.x_first.next = (self.nep_wide.val() << self.sh_one.val()) - self.p_one.val();
        self.x_next.next = (self.mul_x.q.val() & self.p_x_next.val()) != self.p_zero.val();
        self.mul_last_next.next = self.count.q.val() == self.count_before_mul_last.val();
        if (self.state.q.val() == self.st_setup.val()) & self.second.q.val() {
            // The first step's bit: the top bit of X; it is not the last step (S − 1 > F).
            self.x_next.next = (self.x_first.val() & self.p_x_msb.val()) != self.p_zero.val();
            self.mul_last_next.next = false;
        }
        self.op_den.d.next = self.p_zero.val();
        self.op_num.d.next = self.p_zero.val();
        if self.x_next.val() {
            self.op_den.d.next = self.ndt_wide.val();
            if !self.mul_last_next.val() {
                self.op_num.d.next = self.nep_wide.val();
            }
        }

        // Round, mode-scale and sign with one adder (module docs): (h or ~h) + (e or f),
        // then an arithmetic shift by s. With q the last quotient, h = q >> 1 and r = q & 1;
        // the special cases replace h and r (Ndt = 0: h = 2^(N+F) − 1, r = 0; Nep = 0:
        // h = 0, r = 0).
        self.half.next = self.quo.q.val() & self.s_half_mask.val();
        self.last_bit.next = !self.rem_negative.val();
        if self.w_ndt_zero.q.val() {
            self.half.next = self.s_max.val();
        }
        if self.w_nep_zero.q.val() {
            self.half.next = self.s_zero.val();
        }
        self.by_two.next = self.w_shift.q.val() == self.m_one.val();
        self.by_four.next = (self.w_shift.q.val() & self.m_two.val()) != self.m_zero.val();
        self.addend.next = self.half.val();
        if self.w_neg.q.val() {
            self.addend.next = !self.half.val();
        }
        // e or f for r = 0 and r = 1 were registered when the request was taken: only r,
        // the quotient's bit 0, chooses here, one logic level in front of the adder.
        self.increment.next = self.inc_r0.q.val();
        if self.last_bit.val() {
            self.increment.next = self.inc_r1.q.val();
        }
        self.round_add.a.next = self.addend.val();
        self.round_add.b.next = self.increment.val();
        self.round_add.carry_in.next = false;
        self.sum.next = self.round_add.sum.val();
        self.sum_negative.next =
            self.w_neg.q.val() & ((self.sum.val() & self.s_msb.val()) != self.s_zero.val());
        self.rounded.next = self.sum.val();
        if self.by_two.val() {
            self.rounded.next = self.sum.val() >> self.sh_one.val();
            if self.sum_negative.val() {
                self.rounded.next = (self.sum.val() >> self.sh_one.val()) | self.s_msb.val();
            }
        }
        if self.by_four.val() {
            self.rounded.next = self.sum.val() >> self.sh_two.val();
            if self.sum_negative.val() {
                self.rounded.next = (self.sum.val() >> self.sh_two.val()) | self.s_fill_two.val();
            }
        }

        // The rounding adder's small operand for r = 0 (`inc_base`) and r = 1 (`inc_plus`),
        // registered when the request is taken: e = r (+1 in x2, +2 in x4), or for a
        // negative request f = 1 − r (2 − r in x4); the special cases (Nep = 0, Ndt = 0)
        // force r = 0.
        self.req_by_two.next = self.req_shift.q.val() == self.m_one.val();
        self.req_by_four.next = (self.req_shift.q.val() & self.m_two.val()) != self.m_zero.val();
        self.inc_base.next = self.s_zero.val();
        self.inc_plus.next = self.s_one.val();
        if self.req_by_two.val() {
            self.inc_base.next = self.s_one.val();
            self.inc_plus.next = self.s_two.val();
        }
        if self.req_by_four.val() {
            self.inc_base.next = self.s_two.val();
            self.inc_plus.next = self.s_three.val();
        }
        if self.req_neg.q.val() {
            self.inc_base.next = self.s_one.val();
            self.inc_plus.next = self.s_zero.val();
            if self.req_by_four.val() {
                self.inc_base.next = self.s_two.val();
                self.inc_plus.next = self.s_one.val();
            }
        }
        if (self.req_nep.q.val() == self.n_zero.val()) | (self.req_ndt.q.val() == self.n_zero.val())
        {
            self.inc_plus.next = self.inc_base.val();
        }

        self.valid_reg.d.next = false;
        if (self.state.q.val() == self.st_idle.val()) & self.pending.q.val() {
            self.w_position.d.next = self.req_position.q.val();
            self.w_nep.d.next = self.req_nep.q.val();
            self.w_ndt.d.next = self.req_ndt.q.val();
            // 2·Ndt ≤ Nep ⇔ Ndt ≤ ⌊Nep/2⌋, at N bits.
            self.w_high.d.next =
                self.req_ndt.q.val() <= (self.req_nep.q.val() >> self.sh_one.val());
            self.w_neg.d.next = self.req_neg.q.val();
            self.w_shift.d.next = self.req_shift.q.val();
            self.inc_r0.d.next = self.inc_base.val();
            self.inc_r1.d.next = self.inc_plus.val();
            self.w_nep_zero.d.next = self.req_nep.q.val() == self.n_zero.val();
            self.w_ndt_zero.d.next = self.req_ndt.q.val() == self.n_zero.val();
            self.pending.d.next = false;
            self.phase.d.next = self.ph_one.val();
            self.second.d.next = false;
            self.state.d.next = self.st_setup.val();
        }
        // Every other state lasts two cycles: its first only lets the adders' low halves
        // take their (held) operands, its second acts (FINISH: a third publishes).
        if self.state.q.val() != self.st_idle.val() {
            self.second.d.next = !self.second.q.val();
        }
        if (self.state.q.val() == self.st_setup.val()) & self.second.q.val() {
            self.part_rem.d.next = self.num_sel.val() >> self.sh_n.val();
            self.num_shift.d.next = self.num_sel.val() << self.sh_low.val();
            self.den.d.next = self.den_sel.val();
            self.count.d.next = self.count_first.val();
            // S − 1 > F (N ≥ 8).
            self.mul_last.d.next = false;
            self.state.d.next = self.st_step.val();
            if self.phase.q.val() == self.ph_one.val() {
                self.mul_x.d.next = self.x_first.val();
                self.acc_num.d.next = self.p_zero.val();
                self.acc_den.d.next = self.p_zero.val();
                self.mul_on.d.next = true;
            }
            if self.phase.q.val() == self.ph_two.val() {
                self.stage_n1.d.next = self.rounded.val();
            }
            if self.phase.q.val() == self.ph_three.val() {
                self.stage_n2.d.next = self.rounded.val();
            }
        }
        if (self.state.q.val() == self.st_step.val()) & self.second.q.val() {
            self.part_rem.d.next = self.div_sub.sum.val();
            self.num_shift.d.next = self.num_shift.q.val() << self.sh_one.val();
            // The quotient bit of the step before this one: the sign of the remainder
            // it left, a register, so the carry chain ends at `part_rem` alone.
            self.quo.d.next = self.quo.q.val() << self.sh_one.val();
            if !self.rem_negative.val() {
                self.quo.d.next = (self.quo.q.val() << self.sh_one.val()) | self.s_one.val();
            }
            self.count.d.next = self.count.q.val() - self.count_one.val();
            self.mul_last.d.next = self.mul_last_next.val();
            if self.mul_on.q.val() {
                self.mul_x.d.next = self.mul_x.q.val() << self.sh_one.val();
                self.acc_num.d.next = self.mul_num.sum.val();
                self.acc_den.d.next = self.mul_den.sum.val();
                if self.mul_last.q.val() {
                    self.mul_on.d.next = false;
                }
            }
            if self.count.q.val() == self.count_zero.val() {
                self.state.d.next = self.st_setup.val();
                self.phase.d.next = self.phase.q.val() + self.ph_one.val();
                if self.phase.q.val() == self.ph_three.val() {
                    self.state.d.next = self.st_finish.val();
                }
            }
        }
        // FINISH: the rounding adder's sum stands from the second cycle on (its operands
        // hold); the third writes the outputs, which are the core's output registers.
        if (self.state.q.val() == self.st_finish.val()) & self.second.q.val() {
            self.publish.d.next = true;
        }
        if self.publish.q.val() {
            self.out_n1.d.next = self.stage_n1.q.val();
            self.out_n2.d.next = self.stage_n2.q.val();
            self.out_n3.d.next = self.rounded.val();
            self.out_position.d.next = self.w_position.q.val();
            self.out_nep.d.next = self.w_nep.q.val();
            self.out_ndt.d.next = self.w_ndt.q.val();
            self.valid_reg.d.next = true;
            self.have_reg.d.next = true;
            self.publish.d.next = false;
            self.second.d.next = false;
            self.state.d.next = self.st_idle.val();
        }
        if self.start.val() {
            self.req_position.d.next = self.position.val();
            self.req_nep.d.next = self.nep.val();
            self.req_ndt.d.next = self.ndt.val();
            self.req_neg.d.next = self.negative.val();
            self.req_shift.d.next = self.mode_shift.val();
            self.pending.d.next = true;
        }
        if self.reset.val() {
            self.pending.d.next = false;
            self.mul_on.d.next = false;
            self.second.d.next = false;
            self.publish.d.next = false;
            self.state.d.next = self.st_idle.val();
            self.valid_reg.d.next = false;
            self.have_reg.d.next = false;
            self.out_n1.d.next = self.s_zero.val();
            self.out_n2.d.next = self.s_zero.val();
            self.out_n3.d.next = self.s_zero.val();
            self.out_position.d.next = self.c_zero.val();
            self.out_nep.d.next = self.n_zero.val();
            self.out_ndt.d.next = self.n_zero.val();
        }
        self.speed_n1.next = self.out_n1.q.val();
        self.speed_n2.next = self.out_n2.q.val();
        self.speed_n3.next = self.out_n3.q.val();
        self.speed_position.next = self.out_position.q.val();
        self.speed_nep.next = self.out_nep.q.val();
        self.speed_ndt.next = self.out_ndt.q.val();
        self.valid.next = self.valid_reg.q.val();
        self.have_speeds.next = self.have_reg.q.val();
        self.busy.next = self.pending.q.val() | (self.state.q.val() != self.st_idle.val());
    }
}

/// The Verilog of a `SpeedCalc<N, F, P, S>` with its top module named `module_name`.
pub fn speed_calc_verilog<const N: usize, const F: usize, const P: usize, const S: usize>(
    module_name: &str,
) -> String {
    crate::verilog::default_block_verilog::<SpeedCalc<N, F, P, S>>(module_name)
}
