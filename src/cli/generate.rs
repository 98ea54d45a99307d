// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed generate`: write every file of every shipped top (`hdl::Top::ALL`): for each
//! top its Verilog, manifest (`.toml`), instantiation template (`_inst.v`) and Verilator
//! waivers (`.vlt`), and the C headers of the Wishbone tops; the eccentricity tops only for a
//! multiple of 4 lines; then the board tops (`generated/encspeed_board_<board>.v`, the IP at
//! each board's clock: `golden::board::boards`), except with `--prefix`, which renames
//! every module, macro and file of the IP (`hdl::Prefix`) for use inside another design.

use clap::Args;
use golden::board::boards::Board;
use golden::params::Params;
use hdl::{Prefix, Top};
use std::path::{Path, PathBuf};

use super::spec::SpecArgs;
use super::Outcome;

/// Options of `encspeed generate`.
#[derive(Args)]
pub struct GenerateArgs {
    #[command(flatten)]
    spec: SpecArgs,
    /// Output directory.
    #[arg(long, default_value = "generated")]
    out: PathBuf,
    /// Put this in front of every module name, C macro and file name, so that several
    /// configurations load into one design (e.g. acme_: module acme_encspeed_core in
    /// acme_encspeed_core.v, macros ACME_ENCSPEED_*).
    #[arg(long, default_value = "")]
    prefix: String,
}

/// `encspeed generate`.
pub fn run(args: &GenerateArgs) -> Outcome {
    let prefix = Prefix::new(&args.prefix).map_err(|e| (2, e))?;
    args.spec.run(|p| generate(p, &prefix, &args.out))
}

/// Every file of every shipped top ([`hdl::Top::ALL`]) into `out`. A top the parameters
/// cannot have (the eccentricity tops need a multiple of 4 lines) is reported on stderr
/// and the others are written.
fn generate(p: &Params, prefix: &Prefix, out: &Path) -> Outcome {
    let write = |name: &str, text: &str| {
        std::fs::create_dir_all(out)
            .and_then(|_| std::fs::write(out.join(name), text))
            .map_err(|e| (1, format!("cannot write {}: {e}", out.join(name).display())))
    };
    let mut written = Vec::new();
    let mut refused: Vec<(String, String)> = Vec::new();
    for top in Top::ALL {
        match top.files_prefixed(p, prefix) {
            Ok(files) => {
                for (name, text) in files {
                    write(&name, &text)?;
                    written.push(out.join(name).display().to_string());
                }
            }
            Err(why) => refused.push((prefix.file_name(&top.verilog_file()), why)),
        }
    }
    // The board tops: bitstream tops, not IP for another design, so no prefix.
    if prefix.is_empty() {
        let command = golden::provenance::generate_command(p);
        for board in Board::ALL {
            match hdl::emit::boards::board_files(board, p.spec(), &command) {
                Ok(files) => {
                    for (name, text) in files {
                        write(&name, &text)?;
                        written.push(out.join(name).display().to_string());
                    }
                }
                Err(why) => refused.push((format!("{}.v", board.module()), why)),
            }
        }
    }
    // One line per reason: "encspeed_ecc.v and encspeed_ecc_wb.v not written: ...".
    let mut reasons: Vec<&str> = refused.iter().map(|(_, why)| why.as_str()).collect();
    reasons.dedup();
    for why in reasons {
        let names: Vec<&str> = refused
            .iter()
            .filter(|(_, w)| w == why)
            .map(|(n, _)| n.as_str())
            .collect();
        eprintln!("{} not written: {why}", names.join(" and "));
    }
    println!(
        "wrote {} ({}-bit counters, dt = {} cycles, ω_lim = {} rev/s)",
        written.join(", "),
        p.counter_bits(),
        p.dt_cycles(),
        p.omega_lim_rps()
    );
    Ok(())
}
