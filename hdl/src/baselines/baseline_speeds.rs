// SPDX-License-Identifier: MIT OR Apache-2.0
//! Baseline speeds: the raw results of the three baseline estimators ([`PcCounter`],
//! [`EtTimer`], [`MtCounter`]) as signed fixed-point speeds in the format of [`SpeedCalc`], by
//! one sequential shift-add multiplier and one sequential divider. A standalone block; its
//! bit-true model is [`golden::baselines::baseline_speeds::BaselineSpeedsModel`], whose module docs
//! state the values, the rounding rule, the saturation and the timing this block implements.
//!
//! [`PcCounter`]: crate::PcCounter
//! [`EtTimer`]: crate::EtTimer
//! [`MtCounter`]: crate::MtCounter
//! [`SpeedCalc`]: crate::SpeedCalc
//!
//! # Generation parameters
//!
//! | parameter | meaning | range |
//! |---|---|---|
//! | `N` | counter width: every count input and `cfg_dt` | 8..=32 |
//! | `F` | fractional bits of the speeds | 2..=24 |
//! | `S` | must be N + F + 1: width of each speed output | derived |
//!
//! Stable Rust cannot compute `N + F + 1` from generic `N` and `F`, so `S` is a parameter
//! too, checked at compile time. Name the type with
//! [`baseline_speeds_type!`](crate::baseline_speeds_type): `baseline_speeds_type!(24, 16)` is
//! `BaselineSpeeds<24, 16, 41>`.
//!
//! # Ports
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | clock; everything happens at its rising edge |
//! | `reset` | in | 1 | synchronous, active high; wins over `start` |
//! | `start` | in | 1 | request a computation; latches every input below |
//! | `pc_count` | in | N | PC: net steps of the window, two's complement |
//! | `et_period` | in | N | ET: clock cycles between the last two steps, unsigned |
//! | `et_negative` | in | 1 | ET direction: 1 = reverse |
//! | `et_valid` | in | 1 | 1 = `et_period` is available and trustworthy; 0 gives `speed_et` = 0 |
//! | `mt_m` | in | N | M/T: steps m, unsigned |
//! | `mt_t` | in | N | M/T: clock cycles t, unsigned |
//! | `mt_negative` | in | 1 | M/T direction: 1 = reverse |
//! | `cfg_dt` | in | N | window dt, clock cycles, unsigned (0 counts as 1) |
//! | `mode_shift` | in | 2 | log2 of the decoding multiplier: 0 = x1, 1 = x2, 2 = x4 (3 counts as 2) |
//! | `speed_pc` | out | N+F+1 | `pc_count`·2^(F−s), exact |
//! | `speed_et` | out | N+F+1 | ±round(dt·2^(F−s)/`et_period`); 0 if `et_valid` = 0 or `et_period` = 0 |
//! | `speed_mt` | out | N+F+1 | ±round(m·dt·2^(F−s)/t), saturated at ±(2^(N+F) − 1); 0 if m = 0 or t = 0 |
//! | `valid` | out | 1 | one cycle: the three speeds were just written (together) |
//! | `busy` | out | 1 | a computation runs or a request is pending |
//!
//! Speeds are two's complement, Q(N).F in units of ω_lim = one encoder line per dt: the value
//! is `raw · 2^−F`. round is to nearest with ties away from zero on the magnitude, then the
//! sign: error ≤ 2^−(F+1) ω_lim. `speed_pc` and `speed_et` always fit; `speed_mt` fits when
//! m ≤ t (always so from [`MtCounter`](crate::MtCounter)) and saturates otherwise.
//!
//! # Timing
//!
//! A `start` sampled at edge k while idle gives `valid` after edge k + L, with
//! L = 4·(N + F + 1) + 4 ([`golden::baselines::baseline_speeds::latency_cycles`]; 168 for
//! N = 24, F = 16), whatever the operands. `busy` is high after edges k … k + L − 1. A `start`
//! while busy latches its inputs into the one-deep request register (replacing a request
//! that has not begun) and is served at the edge after the current `valid`, so the values of
//! the last start are always computed; starts at least L cycles apart each get their own
//! result, L cycles later.
//!
//! # Datapath
//!
//! Schedule, state register IDLE → STEP ×S → SETUP → STEP ×S → FINISH → OUTPUT → IDLE,
//! every STEP two cycles (`second`: the divider's adder is split by a register, and the
//! step's registers are written at the second cycle's edge):
//!
//! * **Take** (IDLE with a request pending): the request is copied into the working
//!   registers and the divider is set up for ET at once: X = dt (A = 0, Q = dt), den =
//!   `et_period`.
//! * **STEP ×S, ET**: S = N + F + 1 divider steps. During the first N the **multiplier**
//!   forms m·dt least significant bit first: if bit 0 of Q is set, A + dt (N bits plus the
//!   carry read off the operands' and the sum's top bits), then {carry, A, Q} shifts right
//!   by one; after N steps {A, Q} = m·dt. No N×N multiplier (iCE40 has no DSP).
//! * **SETUP**: the ET quotient goes into the round-and-sign adder, whose sum the first M/T
//!   step writes into a staging register; the divider is set up for M/T: X = {A, Q},
//!   den = t. The saturation flag A >> s ≥ t is registered at every edge from the working
//!   registers, which hold the product from the last multiplier step on, so FINISH reads
//!   the flag of this product.
//! * **STEP ×S, M/T**, then **FINISH** puts the M/T quotient into the round-and-sign adder,
//!   and **OUTPUT** writes `speed_pc` (the working copy of `pc_count` shifted), `speed_et`
//!   (staged) and `speed_mt` (the adder's sum) together with `valid`.
//!
//! **Divider** (radix 2, [`golden::baselines::baseline_speeds::hardware_magnitude`]): for
//! num' = X·2^(2−s) (2N + 2 bits, never formed) the partial remainder R (N bits) is preloaded
//! with num' >> (N + 2) = A >> s, and an S-bit register `dq` with the low N + 2 bits of num'
//! (A's low s bits, Q, 2 − s zeros) at its top. Each step shifts one numerator bit out of
//! the top of `dq` into 2R + b and one quotient bit into its bottom, so after S steps `dq`
//! holds q = ⌊X·2^(F+1−s)/den⌋ (S bits, since R < den) without ever forming X·2^F. The
//! step is non-restoring, as [`SpeedCalc`](crate::SpeedCalc)'s: R ∈ [−den, den) is held as
//! N bits `part_rem` (R modulo 2^N) and a sign `rem_neg`; a step from R ≥ 0 forms
//! 2R + b − den, from R < 0 2R + b + den, in one N-bit
//! [`TwoCycleAdder`](crate::TwoCycleAdder) (operand den or ~den and the carry in chosen by
//! `rem_neg`, a register), whose sum is the new `part_rem` as it stands; the quotient bit
//! is R' ≥ 0. Its quotient bits are those of restoring division: where restoring division
//! holds R_r, this one holds R_r or R_r − den, and 2(R_r − den) + b + den = 2R_r + b − den.
//! R' needs N + 1 bits, and rust-hdl cannot size a signal N + 1 from a generic N, so its
//! sign is read off the carry out of the N-bit sum: with c = R's bit N − 1,
//! R' = (c + co − 1)·2^N + sum from R ≥ 0 (negative unless c or co) and
//! (c + co − 2)·2^N + sum from R < 0 (negative unless c and co), and co is both operands'
//! top bits when the sum's top bit is 1, either of them when it is 0: both candidate signs
//! are formed from the registers and the sum's top bit chooses. Why two cycles: in one, the
//! step (the sign register's fan-out into the operand, a 24-bit carry chain, the sign
//! logic and the registers' multiplexers) was the critical path of `encspeed_wb` on the
//! iCE40 HX8K on most placement seeds, restoring (97.0 to 101.8 MHz over seeds 1-3) or
//! non-restoring (90.8 to 102.0 MHz) alike.
//! The magnitude is (q + 1) >> 1; q all ones (which would round up past the format; its
//! bits above bit 0 are tested on `dq` one edge earlier, a register) and a preload not below den
//! saturate to 2^(N+F) − 1. Rounding
//! and sign share one adder: with h = q >> 1 and r = q & 1, the result is (h, or ~h if
//! negative) + (r xor negative), as in [`SpeedCalc`](crate::SpeedCalc).
//!
//! **PC**: `pc_count` is shifted in at the top of S bits (pc·2^(F+1)), then shifted right
//! arithmetically 1 + s times: pc·2^(F−s). F ≥ 2 keeps F − s ≥ 0.
//!
//! Widths never change inside an expression (rust-hdl emits literals 32 bits wide and casts
//! as masks that Verilator flags): N-bit values are widened to S bits by shift-in loops
//! (wires after synthesis) and every constant is a `Constant` of its operand's width.
//!
//! # Resources
//!
//! Registers: the request (5N + 6), working copies and flags (2N + 11), the multiplier (3N),
//! the divider (2N + S + 2) and its two-cycle adder's low sum and high operands (about
//! 1.5N), staging and outputs (4S + 1), the round adder's low sum and high operand (about
//! S + 3), a 6-bit step counter and 4 control bits. Adders: the divider's N-bit add or
//! subtract in two halves, the multiplier's N-bit add, the S-bit round-and-sign adder in
//! two halves, the N-bit saturation comparison. yosys 0.23 `synth_ice40 -top
//! 'encspeed_core$baseline'; stat` on generated/encspeed_core.v (the block at N = 24,
//! F = 16, S = 41) maps it to 588 flip-flops (constant bits removed), 673 LUT4 and 119
//! carry cells (549, 636 and 119 with the restoring step in one cycle; 501, 677 and 118
//! with the round-and-sign adder in one cycle as well). (SpeedCalc, three divisions of
//! 2N + 1 bits: 604, 792 and 277.)

