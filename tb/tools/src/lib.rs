// SPDX-License-Identifier: MIT OR Apache-2.0
//! The one place that finds and runs the external tools of encspeed's tests and benches:
//! Icarus Verilog (`iverilog`, `vvp`), Verilator, yosys, nextpnr and FuseSoC.
//!
//! - **Finding them.** Each tool is run by its plain name from `PATH` ([`run`]). A missing
//!   tool is an error that names `.ci/run` (which installs all of them), never a skip.
//! - **Where their work goes.** Every file a tool reads or writes lies under the workspace's
//!   `target/` ([`target_dir`], or `CARGO_TARGET_DIR` when set), never in the source tree:
//!   [`work_dir`] makes a named directory there; [`lint_verilog`] and [`verilator_build`]
//!   name theirs by content, so parallel tests never write into each other's files.
//! - **Strictness.** `iverilog -Wall -g2005` must print nothing at all ([`iverilog`]);
//!   `verilator --lint-only -Wall` fails on any `%Warning` or `%Error` ([`verilator_lint`]);
//!   yosys `synth_ice40` runs `check -assert` and fails on any inferred latch
//!   ([`yosys_synth_ice40`]). Place and route (yosys with nextpnr-ice40, and the boundary
//!   wrapper that makes a wide top placeable) is [`fpga`]. gcc (the tests of the C register
//!   headers, with `-Werror`) has no wrapper: it goes through [`run`].
//! - **Lint waivers.** No Verilator rule is switched off on the command line but one:
//!   [`lint_verilog`], for single rust-hdl blocks, passes `-Wno-DECLFILENAME` (rust-hdl
//!   names every sub-module by its path, which never matches the file name). Every other
//!   waiver is a line of a shipped `.vlt` file (`hdl/src/emit/lint/`, emitted as
//!   `generated/<top>.vlt`), or added to one in `tb` with its reason, as
//!   `tb::ecc_verilator::waivers_for` does, scoped to one file (and to one message
//!   where it can be) and explained next to it; the caller stages that file and lists it
//!   before the Verilog for [`verilator_lint`] and [`verilator_build`].

pub mod fpga;

use std::path::{Path, PathBuf};
use std::process::Command;

/// The workspace's `target/` (`CARGO_TARGET_DIR` when set): where every tool's work goes,
/// never the source tree.
pub fn target_dir() -> PathBuf {
    match std::env::var_os("CARGO_TARGET_DIR") {
        Some(d) => d.into(),
        // This crate is `<workspace>/tb/tools`.
        None => Path::new(env!("CARGO_MANIFEST_DIR"))
            .ancestors()
            .nth(2)
            .expect("tb/tools lies two levels below the workspace")
            .join("target"),
    }
}

/// `target/<sub>/<name>`, created if missing.
pub fn work_dir(sub: &str, name: &str) -> Result<PathBuf, String> {
    let dir = target_dir().join(sub).join(name);
    std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    Ok(dir)
}

/// Write `files` (name, contents) into `dir`, created if missing; their paths, in order.
pub fn stage(dir: &Path, files: &[(&str, &str)]) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    files
        .iter()
        .map(|(name, text)| {
            let path = dir.join(name);
            std::fs::write(&path, text)
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            Ok(path)
        })
        .collect()
}

