// SPDX-License-Identifier: MIT OR Apache-2.0
//! Cycle model of a Wishbone register file as the hardware builds it (`hdl::RegFile` and
//! its cells, `hdl/src/bus`): the front end, the interrupt pair, and every register of a
//! map by its kind. [`crate::bus::wb_regs::WbRegsModel`] and
//! [`crate::bus::ecc_regs::EccRegsModel`] are this model with their windows' live words,
//! events and outputs.
//!
//! Conventions as in [`crate::estimator::sync_estimator`]: one [`RegFileModel::step`] per
//! rising clock edge with the inputs applied during the cycle before it; registers are
//! updated from the values before the edge. Per edge, when `reset` is low:
//! - request = `wb_cyc_i & wb_stb_i & !wb_ack_o & !pending` ([`Request::decode`]);
//!   `pending` ← request, `wb_ack_o` ← `pending`: the ack is high in the cycle after the
//!   edge after the request's; the read data takes the same two edges: the word at the
//!   request's offset if it reads, else 0, is taken at the request's edge and shows on
//!   `wb_dat_o` with the ack (the hardware's two read stages, `hdl::bus::read_data`);
//! - the word at an offset is, by kind: the interrupt enable or status; a shadow pair's LO
//!   (bits 31:0 of the value sign-extended to 64 bits, live) or HI (the shadow); a
//!   register with RW fields, its stored fields; a register the file holds with only RO
//!   fields, its reset value (a constant); otherwise the window's live word (0 where
//!   nothing is mapped);
//! - a read of a LO loads its HI shadow with bits 63:32; a write stores
//!   `(old & !lanes) | ones` in the RW fields of its register; a write of ones to the
//!   enable register's RW fields likewise; `IRQ_STATUS` ← (`IRQ_STATUS` & !(W1C bits
//!   written 1)) | events (an event wins over a clear);
//! - a pulse (offset, mask) is high for the cycle after a write to its offset with a 1 in
//!   its mask.
//!
//! `reset` returns every register to 0.

use crate::bus::regmap::{Access, Register, SPAN_BYTES};

/// The Wishbone inputs of a register file, named as its ports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WbBus {
    /// Bus cycle in progress.
    pub wb_cyc_i: bool,
    /// This slave is addressed.
    pub wb_stb_i: bool,
    /// 1 write, 0 read.
    pub wb_we_i: bool,
    /// Byte address ([`crate::bus::regmap::ADDR_BITS`] bits; bits 1:0 ignored).
    pub wb_adr_i: u32,
    /// Write data.
    pub wb_dat_i: u32,
    /// Byte lanes written (4 bits).
    pub wb_sel_i: u8,
}

/// The 32-bit mask of the byte lanes in `sel`.
pub fn lane_mask(sel: u8) -> u32 {
    (0..4)
        .filter(|j| sel & (1 << j) != 0)
        .fold(0, |m, j| m | (0xFF << (8 * j)))
}

/// A bus access as a classic slave decodes it at an edge: a request is
/// `wb_cyc_i & wb_stb_i` while its `wb_ack_o` is low.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Request {
    /// Word offset (`wb_adr_i` with bits 1:0 cleared).
    pub off: u32,
    /// A read request.
    pub rd: bool,
    /// A write request.
    pub wr: bool,
    /// The written byte lanes as a 32-bit mask.
    pub lanes: u32,
    /// `wb_dat_i` in those lanes: the bits written 1.
    pub ones: u32,
}

impl Request {
    /// The access of `b` for a slave that is `busy` (its `wb_ack_o` or its pending flag
    /// high). Panics if the address does not fit `wb_adr_i` or `wb_sel_i` is wider than 4
    /// bits.
    pub fn decode(b: &WbBus, busy: bool) -> Request {
        assert!(b.wb_adr_i < SPAN_BYTES, "wb_adr_i = {:#x}", b.wb_adr_i);
        assert!(b.wb_sel_i < 16, "wb_sel_i = {:#x}", b.wb_sel_i);
        let req = b.wb_cyc_i && b.wb_stb_i && !busy;
        let lanes = lane_mask(b.wb_sel_i);
        Request {
            off: b.wb_adr_i & !3,
            rd: req && !b.wb_we_i,
            wr: req && b.wb_we_i,
            lanes,
            ones: b.wb_dat_i & lanes,
        }
    }

