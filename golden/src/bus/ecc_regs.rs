// SPDX-License-Identifier: MIT OR Apache-2.0
//! Cycle model of the eccentricity window's slave (the block `hdl::EccRegs`): bus signals
//! and `encspeed_ecc`'s corrected speeds and identification results in; bus outputs,
//! `ecc_c`, `ecc_d` and `ident_arm` out. The map and its behaviour are specified in
//! [`crate::bus::ecc_regmap`]; this model implements that text.
//!
//! Conventions as in [`crate::bus::wb_regs`]: one [`EccRegsModel::step`] per rising clock edge
//! with the inputs applied during the cycle before it; `step` returns the outputs after the
//! edge; every output is a register or a function of registers only. Per edge, when
//! `reset` is low:
//! - request = `wb_cyc_i & wb_stb_i & !wb_ack_o & !pending`; `pending` ← request;
//!   `wb_ack_o` ← `pending`; `wb_dat_o` in the ack cycle ← the register at `wb_adr_i`
//!   (bits 1:0 ignored) as it stood before the request's edge if the request reads, else
//!   0 (the top
//!   routes only the window's offsets here, but the slave answers any offset it is given:
//!   0 where nothing is mapped);
//! - a read of a corrected speed's LO register loads its HI shadow;
//! - `ident_arm` ← a write to `ECC_CTRL` with a 1 in `IDENT_ARM` (byte lane 0);
//!   `ecc_c`, `ecc_d` ← `ECC_C`, `ECC_D` (as they stood before the edge) on such a write
//!   with a 1 in `LOAD`;
//! - `ECC_IRQ_STATUS` ← (`ECC_IRQ_STATUS` & !(bits written 1)) | events: `mtc_strobe`,
//!   `n3c_strobe`, `ident_done` rising (previous level registered, 0 after reset);
//! - the snapshot: at an edge with `snap_take` (the core register file's snapshot strobe)
//!   the two corrected speeds are stored as they stand before the edge (0 after reset);
//!   while `snap_sampled` (its `CTRL.SAMPLED`) the `SPEED_MTC`/`SPEED_N3C` pairs read them
//!   instead of the live speeds (a LO read latches HI from the snapshot).

use crate::bus::ecc_regmap::{self, ECC_SPEEDS, IDENT_SUMS};
use crate::bus::reg_file::{sign_extend, Cycle, RegFileModel, WbBus};
use crate::ecc::ident_gatherer::GatherOutputs;

/// What `encspeed_ecc` gives the window, named as its ports: the speeds as S-bit two's
/// complement bit patterns.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccStatus {
    /// `speed_mtc`, S bits.
    pub speed_mtc: u64,
    /// `mtc_strobe`.
    pub mtc_strobe: bool,
    /// `speed_n3c`, S bits.
    pub speed_n3c: u64,
    /// `n3c_strobe`.
    pub n3c_strobe: bool,
    /// The `ident_*` ports.
    pub ident: GatherOutputs,
}

impl EccStatus {
    /// The two corrected speeds in the order of [`ECC_SPEEDS`].
    pub fn speeds(&self) -> [u64; 2] {
        [self.speed_mtc, self.speed_n3c]
    }
}

/// Inputs of one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccRegsInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// Wishbone inputs (the top gates `wb_stb_i` to the window's offsets).
    pub bus: WbBus,
    /// `encspeed_ecc`'s outputs.
    pub status: EccStatus,
    /// Store the corrected speeds at this edge: the core register file's snapshot strobe
    /// (`sample` & !`CTRL.HOLD`, or the `CTRL.TRIGGER` pulse: [`crate::bus::wb_regs::WbRegsModel::take`]).
    pub snap_take: bool,
    /// `CTRL.SAMPLED` of the core's register file: the speed pairs read the snapshot.
    pub snap_sampled: bool,
}

/// Outputs after a clock edge, named as the ports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccRegsOutputs {
    /// Acknowledge (one cycle per access).
    pub wb_ack_o: bool,
    /// Read data (0 unless `wb_ack_o` of a read).
    pub wb_dat_o: u32,
    /// Interrupt request of the window, level.
    pub irq: bool,
    /// `ecc_c`, the 32-bit port pattern.
    pub ecc_c: u32,
    /// `ecc_d`, the 32-bit port pattern.
    pub ecc_d: u32,
    /// One cycle: arm the identification.
    pub ident_arm: bool,
}

