// SPDX-License-Identifier: MIT OR Apache-2.0
//! Wishbone B4 classic register file of `encspeed_core`: drives the core's configuration
//! inputs and reads its status outputs. The register map, the bus protocol, coherence,
//! faults and interrupts are specified in [`golden::bus::regmap`] (offsets, fields, reset values,
//! all taken from there at construction); the cycle model is
//! [`golden::bus::wb_regs::WbRegsModel`].
//!
//! # Generation parameters
//!
//! | parameter | meaning | range |
//! |---|---|---|
//! | `N` | `counter_bits`: `cfg_dt`, `cfg_timeout`, `nep`, `ndt` | 8..=32 |
//! | `S` | `speed_bits` = N + F + 1: the six speeds | 11..=57 |
//! | `C` | `position_bits`: `position`, `z_latch` | 1..=32 |
//! | `FB` | `filter_bits`: `cfg_filter` | 1..=32 |
//! | `G` | `error_count_bits`: the three fault counters | 1..=32 |
//!
//! [`wb_regs_type!`](crate::wb_regs_type) names the type from N, F, C, FB, G;
//! [`WbRegs::new`] checks that the generics are the widths of the parameters.
//!
//! # Ports
//!
//! | port | dir | width | meaning |
//! |---|---|---|---|
//! | `clock`, `reset` | in | 1 | the core's clock; synchronous active-high reset |
//! | `wb_cyc_i`, `wb_stb_i`, `wb_we_i` | in | 1 | Wishbone cycle, strobe, write enable |
//! | `wb_adr_i` | in | 8 | byte address ([`ADDR_BITS`]); bits 1:0 ignored |
//! | `wb_dat_i` | in | 32 | write data |
//! | `wb_sel_i` | in | 4 | byte lanes of a write |
//! | `wb_dat_o` | out | 32 | read data, valid with `wb_ack_o` (0 otherwise) |
//! | `wb_ack_o` | out | 1 | one cycle after the request edge |
//! | `irq` | out | 1 | level: (`IRQ_STATUS` & `IRQ_ENABLE`) ≠ 0 |
//! | `cfg_dt`, `cfg_timeout` | out | N | `CFG_DT`, `CFG_TIMEOUT` |
//! | `cfg_filter` | out | FB | `CFG_FILTER` |
//! | `cfg_mode`, `cfg_z_mode` | out | 2 | `CTRL.MODE`, `CTRL.Z_MODE` |
//! | `clear_faults` | out | 1 | one cycle after a write of 1 to a `STATUS` fault bit |
//! | `position`, `z_latch` | in | C | core outputs |
//! | `nep`, `ndt` | in | N | core outputs |
//! | `speed_n1..n3`, `speed_pc`, `speed_et`, `speed_mt` | in | S | core outputs (two's complement) |
//! | `index`, `direction`, `update`, `speed_strobe`, `baseline_strobe`, `valid`, `stalled`, `fault_illegal`, `fault_overspeed`, `fault_revolution`, `cfg_error` | in | 1 | core outputs |
//! | `glitch_count`, `illegal_count`, `rev_error_count` | in | G | core outputs |
//!
//! Every output is a register or a function of registers only (`irq`: an AND-OR of two).
//!
//! # Timing
//!
//! A request sampled at edge k (`wb_cyc_i & wb_stb_i` while `wb_ack_o` is low) is executed
//! at edge k and acknowledged in the cycle after it: two cycles per access, `wb_ack_o` low
//! for at least one cycle between accesses. A status input is read as it stood before edge
//! k. A configuration write shows on its port after edge k; `clear_faults` is high in the
//! cycle after edge k (with `wb_ack_o`).
//!
//! # Implementation
//!
//! Configuration and interrupt registers are 32 bits wide with the reserved bits held at 0
//! (synthesis removes those flops), so read-back needs no widening. Status inputs are
//! widened to 32 (speeds: sign-extended to 64) by shifting their bits in at the top and
//! shifting down by a constant, because rust-hdl emits casts as masks of another width
//! that Verilator flags; after synthesis these are wires. `CTRL` fields are sliced at the
//! offsets [`CTRL_MODE_LSB`], [`CTRL_Z_MODE_LSB`] through a one-pass loop variable (a const
//! in a slice would be emitted as an undeclared identifier).

use golden::bus::regmap::{
    Access, RegMap, ADDR_BITS, CTRL_MODE_LSB, CTRL_Z_MODE_LSB, MODE_BITS, SPAN_BYTES,
};
use golden::params::Params;
use rust_hdl::prelude::*;

/// Width of the shift-amount constants.
const SHIFT_BITS: usize = 8;

/// The `WbRegs` type for counter width `$n`, `$f` speed fraction bits, position width
/// `$c`, filter width `$fb` and fault-counter width `$g`: `wb_regs_type!(24, 16, 32, 16, 16)`
/// is `WbRegs<24, 41, 32, 16, 16>`.
#[macro_export]
macro_rules! wb_regs_type {
    ($n:expr, $f:expr, $c:expr, $fb:expr, $g:expr) => {
        $crate::bus::wb_regs::WbRegs<{ $n }, { $n + $f + 1 }, { $c }, { $fb }, { $g }>
    };
}

