// SPDX-License-Identifier: MIT OR Apache-2.0
//! The once-per-revolution ripple of `encspeed_ecc` on a rigid eccentric disc, before and
//! after correction, as in Zhao's Figs. 6 and 7: the run's stimulus, the relative errors of
//! the M/T and n3 estimates against the true mean speed, their figures and budgets, a CSV
//! and an SVG. Used by the test `tb/tests/ecc_top.rs` (which also checks every strobe of
//! the Verilog against the bit-true model) and by `encspeed ecc-ripple` (the figures of
//! docs/eccentricity-hardware.md). Every run also arms the Verilog's identification at
//! its first index ([`Identification`]), and a run can load the corrector with the e and
//! θ0 that the Verilog identified ([`RippleSetup::loaded`]): the whole loop of the IP.

use crate::ecc_verilator::{EccStrobe, EccVerilated, EventLog, EventRun};
use golden::ecc::ecc_delta::coefficients;
use golden::ecc::ident_gatherer::{error_budget, identify_from_sums, GatherOutputs};
use golden::eccentric::correct::once_per_rev;
use golden::eccentric::identify::Identified;
use golden::eccentric::motion::EccentricDisc;
use golden::eccentric::{Eccentricity, Model};
use golden::estimator::bounds::n3_error_budget;
use golden::ideal::plant::{Profile, Sample};
use golden::params::Params;
use golden::top::ports::Latency;
use plotters::prelude::*;
use std::f64::consts::TAU;
use std::path::Path;

/// Shaft angle, in revolutions, at which a run starts: just before line 0, so that the
/// first index edge (cfg_z_mode = 1) aligns the position at once.
pub const START_ANGLE_REV: f64 = -0.01;

/// A constant-speed run on a rigid eccentric disc, x1 decoding, cfg_z_mode = 1, the
/// corrector loaded with the coefficients (`golden::ecc::ecc_delta::coefficients`) of the disc's
/// own e and θ0 or of identified ones.
#[derive(Clone, Copy, Debug)]
pub struct RippleSetup {
    /// Shaft speed, r/min.
    pub rpm: f64,
    /// Whole revolutions measured after the first index.
    pub revs: f64,
    /// Eccentricity e = ΔR/R.
    pub e: f64,
    /// Eccentricity angle θ0, rad.
    pub theta0: f64,
    /// (e, θ0 in rad) the corrector is loaded with; `None`: the disc's own.
    pub loaded: Option<(f64, f64)>,
}

/// The encoder levels of a run and where its measurement starts.
pub struct Stimulus {
    /// Levels at cycle 0.
    pub initial: Sample,
    /// (cycle, levels from it on).
    pub changes: Vec<(u64, Sample)>,
    /// Cycles to run.
    pub cycles: u64,
    /// The first index edge has been processed by this cycle (its Z rise plus the
    /// documented edge-to-position latency): estimates strobed after it count from line 0.
    pub aligned_after: u64,
}

impl RippleSetup {
    fn rps(&self) -> f64 {
        self.rpm / 60.0
    }

    /// The encoder levels of the run for `p`: the revolutions and 3 % more.
    pub fn stimulus(&self, p: &Params) -> Result<Stimulus, String> {
        let duration = (self.revs + 0.03) / self.rps();
        let profile = Profile::constant(self.rps(), duration)
            .and_then(|x| x.with_initial_angle(START_ANGLE_REV))
            .map_err(|e| format!("ripple run: {e:?}"))?;
        let ecc = Eccentricity::new(Model::Rigid, self.e, self.theta0)
            .map_err(|e| format!("ripple run: {e:?}"))?;
        let disc = EccentricDisc::new(p.lines(), ecc).map_err(|e| format!("ripple run: {e:?}"))?;
        let (initial, changes) = disc.clock_changes(&profile, p.spec().clock_hz);
        let z_rise = changes
            .iter()
            .find(|c| c.1.z)
            .ok_or("ripple run: no index edge")?
            .0;
        Ok(Stimulus {
            initial,
            changes,
            cycles: (duration * p.spec().clock_hz) as u64,
            aligned_after: z_rise + u64::from(Latency::new(p, 0).edge_to_position),
        })
    }