    /// A write to `off` with a 1 in some bit of `mask`.
    pub fn writes_one(&self, off: u32, mask: u32) -> bool {
        self.wr && self.off == off && self.ones & mask != 0
    }
}

/// `raw` (S bits, two's complement) sign-extended to 64 bits.
pub fn sign_extend(raw: u64, s: u32) -> u64 {
    if s < 64 && raw & (1 << (s - 1)) != 0 {
        raw | !((1u64 << s) - 1)
    } else {
        raw
    }
}

/// What a window supplies in one cycle.
#[derive(Clone, Copy, Debug)]
pub struct Cycle<'a> {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// The bus.
    pub bus: &'a WbBus,
    /// The shadow pairs' values, sign-extended to 64 bits, in the order of the pairs.
    pub wide: &'a [u64],
    /// Interrupt events of this cycle, in `IRQ_STATUS`'s bit positions.
    pub events: u32,
}

#[derive(Clone, Debug, Default, PartialEq, Eq)]
struct State {
    /// A request was executed at the last edge.
    pending: bool,
    /// The word it read (0 for a write).
    pending_dat: u32,
    ack: bool,
    dat: u32,
    irq_enable: u32,
    irq_status: u32,
    /// The stored RW fields, per register (0 for the others).
    rw: Vec<u32>,
    /// The HI shadows, per pair.
    hi: Vec<u32>,
    /// The pulses, per pulse.
    pulses: Vec<bool>,
}

/// A register file, one step per clock edge.
#[derive(Clone, Debug)]
pub struct RegFileModel {
    regs: Vec<Register>,
    irq_enable: u32,
    irq_status: u32,
    /// (LO offset, HI offset) of each shadow pair.
    shadows: Vec<(u32, u32)>,
    /// (offset, mask) of each pulse.
    pulses: Vec<(u32, u32)>,
    s: State,
}

impl RegFileModel {
    /// The file of `regs`, whose interrupt pair is the registers called `irq_enable` and
    /// `irq_status`, with the LO/HI pairs `shadows` and the pulses `pulses` (offset, mask),
    /// in its reset state.
    pub fn new(
        regs: Vec<Register>,
        irq_enable: &str,
        irq_status: &str,
        shadows: &[(u32, u32)],
        pulses: &[(u32, u32)],
    ) -> Self {
        let offset = |name: &str| {
            regs.iter()
                .find(|r| r.name == name)
                .unwrap_or_else(|| panic!("no register {name}"))
                .offset
        };
        let (irq_enable, irq_status) = (offset(irq_enable), offset(irq_status));
        let s = State {
            rw: vec![0; regs.len()],
            hi: vec![0; shadows.len()],
            pulses: vec![false; pulses.len()],
            ..State::default()
        };
        Self {
            regs,
            irq_enable,
            irq_status,
            shadows: shadows.to_vec(),
            pulses: pulses.to_vec(),
            s,
        }
    }

    /// The registers.
    pub fn registers(&self) -> &[Register] {
        &self.regs
    }

    /// The register at byte offset `off`.
    pub fn at(&self, off: u32) -> &Register {
        self.regs
            .iter()
            .find(|r| r.offset == off)
            .unwrap_or_else(|| panic!("no register at {off:#x}"))
    }

    fn index(&self, off: u32) -> Option<usize> {
        self.regs.iter().position(|r| r.offset == off)
    }

    /// `wb_ack_o`.
    pub fn ack(&self) -> bool {
        self.s.ack
    }

    /// The slave takes no request at the next edge: `wb_ack_o` is high or a request was
    /// taken at the last edge (its ack comes at the next).
    pub fn busy(&self) -> bool {
        self.s.ack || self.s.pending
    }

    /// `wb_dat_o`.
    pub fn dat(&self) -> u32 {
        self.s.dat
    }

    /// `irq`: (`IRQ_STATUS` & `IRQ_ENABLE`) ≠ 0.
    pub fn irq(&self) -> bool {
        self.s.irq_status & self.s.irq_enable != 0
    }

    /// The stored RW fields of the register at `off`.
    pub fn rw(&self, off: u32) -> u32 {
        self.s.rw[self.index(off).expect("a register")]
    }

    /// Pulse `k` (in the order given to [`RegFileModel::new`]).
    pub fn pulse(&self, k: usize) -> bool {
        self.s.pulses[k]
    }

