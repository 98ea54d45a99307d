// SPDX-License-Identifier: MIT OR Apache-2.0
//! Corrected M/T speed (issue 4): the M/T counter's m steps in t cycles, corrected by the
//! eccentricity correction δ of the same span ([`EccDelta`](crate::ecc::ecc_delta)), as a signed
//! fixed-point speed in the format of `speed_mt` of [`BaselineSpeeds`](crate::BaselineSpeeds):
//! speed_mtc = ±round((m − δ)·dt·2^(F−s)/t), by one sequential shift-add multiplier and one
//! sequential restoring divider. A standalone block; its bit-true model is
//! [`golden::ecc::ecc_mt_speed::EccMtSpeedModel`], whose module docs state the value, the rounding
//! rule, the corner cases, the hardware algorithm (restated on integers and proven equal to
//! the exact rule by the golden tests) and the timing this block implements.
//!
//! # Generation parameters
//!
//! | parameter | meaning | range |
//! |---|---|---|
//! | `N` | counter width: `mt_m`, `mt_t`, `cfg_dt` | 8..=32 |
//! | `F` | fractional bits of the speed | 2..=24 (the core uses 16) |
//! | `S` | must be N + F + 1: width of `speed_mtc` | derived |
//! | `C` | must be [`corrected_width`]`(N)`: width of the corrected count c = m·2^16 − D, 40 for N ≤ 23, N + 17 above | derived |
//!
//! Stable Rust cannot compute the derived widths from generic `N` and `F`, so they are
//! parameters too, checked at compile time. Name the type with
//! [`ecc_mt_speed_type!`](crate::ecc_mt_speed_type): `ecc_mt_speed_type!(24, 16)` is
//! `EccMtSpeed<24, 16, 41, 41>`, `ecc_mt_speed_type!(8, 16)` is `EccMtSpeed<8, 16, 25, 40>`.
//!
//! # Ports
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock` | in | 1 | clock; everything happens at its rising edge |
//! | `reset` | in | 1 | synchronous, active high; wins over `start` |
//! | `start` | in | 1 | request a computation; latches every input below |
//! | `mt_m` | in | N | M/T: decoder steps m, unsigned ([`MtCounter`](crate::MtCounter) `m`) |
//! | `mt_t` | in | N | M/T: clock cycles t, unsigned ([`MtCounter`](crate::MtCounter) `t`) |
//! | `mt_negative` | in | 1 | M/T direction: 1 = reverse |
//! | `ecc_delta` | in | 40 | δ, the correction of the span, decoder steps, two's complement with 16 fractional bits ([`golden::ecc::ecc_delta::DELTA_BITS`], [`golden::ecc::ecc_delta::DELTA_FRAC_BITS`]) |
//! | `cfg_dt` | in | N | window dt, clock cycles, unsigned (0 counts as 1) |
//! | `mode_shift` | in | 2 | log2 of the decoding multiplier: 0 = x1, 1 = x2, 2 = x4 (3 counts as 2) |
//! | `speed_mtc` | out | N+F+1 | ±round((m − δ)·dt·2^(F−s)/t), units of 2^−F ω_lim (one line per dt); held |
//! | `valid` | out | 1 | one cycle: `speed_mtc` was just written |
//! | `busy` | out | 1 | a computation runs or a request is pending |
//!
//! `speed_mtc` is two's complement Q(N).F, the value is `raw · 2^−F` ω_lim. The magnitude is
//! rounded to nearest, ties away from zero, then the sign is applied: error ≤ 2^−(F+1) ω_lim.
//! Corner cases: m = 0 or t = 0 → 0 (as `speed_mt`); m − δ ≤ 0 → 0; a magnitude above
//! 2^(N+F) − 1 saturates at ±(2^(N+F) − 1), never wraps. With δ = 0 the output equals
//! `speed_mt` of [`BaselineSpeeds`](crate::BaselineSpeeds) bit for bit.
//!
//! # Timing
//!
//! A `start` sampled at edge k while idle gives `valid` after edge k + L, with
//! L = N + S + 3 = 2N + F + 4 ([`golden::ecc::ecc_mt_speed::latency_cycles`]; 68 for N = 24,
//! F = 16), whatever the operands. `busy` is high after edges k … k + L − 1. A `start`
//! while busy latches its inputs into the one-deep request register (replacing a request
//! that has not begun) and is served at the edge after the current `valid`, so the values of
//! the last start are always computed; starts at least L cycles apart each get their own
//! result, L cycles later. `reset` (synchronous) wins: output 0, `valid` and `busy` 0, any
//! computation or request abandoned.
//!
//! # Datapath
//!
//! State register IDLE → MUL ×N → SETUP → DIV ×S → FINISH → IDLE:
//!
//! * **Start** (any state): the request register takes c = m·2^16 − D (C bits: m shifted in
//!   at the top of C bits and shifted down to weight 2^16, minus D sign-extended to C bits,
//!   wrapping), dt with 0 replaced by 1, t, the sign, s decoded into two flags, and a zero
//!   flag: m = 0, t = 0, or c ≤ 0, detected as "D ≥ 0 and m·2^16 ≤ D": the borrow of the
//!   same subtraction (read off the top bits of its operands and difference) or a zero
//!   difference (the wrapped difference is exact whenever c > 0).
//! * **Take** (IDLE with a request pending): multiplicand ← c, Q ← dt, A ← 0, den ← t.
//! * **MUL ×N**: shift-add, least significant bit first: if Q's bit 0 is set, A + c (C bits,
//!   the carry read off the operands' and the sum's top bits), then {carry, A, Q} shifts
//!   right by one; after N steps {A, Q} = c·dt. No N×C multiplier (iCE40 has no DSP).
//! * **SETUP**: the divider is loaded for q = ⌊c·dt·2^(F+1−s)/(t·2^16)⌋: the partial
//!   remainder R (N bits) with A >> (16 + s), and the S-bit register `dq` with the bits of
//!   c·dt below that, top-aligned (Q shifted in at the top, then A's low 16 + s bits; what
//!   does not fit falls off the bottom). The saturation flag is A >> (16 + s) ≥ t (checked as
//!   "bits from N up non-zero, or the low N bits ≥ t").
//! * **DIV ×S**: restoring steps: the top bit of `dq` comes down into 2R + b, which is
//!   compared with t by the borrow of one N-bit subtraction (R's top bit is its carry:
//!   [`DivStep`](crate::arith::div_step::DivStep)), and
//!   the quotient bit goes in at the bottom; after S steps `dq` = q.
//! * **FINISH**: round and sign with one S-bit adder — h = q >> 1, r = q & 1 (dropped when q
//!   is all ones, which would round past the format); saturation: h = 2^(N+F) − 1, r = 0;
//!   zero: h = 0, r = 0; `speed_mtc` ← (h, or !h if negative) + (r xor negative) — and
//!   `valid`.
//!
//! Widths never change inside an expression (rust-hdl emits literals 32 bits wide and casts
//! as masks that Verilator flags): values are widened and narrowed by shift-in loops (wires
//! after synthesis) and every constant is a `Constant` of its operand's width.
//!
//! # Resources
//!
//! Registers: the request (C + 2N + 5), working flags (5), the multiplier (2C + N), the
//! divider (2N + S), the output (S + 1), a 6-bit step counter and a 3-bit state: 3C + 5N +
//! 2S + 20 = 345 for N = 24, F = 16 (C = S = 41). Adders: the C-bit corrected-count
//! subtraction at the input, the multiplier's C-bit add, the divider's N-bit trial
//! subtraction and N-bit saturation comparison, the S-bit round-and-sign adder.
//! yosys 0.23 `synth_ice40 -top ecc_mt_speed; stat` on `ecc_mt_speed_verilog::<24, 16, 41,
//! 41>` maps the block to 345 flip-flops, 620 SB_LUT4 and 169 SB_CARRY (N = 8, F = 16:
//! 230, 370 and 119; `BaselineSpeeds` at N = 24: 501, 642 and 118).

