// SPDX-License-Identifier: MIT OR Apache-2.0
//! Constant-speed accuracy sweep of the bit-true core: every speed estimator of
//! `encspeed_core` (PC, ET, n1, n3, M/T) against the true speed, with each one's computed
//! error bound.
//!
//! The plant ([`golden::ideal::plant`]) turns a constant shaft speed r·ω_lim into exact A/B/Z edge
//! instants, [`ClockSampler`] samples them at the clock, and the bit-true
//! [`CoreModel`] (which the rust-hdl core and the emitted Verilog reproduce cycle for
//! cycle) runs on them one cycle at a time, without storing the inputs. After settling,
//! each hardware output is read at its own strobe (`speed_strobe` for n1 and n3,
//! `baseline_strobe` for PC, ET and M/T) and its relative error |v − r|/r is accumulated
//! (maximum and RMS). The bounds are computed from the estimators' theory, not fitted:
//! see [`Setup::bound`]. Beside the hardware, the paper's fixed-space estimator (time
//! quantised at dt, [`golden::ideal::fixed_space`] on the exact step instants) is measured
//! on the same motion, for Rairán's comparison.
//!
//! # Setup ([`Setup::standard`])
//! Clock 1 MHz, K = 1000 lines, dt = 10 000 cycles (10 ms), so ω_lim = 1/(K·dt) = 0.1 rev/s
//! = 6 r/min and the sweep 0.01–1000 ω_lim is 0.06–6000 r/min; 24-bit counters, timeout
//! 10 s (1000 dt, ten times the slowest pulse period). The same clock and dt serve every
//! estimator. The top speed fixes dt: at r ω_lim each of the four quadrature states lasts
//! dt/(4r) cycles, 2.5 cycles at r = 1000. A two-flop synchroniser shows an edge at the
//! first or (metastability resolving late) the second clock edge after it, so a state of
//! Q cycles is seen for at least Q − 1 ≥ 1.5 cycles: at least one sample, never an illegal
//! jump, and decoder steps at least one cycle apart even in x4. dt = 8000 would give exactly
//! 2 cycles; 10 000 keeps a margin and round numbers. The slowest point then has one line
//! per 100 dt = 1 s = 10⁶ cycles, and the run still sees six of its estimates.

use golden::estimator::bounds::{allowed, er3_max, worst_n1};
pub use golden::estimator::bounds::{Allowed, Estimator};
use golden::ideal::fixed_space;
use golden::ideal::plant::{
    edges, initial_levels, Channel, ClockSampler, Disc, Edge, Profile, Segment,
};
use golden::params::{Params, Spec, SPEED_FRAC_BITS};
use golden::top::core::{mode_shift, CoreInputs, CoreModel};
use golden::top::error_budget::output_bound;
use plotters::prelude::*;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// Clock of the standard setup, Hz.
pub const CLOCK_HZ: f64 = 1e6;
/// Lines of the standard setup's disc.
pub const LINES: u32 = 1000;
/// dt of the standard setup, clock cycles (10 ms).
pub const DT_CYCLES: u64 = 10_000;
/// Counter width of the standard setup, bits.
pub const COUNTER_BITS: u32 = 24;
/// Zero-speed timeout of the standard setup, s.
pub const TIMEOUT_S: f64 = 10.0;
/// Slowest speed of the sweep, ω_lim.
pub const R_MIN: f64 = 0.01;
/// Fastest speed of the sweep, ω_lim.
pub const R_MAX: f64 = 1000.0;
/// Default number of speeds: 12 per decade over five decades, both ends included.
pub const DEFAULT_POINTS: usize = 61;
/// Cycles of reset at the start of every run.
pub const RESET_CYCLES: u64 = crate::stimulus::RESET_CYCLES as u64;
/// Estimates measured per point at low speed: step periods after settling.
pub const LOW_SPEED_PERIODS: u64 = 6;
/// dt windows measured per point at high speed.
pub const HIGH_SPEED_WINDOWS: u64 = 30;

