//! `encspeed`: generate the encoder speed IP, simulate it with waveforms, benchmark it.
//!
//! Exit codes: 0 success, 1 a failed run (tool missing, mismatch), 2 bad parameters or usage.

use clap::{Args, Parser, Subcommand};
use golden::params::{ParamError, Params, Spec};
use golden::top::core::CoreInputs;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

mod identify;

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
    /// Emit encspeed_core.v and its manifest encspeed_core.toml, encspeed_wb.v and
    /// encspeed_regs.h; for a multiple of 4 lines also encspeed_ecc.v (the core with the
    /// eccentricity-corrected speeds and identification), encspeed_ecc_wb.v (that behind
    /// Wishbone) and encspeed_ecc_regs.h.
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
    /// Synthesise the Wishbone top encspeed_wb (core and register file) with yosys
    /// (synth_ice40) and place and route it with nextpnr-ice40: logic cells, I/O and
    /// maximum clock frequency (a benchmark).
    Synth {
        #[command(flatten)]
        spec: SpecArgs,
        /// nextpnr-ice40 device option, e.g. hx8k, up5k, lp8k.
        #[arg(long, default_value = "hx8k")]
        device: String,
        /// Package, e.g. ct256 (hx8k), sg48 (up5k).
        #[arg(long, default_value = "ct256")]
        package: String,
        /// wb: encspeed_wb, synthesised, placed and routed; ecc: encspeed_ecc, synthesised
        /// only (cells by type: its ports outnumber any iCE40's pins).
        #[arg(long, default_value = "wb", value_parser = ["wb", "ecc"])]
        top: String,
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
        /// float: PC, ET, M/T as float estimators; hardware: the core's speed_pc,
        /// speed_et, speed_mt read at baseline_strobe (x1/x2/x4 as --edges, model delayed
        /// by the hardware latency) [default float; n3: hardware, its only source].
        #[arg(long, value_parser = ["float", "hardware"])]
        source: Option<String>,
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
        /// Clock of the float ET/M/T timestamps, or of the core (n3, --source hardware),
        /// Hz [default 100e6; on the core 10e6].
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
    /// Rewrite the generated pages of docs/ (ports.md; registers.md) for the default
    /// parameters; a test checks they are current.
    Docs {
        /// The docs directory.
        #[arg(long, default_value = "docs")]
        out: PathBuf,
    },
    /// Constant-speed accuracy sweep of every estimator of the bit-true core (CSV, SVG).
    ///
    /// Runs the golden core at log-spaced constant speeds from 0.01 to 1000 ω_lim (1 MHz
    /// clock, 1000 lines, dt = 10 000 cycles: docs/accuracy.md) and reads PC, ET, n1, n3 and
    /// M/T at their strobes after settling: per speed the max and RMS relative error and the
    /// computed bound of each. CSV on stdout, a summary on stderr, the figure (max relative
    /// error against r, log-log, with the n3 bound) to --svg.
    Accuracy {
        /// Number of speeds, log-spaced from 0.01 to 1000 ω_lim, both ends included.
        #[arg(long, default_value_t = tb::accuracy::DEFAULT_POINTS)]
        points: usize,
        /// Decoding of the core: x1, x2 or x4.
        #[arg(long, default_value = "x1", value_parser = ["x1", "x2", "x4"])]
        mode: String,
        /// Draw the figure (SVG) here.
        #[arg(long, default_value = "target/figures/accuracy_estimators.svg")]
        svg: PathBuf,
        /// Worker threads [default: the machine's parallelism].
        #[arg(long)]
        threads: Option<usize>,
    },
    /// Identify the disc eccentricity e and its phase θ0 from one revolution between two
    /// Z pulses, of a scenario (golden plant) or of a VCD of A/B/Z.
    ///
    /// Prints e and θ0 by the paper's method (eqs. 17-20 as printed), the ratio method and
    /// the harmonic fit (recommended; also with a 2nd harmonic), the mean speed and the
    /// corrector coefficients. See docs/eccentricity.md.
    Identify(identify::IdentifyArgs),
    /// Once-per-revolution ripple of M/T and n3 before and after the eccentricity correction,
    /// measured on the emitted encspeed_ecc.v in Verilator (Zhao's Figs. 6 and 7).
    ///
    /// A rigid disc whose centre is --delta-r-mm off the shaft, read at a constant speed,
    /// x1, cfg_z_mode = 1 (the position counts from line 0), the coefficients of that disc on
    /// ecc_c/ecc_d (with --identify: those of the e and θ0 that the Verilog's own
    /// identification gathered in a first run). Prints the identification (armed at the
    /// first index) and its error, the 1/rev amplitude, peak to peak and worst error against
    /// its budget; writes the figure (speeds in r/min over the shaft angle) to --svg and the
    /// M/T samples to --csv. See docs/eccentricity-hardware.md.
    EccRipple {
        #[command(flatten)]
        spec: SpecArgs,
        /// Shaft speed, r/min (> 0).
        #[arg(long, default_value_t = 600.0)]
        rpm: f64,
        /// Whole revolutions measured after the first index.
        #[arg(long, default_value_t = 3.0)]
        revs: f64,
        /// Offset of the disc centre from the shaft, mm.
        #[arg(long, default_value_t = 0.35)]
        delta_r_mm: f64,
        /// Radius of the disc's track, mm.
        #[arg(long, default_value_t = 30.0)]
        radius_mm: f64,
        /// Angle of the offset, degrees.
        #[arg(long, default_value_t = 50.0, allow_negative_numbers = true)]
        theta0_deg: f64,
        /// Draw the figure (SVG) here.
        #[arg(long, default_value = "target/ecc-ripple/ripple.svg")]
        svg: PathBuf,
        /// Write every sample (series, angle_rad, error_ppm) here.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Identify e and θ0 on the Verilog first (2.1 revolutions) and load the corrector
        /// with them, instead of the disc's own.
        #[arg(long)]
        identify: bool,
    },
}

