// SPDX-License-Identifier: MIT OR Apache-2.0
//! The register map of `encspeed_core`'s Wishbone register file, as data: the one
//! description from which the hardware ([`hdl::WbRegs`]), its cycle model
//! ([`crate::bus::wb_regs::WbRegsModel`]), the C header ([`c_header`]) and the documentation
//! table ([`markdown`]) are all made.
//!
//! # Bus
//!
//! Wishbone B4 classic slave, 32-bit data, [`ADDR_BITS`]-bit byte address (`wb_adr_i`,
//! a [`SPAN_BYTES`]-byte window; bits 1:0 are ignored, registers are 32-bit words at
//! word-aligned offsets; the interconnect decodes the address bits above). A request
//! (`wb_cyc_i & wb_stb_i`, while the slave is idle: `wb_ack_o` low and no request taken at
//! the edge before) sampled at clock edge k is executed at that edge and acknowledged by
//! `wb_ack_o` high for the one cycle after edge k + 1, with the read data (the register as
//! it stood before edge k) in `wb_dat_o` (0 in every other cycle). So every access takes
//! three cycles, and `wb_ack_o` is low for at least two cycles between back-to-back
//! accesses of a master that keeps `wb_stb_i` high. The second edge is the read
//! multiplexer's pipeline stage: the file meets a 100 MHz clock on an iCE40HX8K with it.
//! A master must wait for `wb_ack_o` (as every classic master does), and the address, data
//! and `wb_we_i` it holds through the access are sampled at edge k only. There is no
//! `wb_err_o`: a read of an unmapped offset returns 0 and a write to it, or to a read-only
//! register or bit, is acknowledged and ignored. Writes honour `wb_sel_i` (byte lane j =
//! bits 8j+7..8j): a lane that is not selected is neither written nor, for W1C bits,
//! cleared. Register bits above a field's width are reserved: they read 0 and ignore
//! writes.
//!
//! # Coherence
//!
//! The speeds are S = N + F + 1 bits (up to 57), read as a LO/HI pair of the value
//! sign-extended to 64 bits. Reading a speed's LO register latches that speed's HI word
//! into its own shadow register, which its HI register returns: read LO then HI for a
//! coherent value (the HI register before any LO read returns the shadow's reset value, 0).
//! Each speed has its own shadow, so pairs of different speeds may be interleaved. Every
//! other value fits one register and is read in one access.
//!
//! # Faults and interrupts
//!
//! `STATUS` shows the core's status levels live. Its three sticky fault bits are W1C: a
//! write with byte lane 0 selected and a 1 in any of them pulses `clear_faults` for the one
//! cycle after the write edge (the cycle before `wb_ack_o`), and the core's single
//! `clear_faults` input clears **all three** flags at the next edge. So a write of 1 to any
//! fault bit clears all of them, and a read of `STATUS` in the next access already sees
//! them cleared (unless a new fault came).
//!
//! `IRQ_STATUS` latches events (a 1-cycle strobe, or a rising edge of a level) at every
//! edge, whether enabled or not; a write of 1 clears a bit, except that an event in the same
//! edge wins. `irq` = (`IRQ_STATUS` & `IRQ_ENABLE`) ≠ 0, a function of registers only (no
//! path from any input to `irq`).
//!
//! # Snapshot
//!
//! The `sample` input (synchronous, active high; say the PWM carrier's peak) takes a
//! **snapshot**: at the edge that samples it high, the register file stores `position`,
//! `nep`, `ndt`, the six speeds and the levels `valid`, `stalled`, `direction` as the core
//! outputs them in that cycle (the values a read requested at that edge would return), and
//! counts it in `SNAP_COUNT` (modulo 2^32) and raises the `SAMPLE` interrupt event. A
//! write of 1 to `CTRL.TRIGGER` takes one the same way at the edge after the write edge
//! (the edge that raises `wb_ack_o`), whatever `sample` and `CTRL.HOLD`; `CTRL.HOLD` = 1 makes the
//! file ignore `sample`. With `CTRL.SAMPLED` = 1, `POSITION`, `NEP`, `NDT`, the `SPEED_*`
//! pairs and `STATUS`'s `VALID`, `STALLED`, `DIRECTION` read the snapshot instead of the live
//! values (everything else stays live; a speed's LO read still latches its HI from the
//! snapshot). The snapshot is coherent: every value comes from one cycle. To read it whole
//! while strobes go on, either set `HOLD` (and use `TRIGGER` for a snapshot of one's own) or
//! read `SNAP_COUNT` before and after and retry if it moved. After reset the snapshot is 0.
//!
//! # Reset
//!
//! Synchronous, active high, the core's reset: every register of the file returns to its
//! reset value; `wb_ack_o`, `wb_dat_o`, `clear_faults` and `irq` go low; a request in the
//! reset cycle is dropped (never acknowledged; a classic master then waits and must retry).
//!
//! [`hdl::WbRegs`]: ../../hdl/wb_regs/index.html

use crate::params::{bits_for, Params};
use std::fmt::Write;

/// The `ID` register: ASCII "ENCS", 'E' in the top byte.
pub const ID_MAGIC: u32 = u32::from_be_bytes(*b"ENCS");
/// Version of this register map: major in bits 31:16, minor in 15:0. The major number
/// changes when an offset or a field moves.
pub const MAP_VERSION: u32 = 0x0001_0001;
/// Width of `wb_adr_i` (a byte address).
pub const ADDR_BITS: usize = 8;
/// Width of `wb_dat_i` and `wb_dat_o`.
pub const DATA_BITS: usize = 32;
/// Bytes of address space the register file decodes.
pub const SPAN_BYTES: u32 = 1 << ADDR_BITS;
/// Lowest bit of the `CTRL.MODE` field (`cfg_mode`, 2 bits).
pub const CTRL_MODE_LSB: usize = 0;
/// Lowest bit of the `CTRL.Z_MODE` field (`cfg_z_mode`, 2 bits).
pub const CTRL_Z_MODE_LSB: usize = 2;
/// Width of `cfg_mode` and `cfg_z_mode`.
pub const MODE_BITS: u32 = 2;
/// The `CTRL.SAMPLED` bit: the value registers read the snapshot.
pub const CTRL_SAMPLED_LSB: usize = 8;
/// The `CTRL.HOLD` bit: the `sample` input is ignored.
pub const CTRL_HOLD_LSB: usize = 9;
/// The `CTRL.TRIGGER` bit (write 1 to pulse): take a snapshot.
pub const CTRL_TRIGGER_LSB: usize = 10;

