//! The `encspeed` command line: the README's generate command reproduces `generated/`,
//! bad parameters are refused with exit code 2 and a message naming them (nothing is
//! written), and `simulate` writes a VCD under the path given.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn encspeed(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_encspeed"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run encspeed")
}

fn scratch(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("target/cli-test")
        .join(name);
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn generate_with_defaults_reproduces_generated_dir() {
    let out = scratch("generate");
    let o = encspeed(&["generate", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in ["encspeed_core.v", "encspeed_core.toml"] {
        let shipped = std::fs::read(
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("generated")
                .join(f),
        )
        .unwrap();
        assert_eq!(std::fs::read(out.join(f)).unwrap(), shipped, "{f}");
    }
}

#[test]
fn the_command_in_the_header_regenerates_the_file() {
    let v = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("generated/encspeed_core.v"),
    )
    .unwrap();
    let cmd = v
        .lines()
        .find_map(|l| l.strip_prefix("// Command: "))
        .expect("header names the command");
    let out = scratch("header-command");
    let mut args: Vec<&str> = cmd.split_whitespace().skip(1).collect();
    args.extend(["--out", out.to_str().unwrap()]);
    assert!(encspeed(&args).status.success());
    assert_eq!(
        std::fs::read_to_string(out.join("encspeed_core.v")).unwrap(),
        v
    );
}

#[test]
fn bad_parameters_exit_2_naming_the_parameter_and_write_nothing() {
    let cases: &[(&[&str], &str)] = &[
        (&["--lines", "0"], "lines"),
        (&["--dt-cycles", "1"], "dt_cycles"),
        (&["--counter-bits", "40"], "counter_bits"),
        (&["--counter-bits", "12"], "dt_cycles"),
        (&["--clock-hz", "NaN"], "clock_hz"),
        (&["--clock-hz=-5"], "clock_hz"),
        (&["--timeout-s", "1e9"], "timeout_s"),
        (&["--lines", "many"], "lines"),
    ];
    for (i, (extra, name)) in cases.iter().enumerate() {
        let out = scratch(&format!("bad{i}"));
        let mut args = vec!["generate", "--out", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        let o = encspeed(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{extra:?}: {err}");
        assert!(
            err.contains(name) || err.contains(&name.replace('_', "-")),
            "{extra:?}: `{err}` should name {name}"
        );
        assert!(!out.exists(), "{extra:?}: wrote {}", out.display());
    }
}

#[test]
fn configuration_file_is_read_and_checked() {
    let dir = scratch("config");
    std::fs::create_dir_all(&dir).unwrap();
    let good = dir.join("good.toml");
    std::fs::write(&good, "counter_bits = 20\ndt_cycles = 50000\n").unwrap();
    let out = dir.join("out");
    let o = encspeed(&[
        "generate",
        "--config",
        good.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v = std::fs::read_to_string(out.join("encspeed_core.v")).unwrap();
    assert!(v.contains("--dt-cycles 50000 --counter-bits 20"));
    assert!(v.contains("input wire  [19:0] cfg_dt;"));
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "counter_bitz = 20\n").unwrap();
    let o = encspeed(&[
        "generate",
        "--config",
        bad.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("counter_bitz"));
}

#[test]
fn simulate_writes_a_vcd_where_asked() {
    let dir = scratch("simulate");
    let vcd = dir.join("low.vcd");
    let o = encspeed(&[
        "simulate",
        "--scenario",
        "constant-low",
        "--dt-cycles",
        "200",
        "--vcd",
        vcd.to_str().unwrap(),
    ]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // 0.4 ω_lim: Nep1 = 1, Ndt1 = floor(2.5) = 2 (hand calculation).
    assert!(text.contains("final Nep1 = 1, Ndt1 = 2"), "{text}");
    let header = std::fs::read_to_string(&vcd).unwrap();
    assert!(header.contains("$var wire 1 ") && header.contains(" ndt $end"));

    let o = encspeed(&[
        "simulate",
        "--motion",
        "hold:2",
        "--vcd",
        vcd.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let o = encspeed(&["simulate", "--scenario", "nope"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--list"));
}

#[test]
fn bode_writes_csv_and_svg_and_refuses_bad_arguments() {
    let dir = scratch("bode");
    let csv = dir.join("et.csv");
    let svg = dir.join("et.svg");
    let o = encspeed(&[
        "bode",
        "--estimator",
        "et",
        "--lines",
        "125",
        "--rpm",
        "100",
        "--ts-s",
        "1e-3",
        "--points",
        "3",
        "--csv",
        csv.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(
        text.starts_with("f_hz,model_gain_db,model_phase_deg,measured_gain_db,measured_phase_deg")
    );
    assert_eq!(text.lines().count(), 4, "{text}");
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    for (args, name) in [
        (vec!["--rpm=-3", "--ts-s", "1e-3"], "--rpm"),
        (vec!["--rpm", "100", "--ts-s", "0"], "--ts-s"),
        (
            vec!["--rpm", "100", "--ts-s", "1e-4", "--fmax", "6000"],
            "--fmax",
        ),
    ] {
        let mut a = vec!["bode", "--estimator", "et", "--lines", "125"];
        a.extend(args.iter().copied());
        let o = encspeed(&a);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(name), "{args:?}: `{err}` should name {name}");
    }
}
