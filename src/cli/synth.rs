// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed synth`: the resource and timing report of the shipped tops. For each top of
//! `hdl::Top::ALL` and each device, yosys `synth_ice40` (with `-dsp` where the device has
//! DSPs) or `synth_ecp5` gives the cells, and nextpnr-ice40 or nextpnr-ecp5 places and routes
//! the top inside `tools::fpga`'s boundary wrapper (every port registered, so a top of any
//! width places on any package) once per seed, with the clock constrained to the generation
//! clock. The ECP5 devices are in `all` when nextpnr-ecp5 is installed. The
//! report is a Markdown table (`--out`, default `target/synth/report.md`), also printed; an
//! `--out` file that holds the [`BEGIN`]/[`END`] markers (docs/resources.md) keeps its text
//! around them.
//!
//! A seed whose router does not finish (nextpnr aborts on an internal assertion, or runs
//! past `tools::fpga::ROUTE_TIMEOUT`: nextpnr's routers can loop for ever on some
//! placements) is reported as "not routed" and the next seed is tried. `--require-timing`
//! makes a routed Fmax below the clock, a seed not routed, or a top that does not fit, an
//! error (exit 1): the static timing check CI runs.

use clap::Args;
use golden::params::Params;
use hdl::emit::tops::Top;
use std::fmt::Write;
use std::path::PathBuf;
use tools::fpga::{self, Cells, Family, Routed};

use super::spec::SpecArgs;
use super::Outcome;

/// A device the report covers: its family, nextpnr's device option and package, and
/// whether yosys may map multipliers to its DSPs (`synth_ice40 -dsp`; `synth_ecp5` always
/// does).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Device {
    name: &'static str,
    family: Family,
    /// nextpnr's `--<device>` option.
    nextpnr: &'static str,
    package: &'static str,
    dsp: bool,
}

/// iCE40HX8K-CT256 (7 680 logic cells, 32 block RAMs, no DSP), iCE40UP5K-SG48 (5 280 logic
/// cells, 30 block RAMs, 8 SB_MAC16), and the ECP5 LFE5U-25F-6BG256 (24 288 LUT4, 56
/// DP16KD, 28 MULT18X18D) and LFE5U-85F-6BG381 (83 640 LUT4, 208 DP16KD, 156 MULT18X18D;
/// the ULX3S board's), both at nextpnr-ecp5's default speed grade 6, the slowest.
const DEVICES: [Device; 4] = [
    Device {
        name: "hx8k",
        family: Family::Ice40,
        nextpnr: "hx8k",
        package: "ct256",
        dsp: false,
    },
    Device {
        name: "up5k",
        family: Family::Ice40,
        nextpnr: "up5k",
        package: "sg48",
        dsp: true,
    },
    Device {
        name: "ecp5-25f",
        family: Family::Ecp5,
        nextpnr: "25k",
        package: "CABGA256",
        dsp: true,
    },
    Device {
        name: "ecp5-85f",
        family: Family::Ecp5,
        nextpnr: "85k",
        package: "CABGA381",
        dsp: true,
    },
];

/// Options of `encspeed synth`.
#[derive(Args)]
pub struct SynthArgs {
    #[command(flatten)]
    spec: SpecArgs,
    /// The tops to report: `all`, or a comma-separated list of module names with or without
    /// the `encspeed_` prefix (core, wb, ecc, ecc_wb).
    #[arg(long, default_value = "all")]
    top: String,
    /// The devices: `all` (the iCE40s, and the ECP5s when nextpnr-ecp5 is installed), or a
    /// comma-separated list of hx8k (CT256), up5k (SG48), ecp5-25f (CABGA256) and ecp5-85f
    /// (CABGA381).
    #[arg(long, default_value = "all")]
    device: String,
    /// nextpnr placement seeds, comma-separated; one place and route per seed.
    #[arg(long, default_value = "1,2,3", value_delimiter = ',')]
    seeds: Vec<u32>,
    /// Where to write the Markdown report (default target/synth/report.md).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Exit 1 when a top does not fit or misses the clock on any seed.
    #[arg(long)]
    require_timing: bool,
}

