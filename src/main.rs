//! `encspeed`: generate the encoder speed IP, simulate it with waveforms, benchmark it.
//!
//! Exit codes: 0 success, 1 a failed run (tool missing, mismatch), 2 bad parameters or usage.

use clap::{Args, Parser, Subcommand};
use golden::bittrue::CoreInputs;
use golden::params::{Params, Spec};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[derive(Parser)]
#[command(
    name = "encspeed",
    version,
    about = "Verilog IP generator for incremental-encoder speed measurement (Rairán's synchronised estimator)"
)]
struct Cli {
    #[command(subcommand)]
    command: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// Emit encspeed_core.v and its manifest encspeed_core.toml.
    Generate {
        #[command(flatten)]
        spec: SpecArgs,
        /// Output directory.
        #[arg(long, default_value = "generated")]
        out: PathBuf,
    },
    /// Run a scenario through the rust-hdl design, check it against the golden model on every
    /// cycle, and write a VCD of every signal.
    Simulate {
        #[command(flatten)]
        spec: SpecArgs,
        /// Named scenario (see --list).
        #[arg(long, conflicts_with = "motion")]
        scenario: Option<String>,
        /// Custom motion, speeds in ω_lim and times in dt: e.g. `rest:2,ramp:0:3:10,hold:3:5`
        /// (segments hold:R:N, ramp:R0:R1:N, sine:MEAN:AMP:PERIOD:N, rest:N).
        #[arg(long)]
        motion: Option<String>,
        /// VCD of the rust-hdl simulation.
        #[arg(long, default_value = "target/waves/encspeed.vcd")]
        vcd: PathBuf,
        /// Also run the emitted Verilog in Verilator, check it, and write its VCD here.
        #[arg(long)]
        verilator_vcd: Option<PathBuf>,
        /// List the named scenarios and exit.
        #[arg(long)]
        list: bool,
    },
    /// Measure simulation speed (cycles/s) of the golden model, rust-hdl and Verilator.
    Bench {
        #[command(flatten)]
        spec: SpecArgs,
        /// Cycles for the golden model and Verilator (rust-hdl runs a tenth of them).
        #[arg(long, default_value_t = 20_000_000)]
        cycles: u64,
    },
    /// Synthesise the core with yosys (synth_ice40) and place and route it with
    /// nextpnr-ice40: logic cells, I/O and maximum clock frequency (a benchmark).
    Synth {
        #[command(flatten)]
        spec: SpecArgs,
        /// nextpnr-ice40 device option, e.g. hx8k, up5k, lp8k.
        #[arg(long, default_value = "hx8k")]
        device: String,
        /// Package, e.g. ct256 (hx8k), sg48 (up5k).
        #[arg(long, default_value = "ct256")]
        package: String,
    },
    /// Measured and model gain/phase of a speed estimator (CSV, SVG).
    ///
    /// The paper's VCO experiment in simulation:
    /// n(t) = rpm·(1 + amplitude·sin 2πft) drives the plant and the golden estimator; the
    /// single DFT bin at f of the held output over the input gives gain and phase, beside
    /// the small-signal model. CSV on stdout (and --csv), a summary on stderr, and an SVG
    /// figure (--svg). See docs/frequency-response.md.
    Bode {
        /// pc (pulse count), et (elapsed time), n3 (Rairán, bit-true core) or mt (M/T).
        #[arg(long, value_parser = ["pc", "et", "n3", "mt"])]
        estimator: String,
        /// Lines of the disc.
        #[arg(long)]
        lines: u32,
        /// Edges counted per line, 1, 2 or 4 (R = lines·edges) [default 4; n3: 1].
        #[arg(long)]
        edges: Option<u32>,
        /// Mean speed, r/min.
        #[arg(long, allow_negative_numbers = true)]
        rpm: f64,
        /// Control sample time T_s, s (for n3 also dt).
        #[arg(long, allow_negative_numbers = true)]
        ts_s: f64,
        /// Clock of the ET/M/T timestamps and of the n3 core, Hz [default 100e6; n3: 10e6].
        #[arg(long, allow_negative_numbers = true)]
        clock_hz: Option<f64>,
        /// Modulation depth ñ/n̄ [default 0.02; n3: 0.2].
        #[arg(long, allow_negative_numbers = true)]
        amplitude: Option<f64>,
        /// Relative detuning ε of the simulated mean speed [default √2·10⁻³].
        #[arg(long, allow_negative_numbers = true)]
        detune: Option<f64>,
        /// Lowest frequency, Hz [default 1/(1000 T_s)].
        #[arg(long, allow_negative_numbers = true)]
        fmin: Option<f64>,
        /// Highest frequency, Hz, below 1/(2 T_s) [default 0.45/T_s].
        #[arg(long, allow_negative_numbers = true)]
        fmax: Option<f64>,
        /// Number of frequencies, log-spaced.
        #[arg(long, default_value_t = 25)]
        points: u32,
        /// Least number of samples in each analysis window [default 4000].
        #[arg(long)]
        min_samples: Option<u32>,
        /// Write the CSV here too.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Draw the Bode figure (SVG) here.
        #[arg(long)]
        svg: Option<PathBuf>,
        /// Caption of the figure [default: the operating point].
        #[arg(long)]
        title: Option<String>,
    },
}