use rust_hdl::prelude::*;

/// Width of the step counter: it holds S − 1 ≤ 56.
const COUNT_BITS: usize = 6;
/// Width of the state register.
const STATE_BITS: usize = 3;
/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// The `BaselineSpeeds` type for counter width `$n` and `$f` fractional bits (literals or
/// constants), with the derived width filled in: `baseline_speeds_type!(24, 16)` is
/// `BaselineSpeeds<24, 16, 41>`.
#[macro_export]
macro_rules! baseline_speeds_type {
    ($n:expr, $f:expr) => {
        $crate::baselines::baseline_speeds::BaselineSpeeds<{ $n }, { $f }, { $n + $f + 1 }>
    };
}

/// Baseline speeds: PC, ET and M/T results as signed Q(N).F fixed point.
#[derive(LogicBlock)]
pub struct BaselineSpeeds<const N: usize, const F: usize, const S: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset (wins over `start`).
    pub reset: Signal<In, Bit>,
    /// Request a computation; latches every input.
    pub start: Signal<In, Bit>,
    /// PC: net steps of the window, two's complement.
    pub pc_count: Signal<In, Bits<N>>,
    /// ET: clock cycles between the last two steps.
    pub et_period: Signal<In, Bits<N>>,
    /// ET direction: 1 = reverse.
    pub et_negative: Signal<In, Bit>,
    /// 1 = `et_period` is available and trustworthy (else `speed_et` = 0).
    pub et_valid: Signal<In, Bit>,
    /// M/T: steps m.
    pub mt_m: Signal<In, Bits<N>>,
    /// M/T: clock cycles t.
    pub mt_t: Signal<In, Bits<N>>,
    /// M/T direction: 1 = reverse.
    pub mt_negative: Signal<In, Bit>,
    /// Window dt, clock cycles (0 counts as 1).
    pub cfg_dt: Signal<In, Bits<N>>,
    /// log2 of the decoding multiplier (x1, x2, x4; 3 counts as 2).
    pub mode_shift: Signal<In, Bits<2>>,
    /// PC speed, Q(N).F two's complement, units of ω_lim.
    pub speed_pc: Signal<Out, Bits<S>>,
    /// ET speed, Q(N).F two's complement, units of ω_lim.
    pub speed_et: Signal<Out, Bits<S>>,
    /// M/T speed, Q(N).F two's complement, units of ω_lim.
    pub speed_mt: Signal<Out, Bits<S>>,
    /// One-cycle strobe: the three speeds were just written.
    pub valid: Signal<Out, Bit>,
    /// A computation runs or a request is pending.
    pub busy: Signal<Out, Bit>,
    // Request register.
    req_pc: DFF<Bits<N>>,
    req_period: DFF<Bits<N>>,
    req_et_neg: DFF<Bit>,
    req_et_valid: DFF<Bit>,
    req_m: DFF<Bits<N>>,
    req_t: DFF<Bits<N>>,
    req_mt_neg: DFF<Bit>,
    req_dt: DFF<Bits<N>>,
    req_shift: DFF<Bits<2>>,
    pending: DFF<Bit>,
    // Working copy of what is needed after the take edge.
    w_pc: DFF<Bits<N>>,
    w_t: DFF<Bits<N>>,
    /// s ≥ 1.
    w_sh1: DFF<Bit>,
    /// s ≥ 2.
    w_sh2: DFF<Bit>,
    w_et_neg: DFF<Bit>,
    /// `speed_et` = 0.
    w_et_zero: DFF<Bit>,
    w_mt_neg: DFF<Bit>,
    /// `speed_mt` = 0.
    w_mt_zero: DFF<Bit>,
    /// `speed_mt` saturates (preload not below t). Registered at every edge from the
    /// product and t, which are steady from the last multiplier step to FINISH, where it is
    /// read: no state decode or set-up mux in front of its comparison.
    w_mt_sat: DFF<Bit>,
    // Sequencer.
    state: DFF<Bits<STATE_BITS>>,
    /// 0: the ET division, 1: the M/T division.
    phase: DFF<Bit>,
    count: DFF<Bits<COUNT_BITS>>,
    // Multiplier: {A, Q} = m·dt after N steps; md = dt.
    mul_md: DFF<Bits<N>>,
    mul_a: DFF<Bits<N>>,
    mul_q: DFF<Bits<N>>,
    // Divider.
    part_rem: DFF<Bits<N>>,
    den: DFF<Bits<N>>,
    /// Numerator bits out at the top, quotient bits in at the bottom.
    dq: DFF<Bits<S>>,
    // Results.
    stage_et: DFF<Bits<S>>,
    /// The round adder's sum is the ET result (the cycle after SETUP).
    et_rounding: DFF<Bit>,
    out_pc: DFF<Bits<S>>,
    out_et: DFF<Bits<S>>,
    out_mt: DFF<Bits<S>>,
    valid_reg: DFF<Bit>,
    // Combinational.
    /// Idle with a request pending: take it.
    take: Signal<Local, Bit>,
    /// `cfg_dt` of the request, 0 replaced by 1.
    dt_eff: Signal<Local, Bits<N>>,
    // Divider set-up: ET at the take edge (A = 0, Q = dt), M/T at SETUP (the product).
    src_a: Signal<Local, Bits<N>>,
    src_q: Signal<Local, Bits<N>>,
    src_sh1: Signal<Local, Bit>,
    src_sh2: Signal<Local, Bit>,
    load_dq: Signal<Local, Bits<S>>,
    load_rem: Signal<Local, Bits<N>>,
    /// The M/T preload A >> s, from the working registers.
    sat_rem: Signal<Local, Bits<N>>,
    // Multiplier step.
    /// Bit 0 of Q: add dt in this step.
    mul_q0: Signal<Local, Bit>,
    mul_sum: Signal<Local, Bits<N>>,
    mul_a_msb: Signal<Local, Bit>,
    mul_md_msb: Signal<Local, Bit>,
    mul_sum_msb: Signal<Local, Bit>,
    mul_carry: Signal<Local, Bit>,
    // Divider step: non-restoring, over two cycles.
    /// The partial remainder is negative (`part_rem` holds it modulo 2^N).
    rem_neg: DFF<Bit>,
    /// The second cycle of a step: the divider's sum is ready.
    second: DFF<Bit>,
    /// 2R + b modulo 2^N.
    shifted: Signal<Local, Bits<N>>,
    /// shifted + (den if R < 0, else ~den) + (0 if R < 0, else 1): R' modulo 2^N, ready in
    /// the step's second cycle (the operands are registers held for both).
    div_add: crate::arith::two_cycle_adder::TwoCycleAdder<N>,
    /// den if R < 0, else ~den.
    operand: Signal<Local, Bits<N>>,
    rem_msb: Signal<Local, Bit>,
    shifted_msb: Signal<Local, Bit>,
    operand_msb: Signal<Local, Bit>,
    sum_msb: Signal<Local, Bit>,
    /// Both operands' top bits are 1.
    both_msb: Signal<Local, Bit>,
    /// Either operand's top bit is 1.
    either_msb: Signal<Local, Bit>,
    /// R' < 0 if the sum's top bit is 1 (carry out = both operands' top bits).
    neg_if_sum_msb: Signal<Local, Bit>,
    /// R' < 0 if the sum's top bit is 0 (carry out = either operand's top bit).
    neg_if_no_sum_msb: Signal<Local, Bit>,
    /// R' < 0.
    next_neg: Signal<Local, Bit>,
    // Round and sign.
    /// The sign, zero and saturation flags of the division being rounded, registered from
    /// `phase` at every edge: `phase` and the flags are steady for many cycles before
    /// SETUP and FINISH read them, and a register takes the selection out of the round
    /// adder's input logic.
    sel_neg: DFF<Bit>,
    sel_zero: DFF<Bit>,
    sel_sat: DFF<Bit>,
    /// Quotient bit 0 may round up: `dq`'s low S − 1 bits were not all ones at the edge
    /// before (when SETUP or FINISH rounds a quotient, its bits above bit 0), and the
    /// selected result neither saturates nor is zero; registered at every edge from `dq`
    /// and the next values of `sel_sat` and `sel_zero`, so that no S-bit reduction, no
    /// flag logic and nothing of the division step lies in front of the round adder's
    /// carry chain: the increment is bit 0 with this one register, one LUT with the sign
    /// (three LUT levels before, the core's critical path on two of three HX8K seeds).
    round_enable: DFF<Bit>,
    /// The next values of `sel_zero` and `sel_sat` (the flags of the division `phase`
    /// selects), which `round_enable` reads too.
    zero_next: Signal<Local, Bit>,
    sat_next: Signal<Local, Bit>,
    /// Quotient >> 1 (or a special value).
    half: Signal<Local, Bits<S>>,
    /// Quotient bit 0: the rounding increment.
    round_bit: Signal<Local, Bit>,
    addend: Signal<Local, Bits<S>>,
    /// addend + (round_bit xor negative), ready the cycle after its operands: the carry
    /// chain is cut in two by a register (S = 41 bits for N = 24 was the block's slowest
    /// path in one cycle).
    round_add: crate::arith::two_cycle_adder::TwoCycleAdder<S>,
    // PC.
    pc_sign: Signal<Local, Bit>,
    pc_speed: Signal<Local, Bits<S>>,
    // Constants, each of the width it is used at.
    n_zero: Constant<Bits<N>>,
    n_one: Constant<Bits<N>>,
    /// 2^(N−1).
    n_msb: Constant<Bits<N>>,
    s_zero: Constant<Bits<S>>,
    s_one: Constant<Bits<S>>,
    /// 2^(S−1).
    s_msb: Constant<Bits<S>>,
    /// 2^(N+F) − 1: the saturated magnitude.
    s_max: Constant<Bits<S>>,
    /// 2^(S−1) − 1: `dq`'s low S − 1 bits.
    s_low_bits: Constant<Bits<S>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    sh_two: Constant<Bits<SHIFT_BITS>>,
    mode_zero: Constant<Bits<2>>,
    /// Bit 1 of `mode_shift`: s = 2.
    mode_two: Constant<Bits<2>>,
    count_zero: Constant<Bits<COUNT_BITS>>,
    count_one: Constant<Bits<COUNT_BITS>>,
    /// S − 1: loaded at each set-up.
    count_first: Constant<Bits<COUNT_BITS>>,
    /// F: the multiplier runs while count > F (the first N steps).
    count_mul_end: Constant<Bits<COUNT_BITS>>,
    st_idle: Constant<Bits<STATE_BITS>>,
    st_step: Constant<Bits<STATE_BITS>>,
    st_setup: Constant<Bits<STATE_BITS>>,
    st_finish: Constant<Bits<STATE_BITS>>,
    st_output: Constant<Bits<STATE_BITS>>,
}

