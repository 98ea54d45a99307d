// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed identify`: the eccentricity e and its phase θ0 of an encoder disc, from one
//! revolution of line periods between two Z pulses, taken either from a scenario run through
//! the golden plant or from a VCD of the A/B/Z signals.
//!
//! A thin front end: the plant (`golden::eccentric::motion`), the period extraction
//! (`revolution_periods`) and the three methods (`golden::eccentric::identify`) are the
//! golden model's; this module checks the arguments and the input, converts a VCD into the
//! plant's edge list, and prints. Conventions (e, θ0, which Z edge is line 0):
//! docs/eccentricity.md.

use clap::Args;
use golden::eccentric::identify::{
    harmonic_fit, paper_identify, phase_difference, ratio_identify, revolution_periods, FitOptions,
    HarmonicFit,
};
use golden::eccentric::motion::{EccentricDisc, JitterMotion};
use golden::eccentric::{EccError, Eccentricity, Model};
use golden::ideal::plant::{Channel, Edge};
use std::f64::consts::TAU;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::Outcome;

/// Fewest lines: the identification needs at least 8 periods.
const MIN_LINES: u32 = 8;
/// Most lines of a scenario: its edge list (about 10·K edges) stays near 100 MB.
const MAX_SCENARIO_LINES: u32 = 1 << 18;
/// Speed noise of a scenario (`JitterMotion::broadband`, as in docs/eccentricity.md):
/// tones, and their frequency band in cycles per revolution of the mean motion.
const NOISE_TONES: usize = 32;
const NOISE_BAND: (f64, f64) = (3.0, 300.0);

/// Options of `encspeed identify`. The source is a scenario (`--rpm` with `--e` or
/// `--delta-r-mm`) or `--vcd`, never both.
#[derive(Args, Debug)]
pub struct IdentifyArgs {
    /// Lines K of the disc (A pulses per revolution), 8..=262144 for a scenario.
    #[arg(long, value_name = "K")]
    lines: u32,
    /// Scenario: mean shaft speed, r/min (> 0: forward rotation).
    #[arg(long, allow_negative_numbers = true)]
    rpm: Option<f64>,
    /// Scenario: relative eccentricity e = ΔR/R, in [0, 1).
    #[arg(long = "e", value_name = "E", allow_negative_numbers = true)]
    e: Option<f64>,
    /// Scenario: disc centre offset ΔR, mm (with --radius-mm; instead of --e).
    #[arg(
        long,
        value_name = "MM",
        allow_negative_numbers = true,
        conflicts_with = "e"
    )]
    delta_r_mm: Option<f64>,
    /// Read radius R, mm: with --delta-r-mm gives e; in the output, ΔR = e·R.
    #[arg(long, value_name = "MM", allow_negative_numbers = true)]
    radius_mm: Option<f64>,
    /// Scenario: eccentricity phase θ0, degrees (the apparent phase of the Z line).
    #[arg(long, value_name = "DEG", allow_negative_numbers = true)]
    theta0_deg: Option<f64>,
    /// Scenario: plant law, rigid (a real disc) or zhao (the paper's eq. 8) [default rigid].
    #[arg(long, value_parser = ["rigid", "zhao"])]
    plant: Option<String>,
    /// Scenario: relative rms speed noise (broadband jitter, 32 tones in 3-300 cycles per
    /// revolution), in [0, 0.125) [default 0].
    #[arg(long, value_name = "REL", allow_negative_numbers = true)]
    noise_rms: Option<f64>,
    /// Scenario: seed of the noise's frequencies and phases [default 1].
    #[arg(long)]
    seed: Option<u64>,
    /// Scenario: clock, Hz, to which every edge is stamped (the first clock edge at or
    /// after it), as a capture register would [default 100e6].
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    clock_hz: Option<f64>,
    /// Scenario: whole revolutions to run before the identified one [default 0].
    #[arg(long, value_name = "N")]
    skip_revs: Option<u32>,
    /// VCD of the encoder signals: identify from the first revolution between two rising
    /// edges of Z in it (times from its $timescale).
    #[arg(
        long,
        value_name = "FILE",
        conflicts_with_all = [
            "rpm", "e", "delta_r_mm", "theta0_deg", "plant", "noise_rms", "seed",
            "clock_hz", "skip_revs",
        ]
    )]
    vcd: Option<PathBuf>,
    /// VCD: reference name of channel A, in any scope, or a dotted path (tb.enc_a)
    /// [default enc_a].
    #[arg(long, value_name = "NAME")]
    a: Option<String>,
    /// VCD: reference name of channel B (checked low at every A rising edge: forward
    /// rotation) [default enc_b].
    #[arg(long, value_name = "NAME")]
    b: Option<String>,
    /// VCD: reference name of the index channel Z [default enc_z].
    #[arg(long, value_name = "NAME")]
    z: Option<String>,
    /// Plant law through which the fitted first harmonic is read as e: rigid or zhao.
    #[arg(long, default_value = "rigid", value_parser = ["rigid", "zhao"])]
    model: String,
    /// Also write the results as CSV here.
    #[arg(long, value_name = "PATH")]
    csv: Option<PathBuf>,
}