/// Generation parameters: a TOML file (fields of `Spec`) and/or options; options win.
#[derive(Args, Clone)]
struct SpecArgs {
    /// TOML file with any of: clock_hz, lines, dt_cycles, counter_bits, timeout_s.
    #[arg(long)]
    config: Option<PathBuf>,
    /// Clock frequency, Hz [default 100e6].
    #[arg(long)]
    clock_hz: Option<f64>,
    /// Encoder lines per revolution [default 1024].
    #[arg(long)]
    lines: Option<u32>,
    /// Nominal dt, clock cycles (>= 2) [default 100000].
    #[arg(long)]
    dt_cycles: Option<u64>,
    /// Counter width, bits (8..=32) [default 24].
    #[arg(long)]
    counter_bits: Option<u32>,
    /// Zero-speed timeout, s [default 1].
    #[arg(long)]
    timeout_s: Option<f64>,
}

/// `Spec` with every field optional, for configuration files.
#[derive(serde::Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct SpecFile {
    clock_hz: Option<f64>,
    lines: Option<u32>,
    dt_cycles: Option<u64>,
    counter_bits: Option<u32>,
    timeout_s: Option<f64>,
}

impl SpecArgs {
    fn params(&self) -> Result<Params, String> {
        let file = match &self.config {
            Some(path) => {
                let text = std::fs::read_to_string(path)
                    .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
                toml::from_str::<SpecFile>(&text).map_err(|e| format!("{}: {e}", path.display()))?
            }
            None => SpecFile::default(),
        };
        let d = Spec::default();
        let spec = Spec {
            clock_hz: self.clock_hz.or(file.clock_hz).unwrap_or(d.clock_hz),
            lines: self.lines.or(file.lines).unwrap_or(d.lines),
            dt_cycles: self.dt_cycles.or(file.dt_cycles).unwrap_or(d.dt_cycles),
            counter_bits: self
                .counter_bits
                .or(file.counter_bits)
                .unwrap_or(d.counter_bits),
            timeout_s: self.timeout_s.or(file.timeout_s).unwrap_or(d.timeout_s),
        };
        Params::new(spec).map_err(|e| e.to_string())
    }
}

