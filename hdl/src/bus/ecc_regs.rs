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
//! | `wb_ack_o` | out | 1 | high for one cycle from the edge after the request edge |
//! | `irq` | out | 1 | (`ECC_IRQ_STATUS` & `ECC_IRQ_ENABLE`) ≠ 0 |
//! | `ecc_c`, `ecc_d` | out | 32 | the coefficients last loaded by `ECC_CTRL.LOAD` |
//! | `ident_arm` | out | 1 | the cycle after a write of 1 to `ECC_CTRL.IDENT_ARM` |
//! | `speed_mtc`, `speed_n3c` | in | S | corrected speeds (two's complement) |
//! | `snap_take`, `snap_sampled` | in | 1 | the core register file's snapshot strobe and `CTRL.SAMPLED` ([`EccSnapshot`]) |
//! | `mtc_strobe`, `n3c_strobe`, `ident_done`, `ident_overflow` | in | 1 | `encspeed_ecc` outputs |
//! | `ident_count` | in | 17 | |
//! | `ident_t_min`, `ident_t_max` | in | 32 | |
//! | `ident_p_min`, `ident_p_max` | in | 16 | |
//! | `ident_sum_t`, `ident_sum_sin`, `ident_sum_cos` | in | 72 | two's complement |
//!
//! Every output is a register or a function of registers only.
//!
//! # Implementation
//! As [`crate::bus::wb_regs::WbRegs`]: a [`RegFile`] (front end, read data and the
//! interrupt pair `ECC_IRQ_ENABLE`/`ECC_IRQ_STATUS`) and one cell per register of the map:
//! [`ConstCell`]
//! for the identification, [`RwCell`] for the staging registers `ECC_C`, `ECC_D`,
//! [`PulseCell`] for `ECC_CTRL.IDENT_ARM`, [`ReadCell`] for the live words (the 72-bit
//! sums as two plain words and a sign-extended top byte, `IDENT_P` as two fields at one
//! offset) and [`ShadowCell`] for the two LO/HI speed pairs. This file's own: the
//! interrupt events, the `ECC_STATUS` word, and `ECC_CTRL.LOAD`, which copies both staged
//! coefficients to `ecc_c`, `ecc_d` at the edge of the write.

use crate::bus::const_cell::ConstCell;
use crate::bus::ecc_snapshot::EccSnapshot;
use crate::bus::pulse_cell::PulseCell;
use crate::bus::read_cell::ReadCell;
use crate::bus::reg_file::RegFile;
use crate::bus::rw_cell::RwCell;
use crate::bus::shadow_cell::ShadowCell;
use golden::bus::ecc_regmap::{self as m, ECC_CTRL, ECC_IRQ_STATUS, ECC_STATUS};
use golden::bus::regmap::{Register, ADDR_BITS};
use rust_hdl::prelude::*;

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
    /// The core register file's snapshot strobe: store both corrected speeds at this edge.
    pub snap_take: Signal<In, Bit>,
    /// The core register file's `CTRL.SAMPLED`: the speed pairs read the snapshot.
    pub snap_sampled: Signal<In, Bit>,
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
    // Front end, read data and the cells, in map order.
    file: RegFile,
    id: ConstCell,
    version: ConstCell,
    arm: PulseCell,
    status: ReadCell<32>,
    stage_c: RwCell<32>,
    stage_d: RwCell<32>,
    /// The corrected speeds of the last snapshot, and what the pairs read.
    snapshot: EccSnapshot<S>,
    mtc: ShadowCell<S>,
    n3c: ShadowCell<S>,
    count: ReadCell<17>,
    t_min: ReadCell<32>,
    t_max: ReadCell<32>,
    p_min: ReadCell<16>,
    p_max: ReadCell<16>,
    t0: ReadCell<32>,
    t1: ReadCell<32>,
    t2: ReadCell<8>,
    s0: ReadCell<32>,
    s1: ReadCell<32>,
    s2: ReadCell<8>,
    c0: ReadCell<32>,
    c1: ReadCell<32>,
    c2: ReadCell<8>,
    // The loaded coefficients and the interrupt events.
    r_ecc_c: DFF<Bits<32>>,
    r_ecc_d: DFF<Bits<32>>,
    prev_done: DFF<Bit>,
    status_word: Signal<Local, Bits<32>>,
    events: Signal<Local, Bits<32>>,
    a_ctrl: Constant<Bits<ADDR_BITS>>,
    f_load: Constant<Bits<32>>,
    s_done: Constant<Bits<32>>,
    s_overflow: Constant<Bits<32>>,
    e_mtc: Constant<Bits<32>>,
    e_n3c: Constant<Bits<32>>,
    e_ident: Constant<Bits<32>>,
    z32: Constant<Bits<32>>,
}