    /// `(ecc_c, ecc_d)` the corrector is loaded with.
    pub fn coefficients(&self, p: &Params) -> (i64, i64) {
        let (e, theta0) = self.loaded.unwrap_or((self.e, self.theta0));
        coefficients(p.lines(), e, theta0)
    }

    /// The event-mode configuration of the run.
    pub fn event_run(&self, p: &Params, cycles: u64) -> EventRun {
        let (ecc_c, ecc_d) = self.coefficients(p);
        EventRun {
            cycles,
            cfg_dt: 0,
            cfg_mode: 0,
            cfg_z_mode: 1,
            ecc_c,
            ecc_d,
            arm_delay: Some(0),
        }
    }
}

/// The Verilog's identification of one revolution, against the disc's e and θ0.
#[derive(Clone, Copy, Debug)]
pub struct Identification {
    /// Cycle at which `ident_done` rose.
    pub cycle: u64,
    /// The gathered results.
    pub gathered: GatherOutputs,
    /// e and θ0 from the sums (`golden::ecc::ident_gatherer::identify_from_sums`).
    pub identified: Identified,
    /// Identified − true e.
    pub e_error: f64,
    /// Identified − true θ0, rad, wrapped to ±π.
    pub theta0_error: f64,
    /// `golden::ecc::ident_gatherer::error_budget`: (e, θ0 rad).
    pub budget: (f64, f64),
}

impl Identification {
    /// The first identification of `log` for `setup` on `p`, if any.
    pub fn of(p: &Params, setup: &RippleSetup, log: &EventLog) -> Option<Self> {
        let &(cycle, g) = log.ident.first()?;
        let identified = identify_from_sums(p.lines(), g.sum_t, g.sum_sin, g.sum_cos, Model::Rigid);
        let pi = std::f64::consts::PI;
        Some(Identification {
            cycle,
            gathered: g,
            identified,
            e_error: identified.e - setup.e,
            theta0_error: (identified.theta0 - setup.theta0 + pi).rem_euclid(TAU) - pi,
            budget: error_budget(g.sum_t as f64, setup.e),
        })
    }

    /// Ok when e and θ0 are both within their budget; else the summary.
    pub fn within_budget(&self) -> Result<(), String> {
        if self.e_error.abs() <= self.budget.0 && self.theta0_error.abs() <= self.budget.1 {
            Ok(())
        } else {
            Err(format!("outside the budget: {}", self.summary()))
        }
    }

    /// One line: e and θ0 identified, their errors and budgets.
    pub fn summary(&self) -> String {
        format!(
            "identified on the Verilog ({} lines, {} cycles): e = {:.8} (error {:+.2e}, {:+.4} %, budget {:.2e}), theta0 = {:.5} deg (error {:+.2e} deg, budget {:.2e} deg)",
            self.gathered.count,
            self.gathered.sum_t,
            self.identified.e,
            self.e_error,
            self.e_error / (self.identified.e - self.e_error) * 100.0,
            self.budget.0,
            self.identified.theta0.to_degrees(),
            self.theta0_error.to_degrees(),
            self.budget.1.to_degrees()
        )
    }
}

/// Identify the disc of `setup` on the Verilog: a run of 2.1 revolutions (the first index
/// aligns the position and arms the gatherer, the next two bound the revolution it
/// gathers).
pub fn identify_on_verilog(
    sim: &EccVerilated,
    p: &Params,
    setup: &RippleSetup,
) -> Result<Identification, String> {
    let short = RippleSetup {
        revs: 2.1,
        ..*setup
    };
    let (log, _) = run_verilog(sim, p, &short)?;
    Identification::of(p, setup, &log).ok_or_else(|| "no identification in 2.1 revolutions".into())
}