/// Clock, disc, dt and decoding mode of a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setup {
    /// Clock, Hz.
    pub clock_hz: f64,
    /// Lines of the disc.
    pub lines: u32,
    /// dt of every estimator, clock cycles (driven on `cfg_dt`).
    pub dt_cycles: u64,
    /// Counter width, bits.
    pub counter_bits: u32,
    /// `cfg_mode`: 0 x1, 1 x2, 2 x4.
    pub cfg_mode: u8,
}

impl Setup {
    /// The standard setup (module docs) in decoding mode `cfg_mode`.
    pub fn standard(cfg_mode: u8) -> Setup {
        assert!(
            cfg_mode < golden::frontend::MODE_INVALID,
            "cfg_mode {cfg_mode}: x1, x2 or x4 (0, 1 or 2)"
        );
        Setup {
            clock_hz: CLOCK_HZ,
            lines: LINES,
            dt_cycles: DT_CYCLES,
            counter_bits: COUNTER_BITS,
            cfg_mode,
        }
    }

    /// Validated core parameters (nominal dt = `dt_cycles`, timeout [`TIMEOUT_S`]).
    pub fn params(&self) -> Params {
        Params::new(Spec {
            clock_hz: self.clock_hz,
            lines: self.lines,
            dt_cycles: self.dt_cycles,
            counter_bits: self.counter_bits,
            timeout_s: TIMEOUT_S,
            ..Spec::default()
        })
        .expect("the accuracy setup is a legal parameter set")
    }

    /// log2 of the decoder steps per line.
    pub fn shift(&self) -> u32 {
        mode_shift(self.cfg_mode)
    }

    /// "x1", "x2" or "x4".
    pub fn mode_name(&self) -> &'static str {
        ["x1", "x2", "x4"][self.shift() as usize]
    }

    /// ω_lim, rev/s.
    pub fn omega_lim_rps(&self) -> f64 {
        golden::params::omega_lim_rps(self.clock_hz, self.lines, self.dt_cycles)
    }

    /// Decoder steps per dt at r ω_lim: the count rate Table 1 and the counters see.
    pub fn steps_per_dt(&self, r: f64) -> f64 {
        r * f64::from(1u32 << self.shift())
    }

    /// Step period at r ω_lim, clock cycles.
    pub fn step_period(&self, r: f64) -> f64 {
        self.dt_cycles as f64 / self.steps_per_dt(r)
    }

    /// Length of each quadrature state at r ω_lim, clock cycles.
    pub fn quarter_cycles(&self, r: f64) -> f64 {
        self.dt_cycles as f64 / (4.0 * r)
    }

    /// What clock quantisation allows for Nep1 and Ndt1 at r ω_lim ([`allowed`]).
    pub fn allowed(&self, r: f64) -> Allowed {
        allowed(self.steps_per_dt(r), self.dt_cycles)
    }

    /// The worst n1 of the allowed range at r ω_lim ([`worst_n1`]).
    pub fn worst_n1(&self, r: f64) -> f64 {
        worst_n1(self.steps_per_dt(r), self.dt_cycles)
    }

    /// The computed bound on the relative error of `est` at a constant r ω_lim in this
    /// decode mode ([`output_bound`]: the estimator's own term, the clock and the output
    /// rounding), the figure the manifests' error budget tables give.
    pub fn bound(&self, est: Estimator, r: f64) -> f64 {
        output_bound(est, r, self.shift(), self.dt_cycles, SPEED_FRAC_BITS)
    }
}

/// `points` speeds from `r_min` to `r_max`, log-spaced, both ends included (decades of
/// the default grid come out exact: 10^e with e a whole number).
pub fn log_speeds(points: usize, r_min: f64, r_max: f64) -> Vec<f64> {
    assert!(
        points >= 2 && r_min > 0.0 && r_max > r_min,
        "bad speed grid"
    );
    let (lo, hi) = (r_min.log10(), r_max.log10());
    (0..points)
        .map(|i| {
            let e = lo + (hi - lo) * i as f64 / (points - 1) as f64;
            let e = if (e - e.round()).abs() < 1e-12 {
                e.round()
            } else {
                e
            };
            10f64.powf(e)
        })
        .collect()
}