/// Wishbone register file of `encspeed_core`.
#[derive(LogicBlock)]
pub struct WbRegs<const N: usize, const S: usize, const C: usize, const FB: usize, const G: usize> {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Wishbone: bus cycle.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone: strobe.
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
    /// Interrupt request, level.
    pub irq: Signal<Out, Bit>,
    /// dt, clock cycles (0 = generation default).
    pub cfg_dt: Signal<Out, Bits<N>>,
    /// Zero-speed timeout, dt intervals (0 = generation default).
    pub cfg_timeout: Signal<Out, Bits<N>>,
    /// Glitch filter length, clock cycles (0 = off).
    pub cfg_filter: Signal<Out, Bits<FB>>,
    /// Decoding: 0 x1, 1 x2, 2 x4, 3 invalid.
    pub cfg_mode: Signal<Out, Bits<2>>,
    /// Z: 0 ignore, 1 reset position, 2 latch, 3 latch then reset.
    pub cfg_z_mode: Signal<Out, Bits<2>>,
    /// One cycle: clear the sticky faults.
    pub clear_faults: Signal<Out, Bit>,
    /// Position, steps.
    pub position: Signal<In, Bits<C>>,
    /// Position latched at the last index edge.
    pub z_latch: Signal<In, Bits<C>>,
    /// One cycle: a Z edge.
    pub index: Signal<In, Bit>,
    /// Direction of the last step: 1 forward.
    pub direction: Signal<In, Bit>,
    /// Nep1, pulses.
    pub nep: Signal<In, Bits<N>>,
    /// Ndt1, dt intervals.
    pub ndt: Signal<In, Bits<N>>,
    /// One cycle: nep/ndt written.
    pub update: Signal<In, Bit>,
    /// n1, Q(N).F two's complement, units of ω_lim.
    pub speed_n1: Signal<In, Bits<S>>,
    /// n2, Q(N).F two's complement, units of ω_lim.
    pub speed_n2: Signal<In, Bits<S>>,
    /// n3, Q(N).F two's complement, units of ω_lim.
    pub speed_n3: Signal<In, Bits<S>>,
    /// One cycle: n1..n3 written.
    pub speed_strobe: Signal<In, Bit>,
    /// PC speed, Q(N).F two's complement, units of ω_lim.
    pub speed_pc: Signal<In, Bits<S>>,
    /// ET speed, Q(N).F two's complement, units of ω_lim.
    pub speed_et: Signal<In, Bits<S>>,
    /// M/T speed, Q(N).F two's complement, units of ω_lim.
    pub speed_mt: Signal<In, Bits<S>>,
    /// One cycle: the baseline speeds written.
    pub baseline_strobe: Signal<In, Bit>,
    /// A valid measurement.
    pub valid: Signal<In, Bit>,
    /// No step for the zero-speed timeout.
    pub stalled: Signal<In, Bit>,
    /// Sticky: illegal transition.
    pub fault_illegal: Signal<In, Bit>,
    /// Sticky: a filter rejected a pulse.
    pub fault_overspeed: Signal<In, Bit>,
    /// Sticky: a revolution had the wrong count.
    pub fault_revolution: Signal<In, Bit>,
    /// Illegal configuration.
    pub cfg_error: Signal<In, Bit>,
    /// Rejected pulses (saturating).
    pub glitch_count: Signal<In, Bits<G>>,
    /// Illegal transitions (saturating).
    pub illegal_count: Signal<In, Bits<G>>,
    /// Revolution errors (saturating).
    pub rev_error_count: Signal<In, Bits<G>>,
    // Registers.
    ack: DFF<Bit>,
    dat: DFF<Bits<32>>,
    ctrl: DFF<Bits<32>>,
    r_cfg_dt: DFF<Bits<32>>,
    r_cfg_timeout: DFF<Bits<32>>,
    r_cfg_filter: DFF<Bits<32>>,
    irq_enable: DFF<Bits<32>>,
    irq_status: DFF<Bits<32>>,
    hi_n1: DFF<Bits<32>>,
    hi_n2: DFF<Bits<32>>,
    hi_n3: DFF<Bits<32>>,
    hi_pc: DFF<Bits<32>>,
    hi_et: DFF<Bits<32>>,
    hi_mt: DFF<Bits<32>>,
    clear: DFF<Bit>,
    prev_illegal: DFF<Bit>,
    prev_overspeed: DFF<Bit>,
    prev_revolution: DFF<Bit>,
    prev_stalled: DFF<Bit>,
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
    fault_rose: Signal<Local, Bit>,
    /// Copies of the C- and G-bit inputs, shifted down one bit per step (a bit select
    /// would be invalid Verilog on a 1-bit port).
    t_position: Signal<Local, Bits<C>>,
    t_z_latch: Signal<Local, Bits<C>>,
    t_glitch: Signal<Local, Bits<G>>,
    t_illegal: Signal<Local, Bits<G>>,
    t_rev: Signal<Local, Bits<G>>,
    x_position: Signal<Local, Bits<32>>,
    x_z_latch: Signal<Local, Bits<32>>,
    x_nep: Signal<Local, Bits<32>>,
    x_ndt: Signal<Local, Bits<32>>,
    x_glitch: Signal<Local, Bits<32>>,
    x_illegal: Signal<Local, Bits<32>>,
    x_rev: Signal<Local, Bits<32>>,
    x_n1: Signal<Local, Bits<64>>,
    x_n2: Signal<Local, Bits<64>>,
    x_n3: Signal<Local, Bits<64>>,
    x_pc: Signal<Local, Bits<64>>,
    x_et: Signal<Local, Bits<64>>,
    x_mt: Signal<Local, Bits<64>>,
    // Offsets, from golden::bus::regmap.
    adr_mask: Constant<Bits<ADDR_BITS>>,
    a_id: Constant<Bits<ADDR_BITS>>,
    a_version: Constant<Bits<ADDR_BITS>>,
    a_param0: Constant<Bits<ADDR_BITS>>,
    a_param1: Constant<Bits<ADDR_BITS>>,
    a_lines: Constant<Bits<ADDR_BITS>>,
    a_dt_default: Constant<Bits<ADDR_BITS>>,
    a_timeout_default: Constant<Bits<ADDR_BITS>>,
    a_clock_hz: Constant<Bits<ADDR_BITS>>,
    a_ctrl: Constant<Bits<ADDR_BITS>>,
    a_cfg_dt: Constant<Bits<ADDR_BITS>>,
    a_cfg_timeout: Constant<Bits<ADDR_BITS>>,
    a_cfg_filter: Constant<Bits<ADDR_BITS>>,
    a_status: Constant<Bits<ADDR_BITS>>,
    a_irq_enable: Constant<Bits<ADDR_BITS>>,
    a_irq_status: Constant<Bits<ADDR_BITS>>,
    a_position: Constant<Bits<ADDR_BITS>>,
    a_z_latch: Constant<Bits<ADDR_BITS>>,
    a_nep: Constant<Bits<ADDR_BITS>>,
    a_ndt: Constant<Bits<ADDR_BITS>>,
    a_n1_lo: Constant<Bits<ADDR_BITS>>,
    a_n1_hi: Constant<Bits<ADDR_BITS>>,
    a_n2_lo: Constant<Bits<ADDR_BITS>>,
    a_n2_hi: Constant<Bits<ADDR_BITS>>,
    a_n3_lo: Constant<Bits<ADDR_BITS>>,
    a_n3_hi: Constant<Bits<ADDR_BITS>>,
    a_pc_lo: Constant<Bits<ADDR_BITS>>,
    a_pc_hi: Constant<Bits<ADDR_BITS>>,
    a_et_lo: Constant<Bits<ADDR_BITS>>,
    a_et_hi: Constant<Bits<ADDR_BITS>>,
    a_mt_lo: Constant<Bits<ADDR_BITS>>,
    a_mt_hi: Constant<Bits<ADDR_BITS>>,
    a_glitch: Constant<Bits<ADDR_BITS>>,
    a_illegal: Constant<Bits<ADDR_BITS>>,
    a_rev: Constant<Bits<ADDR_BITS>>,
    // Constant registers, from the map's reset values.
    k_id: Constant<Bits<32>>,
    k_version: Constant<Bits<32>>,
    k_param0: Constant<Bits<32>>,
    k_param1: Constant<Bits<32>>,
    k_lines: Constant<Bits<32>>,
    k_dt_default: Constant<Bits<32>>,
    k_timeout_default: Constant<Bits<32>>,
    k_clock_hz: Constant<Bits<32>>,
    // Field masks, from the map.
    m_ctrl: Constant<Bits<32>>,
    m_cfg_dt: Constant<Bits<32>>,
    m_cfg_timeout: Constant<Bits<32>>,
    m_cfg_filter: Constant<Bits<32>>,
    m_irq_enable: Constant<Bits<32>>,
    m_irq_w1c: Constant<Bits<32>>,
    m_fault_w1c: Constant<Bits<32>>,
    s_valid: Constant<Bits<32>>,
    s_stalled: Constant<Bits<32>>,
    s_direction: Constant<Bits<32>>,
    s_cfg_error: Constant<Bits<32>>,
    s_fault_illegal: Constant<Bits<32>>,
    s_fault_overspeed: Constant<Bits<32>>,
    s_fault_revolution: Constant<Bits<32>>,
    e_speed: Constant<Bits<32>>,
    e_baseline: Constant<Bits<32>>,
    e_index: Constant<Bits<32>>,
    e_fault: Constant<Bits<32>>,
    e_update: Constant<Bits<32>>,
    e_stall: Constant<Bits<32>>,
    // Arithmetic constants.
    lane0: Constant<Bits<32>>,
    lane1: Constant<Bits<32>>,
    lane2: Constant<Bits<32>>,
    lane3: Constant<Bits<32>>,
    c_zero: Constant<Bits<C>>,
    c_one: Constant<Bits<C>>,
    g_zero: Constant<Bits<G>>,
    g_one: Constant<Bits<G>>,
    z32: Constant<Bits<32>>,
    msb32: Constant<Bits<32>>,
    z64: Constant<Bits<64>>,
    msb64: Constant<Bits<64>>,
    /// Bits 63..S: the sign extension of a speed.
    sext: Constant<Bits<64>>,
    sh_one: Constant<Bits<SHIFT_BITS>>,
    /// 32 − C, 32 − N, 32 − G, 64 − S: shifts from the top down to bit 0.
    sh_c: Constant<Bits<SHIFT_BITS>>,
    sh_n: Constant<Bits<SHIFT_BITS>>,
    sh_g: Constant<Bits<SHIFT_BITS>>,
    sh_s: Constant<Bits<SHIFT_BITS>>,
}

