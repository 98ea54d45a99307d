// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed`: generate the encoder speed IP, simulate it with waveforms, benchmark it.
//!
//! Exit codes: 0 success, 1 a failed run (tool missing, mismatch), 2 bad parameters or usage.
//!
//! This file holds the command line and the dispatch; each command is in `cli/`.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

mod cli;

use cli::{
    accuracy, bench, bode, check, docs, ecc_ripple, generate, identify, monitor, simulate, synth,
    vectors,
};

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
    /// Emit encspeed_core.v, encspeed_wb.v (the core behind Wishbone, with encspeed_regs.h)
    /// and, for a multiple of 4 lines, encspeed_ecc.v (the core with the eccentricity-corrected
    /// speeds and identification) and encspeed_ecc_wb.v (with encspeed_ecc_regs.h); each top
    /// with its manifest (.toml), instantiation template (_inst.v) and lint waivers (.vlt);
    /// then the board tops encspeed_board_BOARD.v (and .vlt) at the board clock (docs/boards.md).
    Generate(generate::GenerateArgs),
    /// Run a scenario through the rust-hdl design, check it against the golden model on every
    /// cycle, and write a VCD of every signal.
    Simulate(simulate::SimulateArgs),
    /// Measure simulation speed (cycles/s) of the golden model, rust-hdl and Verilator.
    Bench(bench::BenchArgs),
    /// Resource and timing report of the shipped tops on iCE40HX8K and iCE40UP5K: yosys
    /// synth_ice40 cells, nextpnr-ice40 logic cells and Fmax per seed, critical path.
    Synth(synth::SynthArgs),
    /// Measured and model gain/phase of a speed estimator (CSV, SVG).
    ///
    /// The paper's VCO experiment in simulation:
    /// n(t) = rpm·(1 + amplitude·sin 2πft) drives the plant and the golden estimator; the
    /// single DFT bin at f of the held output over the input gives gain and phase, beside
    /// the small-signal model. CSV on stdout (and --csv), a summary on stderr, and an SVG
    /// figure (--svg). See docs/frequency-response.md.
    Bode(bode::BodeArgs),
    /// Rewrite the generated pages of docs/ (ports.md; registers.md) for the default
    /// parameters; a test checks they are current.
    Docs(docs::DocsArgs),
    /// Constant-speed accuracy sweep of every estimator of the bit-true core (CSV, SVG).
    ///
    /// Runs the golden core at log-spaced constant speeds from 0.01 to 1000 ω_lim (1 MHz
    /// clock, 1000 lines, dt = 10 000 cycles: docs/accuracy.md) and reads PC, ET, n1, n3 and
    /// M/T at their strobes after settling: per speed the max and RMS relative error and the
    /// computed bound of each. CSV on stdout, a summary on stderr, the figure (max relative
    /// error against r, log-log, with the n3 bound) to --svg.
    Accuracy(accuracy::AccuracyArgs),
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
    EccRipple(ecc_ripple::EccRippleArgs),
    /// The reference model's expected outputs for a stimulus: runs the bit-true model of
    /// encspeed_core (or encspeed_ecc) on a stimulus CSV or VCD and writes every output port
    /// as CSV (a row at every change) or VCD. See docs/reference-model.md.
    Vectors(vectors::VectorsArgs),
    /// A verdict on another implementation's VCD: runs the model on the inputs its clock
    /// edges sample and compares every output it has, bit for bit, from the first reset.
    /// Exit 0 PASS, 1 mismatches (the first listed), 2 a VCD that cannot be checked. See
    /// docs/reference-model.md.
    Check(check::CheckArgs),
    /// Watch a board top over its serial port: the IP's parameters read from its registers,
    /// then position, the six speeds in r/min and the status flags, one line per interval.
    /// See docs/boards.md.
    Monitor(monitor::MonitorArgs),
}

fn fail(code: u8, msg: impl std::fmt::Display) -> ExitCode {
    eprintln!("encspeed: {msg}");
    ExitCode::from(code)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Cmd::Generate(args) => generate::run(&args),
        Cmd::Simulate(args) => simulate::run(&args),
        Cmd::Docs(args) => docs::run(&args),
        Cmd::Bench(args) => bench::run(&args),
        Cmd::Synth(args) => synth::run(&args),
        Cmd::Bode(args) => bode::run(args),
        Cmd::Accuracy(args) => accuracy::run(&args),
        Cmd::Identify(args) => identify::run(&args),
        Cmd::EccRipple(args) => ecc_ripple::run(args),
        Cmd::Vectors(args) => vectors::run(&args),
        Cmd::Check(args) => check::run(&args),
        Cmd::Monitor(args) => monitor::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err((code, msg)) => fail(code, msg),
    }
}