/// Start angle of point i in lines: spread over (0.05, 0.95) by the golden ratio, never a
/// whole line, so the first pulse falls at a different phase of the clock at every point.
pub fn start_lines(i: usize) -> f64 {
    0.05 + 0.9 * (0.137 + i as f64 * 0.618_033_988_749_895).fract()
}

/// Error statistics of one estimator at one point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stat {
    /// Samples (strobes after settling that carried an estimate).
    pub samples: u64,
    /// Largest relative error.
    pub max_err: f64,
    /// Sum of squared relative errors.
    pub sum_sq: f64,
    /// The computed bound at this point ([`Setup::bound`]); NaN where none is defined.
    pub bound: f64,
    /// Smallest estimate, ω_lim.
    pub min_est: f64,
    /// Largest estimate, ω_lim.
    pub max_est: f64,
}

impl Stat {
    fn new(bound: f64) -> Stat {
        Stat {
            bound,
            min_est: f64::INFINITY,
            max_est: f64::NEG_INFINITY,
            ..Stat::default()
        }
    }

    fn add(&mut self, est: f64, r: f64) {
        let err = (est - r).abs() / r;
        self.samples += 1;
        self.max_err = self.max_err.max(err);
        self.sum_sq += err * err;
        self.min_est = self.min_est.min(est);
        self.max_est = self.max_est.max(est);
    }

    /// RMS relative error.
    pub fn rms(&self) -> f64 {
        (self.sum_sq / self.samples as f64).sqrt()
    }

    /// Largest error over the bound.
    pub fn ratio(&self) -> f64 {
        self.max_err / self.bound
    }
}

/// What one constant-speed run measured.
#[derive(Clone, Debug, PartialEq)]
pub struct PointResult {
    /// True speed, ω_lim.
    pub r: f64,
    /// Start angle, lines.
    pub start_lines: f64,
    /// Cycles simulated (settling included).
    pub cycles: u64,
    /// Cycles ignored at the start.
    pub settle: u64,
    /// Per estimator, in the order of [`Estimator::ALL`].
    pub stats: [Stat; 5],
    /// The paper's fixed-space estimator: exact step instants, time quantised at dt
    /// ([`fixed_space`] with q = dt), estimates made after settling. Infinite error where
    /// two steps fall between the same two ticks (any r_s > 1).
    pub et_dt: Stat,
    /// Smallest and largest Nep1 after settling.
    pub nep: (u64, u64),
    /// Smallest and largest Ndt1 after settling.
    pub ndt: (u64, u64),
    /// Cycles at which (Nep1, Ndt1) changed after settling.
    pub reg_changes: u64,
    /// Strobes at which `speed_n3` differed from the previous strobe, after settling.
    pub n3_changes: u64,
    /// Largest n3 error over eq. (13) alone at the sample's own n1 = Nep1/Ndt1.
    pub n3_over_eq13: f64,
    /// Baseline windows without a step (M/T outputs 0 there: no estimate, not counted).
    pub mt_empty: u64,
    /// Baseline strobes with `speed_et` = 0 (no period yet) after settling.
    pub et_empty: u64,
    /// A fault flag (illegal transition, overspeed) rose during the run.
    pub fault: bool,
    /// `stalled` was high after settling.
    pub stalled: bool,
    /// `valid` was low at a speed strobe after settling.
    pub invalid: bool,
}

impl PointResult {
    /// The statistics of `est`.
    pub fn stat(&self, est: Estimator) -> &Stat {
        &self.stats[est.index()]
    }
}