impl<const N: usize, const F: usize, const S: usize> BaselineSpeeds<N, F, S> {
    const PARAMS_OK: () = {
        assert!(N >= 8 && N <= 32, "BaselineSpeeds supports N in 8..=32");
        assert!(F >= 2 && F <= 24, "BaselineSpeeds supports F in 2..=24");
        assert!(S == N + F + 1, "BaselineSpeeds needs S = N + F + 1");
    };
}

impl<const N: usize, const F: usize, const S: usize> Default for BaselineSpeeds<N, F, S> {
    fn default() -> Self {
        let () = Self::PARAMS_OK;
        let c = |v: usize| -> u64 { v.try_into().unwrap() };
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            pc_count: Default::default(),
            et_period: Default::default(),
            et_negative: Default::default(),
            et_valid: Default::default(),
            mt_m: Default::default(),
            mt_t: Default::default(),
            mt_negative: Default::default(),
            cfg_dt: Default::default(),
            mode_shift: Default::default(),
            speed_pc: Default::default(),
            speed_et: Default::default(),
            speed_mt: Default::default(),
            valid: Default::default(),
            busy: Default::default(),
            req_pc: Default::default(),
            req_period: Default::default(),
            req_et_neg: Default::default(),
            req_et_valid: Default::default(),
            req_m: Default::default(),
            req_t: Default::default(),
            req_mt_neg: Default::default(),
            req_dt: Default::default(),
            req_shift: Default::default(),
            pending: Default::default(),
            w_pc: Default::default(),
            w_t: Default::default(),
            w_sh1: Default::default(),
            w_sh2: Default::default(),
            w_et_neg: Default::default(),
            w_et_zero: Default::default(),
            w_mt_neg: Default::default(),
            w_mt_zero: Default::default(),
            w_mt_sat: Default::default(),
            state: Default::default(),
            phase: Default::default(),
            count: Default::default(),
            mul_md: Default::default(),
            mul_a: Default::default(),
            mul_q: Default::default(),
            part_rem: Default::default(),
            den: Default::default(),
            dq: Default::default(),
            stage_et: Default::default(),
            et_rounding: Default::default(),
            out_pc: Default::default(),
            out_et: Default::default(),
            out_mt: Default::default(),
            valid_reg: Default::default(),
            take: Default::default(),
            dt_eff: Default::default(),
            src_a: Default::default(),
            src_q: Default::default(),
            src_sh1: Default::default(),
            src_sh2: Default::default(),
            load_dq: Default::default(),
            load_rem: Default::default(),
            sat_rem: Default::default(),
            mul_q0: Default::default(),
            mul_sum: Default::default(),
            mul_a_msb: Default::default(),
            mul_md_msb: Default::default(),
            mul_sum_msb: Default::default(),
            mul_carry: Default::default(),
            rem_neg: Default::default(),
            second: Default::default(),
            shifted: Default::default(),
            div_add: Default::default(),
            operand: Default::default(),
            rem_msb: Default::default(),
            shifted_msb: Default::default(),
            operand_msb: Default::default(),
            sum_msb: Default::default(),
            both_msb: Default::default(),
            either_msb: Default::default(),
            neg_if_sum_msb: Default::default(),
            neg_if_no_sum_msb: Default::default(),
            next_neg: Default::default(),
            sel_neg: Default::default(),
            sel_zero: Default::default(),
            sel_sat: Default::default(),
            round_enable: Default::default(),
            zero_next: Default::default(),
            sat_next: Default::default(),
            half: Default::default(),
            round_bit: Default::default(),
            addend: Default::default(),
            round_add: Default::default(),
            pc_sign: Default::default(),
            pc_speed: Default::default(),
            n_zero: Constant::new(0.into()),
            n_one: Constant::new(1.into()),
            n_msb: Constant::new((1u64 << (N - 1)).into()),
            s_zero: Constant::new(0.into()),
            s_one: Constant::new(1.into()),
            s_msb: Constant::new((1u64 << (S - 1)).into()),
            s_max: Constant::new(((1u64 << (N + F)) - 1).into()),
            s_low_bits: Constant::new(((1u64 << (S - 1)) - 1).into()),
            sh_one: Constant::new(1.into()),
            sh_two: Constant::new(2.into()),
            mode_zero: Constant::new(0.into()),
            mode_two: Constant::new(2.into()),
            count_zero: Constant::new(0.into()),
            count_one: Constant::new(1.into()),
            count_first: Constant::new(c(S - 1).into()),
            count_mul_end: Constant::new(c(F).into()),
            st_idle: Constant::new(0.into()),
            st_step: Constant::new(1.into()),
            st_setup: Constant::new(2.into()),
            st_finish: Constant::new(3.into()),
            st_output: Constant::new(4.into()),
        }
    }
}