/// The offsets, each a `pub const` of its register's name, and [`LAYOUT`] listing them in
/// address order.
macro_rules! layout {
    ($($(#[$doc:meta])* $name:ident = $off:expr;)*) => {
        $($(#[$doc])* pub const $name: u32 = $off;)*
        /// Every register's name and byte offset, in address order.
        pub const LAYOUT: &[(&str, u32)] = &[$((stringify!($name), $off)),*];
    };
}
pub(crate) use layout;

layout! {
    /// Constant magic [`ID_MAGIC`].
    ID = 0x00;
    /// Map version [`MAP_VERSION`].
    VERSION = 0x04;
    /// Widths N, F, S, C.
    PARAM0 = 0x08;
    /// Widths FB, G.
    PARAM1 = 0x0C;
    /// Lines per revolution.
    LINES = 0x10;
    /// Generation default dt (clock cycles).
    DT_DEFAULT = 0x14;
    /// Generation default zero-speed timeout (dt intervals).
    TIMEOUT_DEFAULT = 0x18;
    /// Clock frequency (Hz).
    CLOCK_HZ = 0x1C;
    /// `cfg_mode`, `cfg_z_mode`.
    CTRL = 0x20;
    /// `cfg_dt`.
    CFG_DT = 0x24;
    /// `cfg_timeout`.
    CFG_TIMEOUT = 0x28;
    /// `cfg_filter`.
    CFG_FILTER = 0x2C;
    /// Status levels and W1C sticky faults.
    STATUS = 0x30;
    /// Interrupt enables.
    IRQ_ENABLE = 0x34;
    /// Interrupt events (W1C).
    IRQ_STATUS = 0x38;
    /// `position`.
    POSITION = 0x40;
    /// `z_latch`.
    Z_LATCH = 0x44;
    /// `nep`.
    NEP = 0x48;
    /// `ndt`.
    NDT = 0x4C;
    /// `speed_n1` bits 31:0; latches [`SPEED_N1_HI`].
    SPEED_N1_LO = 0x50;
    /// `speed_n1` bits 63:32 (shadow).
    SPEED_N1_HI = 0x54;
    /// `speed_n2` bits 31:0; latches [`SPEED_N2_HI`].
    SPEED_N2_LO = 0x58;
    /// `speed_n2` bits 63:32 (shadow).
    SPEED_N2_HI = 0x5C;
    /// `speed_n3` bits 31:0; latches [`SPEED_N3_HI`].
    SPEED_N3_LO = 0x60;
    /// `speed_n3` bits 63:32 (shadow).
    SPEED_N3_HI = 0x64;
    /// `speed_pc` bits 31:0; latches [`SPEED_PC_HI`].
    SPEED_PC_LO = 0x68;
    /// `speed_pc` bits 63:32 (shadow).
    SPEED_PC_HI = 0x6C;
    /// `speed_et` bits 31:0; latches [`SPEED_ET_HI`].
    SPEED_ET_LO = 0x70;
    /// `speed_et` bits 63:32 (shadow).
    SPEED_ET_HI = 0x74;
    /// `speed_mt` bits 31:0; latches [`SPEED_MT_HI`].
    SPEED_MT_LO = 0x78;
    /// `speed_mt` bits 63:32 (shadow).
    SPEED_MT_HI = 0x7C;
    /// `glitch_count`.
    GLITCH_COUNT = 0x80;
    /// `illegal_count`.
    ILLEGAL_COUNT = 0x84;
    /// `rev_error_count`.
    REV_ERROR_COUNT = 0x88;
    /// Snapshots taken since reset.
    SNAP_COUNT = 0x8C;
}

/// The six speeds as (LO offset, HI offset, core port), in map order.
pub const SPEEDS: [(u32, u32, &str); 6] = [
    (SPEED_N1_LO, SPEED_N1_HI, "speed_n1"),
    (SPEED_N2_LO, SPEED_N2_HI, "speed_n2"),
    (SPEED_N3_LO, SPEED_N3_HI, "speed_n3"),
    (SPEED_PC_LO, SPEED_PC_HI, "speed_pc"),
    (SPEED_ET_LO, SPEED_ET_HI, "speed_et"),
    (SPEED_MT_LO, SPEED_MT_HI, "speed_mt"),
];

/// Byte offset of the register called `name`, if there is one.
pub fn offset(name: &str) -> Option<u32> {
    LAYOUT.iter().find(|(n, _)| *n == name).map(|&(_, o)| o)
}

/// What a bus access does to a field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// Read-only: writes are ignored.
    Ro,
    /// Read-write: a write stores the selected bytes.
    Rw,
    /// Read, write 1 to clear: a written 1 clears the bit (or, for the fault bits, pulses
    /// `clear_faults`); a written 0 does nothing.
    W1c,
    /// Write 1 to pulse: a written 1 raises a one-cycle output in the cycle after the write
    /// edge; a written 0 does nothing; reads 0.
    W1p,
}

impl Access {
    /// "RO", "RW" or "W1C".
    pub fn as_str(self) -> &'static str {
        match self {
            Access::Ro => "RO",
            Access::Rw => "RW",
            Access::W1c => "W1C",
            Access::W1p => "W1P",
        }
    }
}

/// A bit field of a register.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// Name, upper case (C macros are `ENCSPEED_<REG>_<FIELD>_*`).
    pub name: &'static str,
    /// Lowest bit.
    pub lsb: u32,
    /// Width in bits (≥ 1; lsb + width ≤ 32).
    pub width: u32,
    /// Access.
    pub access: Access,
    /// What it holds, with units.
    pub description: String,
}

impl Field {
    /// The field's bits in place in the register.
    pub fn mask(&self) -> u32 {
        (((1u64 << self.width) - 1) << self.lsb) as u32
    }
    /// Highest bit.
    pub fn msb(&self) -> u32 {
        self.lsb + self.width - 1
    }
    /// "msb:lsb", or "lsb" for one bit.
    pub fn bits(&self) -> String {
        if self.width == 1 {
            format!("{}", self.lsb)
        } else {
            format!("{}:{}", self.msb(), self.lsb)
        }
    }
}

/// A 32-bit register.
#[derive(Clone, Debug, PartialEq)]
pub struct Register {
    /// Name, upper case (as in [`LAYOUT`]).
    pub name: &'static str,
    /// Byte offset, word aligned.
    pub offset: u32,
    /// Value after reset: `Some` for a register the file holds (constant, configuration,
    /// interrupt, shadow), `None` for a live view of core outputs.
    pub reset: Option<u32>,
    /// What it is for.
    pub description: String,
    /// What an access does besides reading or writing the fields, if anything.
    pub side_effect: Option<String>,
    /// Its fields, lowest bit first; bits outside every field are reserved (read 0).
    pub fields: Vec<Field>,
}

impl Register {
    /// "RO", "RW", "W1C", or e.g. "RO/W1C" when the fields differ.
    pub fn access(&self) -> String {
        let mut kinds: Vec<&str> = Vec::new();
        for a in [Access::Ro, Access::Rw, Access::W1c, Access::W1p] {
            if self.fields.iter().any(|f| f.access == a) {
                kinds.push(a.as_str());
            }
        }
        kinds.join("/")
    }
    /// Bits of all fields.
    pub fn defined_mask(&self) -> u32 {
        self.fields.iter().fold(0, |m, f| m | f.mask())
    }
    /// Bits of the fields with access `a`.
    pub fn mask_of(&self, a: Access) -> u32 {
        self.fields
            .iter()
            .filter(|f| f.access == a)
            .fold(0, |m, f| m | f.mask())
    }
    /// The field called `name`; panics if there is none (a typo in the caller).
    pub fn field(&self, name: &str) -> &Field {
        self.fields
            .iter()
            .find(|f| f.name == name)
            .unwrap_or_else(|| panic!("register {} has no field {name}", self.name))
    }
}

/// The parameters the register map depends on: the core's port widths and the generation
/// constants shown in the read-only registers. Made from [`Params`] by [`MapParams::new`];
/// the fields are public so that tests can also build the register file at widths that
/// `Params` does not currently offer (every width is checked by [`RegMap::from_map_params`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MapParams {
    /// N: `cfg_dt`, `cfg_timeout`, `nep`, `ndt` (8..=32).
    pub counter_bits: u32,
    /// F: fractional bits of the speeds (0..=24; S = N + F + 1 ≤ 57).
    pub speed_frac_bits: u32,
    /// C: `position`, `z_latch` (1..=32).
    pub position_bits: u32,
    /// FB: `cfg_filter` (1..=32).
    pub filter_bits: u32,
    /// G: the three fault counters (1..=32).
    pub error_count_bits: u32,
    /// Lines per revolution.
    pub lines: u32,
    /// Generation default dt, clock cycles (fits N bits).
    pub dt_cycles: u64,
    /// Generation default zero-speed timeout, dt intervals (fits N bits).
    pub timeout_dt: u64,
    /// Clock frequency, Hz.
    pub clock_hz: f64,
}

