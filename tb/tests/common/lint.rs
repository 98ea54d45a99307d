// SPDX-License-Identifier: MIT OR Apache-2.0
//! Verilator lint of one block's Verilog with documented waivers.

/// `verilator --lint-only -Wall` on `verilog` (top module `top`), in
/// `target/block_lint/<top>-<hash>/` from a file of its own per process and call (as
/// [`tools::lint_verilog`]), with DECLFILENAME waived (rust-hdl emits every sub-module into
/// the one file) and the given `(rule, message pattern)` waivers, each for a reason the
/// caller documents; panics on any other warning.
pub fn lint_with_waivers(top: &str, verilog: &str, waivers: &[(&str, &str)]) {
    static CALLS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let file = format!("{top}-{}-{call}.v", std::process::id());
    let mut vlt = format!("`verilator_config\nlint_off -rule DECLFILENAME -file \"*{file}\"\n");
    for (rule, pattern) in waivers {
        vlt += &format!("lint_off -rule {rule} -file \"*{file}\" -match \"{pattern}\"\n");
    }
    let dir = tools::work_dir(
        "block_lint",
        &format!("{top}-{:016x}", tools::content_hash(&[verilog, &vlt])),
    )
    .unwrap();
    let waiver_file = format!("{top}-{}-{call}.vlt", std::process::id());
    tools::stage(&dir, &[(&file, verilog), (&waiver_file, &vlt)]).unwrap();
    if let Err(e) = tools::verilator_lint(&dir, top, &[&waiver_file, &file]) {
        panic!("{e}");
    }
}

/// The waivers of the correctors' Verilog, as for the shipped `encspeed_ecc`
/// (`hdl/src/emit/lint/ecc.vlt`): rust-hdl's `bit_cast` masks its operand at the
/// target width (`count & 64'hff…ff` on a narrower `count`: WIDTH), and the correctors
/// sequence their arithmetic blocks from their own state, never reading a block's `busy`.
pub const CORRECTOR_WAIVERS: &[(&str, &str)] = &[
    ("WIDTH", "*Operator AND expects*"),
    ("WIDTH", "*Assign RHS's AND generates*"),
    ("UNUSEDSIGNAL", "*corr$busy*"),
    ("UNUSEDSIGNAL", "*speed$busy*"),
    ("UNUSEDSIGNAL", "*ecc$busy*"),
];