fn fail(code: u8, msg: impl std::fmt::Display) -> ExitCode {
    eprintln!("encspeed: {msg}");
    ExitCode::from(code)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Cmd::Generate { spec, out } => spec
            .params()
            .map_err(|e| (2, e))
            .and_then(|p| generate(&p, &out)),
        Cmd::Simulate {
            spec,
            scenario,
            motion,
            vcd,
            verilator_vcd,
            list,
        } => {
            if list {
                for s in tb::scenarios::all() {
                    println!("{:<16} {}", s.name, s.description);
                }
                Ok(())
            } else {
                spec.params().map_err(|e| (2, e)).and_then(|p| {
                    simulate(
                        &p,
                        scenario.as_deref(),
                        motion.as_deref(),
                        &vcd,
                        verilator_vcd.as_deref(),
                    )
                })
            }
        }
        Cmd::Bench { spec, cycles } => spec
            .params()
            .map_err(|e| (2, e))
            .and_then(|p| bench(&p, cycles)),
        Cmd::Synth {
            spec,
            device,
            package,
        } => spec
            .params()
            .map_err(|e| (2, e))
            .and_then(|p| synth(&p, &device, &package)),
        Cmd::Bode {
            estimator,
            lines,
            edges,
            rpm,
            ts_s,
            clock_hz,
            amplitude,
            detune,
            fmin,
            fmax,
            points,
            min_samples,
            csv,
            svg,
            title,
        } => {
            let mut spec = match estimator.parse() {
                Ok(e) => golden::freqresp::BodeSpec::new(e, lines, rpm, ts_s),
                Err(e) => return fail(2, format!("bode: --{e}")),
            };
            spec.edges = edges.unwrap_or(spec.edges);
            spec.clock_hz = clock_hz.unwrap_or(spec.clock_hz);
            spec.amplitude = amplitude.unwrap_or(spec.amplitude);
            spec.detune = detune.unwrap_or(spec.detune);
            spec.min_samples = min_samples.unwrap_or(spec.min_samples);
            bode(
                spec,
                (
                    fmin.unwrap_or(1e-3 / ts_s),
                    fmax.unwrap_or(0.45 / ts_s),
                    points,
                ),
                csv.as_deref(),
                svg.as_deref(),
                title,
            )
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err((code, msg)) => fail(code, msg),
    }
}

type Outcome = Result<(), (u8, String)>;

fn generate(p: &Params, out: &Path) -> Outcome {
    let e = hdl::emit_core(p);
    let write = |name: &str, text: &str| {
        std::fs::create_dir_all(out)
            .and_then(|_| std::fs::write(out.join(name), text))
            .map_err(|e| (1, format!("cannot write {}: {e}", out.join(name).display())))
    };
    write("encspeed_core.v", &e.verilog)?;
    write("encspeed_core.toml", &e.manifest)?;
    println!(
        "wrote {} and {} ({}-bit counters, dt = {} cycles, ω_lim = {} rev/s)",
        out.join("encspeed_core.v").display(),
        out.join("encspeed_core.toml").display(),
        p.counter_bits(),
        p.dt_cycles(),
        p.omega_lim_rps()
    );
    Ok(())
}

fn simulate(
    p: &Params,
    scenario: Option<&str>,
    motion: Option<&str>,
    vcd: &Path,
    verilator_vcd: Option<&Path>,
) -> Outcome {
    let (name, segments) = match (scenario, motion) {
        (Some(n), None) => {
            let s = tb::scenarios::find(n).ok_or_else(|| {
                (
                    2,
                    format!("scenario `{n}` is unknown; `encspeed simulate --list` lists them"),
                )
            })?;
            (n.to_string(), s.segments().to_vec())
        }
        (None, Some(m)) => (
            "motion".to_string(),
            tb::scenarios::parse_motion(m).map_err(|e| (2, format!("motion: {e}")))?,
        ),
        _ => {
            return Err((
                2,
                "give --scenario NAME or --motion SEGMENTS (or --list)".into(),
            ))
        }
    };
    let profile = tb::scenarios::profile(&segments, p).map_err(|e| (2, format!("motion: {e}")))?;
    let inputs: Vec<CoreInputs> = tb::stimulus::from_profile(p, &profile, p.dt_cycles())
        .map_err(|e| (2, format!("motion: {e}")))?;
    let golden = tb::cosim::run_golden(p, &inputs);
    let hdl_out = tb::waves::simulate_to_vcd(p, &inputs, vcd)
        .map_err(|e| (1, format!("{}: {e}", vcd.display())))?;
    if let Some((k, e, g)) = tb::cosim::first_mismatch(&golden, &hdl_out) {
        return Err((
            1,
            format!("rust-hdl differs from the golden model at cycle {k}: {e:?} vs {g:?}"),
        ));
    }
    println!(
        "{name}: {} cycles; rust-hdl = golden on every cycle; VCD {}",
        inputs.len(),
        vcd.display()
    );
    if let Some(path) = verilator_vcd {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(|e| (1, e.to_string()))?;
        }
        let v = tb::verilator::Verilated::build(&hdl::emit_core(p).verilog).map_err(|e| (1, e))?;
        let out = v.run(&inputs, Some(path)).map_err(|e| (1, e))?;
        if let Some((k, e, g)) = tb::cosim::first_mismatch(&golden, &out) {
            return Err((
                1,
                format!("Verilator differs from the golden model at cycle {k}: {e:?} vs {g:?}"),
            ));
        }
        println!(
            "{name}: Verilator = golden on every cycle; VCD {}",
            path.display()
        );
    }
    let updates = golden.iter().filter(|o| o.update).count();
    let last = golden.last().copied().unwrap_or_default();
    println!(
        "{updates} updates; final Nep1 = {}, Ndt1 = {}, n3 = {:.6} ω_lim, true speed {:.6} ω_lim{}",
        last.nep,
        last.ndt,
        golden::ideal::n3(last.nep, last.ndt),
        profile.speed(profile.duration() - p.ts_s()) / p.omega_lim_rps(),
        if last.stalled { " (stalled)" } else { "" }
    );
    Ok(())
}