/// The tops named by `--top`.
fn tops(list: &str) -> Result<Vec<Top>, String> {
    if list == "all" {
        return Ok(Top::ALL.to_vec());
    }
    list.split(',')
        .map(|name| {
            let name = name.trim();
            Top::ALL
                .into_iter()
                .find(|t| t.module() == name || t.module().strip_prefix("encspeed_") == Some(name))
                .ok_or_else(|| {
                    let known: Vec<&str> = Top::ALL.iter().map(|t| t.module()).collect();
                    format!("unknown top `{name}` (the tops: {})", known.join(", "))
                })
        })
        .collect()
}

/// The devices named by `--device`; `all` leaves out a family whose nextpnr is not
/// installed (`installed`), a device named explicitly never is.
fn devices(list: &str, installed: impl Fn(Family) -> bool) -> Result<Vec<Device>, String> {
    if list == "all" {
        // Asked once per family (a WebAssembly nextpnr takes a second to answer), not once
        // per device.
        let have = [Family::Ice40, Family::Ecp5].map(|f| (f, installed(f)));
        return Ok(DEVICES
            .into_iter()
            .filter(|d| have.contains(&(d.family, true)))
            .collect());
    }
    list.split(',')
        .map(|name| {
            DEVICES
                .into_iter()
                .find(|d| d.name == name.trim())
                .ok_or_else(|| {
                    let known: Vec<&str> = DEVICES.iter().map(|d| d.name).collect();
                    format!(
                        "unknown device `{name}` (the devices: {})",
                        known.join(", ")
                    )
                })
        })
        .collect()
}

/// One row of the report: a top on a device.
struct Row {
    top: Top,
    device: Device,
    cells: Cells,
    /// One per seed.
    routed: Vec<(u32, Routed)>,
}

/// `encspeed synth`.
pub fn run(args: &SynthArgs) -> Outcome {
    let tops = tops(&args.top).map_err(|e| (2, e))?;
    let devices = devices(&args.device, Family::installed).map_err(|e| (2, e))?;
    if args.seeds.is_empty() {
        return Err((2, "--seeds: give at least one seed".into()));
    }
    args.spec.run(|p| {
        let mut rows = Vec::new();
        for &top in &tops {
            if let Err(e) = top.check(p) {
                println!("{}: not generated for these parameters: {e}", top.module());
                continue;
            }
            for &device in &devices {
                let row = place_and_route(p, top, device, &args.seeds).map_err(|e| (1, e))?;
                print_row(&row, p);
                rows.push(row);
            }
        }
        let report = markdown(p, &rows);
        let out = match &args.out {
            Some(f) => f.clone(),
            None => tools::work_dir("synth", "")
                .map_err(|e| (1, e))?
                .join("report.md"),
        };
        let text = match std::fs::read_to_string(&out) {
            Ok(old) => into_markers(&old, &report).unwrap_or(report),
            Err(_) => report,
        };
        std::fs::write(&out, text).map_err(|e| (1, format!("{}: {e}", out.display())))?;
        println!("report: {}", out.display());
        let mhz = p.clock_hz() / 1e6;
        let failed: Vec<String> = rows
            .iter()
            .filter(|r| !meets(r, mhz))
            .map(|r| format!("{} on {}", r.top.module(), r.device.name))
            .collect();
        if args.require_timing && !failed.is_empty() {
            return Err((
                1,
                format!("timing not met at {mhz} MHz: {}", failed.join(", ")),
            ));
        }
        Ok(())
    })
}

/// The lines that enclose the report in a document that has more around it
/// (docs/resources.md): `--out` into such a file replaces only what lies between them.
const BEGIN: &str = "<!-- begin encspeed synth -->";
const END: &str = "<!-- end encspeed synth -->";