/// Instants (s) of the decoder steps of a forward motion: A rising in x1, A edges in x2,
/// A and B edges in x4.
fn step_instants(e: &[Edge], shift: u32) -> Vec<f64> {
    e.iter()
        .filter(|x| match shift {
            0 => x.channel == Channel::A && x.rising,
            1 => x.channel == Channel::A,
            _ => x.channel != Channel::Z,
        })
        .map(|x| x.t)
        .collect()
}

/// Cycles to ignore at r: reset, the first three steps (the first restart may come before
/// the first dt tick, so the first computed n3 can use an unsynchronised Ndt1; the third
/// step's is clean), one more dt and the dividers' latencies.
pub fn settle_cycles(setup: &Setup, r: f64) -> u64 {
    let big = setup.step_period(r).max(setup.dt_cycles as f64).ceil() as u64;
    3 * big + setup.dt_cycles + 1000
}

/// Cycles measured after settling at r: [`HIGH_SPEED_WINDOWS`] dt windows, or
/// [`LOW_SPEED_PERIODS`] step periods if longer.
pub fn measure_cycles(setup: &Setup, r: f64) -> u64 {
    let p = setup.step_period(r).ceil() as u64;
    (HIGH_SPEED_WINDOWS * setup.dt_cycles).max(LOW_SPEED_PERIODS * p)
}

/// Run the core at constant speed r ω_lim from a start angle of `start` lines and measure
/// every estimator after settling.
pub fn run_point(setup: &Setup, r: f64, start: f64) -> PointResult {
    assert!(r > 0.0, "speed must be > 0");
    let p = setup.params();
    let settle = settle_cycles(setup, r);
    let n_cycles = settle + measure_cycles(setup, r);
    let duration = n_cycles as f64 / setup.clock_hz;
    let profile = Profile::new(
        start / f64::from(setup.lines),
        vec![Segment::Constant {
            speed: r * setup.omega_lim_rps(),
            duration,
        }],
    )
    .expect("a constant-speed profile");
    let disc = Disc::new(setup.lines).expect("lines > 0");
    let e = edges(&profile, &disc);
    let sampler = ClockSampler::new(
        initial_levels(&profile, &disc),
        &e,
        setup.clock_hz,
        n_cycles,
    )
    .expect("a legal clock");
    let mut model = CoreModel::new(&p);
    let mut stats = Estimator::ALL.map(|est| Stat::new(setup.bound(est, r)));
    let mut pt = PointResult {
        r,
        start_lines: start,
        cycles: n_cycles,
        settle,
        stats: [Stat::default(); 5],
        et_dt: Stat::new(f64::NAN),
        nep: (u64::MAX, 0),
        ndt: (u64::MAX, 0),
        reg_changes: 0,
        n3_changes: 0,
        n3_over_eq13: 0.0,
        mt_empty: 0,
        et_empty: 0,
        fault: false,
        stalled: false,
        invalid: false,
    };
    let lsb = (-f64::from(SPEED_FRAC_BITS)).exp2();
    let (mut last_regs, mut last_n3) = (None, None);
    for (k, s) in sampler.enumerate() {
        let o = model.step(CoreInputs {
            reset: (k as u64) < RESET_CYCLES,
            enc_a: s.a,
            enc_b: s.b,
            enc_z: s.z,
            cfg_dt: setup.dt_cycles,
            cfg_mode: setup.cfg_mode,
            ..CoreInputs::default()
        });
        pt.fault |= o.fault_illegal || o.fault_overspeed;
        if (k as u64) < settle {
            continue;
        }
        pt.stalled |= o.stalled;
        let regs = (o.nep, o.ndt);
        if last_regs.is_some_and(|l| l != regs) {
            pt.reg_changes += 1;
        }
        last_regs = Some(regs);
        pt.nep = (pt.nep.0.min(o.nep), pt.nep.1.max(o.nep));
        pt.ndt = (pt.ndt.0.min(o.ndt), pt.ndt.1.max(o.ndt));
        if o.speed_strobe {
            pt.invalid |= !o.valid;
            stats[Estimator::N1.index()].add(o.speed_n1 as f64 * lsb, r);
            let n3 = o.speed_n3 as f64 * lsb;
            stats[Estimator::N3.index()].add(n3, r);
            if last_n3.is_some_and(|l| l != o.speed_n3) {
                pt.n3_changes += 1;
            }
            last_n3 = Some(o.speed_n3);
            // At constant speed the registers at the strobe are the ones it was computed
            // from (the next write is at least dt − 1 cycles after the last, far beyond the
            // calculator's latency).
            let n1 = o.nep as f64 / o.ndt as f64;
            pt.n3_over_eq13 = pt.n3_over_eq13.max(((n3 - r).abs() / r) / er3_max(n1));
        }
        if o.baseline_strobe {
            stats[Estimator::Pc.index()].add(o.speed_pc as f64 * lsb, r);
            if o.speed_et == 0 {
                pt.et_empty += 1;
            } else {
                stats[Estimator::Et.index()].add(o.speed_et as f64 * lsb, r);
            }
            if o.speed_mt == 0 {
                pt.mt_empty += 1;
            } else {
                stats[Estimator::Mt.index()].add(o.speed_mt as f64 * lsb, r);
            }
        }
    }
    pt.stats = stats;
    // The paper's ET: ticks of dt between consecutive steps, on the exact instants.
    let dt_s = setup.dt_cycles as f64 / setup.clock_hz;
    let t_settle = settle as f64 / setup.clock_hz;
    let steps = step_instants(&e, setup.shift());
    let scale = f64::from(1u32 << setup.shift());
    for est in fixed_space(&steps, dt_s, dt_s).expect("sorted step instants") {
        if est.t >= t_settle {
            pt.et_dt.add(est.n / scale, r);
        }
    }
    pt
}

