//! `encspeed synth`: yosys `synth_ice40` and nextpnr-ice40 place and route of the Wishbone
//! top encspeed_wb (logic cells, I/O, maximum clock frequency), or yosys alone on
//! encspeed_ecc (cells by type).

use clap::Args;
use golden::params::Params;

use super::spec::SpecArgs;
use super::Outcome;

/// Options of `encspeed synth`.
#[derive(Args)]
pub struct SynthArgs {
    #[command(flatten)]
    spec: SpecArgs,
    /// nextpnr-ice40 device option, e.g. hx8k, up5k, lp8k.
    #[arg(long, default_value = "hx8k")]
    device: String,
    /// Package, e.g. ct256 (hx8k), sg48 (up5k).
    #[arg(long, default_value = "ct256")]
    package: String,
    /// wb: encspeed_wb, synthesised, placed and routed; ecc: encspeed_ecc, synthesised
    /// only (cells by type: its ports outnumber any iCE40's pins).
    #[arg(long, default_value = "wb", value_parser = ["wb", "ecc"])]
    top: String,
}

/// `encspeed synth`: `synth` for `--top wb`, `synth_ecc` for `--top ecc`.
pub fn run(args: &SynthArgs) -> Outcome {
    args.spec.run(|p| {
        if args.top == "ecc" {
            synth_ecc(p)
        } else {
            synth(p, &args.device, &args.package)
        }
    })
}

/// yosys `synth_ice40` of `encspeed_ecc` for `p`: the cells by type.
fn synth_ecc(p: &Params) -> Outcome {
    let dir = tools::work_dir("synth-ecc", "").map_err(|e| (1, e))?;
    let verilog = hdl::emit_ecc(p).map_err(|e| (2, e))?;
    std::fs::write(dir.join("encspeed_ecc.v"), verilog).map_err(|e| (1, e.to_string()))?;
    let _ = std::fs::remove_file(dir.join("stat.txt"));
    tools::run(
        std::process::Command::new("yosys").current_dir(&dir).args([
            "-q",
            "-p",
            "read_verilog encspeed_ecc.v; synth_ice40 -top encspeed_ecc; tee -q -o stat.txt stat",
        ]),
        "yosys",
    )
    .map_err(|e| (1, e))?;
    let stat = std::fs::read_to_string(dir.join("stat.txt")).map_err(|e| (1, e.to_string()))?;
    println!(
        "encspeed_ecc, yosys synth_ice40, {}-bit counters, K = {}:",
        p.counter_bits(),
        p.lines()
    );
    let mut flip_flops = 0u64;
    for l in stat.lines().map(str::trim) {
        let mut it = l.split_whitespace();
        if let (Some(cell), Some(n)) = (it.next(), it.next().and_then(|n| n.parse::<u64>().ok())) {
            if cell.starts_with("SB_") {
                println!("  {cell:<14} {n}");
                if cell.starts_with("SB_DFF") {
                    flip_flops += n;
                }
            }
        }
    }
    println!("  flip-flops     {flip_flops}");
    Ok(())
}

fn synth(p: &Params, device: &str, package: &str) -> Outcome {
    let dir = tools::work_dir("synth", "").map_err(|e| (1, e))?;
    // The complete core has about 430 port bits, more than any iCE40 package has pins: place
    // and route the Wishbone top `encspeed_wb` (the core behind its register file, about 80
    // pins), as a CPU-attached design would be.
    hdl::emit::wb::write_all(p, &dir).map_err(|e| (1, e.to_string()))?;
    let clock = dir.join("clock.py");
    std::fs::write(
        &clock,
        format!("ctx.addClock(\"clock\", {})\n", p.clock_hz() / 1e6),
    )
    .map_err(|e| (1, e.to_string()))?;
    let run = |cmd: &mut std::process::Command, what: &str| {
        tools::run(cmd.current_dir(&dir), what).map_err(|e| (1, e))
    };
    run(
        std::process::Command::new("yosys").args([
            "-q",
            "-p",
            "read_verilog encspeed_wb.v; synth_ice40 -top encspeed_wb -json core.json",
        ]),
        "yosys",
    )?;
    let log = run(
        std::process::Command::new("nextpnr-ice40")
            .arg(format!("--{device}"))
            .args([
                "--package",
                package,
                "--json",
                "core.json",
                "--asc",
                "core.asc",
            ])
            .args([
                "--pcf-allow-unconstrained",
                "--timing-allow-fail",
                "--seed",
                "1",
                "--pre-pack",
                "clock.py",
            ]),
        "nextpnr-ice40",
    )?;
    // Utilisation is reported once (the line with a percentage); the routed Fmax is the
    // last frequency line.
    let tidy = |l: &str| {
        let l = l.trim();
        let l = l
            .strip_prefix("Info:")
            .or(l.strip_prefix("Warning:"))
            .unwrap_or(l);
        l.trim().to_string()
    };
    let first = |key: &str| {
        log.lines()
            .find(|l| l.contains(key) && l.contains('%'))
            .map(tidy)
    };
    let last = |key: &str| log.lines().rev().find(|l| l.contains(key)).map(tidy);
    let missing = |key: &str| (1, format!("no `{key}` in the nextpnr log"));
    println!(
        "encspeed_wb on {device} {package}, {}-bit counters, clock constraint {} MHz",
        p.counter_bits(),
        p.clock_hz() / 1e6
    );
    for key in ["ICESTORM_LC:", "SB_IO:"] {
        println!("{}", first(key).ok_or_else(|| missing(key))?);
    }
    let key = "Max frequency for clock";
    println!("{}", last(key).ok_or_else(|| missing(key))?);
    Ok(())
}
