// SPDX-License-Identifier: MIT OR Apache-2.0
//! Emission of `encspeed_wb.v` (the core behind its Wishbone register file,
//! [`crate::EncspeedWb`]), its C header `encspeed_regs.h`, and the register
//! documentation `docs/registers.md`.
//!
//! Every output is a pure function of the validated parameters (no dates, no paths of
//! this machine), so the shipped copies can be checked for staleness byte for byte.

use crate::emit::regenerate_command;
use crate::sim::wb_channels_sim::build_wb_channels;
use crate::sim::wb_sim::build_wb;
use golden::bus::ecc_regmap::{ECC_BASE, ECC_MAP_VERSION};
use golden::bus::regmap::{self, ADDR_BITS, MAP_VERSION, SPAN_BYTES};
use golden::params::{Params, Spec};
use golden::top::ports::Port;
use golden::top::wb_channels::address_bits;
use golden::top::wb_top::TOP_MODULE;
use std::path::{Path, PathBuf};

/// File name of the emitted Verilog.
pub const VERILOG_FILE: &str = "encspeed_wb.v";
/// File name of the C header.
pub const HEADER_FILE: &str = "encspeed_regs.h";
/// File name of the emitted `encspeed_ecc_wb` Verilog.
pub const ECC_WB_VERILOG_FILE: &str = "encspeed_ecc_wb.v";
/// File name of the eccentricity window's C header.
pub const ECC_HEADER_FILE: &str = "encspeed_ecc_regs.h";
/// Path of the register documentation, relative to the workspace root.
pub const REGISTERS_DOC: &str = "docs/registers.md";

/// The comment header of `encspeed_wb.v`.
fn verilog_header(p: &Params) -> String {
    let function = if p.channels() > 1 {
        format!(
            "Function: {} channels of encspeed_core (its logic is included in this file), each \
             behind its own register window, on one Wishbone B4 classic slave, 32-bit data, \
             {}-bit byte address: channel c's registers at c * 0x{SPAN_BYTES:X} + offset \
             (windows above the last channel read 0), register map version {}.{}: \
             {HEADER_FILE}, {REGISTERS_DOC}.",
            p.channels(),
            address_bits(p.channels()),
            MAP_VERSION >> 16,
            MAP_VERSION & 0xFFFF
        )
    } else {
        format!(
            "Function: encspeed_core (its logic is included in this file) behind a Wishbone B4 \
             classic slave, 32-bit data, {ADDR_BITS}-bit byte address ({SPAN_BYTES}-byte window), register map \
             version {}.{}: {HEADER_FILE}, {REGISTERS_DOC}.",
            MAP_VERSION >> 16,
            MAP_VERSION & 0xFFFF
        )
    };
    header_of(p, VERILOG_FILE, function, &crate::Top::Wb.ports(p))
}

/// The comment header of `encspeed_ecc_wb.v`.
fn ecc_wb_verilog_header(p: &Params) -> String {
    let function = format!(
        "Function: encspeed_ecc (the core with its eccentricity correctors and identification; \
         its logic is included in this file) behind one Wishbone B4 classic window, 32-bit data, \
         {ADDR_BITS}-bit byte address: offsets below 0x{ECC_BASE:02X} are encspeed_wb's registers \
         ({HEADER_FILE}, map {}.{}), offsets from 0x{ECC_BASE:02X} the eccentricity window \
         ({ECC_HEADER_FILE}, map {}.{}); {REGISTERS_DOC}.",
        MAP_VERSION >> 16,
        MAP_VERSION & 0xFFFF,
        ECC_MAP_VERSION >> 16,
        ECC_MAP_VERSION & 0xFFFF
    );
    header_of(
        p,
        ECC_WB_VERILOG_FILE,
        function,
        &crate::Top::EccWb.ports(p),
    )
}

/// A Wishbone top's comment header: file, command, parameters, `function`, bus and speed
/// rules, `ports`.
fn header_of(p: &Params, file: &str, function: String, ports: &[Port]) -> String {
    let mut lines = vec![
        format!("Parameters: {}", p.summary()),
        format!(
            "Derived: omega_lim = {} rev/s at dt_cycles, timeout_dt = {} dt intervals, counters saturate at {}",
            p.omega_lim_rps(),
            p.timeout_dt(),
            p.counter_max()
        ),
        function,
        "Bus: a request (wb_cyc_i & wb_stb_i while the slave is idle) is executed at the edge that samples it and acknowledged in the cycle after the next edge; three cycles per access; no wb_err_o.".into(),
        format!(
            "Speeds: {} bits, speed_frac_bits = {}: read SPEED_*_LO (latches HI) then SPEED_*_HI, \
             a 64-bit sign extension; value = raw * 2^-{} omega_lim.",
            p.speed_bits(),
            p.speed_frac_bits(),
            p.speed_frac_bits()
        ),
        "Snapshot: sample high (or a write of 1 to CTRL.TRIGGER) stores position, nep, ndt, the speeds and valid/stalled/direction of one cycle; CTRL.SAMPLED = 1 reads them in place of the live values; CTRL.HOLD = 1 ignores sample; SNAP_COUNT counts snapshots.".into(),
        "A write that changes CTRL.MODE resets the core (not the registers) at the next edge.".into(),
        "Ports:".into(),
    ];
    lines.extend(ports.iter().map(super::port_line));
    let body: String = lines.iter().map(|l| format!("// {l}\n")).collect();
    let module = file.trim_end_matches(".v");
    super::file_header(&regenerate_command(p), module, &body)
}

