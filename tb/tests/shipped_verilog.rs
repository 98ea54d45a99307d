// SPDX-License-Identifier: MIT OR Apache-2.0
//! The Verilog that ships is the Verilog that was tested: `generated/encspeed_core.v` is
//! what the generator emits for the default parameters, it passes lint and synthesis, and
//! it equals the bit-true golden model on every cycle in Verilator and in Icarus;
//! `generated/encspeed_ecc.v` is current and synthesises with its tables in block RAM (its
//! behaviour on the Verilog: tb/tests/ecc_top.rs).

use golden::params::{Params, Spec};
use golden::top::core::CoreInputs;
use std::path::PathBuf;
use tb::cosim::{assert_same, run_golden};
use tb::verilator::Verilated;

fn generated(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../generated")
        .join(name)
}

fn shipped_verilog() -> String {
    std::fs::read_to_string(generated("encspeed_core.v")).expect("generated/encspeed_core.v")
}

fn default_params() -> Params {
    Params::new(Spec::default()).unwrap()
}

/// Every file of every shipped top ([`hdl::Top::ALL`]) and every board top
/// ([`golden::board::boards::Board::ALL`]) is in `generated/` byte for byte, and
/// `generated/` holds nothing else (no file left behind by a renamed top).
#[test]
fn generated_files_are_up_to_date() {
    let p = default_params();
    let stale = "is stale: run `cargo run --release -- generate` and commit generated/";
    let mut expected = std::collections::BTreeSet::new();
    for top in hdl::Top::ALL {
        for (name, text) in top.files(&p).unwrap() {
            let shipped = std::fs::read_to_string(generated(&name)).unwrap_or_default();
            assert!(text == shipped, "generated/{name} {stale}");
            expected.insert(name);
        }
    }
    let command = golden::provenance::generate_command(&p);
    for board in golden::board::boards::Board::ALL {
        for (name, text) in hdl::emit::boards::board_files(board, p.spec(), &command).unwrap() {
            let shipped = std::fs::read_to_string(generated(&name)).unwrap_or_default();
            assert!(text == shipped, "generated/{name} {stale}");
            expected.insert(name);
        }
    }
    let present: std::collections::BTreeSet<String> = std::fs::read_dir(generated(""))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        present, expected,
        "generated/ holds files of no shipped top"
    );
    // Emission is deterministic.
    assert_eq!(
        hdl::Top::Core.files(&p).unwrap(),
        hdl::Top::Core.files(&p).unwrap()
    );
}

#[test]
fn generated_docs_are_up_to_date() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/ports.md");
    let doc = std::fs::read_to_string(&path).expect("docs/ports.md");
    assert!(
        doc == hdl::emit::ports_markdown(&default_params()),
        "docs/ports.md is stale: run `cargo run --release -- docs` and commit it"
    );
}

#[test]
fn manifest_records_the_parameters_and_ports() {
    let m: toml::Value =
        toml::from_str(&std::fs::read_to_string(generated("encspeed_core.toml")).unwrap()).unwrap();
    let d = Spec::default();
    assert_eq!(m["spec"]["clock_hz"].as_float(), Some(d.clock_hz));
    assert_eq!(
        m["spec"]["counter_bits"].as_integer(),
        Some(d.counter_bits as i64)
    );
    assert_eq!(m["generator"]["top_module"].as_str(), Some("encspeed_core"));
    // What an outside bench reads to scale speed_n3: a top-level key.
    assert_eq!(m["speed_frac_bits"].as_integer(), Some(16));
    assert_eq!(
        m["speed_bits"].as_integer(),
        Some(i64::from(d.counter_bits) + 17)
    );
    // ω_lim = 100e6 / (1024 · 100000) rev/s, by hand.
    assert_eq!(m["derived"]["omega_lim_rps"].as_float(), Some(0.9765625));
    let ports: Vec<&str> = m["ports"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap())
        .collect();
    // The ports of the module header, in order, are those of the manifest.
    let header = format!("module encspeed_core({});", ports.join(","));
    assert!(
        shipped_verilog().contains(&header),
        "Verilog lacks `{header}`"
    );
    for name in [
        "clock",
        "reset",
        "enc_a",
        "enc_b",
        "enc_z",
        "cfg_dt",
        "cfg_timeout",
        "cfg_filter",
        "cfg_mode",
        "cfg_z_mode",
        "clear_faults",
        "position",
        "speed_n3",
        "speed_strobe",
        "speed_pc",
        "speed_et",
        "speed_mt",
        "valid",
        "stalled",
        "fault_overspeed",
    ] {
        assert!(ports.contains(&name), "port {name} missing");
    }
}

#[test]
fn verilator_lint_is_clean_with_the_documented_waivers() {
    tb::verilator::lint(&shipped_verilog()).unwrap();
}

#[test]
fn yosys_synthesises_it_for_ice40_without_latches() {
    let log = yosys_synth("encspeed_core", &shipped_verilog());
    assert!(log.contains("SB_LUT4"), "no logic synthesised:\n{log}");
}

// The two ecc synthesis tests are the binary's longest (yosys takes minutes on each): their
// names sort first, so that libtest, which starts tests in name order, runs them side by
// side from the start and the short tests fill the gap after the first ends.