/// A refusal of the arguments or of the input (exit code 2).
fn bad(msg: impl std::fmt::Display) -> (u8, String) {
    (2, format!("identify: {msg}"))
}

fn model_of(name: &str) -> Model {
    if name == "zhao" {
        Model::Zhao
    } else {
        Model::Rigid
    }
}

fn model_name(m: Model) -> &'static str {
    match m {
        Model::Rigid => "rigid disc",
        Model::Zhao => "Zhao eq. (8)",
    }
}

/// One revolution of line periods (s) and where they came from.
struct Revolution {
    periods: Vec<f64>,
    /// What the input was, for the heading.
    source: String,
    /// The scenario's plant parameters, when the input is a scenario.
    truth: Option<Eccentricity>,
}

/// `encspeed identify`.
pub fn run(args: &IdentifyArgs) -> Outcome {
    if args.lines < MIN_LINES {
        return Err(bad(format!(
            "--lines = {}: at least {MIN_LINES} (one period per line; the fit needs 8)",
            args.lines
        )));
    }
    if let Some(r) = args.radius_mm {
        if !(r.is_finite() && r > 0.0) {
            return Err(bad(format!("--radius-mm = {r}: must be finite and > 0")));
        }
    }
    if args.vcd.is_none() {
        // Checked here rather than by clap's `requires`, which these options escaped.
        for (opt, v) in [("--a", &args.a), ("--b", &args.b), ("--z", &args.z)] {
            if let Some(name) = v {
                return Err(bad(format!(
                    "{opt} = {name} names a VCD signal: it needs --vcd FILE"
                )));
            }
        }
    }
    let model = model_of(&args.model);
    let rev = match (&args.vcd, args.rpm) {
        (Some(path), _) => from_vcd(args, path)?,
        (None, Some(rpm)) => from_scenario(args, rpm)?,
        (None, None) => {
            return Err(bad(
                "no source: give a scenario (--rpm with --e or --delta-r-mm) or --vcd FILE",
            ))
        }
    };
    let report = Report::new(&rev, args.lines, model, args.radius_mm)?;
    print!("{}", report.table());
    if let Some(path) = &args.csv {
        write_file(path, &report.csv())?;
    }
    Ok(())
}