impl MapParams {
    /// The map parameters of validated [`Params`].
    pub fn new(p: &Params) -> MapParams {
        MapParams {
            counter_bits: p.counter_bits(),
            speed_frac_bits: p.speed_frac_bits(),
            position_bits: p.position_bits(),
            filter_bits: p.filter_bits(),
            error_count_bits: p.error_count_bits(),
            lines: p.lines(),
            dt_cycles: p.dt_cycles(),
            timeout_dt: p.timeout_dt(),
            clock_hz: p.clock_hz(),
        }
    }
    /// Map parameters of the given widths (N, F, C, FB, G), with plausible generation
    /// constants (100 MHz, lines = 2^(C − 2) up to 2^30, dt = min(100,000, 2^N − 1),
    /// timeout = min(1,000, 2^N − 2) dt): for testing the register file at widths that
    /// [`Params`] does not offer.
    pub fn for_widths(n: u32, f: u32, c: u32, fb: u32, g: u32) -> MapParams {
        let max = (1u64 << n) - 1;
        MapParams {
            counter_bits: n,
            speed_frac_bits: f,
            position_bits: c,
            filter_bits: fb,
            error_count_bits: g,
            lines: 1 << c.saturating_sub(2).min(30),
            dt_cycles: max.min(100_000),
            timeout_dt: (max - 1).min(1000),
            clock_hz: 100e6,
        }
    }
    /// S = N + F + 1: width of every speed (two's complement).
    pub fn speed_bits(&self) -> u32 {
        self.counter_bits + self.speed_frac_bits + 1
    }
    /// `CLOCK_HZ`: the clock rounded to a whole Hz, saturating at 2^32 − 1.
    pub fn clock_hz_word(&self) -> u32 {
        self.clock_hz.round().clamp(0.0, f64::from(u32::MAX)) as u32
    }
    fn check(&self) {
        let n = self.counter_bits;
        // The block is generic over every width (its tests take the extremes), so the
        // widths that `Params` fixes are checked here against the same limits.
        let range = crate::params::MIN_COUNTER_BITS..=crate::params::MAX_COUNTER_BITS;
        assert!(range.contains(&n), "counter_bits {n}: {range:?}");
        assert!(self.speed_frac_bits <= 24, "speed_frac_bits: 0..=24");
        for (w, what) in [
            (self.position_bits, "position_bits"),
            (self.filter_bits, "filter_bits"),
            (self.error_count_bits, "error_count_bits"),
        ] {
            assert!((1..=32).contains(&w), "{what} = {w}: 1..=32");
        }
        assert!(self.lines >= 1, "lines ≥ 1");
        assert!(bits_for(self.dt_cycles) <= n, "dt_cycles fits N bits");
        assert!(bits_for(self.timeout_dt) <= n, "timeout_dt fits N bits");
    }
}

/// The register map for one set of parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct RegMap {
    params: MapParams,
    registers: Vec<Register>,
}

pub(crate) fn field(name: &'static str, lsb: u32, width: u32, access: Access, d: &str) -> Field {
    Field {
        name,
        lsb,
        width,
        access,
        description: d.to_string(),
    }
}

impl RegMap {
    /// The map of validated [`Params`].
    pub fn new(p: &Params) -> RegMap {
        RegMap::from_map_params(MapParams::new(p))
    }

    /// The map of `mp`; panics if a width is outside the ranges of [`MapParams`].
    pub fn from_map_params(mp: MapParams) -> RegMap {
        mp.check();
        let registers = build(&mp);
        RegMap {
            params: mp,
            registers,
        }
    }