/// The files for `p`, as (file name, contents): `encspeed_wb.v` (top module
/// `encspeed_wb`) and `encspeed_regs.h`. Deterministic.
pub fn emit_wb(p: &Params) -> Vec<(&'static str, String)> {
    let body = if p.channels() > 1 {
        build_wb_channels(p).verilog(TOP_MODULE)
    } else {
        build_wb(p).verilog(TOP_MODULE)
    };
    vec![
        (VERILOG_FILE, format!("{}\n{body}", verilog_header(p))),
        (HEADER_FILE, regmap::c_header(p)),
    ]
}

/// The files of `encspeed_ecc_wb` for `p`, as (file name, contents): `encspeed_ecc_wb.v`
/// (top module `encspeed_ecc_wb`) and `encspeed_ecc_regs.h`; an error where
/// [`golden::top::ecc_top::check`] refuses `p`. Deterministic.
pub fn emit_ecc_wb(p: &Params) -> Result<Vec<(&'static str, String)>, String> {
    let body = crate::sim::ecc_wb_sim::build_ecc_wb(p)?.verilog();
    Ok(vec![
        (
            ECC_WB_VERILOG_FILE,
            format!("{}\n{body}", ecc_wb_verilog_header(p)),
        ),
        (ECC_HEADER_FILE, golden::bus::ecc_regmap::c_header(p)),
    ])
}

/// Write the files of [`emit_wb`] into `dir` (created if needed); their paths.
pub fn write_all(p: &Params, dir: &Path) -> std::io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)?;
    emit_wb(p)
        .into_iter()
        .map(|(name, text)| {
            let path = dir.join(name);
            std::fs::write(&path, text)?;
            Ok(path)
        })
        .collect()
}