impl<const N: usize, const S: usize, const C: usize, const FB: usize, const G: usize>
    WbRegs<N, S, C, FB, G>
{
    /// The register file of validated parameters `p`; panics unless the generics are
    /// `p`'s widths.
    pub fn new(p: &Params) -> Self {
        Self::from_map(&RegMap::new(p))
    }

    /// The register file of `map` (e.g. built by [`RegMap::from_map_params`] at widths
    /// that `Params` does not offer); panics unless the generics are its widths.
    pub fn from_map(map: &RegMap) -> Self {
        let mp = map.params();
        let w = |v: u32| v as usize;
        assert_eq!(
            (N, S, C, FB, G),
            (
                w(mp.counter_bits),
                w(mp.speed_bits()),
                w(mp.position_bits),
                w(mp.filter_bits),
                w(mp.error_count_bits)
            ),
            "WbRegs<N, S, C, FB, G> must have the map's widths"
        );
        assert!(S <= 64 && FB <= 32 && C <= 32 && G <= 32 && N <= 32);
        let ctrl = map.reg("CTRL");
        assert_eq!(ctrl.field("MODE").lsb as usize, CTRL_MODE_LSB);
        assert_eq!(ctrl.field("Z_MODE").lsb as usize, CTRL_Z_MODE_LSB);
        assert_eq!(ctrl.field("MODE").width, MODE_BITS);
        assert_eq!(ctrl.field("Z_MODE").width, MODE_BITS);
        assert_eq!(SPAN_BYTES, 1 << ADDR_BITS);
        let a = |name: &str| -> Constant<Bits<ADDR_BITS>> {
            Constant::new(u64::from(map.reg(name).offset).into())
        };
        let k = |v: u32| -> Constant<Bits<32>> { Constant::new(u64::from(v).into()) };
        let value = |name: &str| k(map.reg(name).reset.expect("a constant register"));
        let rw = |name: &str| k(map.reg(name).mask_of(Access::Rw));
        let status = |field: &str| k(map.mask("STATUS", field));
        let event = |field: &str| k(map.mask("IRQ_STATUS", field));
        let sh = |v: usize| -> Constant<Bits<SHIFT_BITS>> { Constant::new((v as u64).into()) };
        let sext = if S == 64 { 0 } else { !((1u64 << S) - 1) };
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
            cfg_dt: Default::default(),
            cfg_timeout: Default::default(),
            cfg_filter: Default::default(),
            cfg_mode: Default::default(),
            cfg_z_mode: Default::default(),
            clear_faults: Default::default(),
            position: Default::default(),
            z_latch: Default::default(),
            index: Default::default(),
            direction: Default::default(),
            nep: Default::default(),
            ndt: Default::default(),
            update: Default::default(),
            speed_n1: Default::default(),
            speed_n2: Default::default(),
            speed_n3: Default::default(),
            speed_strobe: Default::default(),
            speed_pc: Default::default(),
            speed_et: Default::default(),
            speed_mt: Default::default(),
            baseline_strobe: Default::default(),
            valid: Default::default(),
            stalled: Default::default(),
            fault_illegal: Default::default(),
            fault_overspeed: Default::default(),
            fault_revolution: Default::default(),
            cfg_error: Default::default(),
            glitch_count: Default::default(),
            illegal_count: Default::default(),
            rev_error_count: Default::default(),
            ack: Default::default(),
            dat: Default::default(),
            ctrl: Default::default(),
            r_cfg_dt: Default::default(),
            r_cfg_timeout: Default::default(),
            r_cfg_filter: Default::default(),
            irq_enable: Default::default(),
            irq_status: Default::default(),
            hi_n1: Default::default(),
            hi_n2: Default::default(),
            hi_n3: Default::default(),
            hi_pc: Default::default(),
            hi_et: Default::default(),
            hi_mt: Default::default(),
            clear: Default::default(),
            prev_illegal: Default::default(),
            prev_overspeed: Default::default(),
            prev_revolution: Default::default(),
            prev_stalled: Default::default(),
            adr: Default::default(),
            req: Default::default(),
            rd: Default::default(),
            wr: Default::default(),
            lanes: Default::default(),
            ones: Default::default(),
            rdata: Default::default(),
            irq_clear: Default::default(),
            events: Default::default(),
            fault_rose: Default::default(),
            t_position: Default::default(),
            t_z_latch: Default::default(),
            t_glitch: Default::default(),
            t_illegal: Default::default(),
            t_rev: Default::default(),
            x_position: Default::default(),
            x_z_latch: Default::default(),
            x_nep: Default::default(),
            x_ndt: Default::default(),
            x_glitch: Default::default(),
            x_illegal: Default::default(),
            x_rev: Default::default(),
            x_n1: Default::default(),
            x_n2: Default::default(),
            x_n3: Default::default(),
            x_pc: Default::default(),
            x_et: Default::default(),
            x_mt: Default::default(),
            adr_mask: Constant::new(u64::from((SPAN_BYTES - 1) & !3).into()),
            a_id: a("ID"),
            a_version: a("VERSION"),
            a_param0: a("PARAM0"),
            a_param1: a("PARAM1"),
            a_lines: a("LINES"),
            a_dt_default: a("DT_DEFAULT"),
            a_timeout_default: a("TIMEOUT_DEFAULT"),
            a_clock_hz: a("CLOCK_HZ"),
            a_ctrl: a("CTRL"),
            a_cfg_dt: a("CFG_DT"),
            a_cfg_timeout: a("CFG_TIMEOUT"),
            a_cfg_filter: a("CFG_FILTER"),
            a_status: a("STATUS"),
            a_irq_enable: a("IRQ_ENABLE"),
            a_irq_status: a("IRQ_STATUS"),
            a_position: a("POSITION"),
            a_z_latch: a("Z_LATCH"),
            a_nep: a("NEP"),
            a_ndt: a("NDT"),
            a_n1_lo: a("SPEED_N1_LO"),
            a_n1_hi: a("SPEED_N1_HI"),
            a_n2_lo: a("SPEED_N2_LO"),
            a_n2_hi: a("SPEED_N2_HI"),
            a_n3_lo: a("SPEED_N3_LO"),
            a_n3_hi: a("SPEED_N3_HI"),
            a_pc_lo: a("SPEED_PC_LO"),
            a_pc_hi: a("SPEED_PC_HI"),
            a_et_lo: a("SPEED_ET_LO"),
            a_et_hi: a("SPEED_ET_HI"),
            a_mt_lo: a("SPEED_MT_LO"),
            a_mt_hi: a("SPEED_MT_HI"),
            a_glitch: a("GLITCH_COUNT"),
            a_illegal: a("ILLEGAL_COUNT"),
            a_rev: a("REV_ERROR_COUNT"),
            k_id: value("ID"),
            k_version: value("VERSION"),
            k_param0: value("PARAM0"),
            k_param1: value("PARAM1"),
            k_lines: value("LINES"),
            k_dt_default: value("DT_DEFAULT"),
            k_timeout_default: value("TIMEOUT_DEFAULT"),
            k_clock_hz: value("CLOCK_HZ"),
            m_ctrl: rw("CTRL"),
            m_cfg_dt: rw("CFG_DT"),
            m_cfg_timeout: rw("CFG_TIMEOUT"),
            m_cfg_filter: rw("CFG_FILTER"),
            m_irq_enable: rw("IRQ_ENABLE"),
            m_irq_w1c: k(map.reg("IRQ_STATUS").mask_of(Access::W1c)),
            m_fault_w1c: k(map.reg("STATUS").mask_of(Access::W1c)),
            s_valid: status("VALID"),
            s_stalled: status("STALLED"),
            s_direction: status("DIRECTION"),
            s_cfg_error: status("CFG_ERROR"),
            s_fault_illegal: status("FAULT_ILLEGAL"),
            s_fault_overspeed: status("FAULT_OVERSPEED"),
            s_fault_revolution: status("FAULT_REVOLUTION"),
            e_speed: event("SPEED"),
            e_baseline: event("BASELINE"),
            e_index: event("INDEX"),
            e_fault: event("FAULT"),
            e_update: event("UPDATE"),
            e_stall: event("STALL"),
            lane0: k(0x0000_00FF),
            lane1: k(0x0000_FF00),
            lane2: k(0x00FF_0000),
            lane3: k(0xFF00_0000),
            c_zero: Constant::new(0.into()),
            c_one: Constant::new(1.into()),
            g_zero: Constant::new(0.into()),
            g_one: Constant::new(1.into()),
            z32: k(0),
            msb32: k(1 << 31),
            z64: Constant::new(0.into()),
            msb64: Constant::new((1u64 << 63).into()),
            sext: Constant::new(sext.into()),
            sh_one: sh(1),
            sh_c: sh(32 - C),
            sh_n: sh(32 - N),
            sh_g: sh(32 - G),
            sh_s: sh(64 - S),
        }
    }
}