/// `generated/encspeed_ecc.v` synthesises without latches, and its four sine tables (one
/// per corrector, the identification's sine and cosine; K = 1024 words of 24 bits = 24
/// kbit each) map to block RAM: 6 SB_RAM40_4K (4 kbit) each, 24 in all, by hand.
#[test]
fn ecc_top_synthesises_in_yosys_with_its_tables_in_block_ram() {
    let v = std::fs::read_to_string(generated("encspeed_ecc.v")).expect("generated/encspeed_ecc.v");
    let log = yosys_synth("encspeed_ecc", &v);
    let brams = log
        .lines()
        .rev()
        .find_map(|l| l.trim().strip_prefix("SB_RAM40_4K"))
        .map(|n| n.trim().parse::<u32>().unwrap());
    assert_eq!(brams, Some(24), "block RAMs:\n{log}");
}

/// The shipped `encspeed_ecc_wb.v` synthesises for iCE40 without latches, with the same
/// 24 block RAMs as `encspeed_ecc` (the two register files add none); the cell counts are
/// printed for docs/benchmarks.md.
#[test]
fn ecc_wishbone_top_synthesises_in_yosys() {
    let v = std::fs::read_to_string(generated("encspeed_ecc_wb.v"))
        .expect("generated/encspeed_ecc_wb.v");
    let log = yosys_synth("encspeed_ecc_wb", &v);
    let count = |cell: &str| {
        log.lines()
            .rev()
            .find_map(|l| l.trim().strip_prefix(cell))
            .and_then(|n| n.trim().parse::<u32>().ok())
    };
    println!(
        "encspeed_ecc_wb: SB_LUT4 {:?}, SB_CARRY {:?}, SB_RAM40_4K {:?}",
        count("SB_LUT4"),
        count("SB_CARRY"),
        count("SB_RAM40_4K")
    );
    assert_eq!(count("SB_RAM40_4K"), Some(24), "block RAMs:\n{log}");
}

/// yosys `synth_ice40` of `top` in `verilog`, `check -assert`, no latch inferred; the log.
fn yosys_synth(top: &str, verilog: &str) -> String {
    let dir = tools::work_dir("yosys", "shipped").unwrap();
    let v = format!("{top}.v");
    tools::stage(&dir, &[(&v, verilog)]).unwrap();
    tools::yosys_synth_ice40(&dir, top, &v).unwrap()
}

/// Named scenarios with the motion scaled to a dt of 1000 cycles (driven on cfg_dt), so
/// they are short enough for Icarus.
fn scenario_inputs(p: &Params, cfg_dt: u64) -> Vec<(String, Vec<CoreInputs>)> {
    let at_dt = Params::new(Spec {
        dt_cycles: cfg_dt,
        ..p.spec().clone()
    })
    .unwrap();
    tb::scenarios::all()
        .iter()
        .map(|s| {
            let prof = s.profile(&at_dt).unwrap();
            (
                s.name.to_string(),
                tb::stimulus::from_profile(p, &prof, cfg_dt).unwrap(),
            )
        })
        .collect()
}

#[test]
fn shipped_verilog_equals_golden_in_verilator() {
    let p = default_params();
    let v = Verilated::build(&shipped_verilog()).unwrap();
    let mut cycles = 0;
    for (name, inputs) in scenario_inputs(&p, 1000) {
        let golden = run_golden(&p, &inputs);
        assert_same(
            &format!("{name} (verilator, shipped)"),
            &inputs,
            &golden,
            &v.run(&inputs, None).unwrap(),
        );
        cycles += inputs.len();
    }
    // One scenario at the nominal dt of 100 000 cycles (1.2 million cycles).
    let s = tb::scenarios::find("constant-high").unwrap();
    let inputs = s.inputs(&p).unwrap();
    let golden = run_golden(&p, &inputs);
    assert_same(
        "constant-high at nominal dt (verilator, shipped)",
        &inputs,
        &golden,
        &v.run(&inputs, None).unwrap(),
    );
    cycles += inputs.len();
    let last = golden.last().unwrap();
    assert_eq!(
        (last.nep, last.ndt),
        (4, 1),
        "3.3 ω_lim: Nep1 = ceil(3.3), Ndt1 = 1"
    );
    // n3 = 2·Nep·(Nep − 1)/(Ndt·(2·Nep − 1)) = 24/7 ω_lim (eq. 11, by hand), in units of
    // 2^−16: 24/7 · 65536 = 224694.86 → 224695.
    assert_eq!(last.speed_n3, 224_695);
    assert!(last.valid && !last.stalled);
    println!("{cycles} cycles identical");
}

#[test]
fn shipped_verilog_equals_golden_in_icarus() {
    let p = default_params();
    let mut total = 0;
    for (name, inputs) in scenario_inputs(&p, 400) {
        let golden = run_golden(&p, &inputs);
        let r = tb::icarus::replay(
            &name,
            &shipped_verilog(),
            p.counter_bits(),
            p.speed_bits(),
            &inputs,
            &golden,
        )
        .unwrap();
        assert_eq!(
            r.failed, 0,
            "{name}: Icarus differs from the golden model on {} cycles",
            r.failed
        );
        assert_eq!(
            r.passed as usize,
            inputs.len(),
            "{name}: not every cycle was checked"
        );
        total += r.passed;
    }
    println!("{total} cycles identical in Icarus");
}
