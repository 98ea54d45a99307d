//! `SineRom` and `EccCorrector` against their bit-true models (`golden::sine_rom`,
//! `golden::ecc_corrector`), every cycle: the rust-hdl simulation (direct drive) on proptest
//! stimuli with random K, and the emitted Verilog in Icarus Verilog (a self-checking replay
//! bench written under `target/` at test time, ending in one `RESULT PASS`/`RESULT FAIL`
//! line that the test asserts).
//!
//! Stimuli: segments of 16..256 cycles, each with its own request rate (none, some, every
//! cycle), positions mostly within 0..K and sometimes anywhere in A bits (out of contract,
//! still defined), ΔM and E_reg random with their extremes, and random resets.

mod common;

use common::SplitMix;
use golden::ecc_corrector::{EccCorrector as EccModel, EccInputs, EccOutputs, NC_BITS};
use golden::sine_rom::SineRom as RomModel;
use hdl::{ecc_corrector_verilog, sine_rom_verilog, EccCorrector, SineRom};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn edge<T: Block>(uut: &mut T, clock: impl Fn(&mut T, bool)) {
    clock(uut, false);
    assert!(simulate(uut, 100), "design did not settle");
    clock(uut, true);
    assert!(simulate(uut, 100), "design did not settle");
}

fn sext(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

/// A reproducible stimulus of `len` cycles for K = `lines`, A = `a` from `seed`.
fn stimulus(seed: u64, lines: u32, a: u32, len: usize) -> Vec<EccInputs> {
    let mut rng = SplitMix(seed);
    let amask = (1u64 << a) - 1;
    let k = u64::from(lines);
    let pos = |rng: &mut SplitMix| {
        if rng.next().is_multiple_of(20) {
            rng.next() & amask
        } else {
            [0, k - 1, rng.next() % k, rng.next() % k][(rng.next() % 4) as usize]
        }
    };
    let mut out = Vec::with_capacity(len);
    let (mut rate, mut left) = (0u64, 0u64);
    while out.len() < len {
        if left == 0 {
            left = 16 + rng.next() % 240;
            rate = [0, 100, 500, 1000][(rng.next() % 4) as usize];
        }
        left -= 1;
        let delta_m = match rng.next() % 8 {
            0 => -(1 << 23),
            1 => (1 << 23) - 1,
            2 => (rng.next() % 5) as i64 - 2,
            _ => sext(rng.next() & 0xff_ffff, 24),
        };
        let e_coef = match rng.next() % 6 {
            0 => -32768,
            1 => 32767,
            2 => 15576,
            _ => sext(rng.next() & 0xffff, 16),
        };
        out.push(EccInputs {
            reset: rng.next().is_multiple_of(60),
            start: rng.next() % 1000 < rate,
            delta_m,
            m_a: pos(&mut rng),
            m_b: pos(&mut rng),
            m0: pos(&mut rng),
            e_coef,
        });
    }
    out
}

fn rom_step<const A: usize, const D: usize>(uut: &mut SineRom<A, D>, c: &EccInputs) -> i64 {
    uut.m.next = c.m_a.into();
    uut.m0.next = c.m0.into();
    edge(uut, |u, v| u.clock.next = Clock { clk: v });
    sext(uut.data.val().to_u64(), D as u32)
}

fn ecc_step<const A: usize>(uut: &mut EccCorrector<A>, c: &EccInputs) -> EccOutputs {
    uut.reset.next = c.reset;
    uut.start.next = c.start;
    uut.delta_m.next = ((c.delta_m as u64) & 0xff_ffff).into();
    uut.m_a.next = c.m_a.into();
    uut.m_b.next = c.m_b.into();
    uut.m0.next = c.m0.into();
    uut.e_coef.next = ((c.e_coef as u64) & 0xffff).into();
    edge(uut, |u, v| u.clock.next = Clock { clk: v });
    EccOutputs {
        n_c: sext(uut.n_c.val().to_u64(), NC_BITS),
        valid: uut.valid.val(),
    }
}

fn compare_rom<const A: usize, const D: usize>(
    lines: u32,
    cycles: &[EccInputs],
) -> Result<(), TestCaseError> {
    let mut uut = SineRom::<A, D>::new(lines);
    uut.connect_all();
    let mut model = RomModel::new(lines, A as u32, D as u32);
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(c.m_a, c.m0);
        prop_assert_eq!(
            rom_step(&mut uut, c),
            want,
            "K {} edge {} {:?}",
            lines,
            k,
            c
        );
    }
    Ok(())
}

fn compare_ecc<const A: usize>(lines: u32, cycles: &[EccInputs]) -> Result<(), TestCaseError> {
    let mut uut = EccCorrector::<A>::new(lines);
    uut.connect_all();
    let mut model = EccModel::new(lines, A as u32);
    for (k, c) in cycles.iter().enumerate() {
        let want = model.step(*c);
        prop_assert_eq!(
            ecc_step(&mut uut, c),
            want,
            "K {} edge {} {:?}",
            lines,
            k,
            c
        );
    }
    Ok(())
}

