// SPDX-License-Identifier: MIT OR Apache-2.0
//! The `encspeed` command line: the README's generate command reproduces `generated/`,
//! bad parameters are refused with exit code 2 and a message naming them (nothing is
//! written), and `simulate` writes a VCD under the path given.

use golden::params::Spec;
use golden::provenance::Comment;
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
    let list = |d: &Path| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    };
    // The same files as generated/ (which tb's shipped_verilog test proves holds exactly
    // the files of hdl::Top::ALL), byte for byte.
    let files = list(&Path::new(env!("CARGO_MANIFEST_DIR")).join("generated"));
    assert_eq!(list(&out), files);
    for f in &files {
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
fn generate_for_lines_not_a_multiple_of_4_writes_the_core_and_says_why_not_the_ecc_top() {
    let out = scratch("generate-1000");
    let o = encspeed(&[
        "generate",
        "--lines",
        "1001",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.join("encspeed_core.v").exists());
    assert!(!out.join("encspeed_ecc.v").exists());
    assert!(!out.join("encspeed_ecc_wb.v").exists());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("encspeed_ecc.v and encspeed_ecc_wb.v not written")
            && err.contains("multiple of 4"),
        "{err}"
    );
}

#[test]
fn generate_with_channels_writes_the_wide_top_and_says_why_not_the_one_channel_tops() {
    let out = scratch("generate-channels");
    let o = encspeed(&[
        "generate",
        "--channels",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v = std::fs::read_to_string(out.join("encspeed_wb.v")).unwrap();
    assert!(v.starts_with("// Command: encspeed generate") && v.contains("--channels 3"));
    // Three encoders, 8 + 2 address bits, one interrupt per channel.
    for port in [
        "input wire  [2:0] enc_a",
        "input wire  [9:0] wb_adr_i",
        "output reg  [2:0] irq",
    ] {
        assert!(v.contains(port), "{port}");
    }
    let h = std::fs::read_to_string(out.join("encspeed_regs.h")).unwrap();
    assert!(
        h.contains("ENCSPEED_CH2_BASE") && h.contains("0x200u"),
        "{h}"
    );
    assert!(out.join("encspeed_core.v").exists());
    assert!(!out.join("encspeed_ecc_wb.v").exists());
    assert!(!out.join("encspeed_board_icebreaker.v").exists());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("encspeed_ecc_wb.v not written: channels = 3")
            && err.contains("one encoder PMOD"),
        "{err}"
    );
}

/// Five revolutions at 6000 r/min (10 M/T windows each) on encspeed_ecc.v in Verilator,
/// with the corrector loaded from the Verilog's own identification (--identify): it
/// finds e = 0.35/30 (by hand) within 1 % and θ0 = 50° within 1°; before correction the
/// once-per-revolution ripple is the eccentricity e = 11 667 ppm, after it below 10 ppm;
/// bad arguments exit 2.
#[test]
fn ecc_ripple_prints_the_ripple_and_writes_the_figure() {
    let out = scratch("ecc-ripple");
    let svg = out.join("r.svg");
    let csv = out.join("r.csv");
    let o = encspeed(&[
        "ecc-ripple",
        "--rpm",
        "6000",
        "--revs",
        "5",
        "--svg",
        svg.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
        "--identify",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    let number_in = |line: &str, key: &str| -> f64 {
        let rest = &line[line.find(key).expect(line) + key.len()..];
        rest.split_whitespace().next().unwrap().parse().unwrap()
    };
    let id = text
        .lines()
        .find(|l| l.starts_with("identified on the Verilog"))
        .expect(&text);
    assert!(
        (number_in(id, "e = ") / (0.35 / 30.0) - 1.0).abs() < 0.01,
        "{id}"
    );
    assert!((number_in(id, "theta0 = ") - 50.0).abs() < 1.0, "{id}");
    assert!(text.contains("corrector loaded with"), "{text}");
    let line = text.lines().find(|l| l.starts_with("M/T:")).expect(&text);
    let number_after = |key: &str| number_in(line, key);
    let before = number_after("1/rev ");
    let after = number_after("-> ");
    assert!((before / 11_667.0 - 1.0).abs() < 0.03, "{line}");
    assert!(after < 10.0, "{line}");
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    assert!(std::fs::read_to_string(&csv)
        .unwrap()
        .starts_with("series,angle_rad,error_ppm\nmt,"));
    for bad in [
        &["ecc-ripple", "--rpm", "0"][..],
        &["ecc-ripple", "--revs", "0.5"],
        &["ecc-ripple", "--delta-r-mm", "40"],
        &["ecc-ripple", "--lines", "1001"],
    ] {
        let o = encspeed(bad);
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
    }
}

/// The first line of encspeed.example.toml: how to regenerate it.
const EXAMPLE_COMMAND: &str = "encspeed generate --print-config > encspeed.example.toml";

#[test]
fn the_command_in_the_first_line_of_every_generated_file_regenerates_it() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("generated");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    // Four tops, each with .v, _inst.v, .toml and .vlt, the two C headers, and the three
    // board tops' .v and .vlt.
    assert_eq!(files.len(), 4 * 4 + 2 + 3 * 2, "{files:?}");
    // Each distinct command is run once, into a directory of its own.
    let mut runs: std::collections::BTreeMap<String, PathBuf> = Default::default();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        let cmd = golden::provenance::command_of(&text)
            .unwrap_or_else(|| panic!("{}: no command in the first line", path.display()))
            .to_string();
        let k = runs.len();
        let out = runs.entry(cmd.clone()).or_insert_with(|| {
            let out = scratch(&format!("header-command-{k}"));
            let mut args: Vec<&str> = cmd.split_whitespace().skip(1).collect();
            assert_eq!(args.first(), Some(&"generate"), "{}", path.display());
            args.extend(["--out", out.to_str().unwrap()]);
            assert!(encspeed(&args).status.success());
            out
        });
        let name = path.file_name().unwrap();
        assert_eq!(
            std::fs::read_to_string(out.join(name)).unwrap(),
            text,
            "{}",
            path.display()
        );
    }
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

/// One invalid value per `Spec` field: (field, its option, a value `Params::new` refuses,
/// the same value in a TOML file).
const INVALID: &[(&str, &str, &str, &str)] = &[
    ("clock_hz", "--clock-hz", "0", "0"),
    ("lines", "--lines", "0", "0"),
    ("dt_cycles", "--dt-cycles", "1", "1"),
    ("counter_bits", "--counter-bits", "7", "7"),
    ("timeout_s", "--timeout-s", "-1", "-1"),
    ("estimators", "--estimators", "pc,mt", r#"["pc", "mt"]"#),
    ("channels", "--channels", "9", "9"),
    // A flag: its invalid use is a value (`--no-identification=yes`, one argument).
    ("identification", "--no-identification", "=yes", "3"),
];

fn spec_keys() -> Vec<String> {
    let t: toml::Table = toml::from_str(&toml::to_string(&Spec::default()).unwrap()).unwrap();
    t.keys().cloned().collect()
}

/// An empty output directory under target/cli-test.
fn empty_dir(name: &str) -> PathBuf {
    let d = scratch(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn assert_empty(dir: &Path, what: &str) {
    let n = std::fs::read_dir(dir).unwrap().count();
    assert_eq!(n, 0, "{what}: wrote into {}", dir.display());
}

fn print_config(args: &[&str]) -> Spec {
    let mut a = vec!["generate", "--print-config"];
    a.extend_from_slice(args);
    let o = encspeed(&a);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    toml::from_str(&String::from_utf8(o.stdout).unwrap()).unwrap()
}

#[test]
fn invalid_cases_cover_every_spec_field() {
    let mut covered: Vec<String> = INVALID.iter().map(|c| c.0.to_string()).collect();
    let mut keys = spec_keys();
    covered.sort();
    keys.sort();
    assert_eq!(covered, keys);
}

#[test]
fn every_spec_field_has_an_option_with_unit_range_and_default() {
    for cmd in ["generate", "simulate", "bench", "synth"] {
        let o = encspeed(&[cmd, "--help"]);
        let help = String::from_utf8_lossy(&o.stdout);
        for opt in ["--config", "--print-config"] {
            assert!(help.contains(opt), "{cmd} --help lacks {opt}");
        }
        for (key, opt, _, _) in INVALID {
            let line = help
                .lines()
                .find(|l| l.trim_start().starts_with(opt))
                .unwrap_or_else(|| panic!("{cmd} --help lacks {opt} ({key})"));
            assert!(line.contains("[default "), "{cmd}: {line}");
        }
    }
}

#[test]
fn invalid_option_of_every_field_exits_2_naming_it_and_writes_nothing() {
    for (key, opt, value, _) in INVALID {
        let out = empty_dir(&format!("bad-option-{key}"));
        let flag_with_value = format!("{opt}{value}");
        let o = if value.starts_with('=') {
            encspeed(&["generate", "--out", out.to_str().unwrap(), &flag_with_value])
        } else {
            encspeed(&["generate", "--out", out.to_str().unwrap(), opt, value])
        };
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{opt} {value}: {err}");
        assert!(
            err.contains(key),
            "{opt} {value}: `{err}` should name {key}"
        );
        assert!(
            err.contains(opt),
            "{opt} {value}: `{err}` should name {opt}"
        );
        assert!(o.stdout.is_empty(), "{opt} {value}");
        assert_empty(&out, &format!("{opt} {value}"));
    }
}

#[test]
fn invalid_config_value_of_every_field_exits_2_naming_it_and_writes_nothing() {
    let dir = empty_dir("bad-config-values");
    for (key, _, _, value) in INVALID {
        let file = dir.join(format!("{key}.toml"));
        // TOML integers are taken for float fields too.
        std::fs::write(&file, format!("{key} = {value}\n")).unwrap();
        let out = empty_dir(&format!("bad-config-{key}"));
        let o = encspeed(&[
            "generate",
            "--config",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{key} = {value}: {err}");
        assert!(
            err.contains(key),
            "{key} = {value}: `{err}` should name {key}"
        );
        assert!(
            err.contains(file.to_str().unwrap()),
            "{key} = {value}: `{err}` should name the file"
        );
        assert_empty(&out, &format!("{key} = {value}"));
    }
}

#[test]
fn unknown_or_mistyped_config_key_and_bad_files_are_refused() {
    let dir = empty_dir("bad-config-files");
    let out = empty_dir("bad-config-files-out");
    let cases: &[(&str, Option<&str>, &[&str])] = &[
        (
            "unknown.toml",
            Some("lines = 512\ncounter_bitz = 4\n"),
            &["counter_bitz"],
        ),
        ("table.toml", Some("[encoder]\nlines = 512\n"), &["encoder"]),
        ("type.toml", Some("lines = \"many\"\n"), &["lines", "u32"]),
        (
            "negative.toml",
            Some("counter_bits = -3\n"),
            &["counter_bits"],
        ),
        (
            "syntax.toml",
            Some("lines = \n"),
            &["syntax.toml", "line 1"],
        ),
        ("missing.toml", None, &["missing.toml", "cannot read"]),
    ];
    for (name, text, needles) in cases {
        let file = dir.join(name);
        if let Some(t) = text {
            std::fs::write(&file, t).unwrap();
        }
        let o = encspeed(&[
            "generate",
            "--config",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        for n in *needles {
            assert!(err.contains(n), "{name}: `{err}` should name {n}");
        }
        assert_empty(&out, name);
    }
}

#[test]
fn options_override_the_config_file_which_overrides_the_defaults() {
    let dir = empty_dir("precedence");
    let file = dir.join("p.toml");
    std::fs::write(&file, "lines = 500\ncounter_bits = 20\ntimeout_s = 2\n").unwrap();
    let f = file.to_str().unwrap();
    let from_file = print_config(&["--config", f]);
    let both = print_config(&["--config", f, "--lines", "2000", "--timeout-s", "0.5"]);
    let d = Spec::default();
    assert_eq!(
        from_file,
        Spec {
            lines: 500,
            counter_bits: 20,
            timeout_s: 2.0,
            ..d.clone()
        }
    );
    assert_eq!(
        both,
        Spec {
            lines: 2000,
            counter_bits: 20,
            timeout_s: 0.5,
            ..d.clone()
        }
    );
    assert_eq!(print_config(&[]), d);
    // The file's value is refused only if no option overrides it.
    std::fs::write(&file, "lines = 0\n").unwrap();
    assert_eq!(print_config(&["--config", f, "--lines", "8"]).lines, 8);
}

#[test]
fn print_config_writes_nothing() {
    let out = scratch("print-config");
    let o = encspeed(&["generate", "--print-config", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!out.exists(), "wrote {}", out.display());
}

#[test]
fn example_file_is_the_printed_defaults_and_parses_to_them() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("encspeed.example.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    assert_eq!(toml::from_str::<Spec>(&text).unwrap(), Spec::default());
    // The file is the printed defaults after the two lines every generated file starts with.
    let o = encspeed(&["generate", "--print-config"]);
    let preamble = golden::provenance::preamble(Comment::Hash, EXAMPLE_COMMAND);
    assert_eq!(
        format!("{preamble}{}", String::from_utf8_lossy(&o.stdout)),
        text,
        "regenerate with the command of its first line"
    );
    for key in spec_keys() {
        let i = text.find(&format!("\n{key} = ")).expect(&key);
        let comment = text[..i].lines().last().unwrap();
        assert!(comment.starts_with("# "), "{key} has no comment line");
    }
}