use rust_hdl::prelude::*;

/// Width of the step counter: it holds max(N, S) − 1 ≤ 56.
const COUNT_BITS: usize = 6;
/// Width of the state register.
const STATE_BITS: usize = 3;
/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;
/// Width of `ecc_delta`.
const DELTA_W: usize = golden::ecc::ecc_delta::DELTA_BITS as usize;
/// Fractional bits of `ecc_delta`.
const DELTA_G: usize = golden::ecc::ecc_delta::DELTA_FRAC_BITS as usize;

/// C for counter width `n`: the width of the corrected count c = m·2^16 − D
/// ([`golden::ecc::ecc_mt_speed::corrected_bits`]): 40 for n ≤ 23, n + 17 above.
pub const fn corrected_width(n: usize) -> usize {
    golden::ecc::ecc_mt_speed::corrected_bits(n as u32) as usize
}

/// The `EccMtSpeed` type for counter width `$n` and `$f` fractional bits (literals or
/// constants), with the derived widths filled in: `ecc_mt_speed_type!(24, 16)` is
/// `EccMtSpeed<24, 16, 41, 41>`.
#[macro_export]
macro_rules! ecc_mt_speed_type {
    ($n:expr, $f:expr) => {
        $crate::ecc::ecc_mt_speed::EccMtSpeed<
            { $n },
            { $f },
            { $n + $f + 1 },
            { $crate::ecc::ecc_mt_speed::corrected_width($n) },
        >
    };
}

