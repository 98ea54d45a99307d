// SPDX-License-Identifier: MIT OR Apache-2.0
//! The manifest of a shipped top (`generated/<top>.toml`): what a build system, a bench or
//! a driver reads instead of parsing Verilog. The generator and the command that
//! regenerates the files, the parameters and what they imply, the ports, the latencies,
//! the register map where the top has a bus, and the error budget of every speed output
//! at the configured clock, lines and dt ([`golden::top::error_budget::budget`]).

use super::tops::Top;
use super::RUST_HDL_VERSION;
use golden::bus::regmap::{self, Register};
use golden::params::{Params, Spec};
use golden::provenance::{generate_command, preamble, Comment};
use golden::top::error_budget::{budget, BudgetRow};
use golden::top::ports::{Latency, Port};
use serde::Serialize;

#[derive(Serialize)]
struct Manifest<'a> {
    /// Fractional bits of every speed output: value = raw · 2^−speed_frac_bits ω_lim.
    speed_frac_bits: u32,
    /// Width of every speed output (two's complement).
    speed_bits: u32,
    generator: Generator,
    spec: &'a Spec,
    derived: Derived,
    #[serde(skip_serializing_if = "Option::is_none")]
    eccentricity: Option<Eccentricity>,
    #[serde(skip_serializing_if = "Option::is_none")]
    bus: Option<Bus>,
    ports: Vec<Port>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    registers: Vec<RegisterEntry>,
    error_budget: Vec<BudgetRow>,
}

#[derive(Serialize)]
struct Generator {
    tool: String,
    rust_hdl: &'static str,
    command: String,
    top_module: &'static str,
}

#[derive(Serialize)]
struct Derived {
    /// ts, s.
    ts_s: f64,
    /// Nominal dt, s.
    dt_s: f64,
    /// ω_lim at the nominal dt, rev/s.
    omega_lim_rps: f64,
    /// Saturation value of every counter.
    counter_max: u64,
    /// `stalled` threshold, dt intervals.
    timeout_dt: u64,
    /// ω_lim at the nominal dt, rad/s.
    omega_lim_rad_s: f64,
    /// Latencies with the filter off (cfg_filter = 0), clock cycles.
    latency: Latency,
}

/// The eccentricity tops' own figures.
#[derive(Serialize)]
struct Eccentricity {
    /// Entries of the sine table (one per line).
    table_entries: u32,
    /// Bits of each table entry.
    table_data_bits: u32,
    /// `mtc_strobe` rises this many edges after the edge that raised `mt_strobe`.
    mtc_after_mt_strobe: u64,
    /// `n3c_strobe` rises this many edges after the edge that raised `speed_strobe`.
    n3c_after_speed_strobe: u64,
    /// `ident_done` rises this many edges after the edge that raised the closing `index`.
    ident_done_after_index: u64,
    /// Width of the identification sums.
    ident_sum_bits: u32,
    /// The error budget's n3 and M/T rows bound `speed_n3c` and `speed_mtc` on a disc
    /// without eccentricity (the correction is then 0); on an eccentric disc see
    /// docs/eccentricity-hardware.md.
    corrected_speeds: &'static str,
}

/// The bus of the Wishbone tops.
#[derive(Serialize)]
struct Bus {
    standard: &'static str,
    data_bits: usize,
    /// Width of `wb_adr_i`, a byte address.
    addr_bits: usize,
    /// Clock cycles of every access (the request cycle, the read stage's cycle, then the
    /// `wb_ack_o` cycle).
    access_cycles: u32,
    /// Encoder channels behind the slave (`--channels`, more than one), channel c's
    /// register window at byte address c · `channel_stride`.
    #[serde(skip_serializing_if = "Option::is_none")]
    channels: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    channel_stride: Option<u32>,
    /// Register map version, major in bits 31:16.
    map_version: u32,
    /// The C header of the map.
    c_header: &'static str,
    /// Offset of the eccentricity window, for `encspeed_ecc_wb`.
    #[serde(skip_serializing_if = "Option::is_none")]
    ecc_window_base: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ecc_map_version: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ecc_c_header: Option<&'static str>,
}