/// Run every speed of `speeds` (start angle [`start_lines`]`(i)` for the i-th) on up to
/// `threads` threads; results in the order of `speeds`. Points are taken slowest first
/// (they are the longest), so the threads finish together.
pub fn sweep(setup: &Setup, speeds: &[f64], threads: usize) -> Vec<PointResult> {
    let next = AtomicUsize::new(0);
    let out = Mutex::new(vec![None; speeds.len()]);
    let mut order: Vec<usize> = (0..speeds.len()).collect();
    order.sort_by(|&a, &b| speeds[a].total_cmp(&speeds[b]));
    std::thread::scope(|s| {
        for _ in 0..threads.clamp(1, speeds.len().max(1)) {
            s.spawn(|| loop {
                let j = next.fetch_add(1, Ordering::Relaxed);
                let Some(&i) = order.get(j) else { break };
                let pt = run_point(setup, speeds[i], start_lines(i));
                out.lock().expect("no thread panicked")[i] = Some(pt);
            });
        }
    });
    out.into_inner()
        .expect("no thread panicked")
        .into_iter()
        .map(|p| p.expect("every point ran"))
        .collect()
}

/// Threads to use: the machine's parallelism.
pub fn default_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// The sweep as CSV: one row per speed; per estimator the samples, max and RMS relative
/// error and bound, then the paper's ET at dt and the register ranges.
pub fn to_csv(setup: &Setup, results: &[PointResult]) -> String {
    let mut s = String::from("mode,r,rpm");
    for est in Estimator::ALL {
        let n = est.name();
        s += &format!(",{n}_samples,{n}_max,{n}_rms,{n}_bound");
    }
    s += ",et_dt_samples,et_dt_max,nep_min,nep_max,ndt_min,ndt_max,n3_changes,mt_empty,cycles\n";
    let rpm = setup.omega_lim_rps() * 60.0;
    for p in results {
        s += &format!("{},{},{}", setup.mode_name(), p.r, p.r * rpm);
        for st in &p.stats {
            s += &format!(
                ",{},{:.6e},{:.6e},{:.6e}",
                st.samples,
                st.max_err,
                st.rms(),
                st.bound
            );
        }
        s += &format!(
            ",{},{:.6e},{},{},{},{},{},{},{}\n",
            p.et_dt.samples,
            p.et_dt.max_err,
            p.nep.0,
            p.nep.1,
            p.ndt.0,
            p.ndt.1,
            p.n3_changes,
            p.mt_empty,
            p.cycles
        );
    }
    s
}

