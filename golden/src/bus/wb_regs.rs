// SPDX-License-Identifier: MIT OR Apache-2.0
//! Cycle model of the Wishbone register file of `encspeed_core` (the block
//! `hdl::WbRegs`): bus signals and the core's status outputs in, bus outputs and the
//! core's configuration inputs out. The register map, the bus protocol, coherence, faults
//! and interrupts are specified in [`crate::bus::regmap`]; this model implements that text.
//!
//! Conventions as in [`crate::estimator::sync_estimator`]: one [`WbRegsModel::step`] per rising clock edge
//! with the inputs applied during the cycle before it; every register is updated from the
//! values before the edge; `step` returns the outputs after the edge. Every output is a
//! register or a function of registers only. Per edge, when `reset` is low:
//! - request = `wb_cyc_i & wb_stb_i & !wb_ack_o & !pending`; `pending` ← request;
//!   `wb_ack_o` ← `pending` (the ack is high in the cycle after the edge after the
//!   request's); the register at `wb_adr_i` (bits 1:0 ignored) as it stands before the
//!   request's edge if the request reads, else 0, is `wb_dat_o` in the ack cycle (0 in
//!   every other);
//! - a read of a speed's LO register loads that speed's HI shadow with bits 63:32 of the
//!   speed sign-extended from S to 64 bits;
//! - a write stores `(old & !lanes) | (wb_dat_i & lanes)` in the RW bits of the register
//!   (`lanes` = the byte lanes of `wb_sel_i`); W1C bits: `wb_dat_i & lanes` are the bits
//!   written 1;
//! - `clear_faults` ← a write to `STATUS` with a 1 written to a fault bit;
//! - `IRQ_STATUS` ← (`IRQ_STATUS` & !(bits written 1)) | events, the events being the
//!   strobes `speed_strobe`, `baseline_strobe`, `index`, `update` and the rising edges of
//!   (any) fault flag and of `stalled` (previous levels registered, 0 after reset), and
//!   `SAMPLE` when a snapshot is taken;
//! - a snapshot is taken when `sample & !CTRL.HOLD`, or `trigger` (the `CTRL.TRIGGER`
//!   pulse, high in the cycle after a write of 1) is high: the snapshot ← `position`, `nep`,
//!   `ndt`, the speeds, `valid`, `stalled`, `direction`; `SNAP_COUNT` ← `SNAP_COUNT` + 1
//!   (modulo 2^32);
//! - with `CTRL.SAMPLED`, the value registers (and the speeds' LO/HI) read the snapshot.

use crate::bus::reg_file::{sign_extend, Cycle, RegFileModel, WbBus};
use crate::bus::regmap::{
    self, Access, MapParams, RegMap, CTRL_HOLD_LSB, CTRL_MODE_LSB, CTRL_SAMPLED_LSB,
    CTRL_TRIGGER_LSB, CTRL_Z_MODE_LSB, SPEEDS,
};
use crate::params::Params;

/// The core's outputs that the register file reads, named as its ports. Values are the
/// ports' bit patterns: unsigned, and the speeds as S-bit two's complement (`raw`, as
/// [`crate::estimator::speed_calc::SpeedFormat::to_raw`] gives them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(missing_docs)]
pub struct CoreStatus {
    pub position: u64,
    pub z_latch: u64,
    pub index: bool,
    pub direction: bool,
    pub nep: u64,
    pub ndt: u64,
    pub update: bool,
    pub speed_n1: u64,
    pub speed_n2: u64,
    pub speed_n3: u64,
    pub speed_strobe: bool,
    pub speed_pc: u64,
    pub speed_et: u64,
    pub speed_mt: u64,
    pub baseline_strobe: bool,
    pub valid: bool,
    pub stalled: bool,
    pub fault_illegal: bool,
    pub fault_overspeed: bool,
    pub fault_revolution: bool,
    pub cfg_error: bool,
    pub glitch_count: u64,
    pub illegal_count: u64,
    pub rev_error_count: u64,
}

