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
//! - request = `wb_cyc_i & wb_stb_i & !wb_ack_o`; `wb_ack_o` ← request; `wb_dat_o` ← the
//!   register at `wb_adr_i` (bits 1:0 ignored) if the request reads, else 0 (the top
//!   routes only the window's offsets here, but the slave answers any offset it is given:
//!   0 where nothing is mapped);
//! - a read of a corrected speed's LO register loads its HI shadow;
//! - `ident_arm` ← a write to `ECC_CTRL` with a 1 in `IDENT_ARM` (byte lane 0);
//!   `ecc_c`, `ecc_d` ← `ECC_C`, `ECC_D` (as they stood before the edge) on such a write
//!   with a 1 in `LOAD`;
//! - `ECC_IRQ_STATUS` ← (`ECC_IRQ_STATUS` & !(bits written 1)) | events: `mtc_strobe`,
//!   `n3c_strobe`, `ident_done` rising (previous level registered, 0 after reset).

use crate::bus::ecc_regmap::{self, ECC_SPEEDS, IDENT_SUMS};
use crate::bus::regmap::{Access, Register};
use crate::bus::wb_regs::{sign_extend, Request, WbBus};
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

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct State {
    ack: bool,
    dat: u32,
    arm: bool,
    stage_c: u32,
    stage_d: u32,
    ecc_c: u32,
    ecc_d: u32,
    irq_enable: u32,
    irq_status: u32,
    hi: [u32; 2],
    prev_done: bool,
}

/// The window's slave, one step per clock edge.
#[derive(Clone, Debug)]
pub struct EccRegsModel {
    registers: Vec<Register>,
    speed_bits: u32,
    s: State,
}

impl EccRegsModel {
    /// The slave for speeds of `speed_bits` bits (11..=64), in its reset state.
    pub fn new(speed_bits: u32) -> Self {
        assert!((11..=64).contains(&speed_bits), "speed_bits {speed_bits}");
        Self {
            registers: ecc_regmap::registers(speed_bits),
            speed_bits,
            s: State::default(),
        }
    }

    fn reg(&self, off: u32) -> &Register {
        self.registers.iter().find(|r| r.offset == off).unwrap()
    }

    fn mask(&self, off: u32, a: Access) -> u32 {
        self.reg(off).mask_of(a)
    }

    fn field(&self, off: u32, name: &str) -> u32 {
        self.reg(off).field(name).mask()
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> EccRegsOutputs {
        let s = &self.s;
        EccRegsOutputs {
            wb_ack_o: s.ack,
            wb_dat_o: s.dat,
            irq: s.irq_status & s.irq_enable != 0,
            ecc_c: s.ecc_c,
            ecc_d: s.ecc_d,
            ident_arm: s.arm,
        }
    }

    /// The value a read of word offset `off` returns with `st`.
    fn read(&self, off: u32, st: &EccStatus) -> u32 {
        use ecc_regmap as m;
        let s = &self.s;
        let g = &st.ident;
        if let Some(k) = ECC_SPEEDS.iter().position(|e| e.0 == off) {
            return sign_extend(st.speeds()[k], self.speed_bits) as u32;
        }
        if let Some(k) = ECC_SPEEDS.iter().position(|e| e.1 == off) {
            return s.hi[k];
        }
        let sums = [g.sum_t, g.sum_sin, g.sum_cos];
        for (j, (w0, _)) in IDENT_SUMS.iter().enumerate() {
            if (*w0..w0 + 12).contains(&off) {
                return m::sum_word(sums[j], ((off - w0) / 4) as usize);
            }
        }
        let bit = |b: bool, name: &str| {
            if b {
                self.field(m::ECC_STATUS, name)
            } else {
                0
            }
        };
        match off {
            m::ECC_ID | m::ECC_VERSION => self.reg(off).reset.unwrap(),
            m::ECC_STATUS => bit(g.done, "IDENT_DONE") | bit(g.overflow, "IDENT_OVERFLOW"),
            m::ECC_C => s.stage_c,
            m::ECC_D => s.stage_d,
            m::ECC_IRQ_ENABLE => s.irq_enable,
            m::ECC_IRQ_STATUS => s.irq_status,
            m::IDENT_COUNT => g.count as u32,
            m::IDENT_T_MIN => g.t_min as u32,
            m::IDENT_T_MAX => g.t_max as u32,
            m::IDENT_P => (g.p_min as u32) | ((g.p_max as u32) << 16),
            _ => 0,
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
        let b = &inp.bus;
        self.check(st);
        let Request {
            off,
            rd,
            wr,
            lanes,
            ones,
        } = Request::decode(b, self.s.ack);
        if inp.reset {
            self.s = State::default();
            return self.outputs();
        }
        let s = self.s;
        let mut n = s;
        n.ack = rd || wr;
        n.dat = if rd { self.read(off, st) } else { 0 };
        if rd {
            if let Some(k) = ECC_SPEEDS.iter().position(|e| e.0 == off) {
                n.hi[k] = (sign_extend(st.speeds()[k], self.speed_bits) >> 32) as u32;
            }
        }
        let rw = |off: u32, old: u32| ((old & !lanes) | ones) & self.mask(off, Access::Rw);
        let pulse = |name: &str| wr && off == m::ECC_CTRL && ones & self.field(off, name) != 0;
        n.arm = pulse("IDENT_ARM");
        if pulse("LOAD") {
            n.ecc_c = s.stage_c;
            n.ecc_d = s.stage_d;
        }
        let mut irq_cleared = 0;
        if wr {
            match off {
                m::ECC_C => n.stage_c = rw(off, s.stage_c),
                m::ECC_D => n.stage_d = rw(off, s.stage_d),
                m::ECC_IRQ_ENABLE => n.irq_enable = rw(off, s.irq_enable),
                m::ECC_IRQ_STATUS => irq_cleared = ones & self.mask(off, Access::W1c),
                _ => {}
            }
        }
        let ev = |b: bool, name: &str| {
            if b {
                self.field(m::ECC_IRQ_STATUS, name)
            } else {
                0
            }
        };
        let events = ev(st.mtc_strobe, "MTC")
            | ev(st.n3c_strobe, "N3C")
            | ev(st.ident.done && !s.prev_done, "IDENT");
        n.irq_status = (s.irq_status & !irq_cleared) | events;
        n.prev_done = st.ident.done;
        self.s = n;
        self.outputs()
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
        let o = r.step(&EccRegsInputs {
            reset: false,
            bus,
            status: *st,
        });
        assert!(o.wb_ack_o);
        let idle = r.step(&EccRegsInputs {
            reset: false,
            bus: WbBus::default(),
            status: *st,
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
        let o = r.step(&EccRegsInputs {
            reset: false,
            bus,
            status: st,
        });
        assert!(o.ident_arm && o.wb_ack_o);
        let o = r.step(&EccRegsInputs::default());
        assert!(!o.ident_arm);
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
}
