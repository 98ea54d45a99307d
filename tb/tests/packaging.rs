// SPDX-License-Identifier: MIT OR Apache-2.0
//! The IP as a user takes it (docs/integration.md): every shipped top lints clean with its
//! shipped waivers; two configurations generated with
//! `--prefix` load into one design in Verilator (lint clean with their shipped waivers) and in
//! yosys, where two unprefixed ones collide; every top's instantiation template compiles
//! against its module in Icarus with every port at its width; two prefixed C headers
//! compile into one C file; every manifest carries the ports, the latencies and the error
//! budget; FuseSoC lints every top through the core file at the repository root.

use golden::params::{Params, Spec};
use golden::top::ports::Port;
use hdl::{Prefix, Top};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The default configuration (24-bit counters, 1024 lines).
fn default_params() -> Params {
    Params::new(Spec::default()).unwrap()
}

/// A second configuration with other port widths (10-bit counters, 16 lines), so a
/// module of one loaded in place of the other's would not fit its ports.
fn small_params() -> Params {
    Params::new(Spec {
        lines: 16,
        counter_bits: 10,
        dt_cycles: 200,
        clock_hz: 1e6,
        timeout_s: 0.1,
        ..Spec::default()
    })
    .unwrap()
}

fn generated(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../generated")
        .join(name)
}

/// `[w-1:0] ` or nothing for one bit.
fn range(port: &Port) -> String {
    if port.width == 1 {
        String::new()
    } else {
        format!("[{}:0] ", port.width - 1)
    }
}

/// A module `use_<module>` with every port of the top, whose body is the top's
/// instantiation template, included as a user would paste it.
fn user_of(module: &str, ports: &[Port]) -> String {
    let decls: Vec<String> = ports
        .iter()
        .map(|p| format!("    {} {}{}", p.direction, range(p), p.name))
        .collect();
    format!(
        "module use_{module} (\n{}\n);\n`include \"{module}_inst.v\"\nendmodule\n",
        decls.join(",\n")
    )
}