impl<const S: usize> EccRegs<S> {
    /// The window's slave for speeds of S bits.
    pub fn new() -> Self {
        assert!((11..=64).contains(&S), "speed_bits S = {S}: 11..=64");
        let regs = m::registers(S as u32);
        let reg = |off: u32| -> &Register { regs.iter().find(|r| r.offset == off).unwrap() };
        let k = |v: u32| -> Constant<Bits<32>> { Constant::new(u64::from(v).into()) };
        let f = |off: u32, name: &str| reg(off).field(name).mask();
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
            snap_take: Default::default(),
            snap_sampled: Default::default(),
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
            file: RegFile::new(reg(m::ECC_IRQ_ENABLE), reg(ECC_IRQ_STATUS)),
            id: ConstCell::new(reg(m::ECC_ID)),
            version: ConstCell::new(reg(m::ECC_VERSION)),
            arm: PulseCell::new(reg(ECC_CTRL), f(ECC_CTRL, "IDENT_ARM")),
            status: ReadCell::new(reg(ECC_STATUS)),
            stage_c: RwCell::new(reg(m::ECC_C)),
            stage_d: RwCell::new(reg(m::ECC_D)),
            snapshot: Default::default(),
            mtc: ShadowCell::new(reg(m::SPEED_MTC_LO), reg(m::SPEED_MTC_HI)),
            n3c: ShadowCell::new(reg(m::SPEED_N3C_LO), reg(m::SPEED_N3C_HI)),
            count: ReadCell::new(reg(m::IDENT_COUNT)),
            t_min: ReadCell::new(reg(m::IDENT_T_MIN)),
            t_max: ReadCell::new(reg(m::IDENT_T_MAX)),
            p_min: ReadCell::field(reg(m::IDENT_P), "P_MIN"),
            p_max: ReadCell::field(reg(m::IDENT_P), "P_MAX"),
            t0: ReadCell::new(reg(m::IDENT_SUM_T_W0)),
            t1: ReadCell::new(reg(m::IDENT_SUM_T_W1)),
            t2: ReadCell::signed(reg(m::IDENT_SUM_T_W2)),
            s0: ReadCell::new(reg(m::IDENT_SUM_SIN_W0)),
            s1: ReadCell::new(reg(m::IDENT_SUM_SIN_W1)),
            s2: ReadCell::signed(reg(m::IDENT_SUM_SIN_W2)),
            c0: ReadCell::new(reg(m::IDENT_SUM_COS_W0)),
            c1: ReadCell::new(reg(m::IDENT_SUM_COS_W1)),
            c2: ReadCell::signed(reg(m::IDENT_SUM_COS_W2)),
            r_ecc_c: Default::default(),
            r_ecc_d: Default::default(),
            prev_done: Default::default(),
            status_word: Default::default(),
            events: Default::default(),
            a_ctrl: Constant::new(u64::from(ECC_CTRL).into()),
            f_load: k(f(ECC_CTRL, "LOAD")),
            s_done: k(f(ECC_STATUS, "IDENT_DONE")),
            s_overflow: k(f(ECC_STATUS, "IDENT_OVERFLOW")),
            e_mtc: k(f(ECC_IRQ_STATUS, "MTC")),
            e_n3c: k(f(ECC_IRQ_STATUS, "N3C")),
            e_ident: k(f(ECC_IRQ_STATUS, "IDENT")),
            z32: k(0),
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
        dff_setup!(self, clock, r_ecc_c, r_ecc_d, prev_done);
        clock!(self, clock, file, arm, stage_c, stage_d, snapshot, mtc, n3c);
        // The bus.
        self.file.reset.next = self.reset.val();
        self.file.wb_cyc_i.next = self.wb_cyc_i.val();
        self.file.wb_stb_i.next = self.wb_stb_i.val();
        self.file.wb_we_i.next = self.wb_we_i.val();
        self.file.wb_adr_i.next = self.wb_adr_i.val();
        self.file.wb_dat_i.next = self.wb_dat_i.val();
        self.file.wb_sel_i.next = self.wb_sel_i.val();
        self.wb_ack_o.next = self.file.wb_ack_o.val();
        self.wb_dat_o.next = self.file.wb_dat_o.val();
        self.irq.next = self.file.irq.val();

        // Identification words.
        self.id.adr.next = self.file.adr.val();
        self.version.adr.next = self.file.adr.val();

        // ECC_CTRL: IDENT_ARM pulses ident_arm; LOAD copies both staged coefficients (as
        // they stood before this edge) to ecc_c, ecc_d.
        self.arm.reset.next = self.reset.val();
        self.arm.adr.next = self.file.adr.val();
        self.arm.wr.next = self.file.wr.val();
        self.arm.ones.next = self.file.ones.val();
        self.ident_arm.next = self.arm.pulse.val();
        if self.file.wr.val()
            & (self.file.adr.val() == self.a_ctrl.val())
            & ((self.file.ones.val() & self.f_load.val()) != self.z32.val())
        {
            self.r_ecc_c.d.next = self.stage_c.q.val();
            self.r_ecc_d.d.next = self.stage_d.q.val();
        }
        self.stage_c.reset.next = self.reset.val();
        self.stage_c.adr.next = self.file.adr.val();
        self.stage_c.wr.next = self.file.wr.val();
        self.stage_c.lanes.next = self.file.lanes.val();
        self.stage_c.ones.next = self.file.ones.val();
        self.stage_d.reset.next = self.reset.val();
        self.stage_d.adr.next = self.file.adr.val();
        self.stage_d.wr.next = self.file.wr.val();
        self.stage_d.lanes.next = self.file.lanes.val();
        self.stage_d.ones.next = self.file.ones.val();
        self.ecc_c.next = self.r_ecc_c.q.val();
        self.ecc_d.next = self.r_ecc_d.q.val();

        // ECC_STATUS, live.
        self.status_word.next = self.z32.val();
        if self.ident_done.val() {
            self.status_word.next = self.status_word.val() | self.s_done.val();
        }
        if self.ident_overflow.val() {
            self.status_word.next = self.status_word.val() | self.s_overflow.val();
        }
        self.status.adr.next = self.file.adr.val();
        self.status.value.next = self.status_word.val();

        // The corrected speeds: the snapshot's choice (live, or stored at the core file's
        // snapshot edge while CTRL.SAMPLED), read as LO/HI pairs.
        self.snapshot.reset.next = self.reset.val();
        self.snapshot.take.next = self.snap_take.val();
        self.snapshot.sampled.next = self.snap_sampled.val();
        self.snapshot.speed_mtc.next = self.speed_mtc.val();
        self.snapshot.speed_n3c.next = self.speed_n3c.val();
        self.mtc.reset.next = self.reset.val();
        self.mtc.adr.next = self.file.adr.val();
        self.mtc.rd.next = self.file.rd.val();
        self.mtc.value.next = self.snapshot.seen_mtc.val();
        self.n3c.reset.next = self.reset.val();
        self.n3c.adr.next = self.file.adr.val();
        self.n3c.rd.next = self.file.rd.val();
        self.n3c.value.next = self.snapshot.seen_n3c.val();

        // Identification results, live; each sum as words 0, 1 and its sign-extended top byte.
        self.count.adr.next = self.file.adr.val();
        self.count.value.next = self.ident_count.val();
        self.t_min.adr.next = self.file.adr.val();
        self.t_min.value.next = self.ident_t_min.val();
        self.t_max.adr.next = self.file.adr.val();
        self.t_max.value.next = self.ident_t_max.val();
        self.p_min.adr.next = self.file.adr.val();
        self.p_min.value.next = self.ident_p_min.val();
        self.p_max.adr.next = self.file.adr.val();
        self.p_max.value.next = self.ident_p_max.val();
        self.t0.adr.next = self.file.adr.val();
        self.t0.value.next = self.ident_sum_t.val().get_bits::<32>(0);
        self.t1.adr.next = self.file.adr.val();
        self.t1.value.next = self.ident_sum_t.val().get_bits::<32>(32);
        self.t2.adr.next = self.file.adr.val();
        self.t2.value.next = self.ident_sum_t.val().get_bits::<8>(64);
        self.s0.adr.next = self.file.adr.val();
        self.s0.value.next = self.ident_sum_sin.val().get_bits::<32>(0);
        self.s1.adr.next = self.file.adr.val();
        self.s1.value.next = self.ident_sum_sin.val().get_bits::<32>(32);
        self.s2.adr.next = self.file.adr.val();
        self.s2.value.next = self.ident_sum_sin.val().get_bits::<8>(64);
        self.c0.adr.next = self.file.adr.val();
        self.c0.value.next = self.ident_sum_cos.val().get_bits::<32>(0);
        self.c1.adr.next = self.file.adr.val();
        self.c1.value.next = self.ident_sum_cos.val().get_bits::<32>(32);
        self.c2.adr.next = self.file.adr.val();
        self.c2.value.next = self.ident_sum_cos.val().get_bits::<8>(64);

        // Read data: the cells' words (each 0 away from its offset; ECC_CTRL reads 0),
        // grouped by 16-byte block of the map (a group's words share the offset's bits 7:4).
        self.file.group0.next =
            self.id.rdata.val() | self.version.rdata.val() | self.status.rdata.val();
        self.file.group1.next =
            self.stage_c.rdata.val() | self.stage_d.rdata.val() | self.file.irq_rdata.val();
        self.file.group2.next = self.mtc.rdata.val() | self.n3c.rdata.val();
        self.file.group3.next = self.count.rdata.val()
            | self.t_min.rdata.val()
            | self.t_max.rdata.val()
            | self.p_min.rdata.val()
            | self.p_max.rdata.val();
        self.file.group4.next =
            self.t0.rdata.val() | self.t1.rdata.val() | self.t2.rdata.val() | self.s0.rdata.val();
        self.file.group5.next =
            self.s1.rdata.val() | self.s2.rdata.val() | self.c0.rdata.val() | self.c1.rdata.val();
        self.file.group6.next = self.c2.rdata.val();
        self.file.group7.next = self.z32.val();

        // Interrupt events: the strobes and ident_done rising.
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
        self.file.events.next = self.events.val();
        self.prev_done.d.next = self.ident_done.val();
        if self.reset.val() {
            self.r_ecc_c.d.next = self.z32.val();
            self.r_ecc_d.d.next = self.z32.val();
            self.prev_done.d.next = false;
        }
    }
}