/// Figures of (shaft angle, relative error) samples over whole revolutions.
#[derive(Clone, Copy, Debug)]
pub struct Figures {
    /// Samples.
    pub n: usize,
    /// Once-per-revolution amplitude, ppm.
    pub h1_ppm: f64,
    /// Peak to peak, ppm.
    pub pp_ppm: f64,
    /// Largest |error|, ppm.
    pub worst_ppm: f64,
}

/// The figures of `v`.
pub fn figures(v: &[(f64, f64)]) -> Figures {
    let max = v.iter().map(|x| x.1).fold(f64::NEG_INFINITY, f64::max);
    let min = v.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
    Figures {
        n: v.len(),
        h1_ppm: once_per_rev(v) * 1e6,
        pp_ppm: (max - min) * 1e6,
        worst_ppm: max.abs().max(min.abs()) * 1e6,
    }
}

/// One n3 estimate: shaft angle (rad, from the first kept), relative error, and Rairán's
/// bound for the hardware at its own n1 = Nep1/Ndt1 (`golden::estimator::bounds::n3_error_budget`).
#[derive(Clone, Copy, Debug)]
pub struct N3Sample {
    /// Shaft angle, rad.
    pub angle: f64,
    /// n3/r − 1.
    pub error: f64,
    /// Its bound.
    pub bound: f64,
}

/// The relative errors of one run, over `revs` whole revolutions from the first estimate
/// after the index.
pub struct Ripple {
    /// The setup.
    pub setup: RippleSetup,
    /// True speed in lines per dt.
    pub r: f64,
    /// speed_mt: (angle, relative error).
    pub mt_before: Vec<(f64, f64)>,
    /// speed_mtc.
    pub mt_after: Vec<(f64, f64)>,
    /// speed_n3.
    pub n3_before: Vec<N3Sample>,
    /// speed_n3c.
    pub n3_after: Vec<N3Sample>,
    /// Budget of one corrected M/T estimate, ppm: M/T's 1/T̂ (T̂ ≥ dt − one line period,
    /// and at least one line period less the eccentricity's 2e) and ½ LSB, plus the
    /// first-order residual e³/3 (0.5 ppm) and δ's rounding (< 0.1 ppm).
    pub mt_budget_ppm: f64,
}

impl Ripple {
    /// The relative errors of the strobes of a run of `setup` on `p`, keeping those after
    /// `aligned_after`.
    pub fn new(p: &Params, setup: RippleSetup, strobes: &[EccStrobe], aligned_after: u64) -> Self {
        let clock = p.spec().clock_hz;
        let dt = p.dt_cycles() as f64;
        let rps = setup.rps();
        let r = rps * f64::from(p.lines()) * dt / clock;
        let lsb = 2f64.powi(p.speed_frac_bits() as i32);
        // Shaft angle since the index was processed: one origin for every series.
        let angle = |k: u64| TAU * rps * (k - aligned_after) as f64 / clock;
        let kept = || strobes.iter().filter(|s| s.cycle > aligned_after);
        // Whole revolutions from each series' first estimate (the 1/rev DFT bin is exact
        // over whole revolutions).
        let revs = setup.revs;
        // M/T reports 0 for a window that has no measured interval (the first after reset):
        // not an estimate of a turning shaft, so not counted.
        let mt = |f: fn(&EccStrobe) -> Option<i64>| -> Vec<(f64, f64)> {
            let v = kept()
                .filter_map(|s| {
                    f(s).filter(|&x| x != 0)
                        .map(|x| (angle(s.cycle), x as f64 / lsb / r - 1.0))
                })
                .collect();
            whole_revolutions(v, |x| x.0, revs)
        };
        let n3 = |f: fn(&EccStrobe) -> Option<i64>| -> Vec<N3Sample> {
            let v = kept()
                .filter_map(|s| {
                    f(s).map(|x| {
                        let n1 = s.speed_nep as f64 / s.speed_ndt.max(1) as f64;
                        N3Sample {
                            angle: angle(s.cycle),
                            error: x as f64 / lsb / r - 1.0,
                            bound: n3_error_budget(n1, p.dt_cycles()),
                        }
                    })
                })
                .collect();
            whole_revolutions(v, |x| x.angle, revs)
        };
        let line_period = clock / (rps * f64::from(p.lines()));
        let t_min = (dt - line_period).max(line_period * (1.0 - 2.0 * setup.e));
        Ripple {
            setup,
            r,
            mt_before: mt(|s| s.speed_mt),
            mt_after: mt(|s| s.speed_mtc),
            n3_before: n3(|s| s.speed_n3),
            n3_after: n3(|s| s.speed_n3c),
            mt_budget_ppm: (1.0 / t_min + 0.5 / lsb / r) * 1e6 + 0.6,
        }
    }

