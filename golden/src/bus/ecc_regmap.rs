// SPDX-License-Identifier: MIT OR Apache-2.0
//! The register window of the eccentricity corrector and identification in
//! `encspeed_ecc_wb`, as data: the one description from which the hardware
//! (`hdl::EccRegs`), its cycle model ([`crate::bus::ecc_regs::EccRegsModel`]), the C header
//! ([`c_header`]) and the documentation ([`markdown`]) are made.
//!
//! `encspeed_ecc_wb` is `encspeed_ecc` behind one Wishbone window of
//! [`crate::bus::regmap::SPAN_BYTES`] bytes: offsets below [`ECC_BASE`] are the core's register
//! file, exactly as [`crate::bus::regmap`] describes it (same offsets, fields and behaviour);
//! offsets from [`ECC_BASE`] up are this window, served by its own slave with the same bus
//! protocol (a request is executed at the edge that samples it and acknowledged in the
//! cycle after the next edge: three cycles per access; unmapped offsets read 0; writes
//! honour `wb_sel_i`; reserved bits read 0). `irq` is the OR of both slaves' interrupt
//! requests.
//!
//! # Coefficients
//!
//! `ECC_C` and `ECC_D` are staging registers: a write changes neither `ecc_c` nor `ecc_d`.
//! A write of 1 to `ECC_CTRL.LOAD` copies both to the corrector's inputs at that write's
//! edge, so that no estimate is ever corrected with a new c and an old d.
//!
//! # Identification
//!
//! A write of 1 to `ECC_CTRL.IDENT_ARM` pulses `ident_arm` for the cycle after the write
//! edge (`encspeed_ecc` holds an arm that comes before the first index until that index).
//! `ECC_STATUS.IDENT_DONE` rises when the revolution after the arm is gathered; the
//! `IDENT_*` registers then hold the results and do not change until the next arm takes
//! effect, so they can be read in any order. The 72-bit sums are three words each: bits
//! 31:0, 63:32, and 71:64 sign-extended to 32 bits.
//!
//! # Coherence of the corrected speeds
//!
//! As for the core's speeds: reading `SPEED_MTC_LO` (`SPEED_N3C_LO`) latches bits 63:32 of
//! the speed, sign-extended to 64 bits, into the shadow that `SPEED_MTC_HI`
//! (`SPEED_N3C_HI`) returns.
//!
//! # Snapshot
//!
//! The core register file's snapshot ([`crate::bus::regmap`], "Snapshot": the `sample`
//! input, `CTRL.TRIGGER`, `CTRL.HOLD`) stores the two corrected speeds too, at the same
//! edge and from the same cycle as position and the six speeds of the core, and while
//! `CTRL.SAMPLED` = 1 the `SPEED_MTC` and `SPEED_N3C` pairs read them instead of the live
//! speeds (a LO read latches HI from the snapshot). After reset they are 0. The window has
//! no controls of its own for this: one `sample` strobe takes all eight speeds.
//!
//! # Interrupts
//!
//! `ECC_IRQ_STATUS` latches `mtc_strobe`, `n3c_strobe` and the rising edge of `ident_done`
//! at every edge, enabled or not; a write of 1 clears a bit, except that an event at the
//! same edge wins. The window's interrupt request is (`ECC_IRQ_STATUS` & `ECC_IRQ_ENABLE`)
//! ≠ 0, a function of registers only.

use crate::bus::regmap::{
    c_define, c_registers, field, layout, markdown_registers, Access, Register, ADDR_BITS,
    SPAN_BYTES,
};
use crate::ecc::line_tap::IDENT_SUM_BITS;
use crate::params::Params;

/// First byte offset of the window; the core's register file serves the offsets below.
pub const ECC_BASE: u32 = 0x90;
/// The `ECC_ID` register: ASCII "ENCE", 'E' in the top byte.
pub const ECC_ID_MAGIC: u32 = u32::from_be_bytes(*b"ENCE");
/// Version of this window's map: major 31:16, minor 15:0.
pub const ECC_MAP_VERSION: u32 = 0x0001_0000;
/// Width of `ecc_c` and `ecc_d` (Q15.16 lines, two's complement).
pub const COEF_BITS: u32 = 32;