impl<const N: usize, const S: usize, const C: usize, const FB: usize, const G: usize> Logic
    for WbRegs<N, S, C, FB, G>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            ack,
            dat,
            ctrl,
            r_cfg_dt,
            r_cfg_timeout,
            r_cfg_filter,
            irq_enable,
            irq_status,
            hi_n1,
            hi_n2,
            hi_n3,
            hi_pc,
            hi_et,
            hi_mt,
            clear,
            prev_illegal,
            prev_overspeed,
            prev_revolution,
            prev_stalled
        );
        // Widen the status values to 32 bits: shift their bits in at the top, LSB first,
        // then move them down (a cast would be emitted as a mask of another width).
        self.x_position.next = self.z32.val();
        self.x_z_latch.next = self.z32.val();
        self.t_position.next = self.position.val();
        self.t_z_latch.next = self.z_latch.val();
        for _i in 0..C {
            self.x_position.next = self.x_position.val() >> self.sh_one.val();
            if (self.t_position.val() & self.c_one.val()) != self.c_zero.val() {
                self.x_position.next = self.x_position.val() | self.msb32.val();
            }
            self.t_position.next = self.t_position.val() >> self.sh_one.val();
            self.x_z_latch.next = self.x_z_latch.val() >> self.sh_one.val();
            if (self.t_z_latch.val() & self.c_one.val()) != self.c_zero.val() {
                self.x_z_latch.next = self.x_z_latch.val() | self.msb32.val();
            }
            self.t_z_latch.next = self.t_z_latch.val() >> self.sh_one.val();
        }
        self.x_position.next = self.x_position.val() >> self.sh_c.val();
        self.x_z_latch.next = self.x_z_latch.val() >> self.sh_c.val();
        self.x_nep.next = self.z32.val();
        self.x_ndt.next = self.z32.val();
        for i in 0..N {
            self.x_nep.next = self.x_nep.val() >> self.sh_one.val();
            if self.nep.val().get_bit(i) {
                self.x_nep.next = self.x_nep.val() | self.msb32.val();
            }
            self.x_ndt.next = self.x_ndt.val() >> self.sh_one.val();
            if self.ndt.val().get_bit(i) {
                self.x_ndt.next = self.x_ndt.val() | self.msb32.val();
            }
        }
        self.x_nep.next = self.x_nep.val() >> self.sh_n.val();
        self.x_ndt.next = self.x_ndt.val() >> self.sh_n.val();
        self.x_glitch.next = self.z32.val();
        self.x_illegal.next = self.z32.val();
        self.x_rev.next = self.z32.val();
        self.t_glitch.next = self.glitch_count.val();
        self.t_illegal.next = self.illegal_count.val();
        self.t_rev.next = self.rev_error_count.val();
        for _i in 0..G {
            self.x_glitch.next = self.x_glitch.val() >> self.sh_one.val();
            if (self.t_glitch.val() & self.g_one.val()) != self.g_zero.val() {
                self.x_glitch.next = self.x_glitch.val() | self.msb32.val();
            }
            self.t_glitch.next = self.t_glitch.val() >> self.sh_one.val();
            self.x_illegal.next = self.x_illegal.val() >> self.sh_one.val();
            if (self.t_illegal.val() & self.g_one.val()) != self.g_zero.val() {
                self.x_illegal.next = self.x_illegal.val() | self.msb32.val();
            }
            self.t_illegal.next = self.t_illegal.val() >> self.sh_one.val();
            self.x_rev.next = self.x_rev.val() >> self.sh_one.val();
            if (self.t_rev.val() & self.g_one.val()) != self.g_zero.val() {
                self.x_rev.next = self.x_rev.val() | self.msb32.val();
            }
            self.t_rev.next = self.t_rev.val() >> self.sh_one.val();
        }
        self.x_glitch.next = self.x_glitch.val() >> self.sh_g.val();
        self.x_illegal.next = self.x_illegal.val() >> self.sh_g.val();
        self.x_rev.next = self.x_rev.val() >> self.sh_g.val();
        // The speeds, sign-extended to 64 bits the same way.
        self.x_n1.next = self.z64.val();
        self.x_n2.next = self.z64.val();
        self.x_n3.next = self.z64.val();
        self.x_pc.next = self.z64.val();
        self.x_et.next = self.z64.val();
        self.x_mt.next = self.z64.val();
        for i in 0..S {
            self.x_n1.next = self.x_n1.val() >> self.sh_one.val();
            if self.speed_n1.val().get_bit(i) {
                self.x_n1.next = self.x_n1.val() | self.msb64.val();
            }
            self.x_n2.next = self.x_n2.val() >> self.sh_one.val();
            if self.speed_n2.val().get_bit(i) {
                self.x_n2.next = self.x_n2.val() | self.msb64.val();
            }
            self.x_n3.next = self.x_n3.val() >> self.sh_one.val();
            if self.speed_n3.val().get_bit(i) {
                self.x_n3.next = self.x_n3.val() | self.msb64.val();
            }
            self.x_pc.next = self.x_pc.val() >> self.sh_one.val();
            if self.speed_pc.val().get_bit(i) {
                self.x_pc.next = self.x_pc.val() | self.msb64.val();
            }
            self.x_et.next = self.x_et.val() >> self.sh_one.val();
            if self.speed_et.val().get_bit(i) {
                self.x_et.next = self.x_et.val() | self.msb64.val();
            }
            self.x_mt.next = self.x_mt.val() >> self.sh_one.val();
            if self.speed_mt.val().get_bit(i) {
                self.x_mt.next = self.x_mt.val() | self.msb64.val();
            }
        }
        // Now each sign is bit 63: shift down, then fill bits 63..S with it.
        if (self.x_n1.val() & self.msb64.val()) != self.z64.val() {
            self.x_n1.next = (self.x_n1.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x_n1.next = self.x_n1.val() >> self.sh_s.val();
        }
        if (self.x_n2.val() & self.msb64.val()) != self.z64.val() {
            self.x_n2.next = (self.x_n2.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x_n2.next = self.x_n2.val() >> self.sh_s.val();
        }
        if (self.x_n3.val() & self.msb64.val()) != self.z64.val() {
            self.x_n3.next = (self.x_n3.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x_n3.next = self.x_n3.val() >> self.sh_s.val();
        }
        if (self.x_pc.val() & self.msb64.val()) != self.z64.val() {
            self.x_pc.next = (self.x_pc.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x_pc.next = self.x_pc.val() >> self.sh_s.val();
        }
        if (self.x_et.val() & self.msb64.val()) != self.z64.val() {
            self.x_et.next = (self.x_et.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x_et.next = self.x_et.val() >> self.sh_s.val();
        }
        if (self.x_mt.val() & self.msb64.val()) != self.z64.val() {
            self.x_mt.next = (self.x_mt.val() >> self.sh_s.val()) | self.sext.val();
        } else {
            self.x_mt.next = self.x_mt.val() >> self.sh_s.val();
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

        // Read multiplexer: 0 at unmapped offsets.
        self.rdata.next = self.z32.val();
        if self.adr.val() == self.a_id.val() {
            self.rdata.next = self.k_id.val();
        }
        if self.adr.val() == self.a_version.val() {
            self.rdata.next = self.k_version.val();
        }
        if self.adr.val() == self.a_param0.val() {
            self.rdata.next = self.k_param0.val();
        }
        if self.adr.val() == self.a_param1.val() {
            self.rdata.next = self.k_param1.val();
        }
        if self.adr.val() == self.a_lines.val() {
            self.rdata.next = self.k_lines.val();
        }
        if self.adr.val() == self.a_dt_default.val() {
            self.rdata.next = self.k_dt_default.val();
        }
        if self.adr.val() == self.a_timeout_default.val() {
            self.rdata.next = self.k_timeout_default.val();
        }
        if self.adr.val() == self.a_clock_hz.val() {
            self.rdata.next = self.k_clock_hz.val();
        }
        if self.adr.val() == self.a_ctrl.val() {
            self.rdata.next = self.ctrl.q.val();
        }
        if self.adr.val() == self.a_cfg_dt.val() {
            self.rdata.next = self.r_cfg_dt.q.val();
        }
        if self.adr.val() == self.a_cfg_timeout.val() {
            self.rdata.next = self.r_cfg_timeout.q.val();
        }
        if self.adr.val() == self.a_cfg_filter.val() {
            self.rdata.next = self.r_cfg_filter.q.val();
        }
        if self.adr.val() == self.a_status.val() {
            if self.valid.val() {
                self.rdata.next = self.rdata.val() | self.s_valid.val();
            }
            if self.stalled.val() {
                self.rdata.next = self.rdata.val() | self.s_stalled.val();
            }
            if self.direction.val() {
                self.rdata.next = self.rdata.val() | self.s_direction.val();
            }
            if self.cfg_error.val() {
                self.rdata.next = self.rdata.val() | self.s_cfg_error.val();
            }
            if self.fault_illegal.val() {
                self.rdata.next = self.rdata.val() | self.s_fault_illegal.val();
            }
            if self.fault_overspeed.val() {
                self.rdata.next = self.rdata.val() | self.s_fault_overspeed.val();
            }
            if self.fault_revolution.val() {
                self.rdata.next = self.rdata.val() | self.s_fault_revolution.val();
            }
        }
        if self.adr.val() == self.a_irq_enable.val() {
            self.rdata.next = self.irq_enable.q.val();
        }
        if self.adr.val() == self.a_irq_status.val() {
            self.rdata.next = self.irq_status.q.val();
        }
        if self.adr.val() == self.a_position.val() {
            self.rdata.next = self.x_position.val();
        }
        if self.adr.val() == self.a_z_latch.val() {
            self.rdata.next = self.x_z_latch.val();
        }
        if self.adr.val() == self.a_nep.val() {
            self.rdata.next = self.x_nep.val();
        }
        if self.adr.val() == self.a_ndt.val() {
            self.rdata.next = self.x_ndt.val();
        }
        if self.adr.val() == self.a_n1_lo.val() {
            self.rdata.next = self.x_n1.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_n1_hi.val() {
            self.rdata.next = self.hi_n1.q.val();
        }
        if self.adr.val() == self.a_n2_lo.val() {
            self.rdata.next = self.x_n2.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_n2_hi.val() {
            self.rdata.next = self.hi_n2.q.val();
        }
        if self.adr.val() == self.a_n3_lo.val() {
            self.rdata.next = self.x_n3.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_n3_hi.val() {
            self.rdata.next = self.hi_n3.q.val();
        }
        if self.adr.val() == self.a_pc_lo.val() {
            self.rdata.next = self.x_pc.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_pc_hi.val() {
            self.rdata.next = self.hi_pc.q.val();
        }
        if self.adr.val() == self.a_et_lo.val() {
            self.rdata.next = self.x_et.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_et_hi.val() {
            self.rdata.next = self.hi_et.q.val();
        }
        if self.adr.val() == self.a_mt_lo.val() {
            self.rdata.next = self.x_mt.val().get_bits::<32>(0);
        }
        if self.adr.val() == self.a_mt_hi.val() {
            self.rdata.next = self.hi_mt.q.val();
        }
        if self.adr.val() == self.a_glitch.val() {
            self.rdata.next = self.x_glitch.val();
        }
        if self.adr.val() == self.a_illegal.val() {
            self.rdata.next = self.x_illegal.val();
        }
        if self.adr.val() == self.a_rev.val() {
            self.rdata.next = self.x_rev.val();
        }

        // Execute the request: ack and read data in the next cycle.
        self.ack.d.next = self.req.val();
        self.dat.d.next = self.z32.val();
        if self.rd.val() {
            self.dat.d.next = self.rdata.val();
            // A LO read latches its HI word.
            if self.adr.val() == self.a_n1_lo.val() {
                self.hi_n1.d.next = self.x_n1.val().get_bits::<32>(32);
            }
            if self.adr.val() == self.a_n2_lo.val() {
                self.hi_n2.d.next = self.x_n2.val().get_bits::<32>(32);
            }
            if self.adr.val() == self.a_n3_lo.val() {
                self.hi_n3.d.next = self.x_n3.val().get_bits::<32>(32);
            }
            if self.adr.val() == self.a_pc_lo.val() {
                self.hi_pc.d.next = self.x_pc.val().get_bits::<32>(32);
            }
            if self.adr.val() == self.a_et_lo.val() {
                self.hi_et.d.next = self.x_et.val().get_bits::<32>(32);
            }
            if self.adr.val() == self.a_mt_lo.val() {
                self.hi_mt.d.next = self.x_mt.val().get_bits::<32>(32);
            }
        }
        self.irq_clear.next = self.z32.val();
        self.clear.d.next = false;
        if self.wr.val() {
            if self.adr.val() == self.a_ctrl.val() {
                self.ctrl.d.next = ((self.ctrl.q.val() & (!self.lanes.val())) | self.ones.val())
                    & self.m_ctrl.val();
            }
            if self.adr.val() == self.a_cfg_dt.val() {
                self.r_cfg_dt.d.next = ((self.r_cfg_dt.q.val() & (!self.lanes.val()))
                    | self.ones.val())
                    & self.m_cfg_dt.val();
            }
            if self.adr.val() == self.a_cfg_timeout.val() {
                self.r_cfg_timeout.d.next = ((self.r_cfg_timeout.q.val() & (!self.lanes.val()))
                    | self.ones.val())
                    & self.m_cfg_timeout.val();
            }
            if self.adr.val() == self.a_cfg_filter.val() {
                self.r_cfg_filter.d.next = ((self.r_cfg_filter.q.val() & (!self.lanes.val()))
                    | self.ones.val())
                    & self.m_cfg_filter.val();
            }
            if self.adr.val() == self.a_irq_enable.val() {
                self.irq_enable.d.next = ((self.irq_enable.q.val() & (!self.lanes.val()))
                    | self.ones.val())
                    & self.m_irq_enable.val();
            }
            if self.adr.val() == self.a_irq_status.val() {
                self.irq_clear.next = self.ones.val() & self.m_irq_w1c.val();
            }
            if self.adr.val() == self.a_status.val() {
                self.clear.d.next = (self.ones.val() & self.m_fault_w1c.val()) != self.z32.val();
            }
        }

        // Interrupt events; an event wins over a clear at the same edge.
        self.fault_rose.next = (self.fault_illegal.val() & (!self.prev_illegal.q.val()))
            | (self.fault_overspeed.val() & (!self.prev_overspeed.q.val()))
            | (self.fault_revolution.val() & (!self.prev_revolution.q.val()));
        self.events.next = self.z32.val();
        if self.speed_strobe.val() {
            self.events.next = self.events.val() | self.e_speed.val();
        }
        if self.baseline_strobe.val() {
            self.events.next = self.events.val() | self.e_baseline.val();
        }
        if self.index.val() {
            self.events.next = self.events.val() | self.e_index.val();
        }
        if self.fault_rose.val() {
            self.events.next = self.events.val() | self.e_fault.val();
        }
        if self.update.val() {
            self.events.next = self.events.val() | self.e_update.val();
        }
        if self.stalled.val() & (!self.prev_stalled.q.val()) {
            self.events.next = self.events.val() | self.e_stall.val();
        }
        self.irq_status.d.next =
            (self.irq_status.q.val() & (!self.irq_clear.val())) | self.events.val();
        self.prev_illegal.d.next = self.fault_illegal.val();
        self.prev_overspeed.d.next = self.fault_overspeed.val();
        self.prev_revolution.d.next = self.fault_revolution.val();
        self.prev_stalled.d.next = self.stalled.val();

        if self.reset.val() {
            self.ack.d.next = false;
            self.dat.d.next = self.z32.val();
            self.ctrl.d.next = self.z32.val();
            self.r_cfg_dt.d.next = self.z32.val();
            self.r_cfg_timeout.d.next = self.z32.val();
            self.r_cfg_filter.d.next = self.z32.val();
            self.irq_enable.d.next = self.z32.val();
            self.irq_status.d.next = self.z32.val();
            self.hi_n1.d.next = self.z32.val();
            self.hi_n2.d.next = self.z32.val();
            self.hi_n3.d.next = self.z32.val();
            self.hi_pc.d.next = self.z32.val();
            self.hi_et.d.next = self.z32.val();
            self.hi_mt.d.next = self.z32.val();
            self.clear.d.next = false;
            self.prev_illegal.d.next = false;
            self.prev_overspeed.d.next = false;
            self.prev_revolution.d.next = false;
            self.prev_stalled.d.next = false;
        }

        // Outputs: registers only.
        self.wb_ack_o.next = self.ack.q.val();
        self.wb_dat_o.next = self.dat.q.val();
        self.irq.next = (self.irq_status.q.val() & self.irq_enable.q.val()) != self.z32.val();
        self.cfg_dt.next = self.r_cfg_dt.q.val().get_bits::<N>(0);
        self.cfg_timeout.next = self.r_cfg_timeout.q.val().get_bits::<N>(0);
        self.cfg_filter.next = self.r_cfg_filter.q.val().get_bits::<FB>(0);
        // One pass each: the loop variable carries the map's offset into the slice.
        for lsb in CTRL_MODE_LSB..(CTRL_MODE_LSB + 1) {
            self.cfg_mode.next = self.ctrl.q.val().get_bits::<2>(lsb);
        }
        for lsb in CTRL_Z_MODE_LSB..(CTRL_Z_MODE_LSB + 1) {
            self.cfg_z_mode.next = self.ctrl.q.val().get_bits::<2>(lsb);
        }
        self.clear_faults.next = self.clear.q.val();
    }
}

/// The Verilog of a `WbRegs<N, S, C, FB, G>` for `map`, top module named `module_name`.
pub fn wb_regs_verilog<
    const N: usize,
    const S: usize,
    const C: usize,
    const FB: usize,
    const G: usize,
>(
    map: &RegMap,
    module_name: &str,
) -> String {
    let mut uut = WbRegs::<N, S, C, FB, G>::from_map(map);
    uut.connect_all();
    crate::verilog::named_verilog(&uut, module_name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use golden::bus::regmap::MapParams;

    fn map(n: u32, f: u32, c: u32, fb: u32, g: u32) -> RegMap {
        RegMap::from_map_params(MapParams::for_widths(n, f, c, fb, g))
    }

    #[test]
    fn synthesises() {
        let m = map(24, 16, 32, 16, 16);
        yosys_validate(
            "encspeed_wb_regs",
            &wb_regs_verilog::<24, 41, 32, 16, 16>(&m, "top"),
        )
        .unwrap();
        let m = map(8, 2, 4, 1, 1);
        yosys_validate(
            "encspeed_wb_regs_small",
            &wb_regs_verilog::<8, 11, 4, 1, 1>(&m, "top"),
        )
        .unwrap();
    }

    #[test]
    fn verilator_lint_is_clean() {
        let lint = |v: String| crate::test_support::verilator_lint("wb_regs", &v);
        lint(wb_regs_verilog::<24, 41, 32, 16, 16>(
            &map(24, 16, 32, 16, 16),
            "wb_regs",
        ));
        lint(wb_regs_verilog::<8, 11, 4, 1, 1>(
            &map(8, 2, 4, 1, 1),
            "wb_regs",
        ));
        lint(wb_regs_verilog::<32, 57, 32, 32, 32>(
            &map(32, 24, 32, 32, 32),
            "wb_regs",
        ));
    }

    #[test]
    fn new_refuses_widths_other_than_the_parameters() {
        let p = Params::new(golden::params::Spec::default()).unwrap();
        let r = std::panic::catch_unwind(|| WbRegs::<8, 11, 4, 1, 1>::new(&p));
        assert!(r.is_err());
    }
}