    /// The parameters.
    pub fn params(&self) -> &MapParams {
        &self.params
    }

    /// All registers, in address order.
    pub fn registers(&self) -> &[Register] {
        &self.registers
    }

    /// The register called `name`; panics if there is none (a typo in the caller).
    pub fn reg(&self, name: &str) -> &Register {
        self.registers
            .iter()
            .find(|r| r.name == name)
            .unwrap_or_else(|| panic!("no register {name}"))
    }

    /// The register at byte offset `offset` (bits 1:0 ignored), if any.
    pub fn at(&self, offset: u32) -> Option<&Register> {
        let o = offset & !3;
        self.registers.iter().find(|r| r.offset == o)
    }

    /// In-place mask of field `field` of register `reg`.
    pub fn mask(&self, reg: &str, field: &str) -> u32 {
        self.reg(reg).field(field).mask()
    }
}

/// The registers, in address order: the one description.
fn build(mp: &MapParams) -> Vec<Register> {
    use Access::{Ro, Rw, W1c, W1p};
    let n = mp.counter_bits;
    let s = mp.speed_bits();
    let c = mp.position_bits;
    let fb = mp.filter_bits;
    let g = mp.error_count_bits;
    let mode_bits = MODE_BITS;
    let reg = |name: &'static str,
               reset: Option<u32>,
               description: &str,
               side_effect: Option<String>,
               fields: Vec<Field>| Register {
        name,
        offset: offset(name).unwrap_or_else(|| panic!("{name} is not in LAYOUT")),
        reset,
        description: description.to_string(),
        side_effect,
        fields,
    };
    let value = |width: u32, access: Access, d: &str| field("VALUE", 0, width, access, d);
    let live = |name: &'static str, width: u32, d: &str, unit: &str| {
        reg(
            name,
            None,
            d,
            None,
            vec![value(width, Ro, &format!("{d}, {unit} (unsigned)"))],
        )
    };
    let param0 = n | (mp.speed_frac_bits << 8) | (s << 16) | (c << 24);
    let param1 = fb | (g << 8);
    let w1c_fault = |name, lsb, d: &str| field(name, lsb, 1, W1c, d);
    let irq_fields = |what: &str| {
        vec![
            field(
                "SPEED",
                0,
                1,
                Rw,
                &format!("{what} speed_strobe: speed_n1..n3 written"),
            ),
            field(
                "BASELINE",
                1,
                1,
                Rw,
                &format!("{what} baseline_strobe: speed_pc, speed_et, speed_mt written"),
            ),
            field("INDEX", 2, 1, Rw, &format!("{what} index: a Z edge")),
            field(
                "FAULT",
                3,
                1,
                Rw,
                &format!("{what} a rising edge of any sticky fault flag"),
            ),
            field(
                "UPDATE",
                4,
                1,
                Rw,
                &format!("{what} update: nep/ndt written"),
            ),
            field(
                "STALL",
                5,
                1,
                Rw,
                &format!("{what} a rising edge of stalled"),
            ),
            field(
                "SAMPLE",
                6,
                1,
                Rw,
                &format!("{what} a snapshot was taken (sample or CTRL.TRIGGER)"),
            ),
        ]
    };
    let irq_status_fields = irq_fields("Pending:")
        .into_iter()
        .map(|f| Field { access: W1c, ..f })
        .collect();
    let mut regs = vec![
        reg(
            "ID",
            Some(ID_MAGIC),
            "Identification: ASCII \"ENCS\"",
            None,
            vec![value(32, Ro, "0x454E4353")],
        ),
        reg(
            "VERSION",
            Some(MAP_VERSION),
            "Register map version",
            None,
            vec![
                field("MINOR", 0, 16, Ro, "minor version (compatible additions)"),
                field(
                    "MAJOR",
                    16,
                    16,
                    Ro,
                    "major version (an offset or a field moved)",
                ),
            ],
        ),
        reg(
            "PARAM0",
            Some(param0),
            "Generation widths, in bits",
            None,
            vec![
                field("COUNTER_BITS", 0, 8, Ro, "N: cfg_dt, cfg_timeout, nep, ndt"),
                field(
                    "SPEED_FRAC_BITS",
                    8,
                    8,
                    Ro,
                    "F: fractional bits of every speed (value = raw / 2^F, units of w_lim)",
                ),
                field(
                    "SPEED_BITS",
                    16,
                    8,
                    Ro,
                    "S = N + F + 1: width of every speed",
                ),
                field("POSITION_BITS", 24, 8, Ro, "C: position, z_latch"),
            ],
        ),
        reg(
            "PARAM1",
            Some(param1),
            "Generation widths, in bits",
            None,
            vec![
                field("FILTER_BITS", 0, 8, Ro, "FB: cfg_filter"),
                field("ERROR_COUNT_BITS", 8, 8, Ro, "G: the three fault counters"),
            ],
        ),
        reg(
            "LINES",
            Some(mp.lines),
            "Lines per revolution of the encoder disc",
            None,
            vec![value(32, Ro, "lines")],
        ),
        reg(
            "DT_DEFAULT",
            Some(mp.dt_cycles as u32),
            "Generation default dt, used while CFG_DT = 0",
            None,
            vec![value(n, Ro, "dt, clock cycles")],
        ),
        reg(
            "TIMEOUT_DEFAULT",
            Some(mp.timeout_dt as u32),
            "Generation default zero-speed timeout, used while CFG_TIMEOUT = 0",
            None,
            vec![value(n, Ro, "timeout, dt intervals")],
        ),
        reg(
            "CLOCK_HZ",
            Some(mp.clock_hz_word()),
            "Clock frequency the core was generated for",
            None,
            vec![value(32, Ro, "Hz, rounded (saturates at 2^32 - 1)")],
        ),
        reg(
            "CTRL",
            Some(0),
            "Decoding modes (drive cfg_mode, cfg_z_mode) and the snapshot",
            None,
            vec![
                field(
                    "MODE",
                    CTRL_MODE_LSB as u32,
                    mode_bits,
                    Rw,
                    "cfg_mode: 0 x1, 1 x2, 2 x4, 3 invalid (cfg_error)",
                ),
                field(
                    "Z_MODE",
                    CTRL_Z_MODE_LSB as u32,
                    mode_bits,
                    Rw,
                    "cfg_z_mode: 0 ignore Z, 1 Z resets position, 2 Z latches position, \
                     3 latch then reset",
                ),
                field(
                    "SAMPLED",
                    CTRL_SAMPLED_LSB as u32,
                    1,
                    Rw,
                    "1: POSITION, NEP, NDT, SPEED_* and STATUS.VALID, STALLED, DIRECTION \
                     read the snapshot; 0: live",
                ),
                field(
                    "HOLD",
                    CTRL_HOLD_LSB as u32,
                    1,
                    Rw,
                    "1: the sample input is ignored (the snapshot stays until TRIGGER)",
                ),
                field(
                    "TRIGGER",
                    CTRL_TRIGGER_LSB as u32,
                    1,
                    W1p,
                    "write 1: take a snapshot at the edge after the write edge",
                ),
            ],
        ),
        reg(
            "CFG_DT",
            Some(0),
            "dt (drives cfg_dt)",
            None,
            vec![value(n, Rw, "dt, clock cycles; 0 = DT_DEFAULT")],
        ),
        reg(
            "CFG_TIMEOUT",
            Some(0),
            "Zero-speed timeout (drives cfg_timeout)",
            None,
            vec![value(n, Rw, "timeout, dt intervals; 0 = TIMEOUT_DEFAULT")],
        ),
        reg(
            "CFG_FILTER",
            Some(0),
            "Glitch filter length (drives cfg_filter)",
            None,
            vec![value(fb, Rw, "filter length, clock cycles; 0 = off")],
        ),
        reg(
            "STATUS",
            None,
            "Core status levels (live; VALID, STALLED, DIRECTION the snapshot's with \
             CTRL.SAMPLED) and sticky faults",
            Some(
                "a write with a 1 in any FAULT_* bit (byte lane 0) pulses clear_faults, \
                 which clears all three fault flags"
                    .to_string(),
            ),
            vec![
                field(
                    "VALID",
                    0,
                    1,
                    Ro,
                    "valid: speed_n3 holds a measurement, not stalled, legal configuration",
                ),
                field(
                    "STALLED",
                    1,
                    1,
                    Ro,
                    "stalled: no step for the zero-speed timeout",
                ),
                field(
                    "DIRECTION",
                    2,
                    1,
                    Ro,
                    "direction of the last step: 1 forward",
                ),
                field("CFG_ERROR", 3, 1, Ro, "cfg_error: illegal configuration"),
                w1c_fault("FAULT_ILLEGAL", 4, "sticky: an illegal A/B transition"),
                w1c_fault(
                    "FAULT_OVERSPEED",
                    5,
                    "sticky: the A or B glitch filter rejected a pulse",
                ),
                w1c_fault(
                    "FAULT_REVOLUTION",
                    6,
                    "sticky: a revolution between index edges had the wrong count",
                ),
            ],
        ),
        reg(
            "IRQ_ENABLE",
            Some(0),
            "Interrupt enables: irq = (IRQ_STATUS & IRQ_ENABLE) != 0",
            None,
            irq_fields("Enable:"),
        ),
        reg(
            "IRQ_STATUS",
            Some(0),
            "Interrupt events, latched whether enabled or not",
            Some("a written 1 clears the bit; an event at the same edge wins".to_string()),
            irq_status_fields,
        ),
        live(
            "POSITION",
            c,
            "position (the snapshot's with CTRL.SAMPLED)",
            "steps (modulo the steps per revolution)",
        ),
        live(
            "Z_LATCH",
            c,
            "position latched at the last index edge",
            "steps",
        ),
        live(
            "NEP",
            n,
            "Nep1: encoder pulses of the last window (the snapshot's with CTRL.SAMPLED)",
            "pulses",
        ),
        live(
            "NDT",
            n,
            "Ndt1: dt intervals between the last two pulses (the snapshot's with CTRL.SAMPLED)",
            "dt intervals",
        ),
    ];
    for (lo, hi, port) in SPEEDS {
        let lo_name = LAYOUT.iter().find(|e| e.1 == lo).unwrap().0;
        let hi_name = LAYOUT.iter().find(|e| e.1 == hi).unwrap().0;
        regs.push(reg(
            lo_name,
            None,
            &format!(
                "{port} (live; the snapshot's with CTRL.SAMPLED), Q{n}.{} in units of w_lim, \
                 sign-extended to 64 bits: low word",
                mp.speed_frac_bits
            ),
            Some(format!("a read latches the high word into {hi_name}")),
            vec![value(32, Ro, &format!("bits 31:0 of sign-extended {port}"))],
        ));
        regs.push(reg(
            hi_name,
            Some(0),
            &format!("{port}: high word, as latched by the last read of {lo_name}"),
            None,
            vec![value(
                32,
                Ro,
                &format!("bits 63:32 of sign-extended {port} ({s} bits wide)"),
            )],
        ));
    }
    regs.push(live(
        "GLITCH_COUNT",
        g,
        "pulses rejected by the A, B and Z filters (saturating)",
        "pulses",
    ));
    regs.push(live(
        "ILLEGAL_COUNT",
        g,
        "illegal A/B transitions (saturating)",
        "transitions",
    ));
    regs.push(live(
        "REV_ERROR_COUNT",
        g,
        "revolutions with the wrong count (saturating)",
        "revolutions",
    ));
    regs.push(live(
        "SNAP_COUNT",
        32,
        "snapshots taken since reset",
        "snapshots, modulo 2^32",
    ));
    regs
}