/// The periods of a scenario: the golden plant at constant speed (plus optional jitter),
/// edges stamped on the clock by `revolution_periods`.
fn from_scenario(args: &IdentifyArgs, rpm: f64) -> Result<Revolution, (u8, String)> {
    let k = args.lines;
    if k > MAX_SCENARIO_LINES {
        return Err(bad(format!(
            "--lines = {k}: a scenario has at most {MAX_SCENARIO_LINES} lines"
        )));
    }
    if !(rpm.is_finite() && rpm > 0.0) {
        return Err(bad(format!(
            "--rpm = {rpm}: must be finite and > 0 (identification needs forward rotation)"
        )));
    }
    let plant = model_of(args.plant.as_deref().unwrap_or("rigid"));
    let theta0_deg = args.theta0_deg.unwrap_or(0.0);
    let theta0 = theta0_deg.to_radians();
    let ecc = match (args.e, args.delta_r_mm, args.radius_mm) {
        (Some(e), _, _) => Eccentricity::new(plant, e, theta0).map_err(|err| match err {
            EccError::NonFinitePhase(_) => {
                bad(format!("--theta0-deg = {theta0_deg}: must be finite"))
            }
            other => bad(format!("--e = {e}: {other}")),
        })?,
        (None, Some(dr), Some(r)) => {
            Eccentricity::from_geometry(plant, dr, r, theta0).map_err(|err| match err {
                EccError::NonFinitePhase(_) => {
                    bad(format!("--theta0-deg = {theta0_deg}: must be finite"))
                }
                _ => bad(format!(
                    "--delta-r-mm = {dr}, --radius-mm = {r}: need 0 <= ΔR < R, both finite"
                )),
            })?
        }
        (None, Some(_), None) => {
            return Err(bad("--delta-r-mm needs --radius-mm (e = ΔR/R)"));
        }
        (None, None, _) => {
            return Err(bad(
                "the scenario needs an eccentricity: --e, or --delta-r-mm with --radius-mm",
            ));
        }
    };
    let clock_hz = args.clock_hz.unwrap_or(100e6);
    if !(clock_hz.is_finite() && clock_hz > 0.0) {
        return Err(bad(format!(
            "--clock-hz = {clock_hz}: must be finite and > 0"
        )));
    }
    let noise = args.noise_rms.unwrap_or(0.0);
    if !(noise.is_finite() && noise >= 0.0) {
        return Err(bad(format!(
            "--noise-rms = {noise}: must be finite and >= 0"
        )));
    }
    let seed = args.seed.unwrap_or(1);
    let skip = args.skip_revs.unwrap_or(0);
    let disc = EccentricDisc::new(k, ecc).map_err(|e| bad(format!("--lines = {k}: {e}")))?;
    let speed = rpm / 60.0;
    // Start 1.2 lines before the Z line of the first of skip + 1 revolutions, so that its
    // line 0 (the A rising edge before Z) is seen. K lines take 1/a shaft revolutions
    // (a = 1 − e²/2 for Zhao's plant); 2.5 more revolutions leave room for the jitter's
    // phase excursion (at most 1/(2π·3) revolution for tones from 3 cycles per revolution).
    let start = disc.shaft_angle_rev(-1.2 - f64::from(skip) * f64::from(k));
    let duration = (f64::from(skip) + 2.5) / (speed * ecc.apparent_per_rev());
    let tones = if noise > 0.0 { NOISE_TONES } else { 0 };
    let motion = JitterMotion::broadband(
        start,
        speed,
        noise,
        NOISE_BAND.0,
        NOISE_BAND.1,
        tones,
        seed,
        duration,
    )
    .ok_or_else(|| {
        bad(format!(
            "--noise-rms = {noise}: too large, the shaft could stop (the {NOISE_TONES} tones' \
             amplitudes, rms·√(2/{NOISE_TONES}) each, must sum below 1: rms < 0.125)"
        ))
    })?;
    let edges = disc.edges(&motion);
    // Skip whole revolutions: drop every edge up to the skip-th falling edge of Z, so that
    // the next rising edge of Z (with its line 0 just before it) starts the revolution.
    let from = match skip {
        0 => 0,
        n => edges
            .iter()
            .enumerate()
            .filter(|(_, e)| e.channel == Channel::Z && !e.rising)
            .nth(n as usize - 1)
            .map(|(i, _)| i + 1)
            .expect("the motion covers skip + 2 revolutions"),
    };
    let periods = revolution_periods(&edges[from..], k, Some(clock_hz))
        .map_err(|e| bad(format!("scenario: {e}")))?;
    if let Some(m) = periods.iter().position(|&p| p <= 0.0) {
        return Err(bad(format!(
            "--clock-hz = {clock_hz}: too slow for --lines = {k} at --rpm = {rpm}: line \
             period {m} spans no clock cycle"
        )));
    }
    let noise_text = if noise > 0.0 {
        format!("{} % rms speed noise (seed {seed})", noise * 100.0)
    } else {
        "no speed noise".to_string()
    };
    let source = format!(
        "scenario: {} plant, K = {k}, {rpm} r/min, e = {:.7}{}, θ0 = {theta0_deg}°, {noise_text}, \
         edges stamped on a {} MHz clock{}",
        model_name(plant),
        ecc.e,
        args.radius_mm
            .map_or(String::new(), |r| format!(" (ΔR = {:.4} mm)", ecc.e * r)),
        clock_hz / 1e6,
        if skip > 0 {
            format!(", revolution {} from the start", skip + 1)
        } else {
            String::new()
        }
    );
    Ok(Revolution {
        periods,
        source,
        truth: Some(ecc),
    })
}

