// SPDX-License-Identifier: MIT OR Apache-2.0
//! Shared by the block benches (one test binary per subsystem, `tb/tests/<subsystem>/`, each
//! including this module as `common`): stimuli, clock edges, the proptest configuration and
//! Icarus replay benches (running the tools, and where their work goes, is the `tools`
//! crate's). `compare` replays rows of vectors in Icarus and compares them with the model's,
//! `lint` lints a block's Verilog with waivers, `knobs` is the front end's stimulus
//! generator and `steps` the baseline counters' stream of encoder steps.

// Each test binary includes this module and uses a subset of it.
#![allow(dead_code, unused_imports)]

pub mod compare;
pub mod knobs;
pub mod lint;
pub mod steps;

pub use compare::{compare_rows, first_mismatch, icarus_rows};
pub use lint::{lint_with_waivers, CORRECTOR_WAIVERS};

use proptest::test_runner::{Config as ProptestConfig, FileFailurePersistence};
use rust_hdl::prelude::{simulate, Block};
use std::path::Path;

/// The proptest configuration of the block benches: `cases` cases, failures persisted in
/// `<bench>.proptest-regressions` beside the bench's source file (proptest's default,
/// `SourceParallel`, would find the subsystem's `main.rs` and use
/// `tb/tests/proptest-regressions/<bench>.txt` instead).
pub fn proptest_config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        ..ProptestConfig::default()
    }
}

/// splitmix64: a fixed, reproducible stream of random numbers for the Icarus runs (each
/// test adds its own operand shapes on top of `next`).
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        golden::splitmix::next(&mut self.0)
    }
}

/// One rising clock edge of a directly driven rust-hdl block: `clock(uut, level)` sets the
/// block's clock input.
pub fn edge<T: Block>(uut: &mut T, clock: impl Fn(&mut T, bool)) {
    clock(uut, false);
    assert!(simulate(uut, 100), "design did not settle");
    clock(uut, true);
    assert!(simulate(uut, 100), "design did not settle");
}

/// A self-checking replay bench for `module` with the given input and output ports (name,
/// width): each line of `vectors.txt` holds the inputs and then the outputs expected after
/// the edge, in hex; counts the cycles with `count_port` high; ends with one `RESULT` line.
pub fn replay_bench(
    module: &str,
    inputs: &[(&str, usize)],
    outputs: &[(&str, usize)],
    count_port: &str,
) -> String {
    let decl = |(n, w): &(&str, usize), kind: &str, prefix: &str| {
        if *w == 1 {
            format!("    {kind} {prefix}{n};\n")
        } else {
            format!("    {kind} [{}:0] {prefix}{n};\n", w - 1)
        }
    };
    let mut v = format!("module {module}_tb;\n    reg clock = 1'b0;\n");
    for p in inputs {
        v += &decl(p, "reg", "");
        v += &decl(p, "reg", "v_");
    }
    for p in outputs {
        v += &decl(p, "wire", "");
        v += &decl(p, "reg", "e_");
    }
    v += "    integer fd, n, cycles, errors, counted;\n";
    let ports: Vec<String> = std::iter::once("clock".to_string())
        .chain(inputs.iter().chain(outputs).map(|p| p.0.to_string()))
        .map(|n| format!(".{n}({n})"))
        .collect();
    v += &format!("    {module} uut({});\n", ports.join(", "));
    let fields = inputs.len() + outputs.len();
    let fmt = vec!["%h"; fields].join(" ");
    let args: Vec<String> = inputs
        .iter()
        .map(|p| format!("v_{}", p.0))
        .chain(outputs.iter().map(|p| format!("e_{}", p.0)))
        .collect();
    let scan = format!("n = $fscanf(fd, \"{fmt}\\n\", {});", args.join(", "));
    let apply: String = inputs
        .iter()
        .map(|p| format!(" {0} = v_{0};", p.0))
        .collect();
    let differ: Vec<String> = outputs
        .iter()
        .map(|p| format!("{0} !== e_{0}", p.0))
        .collect();
    v += &format!(
        r#"    initial begin
        cycles = 0; errors = 0; counted = 0;
        fd = $fopen("vectors.txt", "r");
        if (fd == 0) begin
            $display("RESULT FAIL cannot open vectors.txt");
            $finish;
        end
        {scan}
        while (n == {fields}) begin
           {apply}
            #5 clock = 1'b1;
            #1;
            if ({differ}) begin
                if (errors < 10) $display("MISMATCH cycle %0d", cycles);
                errors = errors + 1;
            end
            if ({count_port} !== 1'b0) counted = counted + 1;
            cycles = cycles + 1;
            #4 clock = 1'b0;
            {scan}
        end
        $fclose(fd);
        if (errors == 0 && cycles > 0)
            $display("RESULT PASS %0d cycles %0d counted", cycles, counted);
        else
            $display("RESULT FAIL %0d cycles %0d mismatches", cycles, errors);
        $finish;
    end
endmodule
"#,
        differ = differ.join(" || ")
    );
    v
}

/// Replay `vectors` through `verilog` (top `module`) with the bench `tb` from
/// [`replay_bench`] in Icarus, under `target/<suite>/<dir>/`, and assert the bench passed on
/// every line and counted `counted` cycles with its count port non-zero.
pub fn replay(
    suite: &str,
    dir: &str,
    module: &str,
    verilog: &str,
    tb: &str,
    vectors: &str,
    counted: usize,
) {
    let dir = tools::work_dir(suite, dir).unwrap();
    let (v, v_tb) = (format!("{module}.v"), format!("{module}_tb.v"));
    tools::stage(
        &dir,
        &[(&v, verilog), (&v_tb, tb), ("vectors.txt", vectors)],
    )
    .unwrap();
    assert_bench_passes(
        &dir,
        &[],
        &[&v_tb, &v],
        vectors,
        &format!("{counted} counted"),
    );
}

/// Compile the self-checking bench `sources` in `dir` (`iverilog` with `args`, not one
/// warning), run it in `vvp`, and assert that its `RESULT` line reads `RESULT PASS <n> cycles
/// <tail>`, `n` being the lines of `vectors`.
pub fn assert_bench_passes(dir: &Path, args: &[&str], sources: &[&str], vectors: &str, tail: &str) {
    tools::iverilog(dir, args, sources, "tb.vvp").unwrap();
    let text = tools::vvp(dir, "tb.vvp", &[]).unwrap();
    let result = text
        .lines()
        .find(|l| l.starts_with("RESULT"))
        .unwrap_or_else(|| panic!("no RESULT line from the bench:\n{text}"));
    let cycles = vectors.lines().count();
    assert_eq!(
        result,
        format!("RESULT PASS {cycles} cycles {tail}"),
        "\n{text}"
    );
}