/// The parameters a generated file states in its header, one per line.
fn param_lines(mp: &MapParams) -> Vec<String> {
    vec![
        format!("counter_bits N = {}", mp.counter_bits),
        format!("speed_frac_bits F = {}", mp.speed_frac_bits),
        format!("speed_bits S = {}", mp.speed_bits()),
        format!("position_bits C = {}", mp.position_bits),
        format!("filter_bits FB = {}", mp.filter_bits),
        format!("error_count_bits G = {}", mp.error_count_bits),
        format!("lines = {}", mp.lines),
        format!("dt_cycles = {} (nominal dt)", mp.dt_cycles),
        format!(
            "timeout_dt = {} (default timeout, dt intervals)",
            mp.timeout_dt
        ),
        format!("clock_hz = {}", mp.clock_hz),
    ]
}

/// `#define name value`, with a comment if given.
pub(crate) fn c_define(h: &mut String, name: &str, value: &str, comment: Option<&str>) {
    let _ = match comment {
        Some(c) => writeln!(h, "#define {name:<44} {value} /* {} */", c_text(c)),
        None => writeln!(h, "#define {name:<44} {value}"),
    };
}

/// A C comment body: no "*/" and no line breaks.
fn c_text(s: &str) -> String {
    s.replace("*/", "* /").replace('\n', " ")
}