layout! {
    /// Constant magic [`ECC_ID_MAGIC`].
    ECC_ID = 0x90;
    /// Window map version [`ECC_MAP_VERSION`].
    ECC_VERSION = 0x94;
    /// Pulses: arm the identification, load the coefficients.
    ECC_CTRL = 0x98;
    /// Identification status.
    ECC_STATUS = 0x9C;
    /// Staged coefficient c.
    ECC_C = 0xA0;
    /// Staged coefficient d.
    ECC_D = 0xA4;
    /// Interrupt enables.
    ECC_IRQ_ENABLE = 0xA8;
    /// Interrupt events (W1C).
    ECC_IRQ_STATUS = 0xAC;
    /// `speed_mtc` bits 31:0; latches [`SPEED_MTC_HI`].
    SPEED_MTC_LO = 0xB0;
    /// `speed_mtc` bits 63:32 (shadow).
    SPEED_MTC_HI = 0xB4;
    /// `speed_n3c` bits 31:0; latches [`SPEED_N3C_HI`].
    SPEED_N3C_LO = 0xB8;
    /// `speed_n3c` bits 63:32 (shadow).
    SPEED_N3C_HI = 0xBC;
    /// `ident_count`.
    IDENT_COUNT = 0xC0;
    /// `ident_t_min`.
    IDENT_T_MIN = 0xC4;
    /// `ident_t_max`.
    IDENT_T_MAX = 0xC8;
    /// `ident_p_min`, `ident_p_max`.
    IDENT_P = 0xCC;
    /// `ident_sum_t` bits 31:0.
    IDENT_SUM_T_W0 = 0xD0;
    /// `ident_sum_t` bits 63:32.
    IDENT_SUM_T_W1 = 0xD4;
    /// `ident_sum_t` bits 71:64, sign-extended.
    IDENT_SUM_T_W2 = 0xD8;
    /// `ident_sum_sin` bits 31:0.
    IDENT_SUM_SIN_W0 = 0xDC;
    /// `ident_sum_sin` bits 63:32.
    IDENT_SUM_SIN_W1 = 0xE0;
    /// `ident_sum_sin` bits 71:64, sign-extended.
    IDENT_SUM_SIN_W2 = 0xE4;
    /// `ident_sum_cos` bits 31:0.
    IDENT_SUM_COS_W0 = 0xE8;
    /// `ident_sum_cos` bits 63:32.
    IDENT_SUM_COS_W1 = 0xEC;
    /// `ident_sum_cos` bits 71:64, sign-extended.
    IDENT_SUM_COS_W2 = 0xF0;
}

/// The two corrected speeds as (LO offset, HI offset, port), in map order.
pub const ECC_SPEEDS: [(u32, u32, &str); 2] = [
    (SPEED_MTC_LO, SPEED_MTC_HI, "speed_mtc"),
    (SPEED_N3C_LO, SPEED_N3C_HI, "speed_n3c"),
];

/// The three identification sums as (offset of word 0, port); words 1 and 2 follow at +4
/// and +8.
pub const IDENT_SUMS: [(u32, &str); 3] = [
    (IDENT_SUM_T_W0, "ident_sum_t"),
    (IDENT_SUM_SIN_W0, "ident_sum_sin"),
    (IDENT_SUM_COS_W0, "ident_sum_cos"),
];

/// Whether byte offset `adr` belongs to this window (else to the core's register file).
pub fn in_window(adr: u32) -> bool {
    (ECC_BASE..SPAN_BYTES).contains(&adr)
}

/// Word `k` (0, 1, 2) of a 72-bit two's complement sum `v`, as the registers show it.
pub fn sum_word(v: i128, k: usize) -> u32 {
    assert!(k < 3, "a sum has three words");
    ((v >> (32 * k)) as u64 & 0xFFFF_FFFF) as u32
}

/// The 72-bit sum whose three register words are `w` ([`sum_word`] inverted).
pub fn sum_of_words(w: [u32; 3]) -> i128 {
    let v = i128::from(w[0]) | (i128::from(w[1]) << 32) | (i128::from(w[2] as i32) << 64);
    let shift = 128 - IDENT_SUM_BITS;
    (v << shift) >> shift
}