/// Corrected M/T speed: ±round((m − δ)·dt·2^(F−s)/t) as signed Q(N).F fixed point.
#[derive(LogicBlock)]
pub struct EccMtSpeed<const N: usize, const F: usize, const S: usize, const C: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset (wins over `start`).
    pub reset: Signal<In, Bit>,
    /// Request a computation; latches every input.
    pub start: Signal<In, Bit>,
    /// M/T: decoder steps m (unsigned).
    pub mt_m: Signal<In, Bits<N>>,
    /// M/T: clock cycles t (unsigned).
    pub mt_t: Signal<In, Bits<N>>,
    /// M/T direction: 1 = reverse.
    pub mt_negative: Signal<In, Bit>,
    /// δ: correction of the span, decoder steps, two's complement, 16 fractional bits.
    pub ecc_delta: Signal<In, Bits<DELTA_W>>,
    /// Window dt, clock cycles (0 counts as 1).
    pub cfg_dt: Signal<In, Bits<N>>,
    /// log2 of the decoding multiplier (x1, x2, x4; 3 counts as 2).
    pub mode_shift: Signal<In, Bits<2>>,
    /// Corrected M/T speed, Q(N).F two's complement, units of ω_lim (one line per dt).
    pub speed_mtc: Signal<Out, Bits<S>>,
    /// One-cycle strobe: `speed_mtc` was just written.
    pub valid: Signal<Out, Bit>,
    /// A computation runs or a request is pending.
    pub busy: Signal<Out, Bit>,
    // Request register.
    /// c = m·2^16 − D (C bits, wrapped; exact unless `req_zero`).
    req_c: DFF<Bits<C>>,
    /// The result is 0: m = 0, t = 0 or c ≤ 0.
    req_zero: DFF<Bit>,
    req_t: DFF<Bits<N>>,
    /// dt, 0 replaced by 1.
    req_dt: DFF<Bits<N>>,
    req_neg: DFF<Bit>,
    /// s ≥ 1.
    req_sh1: DFF<Bit>,
    /// s ≥ 2.
    req_sh2: DFF<Bit>,
    pending: DFF<Bit>,
    // Working flags.
    w_neg: DFF<Bit>,
    w_zero: DFF<Bit>,
    w_sh1: DFF<Bit>,
    w_sh2: DFF<Bit>,
    /// The preload was not below t: saturate.
    w_sat: DFF<Bit>,
    // Sequencer.
    state: DFF<Bits<STATE_BITS>>,
    count: DFF<Bits<COUNT_BITS>>,
    // Multiplier: {A, Q} = c·dt after N steps; md = c.
    mul_md: DFF<Bits<C>>,
    mul_a: DFF<Bits<C>>,
    mul_q: DFF<Bits<N>>,
    // Divider.
    part_rem: DFF<Bits<N>>,
    /// t.
    den: DFF<Bits<N>>,
    /// Numerator bits out at the top, quotient bits in at the bottom.
    dq: DFF<Bits<S>>,
    // Result.
    out_speed: DFF<Bits<S>>,
    valid_reg: DFF<Bit>,
    // Combinational: the request.
    /// m at the top of C bits.
    m_top: Signal<Local, Bits<C>>,
    /// m·2^16 in C bits.
    m_scaled: Signal<Local, Bits<C>>,
    /// Bit 39 of `ecc_delta`: δ < 0.
    delta_sign: Signal<Local, Bit>,
    /// D sign-extended to C bits.
    delta_ext: Signal<Local, Bits<C>>,
    /// m·2^16 − D, C bits, wrapping.
    corrected: Signal<Local, Bits<C>>,
    m_scaled_msb: Signal<Local, Bit>,
    delta_ext_msb: Signal<Local, Bit>,
    corrected_msb: Signal<Local, Bit>,
    /// m·2^16 < D as unsigned C-bit numbers: the borrow of `corrected`.
    corrected_borrow: Signal<Local, Bit>,
    /// c ≤ 0.
    non_positive: Signal<Local, Bit>,
    dt_in: Signal<Local, Bits<N>>,
    /// Idle with a request pending: take it.
    take: Signal<Local, Bit>,
    // Multiplier step.
    /// Bit 0 of Q: add c in this step.
    mul_q0: Signal<Local, Bit>,
    mul_sum: Signal<Local, Bits<C>>,
    mul_a_msb: Signal<Local, Bit>,
    mul_md_msb: Signal<Local, Bit>,
    mul_sum_msb: Signal<Local, Bit>,
    mul_carry: Signal<Local, Bit>,
    // Divider set-up.
    /// A >> 16.
    a_frac: Signal<Local, Bits<C>>,
    /// A >> (16 + s): the preload.
    pre: Signal<Local, Bits<C>>,
    /// pre >> N: non-zero means pre ≥ 2^N > t.
    pre_hi: Signal<Local, Bits<C>>,
    load_rem: Signal<Local, Bits<N>>,
    load_dq: Signal<Local, Bits<S>>,
    // Divider step.
    /// One restoring division step at N bits.
    div: crate::arith::div_step::DivStep<N>,
    fits: Signal<Local, Bit>,
    next_rem: Signal<Local, Bits<N>>,
    // Round and sign.
    /// Quotient >> 1 (or a special value).
    half: Signal<Local, Bits<S>>,
    /// Quotient bit 0: the rounding increment.
    round_bit: Signal<Local, Bit>,
    addend: Signal<Local, Bits<S>>,
    rounded: Signal<Local, Bits<S>>,
    // Constants, each of the width it is used at.
    n_zero: Constant<Bits<N>>,
    n_one: Constant<Bits<N>>,
    /// 2^(N−1).
    n_msb: Constant<Bits<N>>,
    c_zero: Constant<Bits<C>>,
    c_one: Constant<Bits<C>>,
    /// 2^(C−1).
    c_msb: Constant<Bits<C>>,
    d_zero: Constant<Bits<DELTA_W>>,
    /// 2^39: the sign bit of `ecc_delta`.
    d_msb: Constant<Bits<DELTA_W>>,
    s_zero: Constant<Bits<S>>,
    s_one: Constant<Bits<S>>,
    /// 2^(S−1).
    s_msb: Constant<Bits<S>>,
    /// 2^(N+F) − 1: the saturated magnitude.
    s_max: Constant<Bits<S>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    /// 16: δ's fractional bits.
    sh_frac: Constant<Bits<SHIFT_BITS>>,
    /// N.
    sh_n: Constant<Bits<SHIFT_BITS>>,
    /// C − N − 16: from m at the top of C bits down to weight 2^16.
    sh_m: Constant<Bits<SHIFT_BITS>>,
    mode_zero: Constant<Bits<2>>,
    /// Bit 1 of `mode_shift`: s = 2.
    mode_two: Constant<Bits<2>>,
    count_zero: Constant<Bits<COUNT_BITS>>,
    count_one: Constant<Bits<COUNT_BITS>>,
    /// N − 1: loaded at the take edge.
    count_mul: Constant<Bits<COUNT_BITS>>,
    /// S − 1: loaded at SETUP.
    count_div: Constant<Bits<COUNT_BITS>>,
    st_idle: Constant<Bits<STATE_BITS>>,
    st_mul: Constant<Bits<STATE_BITS>>,
    st_setup: Constant<Bits<STATE_BITS>>,
    st_div: Constant<Bits<STATE_BITS>>,
    st_finish: Constant<Bits<STATE_BITS>>,
}