/// `#define`s of `registers`: `ENCSPEED_<REG>_OFFSET`, `_RESET` (registers the file holds),
/// `ENCSPEED_<REG>_<FIELD>_SHIFT`, `_WIDTH`, `_MASK`, each register under a comment.
pub(crate) fn c_registers(h: &mut String, registers: &[Register]) {
    for r in registers {
        let mut head = format!("{} ({}): {}", r.name, r.access(), r.description);
        if let Some(e) = &r.side_effect {
            head += &format!("; {e}");
        }
        let _ = writeln!(h, "\n/* {} */", c_text(&head));
        let p = format!("ENCSPEED_{}", r.name);
        c_define(
            h,
            &format!("{p}_OFFSET"),
            &format!("0x{:02X}u", r.offset),
            None,
        );
        if let Some(v) = r.reset {
            c_define(h, &format!("{p}_RESET"), &format!("0x{v:08X}u"), None);
        }
        for f in &r.fields {
            let q = format!("{p}_{}", f.name);
            let d = format!("[{}] {}: {}", f.bits(), f.access.as_str(), f.description);
            c_define(h, &format!("{q}_SHIFT"), &format!("{}u", f.lsb), Some(&d));
            c_define(h, &format!("{q}_WIDTH"), &format!("{}u", f.width), None);
            c_define(
                h,
                &format!("{q}_MASK"),
                &format!("0x{:08X}u", f.mask()),
                None,
            );
        }
    }
}

/// The summary table of `registers`, then one field table per register, in Markdown.
pub(crate) fn markdown_registers(m: &mut String, registers: &[Register]) {
    *m += "| offset | register | access | reset | description |\n";
    *m += "|---|---|---|---|---|\n";
    for r in registers {
        let reset = match r.reset {
            Some(v) => format!("0x{v:08X}"),
            None => "live".to_string(),
        };
        let mut d = r.description.clone();
        if let Some(e) = &r.side_effect {
            d += &format!("; {e}");
        }
        let _ = writeln!(
            m,
            "| 0x{:02X} | {} | {} | {reset} | {} |",
            r.offset,
            r.name,
            r.access(),
            d.replace('|', "\\|")
        );
    }
    for r in registers {
        let _ = writeln!(m, "\n## {} (0x{:02X})\n", r.name, r.offset);
        *m += "| bits | field | access | description |\n|---|---|---|---|\n";
        for f in &r.fields {
            let _ = writeln!(
                m,
                "| {} | {} | {} | {} |",
                f.bits(),
                f.name,
                f.access.as_str(),
                f.description.replace('|', "\\|")
            );
        }
    }
}

impl RegMap {
    /// The C header: include guard, `ENCSPEED_<REG>_OFFSET`, `_RESET` (registers the file
    /// holds), `ENCSPEED_<REG>_<FIELD>_SHIFT`, `_WIDTH`, `_MASK` (in place), the parameters
    /// as `ENCSPEED_<PARAM>` and a comment header naming the generator and the parameters.
    /// C99, compiles cleanly with `gcc -std=c99 -Wall -Wextra -Werror`.
    pub fn c_header(&self) -> String {
        let mp = &self.params;
        let mut h = String::new();
        h += "/*\n * encspeed_regs.h: register map of encspeed_core (Wishbone B4 classic, 32-bit).\n";
        h += &format!(
            " * Generated by encspeed-golden {} (golden::bus::regmap::c_header); do not edit.\n",
            env!("CARGO_PKG_VERSION")
        );
        h += " * Parameters:\n";
        for l in param_lines(mp) {
            h += &format!(" *   {l}\n");
        }
        h += " * Offsets are in bytes from the base of the register window. Read a speed's\n";
        h += " * _LO register, then its _HI register: the LO read latches HI (coherent pair).\n";
        h += " * Writing 1 to any STATUS FAULT_* bit clears all three fault flags.\n";
        h += " * The sample input (or a write of 1 to CTRL.TRIGGER) takes a coherent snapshot;\n";
        h += " * with CTRL.SAMPLED = 1 the value registers read it (CTRL.HOLD: sample ignored).\n */\n";
        h += "#ifndef ENCSPEED_REGS_H\n#define ENCSPEED_REGS_H\n\n";
        let params: [(&str, String, &str); 14] = [
            ("ID_MAGIC", format!("0x{ID_MAGIC:08X}u"), "ASCII \"ENCS\""),
            (
                "MAP_VERSION",
                format!("0x{MAP_VERSION:08X}u"),
                "major 31:16, minor 15:0",
            ),
            (
                "ADDR_BITS",
                format!("{ADDR_BITS}u"),
                "wb_adr_i width (byte address)",
            ),
            ("SPAN_BYTES", format!("0x{SPAN_BYTES:X}u"), "bytes decoded"),
            ("COUNTER_BITS", format!("{}u", mp.counter_bits), "N"),
            (
                "SPEED_FRAC_BITS",
                format!("{}u", mp.speed_frac_bits),
                "F: speed = raw / 2^F, units of w_lim",
            ),
            (
                "SPEED_BITS",
                format!("{}u", mp.speed_bits()),
                "S = N + F + 1",
            ),
            ("POSITION_BITS", format!("{}u", mp.position_bits), "C"),
            ("FILTER_BITS", format!("{}u", mp.filter_bits), "FB"),
            ("ERROR_COUNT_BITS", format!("{}u", mp.error_count_bits), "G"),
            ("LINES", format!("{}u", mp.lines), "lines per revolution"),
            ("DT_DEFAULT", format!("{}u", mp.dt_cycles), "clock cycles"),
            (
                "TIMEOUT_DEFAULT",
                format!("{}u", mp.timeout_dt),
                "dt intervals",
            ),
            ("CLOCK_HZ", format!("{}u", mp.clock_hz_word()), "Hz"),
        ];
        for (name, value, comment) in params {
            c_define(&mut h, &format!("ENCSPEED_{name}"), &value, Some(comment));
        }
        c_registers(&mut h, &self.registers);
        h += "\n#endif /* ENCSPEED_REGS_H */\n";
        h
    }

