// SPDX-License-Identifier: MIT OR Apache-2.0
//! Wishbone slave of the eccentricity window of `encspeed_ecc_wb`: drives `encspeed_ecc`'s
//! `ecc_c`, `ecc_d` and `ident_arm`, and reads its corrected speeds and identification
//! results. The map and its behaviour are specified in [`golden::bus::ecc_regmap`] (offsets,
//! fields and reset values taken from there at construction); the cycle model is
//! [`golden::bus::ecc_regs::EccRegsModel`].
//!
//! # Generation parameter
//! `S` = `speed_bits` (11..=64): `speed_mtc`, `speed_n3c`. The identification widths are
//! `encspeed_ecc`'s fixed ones (count 17, periods 32, line numbers 16, sums 72).
//!
//! # Ports
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock`, `reset` | in | 1 | the core's clock; synchronous active-high reset |
//! | `wb_cyc_i`, `wb_stb_i`, `wb_we_i` | in | 1 | Wishbone; `wb_stb_i` only for the window's offsets (the top routes it) |
//! | `wb_adr_i` | in | 8 | byte address; bits 1:0 ignored |
//! | `wb_dat_i`, `wb_sel_i` | in | 32, 4 | write data, byte lanes |
//! | `wb_dat_o` | out | 32 | read data, valid with `wb_ack_o` (0 otherwise) |
//! | `wb_ack_o` | out | 1 | one cycle after the request edge |
//! | `irq` | out | 1 | (`ECC_IRQ_STATUS` & `ECC_IRQ_ENABLE`) ≠ 0 |
//! | `ecc_c`, `ecc_d` | out | 32 | the coefficients last loaded by `ECC_CTRL.LOAD` |
//! | `ident_arm` | out | 1 | the cycle after a write of 1 to `ECC_CTRL.IDENT_ARM` |
//! | `speed_mtc`, `speed_n3c` | in | S | corrected speeds (two's complement) |
//! | `mtc_strobe`, `n3c_strobe`, `ident_done`, `ident_overflow` | in | 1 | `encspeed_ecc` outputs |
//! | `ident_count` | in | 17 | |
//! | `ident_t_min`, `ident_t_max` | in | 32 | |
//! | `ident_p_min`, `ident_p_max` | in | 16 | |
//! | `ident_sum_t`, `ident_sum_sin`, `ident_sum_cos` | in | 72 | two's complement |
//!
//! Every output is a register or a function of registers only.
//!
//! # Implementation
//! As `crate::WbRegs`: registers are 32 bits with reserved bits held at 0; narrow inputs are
//! widened by shifting their bits in at the top and shifting down by a constant (a cast
//! would be emitted as a mask of another width), and bit slices take literal offsets only.

use golden::bus::ecc_regmap::{self as m, ECC_CTRL, ECC_IRQ_STATUS, ECC_STATUS};
use golden::bus::regmap::{Access, Register, ADDR_BITS, SPAN_BYTES};
use rust_hdl::prelude::*;

/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// The eccentricity window's Wishbone slave, speeds of S bits.
#[derive(LogicBlock)]
pub struct EccRegs<const S: usize> {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Wishbone: bus cycle.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone: strobe (routed to the window's offsets by the top).
    pub wb_stb_i: Signal<In, Bit>,
    /// Wishbone: 1 write, 0 read.
    pub wb_we_i: Signal<In, Bit>,
    /// Wishbone: byte address (bits 1:0 ignored).
    pub wb_adr_i: Signal<In, Bits<ADDR_BITS>>,
    /// Wishbone: write data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Wishbone: byte lanes.
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone: read data (0 outside a read's ack cycle).
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone: acknowledge.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Interrupt request of the window, level.
    pub irq: Signal<Out, Bit>,
    /// c, Q15.16 lines (loaded).
    pub ecc_c: Signal<Out, Bits<32>>,
    /// d, Q15.16 lines (loaded).
    pub ecc_d: Signal<Out, Bits<32>>,
    /// One cycle: arm the identification.
    pub ident_arm: Signal<Out, Bit>,
    /// Corrected M/T speed.
    pub speed_mtc: Signal<In, Bits<S>>,
    /// One cycle: `speed_mtc` written.
    pub mtc_strobe: Signal<In, Bit>,
    /// Corrected n3.
    pub speed_n3c: Signal<In, Bits<S>>,
    /// One cycle: `speed_n3c` written.
    pub n3c_strobe: Signal<In, Bit>,
    /// Identification results complete.
    pub ident_done: Signal<In, Bit>,
    /// Too many lines between the index pulses.
    pub ident_overflow: Signal<In, Bit>,
    /// Lines gathered.
    pub ident_count: Signal<In, Bits<17>>,
    /// Shortest line period.
    pub ident_t_min: Signal<In, Bits<32>>,
    /// Longest line period.
    pub ident_t_max: Signal<In, Bits<32>>,
    /// Line number of the shortest period.
    pub ident_p_min: Signal<In, Bits<16>>,
    /// Line number of the longest period.
    pub ident_p_max: Signal<In, Bits<16>>,
    /// Σ T.
    pub ident_sum_t: Signal<In, Bits<72>>,
    /// Σ T·sin.
    pub ident_sum_sin: Signal<In, Bits<72>>,
    /// Σ T·cos.
    pub ident_sum_cos: Signal<In, Bits<72>>,
    // Registers.
    ack: DFF<Bit>,
    dat: DFF<Bits<32>>,
    arm: DFF<Bit>,
    stage_c: DFF<Bits<32>>,
    stage_d: DFF<Bits<32>>,
    r_ecc_c: DFF<Bits<32>>,
    r_ecc_d: DFF<Bits<32>>,
    irq_enable: DFF<Bits<32>>,
    irq_status: DFF<Bits<32>>,
    hi_mtc: DFF<Bits<32>>,
    hi_n3c: DFF<Bits<32>>,
    prev_done: DFF<Bit>,
    // Combinational.
    adr: Signal<Local, Bits<ADDR_BITS>>,
    req: Signal<Local, Bit>,
    rd: Signal<Local, Bit>,
    wr: Signal<Local, Bit>,
    lanes: Signal<Local, Bits<32>>,
    ones: Signal<Local, Bits<32>>,
    rdata: Signal<Local, Bits<32>>,
    irq_clear: Signal<Local, Bits<32>>,
    events: Signal<Local, Bits<32>>,
    x_mtc: Signal<Local, Bits<64>>,
    x_n3c: Signal<Local, Bits<64>>,
    x_count: Signal<Local, Bits<32>>,
    x_p: Signal<Local, Bits<32>>,
    x_t2: Signal<Local, Bits<32>>,
    x_s2: Signal<Local, Bits<32>>,
    x_c2: Signal<Local, Bits<32>>,
    // Offsets, from the map.
    adr_mask: Constant<Bits<ADDR_BITS>>,
    a_id: Constant<Bits<ADDR_BITS>>,
    a_version: Constant<Bits<ADDR_BITS>>,
    a_ctrl: Constant<Bits<ADDR_BITS>>,
    a_status: Constant<Bits<ADDR_BITS>>,
    a_c: Constant<Bits<ADDR_BITS>>,
    a_d: Constant<Bits<ADDR_BITS>>,
    a_irq_enable: Constant<Bits<ADDR_BITS>>,
    a_irq_status: Constant<Bits<ADDR_BITS>>,
    a_mtc_lo: Constant<Bits<ADDR_BITS>>,
    a_mtc_hi: Constant<Bits<ADDR_BITS>>,
    a_n3c_lo: Constant<Bits<ADDR_BITS>>,
    a_n3c_hi: Constant<Bits<ADDR_BITS>>,
    a_count: Constant<Bits<ADDR_BITS>>,
    a_t_min: Constant<Bits<ADDR_BITS>>,
    a_t_max: Constant<Bits<ADDR_BITS>>,
    a_p: Constant<Bits<ADDR_BITS>>,
    a_t0: Constant<Bits<ADDR_BITS>>,
    a_t1: Constant<Bits<ADDR_BITS>>,
    a_t2: Constant<Bits<ADDR_BITS>>,
    a_s0: Constant<Bits<ADDR_BITS>>,
    a_s1: Constant<Bits<ADDR_BITS>>,
    a_s2: Constant<Bits<ADDR_BITS>>,
    a_c0: Constant<Bits<ADDR_BITS>>,
    a_c1: Constant<Bits<ADDR_BITS>>,
    a_c2: Constant<Bits<ADDR_BITS>>,
    // Constant registers and field masks, from the map.
    k_id: Constant<Bits<32>>,
    k_version: Constant<Bits<32>>,
    m_coef: Constant<Bits<32>>,
    m_irq_enable: Constant<Bits<32>>,
    m_irq_w1c: Constant<Bits<32>>,
    f_arm: Constant<Bits<32>>,
    f_load: Constant<Bits<32>>,
    s_done: Constant<Bits<32>>,
    s_overflow: Constant<Bits<32>>,
    e_mtc: Constant<Bits<32>>,
    e_n3c: Constant<Bits<32>>,
    e_ident: Constant<Bits<32>>,
    // Arithmetic constants.
    lane0: Constant<Bits<32>>,
    lane1: Constant<Bits<32>>,
    lane2: Constant<Bits<32>>,
    lane3: Constant<Bits<32>>,
    z32: Constant<Bits<32>>,
    msb32: Constant<Bits<32>>,
    /// Bits 31..8: the sign extension of a sum's top byte.
    sext8: Constant<Bits<32>>,
    z64: Constant<Bits<64>>,
    msb64: Constant<Bits<64>>,
    /// Bits 63..S: the sign extension of a speed.
    sext: Constant<Bits<64>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    /// 32 − 17, 32 − 8, 64 − S: shifts from the top down to bit 0.
    sh_count: Constant<Bits<SHIFT_BITS>>,
    sh_byte: Constant<Bits<SHIFT_BITS>>,
    sh_s: Constant<Bits<SHIFT_BITS>>,
}

impl<const S: usize> EccRegs<S> {
    /// The window's slave for speeds of S bits.
    pub fn new() -> Self {
        assert!((11..=64).contains(&S), "speed_bits S = {S}: 11..=64");
        assert_eq!(SPAN_BYTES, 1 << ADDR_BITS);
        let regs = m::registers(S as u32);
        let reg = |off: u32| -> &Register { regs.iter().find(|r| r.offset == off).unwrap() };
        let a = |off: u32| -> Constant<Bits<ADDR_BITS>> { Constant::new(u64::from(off).into()) };
        let k = |v: u32| -> Constant<Bits<32>> { Constant::new(u64::from(v).into()) };
        let f = |off: u32, name: &str| k(reg(off).field(name).mask());
        let sh = |v: usize| -> Constant<Bits<SHIFT_BITS>> { Constant::new((v as u64).into()) };
        let sext = if S == 64 { 0 } else { !((1u64 << S) - 1) };
        assert_eq!(
            reg(m::ECC_C).mask_of(Access::Rw),
            reg(m::ECC_D).mask_of(Access::Rw)
        );
        Self {
            clock: Default::default(),
            reset: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_sel_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            irq: Default::default(),
            ecc_c: Default::default(),
            ecc_d: Default::default(),
            ident_arm: Default::default(),
            speed_mtc: Default::default(),
            mtc_strobe: Default::default(),
            speed_n3c: Default::default(),
            n3c_strobe: Default::default(),
            ident_done: Default::default(),
            ident_overflow: Default::default(),
            ident_count: Default::default(),
            ident_t_min: Default::default(),
            ident_t_max: Default::default(),
            ident_p_min: Default::default(),
            ident_p_max: Default::default(),
            ident_sum_t: Default::default(),
            ident_sum_sin: Default::default(),
            ident_sum_cos: Default::default(),
            ack: Default::default(),
            dat: Default::default(),
            arm: Default::default(),
            stage_c: Default::default(),
            stage_d: Default::default(),
            r_ecc_c: Default::default(),
            r_ecc_d: Default::default(),
            irq_enable: Default::default(),
            irq_status: Default::default(),
            hi_mtc: Default::default(),
            hi_n3c: Default::default(),
            prev_done: Default::default(),
            adr: Default::default(),
            req: Default::default(),
            rd: Default::default(),
            wr: Default::default(),
            lanes: Default::default(),
            ones: Default::default(),
            rdata: Default::default(),
            irq_clear: Default::default(),
            events: Default::default(),
            x_mtc: Default::default(),
            x_n3c: Default::default(),
            x_count: Default::default(),
            x_p: Default::default(),
            x_t2: Default::default(),
            x_s2: Default::default(),
            x_c2: Default::default(),
            adr_mask: Constant::new(u64::from((SPAN_BYTES - 1) & !3).into()),
            a_id: a(m::ECC_ID),
            a_version: a(m::ECC_VERSION),
            a_ctrl: a(ECC_CTRL),
            a_status: a(ECC_STATUS),
            a_c: a(m::ECC_C),
            a_d: a(m::ECC_D),
            a_irq_enable: a(m::ECC_IRQ_ENABLE),
            a_irq_status: a(ECC_IRQ_STATUS),
            a_mtc_lo: a(m::SPEED_MTC_LO),
            a_mtc_hi: a(m::SPEED_MTC_HI),
            a_n3c_lo: a(m::SPEED_N3C_LO),
            a_n3c_hi: a(m::SPEED_N3C_HI),
            a_count: a(m::IDENT_COUNT),
            a_t_min: a(m::IDENT_T_MIN),
            a_t_max: a(m::IDENT_T_MAX),
            a_p: a(m::IDENT_P),
            a_t0: a(m::IDENT_SUM_T_W0),
            a_t1: a(m::IDENT_SUM_T_W1),
            a_t2: a(m::IDENT_SUM_T_W2),
            a_s0: a(m::IDENT_SUM_SIN_W0),
            a_s1: a(m::IDENT_SUM_SIN_W1),
            a_s2: a(m::IDENT_SUM_SIN_W2),
            a_c0: a(m::IDENT_SUM_COS_W0),
            a_c1: a(m::IDENT_SUM_COS_W1),
            a_c2: a(m::IDENT_SUM_COS_W2),
            k_id: k(reg(m::ECC_ID).reset.unwrap()),
            k_version: k(reg(m::ECC_VERSION).reset.unwrap()),
            m_coef: k(reg(m::ECC_C).mask_of(Access::Rw)),
            m_irq_enable: k(reg(m::ECC_IRQ_ENABLE).mask_of(Access::Rw)),
            m_irq_w1c: k(reg(ECC_IRQ_STATUS).mask_of(Access::W1c)),
            f_arm: f(ECC_CTRL, "IDENT_ARM"),
            f_load: f(ECC_CTRL, "LOAD"),
            s_done: f(ECC_STATUS, "IDENT_DONE"),
            s_overflow: f(ECC_STATUS, "IDENT_OVERFLOW"),
            e_mtc: f(ECC_IRQ_STATUS, "MTC"),
            e_n3c: f(ECC_IRQ_STATUS, "N3C"),
            e_ident: f(ECC_IRQ_STATUS, "IDENT"),
            lane0: k(0x0000_00FF),
            lane1: k(0x0000_FF00),
            lane2: k(0x00FF_0000),
            lane3: k(0xFF00_0000),
            z32: k(0),
            msb32: k(1 << 31),
            sext8: k(0xFFFF_FF00),
            z64: Constant::new(0.into()),
            msb64: Constant::new((1u64 << 63).into()),
            sext: Constant::new(sext.into()),
            sh_one: sh(1),
            sh_count: sh(32 - 17),
            sh_byte: sh(32 - 8),
            sh_s: sh(64 - S),
        }
    }
}

impl<const S: usize> Default for EccRegs<S> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const S: usize> Logic for EccRegs<S> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, ack, dat, arm, stage_c, stage_d, r_ecc_c, r_ecc_d, irq_enable, irq_status,
            hi_mtc, hi_n3c, prev_done
        );
        // Widen the speeds to 64 bits, sign-extended: shift their bits in at the top, then
        // move them down and fill bits 63..S with the sign.
        self.x_mtc.next = self.z64.val();
        self.x_n3c.next = self.z64.val();
        for i in 0..S {
            self.x_mtc.next = self.x_mtc.val() >> self.sh_one.val();
            if self.speed_mtc.val().get_bit(i) {
                self.x_mtc.next = self.x_mtc.val() | self.msb64.val();
            }
            self.x_n3c.next = self.x_n3c.val() >> self.sh_one.val();
            if self.speed_n3c.val().get_bit(i) {
                self.x_n3c.next = self.x_n3c.val() | self.msb64.val();
            }
        }
        if (self.x_mtc.val() & self.msb64.val()) != self.z64.val() {
            self.x_mtc.next = (self.x_mtc.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x_mtc.next = self.x_mtc.val() >> self.sh_s.val();
        }
        if (self.x_n3c.val() & self.msb64.val()) != self.z64.val() {
            self.x_n3c.next = (self.x_n3c.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x_n3c.next = self.x_n3c.val() >> self.sh_s.val();
        }
        // The count (17 bits) and the two line numbers (P_MIN low, P_MAX high).
        self.x_count.next = self.z32.val();
        for i in 0..17 {
            self.x_count.next = self.x_count.val() >> self.sh_one.val();
            if self.ident_count.val().get_bit(i) {
                self.x_count.next = self.x_count.val() | self.msb32.val();
            }
        }
        self.x_count.next = self.x_count.val() >> self.sh_count.val();
        self.x_p.next = self.z32.val();
        for i in 0..16 {
            self.x_p.next = self.x_p.val() >> self.sh_one.val();
            if self.ident_p_min.val().get_bit(i) {
                self.x_p.next = self.x_p.val() | self.msb32.val();
            }
        }
        for i in 0..16 {
            self.x_p.next = self.x_p.val() >> self.sh_one.val();
            if self.ident_p_max.val().get_bit(i) {
                self.x_p.next = self.x_p.val() | self.msb32.val();
            }
        }
        // Word 2 of each sum: bits 71:64, sign-extended.
        self.x_t2.next = self.z32.val();
        self.x_s2.next = self.z32.val();
        self.x_c2.next = self.z32.val();
        for i in 64..72 {
            self.x_t2.next = self.x_t2.val() >> self.sh_one.val();
            if self.ident_sum_t.val().get_bit(i) {
                self.x_t2.next = self.x_t2.val() | self.msb32.val();
            }
            self.x_s2.next = self.x_s2.val() >> self.sh_one.val();
            if self.ident_sum_sin.val().get_bit(i) {
                self.x_s2.next = self.x_s2.val() | self.msb32.val();
            }
            self.x_c2.next = self.x_c2.val() >> self.sh_one.val();
            if self.ident_sum_cos.val().get_bit(i) {
                self.x_c2.next = self.x_c2.val() | self.msb32.val();
            }
        }
        self.x_t2.next = self.x_t2.val() >> self.sh_byte.val();
        if self.ident_sum_t.val().get_bit(71) {
            self.x_t2.next = self.x_t2.val() | self.sext8.val();
        }
        self.x_s2.next = self.x_s2.val() >> self.sh_byte.val();
        if self.ident_sum_sin.val().get_bit(71) {
            self.x_s2.next = self.x_s2.val() | self.sext8.val();
        }
        self.x_c2.next = self.x_c2.val() >> self.sh_byte.val();
        if self.ident_sum_cos.val().get_bit(71) {
            self.x_c2.next = self.x_c2.val() | self.sext8.val();
        }

        // The bus request.
        self.adr.next = self.wb_adr_i.val() & self.adr_mask.val();
        self.req.next = self.wb_cyc_i.val() & self.wb_stb_i.val() & (!self.ack.q.val());
        self.rd.next = self.req.val() & (!self.wb_we_i.val());
        self.wr.next = self.req.val() & self.wb_we_i.val();
        self.lanes.next = self.z32.val();
        if self.wb_sel_i.val().get_bit(0) {
            self.lanes.next = self.lanes.val() | self.lane0.val();
        }
        if self.wb_sel_i.val().get_bit(1) {
            self.lanes.next = self.lanes.val() | self.lane1.val();
        }
        if self.wb_sel_i.val().get_bit(2) {
            self.lanes.next = self.lanes.val() | self.lane2.val();
        }
        if self.wb_sel_i.val().get_bit(3) {
            self.lanes.next = self.lanes.val() | self.lane3.val();
        }
        self.ones.next = self.wb_dat_i.val() & self.lanes.val();

        // Read multiplexer: 0 at unmapped offsets (ECC_CTRL's pulses read 0).
        self.rdata.next = self.z32.val();
        if self.adr.val() == self.a_id.val() {
            self.rdata.next = self.k_id.val();
        }
        if self.adr.val() == self.a_version.val() {
            self.rdata.next = self.k_version.val();
        }
        if self.adr.val() == self.a_status.val() {
            if self.ident_done.val() {
                self.rdata.next = self.rdata.val() | self.s_done.val();
            }
            if self.ident_overflow.val() {
                self.rdata.next = self.rdata.val() | self.s_overflow.val();
            }
        }
        if self.adr.val() == self.a_c.val() {
            self.rdata.next = self.stage_c.q.val();
        }
        if self.adr.val() == self.a_d.val() {
            self.rdata.next = self.stage_d.q.val();
        }
        if self.adr.val() == self.a_irq_enable.val() {
            self.rdata.next = self.irq_enable.q.val();
        }
        if self.adr.val() == self.a_irq_status.val() {
            self.rdata.next = self.irq_status.q.val();
        }
        if self.adr.val() == self.a_mtc_lo.val() {
            self.rdata.next = self.x_mtc.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_mtc_hi.val() {
            self.rdata.next = self.hi_mtc.q.val();
        }
        if self.adr.val() == self.a_n3c_lo.val() {
            self.rdata.next = self.x_n3c.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_n3c_hi.val() {
            self.rdata.next = self.hi_n3c.q.val();
        }
        if self.adr.val() == self.a_count.val() {
            self.rdata.next = self.x_count.val();
        }
        if self.adr.val() == self.a_t_min.val() {
            self.rdata.next = self.ident_t_min.val();
        }
        if self.adr.val() == self.a_t_max.val() {
            self.rdata.next = self.ident_t_max.val();
        }
        if self.adr.val() == self.a_p.val() {
            self.rdata.next = self.x_p.val();
        }
        if self.adr.val() == self.a_t0.val() {
            self.rdata.next = self.ident_sum_t.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_t1.val() {
            self.rdata.next = self.ident_sum_t.val().get_bits::<32>(32);
        }
        if self.adr.val() == self.a_t2.val() {
            self.rdata.next = self.x_t2.val();
        }
        if self.adr.val() == self.a_s0.val() {
            self.rdata.next = self.ident_sum_sin.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_s1.val() {
            self.rdata.next = self.ident_sum_sin.val().get_bits::<32>(32);
        }
        if self.adr.val() == self.a_s2.val() {
            self.rdata.next = self.x_s2.val();
        }
        if self.adr.val() == self.a_c0.val() {
            self.rdata.next = self.ident_sum_cos.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_c1.val() {
            self.rdata.next = self.ident_sum_cos.val().get_bits::<32>(32);
        }
        if self.adr.val() == self.a_c2.val() {
            self.rdata.next = self.x_c2.val();
        }

        // Execute the request: ack and read data in the next cycle.
        self.ack.d.next = self.req.val();
        self.dat.d.next = self.z32.val();
        if self.rd.val() {
            self.dat.d.next = self.rdata.val();
            // A LO read latches its HI word.
            if self.adr.val() == self.a_mtc_lo.val() {
                self.hi_mtc.d.next = self.x_mtc.val().get_bits::<32>(32);
            }
            if self.adr.val() == self.a_n3c_lo.val() {
                self.hi_n3c.d.next = self.x_n3c.val().get_bits::<32>(32);
            }
        }
        self.irq_clear.next = self.z32.val();
        self.arm.d.next = false;
        if self.wr.val() {
            if self.adr.val() == self.a_ctrl.val() {
                self.arm.d.next = (self.ones.val() & self.f_arm.val()) != self.z32.val();
                // Both coefficients at once, from the staging registers before this edge.
                if (self.ones.val() & self.f_load.val()) != self.z32.val() {
                    self.r_ecc_c.d.next = self.stage_c.q.val();
                    self.r_ecc_d.d.next = self.stage_d.q.val();
                }
            }
            if self.adr.val() == self.a_c.val() {
                self.stage_c.d.next = ((self.stage_c.q.val() & (!self.lanes.val()))
                    | self.ones.val())
                    & self.m_coef.val();
            }
            if self.adr.val() == self.a_d.val() {
                self.stage_d.d.next = ((self.stage_d.q.val() & (!self.lanes.val()))
                    | self.ones.val())
                    & self.m_coef.val();
            }
            if self.adr.val() == self.a_irq_enable.val() {
                self.irq_enable.d.next = ((self.irq_enable.q.val() & (!self.lanes.val()))
                    | self.ones.val())
                    & self.m_irq_enable.val();
            }
            if self.adr.val() == self.a_irq_status.val() {
                self.irq_clear.next = self.ones.val() & self.m_irq_w1c.val();
            }
        }
        // Interrupt events; an event wins over a clear at the same edge.
        self.events.next = self.z32.val();
        if self.mtc_strobe.val() {
            self.events.next = self.events.val() | self.e_mtc.val();
        }
        if self.n3c_strobe.val() {
            self.events.next = self.events.val() | self.e_n3c.val();
        }
        if self.ident_done.val() & (!self.prev_done.q.val()) {
            self.events.next = self.events.val() | self.e_ident.val();
        }
        self.irq_status.d.next =
            (self.irq_status.q.val() & (!self.irq_clear.val())) | self.events.val();
        self.prev_done.d.next = self.ident_done.val();
        if self.reset.val() {
            self.ack.d.next = false;
            self.dat.d.next = self.z32.val();
            self.arm.d.next = false;
            self.stage_c.d.next = self.z32.val();
            self.stage_d.d.next = self.z32.val();
            self.r_ecc_c.d.next = self.z32.val();
            self.r_ecc_d.d.next = self.z32.val();
            self.irq_enable.d.next = self.z32.val();
            self.irq_status.d.next = self.z32.val();
            self.hi_mtc.d.next = self.z32.val();
            self.hi_n3c.d.next = self.z32.val();
            self.prev_done.d.next = false;
        }
        // Outputs: registers only.
        self.wb_ack_o.next = self.ack.q.val();
        self.wb_dat_o.next = self.dat.q.val();
        self.irq.next = (self.irq_status.q.val() & self.irq_enable.q.val()) != self.z32.val();
        self.ecc_c.next = self.r_ecc_c.q.val();
        self.ecc_d.next = self.r_ecc_d.q.val();
        self.ident_arm.next = self.arm.q.val();
    }
}