impl CoreStatus {
    /// The six speeds in the order of [`SPEEDS`].
    pub fn speeds(&self) -> [u64; 6] {
        [
            self.speed_n1,
            self.speed_n2,
            self.speed_n3,
            self.speed_pc,
            self.speed_et,
            self.speed_mt,
        ]
    }
}

/// Inputs of one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WbRegsInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Take a snapshot (unless `CTRL.HOLD`).
    pub sample: bool,
    /// Wishbone inputs.
    pub bus: WbBus,
    /// The core's status outputs.
    pub status: CoreStatus,
}

/// Outputs after a clock edge, named as the ports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WbRegsOutputs {
    /// Acknowledge (one cycle per access).
    pub wb_ack_o: bool,
    /// Read data (0 unless `wb_ack_o` of a read).
    pub wb_dat_o: u32,
    /// Interrupt request, level.
    pub irq: bool,
    /// `CFG_DT`.
    pub cfg_dt: u64,
    /// `CFG_TIMEOUT`.
    pub cfg_timeout: u64,
    /// `CFG_FILTER`.
    pub cfg_filter: u64,
    /// `CTRL.MODE`.
    pub cfg_mode: u8,
    /// `CTRL.Z_MODE`.
    pub cfg_z_mode: u8,
    /// One cycle: clear the core's sticky faults.
    pub clear_faults: bool,
}

/// The values a snapshot holds (0 after reset), and how many were taken.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Snapshot {
    /// `position`, `nep`, `ndt`, the six speeds and the levels `valid`, `stalled`,
    /// `direction` (the other fields 0) as the core output them in the sampled cycle.
    pub values: CoreStatus,
    /// `SNAP_COUNT`: snapshots taken since reset, modulo 2^32.
    pub count: u32,
}

impl Snapshot {
    /// The snapshot of `st`.
    fn of(st: &CoreStatus, count: u32) -> Snapshot {
        Snapshot {
            values: snapshot_fields(st, &CoreStatus::default()),
            count,
        }
    }

    /// `st` with the snapshot's values in place of the live ones.
    fn view(&self, st: &CoreStatus) -> CoreStatus {
        snapshot_fields(&self.values, st)
    }
}

/// `onto` with the fields a snapshot holds taken from `from`: `position`, `nep`, `ndt`, the
/// six speeds, `valid`, `stalled`, `direction`.
fn snapshot_fields(from: &CoreStatus, onto: &CoreStatus) -> CoreStatus {
    CoreStatus {
        position: from.position,
        nep: from.nep,
        ndt: from.ndt,
        speed_n1: from.speed_n1,
        speed_n2: from.speed_n2,
        speed_n3: from.speed_n3,
        speed_pc: from.speed_pc,
        speed_et: from.speed_et,
        speed_mt: from.speed_mt,
        valid: from.valid,
        stalled: from.stalled,
        direction: from.direction,
        ..*onto
    }
}

/// The register file, one step per clock edge: a [`RegFileModel`] with the core's live
/// words, events and configuration outputs.
#[derive(Clone, Debug)]
pub struct WbRegsModel {
    map: RegMap,
    file: RegFileModel,
    snapshot: Snapshot,
    /// fault_illegal, fault_overspeed, fault_revolution before the last edge.
    prev_faults: [bool; 3],
    prev_stalled: bool,
}

/// The file's pulses: `clear_faults`, and the snapshot trigger.
const CLEAR_FAULTS: usize = 0;
const TRIGGER: usize = 1;

impl WbRegsModel {
    /// The register file of `p`, in its reset state.
    pub fn new(p: &Params) -> WbRegsModel {
        WbRegsModel::from_map(RegMap::new(p))
    }