/// Per estimator over a sweep: the largest relative error and the r where it occurs, and
/// the largest error/bound and its r.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Worst {
    /// The estimator.
    pub est: Estimator,
    /// Largest max relative error over the points.
    pub max_err: f64,
    /// Speed of `max_err`, ω_lim.
    pub max_err_r: f64,
    /// Largest max error / bound over the points.
    pub max_ratio: f64,
    /// Speed of `max_ratio`, ω_lim.
    pub max_ratio_r: f64,
}

/// [`Worst`] of every estimator, in the order of [`Estimator::ALL`].
pub fn worst(results: &[PointResult]) -> Vec<Worst> {
    Estimator::ALL
        .iter()
        .map(|&est| {
            let mut w = Worst {
                est,
                max_err: 0.0,
                max_err_r: f64::NAN,
                max_ratio: 0.0,
                max_ratio_r: f64::NAN,
            };
            for p in results {
                let s = p.stat(est);
                if s.max_err > w.max_err || w.max_err_r.is_nan() {
                    (w.max_err, w.max_err_r) = (s.max_err, p.r);
                }
                if s.ratio() > w.max_ratio || w.max_ratio_r.is_nan() {
                    (w.max_ratio, w.max_ratio_r) = (s.ratio(), p.r);
                }
            }
            w
        })
        .collect()
}

/// Smallest relative error drawn; smaller ones (exact estimates) are drawn at this floor.
pub const ERROR_FLOOR: f64 = 1e-8;

const COLOURS: [(Estimator, RGBColor); 5] = [
    (Estimator::Pc, RGBColor(230, 140, 0)),
    (Estimator::Et, RGBColor(0, 110, 60)),
    (Estimator::N1, RGBColor(120, 60, 170)),
    (Estimator::N3, RGBColor(0, 70, 200)),
    (Estimator::Mt, RGBColor(200, 30, 30)),
];

fn legend(est: Estimator) -> &'static str {
    match est {
        Estimator::Pc => "PC (fixed time)",
        Estimator::Et => "ET (fixed space, clock-timed)",
        Estimator::N1 => "n1 (Rairán)",
        Estimator::N3 => "n3 (Rairán)",
        Estimator::Mt => "M/T (same as ET for r < 1)",
    }
}

/// Draw the max relative error of every estimator against r (log-log), with the n3 bound
/// and the paper's ET at dt, into an SVG at `path` (900 × 620 px). Deterministic.
pub fn draw_svg(
    path: &Path,
    title: &str,
    setup: &Setup,
    results: &[PointResult],
) -> Result<(), String> {
    if results.is_empty() {
        return Err("draw_svg: no points".into());
    }
    let svg = render(title, setup, results).map_err(|e| format!("draw_svg: {e}"))?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(path, svg).map_err(|e| format!("{}: {e}", path.display()))
}

/// Labels at powers of ten only.
fn decade_label(v: &f64) -> String {
    let e = v.log10();
    if (e - e.round()).abs() < 1e-6 {
        format!("1e{}", e.round() as i32)
    } else {
        String::new()
    }
}

/// Runs of consecutive points above [`ERROR_FLOOR`] (drawn as lines), and the points at or
/// below it (drawn as markers on the floor). Infinite errors are left out.
type Split = (Vec<Vec<(f64, f64)>>, Vec<f64>);

fn split(points: impl Iterator<Item = (f64, f64)>) -> Split {
    let (mut runs, mut floor) = (vec![Vec::new()], Vec::new());
    for (r, e) in points {
        if !e.is_finite() {
            runs.push(Vec::new());
        } else if e <= ERROR_FLOOR {
            floor.push(r);
            runs.push(Vec::new());
        } else {
            runs.last_mut().expect("never empty").push((r, e));
        }
    }
    runs.retain(|run| !run.is_empty());
    (runs, floor)
}