impl EccRegsOutputs {
    /// `ecc_c` as a value (two's complement).
    pub fn coef_c(&self) -> i64 {
        i64::from(self.ecc_c as i32)
    }
    /// `ecc_d` as a value (two's complement).
    pub fn coef_d(&self) -> i64 {
        i64::from(self.ecc_d as i32)
    }
}

/// The window's slave, one step per clock edge: a [`RegFileModel`] with the window's live
/// words, events, the loaded coefficients and `ident_arm`.
#[derive(Clone, Debug)]
pub struct EccRegsModel {
    file: RegFileModel,
    masks: FieldMasks,
    speed_bits: u32,
    ecc_c: u32,
    ecc_d: u32,
    prev_done: bool,
    /// The corrected speeds of the last snapshot (S-bit patterns, 0 after reset).
    snapshot: [u64; 2],
}

/// The masks of the fields the window drives or reads each cycle, looked up in the map once.
#[derive(Clone, Copy, Debug)]
struct FieldMasks {
    /// `ECC_IRQ_STATUS` events.
    mtc: u32,
    n3c: u32,
    ident: u32,
    /// `ECC_CTRL.LOAD`.
    load: u32,
    /// `ECC_STATUS` flags.
    done: u32,
    overflow: u32,
}

/// The file's one pulse: `ident_arm`.
const IDENT_ARM: usize = 0;

impl EccRegsModel {
    /// The slave for speeds of `speed_bits` bits (11..=64), in its reset state.
    pub fn new(speed_bits: u32) -> Self {
        use ecc_regmap as m;
        assert!((11..=64).contains(&speed_bits), "speed_bits {speed_bits}");
        let regs = ecc_regmap::registers(speed_bits);
        let shadows: Vec<(u32, u32)> = ECC_SPEEDS.iter().map(|&(lo, hi, _)| (lo, hi)).collect();
        let ctrl = regs.iter().find(|r| r.offset == m::ECC_CTRL).unwrap();
        let arm = (m::ECC_CTRL, ctrl.field("IDENT_ARM").mask());
        let file = RegFileModel::new(regs, "ECC_IRQ_ENABLE", "ECC_IRQ_STATUS", &shadows, &[arm]);
        let mask = |off: u32, name: &str| file.at(off).field(name).mask();
        let masks = FieldMasks {
            mtc: mask(m::ECC_IRQ_STATUS, "MTC"),
            n3c: mask(m::ECC_IRQ_STATUS, "N3C"),
            ident: mask(m::ECC_IRQ_STATUS, "IDENT"),
            load: mask(m::ECC_CTRL, "LOAD"),
            done: mask(m::ECC_STATUS, "IDENT_DONE"),
            overflow: mask(m::ECC_STATUS, "IDENT_OVERFLOW"),
        };
        Self {
            file,
            masks,
            speed_bits,
            ecc_c: 0,
            ecc_d: 0,
            prev_done: false,
            snapshot: [0; 2],
        }
    }

    /// The corrected speeds of the last snapshot, in the order of [`ECC_SPEEDS`].
    pub fn snapshot(&self) -> [u64; 2] {
        self.snapshot
    }