/// The VCD's reference names of A, B, Z (defaults enc_a, enc_b, enc_z), with their options.
fn signal_names(args: &IdentifyArgs) -> [(&'static str, String); 3] {
    let pick = |v: &Option<String>, d: &str| v.clone().unwrap_or_else(|| d.to_string());
    [
        ("--a", pick(&args.a, "enc_a")),
        ("--b", pick(&args.b, "enc_b")),
        ("--z", pick(&args.z, "enc_z")),
    ]
}

/// Every variable of the header with its dotted scope path, depth first in file order.
fn all_vars(items: &[vcd::ScopeItem], prefix: &str, out: &mut Vec<(String, vcd::Var)>) {
    for item in items {
        match item {
            vcd::ScopeItem::Var(v) => out.push((format!("{prefix}{}", v.reference), v.clone())),
            vcd::ScopeItem::Scope(s) => {
                all_vars(&s.children, &format!("{prefix}{}.", s.identifier), out)
            }
        }
    }
}

/// An I/O failure reading the VCD: malformed content is unusable input (2), anything else
/// an I/O failure (1).
fn vcd_error(path: &Path, e: std::io::Error) -> (u8, String) {
    let code = match e.kind() {
        std::io::ErrorKind::InvalidData
        | std::io::ErrorKind::InvalidInput
        | std::io::ErrorKind::UnexpectedEof => 2,
        _ => 1,
    };
    (code, format!("identify: --vcd {}: {e}", path.display()))
}

/// The periods of the first revolution of a VCD (module docs; docs/eccentricity.md):
/// the signals become the plant's edge list (times in ticks of the timescale, exact
/// integers), checked, then handed to `revolution_periods` unchanged.
fn from_vcd(args: &IdentifyArgs, path: &Path) -> Result<Revolution, (u8, String)> {
    let k = args.lines;
    let file = std::fs::File::open(path).map_err(|e| {
        (
            1,
            format!("identify: cannot read --vcd {}: {e}", path.display()),
        )
    })?;
    let mut parser = vcd::Parser::new(std::io::BufReader::new(file));
    let header = parser.parse_header().map_err(|e| vcd_error(path, e))?;
    let (scale, unit) = header.timescale.ok_or_else(|| {
        bad(format!(
            "--vcd {}: no $timescale: the times cannot be converted to seconds",
            path.display()
        ))
    })?;
    let tick_s = f64::from(scale) * unit.fraction();
    let mut vars = Vec::new();
    all_vars(&header.items, "", &mut vars);
    let names = signal_names(args);
    let mut codes = Vec::new();
    for (opt, name) in &names {
        // A dotted name is a full path; a plain one a reference name in any scope.
        let matches: Vec<&(String, vcd::Var)> = vars
            .iter()
            .filter(|(full, v)| {
                if name.contains('.') {
                    full == name
                } else {
                    v.reference == *name
                }
            })
            .collect();
        let Some((full, var)) = matches.first() else {
            let mut list: Vec<&str> = vars.iter().map(|(f, _)| f.as_str()).collect();
            list.dedup();
            let shown = list.len().min(40);
            return Err(bad(format!(
                "--vcd {}: no signal `{name}` ({opt}); the file has: {}{}",
                path.display(),
                if list.is_empty() {
                    "no signals".to_string()
                } else {
                    list[..shown].join(", ")
                },
                if list.len() > shown {
                    format!(" and {} more", list.len() - shown)
                } else {
                    String::new()
                }
            )));
        };
        if var.size != 1 {
            return Err(bad(format!(
                "--vcd {}: signal {full} ({opt}) is {} bits wide: A, B and Z are single bits",
                path.display(),
                var.size
            )));
        }
        if matches.iter().any(|(_, v)| v.code != var.code) {
            eprintln!("encspeed: identify: note: `{name}` is in several scopes; using {full}");
        }
        if let Some(i) = codes.iter().position(|(c, _, _)| *c == var.code) {
            let (_, other_opt, other): &(vcd::IdCode, &str, String) = &codes[i];
            return Err(bad(format!(
                "--vcd {}: {opt} {full} and {other_opt} {other} are the same signal",
                path.display()
            )));
        }
        codes.push((var.code, *opt, full.clone()));
    }
    // Level changes → edges: a rising edge is 0 → 1, a falling one 1 → 0; x and z are
    // levels of their own, so neither the initial dump nor x → 1 makes an edge.
    let channels = [Channel::A, Channel::B, Channel::Z];
    let mut level = [vcd::Value::X; 3];
    let mut now = 0u64;
    let mut edges = Vec::new();
    // B's level at each A rising edge (the index is the edge's position in `edges`).
    let mut b_at_a_rise = Vec::new();
    // Z rising edges after the first A rising edge: reading stops at the second, which
    // closes the revolution (a long capture need not be read to its end).
    let mut usable_z = 0;
    for cmd in parser {
        let (code, value) = match cmd.map_err(|e| vcd_error(path, e))? {
            vcd::Command::Timestamp(t) => {
                now = t;
                continue;
            }
            vcd::Command::ChangeScalar(c, v) => (c, v),
            vcd::Command::ChangeVector(c, v) if v.len() == 1 => (c, v[0]),
            _ => continue,
        };
        let Some(i) = codes.iter().position(|(c, _, _)| *c == code) else {
            continue;
        };
        let edge = match (level[i], value) {
            (vcd::Value::V0, vcd::Value::V1) => Some(true),
            (vcd::Value::V1, vcd::Value::V0) => Some(false),
            _ => None,
        };
        level[i] = value;
        if let Some(rising) = edge {
            if channels[i] == Channel::A && rising {
                b_at_a_rise.push((edges.len(), level[1]));
            }
            edges.push(Edge {
                // Ticks as f64: exact below 2^53, and differences of them stay exact.
                t: now as f64,
                channel: channels[i],
                rising,
            });
            if channels[i] == Channel::Z && rising && !b_at_a_rise.is_empty() {
                usable_z += 1;
                if usable_z == 2 {
                    break;
                }
            }
        }
    }
    let name_of = |i: usize| &codes[i].2;
    let at = |t: f64| format!("{:.9} s", t * tick_s);
    // The revolution that revolution_periods takes: the first rising edge of Z with an A
    // rising edge (line 0) before it, to the next rising edge of Z.
    let z_rises: Vec<usize> = edges
        .iter()
        .enumerate()
        .filter(|(_, e)| e.channel == Channel::Z && e.rising)
        .map(|(i, _)| i)
        .collect();
    let first_a = edges
        .iter()
        .position(|e| e.channel == Channel::A && e.rising);
    let usable: Vec<usize> = z_rises
        .iter()
        .copied()
        .filter(|&i| first_a.is_some_and(|a| a < i))
        .collect();
    let (z1, z2) = match usable.as_slice() {
        [z1, z2, ..] => (*z1, *z2),
        _ => {
            return Err(bad(format!(
                "--vcd {}: {} rising edge(s) of Z ({}){}: one revolution needs two, \
                 with an A rising edge (line 0) before the first",
                path.display(),
                z_rises.len(),
                name_of(2),
                if z_rises.len() > usable.len() {
                    format!(
                        ", {} of them before any A rising edge",
                        z_rises.len() - usable.len()
                    )
                } else {
                    String::new()
                }
            )))
        }
    };
    let a_between = edges[z1..z2]
        .iter()
        .filter(|e| e.channel == Channel::A && e.rising)
        .count();
    if a_between != k as usize {
        return Err(bad(format!(
            "--vcd {}: {a_between} A rising edges of {} between the Z rising edges at {} \
             and {}, so {a_between} line periods from line 0, but --lines = {k}: wrong \
             --lines, a missed or extra pulse, a reversal, or not one Z pulse per revolution",
            path.display(),
            name_of(0),
            at(edges[z1].t),
            at(edges[z2].t),
        )));
    }
    // Forward rotation: in quadrature, B is low when A rises forwards and high when it
    // rises backwards. Lines 0..=K: the last A rise before z1, and those up to z2.
    let line0 = b_at_a_rise
        .iter()
        .rposition(|(i, _)| *i < z1)
        .expect("line 0");
    for (m, (i, b)) in b_at_a_rise[line0..].iter().enumerate() {
        if *i > z2 {
            break;
        }
        if *b != vcd::Value::V0 {
            return Err(bad(format!(
                "--vcd {}: {} is {} at the A rising edge of line {m} ({}): the shaft turns \
                 backwards there, or A and B are swapped; identification needs forward \
                 rotation at constant speed",
                path.display(),
                name_of(1),
                match b {
                    vcd::Value::V1 => "high",
                    _ => "unknown (x/z)",
                },
                at(edges[*i].t)
            )));
        }
    }
    let ticks = revolution_periods(&edges, k, None)
        .map_err(|e| bad(format!("--vcd {}: {e}", path.display())))?;
    let periods: Vec<f64> = ticks.iter().map(|p| p * tick_s).collect();
    let source = format!(
        "VCD {}: signals {}, {}, {} (timescale {scale} {unit}); revolution from the Z rising \
         edge at {} to the one at {}",
        path.display(),
        name_of(0),
        name_of(1),
        name_of(2),
        at(edges[z1].t),
        at(edges[z2].t),
    );
    Ok(Revolution {
        periods,
        source,
        truth: None,
    })
}

/// One method's result.
struct Row {
    label: &'static str,
    csv_name: &'static str,
    e: f64,
    /// rad, [0, 2π).
    theta0: f64,
}

/// Everything printed.
struct Report {
    lines: u32,
    model: Model,
    radius_mm: Option<f64>,
    source: String,
    truth: Option<Eccentricity>,
    rows: Vec<Row>,
    fit2: HarmonicFit,
    mean_period_s: f64,
    mean_rpm: f64,
}

/// Index of the recommended row (the harmonic fit, first harmonic).
const FIT_ROW: usize = 2;

impl Report {
    fn new(
        rev: &Revolution,
        lines: u32,
        model: Model,
        radius_mm: Option<f64>,
    ) -> Result<Self, (u8, String)> {
        let p = &rev.periods;
        let err = |e: EccError| bad(format!("identification: {e}"));
        let paper = paper_identify(p).map_err(err)?.identified();
        let ratio = ratio_identify(p).map_err(err)?;
        let fit = harmonic_fit(p, FitOptions::default()).map_err(err)?;
        let fit2 = harmonic_fit(
            p,
            FitOptions {
                second_harmonic: true,
                trend: false,
            },
        )
        .map_err(err)?;
        let (id, id2) = (fit.identified(model), fit2.identified(model));
        // K line periods are one shaft revolution on the rigid disc, 1/(1 − e²/2) of one on
        // Zhao's plant (it loses counts).
        let per_rev =
            Eccentricity::new(model, id.e, id.theta0).map_or(1.0, |x| x.apparent_per_rev());
        let mean_rpm = 60.0 / (f64::from(lines) * fit.mean) / per_rev;
        let row = |label, csv_name, e, theta0| Row {
            label,
            csv_name,
            e,
            theta0,
        };
        Ok(Self {
            lines,
            model,
            radius_mm,
            source: rev.source.clone(),
            truth: rev.truth,
            rows: vec![
                row(
                    "paper, eqs. (17)-(20) as printed",
                    "paper",
                    paper.e,
                    paper.theta0,
                ),
                row("ratio T_max/T_min", "ratio", ratio.e, ratio.theta0),
                row(
                    "harmonic fit (recommended)",
                    "harmonic_fit",
                    id.e,
                    id.theta0,
                ),
                row(
                    "harmonic fit + 2nd harmonic",
                    "harmonic_fit_2nd",
                    id2.e,
                    id2.theta0,
                ),
            ],
            fit2,
            mean_period_s: fit.mean,
            mean_rpm,
        })
    }

    /// Corrector coefficients of e, θ0: E = K·e/(2π) lines, E·cos θ0, E·sin θ0, and the
    /// phase as a line offset m0 = K·θ0/(2π).
    fn coefficients(&self, row: &Row) -> (f64, f64, f64, f64) {
        let k = f64::from(self.lines);
        let big_e = k * row.e / TAU;
        (
            big_e,
            big_e * row.theta0.cos(),
            big_e * row.theta0.sin(),
            k * row.theta0 / TAU,
        )
    }

    /// Relative error of e and error of θ0 (degrees) against the scenario's plant.
    fn errors(&self, row: &Row) -> Option<(Option<f64>, f64)> {
        self.truth.map(|t| {
            (
                (t.e > 0.0).then(|| row.e / t.e - 1.0),
                phase_difference(row.theta0, t.theta0).to_degrees(),
            )
        })
    }

    fn table(&self) -> String {
        let mut s = String::new();
        let k = self.lines;
        let _ = writeln!(s, "{}", self.source);
        let _ = writeln!(
            s,
            "{k} line periods from line 0 (the A rising edge before the Z rising edge) to \
             line {k}: mean period {:.6e} s, mean speed {:.6} r/min; e read through the \
             {} model",
            self.mean_period_s,
            self.mean_rpm,
            model_name(self.model)
        );
        let _ = writeln!(s);
        let mut head = format!("{:<34} {:>12} {:>10}", "method", "e", "e (%)");
        if self.radius_mm.is_some() {
            let _ = write!(head, " {:>10}", "ΔR (mm)");
        }
        let _ = write!(head, " {:>10}", "θ0 (deg)");
        if self.truth.is_some() {
            let _ = write!(head, " {:>12} {:>12}", "e error (%)", "θ0 err (deg)");
        }
        let _ = writeln!(s, "{head}");
        for row in &self.rows {
            let _ = write!(
                s,
                "{:<34} {:>12.8} {:>10.5}",
                row.label,
                row.e,
                row.e * 100.0
            );
            if let Some(r) = self.radius_mm {
                let _ = write!(s, " {:>10.5}", row.e * r);
            }
            let _ = write!(s, " {:>10.4}", row.theta0.to_degrees());
            if let Some((de, dt)) = self.errors(row) {
                let de = de.map_or("-".to_string(), |d| format!("{:+.5}", d * 100.0));
                let _ = write!(s, " {de:>12} {dt:>+12.5}");
            }
            let _ = writeln!(s);
        }
        let f2 = &self.fit2;
        let _ = writeln!(
            s,
            "(2nd harmonic of the periods: a2 = {:.4e} at p2 = {:.3}°; Zhao's plant gives \
             e²/2 at 2θ0 + 180°, the rigid disc none)",
            f2.a2,
            f2.p2.to_degrees()
        );
        let fit = &self.rows[FIT_ROW];
        let (big_e, c, sn, m0) = self.coefficients(fit);
        let _ = writeln!(s);
        let _ = writeln!(
            s,
            "corrector coefficients (harmonic fit): E = K·e/(2π) = {big_e:.6} lines at \
             θ0 = {:.4}° (m0 = K·θ0/(2π) = {m0:.3} lines); E·cos θ0 = {c:.6} lines, \
             E·sin θ0 = {sn:.6} lines",
            fit.theta0.to_degrees()
        );
        s
    }

    fn csv(&self) -> String {
        let mut s = String::from(
            "method,recommended,e,e_percent,delta_r_mm,theta0_deg,e_error_rel,\
             theta0_error_deg,E_lines,E_cos_lines,E_sin_lines,m0_lines,mean_period_s,mean_rpm\n",
        );
        for (i, row) in self.rows.iter().enumerate() {
            let (big_e, c, sn, m0) = self.coefficients(row);
            let (de, dt) = match self.errors(row) {
                Some((de, dt)) => (de.map_or(String::new(), |d| d.to_string()), dt.to_string()),
                None => (String::new(), String::new()),
            };
            let _ = writeln!(
                s,
                "{},{},{},{},{},{},{de},{dt},{big_e},{c},{sn},{m0},{},{}",
                row.csv_name,
                i == FIT_ROW,
                row.e,
                row.e * 100.0,
                self.radius_mm
                    .map_or(String::new(), |r| (row.e * r).to_string()),
                row.theta0.to_degrees(),
                self.mean_period_s,
                self.mean_rpm
            );
        }
        s
    }
}

fn write_file(path: &Path, text: &str) -> Outcome {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| (1, format!("{}: {e}", dir.display())))?;
    }
    std::fs::write(path, text).map_err(|e| {
        (
            1,
            format!("identify: cannot write CSV {}: {e}", path.display()),
        )
    })
}