/// FNV-1a over the parts, each followed by a zero byte: the content key of the directories
/// named by content.
pub fn content_hash(parts: &[&str]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for p in parts {
        for b in p.bytes().chain([0u8]) {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

/// Run an external tool; its stdout and stderr on success, or an error that says which tool
/// (`what`) failed and how, with its output (a missing tool names `.ci/run`, which installs
/// it).
pub fn run(cmd: &mut Command, what: &str) -> Result<String, String> {
    let out = cmd
        .output()
        .map_err(|e| format!("cannot run {what}: {e} (install it: see .ci/run)"))?;
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    if out.status.success() {
        Ok(text)
    } else {
        Err(format!("{what} failed ({}):\n{text}", out.status))
    }
}

/// `iverilog -Wall -g2005 <args> -o <out_vvp> <sources>` in `dir` (sources relative to it):
/// an error on a failed compile and on any warning (any output at all).
pub fn iverilog(dir: &Path, args: &[&str], sources: &[&str], out_vvp: &str) -> Result<(), String> {
    let text = run(
        Command::new("iverilog")
            .current_dir(dir)
            .args(["-Wall", "-g2005"])
            .args(args)
            .args(["-o", out_vvp])
            .args(sources),
        "iverilog -Wall",
    )?;
    if text.trim().is_empty() {
        Ok(())
    } else {
        Err(format!("iverilog -Wall in {}:\n{text}", dir.display()))
    }
}

/// `vvp -n <vvp_file> <args>` in `dir` (`-n`: `$stop` ends the run, never waits for input):
/// what the simulation printed on stdout, or an error if vvp failed.
pub fn vvp(dir: &Path, vvp_file: &str, args: &[&str]) -> Result<String, String> {
    let out = Command::new("vvp")
        .current_dir(dir)
        .arg("-n")
        .arg(vvp_file)
        .args(args)
        .output()
        .map_err(|e| format!("cannot run vvp: {e} (install it: see .ci/run)"))?;
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    if out.status.success() {
        Ok(stdout)
    } else {
        Err(format!(
            "vvp {vvp_file} in {} failed ({}):\n{stdout}{}",
            dir.display(),
            out.status,
            String::from_utf8_lossy(&out.stderr)
        ))
    }
}

/// `verilator --lint-only -Wall <extra> --top-module <top> <files>` in `dir`; Verilator's
/// output on a clean lint, an error on any `%Warning` or `%Error`.
fn lint(dir: &Path, top: &str, extra: &[&str], files: &[&str]) -> Result<String, String> {
    let text = run(
        Command::new("verilator")
            .current_dir(dir)
            .args(["--lint-only", "-Wall"])
            .args(extra)
            .args(["--top-module", top])
            .args(files),
        "verilator --lint-only -Wall",
    )
    .map_err(|e| format!("{e}\n(in {})", dir.display()))?;
    if text.contains("%Warning") || text.contains("%Error") {
        Err(format!(
            "verilator --lint-only -Wall in {}:\n{text}",
            dir.display()
        ))
    } else {
        Ok(text)
    }
}

/// `verilator --lint-only -Wall --top-module <top> <files>` in `dir` (files relative to it,
/// the `.vlt` waivers first); Verilator's output on a clean lint, an error on any
/// `%Warning` or `%Error`.
pub fn verilator_lint(dir: &Path, top: &str, files: &[&str]) -> Result<String, String> {
    lint(dir, top, &[], files)
}

/// [`verilator_lint`] of one rust-hdl block's `verilog` (top module `top`) with
/// `-Wno-DECLFILENAME` and no other waiver, in `target/block_lint/<top>-<hash>/`, from a file
/// of its own per call: tests (and test processes) lint the same design at once, and one must
/// never read a file another is rewriting.
pub fn lint_verilog(top: &str, verilog: &str) -> Result<(), String> {
    static CALLS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = work_dir(
        "block_lint",
        &format!("{top}-{:016x}", content_hash(&[verilog])),
    )?;
    let file = format!("{top}-{}-{call}.v", std::process::id());
    stage(&dir, &[(&file, verilog)])?;
    lint(&dir, top, &["-Wno-DECLFILENAME"], &[&file]).map(|_| ())
}

/// The executable of `verilator --cc --exe --build -O3` of `files` (name, contents: the
/// `.vlt` waivers, the Verilog and the C++ harness, in the order Verilator should read them)
/// with top module `top`, with `--trace` if `trace` (only a run that writes a VCD needs it:
/// the tracing hooks cost about a sixth of the speed of every run, traced or not), built once
/// per content and `trace` in `target/verilator/<prefix><hash>/` (`obj/V<top>`). Each call
/// builds in a directory private to the process and the call and renames it into place, so
/// parallel tests never see or write into a half-built one. Where `ccache` is on `PATH`
/// (`.ci/run` installs it), the C++ compiler runs through it, with its cache in
/// `target/verilator/ccache/` unless `CCACHE_DIR` says otherwise: an accelerator, not a
/// check, so a machine without it builds the same executables, only slower.
pub fn verilator_build(
    prefix: &str,
    top: &str,
    files: &[(&str, &str)],
    trace: bool,
) -> Result<PathBuf, String> {
    let mut parts: Vec<&str> = vec![top, if trace { "--trace" } else { "" }];
    for (name, text) in files {
        parts.push(name);
        parts.push(text);
    }
    let hash = content_hash(&parts);
    let root = target_dir().join("verilator");
    let done = root.join(format!("{prefix}{hash:016x}"));
    let exe = done.join(format!("obj/V{top}"));
    if exe.exists() {
        return Ok(exe);
    }
    static BUILDS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let build = BUILDS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let tmp = root.join(format!(
        "{prefix}{hash:016x}.tmp{}-{build}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&tmp);
    let paths = stage(&tmp, files)?;
    let mut verilator = Command::new("verilator");
    if on_path("ccache") {
        // The C++ of the Verilator runtime (verilated.cpp and its kin, some 7 s of a core's
        // time per build, with `--trace` 11 s) is the same in every build: ccache compiles it
        // once (and a model whose C++ another build already compiled).
        verilator.env("OBJCACHE", "ccache");
        if std::env::var_os("CCACHE_DIR").is_none() {
            verilator.env("CCACHE_DIR", root.join("ccache"));
        }
    }
    run(
        verilator
            .current_dir(&tmp)
            .args(["--cc", "--exe", "--build", "-O3", "-j", "2"])
            .args(trace.then_some("--trace"))
            .args(["--top-module", top, "-Mdir", "obj"])
            .args(&paths),
        "verilator --build",
    )?;
    if std::fs::rename(&tmp, &done).is_err() {
        // Another process won the race; its build is identical.
        let _ = std::fs::remove_dir_all(&tmp);
    }
    Ok(exe)
}

/// Whether an executable `name` lies in a directory of `PATH`.
fn on_path(name: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|d| d.join(name).is_file()))
}

/// `fusesoc --cores-root <cores_root> run --build-root <build_root> --target=<target> <core>`:
/// its output, or an error if FuseSoC (or the tool it ran) failed. FuseSoC comes from PyPI
/// (`.ci/run` installs it into `target/fusesoc-venv` and puts that on `PATH`).
pub fn fusesoc_run(
    cores_root: &Path,
    build_root: &Path,
    target: &str,
    core: &str,
) -> Result<String, String> {
    run(
        Command::new("fusesoc")
            .arg("--cores-root")
            .arg(cores_root)
            .arg("run")
            .arg("--build-root")
            .arg(build_root)
            .arg(format!("--target={target}"))
            .arg(core),
        &format!("fusesoc (target {target})"),
    )
}

/// yosys `read_verilog -noautowire <file>; synth_ice40 -top <top>; check -assert; stat` in
/// `dir`: the log (stdout), or an error if yosys failed or inferred a latch. `-noautowire`
/// makes an undeclared name an error: yosys otherwise declares it as an undriven wire and
/// synthesises on (rust-hdl once emitted a Rust constant's name in a bit index).
pub fn yosys_synth_ice40(dir: &Path, top: &str, file: &str) -> Result<String, String> {
    let out = Command::new("yosys")
        .current_dir(dir)
        .arg("-p")
        .arg(format!(
            "read_verilog -noautowire {file}; synth_ice40 -top {top}; check -assert; stat"
        ))
        .output()
        .map_err(|e| format!("cannot run yosys: {e} (install it: see .ci/run)"))?;
    let log = String::from_utf8_lossy(&out.stdout).into_owned();
    if !out.status.success() {
        return Err(format!(
            "yosys synth_ice40 of {top} in {} failed ({}):\n{log}\n{}",
            dir.display(),
            out.status,
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    // yosys says "No latch inferred for signal …" for each combinational signal it checked,
    // and "Latch inferred for signal …" for a latch.
    let latches: Vec<&str> = log
        .lines()
        .filter(|l| l.trim_start().starts_with("Latch inferred"))
        .collect();
    if latches.is_empty() {
        Ok(log)
    } else {
        Err(format!("{top}: latches inferred: {latches:#?}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const COUNTER: &str = "module counter(input wire clock, output reg [3:0] q);\n\
        initial q = 4'd0;\n\
        always @(posedge clock) q <= q + 4'd1;\n\
        endmodule\n";

    #[test]
    fn target_dir_is_the_workspace_target_or_cargo_target_dir() {
        let t = target_dir();
        match std::env::var_os("CARGO_TARGET_DIR") {
            Some(d) => assert_eq!(t, PathBuf::from(d)),
            None => {
                assert!(t.ends_with("target"));
                assert!(t.parent().unwrap().join("Cargo.toml").exists());
                assert!(t.parent().unwrap().join("tb/tools").exists());
            }
        }
        let w = work_dir("tools-test", "work").unwrap();
        assert!(w.starts_with(&t) && w.is_dir());
    }

    #[test]
    fn a_missing_tool_names_ci_run_and_a_failing_one_its_output() {
        let e = run(&mut Command::new("encspeed-no-such-tool"), "no-such-tool").unwrap_err();
        assert!(e.contains("no-such-tool") && e.contains(".ci/run"), "{e}");
        let e = run(Command::new("sh").args(["-c", "echo oops; exit 3"]), "sh").unwrap_err();
        assert!(e.contains("sh failed") && e.contains("oops"), "{e}");
        assert_eq!(
            run(Command::new("sh").args(["-c", "echo ok"]), "sh"),
            Ok("ok\n".into())
        );
    }

    #[test]
    fn content_hash_separates_the_parts() {
        assert_ne!(content_hash(&["ab", "c"]), content_hash(&["a", "bc"]));
        assert_eq!(content_hash(&["x"]), content_hash(&["x"]));
    }

    #[test]
    fn icarus_compiles_clean_code_runs_it_and_refuses_a_warning() {
        let dir = work_dir("tools-test", "icarus").unwrap();
        let tb = "module tb;\n    reg clock = 1'b0;\n    wire [3:0] q;\n\
                  counter uut(.clock(clock), .q(q));\n\
                  initial begin\n        repeat (`N) #1 clock = ~clock;\n\
                  $display(\"q %0d\", q);\n        $finish;\n    end\nendmodule\n";
        stage(&dir, &[("counter.v", COUNTER), ("tb.v", tb)]).unwrap();
        iverilog(&dir, &["-DN=10"], &["tb.v", "counter.v"], "tb.vvp").unwrap();
        let text = vvp(&dir, "tb.vvp", &[]).unwrap();
        assert!(text.contains("q 5"), "{text}");
        // A port connected with the wrong width is a warning under -Wall: refused.
        let narrow = tb.replace("wire [3:0] q", "wire [2:0] q");
        stage(&dir, &[("narrow.v", &narrow)]).unwrap();
        let e = iverilog(&dir, &["-DN=10"], &["narrow.v", "counter.v"], "narrow.vvp");
        assert!(e.is_err(), "a width mismatch must fail: {e:?}");
    }

    #[test]
    fn verilator_lint_passes_clean_code_and_fails_on_a_warning() {
        let dir = work_dir("tools-test", "lint").unwrap();
        stage(&dir, &[("counter.v", COUNTER)]).unwrap();
        verilator_lint(&dir, "counter", &["counter.v"]).unwrap();
        // An unused internal signal is an UNUSEDSIGNAL warning under -Wall.
        let unused = COUNTER.replace("initial", "wire [7:0] spare = {4'd0, q};\ninitial");
        let other = work_dir("tools-test", "lint-unused").unwrap();
        stage(&other, &[("counter.v", &unused)]).unwrap();
        let e = verilator_lint(&other, "counter", &["counter.v"]).unwrap_err();
        assert!(
            e.contains("UNUSEDSIGNAL") && !e.contains("DECLFILENAME"),
            "{e}"
        );
        // The block lint waives only DECLFILENAME (the module is not named like its file).
        lint_verilog("counter", COUNTER).unwrap();
        let e = lint_verilog("counter", &unused).unwrap_err();
        assert!(
            e.contains("UNUSEDSIGNAL") && !e.contains("DECLFILENAME"),
            "{e}"
        );
    }

    #[test]
    fn verilator_builds_once_per_content() {
        let main = "#include \"Vcounter.h\"\n#include <cstdio>\n\
                    int main() {\n    Vcounter top;\n\
                    for (int i = 0; i < 6; i++) { top.clock = i & 1; top.eval(); }\n\
                    std::printf(\"%d\\n\", (int)top.q);\n    return 0;\n}\n";
        let files = [("counter.v", COUNTER), ("main.cpp", main)];
        let exe = verilator_build("tools-test-", "counter", &files, false).unwrap();
        let out = run(&mut Command::new(&exe), "counter harness").unwrap();
        assert_eq!(out.trim(), "3");
        assert_eq!(
            verilator_build("tools-test-", "counter", &files, false),
            Ok(exe)
        );
    }

    #[test]
    fn yosys_synthesises_for_ice40_and_refuses_a_latch() {
        let dir = work_dir("tools-test", "yosys").unwrap();
        let latch = "module latch(input wire en, input wire d, output reg q);\n\
                     always @* if (en) q = d;\nendmodule\n";
        stage(&dir, &[("counter.v", COUNTER), ("latch.v", latch)]).unwrap();
        let log = yosys_synth_ice40(&dir, "counter", "counter.v").unwrap();
        assert!(log.contains("SB_DFF"), "{log}");
        assert!(yosys_synth_ice40(&dir, "latch", "latch.v").is_err());
    }
}