    /// The slave takes no request at the next edge (an access in progress).
    pub fn busy(&self) -> bool {
        self.file.busy()
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> EccRegsOutputs {
        let f = &self.file;
        EccRegsOutputs {
            wb_ack_o: f.ack(),
            wb_dat_o: f.dat(),
            irq: f.irq(),
            ecc_c: self.ecc_c,
            ecc_d: self.ecc_d,
            ident_arm: f.pulse(IDENT_ARM),
        }
    }

    fn check(&self, st: &EccStatus) {
        let fits = |v: u64, bits: u32, what: &str| {
            assert!(
                bits >= 64 || v >> bits == 0,
                "{what} = {v:#x} does not fit {bits} bits"
            );
        };
        fits(st.speed_mtc, self.speed_bits, "speed_mtc");
        fits(st.speed_n3c, self.speed_bits, "speed_n3c");
        let g = &st.ident;
        fits(g.count, 17, "ident_count");
        fits(g.t_min, 32, "ident_t_min");
        fits(g.t_max, 32, "ident_t_max");
        fits(g.p_min, 16, "ident_p_min");
        fits(g.p_max, 16, "ident_p_max");
        let bound = 1i128 << (crate::ecc::line_tap::IDENT_SUM_BITS - 1);
        for v in [g.sum_t, g.sum_sin, g.sum_cos] {
            assert!((-bound..bound).contains(&v), "sum {v} does not fit 72 bits");
        }
    }

    /// One rising clock edge with `inp` applied; the outputs after it. Panics if a status
    /// value does not fit its port or the address does not fit `wb_adr_i`.
    pub fn step(&mut self, inp: &EccRegsInputs) -> EccRegsOutputs {
        use ecc_regmap as m;
        let st = &inp.status;
        self.check(st);
        // What the speed pairs read: the snapshot before this edge, or the live speeds.
        let seen = if inp.snap_sampled {
            self.snapshot
        } else {
            st.speeds()
        };
        let wide = seen.map(|v| sign_extend(v, self.speed_bits));
        let k = self.masks;
        let ev = |b: bool, mask: u32| if b { mask } else { 0 };
        let events = ev(st.mtc_strobe, k.mtc)
            | ev(st.n3c_strobe, k.n3c)
            | ev(st.ident.done && !self.prev_done, k.ident);
        // The staged coefficients as they stand before the edge.
        let staged = (self.file.rw(m::ECC_C), self.file.rw(m::ECC_D));
        let cycle = Cycle {
            reset: inp.reset,
            bus: &inp.bus,
            wide: &wide,
            events,
        };
        let flags = (k.done, k.overflow);
        let req = self.file.step(&cycle, &|off| live(off, st, flags));
        if inp.reset {
            (self.ecc_c, self.ecc_d, self.prev_done) = (0, 0, false);
            self.snapshot = [0; 2];
        } else {
            if inp.snap_take {
                self.snapshot = st.speeds();
            }
            if req.writes_one(m::ECC_CTRL, k.load) {
                (self.ecc_c, self.ecc_d) = staged;
            }
            self.prev_done = st.ident.done;
        }
        self.outputs()
    }
}

/// The live word at offset `off` with `st`; `flags` are the masks of `ECC_STATUS`'s
/// `IDENT_DONE` and `IDENT_OVERFLOW`.
fn live(off: u32, st: &EccStatus, flags: (u32, u32)) -> u32 {
    use ecc_regmap as m;
    let g = &st.ident;
    let sums = [g.sum_t, g.sum_sin, g.sum_cos];
    for (j, (w0, _)) in IDENT_SUMS.iter().enumerate() {
        if (*w0..w0 + 12).contains(&off) {
            return m::sum_word(sums[j], ((off - w0) / 4) as usize);
        }
    }
    let bit = |b: bool, mask: u32| if b { mask } else { 0 };
    match off {
        m::ECC_STATUS => bit(g.done, flags.0) | bit(g.overflow, flags.1),
        m::IDENT_COUNT => g.count as u32,
        m::IDENT_T_MIN => g.t_min as u32,
        m::IDENT_T_MAX => g.t_max as u32,
        m::IDENT_P => (g.p_min as u32) | ((g.p_max as u32) << 16),
        _ => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::ecc_regmap as m;

    fn access(r: &mut EccRegsModel, st: &EccStatus, we: bool, adr: u32, dat: u32) -> u32 {
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: we,
            wb_adr_i: adr,
            wb_dat_i: dat,
            wb_sel_i: 0xF,
        };
        let inputs = EccRegsInputs {
            reset: false,
            bus,
            status: *st,
            ..Default::default()
        };
        assert!(!r.step(&inputs).wb_ack_o, "executed, not yet acknowledged");
        let o = r.step(&inputs);
        assert!(o.wb_ack_o);
        let idle = r.step(&EccRegsInputs {
            status: *st,
            ..Default::default()
        });
        assert!(!idle.wb_ack_o && idle.wb_dat_o == 0);
        o.wb_dat_o
    }

    /// Hand-worked accesses: the constants, the staged load, the arm pulse, the sum words
    /// and the speed pair.
    #[test]
    fn hand_worked_accesses() {
        let mut r = EccRegsModel::new(41);
        let mut st = EccStatus::default();
        assert_eq!(access(&mut r, &st, false, m::ECC_ID, 0), 0x454E_4345);
        assert_eq!(access(&mut r, &st, false, m::ECC_VERSION, 0), 0x0001_0000);
        // c = -1.5 lines = 0xFFFE8000 in Q15.16; d = 0.25 = 0x4000.
        access(&mut r, &st, true, m::ECC_C, 0xFFFE_8000);
        access(&mut r, &st, true, m::ECC_D, 0x4000);
        assert_eq!(
            (r.outputs().ecc_c, r.outputs().ecc_d),
            (0, 0),
            "staged only"
        );
        assert_eq!(access(&mut r, &st, false, m::ECC_C, 0), 0xFFFE_8000);
        access(&mut r, &st, true, m::ECC_CTRL, 0b10);
        assert_eq!(
            (r.outputs().coef_c(), r.outputs().coef_d()),
            (-98_304, 16_384)
        );
        // The arm: high for exactly the cycle after the write edge.
        let bus = WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: true,
            wb_adr_i: m::ECC_CTRL,
            wb_dat_i: 1,
            wb_sel_i: 1,
        };
        let inputs = EccRegsInputs {
            bus,
            status: st,
            ..Default::default()
        };
        let o = r.step(&inputs);
        assert!(o.ident_arm && !o.wb_ack_o);
        let o = r.step(&inputs);
        assert!(!o.ident_arm && o.wb_ack_o);
        r.step(&EccRegsInputs::default());
        assert_eq!(
            access(&mut r, &st, false, m::ECC_CTRL, 0),
            0,
            "pulses read 0"
        );
        // Results: sum_sin = -3 * 2^64 + 7 reads (7, 0, 0xFFFFFFFD).
        st.ident.done = true;
        st.ident.sum_sin = -3 * (1i128 << 64) + 7;
        st.ident.p_min = 0x1234;
        st.ident.p_max = 0xABCD;
        assert_eq!(access(&mut r, &st, false, m::ECC_STATUS, 0), 1);
        let words = [0, 4, 8].map(|k| access(&mut r, &st, false, m::IDENT_SUM_SIN_W0 + k, 0));
        assert_eq!(words, [7, 0, 0xFFFF_FFFD]);
        assert_eq!(access(&mut r, &st, false, m::IDENT_P, 0), 0xABCD_1234);
        // A negative 41-bit speed: -2 reads LO 0xFFFFFFFE, then HI 0xFFFFFFFF.
        st.speed_n3c = (1u64 << 41) - 2;
        assert_eq!(access(&mut r, &st, false, m::SPEED_N3C_LO, 0), 0xFFFF_FFFE);
        st.speed_n3c = 5;
        assert_eq!(access(&mut r, &st, false, m::SPEED_N3C_HI, 0), 0xFFFF_FFFF);
        // The done edge latched IDENT; enabling it raises irq; W1C clears it.
        assert_eq!(access(&mut r, &st, false, m::ECC_IRQ_STATUS, 0), 0b100);
        access(&mut r, &st, true, m::ECC_IRQ_ENABLE, 0b100);
        assert!(r.outputs().irq);
        access(&mut r, &st, true, m::ECC_IRQ_STATUS, 0b100);
        assert!(!r.outputs().irq);
    }

