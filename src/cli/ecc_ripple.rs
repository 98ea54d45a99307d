// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed ecc-ripple`: the once-per-revolution ripple of M/T and n3 before and after the
//! eccentricity correction, measured on the emitted encspeed_ecc.v in Verilator.

use clap::Args;
use golden::params::Params;
use std::path::{Path, PathBuf};

use super::spec::SpecArgs;
use super::Outcome;

/// Options of `encspeed ecc-ripple`.
#[derive(Args)]
pub struct EccRippleArgs {
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
}

/// `encspeed ecc-ripple`: the options checked, then the run.
pub fn run(args: EccRippleArgs) -> Outcome {
    let EccRippleArgs {
        spec,
        rpm,
        revs,
        delta_r_mm,
        radius_mm,
        theta0_deg,
        svg,
        csv,
        identify,
    } = args;
    spec.run(|p| {
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
    })
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