#[derive(Serialize)]
struct RegisterEntry {
    name: &'static str,
    offset: u32,
    /// "RO", "RW", "W1C", "W1P" or a combination, by field.
    access: String,
    /// Value after reset; absent for a live view of the core's outputs.
    #[serde(skip_serializing_if = "Option::is_none")]
    reset: Option<u32>,
    fields: Vec<FieldEntry>,
}

#[derive(Serialize)]
struct FieldEntry {
    name: &'static str,
    lsb: u32,
    width: u32,
    access: &'static str,
}

fn entries(registers: Vec<Register>) -> Vec<RegisterEntry> {
    registers
        .into_iter()
        .map(|r| RegisterEntry {
            name: r.name,
            offset: r.offset,
            access: r.access(),
            reset: r.reset,
            fields: r
                .fields
                .iter()
                .map(|f| FieldEntry {
                    name: f.name,
                    lsb: f.lsb,
                    width: f.width,
                    access: f.access.as_str(),
                })
                .collect(),
        })
        .collect()
}

/// The manifest of `top` for `p` (unprefixed; [`super::prefix::Prefix::apply`] renames).
pub fn manifest(top: Top, p: &Params) -> String {
    use golden::bus::ecc_regmap;
    use golden::top::ecc_top;
    let eccentricity = top.has_ecc().then(|| Eccentricity {
        table_entries: p.lines(),
        table_data_bits: ecc_top::TABLE_DATA_BITS,
        mtc_after_mt_strobe: ecc_top::mtc_after_mt_strobe(p),
        n3c_after_speed_strobe: ecc_top::n3c_after_speed_strobe(p),
        ident_done_after_index: ecc_top::IDENT_DONE_AFTER_INDEX,
        ident_sum_bits: ecc_top::IDENT_SUM_BITS,
        corrected_speeds: "the n3 and mt rows of error_budget bound speed_n3c and speed_mtc on a disc without eccentricity; on an eccentric disc see docs/eccentricity-hardware.md",
    });
    let (bus, registers) = match top {
        Top::Core | Top::Ecc => (None, Vec::new()),
        Top::Wb | Top::EccWb => {
            let ecc = top == Top::EccWb;
            let several = (top == Top::Wb && p.channels() > 1).then_some(p.channels());
            let mut registers = entries(regmap::registers(p));
            if ecc {
                registers.extend(entries(ecc_regmap::registers(p.speed_bits())));
            }
            let bus = Bus {
                standard: "Wishbone B4 classic slave",
                data_bits: regmap::DATA_BITS,
                addr_bits: golden::top::wb_channels::address_bits(several.unwrap_or(1)) as usize,
                access_cycles: 3,
                channels: several,
                channel_stride: several.map(|_| regmap::SPAN_BYTES),
                map_version: regmap::MAP_VERSION,
                c_header: super::wb::HEADER_FILE,
                ecc_window_base: ecc.then_some(ecc_regmap::ECC_BASE),
                ecc_map_version: ecc.then_some(ecc_regmap::ECC_MAP_VERSION),
                ecc_c_header: ecc.then_some(super::wb::ECC_HEADER_FILE),
            };
            (Some(bus), registers)
        }
    };
    let manifest = Manifest {
        speed_frac_bits: p.speed_frac_bits(),
        speed_bits: p.speed_bits(),
        generator: Generator {
            tool: format!("encspeed {}", env!("CARGO_PKG_VERSION")),
            rust_hdl: RUST_HDL_VERSION,
            command: generate_command(p),
            top_module: top.module(),
        },
        spec: p.spec(),
        derived: Derived {
            ts_s: p.ts_s(),
            dt_s: p.dt_s(),
            omega_lim_rps: p.omega_lim_rps(),
            counter_max: p.counter_max(),
            timeout_dt: p.timeout_dt(),
            omega_lim_rad_s: p.omega_lim_rps() * std::f64::consts::TAU,
            latency: Latency::new(p, 0),
        },
        eccentricity,
        bus,
        ports: top.ports(p),
        registers,
        error_budget: budget(p),
    };
    preamble(Comment::Hash, &generate_command(p))
        + &toml::to_string(&manifest).expect("manifest serialises")
}
