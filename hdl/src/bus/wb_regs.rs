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
//! | `wb_ack_o` | out | 1 | high for one cycle from the edge after the request edge |
//! | `irq` | out | 1 | level: (`IRQ_STATUS` & `IRQ_ENABLE`) ≠ 0 |
//! | `cfg_dt`, `cfg_timeout` | out | N | `CFG_DT`, `CFG_TIMEOUT` |
//! | `cfg_filter` | out | FB | `CFG_FILTER` |
//! | `cfg_mode`, `cfg_z_mode` | out | 2 | `CTRL.MODE`, `CTRL.Z_MODE` |
//! | `clear_faults` | out | 1 | one cycle after a write of 1 to a `STATUS` fault bit |
//! | `sample` | in | 1 | take a snapshot at this edge (ignored while `CTRL.HOLD`) |
//! | `position`, `z_latch` | in | C | core outputs |
//! | `nep`, `ndt` | in | N | core outputs |
//! | `speed_n1..n3`, `speed_pc`, `speed_et`, `speed_mt` | in | S | core outputs (two's complement) |
//! | `index`, `direction`, `update`, `speed_strobe`, `baseline_strobe`, `valid`, `stalled`, `fault_illegal`, `fault_overspeed`, `fault_revolution`, `cfg_error` | in | 1 | core outputs |
//! | `glitch_count`, `illegal_count`, `rev_error_count` | in | G | core outputs |
//! | `snap_hold`, `snap_trigger`, `snap_sampled` | out | 1 | `CTRL.HOLD`, the `CTRL.TRIGGER` pulse, `CTRL.SAMPLED`: the snapshot's controls, for the eccentricity window of `encspeed_ecc_wb` (a snapshot is taken at an edge with (`sample` & !`snap_hold`) \| `snap_trigger`) |
//!
//! Every output is a register or a function of registers only (`irq`: an AND-OR of two).
//!
//! # Timing
//!
//! A request sampled at edge k (`wb_cyc_i & wb_stb_i` while `wb_ack_o` is low and no
//! request was taken at edge k − 1) is executed at edge k and acknowledged in the cycle
//! after edge k + 1: three cycles per access, `wb_ack_o` low for at least two cycles
//! between accesses (the read data's second register stage, [`crate::bus::read_data`]). A
//! status input is read as it stood before edge k. A configuration write shows on its port
//! after edge k; `clear_faults` is high in the cycle after edge k (the cycle before
//! `wb_ack_o`).
//!
//! # Implementation
//!
//! A [`RegFile`] (the Wishbone front end, the registered read data and the interrupt pair
//! `IRQ_ENABLE`/`IRQ_STATUS`) and one cell per register of the map, each built from the
//! map's entry: [`ConstCell`] for the constants,
//! [`RwCell`] for `CTRL` and the `CFG_*` words, [`ReadCell`] for the live words (the
//! `STATUS` word is assembled here from the flags at the map's bit positions),
//! [`ShadowCell`] for the six LO/HI speed pairs and [`PulseCell`] for `clear_faults` and
//! `CTRL.TRIGGER`; the [`Snapshot`] between the core's values and the cells that read them.
//! What is this file's own: the interrupt events (strobes, rising edges of the fault flags
//! and of `stalled`, snapshots taken), the snapshot's `take`, and the slicing of `CTRL` into
//! `cfg_mode`, `cfg_z_mode`, `SAMPLED`, `HOLD` at the map's [`CTRL_MODE_LSB`],
//! [`CTRL_Z_MODE_LSB`], [`CTRL_SAMPLED_LSB`], [`CTRL_HOLD_LSB`] through a one-pass loop
//! variable (a const in a slice would be emitted as an undeclared identifier).

use crate::bus::const_cell::ConstCell;
use crate::bus::pulse_cell::PulseCell;
use crate::bus::read_cell::ReadCell;
use crate::bus::reg_file::RegFile;
use crate::bus::rw_cell::RwCell;
use crate::bus::shadow_cell::ShadowCell;
use crate::bus::snapshot::Snapshot;
use golden::bus::regmap::{
    Access, RegMap, ADDR_BITS, CTRL_HOLD_LSB, CTRL_MODE_LSB, CTRL_SAMPLED_LSB, CTRL_TRIGGER_LSB,
    CTRL_Z_MODE_LSB, MODE_BITS, SPEEDS,
};
use golden::params::Params;
use rust_hdl::prelude::*;