/// Generation parameters, shared by every subcommand that builds the core: the defaults
/// (`Spec::default()`), then a TOML file (`--config`), then one option per `Spec` field
/// (`--clock-hz` for `clock_hz`, ...); a later source overrides an earlier one.
///
/// The options are made from the fields of `Spec` and [`describe`], so that a field, its
/// option, its key in a file and the line of `--print-config` cannot drift apart.
#[derive(Clone, Debug, Default)]
struct SpecArgs {
    /// `--config`.
    config: Option<PathBuf>,
    /// `--print-config`.
    print_config: bool,
    /// The `Spec` fields given as options, each checked to fit its field's type.
    options: toml::Table,
}

/// How a `Spec` field appears on the command line: option name, value name, and meaning,
/// unit and range (the help line and the comment in `--print-config`; the default is
/// added from `Spec::default()`). `None` for a key that is not a field.
fn describe(key: &str) -> Option<(&'static str, &'static str, String)> {
    use golden::params::{MAX_COUNTER_BITS, MAX_LINES, MIN_COUNTER_BITS, MIN_DT_CYCLES};
    Some(match key {
        "clock_hz" => (
            "clock-hz",
            "HZ",
            "Clock frequency, Hz; finite, > 0".to_string(),
        ),
        "lines" => (
            "lines",
            "K",
            format!("Encoder lines (A pulses) per revolution; 1..={MAX_LINES}"),
        ),
        "dt_cycles" => (
            "dt-cycles",
            "CYCLES",
            format!("Nominal dt, clock cycles; {MIN_DT_CYCLES}..=2^counter_bits - 1"),
        ),
        "counter_bits" => (
            "counter-bits",
            "BITS",
            format!(
                "Width of cfg_dt and of the ts/Cep/Cdt/Nep1/Ndt1 counters, bits; \
                 {MIN_COUNTER_BITS}..={MAX_COUNTER_BITS}"
            ),
        ),
        "timeout_s" => (
            "timeout-s",
            "S",
            "Zero-speed timeout, s; at least one dt, under 2^counter_bits - 1 dt".to_string(),
        ),
        _ => return None,
    })
}

/// `Spec::default()` as a table (sorted by key).
fn default_table() -> toml::Table {
    toml::Table::try_from(Spec::default()).expect("a Spec is a flat table")
}