/// A top `two_cores` that instantiates `use_<module>` of each of `modules` (cores of the
/// given ports): the encoder, clock and reset shared, the configuration tied to 0 (the
/// generated defaults), and every output of each reduced into one parity bit, so nothing
/// is unused.
fn two_cores(cores: &[(&str, Vec<Port>)]) -> String {
    let shared = ["clock", "reset", "enc_a", "enc_b", "enc_z"];
    let mut v = format!(
        "module two_cores (\n    input clock, input reset, input enc_a, input enc_b, input enc_z,\n    {}\n);\n",
        (0..cores.len())
            .map(|k| format!("output parity_{k}"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    for (k, (module, ports)) in cores.iter().enumerate() {
        let mut conns = Vec::new();
        let mut outs = Vec::new();
        for p in ports {
            let signal = if p.is_input() {
                if shared.contains(&p.name) {
                    p.name.to_string()
                } else {
                    format!("{}'d0", p.width)
                }
            } else {
                v.push_str(&format!("    wire {}c{k}_{};\n", range(p), p.name));
                outs.push(format!("c{k}_{}", p.name));
                format!("c{k}_{}", p.name)
            };
            conns.push(format!("        .{}({signal})", p.name));
        }
        v.push_str(&format!(
            "    use_{module} u{k} (\n{}\n    );\n    assign parity_{k} = ^{{{}}};\n",
            conns.join(",\n"),
            outs.join(", ")
        ));
    }
    v.push_str("endmodule\n");
    v
}

/// yosys reads `files` in `dir` and elaborates `top`: Ok, or yosys's error.
fn yosys_elaborate(dir: &Path, files: &[String], top: &str) -> Result<String, String> {
    tools::run(
        Command::new("yosys")
            .current_dir(dir)
            .arg("-p")
            .arg(format!(
                "read_verilog -noautowire {}; hierarchy -check -top {top}; proc; stat",
                files.join(" ")
            )),
        "yosys",
    )
}

/// Two cores of different parameters, generated with `--prefix acme_` and `--prefix beta_`,
/// load together: Verilator `--lint-only -Wall` of both with their shipped waivers and
/// templates is clean, and yosys elaborates both under one top. Without the prefixes the
/// same two files redefine `encspeed_core` and yosys refuses them.
#[test]
fn two_prefixed_cores_load_together() {
    let dir = tools::work_dir("packaging", "two-cores").unwrap();
    let mut staged: Vec<(String, String)> = Vec::new();
    let mut cores = Vec::new();
    for (prefix, p) in [("acme_", default_params()), ("beta_", small_params())] {
        let prefix = Prefix::new(prefix).unwrap();
        let files = Top::Core.files_prefixed(&p, &prefix).unwrap();
        let module = format!("{prefix}encspeed_core");
        for (name, _) in &files {
            assert!(name.starts_with(prefix.as_str()), "{name}");
        }
        let verilog = &files[0].1;
        for line in verilog.lines().filter(|l| l.starts_with("module ")) {
            assert!(line.starts_with(&format!("module {module}")), "{line}");
        }
        assert!(
            !verilog.contains(" encspeed_"),
            "an unprefixed name is left"
        );
        staged.extend(files);
        let ports = Top::Core.ports(&p);
        staged.push((format!("use_{module}.v"), user_of(&module, &ports)));
        cores.push((module, ports));
    }
    let cores: Vec<(&str, Vec<Port>)> =
        cores.iter().map(|(m, p)| (m.as_str(), p.clone())).collect();
    staged.push(("two_cores.v".into(), two_cores(&cores)));
    let refs: Vec<(&str, &str)> = staged
        .iter()
        .map(|(n, t)| (n.as_str(), t.as_str()))
        .collect();
    tools::stage(&dir, &refs).unwrap();
    let vlt: Vec<&str> = refs
        .iter()
        .map(|r| r.0)
        .filter(|n| n.ends_with(".vlt"))
        .collect();
    let verilog: Vec<&str> = refs
        .iter()
        .map(|r| r.0)
        .filter(|n| n.ends_with(".v") && !n.ends_with("_inst.v"))
        .collect();
    let files: Vec<&str> = vlt.iter().chain(&verilog).copied().collect();
    tools::verilator_lint(&dir, "two_cores", &files).unwrap();
    let verilog: Vec<String> = verilog.iter().map(|s| s.to_string()).collect();
    let log = yosys_elaborate(&dir, &verilog, "two_cores").unwrap();
    assert!(log.contains("acme_encspeed_core") && log.contains("beta_encspeed_core"));

    // The control: the same two configurations unprefixed define encspeed_core twice.
    let dir = tools::work_dir("packaging", "two-cores-unprefixed").unwrap();
    let a = Top::Core.files(&default_params()).unwrap().swap_remove(0).1;
    let b = Top::Core.files(&small_params()).unwrap().swap_remove(0).1;
    tools::stage(&dir, &[("a.v", &a), ("b.v", &b)]).unwrap();
    let e = yosys_elaborate(&dir, &["a.v".into(), "b.v".into()], "encspeed_core").unwrap_err();
    assert!(e.contains("Re-definition of module"), "{e}");
}

/// `verilator --lint-only -Wall <top>.vlt <top>.v` on each shipped top, as
/// docs/integration.md tells a user to run it, is clean.
#[test]
fn every_shipped_top_lints_clean_with_its_shipped_waivers() {
    for top in Top::ALL {
        let module = top.module();
        let dir = generated("");
        tools::verilator_lint(
            &dir,
            module,
            &[&format!("{module}.vlt"), &top.verilog_file()],
        )
        .unwrap_or_else(|e| panic!("{module}: {e}"));
    }
}

/// Each shipped top's `_inst.v`, pasted into a module with the top's ports, compiles
/// against the shipped Verilog in Icarus `-Wall` with no warning (a port of the wrong width
/// or a missing one would warn).
#[test]
fn every_instantiation_template_compiles_against_its_top() {
    let p = default_params();
    for top in Top::ALL {
        let module = top.module();
        let dir = tools::work_dir("packaging", &format!("inst-{module}")).unwrap();
        let read = |name: String| {
            std::fs::read_to_string(generated(&name)).unwrap_or_else(|e| panic!("{name}: {e}"))
        };
        let verilog = read(top.verilog_file());
        let inst = read(format!("{module}_inst.v"));
        assert_eq!(
            inst.matches("\n    .").count(),
            top.ports(&p).len(),
            "{module}: one line per port"
        );
        let user = user_of(module, &top.ports(&p));
        let v = format!("{module}.v");
        let i = format!("{module}_inst.v");
        let u = format!("use_{module}.v");
        tools::stage(&dir, &[(&v, &verilog), (&i, &inst), (&u, &user)]).unwrap();
        tools::iverilog(
            &dir,
            &["-s", &format!("use_{module}")],
            &[&v, &u],
            "inst.vvp",
        )
        .unwrap_or_else(|e| panic!("{module}: {e}"));
    }
}

/// The C headers of two prefixed configurations compile into one C file (`-Wall -Wextra
/// -Werror`), each with its own values: 24-bit counters in one, 10-bit in the other.
#[test]
fn two_prefixed_c_headers_compile_together() {
    let dir = tools::work_dir("packaging", "c-headers").unwrap();
    let mut staged = Vec::new();
    for (prefix, p) in [("acme_", default_params()), ("beta_", small_params())] {
        let prefix = Prefix::new(prefix).unwrap();
        for top in [Top::Wb, Top::EccWb] {
            for (name, text) in top.files_prefixed(&p, &prefix).unwrap() {
                if name.ends_with(".h") {
                    staged.push((name, text));
                }
            }
        }
    }
    assert_eq!(staged.len(), 4);
    let mut c: String = staged
        .iter()
        .map(|(n, _)| format!("#include \"{n}\"\n"))
        .collect();
    c.push_str(
        "_Static_assert(ACME_ENCSPEED_COUNTER_BITS == 24u, \"acme\");\n\
         _Static_assert(BETA_ENCSPEED_COUNTER_BITS == 10u, \"beta\");\n\
         _Static_assert(ACME_ENCSPEED_ECC_BASE == BETA_ENCSPEED_ECC_BASE, \"one window layout\");\n\
         int main(void) { return 0; }\n",
    );
    staged.push(("both.c".into(), c));
    let refs: Vec<(&str, &str)> = staged
        .iter()
        .map(|(n, t)| (n.as_str(), t.as_str()))
        .collect();
    tools::stage(&dir, &refs).unwrap();
    tools::run(
        Command::new("cc").current_dir(&dir).args([
            "-std=c11", "-Wall", "-Wextra", "-Werror", "-c", "both.c", "-o", "both.o",
        ]),
        "cc",
    )
    .unwrap();
}

/// Every shipped top has a manifest with its module, its ports in the order of the module
/// header, the latencies, and an error budget whose PC column is 1/r_s, by hand; the bus
/// tops list their registers.
#[test]
fn every_manifest_carries_ports_latencies_and_the_error_budget() {
    for top in Top::ALL {
        let module = top.module();
        let text = std::fs::read_to_string(generated(&format!("{module}.toml"))).unwrap();
        let m: toml::Value = toml::from_str(&text).unwrap();
        assert_eq!(m["generator"]["top_module"].as_str(), Some(module));
        let ports: Vec<&str> = m["ports"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["name"].as_str().unwrap())
            .collect();
        let verilog = std::fs::read_to_string(generated(&top.verilog_file())).unwrap();
        assert!(verilog.contains(&format!("module {module}({});", ports.join(","))));
        assert!(m["derived"]["latency"]["edge_to_speed_strobe"]
            .as_integer()
            .is_some());
        let budget = m["error_budget"].as_array().unwrap();
        assert!(budget.len() >= 12, "{module}: {} rows", budget.len());
        for row in budget {
            // PC's bound is 1/r_s: one step in the window.
            let rs = row["steps_per_dt"].as_float().unwrap();
            assert!((row["pc"].as_float().unwrap() - 1.0 / rs).abs() < 1e-12);
            // x4 at 1000 r/min, default: r_s = 1000/60 · 4096 · 1 ms = 68.27 steps/dt.
            if row["mode"].as_str() == Some("x4") && row["rev_per_min"].as_float() == Some(1e3) {
                assert!((rs - 68.266_666_666_666_67).abs() < 1e-9);
            }
        }
        let has_bus = matches!(top, Top::Wb | Top::EccWb);
        assert_eq!(m.get("registers").is_some(), has_bus, "{module}");
        assert_eq!(m.get("eccentricity").is_some(), top.has_ecc(), "{module}");
        if has_bus {
            let names: Vec<&str> = m["registers"]
                .as_array()
                .unwrap()
                .iter()
                .map(|r| r["name"].as_str().unwrap())
                .collect();
            assert!(
                names.contains(&"ID") && names.contains(&"SPEED_N3_LO"),
                "{names:?}"
            );
            assert_eq!(names.contains(&"ECC_C"), top == Top::EccWb);
        }
    }
}

/// The repository root, where `encspeed.core` lies.
fn repository_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// FuseSoC finds `encspeed.core` at the repository root and its `lint_<top>` target lints
/// each shipped top (the board tops too) with its shipped waivers, clean (docs/integration.md). The same target
/// with the waivers taken out of a copy of the core file fails: the target really runs
/// `verilator --lint-only -Wall` and FuseSoC reports its failure.
#[test]
fn fusesoc_lints_every_shipped_top_and_fails_without_the_waivers() {
    let core = "encspeed:ip:encspeed";
    // FuseSoC scans the cores root recursively: keep it out of target/, where the copy
    // below (and FuseSoC's own build trees) would be a second `encspeed:ip:encspeed`.
    std::fs::write(tools::target_dir().join("FUSESOC_IGNORE"), "").unwrap();
    let build = tools::work_dir("fusesoc", "build").unwrap();
    let tops = Top::ALL.map(|t| t.module().to_string());
    let boards = golden::board::boards::Board::ALL.map(|b| b.module());
    for module in tops.iter().chain(&boards) {
        let target = format!("lint_{}", module.trim_start_matches("encspeed_"));
        tools::fusesoc_run(&repository_root(), &build.join(&target), &target, core)
            .unwrap_or_else(|e| panic!("{target}: {e}"));
    }
    let dir = tools::work_dir("fusesoc", "no-waivers").unwrap();
    let text = std::fs::read_to_string(repository_root().join("encspeed.core")).unwrap();
    let stripped = text.replace("filesets: [wb, wb_lint]", "filesets: [wb]");
    assert_ne!(
        stripped, text,
        "lint_wb lists its waivers as `[wb, wb_lint]`"
    );
    let wb = std::fs::read_to_string(generated("encspeed_wb.v")).unwrap();
    tools::stage(&dir, &[("encspeed.core", &stripped)]).unwrap();
    tools::stage(&dir.join("generated"), &[("encspeed_wb.v", &wb)]).unwrap();
    let e = tools::fusesoc_run(&dir, &dir.join("build"), "lint_wb", core)
        .expect_err("lint_wb without its waivers");
    assert!(e.contains("%Warning-UNUSEDSIGNAL"), "{e}");
}

/// FuseSoC builds each board's bitstream from `encspeed.core` at the repository root with
/// the open flow (yosys; nextpnr-ice40 and icepack, or nextpnr-ecp5 and ecppack; each at
/// the board clock): the bitstream exists and is the device's (icepack's image size; the
/// ECP5 device and JTAG ID that ecppack writes in its header), and nextpnr met the board
/// clock (it fails the build otherwise; its report is read as well). docs/boards.md.
#[test]
fn fusesoc_builds_each_board_bitstream_at_the_board_clock() {
    use golden::board::boards::Board;
    let core = "encspeed:ip:encspeed";
    std::fs::write(tools::target_dir().join("FUSESOC_IGNORE"), "").unwrap();
    // Each board target places for the board's device at its clock (the golden board data).
    let text = std::fs::read_to_string(repository_root().join("encspeed.core")).unwrap();
    for board in Board::ALL {
        let options = format!(
            "nextpnr_options: [{}, --freq, \"{}\"]",
            board.nextpnr_device().join(", "),
            board.clock_hz() / 1_000_000
        );
        assert!(text.contains(&options), "{}: {options}", board.name());
    }
    let build = tools::work_dir("fusesoc", "boards").unwrap();
    // The boards side by side: each flow is single-threaded.
    let runs: Vec<(Board, std::thread::JoinHandle<Result<String, String>>)> = Board::ALL
        .into_iter()
        .map(|board| {
            let root = build.join(board.name());
            let _ = std::fs::remove_dir_all(&root);
            let handle = std::thread::spawn(move || {
                tools::fusesoc_run(&repository_root(), &root, board.name(), core)
            });
            (board, handle)
        })
        .collect();
    for (board, handle) in runs {
        let log = handle
            .join()
            .unwrap()
            .unwrap_or_else(|e| panic!("{}: {e}", board.name()));
        let work = build.join(board.name());
        let name = format!("encspeed_ip_encspeed_0.1.0.{}", board.bitstream_extension());
        let bitstream = find_file(&work, &name).unwrap_or_else(|| {
            panic!(
                "{}: no {name} under {}\n{log}",
                board.name(),
                work.display()
            )
        });
        let image = std::fs::read(&bitstream).unwrap();
        match board {
            // icepack's image sizes: 135 100 bytes for the HX8K, 104 090 for the UP5K.
            Board::Hx8kBreakout => assert_eq!(image.len(), 135_100, "hx8k_breakout"),
            Board::Icebreaker => assert_eq!(image.len(), 104_090, "icebreaker"),
            // ecppack's header names the part, and its VERIFY_ID command (0xE2, three
            // zero bytes) carries the LFE5U-85F's JTAG IDCODE, 0x41113043 (Lattice's
            // ECP5 sysCONFIG guide): a configuration port refuses an image for another die.
            Board::Ulx3s => {
                let head = String::from_utf8_lossy(&image[..64]);
                assert!(head.contains("Part: LFE5U-85F-6CABGA381"), "ulx3s: {head}");
                let verify_id = [0xE2, 0, 0, 0, 0x41, 0x11, 0x30, 0x43];
                assert!(
                    image[..256].windows(8).any(|w| w == verify_id),
                    "ulx3s: no VERIFY_ID 0x41113043 in the header"
                );
            }
        }
        let pnr = std::fs::read_to_string(bitstream.with_file_name("next.log"))
            .unwrap_or_else(|_| log.clone());
        let met = format!("PASS at {}.00 MHz", board.clock_hz() / 1_000_000);
        assert!(
            pnr.contains(&met),
            "{}: nextpnr did not report the board clock met ({met})\n{pnr}",
            board.name()
        );
    }
}

/// The first file named `name` under `dir`, depth first.
fn find_file(dir: &Path, name: &str) -> Option<PathBuf> {
    for entry in std::fs::read_dir(dir).ok()? {
        let path = entry.ok()?.path();
        if path.is_dir() {
            if let Some(found) = find_file(&path, name) {
                return Some(found);
            }
        } else if path.file_name().is_some_and(|n| n == name) {
            return Some(path);
        }
    }
    None
}