    /// The register file of `map` (e.g. [`RegMap::from_map_params`]), in its reset state.
    pub fn from_map(map: RegMap) -> WbRegsModel {
        let shadows: Vec<(u32, u32)> = SPEEDS.iter().map(|&(lo, hi, _)| (lo, hi)).collect();
        let clear = (regmap::STATUS, map.reg("STATUS").mask_of(Access::W1c));
        let trigger = (regmap::CTRL, 1 << CTRL_TRIGGER_LSB);
        let file = RegFileModel::new(
            map.registers().to_vec(),
            "IRQ_ENABLE",
            "IRQ_STATUS",
            &shadows,
            &[clear, trigger],
        );
        WbRegsModel {
            map,
            file,
            snapshot: Snapshot::default(),
            prev_faults: [false; 3],
            prev_stalled: false,
        }
    }

    /// The register map.
    pub fn map(&self) -> &RegMap {
        &self.map
    }

    fn mp(&self) -> &MapParams {
        self.map.params()
    }

    /// The snapshot as it stands.
    pub fn snapshot(&self) -> Snapshot {
        self.snapshot
    }

    /// `CTRL.SAMPLED` as it stands: the value registers read the snapshot.
    pub fn sampled(&self) -> bool {
        self.file.rw(regmap::CTRL) >> CTRL_SAMPLED_LSB & 1 != 0
    }

    /// Whether the next edge takes a snapshot with `sample` applied: `sample` &
    /// !`CTRL.HOLD`, or the `CTRL.TRIGGER` pulse (`encspeed_ecc_wb` applies the same rule
    /// to the hardware's `snap_hold`/`snap_trigger` outputs for its eccentricity window).
    pub fn take(&self, sample: bool) -> bool {
        let hold = self.file.rw(regmap::CTRL) >> CTRL_HOLD_LSB & 1 != 0;
        (sample && !hold) || self.file.pulse(TRIGGER)
    }