    /// (angle, error) of n3 samples.
    pub fn errors(v: &[N3Sample]) -> Vec<(f64, f64)> {
        v.iter().map(|s| (s.angle, s.error)).collect()
    }

    /// The largest |error|/bound of n3 samples.
    pub fn worst_over_bound(v: &[N3Sample]) -> f64 {
        v.iter()
            .map(|s| s.error.abs() / s.bound)
            .fold(0.0, f64::max)
    }

    /// A table row: figures before and after for M/T and n3.
    pub fn summary(&self) -> String {
        let (b, a) = (figures(&self.mt_before), figures(&self.mt_after));
        let (nb, na) = (
            figures(&Self::errors(&self.n3_before)),
            figures(&Self::errors(&self.n3_after)),
        );
        format!(
            "{} r/min, r = {:.3} lines/dt\n\
             M/T: {} estimates; 1/rev {:.1} -> {:.3} ppm ({:.0}x); p-p {:.1} -> {:.2} ppm; \
             worst after {:.2} ppm = {:.3} of its budget {:.2} ppm\n\
             n3:  {} estimates; 1/rev {:.1} -> {:.1} ppm; p-p {:.1} -> {:.1} ppm; \
             worst/bound {:.3} -> {:.3}",
            self.setup.rpm,
            self.r,
            a.n,
            b.h1_ppm,
            a.h1_ppm,
            b.h1_ppm / a.h1_ppm,
            b.pp_ppm,
            a.pp_ppm,
            a.worst_ppm,
            a.worst_ppm / self.mt_budget_ppm,
            self.mt_budget_ppm,
            na.n,
            nb.h1_ppm,
            na.h1_ppm,
            nb.pp_ppm,
            na.pp_ppm,
            Self::worst_over_bound(&self.n3_before),
            Self::worst_over_bound(&self.n3_after),
        )
    }

    /// CSV of every sample: series (mt, mtc, n3, n3c), shaft angle since the index (rad),
    /// relative error (ppm).
    pub fn csv(&self) -> String {
        let mut out = String::from("series,angle_rad,error_ppm\n");
        let n3b = Self::errors(&self.n3_before);
        let n3a = Self::errors(&self.n3_after);
        for (name, v) in [
            ("mt", &self.mt_before),
            ("mtc", &self.mt_after),
            ("n3", &n3b),
            ("n3c", &n3a),
        ] {
            for x in v.iter() {
                out.push_str(&format!("{name},{:.6},{:.3}\n", x.0, x.1 * 1e6));
            }
        }
        out
    }
}

/// The samples of `v` (in angle order) less than `revs` revolutions after the first.
fn whole_revolutions<T>(v: Vec<T>, angle: impl Fn(&T) -> f64, revs: f64) -> Vec<T> {
    let a0 = v.first().map_or(0.0, &angle);
    v.into_iter()
        .filter(|x| angle(x) < a0 + TAU * revs)
        .collect()
}

/// Run `setup` on the compiled Verilog `sim` for `p` (event mode): every strobe and
/// identification, and the stimulus (with the cycle after which the position is aligned).
pub fn run_verilog(
    sim: &EccVerilated,
    p: &Params,
    setup: &RippleSetup,
) -> Result<(EventLog, Stimulus), String> {
    let stim = setup.stimulus(p)?;
    let log = sim.run_events(
        &setup.event_run(p, stim.cycles),
        stim.initial,
        &stim.changes,
    )?;
    Ok((log, stim))
}