/// `docs/registers.md` for `p`: an introduction (bus timing, coherence, faults,
/// interrupts, the mode-change rule) followed by [`regmap::markdown`] and
/// [`golden::bus::ecc_regmap::markdown`] (the window `encspeed_ecc_wb` adds) with their headings
/// one level down. The shipped file is this for the default parameters
/// ([`default_registers_markdown`]).
pub fn registers_markdown(p: &Params) -> String {
    let map = regmap::markdown(p);
    // The map's "# title" becomes a section, its "## REG" sections subsections.
    let map = map.replacen("# ", "## ", 1).replace("\n## ", "\n### ");
    let intro = format!(
        r#"{}
# Registers of encspeed_wb

<!-- Generated by hdl::emit::wb::registers_markdown for the default parameters; do not
edit. The tb test `registers_doc_is_up_to_date` checks it and says how to regenerate it. -->

`encspeed_wb` is `encspeed_core` behind a Wishbone B4 classic slave (`hdl::EncspeedWb`,
emitted as `{VERILOG_FILE}` with the C header `{HEADER_FILE}`). Its ports are `clock`,
`reset`, `enc_a`, `enc_b`, `enc_z`, the Wishbone signals `wb_cyc_i`, `wb_stb_i`, `wb_we_i`,
`wb_adr_i[{a}:0]`, `wb_dat_i[31:0]`, `wb_sel_i[3:0]`, `wb_dat_o[31:0]`, `wb_ack_o`, and
`irq`. The register map is the one description in `golden::bus::regmap`; the tables below are
for the default parameters (the `PARAM*`, `LINES`, `*_DEFAULT` and `CLOCK_HZ` values and
the field widths follow the generation parameters: read `PARAM0`/`PARAM1` at run time).

## Bus timing

- A request is `wb_cyc_i & wb_stb_i` while the slave is idle (`wb_ack_o` low and no
  request taken at the edge before). One sampled at clock edge k is executed at edge k;
  `wb_ack_o` is high for the one cycle after edge k + 1, with the read data (the register
  as it stood before edge k) on `wb_dat_o` (0 in every other cycle). Every access takes
  three cycles; a master that keeps `wb_stb_i` high gets an access every third cycle. A
  master must wait for `wb_ack_o`, as every classic master does; the address, data, byte
  lanes and `wb_we_i` are sampled at edge k only. There is no `wb_err_o`.
- Why the extra cycle: the read multiplexer of some 30 words behind the address decode
  does not fit one 10 ns cycle on an iCE40; the words are ORed in eight groups into
  registers at edge k and the groups into `wb_dat_o` at edge k + 1.
- Registers are 32-bit words at word-aligned byte offsets; `wb_adr_i[1:0]` are ignored.
  Reads of unmapped offsets return 0; writes to them, to read-only registers and to
  reserved bits are acknowledged and ignored. Writes honour `wb_sel_i` byte lanes.
- A read returns the core's outputs as they stood in the request cycle. A configuration
  write (`CTRL`, `CFG_*`) drives the core from the cycle after the write edge; the core
  registers `cfg_dt` and `cfg_timeout` once more, so a new dt or timeout is in use from
  the second edge after the write edge.
- `reset` is synchronous and resets the core and every register of the file together; a
  request in a reset cycle is dropped (never acknowledged).

## Several encoder channels: `--channels N`

`encspeed generate --channels N` (N = 2..=8) makes `{VERILOG_FILE}` N channels (each a core
and its register file, `hdl::EncspeedWbChannels`) behind one slave: `enc_a`, `enc_b`,
`enc_z` and `irq` become N bits wide (bit c for channel c), `wb_adr_i` gains the bits that
number the channels, and channel c's registers are at byte address c · 0x100 + the offsets
below (`ENCSPEED_CHANNEL_BASE(c)` in `{HEADER_FILE}`). Only the addressed channel sees
`wb_stb_i`; `wb_dat_o` and `wb_ack_o` are the OR of the channels' registers, so the bus
timing above is unchanged. The windows above the last channel (N not a power of two) are
acknowledged like an unmapped offset: they read 0 and ignore writes. `sample` and `reset`
are shared, so one strobe snapshots every axis at the same edge. The board tops and
`encspeed_ecc_wb` have one channel.

## Speeds: LO/HI coherence

Each speed is S = N + 17 bits of two's complement (Q(N).16 in units of ω_lim, one line
per dt), read as the 64-bit sign extension in two words. Reading `SPEED_*_LO` returns
bits 31:0 and latches bits 63:32 of the same sample into that speed's own shadow, which
`SPEED_*_HI` returns: **read LO, then HI**. Each speed has its own shadow, so pairs of
different speeds may be interleaved; a HI read before any LO read returns 0. Speed in
lines per dt = (HI:LO as a signed 64-bit integer) / 2^16.

## Configuration and the mode rule

`CTRL.MODE` selects x1, x2 or x4 decoding, `CTRL.Z_MODE` what the index does, `CFG_DT`
the dt of Rairán's time base (0 = `DT_DEFAULT`), `CFG_TIMEOUT` the zero-speed timeout
(0 = `TIMEOUT_DEFAULT`), `CFG_FILTER` the glitch filter (0 = off). **Any change of
`CTRL.MODE` resets the whole core** (position, estimators, baselines, fault flags and
counters; the start-up hold runs again) at the edge after the one that sees the new
mode, because a count in one mode means nothing in another. The register file keeps its
values. So firmware writes `CTRL` first and then waits for `STATUS.VALID` before
reading a speed; writing `CTRL` with an unchanged `MODE` (e.g. to change `Z_MODE`)
resets nothing.
`MODE` = 3 and `CFG_DT` = 1 are illegal: they set `STATUS.CFG_ERROR` and `VALID` stays low.

## Faults: clear_faults

`STATUS` shows the core's levels live. Its three sticky fault bits are write-1-to-clear
through the core's single `clear_faults` input: a write to `STATUS` with byte lane 0
selected and a 1 in any `FAULT_*` bit pulses `clear_faults` in the ack cycle, and the core
clears **all three** fault flags at the next edge (a fault event at that edge wins). The
next access therefore already reads them cleared. The fault counters (`GLITCH_COUNT`,
`ILLEGAL_COUNT`, `REV_ERROR_COUNT`) are cleared only by reset or a mode change.

## Interrupts: irq

`IRQ_STATUS` latches events at every edge, enabled or not: `SPEED` (new n1..n3),
`BASELINE` (new PC/ET/M/T speeds), `INDEX` (a Z edge), `FAULT` (a rising edge of any fault
flag), `UPDATE` (Nep1/Ndt1 written), `STALL` (a rising edge of `stalled`). A written 1
clears a bit, except that an event at the same edge wins. `irq` = (`IRQ_STATUS` &
`IRQ_ENABLE`) ≠ 0 is a level driven from registers only; an interrupt handler reads
`IRQ_STATUS`, writes the bits it handled back to clear them, and returns.

"#,
        golden::provenance::preamble(
            golden::provenance::Comment::Html,
            golden::provenance::DOCS_COMMAND
        ),
        a = ADDR_BITS - 1
    );
    // The eccentricity window of encspeed_ecc_wb, likewise one level down.
    let ecc = golden::bus::ecc_regmap::markdown(p)
        .replacen("# ", "## ", 1)
        .replace("\n## ", "\n### ");
    format!("{intro}{map}\n{ecc}")
}

/// [`registers_markdown`] for the default parameters: the contents of `docs/registers.md`.
pub fn default_registers_markdown() -> String {
    registers_markdown(&Params::new(Spec::default()).expect("default parameters are valid"))
}