    /// The register map as Markdown: parameters, the summary table, then one field table
    /// per register.
    pub fn markdown(&self) -> String {
        let mp = &self.params;
        let mut m = String::new();
        m += "# encspeed_core register map\n\n";
        m += &format!(
            "Generated by `golden::bus::regmap::markdown` (map version {}.{}). Wishbone B4 classic, \
             32-bit data, {ADDR_BITS}-bit byte address (window of {SPAN_BYTES} bytes). \
             Parameters: {}.\n\n",
            MAP_VERSION >> 16,
            MAP_VERSION & 0xFFFF,
            param_lines(mp).join(", ")
        );
        m += "Reads of unmapped offsets return 0; writes to them, and to read-only bits, \
              are ignored. Reserved bits read 0. Read a speed's LO register before its HI \
              register: the LO read latches HI. Writing 1 to any STATUS FAULT_* bit clears \
              all three fault flags.\n\n";
        markdown_registers(&mut m, &self.registers);
        m
    }
}

/// The registers of `p`, in address order.
pub fn registers(p: &Params) -> Vec<Register> {
    RegMap::new(p).registers
}

/// The C header of the register map of `p` ([`RegMap::c_header`]), after the command that
/// regenerates it and the licence.
pub fn c_header(p: &Params) -> String {
    use crate::provenance::{generate_command, preamble, Comment};
    let mut h = RegMap::new(p).c_header();
    if p.channels() > 1 {
        let end = h.rfind("\n#endif").expect("the header ends with its guard");
        h.insert_str(end, &channel_defines(p.channels()));
    }
    preamble(Comment::Block, &generate_command(p)) + &h
}

/// The `#define`s of an `encspeed_wb` with `channels` (≥ 2) channels: their number, the
/// address width, and each channel's base (`crate::top::wb_channels`).
fn channel_defines(channels: u32) -> String {
    use crate::top::wb_channels::{address_bits, channel_base};
    let mut h = String::from(
        "\n/* Channels: encspeed_wb with several encoders, one register window each; channel c's\n \
         * register R is at ENCSPEED_CHANNEL_BASE(c) + ENCSPEED_R_OFFSET. Windows above the last\n \
         * channel read 0. */\n",
    );
    c_define(
        &mut h,
        "ENCSPEED_CHANNELS",
        &format!("{channels}u"),
        Some("encoder channels"),
    );
    c_define(
        &mut h,
        "ENCSPEED_CHANNEL_ADDR_BITS",
        &format!("{}u", address_bits(channels)),
        Some("wb_adr_i width of the top (byte address)"),
    );
    c_define(
        &mut h,
        "ENCSPEED_CHANNEL_STRIDE",
        &format!("0x{SPAN_BYTES:X}u"),
        Some("bytes between channel windows"),
    );
    c_define(
        &mut h,
        "ENCSPEED_CHANNEL_BASE(c)",
        &format!("((unsigned)(c) * 0x{SPAN_BYTES:X}u)"),
        Some("byte address of channel c's window"),
    );
    for c in 0..channels {
        c_define(
            &mut h,
            &format!("ENCSPEED_CH{c}_BASE"),
            &format!("0x{:03X}u", channel_base(c)),
            None,
        );
    }
    h
}