impl<const N: usize, const F: usize, const S: usize> Logic for BaselineSpeeds<N, F, S> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            req_pc,
            req_period,
            req_et_neg,
            req_et_valid,
            req_m,
            req_t,
            req_mt_neg,
            req_dt,
            req_shift,
            pending,
            w_pc,
            w_t,
            w_sh1,
            w_sh2,
            w_et_neg,
            w_et_zero,
            w_mt_neg,
            w_mt_zero,
            w_mt_sat,
            state,
            phase,
            count,
            mul_md,
            mul_a,
            mul_q,
            part_rem,
            rem_neg,
            second,
            den,
            dq,
            stage_et,
            et_rounding,
            out_pc,
            out_et,
            out_mt,
            valid_reg,
            sel_neg,
            sel_zero,
            sel_sat,
            round_enable
        );
        self.take.next = (self.state.q.val() == self.st_idle.val()) & self.pending.q.val();
        self.dt_eff.next = self.req_dt.q.val();
        if self.req_dt.q.val() == self.n_zero.val() {
            self.dt_eff.next = self.n_one.val();
        }

        // Divider set-up, shared by the take edge (ET: X = dt, i.e. A = 0, Q = dt) and
        // SETUP (M/T: X = {A, Q} from the multiplier). num' = X·2^(2−s): the partial
        // remainder gets num' >> (N + 2) = A >> s, `dq` the low N + 2 bits of num' at its
        // top: Q shifted in at the top, then shifted right s times taking in A's low bits.
        self.src_a.next = self.mul_a.q.val();
        self.src_q.next = self.mul_q.q.val();
        self.src_sh1.next = self.w_sh1.q.val();
        self.src_sh2.next = self.w_sh2.q.val();
        if self.take.val() {
            self.src_a.next = self.n_zero.val();
            self.src_q.next = self.dt_eff.val();
            self.src_sh1.next = self.req_shift.q.val() != self.mode_zero.val();
            self.src_sh2.next =
                (self.req_shift.q.val() & self.mode_two.val()) != self.mode_zero.val();
        }
        self.load_dq.next = self.s_zero.val();
        for i in 0..N {
            if self.src_q.val().get_bit(i) {
                self.load_dq.next = (self.load_dq.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.load_dq.next = self.load_dq.val() >> self.sh_one.val();
            }
        }
        self.load_rem.next = self.src_a.val();
        if self.src_sh1.val() {
            self.load_rem.next = self.src_a.val() >> self.sh_one.val();
            if self.src_a.val().get_bit(0) {
                self.load_dq.next = (self.load_dq.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.load_dq.next = self.load_dq.val() >> self.sh_one.val();
            }
        }
        if self.src_sh2.val() {
            self.load_rem.next = self.src_a.val() >> self.sh_two.val();
            if self.src_a.val().get_bit(1) {
                self.load_dq.next = (self.load_dq.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.load_dq.next = self.load_dq.val() >> self.sh_one.val();
            }
        }

        // The M/T saturation test, A >> s ≥ t: at FINISH it has the final product.
        self.sat_rem.next = self.mul_a.q.val();
        if self.w_sh1.q.val() {
            self.sat_rem.next = self.mul_a.q.val() >> self.sh_one.val();
        }
        if self.w_sh2.q.val() {
            self.sat_rem.next = self.mul_a.q.val() >> self.sh_two.val();
        }
        self.w_mt_sat.d.next = self.sat_rem.val() >= self.w_t.q.val();

        // Multiplier step: A + (Q bit 0 ? dt : 0) with its carry, from the top bits.
        self.mul_a_msb.next = (self.mul_a.q.val() & self.n_msb.val()) != self.n_zero.val();
        self.mul_md_msb.next = (self.mul_md.q.val() & self.n_msb.val()) != self.n_zero.val();
        self.mul_q0.next = (self.mul_q.q.val() & self.n_one.val()) != self.n_zero.val();
        self.mul_sum.next = self.mul_a.q.val();
        if self.mul_q0.val() {
            self.mul_sum.next = self.mul_a.q.val() + self.mul_md.q.val();
        }
        self.mul_sum_msb.next = (self.mul_sum.val() & self.n_msb.val()) != self.n_zero.val();
        self.mul_carry.next = self.mul_q0.val()
            & ((self.mul_a_msb.val() & self.mul_md_msb.val())
                | ((self.mul_a_msb.val() | self.mul_md_msb.val()) & (!self.mul_sum_msb.val())));

        // One non-restoring division step over two cycles (module docs: Divider): bring
        // down the next numerator bit, subtract den from 2R + b if R ≥ 0, add it if R < 0.
        // The sum is R' modulo 2^N; its sign needs the adder's carry out, which is both
        // operands' top bits when the sum's top bit is 1 and either of them when it is 0:
        // both candidate signs come from the operands, and the sum's top bit chooses.
        self.shifted.next = self.part_rem.q.val() << self.sh_one.val();
        if (self.dq.q.val() & self.s_msb.val()) != self.s_zero.val() {
            self.shifted.next = (self.part_rem.q.val() << self.sh_one.val()) | self.n_one.val();
        }
        self.div_add.clock.next = self.clock.val();
        self.div_add.a.next = self.shifted.val();
        self.operand.next = !self.den.q.val();
        self.div_add.carry_in.next = true;
        if self.rem_neg.q.val() {
            self.operand.next = self.den.q.val();
            self.div_add.carry_in.next = false;
        }
        self.div_add.b.next = self.operand.val();
        self.rem_msb.next = (self.part_rem.q.val() & self.n_msb.val()) != self.n_zero.val();
        self.shifted_msb.next = (self.shifted.val() & self.n_msb.val()) != self.n_zero.val();
        self.operand_msb.next = (self.operand.val() & self.n_msb.val()) != self.n_zero.val();
        self.sum_msb.next = (self.div_add.sum.val() & self.n_msb.val()) != self.n_zero.val();
        self.both_msb.next = self.shifted_msb.val() & self.operand_msb.val();
        self.either_msb.next = self.shifted_msb.val() | self.operand_msb.val();
        // R ≥ 0: R' = (c + co − 1)·2^N + sum; R < 0: R' = (c + co − 2)·2^N + sum
        // (c = R's bit N − 1, co the carry out).
        self.neg_if_sum_msb.next = !(self.rem_msb.val() | self.both_msb.val());
        self.neg_if_no_sum_msb.next = !(self.rem_msb.val() | self.either_msb.val());
        if self.rem_neg.q.val() {
            self.neg_if_sum_msb.next = !(self.rem_msb.val() & self.both_msb.val());
            self.neg_if_no_sum_msb.next = !(self.rem_msb.val() & self.either_msb.val());
        }
        self.next_neg.next = self.neg_if_no_sum_msb.val();
        if self.sum_msb.val() {
            self.next_neg.next = self.neg_if_sum_msb.val();
        }

        // Round and sign with one adder: with q = dq, h = q >> 1 and r = q & 1, the result
        // is (h, or ~h if negative) + (r xor negative). q all ones would round past the
        // format: r is dropped (h is then the maximum). Saturation: h = max, r = 0; zero:
        // h = 0, r = 0.
        self.sel_neg.d.next = self.w_et_neg.q.val();
        self.zero_next.next = self.w_et_zero.q.val();
        self.sat_next.next = false;
        if self.phase.q.val() {
            self.sel_neg.d.next = self.w_mt_neg.q.val();
            self.zero_next.next = self.w_mt_zero.q.val();
            self.sat_next.next = self.w_mt_sat.q.val();
        }
        self.sel_zero.d.next = self.zero_next.val();
        self.sel_sat.d.next = self.sat_next.val();
        self.half.next = self.dq.q.val() >> self.sh_one.val();
        // q all ones is bit 0 and the bits above it: r & ¬(all ones) = r & ¬(bits above).
        self.round_enable.d.next = ((self.dq.q.val() & self.s_low_bits.val())
            != self.s_low_bits.val())
            & !self.zero_next.val()
            & !self.sat_next.val();
        self.round_bit.next =
            ((self.dq.q.val() & self.s_one.val()) != self.s_zero.val()) & self.round_enable.q.val();
        if self.sel_sat.q.val() {
            self.half.next = self.s_max.val();
        }
        if self.sel_zero.q.val() {
            self.half.next = self.s_zero.val();
        }
        self.addend.next = self.half.val();
        if self.sel_neg.q.val() {
            self.addend.next = !self.half.val();
        }
        // The sum is ready in the cycle after the operands (TwoCycleAdder): the ET result
        // of SETUP in the first M/T step (`et_rounding`), the M/T result of FINISH in OUTPUT.
        self.round_add.clock.next = self.clock.val();
        self.round_add.a.next = self.addend.val();
        self.round_add.b.next = self.s_zero.val();
        self.round_add.carry_in.next = self.round_bit.val() ^ self.sel_neg.q.val();

        // PC: pc_count at the top of S bits is pc·2^(F+1); 1 + s arithmetic right shifts.
        self.pc_sign.next = (self.w_pc.q.val() & self.n_msb.val()) != self.n_zero.val();
        self.pc_speed.next = self.s_zero.val();
        for i in 0..N {
            if self.w_pc.q.val().get_bit(i) {
                self.pc_speed.next = (self.pc_speed.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.pc_speed.next = self.pc_speed.val() >> self.sh_one.val();
            }
        }
        if self.pc_sign.val() {
            self.pc_speed.next = (self.pc_speed.val() >> self.sh_one.val()) | self.s_msb.val();
        } else {
            self.pc_speed.next = self.pc_speed.val() >> self.sh_one.val();
        }
        if self.w_sh1.q.val() {
            if self.pc_sign.val() {
                self.pc_speed.next = (self.pc_speed.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.pc_speed.next = self.pc_speed.val() >> self.sh_one.val();
            }
        }
        if self.w_sh2.q.val() {
            if self.pc_sign.val() {
                self.pc_speed.next = (self.pc_speed.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.pc_speed.next = self.pc_speed.val() >> self.sh_one.val();
            }
        }

        // Sequencer.
        self.valid_reg.d.next = false;
        self.et_rounding.d.next = self.state.q.val() == self.st_setup.val();
        if self.et_rounding.q.val() {
            self.stage_et.d.next = self.round_add.sum.val();
        }
        if self.take.val() | (self.state.q.val() == self.st_setup.val()) {
            self.part_rem.d.next = self.load_rem.val();
            self.rem_neg.d.next = false;
            self.second.d.next = false;
            self.dq.d.next = self.load_dq.val();
            self.count.d.next = self.count_first.val();
            self.state.d.next = self.st_step.val();
        }
        if self.take.val() {
            self.den.d.next = self.req_period.q.val();
            self.w_pc.d.next = self.req_pc.q.val();
            self.w_t.d.next = self.req_t.q.val();
            self.w_sh1.d.next = self.src_sh1.val();
            self.w_sh2.d.next = self.src_sh2.val();
            self.w_et_neg.d.next = self.req_et_neg.q.val();
            self.w_et_zero.d.next =
                (!self.req_et_valid.q.val()) | (self.req_period.q.val() == self.n_zero.val());
            self.w_mt_neg.d.next = self.req_mt_neg.q.val();
            self.w_mt_zero.d.next = (self.req_m.q.val() == self.n_zero.val())
                | (self.req_t.q.val() == self.n_zero.val());
            self.mul_md.d.next = self.dt_eff.val();
            self.mul_a.d.next = self.n_zero.val();
            self.mul_q.d.next = self.req_m.q.val();
            self.phase.d.next = false;
            self.pending.d.next = false;
        }
        if self.state.q.val() == self.st_setup.val() {
            self.den.d.next = self.w_t.q.val();
            self.phase.d.next = true;
        }
        // A step takes two cycles: the divider's sum is ready in the second, at whose edge
        // the step's registers are written; the first only registers the adder's low half.
        if self.state.q.val() == self.st_step.val() {
            self.second.d.next = !self.second.q.val();
            if self.second.q.val() {
                self.part_rem.d.next = self.div_add.sum.val();
                self.rem_neg.d.next = self.next_neg.val();
                self.dq.d.next = self.dq.q.val() << self.sh_one.val();
                if !self.next_neg.val() {
                    self.dq.d.next = (self.dq.q.val() << self.sh_one.val()) | self.s_one.val();
                }
                self.count.d.next = self.count.q.val() - self.count_one.val();
                if (!self.phase.q.val()) & (self.count.q.val() > self.count_mul_end.val()) {
                    self.mul_a.d.next = self.mul_sum.val() >> self.sh_one.val();
                    if self.mul_carry.val() {
                        self.mul_a.d.next =
                            (self.mul_sum.val() >> self.sh_one.val()) | self.n_msb.val();
                    }
                    self.mul_q.d.next = self.mul_q.q.val() >> self.sh_one.val();
                    if (self.mul_sum.val() & self.n_one.val()) != self.n_zero.val() {
                        self.mul_q.d.next =
                            (self.mul_q.q.val() >> self.sh_one.val()) | self.n_msb.val();
                    }
                }
                if self.count.q.val() == self.count_zero.val() {
                    self.state.d.next = self.st_setup.val();
                    if self.phase.q.val() {
                        self.state.d.next = self.st_finish.val();
                    }
                }
            }
        }
        if self.state.q.val() == self.st_finish.val() {
            self.state.d.next = self.st_output.val();
        }
        if self.state.q.val() == self.st_output.val() {
            self.out_pc.d.next = self.pc_speed.val();
            self.out_et.d.next = self.stage_et.q.val();
            self.out_mt.d.next = self.round_add.sum.val();
            self.valid_reg.d.next = true;
            self.state.d.next = self.st_idle.val();
        }
        if self.start.val() {
            self.req_pc.d.next = self.pc_count.val();
            self.req_period.d.next = self.et_period.val();
            self.req_et_neg.d.next = self.et_negative.val();
            self.req_et_valid.d.next = self.et_valid.val();
            self.req_m.d.next = self.mt_m.val();
            self.req_t.d.next = self.mt_t.val();
            self.req_mt_neg.d.next = self.mt_negative.val();
            self.req_dt.d.next = self.cfg_dt.val();
            self.req_shift.d.next = self.mode_shift.val();
            self.pending.d.next = true;
        }
        if self.reset.val() {
            self.pending.d.next = false;
            self.state.d.next = self.st_idle.val();
            self.valid_reg.d.next = false;
            self.et_rounding.d.next = false;
            self.out_pc.d.next = self.s_zero.val();
            self.out_et.d.next = self.s_zero.val();
            self.out_mt.d.next = self.s_zero.val();
        }
        self.speed_pc.next = self.out_pc.q.val();
        self.speed_et.next = self.out_et.q.val();
        self.speed_mt.next = self.out_mt.q.val();
        self.valid.next = self.valid_reg.q.val();
        self.busy.next = self.pending.q.val() | (self.state.q.val() != self.st_idle.val());
    }
}

/// The Verilog of a `BaselineSpeeds<N, F, S>` with its top module named `module_name`.
pub fn baseline_speeds_verilog<const N: usize, const F: usize, const S: usize>(
    module_name: &str,
) -> String {
    crate::verilog::default_block_verilog::<BaselineSpeeds<N, F, S>>(module_name)
}