    /// The file takes no request at the next edge (an access in progress).
    pub fn busy(&self) -> bool {
        self.file.busy()
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> WbRegsOutputs {
        let f = &self.file;
        let ctrl = f.rw(regmap::CTRL);
        WbRegsOutputs {
            wb_ack_o: f.ack(),
            wb_dat_o: f.dat(),
            irq: f.irq(),
            cfg_dt: u64::from(f.rw(regmap::CFG_DT)),
            cfg_timeout: u64::from(f.rw(regmap::CFG_TIMEOUT)),
            cfg_filter: u64::from(f.rw(regmap::CFG_FILTER)),
            cfg_mode: ((ctrl >> CTRL_MODE_LSB) & 3) as u8,
            cfg_z_mode: ((ctrl >> CTRL_Z_MODE_LSB) & 3) as u8,
            clear_faults: f.pulse(CLEAR_FAULTS),
        }
    }

    fn check(&self, st: &CoreStatus) {
        let mp = self.mp();
        let fits = |v: u64, bits: u32, what: &str| {
            assert!(v >> bits == 0, "{what} = {v:#x} does not fit {bits} bits");
        };
        fits(st.position, mp.position_bits, "position");
        fits(st.z_latch, mp.position_bits, "z_latch");
        fits(st.nep, mp.counter_bits, "nep");
        fits(st.ndt, mp.counter_bits, "ndt");
        for (v, (_, _, port)) in st.speeds().into_iter().zip(SPEEDS) {
            fits(v, mp.speed_bits(), port);
        }
        fits(st.glitch_count, mp.error_count_bits, "glitch_count");
        fits(st.illegal_count, mp.error_count_bits, "illegal_count");
        fits(st.rev_error_count, mp.error_count_bits, "rev_error_count");
    }

    /// One rising clock edge with `inp` applied; the outputs after it. Panics if a status
    /// value does not fit its port or the address does not fit `wb_adr_i`.
    pub fn step(&mut self, inp: &WbRegsInputs) -> WbRegsOutputs {
        let st = &inp.status;
        self.check(st);
        let take = self.take(inp.sample);
        // What the value registers read: the snapshot before this edge, or the live values.
        let seen = if self.sampled() {
            self.snapshot.view(st)
        } else {
            *st
        };
        let wide = seen
            .speeds()
            .map(|v| sign_extend(v, self.mp().speed_bits()));
        let faults = [st.fault_illegal, st.fault_overspeed, st.fault_revolution];
        let fault_rose = faults.iter().zip(self.prev_faults).any(|(&f, p)| f && !p);
        let ev = |b: bool, field: &str| {
            if b {
                self.map.mask("IRQ_STATUS", field)
            } else {
                0
            }
        };
        let events = ev(st.speed_strobe, "SPEED")
            | ev(st.baseline_strobe, "BASELINE")
            | ev(st.index, "INDEX")
            | ev(fault_rose, "FAULT")
            | ev(st.update, "UPDATE")
            | ev(st.stalled && !self.prev_stalled, "STALL")
            | ev(take, "SAMPLE");
        let cycle = Cycle {
            reset: inp.reset,
            bus: &inp.bus,
            wide: &wide,
            events,
        };
        let map = &self.map;
        let count = self.snapshot.count;
        self.file
            .step(&cycle, &|off| live(map, off, &seen, st, count));
        if inp.reset {
            self.snapshot = Snapshot::default();
        } else if take {
            self.snapshot = Snapshot::of(st, count.wrapping_add(1));
        }
        (self.prev_faults, self.prev_stalled) = if inp.reset {
            ([false; 3], false)
        } else {
            (faults, st.stalled)
        };
        self.outputs()
    }
}

/// The live word at byte offset `off` (word aligned) of `m`: `seen` the status as the
/// value registers read it (live or the snapshot), `st` the live status, `count` the
/// snapshots taken.
fn live(m: &RegMap, off: u32, seen: &CoreStatus, st: &CoreStatus, count: u32) -> u32 {
    let bit = |b: bool, field: &str| if b { m.mask("STATUS", field) } else { 0 };
    match off {
        regmap::STATUS => {
            bit(seen.valid, "VALID")
                | bit(seen.stalled, "STALLED")
                | bit(seen.direction, "DIRECTION")
                | bit(st.cfg_error, "CFG_ERROR")
                | bit(st.fault_illegal, "FAULT_ILLEGAL")
                | bit(st.fault_overspeed, "FAULT_OVERSPEED")
                | bit(st.fault_revolution, "FAULT_REVOLUTION")
        }
        regmap::POSITION => seen.position as u32,
        regmap::Z_LATCH => st.z_latch as u32,
        regmap::NEP => seen.nep as u32,
        regmap::NDT => seen.ndt as u32,
        regmap::SNAP_COUNT => count,
        regmap::GLITCH_COUNT => st.glitch_count as u32,
        regmap::ILLEGAL_COUNT => st.illegal_count as u32,
        regmap::REV_ERROR_COUNT => st.rev_error_count as u32,
        _ => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::reg_file::lane_mask;
    use crate::bus::regmap::*;
    use crate::params::Spec;

    fn model() -> WbRegsModel {
        WbRegsModel::new(&Params::new(Spec::default()).unwrap())
    }

    /// A classic master: hold the request until `wb_ack_o`, then one idle cycle. Returns the
    /// data of the ack cycle and the outputs of the cycle after the request edge (where a
    /// write's effects first show).
    fn access(
        m: &mut WbRegsModel,
        st: &CoreStatus,
        we: bool,
        adr: u32,
        dat: u32,
        sel: u8,
    ) -> (u32, WbRegsOutputs) {
        let inputs = WbRegsInputs {
            reset: false,
            sample: false,
            bus: WbBus {
                wb_cyc_i: true,
                wb_stb_i: true,
                wb_we_i: we,
                wb_adr_i: adr,
                wb_dat_i: dat,
                wb_sel_i: sel,
            },
            status: *st,
        };
        let executed = m.step(&inputs);
        assert!(
            !executed.wb_ack_o,
            "no ack in the cycle after the request edge"
        );
        let acked = m.step(&inputs);
        assert!(
            acked.wb_ack_o,
            "ack in the cycle after the edge after the request's"
        );
        let idle = m.step(&WbRegsInputs {
            status: *st,
            ..Default::default()
        });
        assert!(!idle.wb_ack_o && idle.wb_dat_o == 0);
        (acked.wb_dat_o, executed)
    }

    fn read(m: &mut WbRegsModel, st: &CoreStatus, adr: u32) -> u32 {
        access(m, st, false, adr, 0, 0).0
    }

    fn write(m: &mut WbRegsModel, st: &CoreStatus, adr: u32, dat: u32, sel: u8) -> WbRegsOutputs {
        access(m, st, true, adr, dat, sel).1
    }

    #[test]
    fn a_held_request_is_acked_every_third_cycle() {
        let mut m = model();
        let inp = WbRegsInputs {
            bus: WbBus {
                wb_cyc_i: true,
                wb_stb_i: true,
                wb_adr_i: ID,
                ..Default::default()
            },
            ..Default::default()
        };
        for k in 0..9 {
            let o = m.step(&inp);
            assert_eq!(o.wb_ack_o, k % 3 == 1, "edge {k}");
            assert_eq!(o.wb_dat_o, if k % 3 == 1 { ID_MAGIC } else { 0 });
        }
        // No cyc: no request.
        let o = m.step(&WbRegsInputs {
            bus: WbBus {
                wb_cyc_i: false,
                ..inp.bus
            },
            ..inp
        });
        assert!(!o.wb_ack_o);
    }

    #[test]
    fn constants_read_as_the_map_and_ignore_writes_unmapped_reads_zero() {
        let mut m = model();
        let st = CoreStatus::default();
        let map = m.map().clone();
        for r in map.registers() {
            if r.name.starts_with("SPEED") || r.mask_of(Access::Ro) == 0 {
                continue;
            }
            if let (Some(v), true) = (r.reset, r.mask_of(Access::Rw) == 0) {
                write(&mut m, &st, r.offset, !v, 0xF);
                assert_eq!(read(&mut m, &st, r.offset), v, "{}", r.name);
            }
        }
        for off in [0x3C, 0x8C, 0xFC] {
            write(&mut m, &st, off, u32::MAX, 0xF);
            assert_eq!(read(&mut m, &st, off), 0);
        }
        assert_eq!(read(&mut m, &st, ID + 3), ID_MAGIC, "bits 1:0 ignored");
    }

    #[test]
    fn rw_registers_honour_byte_lanes_and_width() {
        let mut m = model();
        let st = CoreStatus::default();
        let n = m.map().params().counter_bits;
        write(&mut m, &st, CFG_DT, 0xFFFF_FFFF, 0b0101);
        let want = 0x00FF_00FF & ((1u64 << n) - 1) as u32;
        assert_eq!(read(&mut m, &st, CFG_DT), want);
        let o = write(&mut m, &st, CTRL, 0xFFFF_FF06, 0b0001);
        // MODE = 2 (x4), Z_MODE = 1.
        assert_eq!((o.cfg_mode, o.cfg_z_mode), (2, 1));
        assert_eq!(read(&mut m, &st, CTRL), 0x6);
        write(&mut m, &st, CTRL, 0, 0b1110);
        assert_eq!(read(&mut m, &st, CTRL), 0x6, "lane 0 not selected");
        assert_eq!(m.outputs().cfg_dt, u64::from(want));
        // Reset clears them.
        m.step(&WbRegsInputs {
            reset: true,
            ..Default::default()
        });
        assert_eq!(m.outputs(), WbRegsOutputs::default());
    }

    #[test]
    fn lo_then_hi_is_coherent_while_the_speed_changes() {
        let mut m = model();
        let s_bits = m.map().params().speed_bits();
        let raw = |v: i64| (v as u64) & ((1u64 << s_bits) - 1);
        let mut st = CoreStatus {
            speed_n3: raw(-5_000_000_000),
            ..Default::default()
        };
        assert_eq!(read(&mut m, &st, SPEED_N3_HI), 0, "shadow reset value");
        let lo = read(&mut m, &st, SPEED_N3_LO);
        st.speed_n3 = raw(7);
        let hi = read(&mut m, &st, SPEED_N3_HI);
        assert_eq!(
            ((u64::from(hi) << 32) | u64::from(lo)) as i64,
            -5_000_000_000
        );
        assert_eq!(read(&mut m, &st, SPEED_N3_LO), 7);
        assert_eq!(read(&mut m, &st, SPEED_N3_HI), 0);
        assert_eq!(read(&mut m, &st, SPEED_N1_HI), 0, "own shadow per speed");
    }

    /// The snapshot by hand: a `sample` strobe stores one cycle's values, `CTRL.SAMPLED`
    /// reads them in place of the live ones (the fault and cfg_error bits stay live),
    /// `CTRL.HOLD` ignores `sample`, `CTRL.TRIGGER` takes one at the edge after the write
    /// edge; `SNAP_COUNT` counts them and `IRQ_STATUS.SAMPLE` latches each.
    #[test]
    fn a_sample_strobe_takes_a_coherent_snapshot_that_ctrl_sampled_reads() {
        let mut m = model();
        let s_bits = m.map().params().speed_bits();
        let raw = |v: i64| (v as u64) & ((1u64 << s_bits) - 1);
        let then = CoreStatus {
            position: 5,
            nep: 7,
            ndt: 3,
            speed_n3: raw(-5_000_000_000),
            speed_mt: raw(1234),
            valid: true,
            direction: true,
            ..Default::default()
        };
        let now = CoreStatus {
            position: 9,
            nep: 2,
            ndt: 1,
            speed_n3: raw(77),
            stalled: true,
            cfg_error: true,
            fault_illegal: true,
            ..Default::default()
        };
        m.step(&WbRegsInputs {
            sample: true,
            status: then,
            ..Default::default()
        });
        assert_eq!(read(&mut m, &now, SNAP_COUNT), 1);
        // SAMPLE, and FAULT and STALL from `now`'s rising fault_illegal and stalled.
        assert_eq!(read(&mut m, &now, IRQ_STATUS), 0x40 | 0x8 | 0x20);
        assert_eq!(read(&mut m, &now, POSITION), 9, "live while SAMPLED = 0");
        assert_eq!(read(&mut m, &now, STATUS), 0x2 | 0x8 | 0x10);
        // SAMPLED (bit 8, byte lane 1 alone: MODE and Z_MODE stay as written).
        write(&mut m, &now, CTRL, 0x6, 0x1);
        write(&mut m, &now, CTRL, 0x100, 0x2);
        assert_eq!(read(&mut m, &now, CTRL), 0x106);
        assert_eq!((m.outputs().cfg_mode, m.outputs().cfg_z_mode), (2, 1));
        assert_eq!(read(&mut m, &now, POSITION), 5);
        assert_eq!(read(&mut m, &now, NEP), 7);
        assert_eq!(read(&mut m, &now, NDT), 3);
        let lo = read(&mut m, &now, SPEED_N3_LO);
        let hi = read(&mut m, &now, SPEED_N3_HI);
        assert_eq!(
            ((u64::from(hi) << 32) | u64::from(lo)) as i64,
            -5_000_000_000
        );
        assert_eq!(read(&mut m, &now, SPEED_MT_LO), 1234);
        // VALID, DIRECTION from the snapshot; CFG_ERROR, FAULT_ILLEGAL live.
        assert_eq!(read(&mut m, &now, STATUS), 0x1 | 0x4 | 0x8 | 0x10);
        // HOLD: a strobe is ignored.
        write(&mut m, &now, CTRL, 0x300, 0x2);
        m.step(&WbRegsInputs {
            sample: true,
            status: now,
            ..Default::default()
        });
        assert_eq!(read(&mut m, &now, SNAP_COUNT), 1);
        assert_eq!(read(&mut m, &now, POSITION), 5);
        // TRIGGER (bit 10, reads 0): a snapshot at the edge after the write edge, HOLD or not.
        write(&mut m, &now, CTRL, 0x700, 0x2);
        assert_eq!(read(&mut m, &now, CTRL), 0x306);
        assert_eq!(read(&mut m, &now, SNAP_COUNT), 2);
        assert_eq!(read(&mut m, &now, POSITION), 9);
        assert_eq!(read(&mut m, &now, SPEED_N3_LO), 77);
        assert_eq!(read(&mut m, &now, SPEED_N3_HI), 0);
        // Reset: the snapshot and its count are 0.
        m.step(&WbRegsInputs {
            reset: true,
            ..Default::default()
        });
        assert_eq!(m.snapshot(), Snapshot::default());
    }

    #[test]
    fn a_one_written_to_any_fault_bit_pulses_clear_faults_once() {
        let mut m = model();
        let st = CoreStatus {
            fault_overspeed: true,
            valid: true,
            ..Default::default()
        };
        assert_eq!(read(&mut m, &st, STATUS), 0x21);
        let o = write(&mut m, &st, STATUS, 0x10, 0x1);
        assert!(o.clear_faults, "in the cycle after the request edge");
        assert!(!m.outputs().clear_faults, "one cycle");
        for (dat, sel) in [(0x0F, 0x1), (0x70, 0xE), (0xFFFF_FF8F, 0xF)] {
            let o = write(&mut m, &st, STATUS, dat, sel);
            assert!(!o.clear_faults, "{dat:#x} {sel:#x}");
        }
    }

    #[test]
    fn interrupts_latch_events_clear_by_w1c_and_an_event_wins() {
        let mut m = model();
        let mut st = CoreStatus::default();
        let idle = |m: &mut WbRegsModel, st: &CoreStatus| {
            m.step(&WbRegsInputs {
                status: *st,
                ..Default::default()
            })
        };
        st.index = true;
        let o = idle(&mut m, &st);
        assert!(!o.irq, "not enabled");
        st.index = false;
        write(&mut m, &st, IRQ_ENABLE, 0x3F, 0xF);
        assert!(m.outputs().irq);
        assert_eq!(read(&mut m, &st, IRQ_STATUS), 0x4);
        // A fault rising and stalled rising: FAULT and STALL; a level held is not an event.
        st.fault_revolution = true;
        st.stalled = true;
        idle(&mut m, &st);
        assert_eq!(read(&mut m, &st, IRQ_STATUS), 0x4 | 0x8 | 0x20);
        write(&mut m, &st, IRQ_STATUS, 0x2C, 0xF);
        assert_eq!(read(&mut m, &st, IRQ_STATUS), 0);
        assert!(!m.outputs().irq);
        // Clear and event at the same edge: the event wins.
        st.speed_strobe = true;
        let o = write(&mut m, &st, IRQ_STATUS, 0x1, 0xF);
        assert!(o.irq);
        st.speed_strobe = false;
        assert_eq!(read(&mut m, &st, IRQ_STATUS), 0x1);
    }

    #[test]
    fn a_request_during_reset_is_dropped() {
        let mut m = model();
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: true,
            wb_adr_i: CFG_DT,
            wb_dat_i: 9,
            wb_sel_i: 0xF,
        };
        let o = m.step(&WbRegsInputs {
            reset: true,
            bus,
            ..Default::default()
        });
        assert!(!o.wb_ack_o);
        assert_eq!(o.cfg_dt, 0);
    }

    #[test]
    fn sign_extension_and_lanes_by_hand() {
        assert_eq!(sign_extend(0x400, 11), 0xFFFF_FFFF_FFFF_FC00);
        assert_eq!(sign_extend(0x3FF, 11), 0x3FF);
        assert_eq!(lane_mask(0b1010), 0xFF00_FF00);
    }
}