/// The registers of the window for speeds of `speed_bits` bits, in address order.
pub fn registers(speed_bits: u32) -> Vec<Register> {
    use Access::{Ro, Rw, W1c, W1p};
    let reg = |name: &'static str,
               reset: Option<u32>,
               description: &str,
               side_effect: Option<String>,
               fields: Vec<crate::bus::regmap::Field>| Register {
        name,
        offset: LAYOUT
            .iter()
            .find(|(n, _)| *n == name)
            .unwrap_or_else(|| panic!("{name} is not in LAYOUT"))
            .1,
        reset,
        description: description.to_string(),
        side_effect,
        fields,
    };
    let value = |width: u32, access: Access, d: &str| field("VALUE", 0, width, access, d);
    let irq_fields = |what: &str, access: Access| {
        vec![
            field(
                "MTC",
                0,
                1,
                access,
                &format!("{what} mtc_strobe: speed_mtc written"),
            ),
            field(
                "N3C",
                1,
                1,
                access,
                &format!("{what} n3c_strobe: speed_n3c written"),
            ),
            field(
                "IDENT",
                2,
                1,
                access,
                &format!("{what} a rising edge of ident_done"),
            ),
        ]
    };
    let mut regs = vec![
        reg(
            "ECC_ID",
            Some(ECC_ID_MAGIC),
            "Identification of the eccentricity window: ASCII \"ENCE\"",
            None,
            vec![value(32, Ro, "0x454E4345")],
        ),
        reg(
            "ECC_VERSION",
            Some(ECC_MAP_VERSION),
            "Eccentricity window map version",
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
            "ECC_CTRL",
            Some(0),
            "Identification arm and coefficient load (pulses)",
            None,
            vec![
                field(
                    "IDENT_ARM",
                    0,
                    1,
                    W1p,
                    "1: pulse ident_arm: gather the next revolution, index to index, forward \
                     at constant speed, CTRL.Z_MODE 1 or 3 (an arm before the first index \
                     since reset or a mode change waits for it); clears ECC_STATUS.IDENT_DONE",
                ),
                field(
                    "LOAD",
                    1,
                    1,
                    W1p,
                    "1: ecc_c <- ECC_C and ecc_d <- ECC_D together; estimates requested \
                     from the next edge on are corrected with them",
                ),
            ],
        ),
        reg(
            "ECC_STATUS",
            None,
            "Identification status (live)",
            None,
            vec![
                field(
                    "IDENT_DONE",
                    0,
                    1,
                    Ro,
                    "the IDENT_* registers hold a complete revolution (until the next arm)",
                ),
                field(
                    "IDENT_OVERFLOW",
                    1,
                    1,
                    Ro,
                    "more than 2^16 lines between the index pulses: results not usable",
                ),
            ],
        ),
        reg(
            "ECC_C",
            Some(0),
            "Staged c = E cos(theta0), loaded by ECC_CTRL.LOAD",
            None,
            vec![value(
                COEF_BITS,
                Rw,
                "c, Q15.16 lines, two's complement (E = lines * e / 2pi)",
            )],
        ),
        reg(
            "ECC_D",
            Some(0),
            "Staged d = E sin(theta0), loaded by ECC_CTRL.LOAD",
            None,
            vec![value(COEF_BITS, Rw, "d, Q15.16 lines, two's complement")],
        ),
        reg(
            "ECC_IRQ_ENABLE",
            Some(0),
            "Interrupt enables of the window",
            None,
            irq_fields("Enable:", Rw),
        ),
        reg(
            "ECC_IRQ_STATUS",
            Some(0),
            "Interrupt events of the window, latched whether enabled or not",
            None,
            irq_fields("Pending:", W1c),
        ),
    ];
    for (lo, hi, port) in ECC_SPEEDS {
        let upper = port.to_uppercase();
        let lo_name = LAYOUT.iter().find(|e| e.1 == lo).unwrap().0;
        let hi_name = LAYOUT.iter().find(|e| e.1 == hi).unwrap().0;
        regs.push(reg(
            lo_name,
            None,
            &format!("{port} bits 31:0 (speed_bits S = {speed_bits})"),
            Some(format!("a read latches {hi_name}")),
            vec![value(
                32,
                Ro,
                &format!("{upper} bits 31:0 of its 64-bit sign extension"),
            )],
        ));
        regs.push(reg(
            hi_name,
            Some(0),
            &format!("{port} bits 63:32, from the last read of {lo_name}"),
            None,
            vec![value(32, Ro, &format!("{upper} bits 63:32 (shadow)"))],
        ));
    }
    regs.push(reg(
        "IDENT_COUNT",
        None,
        "Forward lines gathered (lines per revolution for a clean revolution)",
        None,
        vec![value(17, Ro, "ident_count, lines")],
    ));
    regs.push(reg(
        "IDENT_T_MIN",
        None,
        "Shortest line period (Zhao's T_min)",
        None,
        vec![value(32, Ro, "ident_t_min, clock cycles")],
    ));
    regs.push(reg(
        "IDENT_T_MAX",
        None,
        "Longest line period (Zhao's T_max)",
        None,
        vec![value(32, Ro, "ident_t_max, clock cycles")],
    ));
    regs.push(reg(
        "IDENT_P",
        None,
        "Line numbers of the edges that closed T_min and T_max",
        None,
        vec![
            field("P_MIN", 0, 16, Ro, "ident_p_min, line number"),
            field("P_MAX", 16, 16, Ro, "ident_p_max, line number"),
        ],
    ));
    for (w0, port) in IDENT_SUMS {
        for k in 0..3u32 {
            let name = LAYOUT.iter().find(|e| e.1 == w0 + 4 * k).unwrap().0;
            let (bits, d) = match k {
                0 => ("31:0", "bits 31:0"),
                1 => ("63:32", "bits 63:32"),
                _ => ("71:64", "bits 71:64, sign-extended to 32 bits"),
            };
            regs.push(reg(
                name,
                None,
                &format!("{port} bits {bits} (72-bit two's complement)"),
                None,
                vec![value(32, Ro, &format!("{port} {d}"))],
            ));
        }
    }
    regs
}