impl<const N: usize, const F: usize, const S: usize, const C: usize> EccMtSpeed<N, F, S, C> {
    const PARAMS_OK: () = {
        assert!(N >= 8 && N <= 32, "EccMtSpeed supports N in 8..=32");
        assert!(F >= 2 && F <= 24, "EccMtSpeed supports F in 2..=24");
        assert!(S == N + F + 1, "EccMtSpeed needs S = N + F + 1");
        assert!(
            C == corrected_width(N),
            "EccMtSpeed needs C = corrected_width(N) (40 for N <= 23, N + 17 above)"
        );
    };
}

impl<const N: usize, const F: usize, const S: usize, const C: usize> Default
    for EccMtSpeed<N, F, S, C>
{
    fn default() -> Self {
        let () = Self::PARAMS_OK;
        let c = |v: usize| -> u64 { v.try_into().unwrap() };
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            mt_m: Default::default(),
            mt_t: Default::default(),
            mt_negative: Default::default(),
            ecc_delta: Default::default(),
            cfg_dt: Default::default(),
            mode_shift: Default::default(),
            speed_mtc: Default::default(),
            valid: Default::default(),
            busy: Default::default(),
            req_c: Default::default(),
            req_zero: Default::default(),
            req_t: Default::default(),
            req_dt: Default::default(),
            req_neg: Default::default(),
            req_sh1: Default::default(),
            req_sh2: Default::default(),
            pending: Default::default(),
            w_neg: Default::default(),
            w_zero: Default::default(),
            w_sh1: Default::default(),
            w_sh2: Default::default(),
            w_sat: Default::default(),
            state: Default::default(),
            count: Default::default(),
            mul_md: Default::default(),
            mul_a: Default::default(),
            mul_q: Default::default(),
            part_rem: Default::default(),
            den: Default::default(),
            dq: Default::default(),
            out_speed: Default::default(),
            valid_reg: Default::default(),
            m_top: Default::default(),
            m_scaled: Default::default(),
            delta_sign: Default::default(),
            delta_ext: Default::default(),
            corrected: Default::default(),
            m_scaled_msb: Default::default(),
            delta_ext_msb: Default::default(),
            corrected_msb: Default::default(),
            corrected_borrow: Default::default(),
            non_positive: Default::default(),
            dt_in: Default::default(),
            take: Default::default(),
            mul_q0: Default::default(),
            mul_sum: Default::default(),
            mul_a_msb: Default::default(),
            mul_md_msb: Default::default(),
            mul_sum_msb: Default::default(),
            mul_carry: Default::default(),
            a_frac: Default::default(),
            pre: Default::default(),
            pre_hi: Default::default(),
            load_rem: Default::default(),
            load_dq: Default::default(),
            div: Default::default(),
            fits: Default::default(),
            next_rem: Default::default(),
            half: Default::default(),
            round_bit: Default::default(),
            addend: Default::default(),
            rounded: Default::default(),
            n_zero: Constant::new(0.into()),
            n_one: Constant::new(1.into()),
            n_msb: Constant::new((1u64 << (N - 1)).into()),
            c_zero: Constant::new(0.into()),
            c_one: Constant::new(1.into()),
            c_msb: Constant::new((1u64 << (C - 1)).into()),
            d_zero: Constant::new(0.into()),
            d_msb: Constant::new((1u64 << (DELTA_W - 1)).into()),
            s_zero: Constant::new(0.into()),
            s_one: Constant::new(1.into()),
            s_msb: Constant::new((1u64 << (S - 1)).into()),
            s_max: Constant::new(((1u64 << (N + F)) - 1).into()),
            sh_one: Constant::new(1.into()),
            sh_frac: Constant::new(c(DELTA_G).into()),
            sh_n: Constant::new(c(N).into()),
            sh_m: Constant::new(c(C - N - DELTA_G).into()),
            mode_zero: Constant::new(0.into()),
            mode_two: Constant::new(2.into()),
            count_zero: Constant::new(0.into()),
            count_one: Constant::new(1.into()),
            count_mul: Constant::new(c(N - 1).into()),
            count_div: Constant::new(c(S - 1).into()),
            st_idle: Constant::new(0.into()),
            st_mul: Constant::new(1.into()),
            st_setup: Constant::new(2.into()),
            st_div: Constant::new(3.into()),
            st_finish: Constant::new(4.into()),
        }
    }
}

