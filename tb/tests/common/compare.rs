// SPDX-License-Identifier: MIT OR Apache-2.0
//! Comparing a block with its model row by row: the first mismatching cycle of a rust-hdl
//! run, and an Icarus replay that returns the outputs of every cycle.

use proptest::test_runner::TestCaseError;

/// The first cycle at which `got` and `want` differ, with its inputs, as an error.
pub fn first_mismatch<I: std::fmt::Debug, O: PartialEq + std::fmt::Debug>(
    stim: &[I],
    got: &[O],
    want: &[O],
) -> Result<(), TestCaseError> {
    proptest::prop_assert_eq!(got.len(), want.len());
    if let Some(c) = (0..got.len()).find(|&c| got[c] != want[c]) {
        let from = c.saturating_sub(3);
        return Err(TestCaseError::fail(format!(
            "cycle {c}: got {:?}, golden {:?}\ninputs {from}..={c}: {:?}",
            got[c],
            want[c],
            &stim[from..=c]
        )));
    }
    Ok(())
}

/// Replays `vectors` (one row of input values per cycle, in the order of `inputs`) through
/// `verilog` (top module `top`) in Icarus, under `target/<suite>/<top>/`: inputs applied
/// before each rising edge, outputs (in the order of `outputs`) read 1 ns after it. Returns
/// one row of outputs per cycle, for the caller to compare with the model.
pub fn icarus_rows(
    suite: &str,
    top: &str,
    verilog: &str,
    inputs: &[(&str, usize)],
    outputs: &[(&str, usize)],
    vectors: &[Vec<u64>],
) -> Vec<Vec<u64>> {
    let dir = tools::work_dir(suite, top).unwrap();
    let decl =
        |kind: &str, (name, w): &(&str, usize)| format!("    {kind} [{}:0] {name};\n", w - 1);
    let mut tb = String::from("module tb;\n    reg clock;\n");
    tb.extend(inputs.iter().map(|p| decl("reg", p)));
    tb.extend(outputs.iter().map(|p| decl("wire", p)));
    tb.push_str("    integer fd, got;\n");
    let ports: Vec<String> = std::iter::once("clock")
        .chain(inputs.iter().chain(outputs).map(|p| p.0))
        .map(|n| format!(".{n}({n})"))
        .collect();
    tb.push_str(&format!("    {top} dut({});\n", ports.join(", ")));
    let fmt = |n: usize| vec!["%h"; n].join(" ");
    let names = |ps: &[(&str, usize)]| ps.iter().map(|p| p.0).collect::<Vec<_>>().join(", ");
    tb.push_str(&format!(
        "    initial begin\n        clock = 0;\n        fd = $fopen(\"vectors.txt\", \"r\");\n\
         \x20       got = $fscanf(fd, \"{}\\n\", {});\n\
         \x20       while (got == {}) begin\n\
         \x20           #5 clock = 1;\n\
         \x20           #1 $display(\"{}\", {});\n\
         \x20           #4 clock = 0;\n\
         \x20           got = $fscanf(fd, \"{}\\n\", {});\n\
         \x20       end\n        $finish;\n    end\nendmodule\n",
        fmt(inputs.len()),
        names(inputs),
        inputs.len(),
        fmt(outputs.len()),
        names(outputs),
        fmt(inputs.len()),
        names(inputs),
    ));
    std::fs::write(dir.join("tb.v"), tb).unwrap();
    std::fs::write(dir.join(format!("{top}.v")), verilog).unwrap();
    let rows: String = vectors
        .iter()
        .map(|v| {
            let cells: Vec<String> = v.iter().map(|x| format!("{x:x}")).collect();
            cells.join(" ") + "\n"
        })
        .collect();
    std::fs::write(dir.join("vectors.txt"), rows).unwrap();
    let v = format!("{top}.v");
    tools::iverilog(&dir, &[], &["tb.v", &v], "tb.vvp").unwrap();
    let text = tools::vvp(&dir, "tb.vvp", &[]).unwrap();
    let rows: Vec<Vec<u64>> = text
        .lines()
        .filter(|l| !l.is_empty() && !l.contains("$finish"))
        .map(|l| {
            l.split_whitespace()
                .map(|x| u64::from_str_radix(x, 16).unwrap_or_else(|_| panic!("{l}")))
                .collect()
        })
        .collect();
    assert_eq!(rows.len(), vectors.len(), "vvp output:\n{text}");
    rows
}

/// Assert that the rows Icarus gave (`got`) equal the model's (`want`), cycle by cycle.
pub fn compare_rows(block: &str, got: &[Vec<u64>], want: &[Vec<u64>]) {
    for (c, (g, w)) in got.iter().zip(want).enumerate() {
        assert_eq!(g, w, "{block}: Icarus differs from golden at cycle {c}");
    }
}