/// The C header `encspeed_ecc_regs.h` for `p`: the window's offsets, fields and constants,
/// as [`crate::bus::regmap::RegMap::c_header`] gives the core's (include both).
pub fn c_header(p: &Params) -> String {
    use crate::provenance::{generate_command, preamble, Comment};
    let mut h = preamble(Comment::Block, &generate_command(p));
    h += "/*\n * encspeed_ecc_regs.h: the eccentricity window of encspeed_ecc_wb (offsets from the\n";
    h += " * base of the same register window as encspeed_regs.h, which describes the offsets\n";
    h += &format!(
        " * below ENCSPEED_ECC_BASE). Generated by encspeed-golden {} (golden::bus::ecc_regmap::c_header);\n * do not edit.\n",
        env!("CARGO_PKG_VERSION")
    );
    h += &format!(
        " * speed_bits S = {}, lines = {}.\n",
        p.speed_bits(),
        p.lines()
    );
    h += " * Load the coefficients: write ECC_C and ECC_D, then 1 to ECC_CTRL.LOAD.\n";
    h += " * Identify: write 1 to ECC_CTRL.IDENT_ARM, wait for ECC_STATUS.IDENT_DONE, read the\n";
    h += " * IDENT_* registers (a 72-bit sum is W0 | W1 << 32 | W2 << 64).\n */\n";
    h += "#ifndef ENCSPEED_ECC_REGS_H\n#define ENCSPEED_ECC_REGS_H\n\n";
    let params: [(&str, String, &str); 5] = [
        (
            "ECC_BASE",
            format!("0x{ECC_BASE:02X}u"),
            "first offset of the window",
        ),
        (
            "ECC_ID_MAGIC",
            format!("0x{ECC_ID_MAGIC:08X}u"),
            "ASCII \"ENCE\"",
        ),
        (
            "ECC_MAP_VERSION",
            format!("0x{ECC_MAP_VERSION:08X}u"),
            "major 31:16, minor 15:0",
        ),
        (
            "ECC_COEF_FRAC_BITS",
            "16u".to_string(),
            "ECC_C, ECC_D: value = raw / 2^16 lines",
        ),
        (
            "IDENT_SUM_BITS",
            format!("{IDENT_SUM_BITS}u"),
            "width of the sums",
        ),
    ];
    for (name, value, comment) in params {
        c_define(&mut h, &format!("ENCSPEED_{name}"), &value, Some(comment));
    }
    c_registers(&mut h, &registers(p.speed_bits()));
    h += "\n#endif /* ENCSPEED_ECC_REGS_H */\n";
    h
}