    /// The word a read of `off` returns, `live` giving the window's live words.
    fn read(&self, off: u32, wide: &[u64], live: &dyn Fn(u32) -> u32) -> u32 {
        let s = &self.s;
        if off == self.irq_enable {
            return s.irq_enable;
        }
        if off == self.irq_status {
            return s.irq_status;
        }
        if let Some(k) = self.shadows.iter().position(|p| p.0 == off) {
            return wide[k] as u32;
        }
        if let Some(k) = self.shadows.iter().position(|p| p.1 == off) {
            return s.hi[k];
        }
        let Some(i) = self.index(off) else {
            return live(off);
        };
        let r = &self.regs[i];
        let ro_only = r.fields.iter().all(|f| f.access == Access::Ro);
        match r.reset {
            _ if r.mask_of(Access::Rw) != 0 => s.rw[i],
            Some(v) if ro_only => v,
            _ => live(off),
        }
    }

    /// One rising clock edge with `c` applied, `live` giving the window's live words; the
    /// request decoded at this edge (before `reset` is applied).
    pub fn step(&mut self, c: &Cycle, live: &dyn Fn(u32) -> u32) -> Request {
        assert_eq!(
            c.wide.len(),
            self.shadows.len(),
            "one value per shadow pair"
        );
        let req = Request::decode(c.bus, self.busy());
        if c.reset {
            let s = &mut self.s;
            (s.pending, s.pending_dat, s.ack, s.dat) = (false, 0, false, 0);
            (s.irq_enable, s.irq_status) = (0, 0);
            s.rw.fill(0);
            s.hi.fill(0);
            s.pulses.fill(false);
            return req;
        }
        let Request {
            off,
            rd,
            wr,
            lanes,
            ones,
        } = req;
        // Everything below reads only the registers it replaces, or reads before writing.
        let dat = if rd { self.read(off, c.wide, live) } else { 0 };
        let s = &mut self.s;
        (s.ack, s.dat) = (s.pending, s.pending_dat);
        (s.pending, s.pending_dat) = (rd || wr, dat);
        if rd {
            if let Some(k) = self.shadows.iter().position(|p| p.0 == off) {
                s.hi[k] = (c.wide[k] >> 32) as u32;
            }
        }
        let mut cleared = 0;
        // The register written, looked up only on a write (this runs every cycle).
        let written = if wr {
            self.regs.iter().position(|r| r.offset == off)
        } else {
            None
        };
        if let Some(i) = written {
            let r = &self.regs[i];
            if off == self.irq_enable {
                s.irq_enable = ((s.irq_enable & !lanes) | ones) & r.mask_of(Access::Rw);
            } else if off == self.irq_status {
                cleared = ones & r.mask_of(Access::W1c);
            } else {
                s.rw[i] = ((s.rw[i] & !lanes) | ones) & r.mask_of(Access::Rw);
            }
        }
        s.irq_status = (s.irq_status & !cleared) | c.events;
        for (p, &(poff, mask)) in s.pulses.iter_mut().zip(&self.pulses) {
            *p = req.writes_one(poff, mask);
        }
        req
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::regmap::Field;

    fn field(name: &'static str, lsb: u32, width: u32, access: Access) -> Field {
        Field {
            name,
            lsb,
            width,
            access,
            description: String::new(),
        }
    }

    fn reg(name: &'static str, offset: u32, reset: Option<u32>, fields: Vec<Field>) -> Register {
        Register {
            name,
            offset,
            reset,
            description: String::new(),
            side_effect: None,
            fields,
        }
    }

    /// A hand-made map of one register of each kind.
    fn file() -> RegFileModel {
        use Access::*;
        let regs = vec![
            reg("K", 0x00, Some(0x1234_5678), vec![field("V", 0, 32, Ro)]),
            reg("RW", 0x04, Some(0), vec![field("V", 0, 12, Rw)]),
            reg("LIVE", 0x08, None, vec![field("V", 0, 32, Ro)]),
            reg("CMD", 0x0C, None, vec![field("GO", 0, 1, W1p)]),
            reg("EN", 0x10, Some(0), vec![field("E", 0, 2, Rw)]),
            reg("ST", 0x14, Some(0), vec![field("E", 0, 2, W1c)]),
            reg("LO", 0x18, None, vec![field("V", 0, 32, Ro)]),
            reg("HI", 0x1C, Some(0), vec![field("V", 0, 32, Ro)]),
        ];
        RegFileModel::new(regs, "EN", "ST", &[(0x18, 0x1C)], &[(0x0C, 1)])
    }

    fn bus(we: bool, adr: u32, dat: u32, sel: u8) -> WbBus {
        WbBus {
            wb_cyc_i: true,
            wb_stb_i: true,
            wb_we_i: we,
            wb_adr_i: adr,
            wb_dat_i: dat,
            wb_sel_i: sel,
        }
    }

    /// One access as a classic master makes it (the request held until the ack, which
    /// comes after the second edge), then one idle cycle; the data of the ack cycle.
    fn access(f: &mut RegFileModel, b: WbBus, wide: u64, events: u32) -> u32 {
        let live = |off: u32| if off == 0x08 { 0xCAFE } else { 0 };
        let w = [wide];
        for (edge, events) in [events, 0].into_iter().enumerate() {
            assert!(!f.ack(), "no ack before edge {edge} of the access");
            f.step(
                &Cycle {
                    reset: false,
                    bus: &b,
                    wide: &w,
                    events,
                },
                &live,
            );
        }
        assert!(f.ack());
        let d = f.dat();
        let idle = WbBus::default();
        f.step(
            &Cycle {
                reset: false,
                bus: &idle,
                wide: &w,
                events: 0,
            },
            &live,
        );
        assert!(!f.ack() && f.dat() == 0);
        d
    }

    #[test]
    fn each_kind_behaves_as_the_text_says() {
        let mut f = file();
        assert_eq!(access(&mut f, bus(false, 0x00, 0, 0), 0, 0), 0x1234_5678);
        assert_eq!(access(&mut f, bus(false, 0x08, 0, 0), 0, 0), 0xCAFE);
        assert_eq!(access(&mut f, bus(false, 0x20, 0, 0), 0, 0), 0, "unmapped");
        // RW: byte lanes and the field mask (12 bits).
        access(&mut f, bus(true, 0x04, 0xFFFF_FFFF, 0b0001), 0, 0);
        assert_eq!(f.rw(0x04), 0x0FF);
        access(&mut f, bus(true, 0x06, 0xABCD_EF00, 0b0010), 0, 0);
        assert_eq!(access(&mut f, bus(false, 0x04, 0, 0), 0, 0), 0xFFF);
        // LO/HI: the HI read returns what the LO read latched, not the value now.
        let v = 0xFFFF_FFFE_0000_0003u64;
        assert_eq!(access(&mut f, bus(false, 0x18, 0, 0), v, 0), 3);
        assert_eq!(access(&mut f, bus(false, 0x1C, 0, 0), 7, 0), 0xFFFF_FFFE);
        // Pulse: one cycle after a write of 1 to GO; the ack one cycle later.
        let live = |_: u32| 0;
        let (go, idle) = (bus(true, 0x0C, 1, 0b0001), WbBus::default());
        let edge = |f: &mut RegFileModel, b: &WbBus| {
            let cycle = Cycle {
                reset: false,
                bus: b,
                wide: &[0],
                events: 0,
            };
            f.step(&cycle, &live);
            (f.pulse(0), f.ack())
        };
        assert_eq!(edge(&mut f, &go), (true, false));
        assert_eq!(
            edge(&mut f, &idle),
            (false, true),
            "the write's ack, after the pulse"
        );
        assert_eq!(edge(&mut f, &idle), (false, false));
        // Interrupts: event, enable, W1C; an event wins over a clear at the same edge.
        access(&mut f, bus(true, 0x10, 0b10, 0b0001), 0, 0b10);
        assert!(f.irq());
        access(&mut f, bus(true, 0x14, 0b10, 0b0001), 0, 0b10);
        assert!(f.irq(), "the event at the clearing edge wins");
        access(&mut f, bus(true, 0x14, 0b10, 0b0001), 0, 0);
        assert!(!f.irq());
        // Reset: everything to 0.
        f.step(
            &Cycle {
                reset: true,
                bus: &idle,
                wide: &[0],
                events: 1,
            },
            &live,
        );
        assert_eq!((f.rw(0x04), f.irq(), f.ack()), (0, false, false));
        assert_eq!(access(&mut f, bus(false, 0x1C, 0, 0), 0, 0), 0);
    }
}
