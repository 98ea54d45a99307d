//! Helpers for the blocks' unit tests.

/// `verilator --lint-only -Wall` on `verilog` (top module `top`), written under
/// `target/block_lint/`; panics on any warning other than DECLFILENAME (rust-hdl names
/// sub-modules by path, so they cannot match the file).
pub(crate) fn verilator_lint(top: &str, verilog: &str) {
    let target = match std::env::var_os("CARGO_TARGET_DIR") {
        Some(d) => std::path::PathBuf::from(d),
        None => std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../target")),
    };
    let dir = target.join("block_lint").join(format!(
        "{top}-{:016x}",
        verilog
            .bytes()
            .fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ u64::from(b))
                .wrapping_mul(0x100_0000_01b3))
    ));
    std::fs::create_dir_all(&dir).unwrap();
    // A file of its own per call: tests (and test processes) lint the same design at once,
    // and one must never read a file another is rewriting.
    static CALLS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let file = dir.join(format!("{top}-{}-{call}.v", std::process::id()));
    std::fs::write(&file, verilog).unwrap();
    let out = std::process::Command::new("verilator")
        .args([
            "--lint-only",
            "-Wall",
            "-Wno-DECLFILENAME",
            "--top-module",
            top,
        ])
        .arg(&file)
        .output()
        .expect("cannot run verilator");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.status.success() && !text.contains("%Warning") && !text.contains("%Error"),
        "verilator --lint-only -Wall on {}:\n{text}",
        file.display()
    );
}