/// The window as Markdown, to follow the core's map in docs/registers.md.
pub fn markdown(p: &Params) -> String {
    let mut m = String::new();
    m += "# encspeed_ecc_wb: the eccentricity window\n\n";
    m += &format!(
        "Generated by `golden::bus::ecc_regmap::markdown` (window map version {}.{}). \
         `encspeed_ecc_wb` serves one {SPAN_BYTES}-byte window ({ADDR_BITS}-bit byte address): \
         offsets below 0x{ECC_BASE:02X} are the core's registers above, unchanged; offsets \
         0x{ECC_BASE:02X} and up are these, with the same bus protocol. C header: \
         `encspeed_ecc_regs.h`. speed_bits S = {}, lines = {}.\n\n",
        ECC_MAP_VERSION >> 16,
        ECC_MAP_VERSION & 0xFFFF,
        p.speed_bits(),
        p.lines()
    );
    m += "ECC_C and ECC_D are staged: write both, then 1 to ECC_CTRL.LOAD, which hands \
          them to the correctors together. An identification: write 1 to \
          ECC_CTRL.IDENT_ARM, wait for ECC_STATUS.IDENT_DONE (or its interrupt), then read \
          the IDENT_* registers, which hold until the next arm; e and theta0 follow from \
          the three sums (docs/eccentricity-hardware.md). Read SPEED_MTC_LO before \
          SPEED_MTC_HI (and N3C likewise): the LO read latches HI. The core's snapshot \
          (sample, CTRL.TRIGGER) stores both corrected speeds with the core's, and with \
          CTRL.SAMPLED = 1 their pairs read it. The window's interrupt is ORed into \
          irq.\n\n";
    markdown_registers(&mut m, &registers(p.speed_bits()));
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::regmap::RegMap;
    use crate::params::Spec;

    #[test]
    fn offsets_are_aligned_distinct_in_the_window_and_clear_of_the_core_map() {
        let p = Params::new(Spec::default()).unwrap();
        let regs = registers(p.speed_bits());
        assert_eq!(regs.len(), LAYOUT.len());
        for (r, (name, off)) in regs.iter().zip(LAYOUT) {
            assert_eq!((r.name, r.offset), (*name, *off));
            assert!(off % 4 == 0 && in_window(*off), "{name}");
        }
        assert!(LAYOUT.windows(2).all(|w| w[0].1 < w[1].1));
        // The core's map ends below the window.
        let core = RegMap::new(&p);
        assert!(core.registers().iter().all(|r| r.offset < ECC_BASE));
        // Hand-checked: 25 registers from 0x90 to 0xF0.
        assert_eq!((LAYOUT.len(), LAYOUT[24].1), (25, 0xF0));
        assert_eq!(ECC_ID_MAGIC, 0x454E_4345);
    }

    #[test]
    fn fields_fit_and_reset_values_fit_their_fields() {
        for r in registers(41) {
            let mut used = 0u32;
            for f in &r.fields {
                assert!(
                    f.width >= 1 && f.lsb + f.width <= 32,
                    "{}.{}",
                    r.name,
                    f.name
                );
                assert_eq!(used & f.mask(), 0, "{}.{} overlaps", r.name, f.name);
                used |= f.mask();
            }
            if let Some(v) = r.reset {
                assert_eq!(v & !used, 0, "{} reset outside its fields", r.name);
            }
        }
    }

    #[test]
    fn sum_words_round_trip_and_sign_extend() {
        // Hand-worked: -1 is all ones in every word; 2^64 + 5 is (5, 0, 1);
        // -2^71 is (0, 0, 0xFFFFFF80).
        assert_eq!([0, 1, 2].map(|k| sum_word(-1, k)), [u32::MAX; 3]);
        assert_eq!([0, 1, 2].map(|k| sum_word((1 << 64) + 5, k)), [5, 0, 1]);
        let min = -(1i128 << 71);
        assert_eq!([0, 1, 2].map(|k| sum_word(min, k)), [0, 0, 0xFFFF_FF80]);
        for v in [
            0,
            1,
            -1,
            123_456_789_012_345_678,
            min,
            (1 << 71) - 1,
            -987_654_321_987,
        ] {
            assert_eq!(sum_of_words([0, 1, 2].map(|k| sum_word(v, k))), v);
        }
    }
}