impl<const N: usize, const F: usize, const S: usize, const C: usize> Logic
    for EccMtSpeed<N, F, S, C>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, req_c, req_zero, req_t, req_dt, req_neg, req_sh1, req_sh2, pending, w_neg,
            w_zero, w_sh1, w_sh2, w_sat, state, count, mul_md, mul_a, mul_q, part_rem, den, dq,
            out_speed, valid_reg
        );
        self.take.next = (self.state.q.val() == self.st_idle.val()) & self.pending.q.val();

        // The request: c = m·2^16 − D in C bits. m is shifted in at the top of C bits and
        // shifted down to weight 2^16; D's 40 bits are shifted in at the top, then C − 40
        // copies of its sign bit (sign extension).
        self.m_top.next = self.c_zero.val();
        for i in 0..N {
            if self.mt_m.val().get_bit(i) {
                self.m_top.next = (self.m_top.val() >> self.sh_one.val()) | self.c_msb.val();
            } else {
                self.m_top.next = self.m_top.val() >> self.sh_one.val();
            }
        }
        self.m_scaled.next = self.m_top.val() >> self.sh_m.val();
        self.delta_sign.next = (self.ecc_delta.val() & self.d_msb.val()) != self.d_zero.val();
        self.delta_ext.next = self.c_zero.val();
        for i in 0..DELTA_W {
            if self.ecc_delta.val().get_bit(i) {
                self.delta_ext.next =
                    (self.delta_ext.val() >> self.sh_one.val()) | self.c_msb.val();
            } else {
                self.delta_ext.next = self.delta_ext.val() >> self.sh_one.val();
            }
        }
        for _i in 0..(C - DELTA_W) {
            if self.delta_sign.val() {
                self.delta_ext.next =
                    (self.delta_ext.val() >> self.sh_one.val()) | self.c_msb.val();
            } else {
                self.delta_ext.next = self.delta_ext.val() >> self.sh_one.val();
            }
        }
        self.corrected.next = self.m_scaled.val() - self.delta_ext.val();
        // c ≤ 0 iff D ≥ 0 and m·2^16 ≤ D: the borrow of the subtraction (read off the top
        // bits of the operands and the difference) or a zero difference.
        self.m_scaled_msb.next = (self.m_scaled.val() & self.c_msb.val()) != self.c_zero.val();
        self.delta_ext_msb.next = (self.delta_ext.val() & self.c_msb.val()) != self.c_zero.val();
        self.corrected_msb.next = (self.corrected.val() & self.c_msb.val()) != self.c_zero.val();
        self.corrected_borrow.next = ((!self.m_scaled_msb.val()) & self.delta_ext_msb.val())
            | ((!(self.m_scaled_msb.val() ^ self.delta_ext_msb.val())) & self.corrected_msb.val());
        self.non_positive.next = (!self.delta_sign.val())
            & (self.corrected_borrow.val() | (self.corrected.val() == self.c_zero.val()));
        self.dt_in.next = self.cfg_dt.val();
        if self.cfg_dt.val() == self.n_zero.val() {
            self.dt_in.next = self.n_one.val();
        }

        // Multiplier step: A + (Q bit 0 ? c : 0) with its carry, from the top bits.
        self.mul_a_msb.next = (self.mul_a.q.val() & self.c_msb.val()) != self.c_zero.val();
        self.mul_md_msb.next = (self.mul_md.q.val() & self.c_msb.val()) != self.c_zero.val();
        self.mul_q0.next = (self.mul_q.q.val() & self.n_one.val()) != self.n_zero.val();
        self.mul_sum.next = self.mul_a.q.val();
        if self.mul_q0.val() {
            self.mul_sum.next = self.mul_a.q.val() + self.mul_md.q.val();
        }
        self.mul_sum_msb.next = (self.mul_sum.val() & self.c_msb.val()) != self.c_zero.val();
        self.mul_carry.next = self.mul_q0.val()
            & ((self.mul_a_msb.val() & self.mul_md_msb.val())
                | ((self.mul_a_msb.val() | self.mul_md_msb.val()) & (!self.mul_sum_msb.val())));

        // Divider set-up from {A, Q} = c·dt: preload A >> (16 + s); dq gets Q at its top,
        // then A's low 16 + s bits shifted in above it (what does not fit falls off).
        self.a_frac.next = self.mul_a.q.val() >> self.sh_frac.val();
        self.pre.next = self.a_frac.val();
        if self.w_sh1.q.val() {
            self.pre.next = self.a_frac.val() >> self.sh_one.val();
        }
        if self.w_sh2.q.val() {
            self.pre.next = self.pre.val() >> self.sh_one.val();
        }
        self.pre_hi.next = self.pre.val() >> self.sh_n.val();
        self.load_rem.next = self.n_zero.val();
        for i in 0..N {
            if self.pre.val().get_bit(i) {
                self.load_rem.next = (self.load_rem.val() >> self.sh_one.val()) | self.n_msb.val();
            } else {
                self.load_rem.next = self.load_rem.val() >> self.sh_one.val();
            }
        }
        self.load_dq.next = self.s_zero.val();
        for i in 0..N {
            if self.mul_q.q.val().get_bit(i) {
                self.load_dq.next = (self.load_dq.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.load_dq.next = self.load_dq.val() >> self.sh_one.val();
            }
        }
        for i in 0..DELTA_G {
            if self.mul_a.q.val().get_bit(i) {
                self.load_dq.next = (self.load_dq.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.load_dq.next = self.load_dq.val() >> self.sh_one.val();
            }
        }
        if self.w_sh1.q.val() {
            // A's bit 16.
            if (self.a_frac.val() & self.c_one.val()) != self.c_zero.val() {
                self.load_dq.next = (self.load_dq.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.load_dq.next = self.load_dq.val() >> self.sh_one.val();
            }
        }
        if self.w_sh2.q.val() {
            // A's bit 17.
            if (self.a_frac.val() & (self.c_one.val() << self.sh_one.val())) != self.c_zero.val() {
                self.load_dq.next = (self.load_dq.val() >> self.sh_one.val()) | self.s_msb.val();
            } else {
                self.load_dq.next = self.load_dq.val() >> self.sh_one.val();
            }
        }

        // One restoring division step (DivStep): bring down the next numerator bit,
        // subtract if 2R + b ≥ den.
        self.div.rem.next = self.part_rem.q.val();
        self.div.bit_in.next = (self.dq.q.val() & self.s_msb.val()) != self.s_zero.val();
        self.div.den.next = self.den.q.val();
        self.fits.next = self.div.fits.val();
        self.next_rem.next = self.div.next_rem.val();

        // Round and sign with one adder: with q = dq, h = q >> 1 and r = q & 1, the result
        // is (h, or ~h if negative) + (r xor negative). q all ones would round past the
        // format: r is dropped (h is then the maximum). Saturation: h = max, r = 0; zero:
        // h = 0, r = 0.
        self.half.next = self.dq.q.val() >> self.sh_one.val();
        self.round_bit.next =
            ((self.dq.q.val() & self.s_one.val()) != self.s_zero.val()) & (!self.dq.q.val().all());
        if self.w_sat.q.val() {
            self.half.next = self.s_max.val();
            self.round_bit.next = false;
        }
        if self.w_zero.q.val() {
            self.half.next = self.s_zero.val();
            self.round_bit.next = false;
        }
        self.addend.next = self.half.val();
        if self.w_neg.q.val() {
            self.addend.next = !self.half.val();
        }
        self.rounded.next = self.addend.val();
        if self.round_bit.val() ^ self.w_neg.q.val() {
            self.rounded.next = self.addend.val() + self.s_one.val();
        }

        // Sequencer.
        self.valid_reg.d.next = false;
        if self.take.val() {
            self.mul_md.d.next = self.req_c.q.val();
            self.mul_a.d.next = self.c_zero.val();
            self.mul_q.d.next = self.req_dt.q.val();
            self.den.d.next = self.req_t.q.val();
            self.w_neg.d.next = self.req_neg.q.val();
            self.w_zero.d.next = self.req_zero.q.val();
            self.w_sh1.d.next = self.req_sh1.q.val();
            self.w_sh2.d.next = self.req_sh2.q.val();
            self.count.d.next = self.count_mul.val();
            self.state.d.next = self.st_mul.val();
            self.pending.d.next = false;
        }
        if self.state.q.val() == self.st_mul.val() {
            self.mul_a.d.next = self.mul_sum.val() >> self.sh_one.val();
            if self.mul_carry.val() {
                self.mul_a.d.next = (self.mul_sum.val() >> self.sh_one.val()) | self.c_msb.val();
            }
            self.mul_q.d.next = self.mul_q.q.val() >> self.sh_one.val();
            if (self.mul_sum.val() & self.c_one.val()) != self.c_zero.val() {
                self.mul_q.d.next = (self.mul_q.q.val() >> self.sh_one.val()) | self.n_msb.val();
            }
            self.count.d.next = self.count.q.val() - self.count_one.val();
            if self.count.q.val() == self.count_zero.val() {
                self.state.d.next = self.st_setup.val();
            }
        }
        if self.state.q.val() == self.st_setup.val() {
            self.part_rem.d.next = self.load_rem.val();
            self.dq.d.next = self.load_dq.val();
            self.w_sat.d.next = (self.pre_hi.val() != self.c_zero.val())
                | (self.load_rem.val() >= self.den.q.val());
            self.count.d.next = self.count_div.val();
            self.state.d.next = self.st_div.val();
        }
        if self.state.q.val() == self.st_div.val() {
            self.part_rem.d.next = self.next_rem.val();
            self.dq.d.next = self.dq.q.val() << self.sh_one.val();
            if self.fits.val() {
                self.dq.d.next = (self.dq.q.val() << self.sh_one.val()) | self.s_one.val();
            }
            self.count.d.next = self.count.q.val() - self.count_one.val();
            if self.count.q.val() == self.count_zero.val() {
                self.state.d.next = self.st_finish.val();
            }
        }
        if self.state.q.val() == self.st_finish.val() {
            self.out_speed.d.next = self.rounded.val();
            self.valid_reg.d.next = true;
            self.state.d.next = self.st_idle.val();
        }
        if self.start.val() {
            self.req_c.d.next = self.corrected.val();
            self.req_zero.d.next = (self.mt_m.val() == self.n_zero.val())
                | (self.mt_t.val() == self.n_zero.val())
                | self.non_positive.val();
            self.req_t.d.next = self.mt_t.val();
            self.req_dt.d.next = self.dt_in.val();
            self.req_neg.d.next = self.mt_negative.val();
            self.req_sh1.d.next = self.mode_shift.val() != self.mode_zero.val();
            self.req_sh2.d.next =
                (self.mode_shift.val() & self.mode_two.val()) != self.mode_zero.val();
            self.pending.d.next = true;
        }
        if self.reset.val() {
            self.pending.d.next = false;
            self.state.d.next = self.st_idle.val();
            self.valid_reg.d.next = false;
            self.out_speed.d.next = self.s_zero.val();
        }
        self.speed_mtc.next = self.out_speed.q.val();
        self.valid.next = self.valid_reg.q.val();
        self.busy.next = self.pending.q.val() | (self.state.q.val() != self.st_idle.val());
    }
}

/// The Verilog of an `EccMtSpeed<N, F, S, C>` with its top module named `module_name`.
pub fn ecc_mt_speed_verilog<const N: usize, const F: usize, const S: usize, const C: usize>(
    module_name: &str,
) -> String {
    crate::verilog::default_block_verilog::<EccMtSpeed<N, F, S, C>>(module_name)
}