fn some_k(pick: u32, max: u32) -> u32 {
    match pick % 4 {
        0 => max,
        1 => 1000.min(max),
        _ => 2 + pick % (max - 1),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn sine_rom_rust_hdl_equals_model(seed in any::<u64>(), pick in any::<u32>(),
                                      len in 100usize..800) {
        let lines = some_k(pick, 1024);
        compare_rom::<10, 16>(lines, &stimulus(seed, lines, 10, len))?;
        let small = 2 + pick % 3;
        compare_rom::<2, 4>(small, &stimulus(seed, small, 2, 100))?;
    }

    #[test]
    fn ecc_corrector_rust_hdl_equals_model(seed in any::<u64>(), pick in any::<u32>(),
                                           len in 100usize..800) {
        let lines = some_k(pick, 1024);
        compare_ecc::<10>(lines, &stimulus(seed, lines, 10, len))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 30, ..ProptestConfig::default() })]

    /// Other widths: a 12-bit, 24-bit table, and the corrector at A = 12 (K = 4096, 2500).
    #[test]
    fn other_widths_rust_hdl_equal_model(seed in any::<u64>(), pick in any::<u32>()) {
        let lines = some_k(pick, 4096);
        compare_rom::<12, 24>(lines, &stimulus(seed, lines, 12, 300))?;
        compare_ecc::<12>(lines, &stimulus(seed, lines, 12, 300))?;
    }
}

/// A self-checking replay bench for `module` with the given input and output ports (name,
/// width): each line of `vectors.txt` holds the inputs and then the outputs expected after
/// the edge, in hex; counts the cycles with `count_port` high; ends with one `RESULT` line.
fn bench(
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

/// Writes the Verilog, the bench and the vectors under `target/sine_rom_ecc/<dir>`, runs
/// Icarus and asserts the PASS line (all cycles, `counted` cycles with the count port high).
fn icarus(dir: &str, module: &str, verilog: String, tb: String, vectors: &str, counted: usize) {
    let dir = common::target_dir().join("sine_rom_ecc").join(dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join(format!("{module}.v")), verilog).unwrap();
    std::fs::write(dir.join(format!("{module}_tb.v")), tb).unwrap();
    std::fs::write(dir.join("vectors.txt"), vectors).unwrap();
    let text = common::icarus_run(
        &dir,
        &[],
        &[format!("{module}_tb.v"), format!("{module}.v")],
    );
    let result = text
        .lines()
        .find(|l| l.starts_with("RESULT"))
        .unwrap_or_else(|| panic!("no RESULT line from the bench:\n{text}"));
    let cycles = vectors.lines().count();
    assert_eq!(
        result,
        format!("RESULT PASS {cycles} cycles {counted} counted"),
        "\n{text}"
    );
}

/// Many stimulus cases back to back, a reset first.
fn long_stimulus(seed: u64, lines: u32, a: u32, cases: u64) -> Vec<EccInputs> {
    let mut out = vec![];
    for i in 0..cases {
        let mut s = stimulus(seed.wrapping_add(i), lines, a, 500);
        s[0].reset = true;
        out.extend(s);
    }
    out
}

fn rom_icarus<const A: usize, const D: usize>(lines: u32, seed: u64) {
    let mut model = RomModel::new(lines, A as u32, D as u32);
    let (mut vectors, mut nonzero) = (String::new(), 0);
    let dmask = (1u64 << D) - 1;
    for c in long_stimulus(seed, lines, A as u32, 40) {
        let d = model.step(c.m_a, c.m0);
        nonzero += usize::from(d != 0);
        vectors += &format!("{:x} {:x} {:x}\n", c.m_a, c.m0, (d as u64) & dmask);
    }
    let tb = bench("sine_rom", &[("m", A), ("m0", A)], &[("data", D)], "data");
    let v = sine_rom_verilog::<A, D>(lines, "sine_rom");
    let dir = format!("rom_a{A}_d{D}_k{lines}");
    icarus(&dir, "sine_rom", v, tb, &vectors, nonzero);
}

fn ecc_icarus<const A: usize>(lines: u32, seed: u64) {
    let mut model = EccModel::new(lines, A as u32);
    let (mut vectors, mut valids) = (String::new(), 0);
    let nmask = (1u64 << NC_BITS) - 1;
    for c in long_stimulus(seed, lines, A as u32, 40) {
        let o = model.step(c);
        valids += usize::from(o.valid);
        vectors += &format!(
            "{:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x} {:x}\n",
            u8::from(c.reset),
            u8::from(c.start),
            (c.delta_m as u64) & 0xff_ffff,
            c.m_a,
            c.m_b,
            c.m0,
            (c.e_coef as u64) & 0xffff,
            (o.n_c as u64) & nmask,
            u8::from(o.valid)
        );
    }
    assert!(valids > 1000, "too few results in the stimulus");
    let tb = bench(
        "ecc_corrector",
        &[
            ("reset", 1),
            ("start", 1),
            ("delta_m", 24),
            ("m_a", A),
            ("m_b", A),
            ("m0", A),
            ("e_coef", 16),
        ],
        &[("n_c", NC_BITS as usize), ("valid", 1)],
        "valid",
    );
    let v = ecc_corrector_verilog::<A>(lines, "ecc_corrector");
    let dir = format!("ecc_a{A}_k{lines}");
    icarus(&dir, "ecc_corrector", v, tb, &vectors, valids);
}

#[test]
fn sine_rom_emitted_verilog_in_icarus_equals_model() {
    rom_icarus::<10, 16>(1000, 0x51_1000);
    rom_icarus::<10, 16>(1024, 0x51_1024);
    rom_icarus::<2, 4>(3, 0x51_0003);
    rom_icarus::<12, 24>(2500, 0x51_2500);
}

#[test]
fn ecc_corrector_emitted_verilog_in_icarus_equals_model() {
    ecc_icarus::<10>(1024, 0xec_1024);
    ecc_icarus::<10>(1000, 0xec_1000);
}