/// The `WbRegs` type for counter width `$n`, `$f` speed fraction bits, position width
/// `$c`, filter width `$fb` and fault-counter width `$g`: `wb_regs_type!(24, 16, 32, 16, 16)`
/// is `WbRegs<24, 41, 32, 16, 16>`.
#[macro_export]
macro_rules! wb_regs_type {
    ($n:expr, $f:expr, $c:expr, $fb:expr, $g:expr) => {
        $crate::bus::wb_regs::WbRegs<{ $n }, { $n + $f + 1 }, { $c }, { $fb }, { $g }>
    };
}

/// Width of `CTRL`'s RW fields (`MODE`, `Z_MODE`, `SAMPLED`, `HOLD`).
const CTRL_BITS: usize = 10;

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
    /// Take a snapshot (unless `CTRL.HOLD`).
    pub sample: Signal<In, Bit>,
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
    // The snapshot's controls, for the eccentricity window of `encspeed_ecc_wb`, which
    // stores its corrected speeds with the same strobe. Last among the ports, and
    // registers only, so that they change `encspeed_wb`'s netlist as little as possible: a
    // yosys netlist moves with any added port, and nextpnr's placement with it
    // (docs/resources.md, "Placement noise").
    /// `CTRL.HOLD`.
    pub snap_hold: Signal<Out, Bit>,
    /// The `CTRL.TRIGGER` pulse (high in the cycle after the write of 1).
    pub snap_trigger: Signal<Out, Bit>,
    /// `CTRL.SAMPLED`.
    pub snap_sampled: Signal<Out, Bit>,
    // Front end, read data and the cells, in map order.
    file: RegFile,
    id: ConstCell,
    version: ConstCell,
    param0: ConstCell,
    param1: ConstCell,
    lines: ConstCell,
    dt_default: ConstCell,
    timeout_default: ConstCell,
    clock_hz: ConstCell,
    ctrl: RwCell<CTRL_BITS>,
    r_cfg_dt: RwCell<N>,
    r_cfg_timeout: RwCell<N>,
    r_cfg_filter: RwCell<FB>,
    status: ReadCell<32>,
    fault_clear: PulseCell,
    trigger: PulseCell,
    snapshot: Snapshot<N, S, C>,
    snap_count: ReadCell<32>,
    sampled: Signal<Local, Bit>,
    hold: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    r_position: ReadCell<C>,
    r_z_latch: ReadCell<C>,
    r_nep: ReadCell<N>,
    r_ndt: ReadCell<N>,
    n1: ShadowCell<S>,
    n2: ShadowCell<S>,
    n3: ShadowCell<S>,
    pc: ShadowCell<S>,
    et: ShadowCell<S>,
    mt: ShadowCell<S>,
    glitch: ReadCell<G>,
    illegal: ReadCell<G>,
    rev: ReadCell<G>,
    // Interrupt events: previous levels of the flags whose rising edges are events.
    prev_illegal: DFF<Bit>,
    prev_overspeed: DFF<Bit>,
    prev_revolution: DFF<Bit>,
    prev_stalled: DFF<Bit>,
    status_word: Signal<Local, Bits<32>>,
    events: Signal<Local, Bits<32>>,
    fault_rose: Signal<Local, Bit>,
    // Bit positions, from the map.
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
    e_sample: Constant<Bits<32>>,
    z32: Constant<Bits<32>>,
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
        assert_eq!(ctrl.field("SAMPLED").lsb as usize, CTRL_SAMPLED_LSB);
        assert_eq!(ctrl.field("HOLD").lsb as usize, CTRL_HOLD_LSB);
        assert_eq!(ctrl.field("TRIGGER").lsb as usize, CTRL_TRIGGER_LSB);
        let r = |name: &str| map.reg(name);
        let k = |v: u32| -> Constant<Bits<32>> { Constant::new(u64::from(v).into()) };
        let status = |field: &str| k(map.mask("STATUS", field));
        let event = |field: &str| k(map.mask("IRQ_STATUS", field));
        let shadow = |k: usize| {
            let (lo, hi, _) = SPEEDS[k];
            ShadowCell::new(map.at(lo).unwrap(), map.at(hi).unwrap())
        };
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
            sample: Default::default(),
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
            snap_hold: Default::default(),
            snap_trigger: Default::default(),
            snap_sampled: Default::default(),
            file: RegFile::new(r("IRQ_ENABLE"), r("IRQ_STATUS")),
            id: ConstCell::new(r("ID")),
            version: ConstCell::new(r("VERSION")),
            param0: ConstCell::new(r("PARAM0")),
            param1: ConstCell::new(r("PARAM1")),
            lines: ConstCell::new(r("LINES")),
            dt_default: ConstCell::new(r("DT_DEFAULT")),
            timeout_default: ConstCell::new(r("TIMEOUT_DEFAULT")),
            clock_hz: ConstCell::new(r("CLOCK_HZ")),
            ctrl: RwCell::new(ctrl),
            r_cfg_dt: RwCell::new(r("CFG_DT")),
            r_cfg_timeout: RwCell::new(r("CFG_TIMEOUT")),
            r_cfg_filter: RwCell::new(r("CFG_FILTER")),
            status: ReadCell::new(r("STATUS")),
            fault_clear: PulseCell::new(r("STATUS"), r("STATUS").mask_of(Access::W1c)),
            trigger: PulseCell::new(ctrl, ctrl.field("TRIGGER").mask()),
            snapshot: Default::default(),
            snap_count: ReadCell::new(r("SNAP_COUNT")),
            sampled: Default::default(),
            hold: Default::default(),
            take: Default::default(),
            r_position: ReadCell::new(r("POSITION")),
            r_z_latch: ReadCell::new(r("Z_LATCH")),
            r_nep: ReadCell::new(r("NEP")),
            r_ndt: ReadCell::new(r("NDT")),
            n1: shadow(0),
            n2: shadow(1),
            n3: shadow(2),
            pc: shadow(3),
            et: shadow(4),
            mt: shadow(5),
            glitch: ReadCell::new(r("GLITCH_COUNT")),
            illegal: ReadCell::new(r("ILLEGAL_COUNT")),
            rev: ReadCell::new(r("REV_ERROR_COUNT")),
            prev_illegal: Default::default(),
            prev_overspeed: Default::default(),
            prev_revolution: Default::default(),
            prev_stalled: Default::default(),
            status_word: Default::default(),
            events: Default::default(),
            fault_rose: Default::default(),
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
            e_sample: event("SAMPLE"),
            z32: k(0),
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
            prev_illegal,
            prev_overspeed,
            prev_revolution,
            prev_stalled
        );
        clock!(
            self,
            clock,
            file,
            ctrl,
            r_cfg_dt,
            r_cfg_timeout,
            r_cfg_filter,
            fault_clear,
            trigger,
            snapshot,
            n1,
            n2,
            n3,
            pc,
            et,
            mt
        );
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

        // Constants.
        self.id.adr.next = self.file.adr.val();
        self.version.adr.next = self.file.adr.val();
        self.param0.adr.next = self.file.adr.val();
        self.param1.adr.next = self.file.adr.val();
        self.lines.adr.next = self.file.adr.val();
        self.dt_default.adr.next = self.file.adr.val();
        self.timeout_default.adr.next = self.file.adr.val();
        self.clock_hz.adr.next = self.file.adr.val();

        // Configuration: CTRL and the CFG_* words drive the core's inputs.
        self.ctrl.reset.next = self.reset.val();
        self.ctrl.adr.next = self.file.adr.val();
        self.ctrl.wr.next = self.file.wr.val();
        self.ctrl.lanes.next = self.file.lanes.val();
        self.ctrl.ones.next = self.file.ones.val();
        self.r_cfg_dt.reset.next = self.reset.val();
        self.r_cfg_dt.adr.next = self.file.adr.val();
        self.r_cfg_dt.wr.next = self.file.wr.val();
        self.r_cfg_dt.lanes.next = self.file.lanes.val();
        self.r_cfg_dt.ones.next = self.file.ones.val();
        self.r_cfg_timeout.reset.next = self.reset.val();
        self.r_cfg_timeout.adr.next = self.file.adr.val();
        self.r_cfg_timeout.wr.next = self.file.wr.val();
        self.r_cfg_timeout.lanes.next = self.file.lanes.val();
        self.r_cfg_timeout.ones.next = self.file.ones.val();
        self.r_cfg_filter.reset.next = self.reset.val();
        self.r_cfg_filter.adr.next = self.file.adr.val();
        self.r_cfg_filter.wr.next = self.file.wr.val();
        self.r_cfg_filter.lanes.next = self.file.lanes.val();
        self.r_cfg_filter.ones.next = self.file.ones.val();
        self.cfg_dt.next = self.r_cfg_dt.q.val();
        self.cfg_timeout.next = self.r_cfg_timeout.q.val();
        self.cfg_filter.next = self.r_cfg_filter.q.val();
        // One pass each: the loop variable carries the map's offset into the slice.
        for lsb in CTRL_MODE_LSB..(CTRL_MODE_LSB + 1) {
            self.cfg_mode.next = self.ctrl.q.val().get_bits::<2>(lsb);
        }
        for lsb in CTRL_Z_MODE_LSB..(CTRL_Z_MODE_LSB + 1) {
            self.cfg_z_mode.next = self.ctrl.q.val().get_bits::<2>(lsb);
        }
        for lsb in CTRL_SAMPLED_LSB..(CTRL_SAMPLED_LSB + 1) {
            self.sampled.next = self.ctrl.q.val().get_bit(lsb);
        }
        for lsb in CTRL_HOLD_LSB..(CTRL_HOLD_LSB + 1) {
            self.hold.next = self.ctrl.q.val().get_bit(lsb);
        }

        // The snapshot: by `sample` unless HOLD, or by a write of 1 to CTRL.TRIGGER.
        self.trigger.reset.next = self.reset.val();
        self.trigger.adr.next = self.file.adr.val();
        self.trigger.wr.next = self.file.wr.val();
        self.trigger.ones.next = self.file.ones.val();
        self.snapshot.reset.next = self.reset.val();
        self.take.next = (self.sample.val() & (!self.hold.val())) | self.trigger.pulse.val();
        self.snapshot.take.next = self.take.val();
        self.snapshot.sampled.next = self.sampled.val();
        // The snapshot's controls for the eccentricity window of encspeed_ecc_wb, which
        // applies the rule of `take` above to them (after they are assigned: a local read
        // before its assignment is a latch to rust-hdl).
        self.snap_hold.next = self.hold.val();
        self.snap_trigger.next = self.trigger.pulse.val();
        self.snap_sampled.next = self.sampled.val();
        self.snapshot.position.next = self.position.val();
        self.snapshot.nep.next = self.nep.val();
        self.snapshot.ndt.next = self.ndt.val();
        self.snapshot.speed_n1.next = self.speed_n1.val();
        self.snapshot.speed_n2.next = self.speed_n2.val();
        self.snapshot.speed_n3.next = self.speed_n3.val();
        self.snapshot.speed_pc.next = self.speed_pc.val();
        self.snapshot.speed_et.next = self.speed_et.val();
        self.snapshot.speed_mt.next = self.speed_mt.val();
        self.snapshot.valid.next = self.valid.val();
        self.snapshot.stalled.next = self.stalled.val();
        self.snapshot.direction.next = self.direction.val();
        self.snap_count.adr.next = self.file.adr.val();
        self.snap_count.value.next = self.snapshot.count.val();

        // STATUS: the flags, live; a 1 written to a fault bit clears the core's faults.
        self.status_word.next = self.z32.val();
        if self.snapshot.seen_valid.val() {
            self.status_word.next = self.status_word.val() | self.s_valid.val();
        }
        if self.snapshot.seen_stalled.val() {
            self.status_word.next = self.status_word.val() | self.s_stalled.val();
        }
        if self.snapshot.seen_direction.val() {
            self.status_word.next = self.status_word.val() | self.s_direction.val();
        }
        if self.cfg_error.val() {
            self.status_word.next = self.status_word.val() | self.s_cfg_error.val();
        }
        if self.fault_illegal.val() {
            self.status_word.next = self.status_word.val() | self.s_fault_illegal.val();
        }
        if self.fault_overspeed.val() {
            self.status_word.next = self.status_word.val() | self.s_fault_overspeed.val();
        }
        if self.fault_revolution.val() {
            self.status_word.next = self.status_word.val() | self.s_fault_revolution.val();
        }
        self.status.adr.next = self.file.adr.val();
        self.status.value.next = self.status_word.val();
        self.fault_clear.reset.next = self.reset.val();
        self.fault_clear.adr.next = self.file.adr.val();
        self.fault_clear.wr.next = self.file.wr.val();
        self.fault_clear.ones.next = self.file.ones.val();
        self.clear_faults.next = self.fault_clear.pulse.val();

        // Live words.
        self.r_position.adr.next = self.file.adr.val();
        self.r_position.value.next = self.snapshot.seen_position.val();
        self.r_z_latch.adr.next = self.file.adr.val();
        self.r_z_latch.value.next = self.z_latch.val();
        self.r_nep.adr.next = self.file.adr.val();
        self.r_nep.value.next = self.snapshot.seen_nep.val();
        self.r_ndt.adr.next = self.file.adr.val();
        self.r_ndt.value.next = self.snapshot.seen_ndt.val();
        self.glitch.adr.next = self.file.adr.val();
        self.glitch.value.next = self.glitch_count.val();
        self.illegal.adr.next = self.file.adr.val();
        self.illegal.value.next = self.illegal_count.val();
        self.rev.adr.next = self.file.adr.val();
        self.rev.value.next = self.rev_error_count.val();

        // The speeds: LO/HI pairs.
        self.n1.reset.next = self.reset.val();
        self.n1.adr.next = self.file.adr.val();
        self.n1.rd.next = self.file.rd.val();
        self.n1.value.next = self.snapshot.seen_n1.val();
        self.n2.reset.next = self.reset.val();
        self.n2.adr.next = self.file.adr.val();
        self.n2.rd.next = self.file.rd.val();
        self.n2.value.next = self.snapshot.seen_n2.val();
        self.n3.reset.next = self.reset.val();
        self.n3.adr.next = self.file.adr.val();
        self.n3.rd.next = self.file.rd.val();
        self.n3.value.next = self.snapshot.seen_n3.val();
        self.pc.reset.next = self.reset.val();
        self.pc.adr.next = self.file.adr.val();
        self.pc.rd.next = self.file.rd.val();
        self.pc.value.next = self.snapshot.seen_pc.val();
        self.et.reset.next = self.reset.val();
        self.et.adr.next = self.file.adr.val();
        self.et.rd.next = self.file.rd.val();
        self.et.value.next = self.snapshot.seen_et.val();
        self.mt.reset.next = self.reset.val();
        self.mt.adr.next = self.file.adr.val();
        self.mt.rd.next = self.file.rd.val();
        self.mt.value.next = self.snapshot.seen_mt.val();

        // Read data: the cells' words (each 0 away from its offset), grouped by 16-byte block
        // of the map (a group's words share the offset's bits 7:4, so that its address
        // decode is one term; the constants of 0x00-0x1C, which need no data path, together).
        self.file.group0.next = self.id.rdata.val()
            | self.version.rdata.val()
            | self.param0.rdata.val()
            | self.param1.rdata.val()
            | self.lines.rdata.val()
            | self.dt_default.rdata.val()
            | self.timeout_default.rdata.val()
            | self.clock_hz.rdata.val();
        self.file.group1.next = self.ctrl.rdata.val()
            | self.r_cfg_dt.rdata.val()
            | self.r_cfg_timeout.rdata.val()
            | self.r_cfg_filter.rdata.val();
        self.file.group2.next = self.status.rdata.val() | self.file.irq_rdata.val();
        self.file.group3.next = self.r_position.rdata.val()
            | self.r_z_latch.rdata.val()
            | self.r_nep.rdata.val()
            | self.r_ndt.rdata.val();
        self.file.group4.next = self.n1.rdata.val() | self.n2.rdata.val();
        self.file.group5.next = self.n3.rdata.val() | self.pc.rdata.val();
        self.file.group6.next = self.et.rdata.val() | self.mt.rdata.val();
        self.file.group7.next = self.glitch.rdata.val()
            | self.illegal.rdata.val()
            | self.rev.rdata.val()
            | self.snap_count.rdata.val();

        // Interrupt events: the strobes and the rising edges of the faults and of stalled.
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
        if self.take.val() {
            self.events.next = self.events.val() | self.e_sample.val();
        }
        self.file.events.next = self.events.val();
        self.prev_illegal.d.next = self.fault_illegal.val();
        self.prev_overspeed.d.next = self.fault_overspeed.val();
        self.prev_revolution.d.next = self.fault_revolution.val();
        self.prev_stalled.d.next = self.stalled.val();
        if self.reset.val() {
            self.prev_illegal.d.next = false;
            self.prev_overspeed.d.next = false;
            self.prev_revolution.d.next = false;
            self.prev_stalled.d.next = false;
        }
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