fn render(
    title: &str,
    setup: &Setup,
    results: &[PointResult],
) -> Result<String, Box<dyn std::error::Error>> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 620)).into_drawing_area();
        root.fill(&WHITE)?;
        let r_lo = results.iter().map(|p| p.r).fold(f64::INFINITY, f64::min);
        let r_hi = results.iter().map(|p| p.r).fold(0.0, f64::max);
        let y_hi = results
            .iter()
            .flat_map(|p| p.stats.iter().map(|s| s.max_err))
            .filter(|v| v.is_finite())
            .fold(1.0, f64::max)
            * 3.0;
        let y_lo = ERROR_FLOOR / 2.0;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 17))
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(64)
            .build_cartesian_2d(
                (r_lo / 1.3..r_hi * 1.3).log_scale(),
                (y_lo..y_hi).log_scale(),
            )?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .x_label_formatter(&decade_label)
            .y_label_formatter(&decade_label)
            .x_desc(format!(
                "r = ω/ω_lim (one line per dt = {} ms; ω_lim = {} r/min)",
                setup.dt_cycles as f64 / setup.clock_hz * 1e3,
                setup.omega_lim_rps() * 60.0
            ))
            .y_desc("max relative error")
            .draw()?;
        // The n3 bound as a dense line (a step function of r).
        let dense: Vec<(f64, f64)> = (0..=2000)
            .map(|i| {
                let r = (r_lo.ln() + (r_hi.ln() - r_lo.ln()) * f64::from(i) / 2000.0).exp();
                (r, setup.bound(Estimator::N3, r))
            })
            .collect();
        let bound_style = BLACK.stroke_width(1);
        chart
            .draw_series(DashedLineSeries::new(dense, 6, 4, bound_style))?
            .label("n3 bound: eq. (13) + clock + LSB")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], bound_style));
        let grey = RGBColor(130, 130, 130);
        let mut series: Vec<(String, RGBColor, u32, bool, Split)> = vec![(
            "ET timed in dt (paper's setting; ∞ for r > 1)".into(),
            grey,
            1,
            true,
            split(results.iter().map(|p| (p.r, p.et_dt.max_err))),
        )];
        for (est, colour) in COLOURS {
            let pts = results
                .iter()
                .filter(|p| p.stat(est).samples > 0)
                .map(|p| (p.r, p.stat(est).max_err));
            let width = if est == Estimator::N3 { 3 } else { 1 };
            series.push((legend(est).into(), colour, width, false, split(pts)));
        }
        for (k, (label, colour, width, dashed, (runs, floor))) in series.into_iter().enumerate() {
            // Exact points of the different series stacked a little apart.
            let floor_y = ERROR_FLOOR * 1.6f64.powi(k as i32);
            let style = colour.stroke_width(width);
            for (j, run) in runs.iter().enumerate() {
                let drawn = if dashed {
                    chart.draw_series(DashedLineSeries::new(run.clone(), 2, 3, style))?
                } else {
                    chart.draw_series(LineSeries::new(run.clone(), style))?
                };
                if j == 0 {
                    drawn
                        .label(label.clone())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
                }
                if !dashed {
                    chart.draw_series(run.iter().map(|&p| Circle::new(p, 2, colour.filled())))?;
                }
            }
            chart.draw_series(
                floor
                    .iter()
                    .map(|&r| TriangleMarker::new((r, floor_y), 5, colour.filled())),
            )?;
        }
        chart.draw_series(std::iter::once(Text::new(
            "▲ at the bottom: exact (error 0 or below 1e-8)",
            (r_lo * 1.15, ERROR_FLOOR * 25.0),
            ("sans-serif", 12),
        )))?;
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
    }
    Ok(svg)
}