fn bench(p: &Params, cycles: u64) -> Outcome {
    // A square wave at 3.3 ω_lim: steady updates, the common case.
    let period = ((p.dt_cycles() as f64 / 3.3).round() as u64).max(2);
    let inputs = tb::stimulus::square_wave(period, 0, cycles as usize, p.dt_cycles());
    let t = Instant::now();
    let g = tb::cosim::run_golden(p, &inputs);
    let golden_rate = cycles as f64 / t.elapsed().as_secs_f64();
    let hdl_cycles = (cycles / 10) as usize;
    let t = Instant::now();
    let h = tb::cosim::run_hdl(p, &inputs[..hdl_cycles]);
    let hdl_rate = hdl_cycles as f64 / t.elapsed().as_secs_f64();
    if tb::cosim::first_mismatch(&g[..hdl_cycles], &h).is_some() {
        return Err((1, "rust-hdl differs from the golden model".into()));
    }
    let v = tb::verilator::Verilated::build(&hdl::emit_core(p).verilog).map_err(|e| (1, e))?;
    let verilator_rate = v.bench(cycles, period, p.dt_cycles()).map_err(|e| (1, e))?;
    println!(
        "configuration: {}-bit counters, dt = {} cycles, square wave of {period} cycles",
        p.counter_bits(),
        p.dt_cycles()
    );
    println!(
        "golden bit-true model        {:>12.0} cycles/s ({cycles} cycles)",
        golden_rate
    );
    println!(
        "rust-hdl direct drive        {:>12.0} cycles/s ({hdl_cycles} cycles)",
        hdl_rate
    );
    println!(
        "Verilator -O3 (emitted .v)   {:>12.0} cycles/s ({cycles} cycles)",
        verilator_rate
    );
    Ok(())
}

fn synth(p: &Params, device: &str, package: &str) -> Outcome {
    let dir = tb::target_dir().join("synth");
    std::fs::create_dir_all(&dir).map_err(|e| (1, e.to_string()))?;
    std::fs::write(dir.join("encspeed_core.v"), hdl::emit_core(p).verilog)
        .map_err(|e| (1, e.to_string()))?;
    let clock = dir.join("clock.py");
    std::fs::write(
        &clock,
        format!("ctx.addClock(\"clock\", {})\n", p.clock_hz() / 1e6),
    )
    .map_err(|e| (1, e.to_string()))?;
    let run = |cmd: &mut std::process::Command, what: &str| {
        tb::run_tool(cmd.current_dir(&dir), what).map_err(|e| (1, e))
    };
    run(
        std::process::Command::new("yosys").args([
            "-q",
            "-p",
            "read_verilog encspeed_core.v; synth_ice40 -top encspeed_core -json core.json",
        ]),
        "yosys",
    )?;
    let log = run(
        std::process::Command::new("nextpnr-ice40")
            .arg(format!("--{device}"))
            .args([
                "--package",
                package,
                "--json",
                "core.json",
                "--asc",
                "core.asc",
            ])
            .args([
                "--pcf-allow-unconstrained",
                "--timing-allow-fail",
                "--seed",
                "1",
                "--pre-pack",
                "clock.py",
            ]),
        "nextpnr-ice40",
    )?;
    // Utilisation is reported once (the line with a percentage); the routed Fmax is the
    // last frequency line.
    let tidy = |l: &str| {
        let l = l.trim();
        let l = l
            .strip_prefix("Info:")
            .or(l.strip_prefix("Warning:"))
            .unwrap_or(l);
        l.trim().to_string()
    };
    let first = |key: &str| {
        log.lines()
            .find(|l| l.contains(key) && l.contains('%'))
            .map(tidy)
    };
    let last = |key: &str| log.lines().rev().find(|l| l.contains(key)).map(tidy);
    let missing = |key: &str| (1, format!("no `{key}` in the nextpnr log"));
    println!(
        "device {device} {package}, {}-bit counters, clock constraint {} MHz",
        p.counter_bits(),
        p.clock_hz() / 1e6
    );
    for key in ["ICESTORM_LC:", "SB_IO:"] {
        println!("{}", first(key).ok_or_else(|| missing(key))?);
    }
    let key = "Max frequency for clock";
    println!("{}", last(key).ok_or_else(|| missing(key))?);
    Ok(())
}