/// The keys of `Spec`, in field order (as its serialisation writes them).
fn spec_keys() -> Vec<String> {
    let text = toml::to_string(&Spec::default()).expect("a Spec is a flat table");
    text.lines()
        .filter_map(|l| l.split_once(" = ").map(|(k, _)| k.trim().to_string()))
        .collect()
}

/// A value as the help text shows it: `100000000`, not `100000000.0`.
fn show(v: &toml::Value) -> String {
    match v {
        toml::Value::Float(f) => f.to_string(),
        other => other.to_string(),
    }
}

/// `key` set to `value` alone, checked against the type of its `Spec` field.
fn check_field(key: &str, value: toml::Value) -> Result<toml::Value, String> {
    let one = toml::Table::from_iter([(key.to_string(), value.clone())]);
    toml::Value::Table(one)
        .try_into::<Spec>()
        .map(|_| value)
        // The first line; the next one (`in `key``) repeats the option's name.
        .map_err(|e| e.to_string().lines().next().unwrap_or("").to_string())
}

impl Args for SpecArgs {
    fn augment_args(cmd: clap::Command) -> clap::Command {
        use clap::{Arg, ArgAction};
        let mut cmd = cmd
            .arg(
                Arg::new("config")
                    .long("config")
                    .value_name("FILE.toml")
                    .value_parser(clap::value_parser!(PathBuf))
                    .help(
                        "TOML file of parameters: any keys of --print-config; \
                         options override it",
                    ),
            )
            .arg(
                Arg::new("print-config")
                    .long("print-config")
                    .action(ArgAction::SetTrue)
                    .help(
                        "Print the effective parameters (defaults < --config < options) \
                         as TOML and exit",
                    ),
            );
        let defaults = default_table();
        for key in spec_keys() {
            let default = &defaults[&key];
            // A field without a description has no option; a unit test sees to it.
            let Some((long, value_name, about)) = describe(&key) else {
                continue;
            };
            let float = default.is_float();
            let field = key.clone();
            let parse = move |s: &str| -> Result<toml::Value, String> {
                let v = if float {
                    s.parse::<f64>()
                        .map(toml::Value::Float)
                        .map_err(|e| e.to_string())
                } else {
                    s.parse::<i64>()
                        .map(toml::Value::Integer)
                        .map_err(|e| e.to_string())
                }?;
                check_field(&field, v)
            };
            cmd = cmd.arg(
                Arg::new(long)
                    .long(long)
                    .value_name(value_name)
                    .allow_negative_numbers(true)
                    .value_parser(parse)
                    .help(format!("{about} [default {}]", show(default))),
            );
        }
        cmd
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

impl clap::FromArgMatches for SpecArgs {
    fn from_arg_matches(m: &clap::ArgMatches) -> Result<Self, clap::Error> {
        let mut s = SpecArgs::default();
        s.update_from_arg_matches(m)?;
        Ok(s)
    }

    fn update_from_arg_matches(&mut self, m: &clap::ArgMatches) -> Result<(), clap::Error> {
        if let Some(path) = m.get_one::<PathBuf>("config") {
            self.config = Some(path.clone());
        }
        self.print_config |= m.get_flag("print-config");
        for key in spec_keys() {
            if let Some((long, _, _)) = describe(&key) {
                if let Some(v) = m.get_one::<toml::Value>(long) {
                    self.options.insert(key, v.clone());
                }
            }
        }
        Ok(())
    }
}

impl SpecArgs {
    /// The configuration file as a table, each key checked against `Spec`; empty when
    /// there is no file.
    fn file_table(&self) -> Result<toml::Table, String> {
        let Some(path) = &self.config else {
            return Ok(toml::Table::new());
        };
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read configuration file {}: {e}", path.display()))?;
        let bad = |e: toml::de::Error| format!("configuration file {}: {e}", path.display());
        // Parsed as a Spec for its messages (unknown key, wrong type, with the line), then
        // kept as a table to know which keys it sets.
        toml::from_str::<Spec>(&text).map_err(bad)?;
        toml::from_str(&text).map_err(bad)
    }

    /// Validated parameters: defaults < file < options. A refusal names the parameter and,
    /// unless it is a default, where its value came from.
    fn params(&self) -> Result<Params, String> {
        let file = self.file_table()?;
        let mut table = file.clone();
        table.extend(self.options.clone());
        let spec: Spec = toml::Value::Table(table)
            .try_into()
            .map_err(|e| format!("parameters: {e}"))?;
        Params::new(spec).map_err(|e| {
            let from: Vec<String> = fields_of(&e)
                .into_iter()
                .filter_map(|k| {
                    if self.options.contains_key(&k) {
                        let long = describe(&k).map_or(k.clone(), |d| d.0.to_string());
                        Some(format!("{k} from --{long}"))
                    } else if file.contains_key(&k) {
                        let path = self.config.as_deref().unwrap_or(Path::new(""));
                        Some(format!("{k} from {}", path.display()))
                    } else {
                        None
                    }
                })
                .collect();
            if from.is_empty() {
                e.to_string()
            } else {
                format!("{e} [{}]", from.join(", "))
            }
        })
    }

    /// Validate, then run `f`; or with `--print-config` print the parameters instead.
    fn run(&self, f: impl FnOnce(&Params) -> Outcome) -> Outcome {
        let p = self.params().map_err(|e| (2, e))?;
        if self.print_config {
            print!("{}", config_toml(p.spec()));
            Ok(())
        } else {
            f(&p)
        }
    }
}

/// The `Spec` fields a refusal names, in the order its message names them.
fn fields_of(e: &ParamError) -> Vec<String> {
    let msg = e.to_string();
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut found: Vec<(usize, String)> = spec_keys()
        .into_iter()
        .filter_map(|k| {
            let at = msg.match_indices(k.as_str()).find(|&(i, _)| {
                !msg[..i].ends_with(ident) && !msg[i + k.len()..].starts_with(ident)
            });
            at.map(|(i, _)| (i, k))
        })
        .collect();
    found.sort();
    found.into_iter().map(|(_, k)| k).collect()
}

/// `spec` as a TOML configuration file: every field after a comment line with its help.
fn config_toml(spec: &Spec) -> String {
    let defaults = default_table();
    let mut out = String::from(
        "# encspeed parameters: `encspeed generate --config FILE.toml`. Any key may be left\n\
         # out for its default; command-line options override the file.\n",
    );
    let text = toml::to_string(spec).expect("a Spec is a flat table");
    for line in text.lines() {
        let key = line.split_once(" = ").map_or("", |(k, _)| k.trim());
        let about = describe(key).map_or(String::new(), |d| d.2);
        let default = defaults.get(key).map_or(String::new(), show);
        out.push_str(&format!("\n# {about} [default {default}]\n{line}\n"));
    }
    out
}

fn fail(code: u8, msg: impl std::fmt::Display) -> ExitCode {
    eprintln!("encspeed: {msg}");
    ExitCode::from(code)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Cmd::Generate { spec, out } => spec.run(|p| generate(p, &out)),
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
                spec.run(|p| {
                    simulate(
                        p,
                        scenario.as_deref(),
                        motion.as_deref(),
                        &vcd,
                        verilator_vcd.as_deref(),
                    )
                })
            }
        }
        Cmd::Docs { out } => docs(&out),
        Cmd::Bench { spec, cycles } => spec.run(|p| bench(p, cycles)),
        Cmd::Synth {
            spec,
            device,
            package,
            top,
        } => spec.run(|p| {
            if top == "ecc" {
                synth_ecc(p)
            } else {
                synth(p, &device, &package)
            }
        }),
        Cmd::Bode {
            estimator,
            source,
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
            use golden::smallsignal::freqresp::{BodeSpec, Source};
            let source = match source.as_deref().map(str::parse::<Source>).transpose() {
                Ok(s) => s,
                Err(e) => return fail(2, format!("bode: --{e}")),
            };
            let mut spec = match (estimator.parse(), source) {
                (Ok(e), Some(Source::Hardware)) => BodeSpec::hardware(e, lines, rpm, ts_s),
                (Ok(e), Some(Source::Float)) => BodeSpec {
                    source: Source::Float,
                    ..BodeSpec::new(e, lines, rpm, ts_s)
                },
                (Ok(e), None) => BodeSpec::new(e, lines, rpm, ts_s),
                (Err(e), _) => return fail(2, format!("bode: --{e}")),
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
        Cmd::Accuracy {
            points,
            mode,
            svg,
            threads,
        } => accuracy(points, &mode, &svg, threads),
        Cmd::Identify(args) => identify::run(&args),
        Cmd::EccRipple {
            spec,
            rpm,
            revs,
            delta_r_mm,
            radius_mm,
            theta0_deg,
            svg,
            csv,
            identify,
        } => spec.run(|p| {
            if !(rpm > 0.0 && rpm.is_finite() && revs >= 1.0 && revs.is_finite()) {
                return Err((2, "ecc-ripple: --rpm must be > 0 and --revs >= 1".into()));
            }
            if !(radius_mm > 0.0 && (0.0..radius_mm).contains(&delta_r_mm)) {
                return Err((2, "ecc-ripple: need 0 <= --delta-r-mm < --radius-mm".into()));
            }
            let setup = tb::ecc_ripple::RippleSetup {
                rpm,
                revs,
                e: delta_r_mm / radius_mm,
                theta0: theta0_deg.to_radians(),
                loaded: None,
            };
            ecc_ripple(p, setup, identify, &svg, csv.as_deref())
        }),
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
    for (name, text) in hdl::emit::wb::emit_wb(p) {
        write(name, &text)?;
    }
    // The eccentricity-corrected top needs a multiple of 4 lines; the core does not, so a
    // refusal is reported and the rest is written.
    let ecc = match hdl::emit_ecc(p) {
        Ok(v) => {
            write("encspeed_ecc.v", &v)?;
            for (name, text) in hdl::emit::wb::emit_ecc_wb(p).map_err(|e| (2, e))? {
                write(name, &text)?;
            }
            format!(
                ", {}, {}",
                out.join("encspeed_ecc.v").display(),
                out.join(hdl::emit::wb::ECC_WB_VERILOG_FILE).display()
            )
        }
        Err(e) => {
            eprintln!("encspeed_ecc.v and encspeed_ecc_wb.v not written: {e}");
            String::new()
        }
    };
    println!(
        "wrote {}, {}{ecc}, the Wishbone top and the C header ({}-bit counters, dt = {} cycles, ω_lim = {} rev/s)",
        out.join("encspeed_core.v").display(),
        out.join("encspeed_core.toml").display(),
        p.counter_bits(),
        p.dt_cycles(),
        p.omega_lim_rps()
    );
    Ok(())
}

/// The ripple of `setup` on the emitted `encspeed_ecc.v` for `p`, in Verilator; with
/// `identify`, the corrector loaded with the Verilog's identification.
fn ecc_ripple(
    p: &Params,
    mut setup: tb::ecc_ripple::RippleSetup,
    identify: bool,
    svg: &Path,
    csv: Option<&Path>,
) -> Outcome {
    use tb::ecc_ripple::{draw_svg, identify_on_verilog, run_verilog, Identification, Ripple};
    let verilog = hdl::emit_ecc(p).map_err(|e| (2, e))?;
    let sim =
        tb::ecc_verilator::EccVerilated::build(&verilog, p.speed_bits()).map_err(|e| (1, e))?;
    if identify {
        let id = identify_on_verilog(&sim, p, &setup).map_err(|e| (1, e))?;
        println!("{}", id.summary());
        setup.loaded = Some((id.identified.e, id.identified.theta0));
    }
    let (log, stim) = run_verilog(&sim, p, &setup).map_err(|e| (1, e))?;
    let ripple = Ripple::new(p, setup, &log.strobes, stim.aligned_after);
    if ripple.mt_before.is_empty() || ripple.n3_before.is_empty() {
        return Err((
            1,
            "ecc-ripple: no estimates after the index (too slow for dt?)".into(),
        ));
    }
    let (le, lth) = setup.loaded.unwrap_or((setup.e, setup.theta0));
    println!(
        "encspeed_ecc.v in Verilator, e = {:.6}, theta0 = {:.2} deg, corrector loaded with \
         e = {le:.8}, theta0 = {:.5} deg ({}), {} cycles",
        setup.e,
        setup.theta0.to_degrees(),
        lth.to_degrees(),
        if setup.loaded.is_some() {
            "identified"
        } else {
            "the disc's own"
        },
        stim.cycles,
    );
    match Identification::of(p, &setup, &log) {
        Some(id) => println!("{}", id.summary()),
        None => println!("no identification in this run (under 2.1 revolutions)"),
    }
    println!("{}", ripple.summary());
    let title = format!(
        "encspeed_ecc.v in Verilator: {} r/min, e = {:.5}, θ0 = {:.0}°, K = {}, dt = {} ms, x1",
        setup.rpm,
        setup.e,
        setup.theta0.to_degrees(),
        p.lines(),
        p.dt_s() * 1e3
    );
    draw_svg(svg, &title, &ripple).map_err(|e| (1, e))?;
    eprintln!("wrote {}", svg.display());
    if let Some(path) = csv {
        std::fs::write(path, ripple.csv())
            .map_err(|e| (1, format!("cannot write {}: {e}", path.display())))?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}

/// The generated pages of docs/, for the default parameters.
fn docs(out: &Path) -> Outcome {
    let p = Params::new(Spec::default()).map_err(|e| (2, e.to_string()))?;
    for (name, text) in [
        ("ports.md", hdl::emit::ports_markdown(&p)),
        ("registers.md", hdl::emit::wb::registers_markdown(&p)),
    ] {
        let path = out.join(name);
        std::fs::write(&path, text)
            .map_err(|e| (1, format!("cannot write {}: {e}", path.display())))?;
        println!("wrote {}", path.display());
    }
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

/// yosys `synth_ice40` of `encspeed_ecc` for `p`: the cells by type.
fn synth_ecc(p: &Params) -> Outcome {
    let dir = tb::target_dir().join("synth-ecc");
    std::fs::create_dir_all(&dir).map_err(|e| (1, e.to_string()))?;
    let verilog = hdl::emit_ecc(p).map_err(|e| (2, e))?;
    std::fs::write(dir.join("encspeed_ecc.v"), verilog).map_err(|e| (1, e.to_string()))?;
    let _ = std::fs::remove_file(dir.join("stat.txt"));
    tb::run_tool(
        std::process::Command::new("yosys").current_dir(&dir).args([
            "-q",
            "-p",
            "read_verilog encspeed_ecc.v; synth_ice40 -top encspeed_ecc; tee -q -o stat.txt stat",
        ]),
        "yosys",
    )
    .map_err(|e| (1, e))?;
    let stat = std::fs::read_to_string(dir.join("stat.txt")).map_err(|e| (1, e.to_string()))?;
    println!(
        "encspeed_ecc, yosys synth_ice40, {}-bit counters, K = {}:",
        p.counter_bits(),
        p.lines()
    );
    let mut flip_flops = 0u64;
    for l in stat.lines().map(str::trim) {
        let mut it = l.split_whitespace();
        if let (Some(cell), Some(n)) = (it.next(), it.next().and_then(|n| n.parse::<u64>().ok())) {
            if cell.starts_with("SB_") {
                println!("  {cell:<14} {n}");
                if cell.starts_with("SB_DFF") {
                    flip_flops += n;
                }
            }
        }
    }
    println!("  flip-flops     {flip_flops}");
    Ok(())
}

fn synth(p: &Params, device: &str, package: &str) -> Outcome {
    let dir = tb::target_dir().join("synth");
    std::fs::create_dir_all(&dir).map_err(|e| (1, e.to_string()))?;
    // The complete core has about 430 port bits, more than any iCE40 package has pins: place
    // and route the Wishbone top `encspeed_wb` (the core behind its register file, about 80
    // pins), as a CPU-attached design would be.
    hdl::emit::wb::write_all(p, &dir).map_err(|e| (1, e.to_string()))?;
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
            "read_verilog encspeed_wb.v; synth_ice40 -top encspeed_wb -json core.json",
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
        "encspeed_wb on {device} {package}, {}-bit counters, clock constraint {} MHz",
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
    spec: golden::smallsignal::freqresp::BodeSpec,
    (fmin, fmax, points): (f64, f64, u32),
    csv: Option<&Path>,
    svg: Option<&Path>,
    title: Option<String>,
) -> Outcome {
    use golden::smallsignal::freqresp::{log_spaced, to_csv, Estimator, Experiment};
    let bad = |e: golden::smallsignal::freqresp::FreqRespError| (2, format!("bode: --{e}"));
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
    // The hardware baselines: where they are read and how late (the model includes it).
    let hw = exp
        .hardware_latency_cycles()
        .map(|d| format!(" (hardware, {} MHz, latency {d} cycles)", s.clock_hz / 1e6));
    let caption = title.unwrap_or_else(|| {
        format!(
            "{}{}: {r_name}, {} r/min, Ts = {} ms",
            s.estimator.name().to_uppercase(),
            hw.as_deref().unwrap_or(""),
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
    let upto = |m: &&golden::smallsignal::freqresp::Measurement| m.f_hz <= quarter * (1.0 + 1e-9);
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

/// `encspeed accuracy`: the constant-speed sweep of `tb::accuracy`, CSV on stdout, a
/// summary on stderr, the figure to `svg`.
fn accuracy(points: usize, mode: &str, svg: &Path, threads: Option<usize>) -> Outcome {
    use tb::accuracy::{
        default_threads, draw_svg, log_speeds, sweep, to_csv, worst, Setup, R_MAX, R_MIN,
    };
    if points < 2 {
        return Err((2, format!("accuracy: --points = {points}: at least 2")));
    }
    if threads == Some(0) {
        return Err((2, "accuracy: --threads = 0: at least 1".into()));
    }
    let cfg_mode = match mode {
        "x1" => 0,
        "x2" => 1,
        _ => 2,
    };
    let setup = Setup::standard(cfg_mode);
    let speeds = log_speeds(points, R_MIN, R_MAX);
    let t = Instant::now();
    let results = sweep(&setup, &speeds, threads.unwrap_or_else(default_threads));
    let secs = t.elapsed().as_secs_f64();
    print!("{}", to_csv(&setup, &results));
    let title = format!(
        "Max relative error at constant speed, {} ({} MHz clock, {} lines, dt = {} cycles, F = 16)",
        setup.mode_name(),
        setup.clock_hz / 1e6,
        setup.lines,
        setup.dt_cycles
    );
    draw_svg(svg, &title, &setup, &results).map_err(|e| (1, e))?;
    let cycles: u64 = results.iter().map(|p| p.cycles).sum();
    eprintln!(
        "{} speeds {R_MIN}..{R_MAX} ω_lim ({} r/min per ω_lim), {}: {cycles} cycles in {secs:.1} s; figure {}",
        results.len(),
        setup.omega_lim_rps() * 60.0,
        setup.mode_name(),
        svg.display()
    );
    for w in worst(&results) {
        eprintln!(
            "  {:<3} max relative error {:.3e} (r = {:.4}), max error/bound {:.4} (r = {:.4})",
            w.est.name(),
            w.max_err,
            w.max_err_r,
            w.max_ratio,
            w.max_ratio_r
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_spec_field_has_an_option() {
        for key in spec_keys() {
            let (long, _, about) = describe(&key).unwrap_or_else(|| panic!("describe {key}"));
            assert_eq!(long.replace('-', "_"), key);
            assert!(!about.is_empty());
        }
    }

    #[test]
    fn printed_config_is_a_spec() {
        let text = config_toml(&Spec::default());
        assert_eq!(toml::from_str::<Spec>(&text).unwrap(), Spec::default());
    }

    #[test]
    fn fields_of_finds_whole_names_in_message_order() {
        let e = ParamError::DtTooWide {
            dt_cycles: 100_000,
            counter_bits: 12,
        };
        assert_eq!(fields_of(&e), ["dt_cycles", "counter_bits"]);
        assert_eq!(fields_of(&ParamError::ZeroLines), ["lines"]);
    }
}