/// `doc` with the text between [`BEGIN`] and [`END`] replaced by `report`; None when `doc`
/// lacks the markers.
fn into_markers(doc: &str, report: &str) -> Option<String> {
    let b = doc.find(BEGIN)? + BEGIN.len();
    let e = doc[b..].find(END)? + b;
    Some(format!("{}\n{report}{}", &doc[..b], &doc[e..]))
}

/// Synthesis once, then place and route per seed, in `target/synth/<top>-<device>/`.
fn place_and_route(p: &Params, top: Top, device: Device, seeds: &[u32]) -> Result<Row, String> {
    let dir = tools::work_dir("synth", &format!("{}-{}", top.module(), device.name))?;
    let verilog = top.verilog(p)?;
    let ports = fpga::module_ports(&verilog, top.module())?;
    let wrapper = fpga::boundary_wrapper(top.module(), &ports)?;
    let file = top.verilog_file();
    tools::stage(&dir, &[(&file, &verilog), ("boundary.v", &wrapper)])?;
    let boundary = format!("{}_boundary", top.module());
    // The cells of the top alone (what a user's design pays), then the wrapped design
    // that is placed.
    let (family, dsp) = (device.family, device.dsp);
    let cells = fpga::synth_json(&dir, &[&file], top.module(), family, dsp, "top.json")?;
    fpga::synth_json(
        &dir,
        &[&file, "boundary.v"],
        &boundary,
        family,
        dsp,
        "wrapped.json",
    )?;
    let mut routed = Vec::new();
    for &seed in seeds {
        let r = fpga::nextpnr(
            &dir,
            "wrapped.json",
            family,
            device.nextpnr,
            device.package,
            p.clock_hz() / 1e6,
            seed,
        )?;
        // A seed whose router does not finish is reported and the next seed tried.
        let fits = !matches!(r, Routed::DoesNotFit(_));
        routed.push((seed, r));
        if !fits {
            break; // another seed places the same cells
        }
    }
    Ok(Row {
        top,
        device,
        cells,
        routed,
    })
}

/// True when every seed placed and routed at or above `mhz`.
fn meets(r: &Row, mhz: f64) -> bool {
    r.routed
        .iter()
        .all(|(_, x)| matches!(x, Routed::Done { fmax_mhz, .. } if *fmax_mhz >= mhz))
}