/// `encspeed bode`: sweep, CSV on stdout (and `csv`), summary on stderr, SVG to `svg`.
fn bode(
    spec: golden::freqresp::BodeSpec,
    (fmin, fmax, points): (f64, f64, u32),
    csv: Option<&Path>,
    svg: Option<&Path>,
    title: Option<String>,
) -> Outcome {
    use golden::freqresp::{log_spaced, to_csv, Estimator, Experiment};
    let bad = |e: golden::freqresp::FreqRespError| (2, format!("bode: --{e}"));
    let exp = Experiment::new(spec).map_err(bad)?;
    let freqs = log_spaced(fmin, fmax, points).map_err(bad)?;
    // Every frequency is validated before anything runs.
    for &f in &freqs {
        exp.plan(f).map_err(bad)?;
    }
    let t = Instant::now();
    let points = exp.sweep(&freqs).map_err(bad)?;
    let text = to_csv(&points);
    print!("{text}");
    let write = |path: &Path, what: &str, bytes: &str| -> Outcome {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|e| (1, format!("{}: {e}", dir.display())))?;
        }
        std::fs::write(path, bytes)
            .map_err(|e| (1, format!("cannot write {what} {}: {e}", path.display())))
    };
    if let Some(path) = csv {
        write(path, "CSV", &text)?;
    }
    let s = exp.spec();
    let op = exp.operating_point();
    let r_name = if s.estimator == Estimator::N3 {
        format!("{} lines, r = {:.4} pulses/dt", s.lines, op.l())
    } else {
        format!(
            "R = {} ({}x{}), l = {:.4} tr./Ts",
            op.transitions_per_rev(),
            s.lines,
            s.edges,
            op.l()
        )
    };
    let caption = title.unwrap_or_else(|| {
        format!(
            "{}: {r_name}, {} r/min, Ts = {} ms",
            s.estimator.name().to_uppercase(),
            s.rpm,
            s.ts_s * 1e3
        )
    });
    if let Some(path) = svg {
        let others = exp.comparison_models();
        let fig = tb::freqresp::BodeFigure {
            title: caption.clone(),
            model: exp.model(),
            others: &others,
            measured: &points,
            fmin_hz: fmin / 1.25,
            fmax_hz: fmax * 1.25,
        };
        tb::freqresp::draw_svg(path, &fig).map_err(|e| (1, e))?;
    }
    let quarter = 0.25 / s.ts_s;
    let max_abs = |it: &mut dyn Iterator<Item = f64>| it.fold(0.0f64, |a, v| a.max(v.abs()));
    let upto = |m: &&golden::freqresp::Measurement| m.f_hz <= quarter * (1.0 + 1e-9);
    eprintln!(
        "{caption}: model {}; simulated {:.4} r/min, amplitude {} of it, T_e = {:.6e} s; \
         {} points in {:.1} s; max |phase error| {:.3} deg up to fs/4 ({:.3} deg overall), \
         max |gain error| {:.3} dB up to fs/4",
        exp.model().name(),
        op.speed_rpm(),
        s.amplitude,
        op.te_s(),
        points.len(),
        t.elapsed().as_secs_f64(),
        max_abs(&mut points.iter().filter(upto).map(|m| m.phase_error_deg())),
        max_abs(&mut points.iter().map(|m| m.phase_error_deg())),
        max_abs(&mut points.iter().filter(upto).map(|m| m.gain_error_db())),
    );
    Ok(())
}