/// The register map of `p` as Markdown ([`RegMap::markdown`]).
pub fn markdown(p: &Params) -> String {
    RegMap::new(p).markdown()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Spec;
    use std::path::PathBuf;
    use std::process::Command;

    fn default_map() -> RegMap {
        RegMap::new(&Params::new(Spec::default()).unwrap())
    }

    /// The small widths of the register-file tests (N = 8, F = 2, C = 4, FB = 1, G = 1).
    fn small_map() -> RegMap {
        RegMap::from_map_params(MapParams {
            counter_bits: 8,
            speed_frac_bits: 2,
            position_bits: 4,
            filter_bits: 1,
            error_count_bits: 1,
            lines: 3,
            dt_cycles: 100,
            timeout_dt: 10,
            clock_hz: 1e6,
        })
    }

    /// The widest ports: N = 32, F = 24 (S = 57), C = FB = G = 32.
    fn wide_map() -> RegMap {
        RegMap::from_map_params(MapParams {
            counter_bits: 32,
            speed_frac_bits: 24,
            position_bits: 32,
            filter_bits: 32,
            error_count_bits: 32,
            lines: 1 << 30,
            dt_cycles: u64::from(u32::MAX),
            timeout_dt: u64::from(u32::MAX) - 1,
            clock_hz: 5e9,
        })
    }

    fn maps() -> Vec<RegMap> {
        vec![default_map(), small_map(), wide_map()]
    }

    #[test]
    fn layout_and_registers_agree_and_offsets_are_distinct_aligned_and_in_the_window() {
        for map in maps() {
            let regs = map.registers();
            assert_eq!(regs.len(), LAYOUT.len());
            for (r, (name, off)) in regs.iter().zip(LAYOUT) {
                assert_eq!((r.name, r.offset), (*name, *off));
                assert_eq!(r.offset % 4, 0, "{} aligned", r.name);
                assert!(r.offset < SPAN_BYTES, "{} in the window", r.name);
                assert_eq!(offset(name), Some(*off));
            }
            for w in regs.windows(2) {
                assert!(
                    w[0].offset < w[1].offset,
                    "{} before {}",
                    w[0].name,
                    w[1].name
                );
            }
        }
        assert_eq!(offset("NO_SUCH"), None);
        // ADDR_BITS is the fewest bits that hold the highest offset's word address, rounded
        // up to whole bytes... at least: it must hold it.
        assert!(LAYOUT.last().unwrap().1 < (1 << ADDR_BITS));
    }

    #[test]
    fn fields_fit_32_bits_do_not_overlap_and_reset_values_fit_them() {
        for map in maps() {
            for r in map.registers() {
                assert!(!r.fields.is_empty(), "{}", r.name);
                let mut seen = 0u32;
                for f in &r.fields {
                    assert!(
                        f.width >= 1 && f.lsb + f.width <= 32,
                        "{}.{}",
                        r.name,
                        f.name
                    );
                    assert_eq!(seen & f.mask(), 0, "{}.{} overlaps", r.name, f.name);
                    seen |= f.mask();
                    assert!(
                        f.name.chars().all(|c| c.is_ascii_uppercase() || c == '_'),
                        "{}",
                        f.name
                    );
                }
                if let Some(v) = r.reset {
                    assert_eq!(v & !r.defined_mask(), 0, "{} reset in its fields", r.name);
                }
                // Registers the file holds have a reset value; RW and W1C registers are held.
                if r.mask_of(Access::Rw) != 0 || r.name == "IRQ_STATUS" {
                    assert_eq!(r.reset, Some(0), "{}", r.name);
                }
            }
        }
    }

    #[test]
    fn hand_checked_offsets_fields_and_constants() {
        assert_eq!(ID, 0x00);
        assert_eq!(CTRL, 0x20);
        assert_eq!(STATUS, 0x30);
        assert_eq!(SPEED_N3_LO, 0x60);
        assert_eq!(SPEED_N3_HI, 0x64);
        assert_eq!(REV_ERROR_COUNT, 0x88);
        // 'E' = 0x45, 'N' = 0x4E, 'C' = 0x43, 'S' = 0x53.
        assert_eq!(ID_MAGIC, 0x454E_4353);
        let m = small_map();
        // N = 8, F = 2, S = 11, C = 4 → 0x040B0208; FB = 1, G = 1 → 0x0101.
        assert_eq!(m.reg("PARAM0").reset, Some(0x040B_0208));
        assert_eq!(m.reg("PARAM1").reset, Some(0x0101));
        assert_eq!(m.reg("CFG_DT").defined_mask(), 0xFF);
        assert_eq!(m.reg("CFG_FILTER").defined_mask(), 0x1);
        assert_eq!(m.mask("CTRL", "Z_MODE"), 0b1100);
        assert_eq!(m.reg("STATUS").mask_of(Access::W1c), 0x70);
        assert_eq!(m.reg("STATUS").access(), "RO/W1C");
        assert_eq!(m.reg("IRQ_STATUS").access(), "W1C");
        assert_eq!(m.reg("CLOCK_HZ").reset, Some(1_000_000));
        assert_eq!(wide_map().reg("CLOCK_HZ").reset, Some(u32::MAX));
        assert_eq!(m.at(0x62).unwrap().name, "SPEED_N3_LO");
        assert!(m.at(0x3C).is_none());
    }

    fn out_dir(name: &str) -> PathBuf {
        tools::work_dir("regmap", name).unwrap()
    }

    /// The header compiles with gcc (C99, all warnings as errors), and a C file that
    /// includes it checks at compile time that every offset, reset value and field mask
    /// is the map's.
    #[test]
    fn c_header_compiles_with_gcc_and_its_values_are_the_maps() {
        for (k, map) in maps().into_iter().enumerate() {
            let dir = out_dir(&format!("c_header_{k}"));
            std::fs::write(dir.join("encspeed_regs.h"), map.c_header()).unwrap();
            let mut c = String::from("#include \"encspeed_regs.h\"\n");
            let mut check = |i: &mut u32, expr: String, v: u32| {
                *i += 1;
                c += &format!("typedef char check_{i}[(({expr}) == 0x{v:X}u) ? 1 : -1];\n");
            };
            let mut i = 0;
            for r in map.registers() {
                check(&mut i, format!("ENCSPEED_{}_OFFSET", r.name), r.offset);
                if let Some(v) = r.reset {
                    check(&mut i, format!("ENCSPEED_{}_RESET", r.name), v);
                }
                for f in &r.fields {
                    let q = format!("ENCSPEED_{}_{}", r.name, f.name);
                    check(&mut i, format!("{q}_MASK"), f.mask());
                    check(&mut i, format!("{q}_SHIFT"), f.lsb);
                    check(
                        &mut i,
                        format!("(({q}_MASK >> {q}_SHIFT) + 1u) & 0xFFFFFFFFu"),
                        ((1u64 << f.width) & 0xFFFF_FFFF) as u32,
                    );
                }
            }
            check(
                &mut i,
                "ENCSPEED_SPEED_FRAC_BITS".into(),
                map.params().speed_frac_bits,
            );
            check(&mut i, "ENCSPEED_ID_MAGIC".into(), ID_MAGIC);
            c += "int main(void) { return (int)(ENCSPEED_SPEED_N3_LO_OFFSET - 0x60u); }\n";
            std::fs::write(dir.join("check.c"), c).unwrap();
            let gcc = |args: &[&str]| {
                let mut cmd = Command::new("gcc");
                cmd.current_dir(&dir)
                    .args(["-fsyntax-only", "-std=c99", "-Wall", "-Werror"])
                    .args(args);
                if let Err(e) = tools::run(&mut cmd, "gcc") {
                    panic!("in {}: {e}", dir.display());
                }
            };
            gcc(&["encspeed_regs.h"]);
            gcc(&["-Wextra", "-pedantic-errors", "check.c"]);
        }
    }

    #[test]
    fn c_header_has_guard_and_generator_comment_and_is_deterministic() {
        let p = Params::new(Spec::default()).unwrap();
        let h = c_header(&p);
        let command = crate::provenance::generate_command(&p);
        assert!(h.starts_with(&format!(
            "/* Command: {command} */\n/* SPDX-License-Identifier: MIT OR Apache-2.0 */\n\
             /*\n * encspeed_regs.h"
        )));
        assert!(h.contains("#ifndef ENCSPEED_REGS_H\n#define ENCSPEED_REGS_H\n"));
        assert!(h.trim_end().ends_with("#endif /* ENCSPEED_REGS_H */"));
        assert!(h.contains(&format!("counter_bits N = {}", p.counter_bits())));
        assert!(h.contains("#define ENCSPEED_SPEED_N3_LO_OFFSET"));
        assert_eq!(h, c_header(&p));
        assert!(!h.contains("\n\n\n"), "no double blank lines");
    }

    #[test]
    fn markdown_lists_every_register_with_its_offset() {
        let p = Params::new(Spec::default()).unwrap();
        let md = markdown(&p);
        std::fs::write(out_dir("markdown").join("encspeed_regs.md"), &md).unwrap();
        for r in registers(&p) {
            assert!(
                md.contains(&format!(
                    "| 0x{:02X} | {} | {} |",
                    r.offset,
                    r.name,
                    r.access()
                )),
                "{}",
                r.name
            );
            assert!(md.contains(&format!("## {} (0x{:02X})", r.name, r.offset)));
        }
    }
}