fn fmax_list(r: &Row) -> String {
    r.routed
        .iter()
        .map(|(seed, x)| match x {
            Routed::Done { fmax_mhz, .. } => format!("{fmax_mhz:.1} (seed {seed})"),
            Routed::DoesNotFit(_) => "does not fit".into(),
            Routed::NotRouted(_) => format!("not routed (seed {seed})"),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn print_row(r: &Row, p: &Params) {
    let c = &r.cells;
    println!(
        "{} on {}-{}: {} LUT4, {} FF, {} carry, {} BRAM, {} DSP; Fmax MHz at {} MHz: {}",
        r.top.module(),
        r.device.name,
        r.device.package,
        c.lut4,
        c.ff,
        c.carry,
        c.bram,
        c.dsp,
        p.clock_hz() / 1e6,
        fmax_list(r)
    );
    for (_, x) in &r.routed {
        match x {
            Routed::DoesNotFit(why) | Routed::NotRouted(why) => println!("  {why}"),
            Routed::Done { .. } => {}
        }
    }
}

/// The report: parameters, tool versions, one table row per top and device, and the
/// critical path of the slowest seed.
fn markdown(p: &Params, rows: &[Row]) -> String {
    let version = |cmd: &str, arg: &str| {
        std::process::Command::new(cmd)
            .arg(arg)
            .output()
            .map(|o| {
                let text = String::from_utf8_lossy(&o.stdout).into_owned()
                    + &String::from_utf8_lossy(&o.stderr);
                text.lines().next().unwrap_or("").trim().to_string()
            })
            .unwrap_or_default()
    };
    let mhz = p.clock_hz() / 1e6;
    let mut tools = vec![version("yosys", "-V")];
    for family in [Family::Ice40, Family::Ecp5] {
        if rows.iter().any(|r| r.device.family == family) {
            tools.push(version(family.nextpnr(), "--version"));
        }
    }
    let mut m = String::new();
    let _ = writeln!(
        m,
        "Written by `encspeed synth` for {} lines, {}-bit counters, dt {} cycles, clock {mhz} MHz, \
         estimators {}.\n\
         Tools: {}.\n\n\
         Cells: yosys `synth_ice40` (`-dsp` on the UP5K) or `synth_ecp5` of the top alone. Logic\n\
         cells and Fmax: nextpnr of the top inside the boundary wrapper (every port registered),\n\
         clock constrained to {mhz} MHz, one run per placement seed. Cells are the family's own:\n\
         LUT4 is SB_LUT4 or LUT4 (the ECP5's PFUMX and L6MUX21 not counted), carry SB_CARRY\n\
         (1 bit) or CCU2C (2 bits), BRAM SB_RAM40_4K (4 kbit) or DP16KD (18 kbit), DSP SB_MAC16\n\
         or MULT18X18D, logic cells ICESTORM_LC or TRELLIS_COMB.\n",
        p.lines(),
        p.counter_bits(),
        p.dt_cycles(),
        p.estimator_list(),
        tools.join("; "),
    );
    m += "| top | device | LUT4 | flip-flops | carry | BRAM | DSP | logic cells | Fmax, MHz | meets clock | critical path (slowest seed) |\n";
    m += "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for r in rows {
        let c = &r.cells;
        let lc = r
            .routed
            .iter()
            .filter_map(|(_, x)| match x {
                Routed::Done { lc, lc_total, .. } => Some(format!("{lc} / {lc_total}")),
                Routed::DoesNotFit(over) => Some(format!("does not fit: {over}")),
                Routed::NotRouted(_) => None,
            })
            .next()
            .unwrap_or_default();
        let slowest = r
            .routed
            .iter()
            .filter_map(|(_, x)| match x {
                Routed::Done {
                    fmax_mhz, from, to, ..
                } => Some((*fmax_mhz, from, to)),
                Routed::DoesNotFit(_) | Routed::NotRouted(_) => None,
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, from, to)| format!("`{from}` → `{to}`"))
            .unwrap_or_default();
        let _ = writeln!(
            m,
            "| `{}` | {}-{} | {} | {} | {} | {} | {} | {lc} | {} | {} | {slowest} |",
            r.top.module(),
            r.device.name,
            r.device.package,
            c.lut4,
            c.ff,
            c.carry,
            c.bram,
            c.dsp,
            fmax_list(r),
            if meets(r, mhz) { "yes" } else { "**no**" },
        );
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_report_replaces_only_the_text_between_the_markers() {
        let doc = format!("# Resources\nintro\n{BEGIN}\nold table\n{END}\nafter\n");
        assert_eq!(
            into_markers(&doc, "| new |\n").unwrap(),
            format!("# Resources\nintro\n{BEGIN}\n| new |\n{END}\nafter\n")
        );
        assert_eq!(into_markers("no markers", "x"), None);
    }

    #[test]
    fn tops_and_devices_are_named_as_in_the_help() {
        assert_eq!(tops("all").unwrap(), Top::ALL.to_vec());
        assert_eq!(
            tops("wb,encspeed_ecc_wb").unwrap(),
            vec![Top::Wb, Top::EccWb]
        );
        assert!(tops("fast").unwrap_err().contains("encspeed_core"));
        assert_eq!(devices("up5k", |_| true).unwrap(), vec![DEVICES[1]]);
        assert_eq!(devices("ecp5-85f", |_| false).unwrap(), vec![DEVICES[3]]);
        assert_eq!(devices("all", |_| true).unwrap(), DEVICES.to_vec());
        assert_eq!(
            devices("all", |f| f == Family::Ice40).unwrap(),
            DEVICES[..2].to_vec()
        );
        assert!(devices("ecp5", |_| true).unwrap_err().contains("ecp5-25f"));
    }
}