/// Write the figure of `ripple` (Zhao's Figs. 6 and 7): the measured speeds in r/min over
/// the shaft angle, before correction above and after below, M/T and n3 in each.
pub fn draw_svg(path: &Path, title: &str, ripple: &Ripple) -> Result<(), String> {
    if ripple.mt_before.is_empty() || ripple.n3_before.is_empty() {
        return Err("draw_svg: no estimates".into());
    }
    let svg = render(title, ripple).map_err(|e| format!("draw_svg: {e}"))?;
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(path, svg).map_err(|e| format!("{}: {e}", path.display()))
}

type Series = (String, RGBColor, u32, Vec<(f64, f64)>);

fn render(title: &str, ripple: &Ripple) -> Result<String, Box<dyn std::error::Error>> {
    let rpm = ripple.setup.rpm;
    // Speeds in r/min over the shaft angle in degrees.
    let speeds = |v: &[(f64, f64)]| -> Vec<(f64, f64)> {
        v.iter()
            .map(|x| (x.0.to_degrees(), rpm * (1.0 + x.1)))
            .collect()
    };
    let label = |name: &str, v: &[(f64, f64)]| {
        let f = figures(v);
        format!("{name}: 1/rev {:.3} ppm, p-p {:.2} ppm", f.h1_ppm, f.pp_ppm)
    };
    let blue = RGBColor(31, 90, 180);
    let red = RGBColor(200, 60, 40);
    let n3b = Ripple::errors(&ripple.n3_before);
    let n3a = Ripple::errors(&ripple.n3_after);
    let mt = |name: &str, v: &[(f64, f64)]| -> Series { (label(name, v), blue, 2, speeds(v)) };
    let n3 = |name: &str, v: &[(f64, f64)]| -> Series { (label(name, v), red, 1, speeds(v)) };
    let panels: [(&str, Vec<Series>); 3] = [
        (
            "before correction (speed_mt, speed_n3)",
            vec![mt("M/T", &ripple.mt_before), n3("n3", &n3b)],
        ),
        (
            "after correction (speed_mtc, speed_n3c)",
            vec![
                mt("M/T corrected", &ripple.mt_after),
                n3("n3 corrected", &n3a),
            ],
        ),
        (
            "after correction, M/T alone (speed_mtc): what remains is its 1/T quantisation",
            vec![mt("M/T corrected", &ripple.mt_after)],
        ),
    ];
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 1080)).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(title, ("sans-serif", 17))?;
        let x_hi = ripple
            .mt_before
            .iter()
            .chain(&ripple.mt_after)
            .map(|x| x.0)
            .chain(
                ripple
                    .n3_before
                    .iter()
                    .chain(&ripple.n3_after)
                    .map(|s| s.angle),
            )
            .map(f64::to_degrees)
            .fold(0.0, f64::max);
        for (area, (caption, series)) in root.split_evenly((3, 1)).iter().zip(panels) {
            let all = series.iter().flat_map(|s| s.3.iter().map(|x| x.1));
            let (lo, hi) = all.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), y| {
                (l.min(y), h.max(y))
            });
            let pad = ((hi - lo) * 0.12).max(rpm * 1e-6);
            let mut chart = ChartBuilder::on(area)
                .caption(caption, ("sans-serif", 14))
                .margin(12)
                .x_label_area_size(36)
                .y_label_area_size(84)
                .build_cartesian_2d(0.0..x_hi, (lo - pad)..(hi + pad * 2.5))?;
            chart
                .configure_mesh()
                .light_line_style(WHITE)
                .x_desc("shaft angle since the index, degrees")
                .y_desc("speed, r/min")
                .y_label_formatter(&|y| format!("{y:.4}"))
                .draw()?;
            for (name, colour, width, pts) in series {
                let style = colour.stroke_width(width);
                chart
                    .draw_series(LineSeries::new(pts.clone(), style))?
                    .label(name)
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
                chart.draw_series(pts.iter().map(|&p| Circle::new(p, 2, colour.filled())))?;
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .draw()?;
        }
        root.present()?;
    }
    Ok(svg)
}