    /// The snapshot by hand: a `snap_take` edge stores the corrected speeds as they stand,
    /// `snap_sampled` reads them (LO latches HI from the snapshot) while the live speeds
    /// move on, and reset clears them.
    #[test]
    fn the_snapshot_stores_the_corrected_speeds_of_one_edge() {
        let mut r = EccRegsModel::new(41);
        let mut st = EccStatus {
            speed_mtc: 1000,
            speed_n3c: (1u64 << 41) - 3,
            ..Default::default()
        };
        r.step(&EccRegsInputs {
            status: st,
            snap_take: true,
            ..Default::default()
        });
        assert_eq!(r.snapshot(), [1000, (1u64 << 41) - 3]);
        st.speed_mtc = 2000;
        st.speed_n3c = 7;
        let sampled = |r: &mut EccRegsModel, st: &EccStatus, adr: u32| {
            let bus = WbBus {
                wb_cyc_i: true,
                wb_stb_i: true,
                wb_adr_i: adr,
                wb_sel_i: 0xF,
                ..Default::default()
            };
            let inp = EccRegsInputs {
                bus,
                status: *st,
                snap_sampled: true,
                ..Default::default()
            };
            r.step(&inp);
            let o = r.step(&inp);
            assert!(o.wb_ack_o);
            r.step(&EccRegsInputs {
                status: *st,
                snap_sampled: true,
                ..Default::default()
            });
            o.wb_dat_o
        };
        assert_eq!(sampled(&mut r, &st, m::SPEED_MTC_LO), 1000);
        assert_eq!(sampled(&mut r, &st, m::SPEED_N3C_LO), 0xFFFF_FFFD);
        assert_eq!(sampled(&mut r, &st, m::SPEED_N3C_HI), 0xFFFF_FFFF);
        // Live again without SAMPLED.
        assert_eq!(access(&mut r, &st, false, m::SPEED_MTC_LO, 0), 2000);
        r.step(&EccRegsInputs {
            reset: true,
            status: st,
            ..Default::default()
        });
        assert_eq!(r.snapshot(), [0, 0]);
    }
}
