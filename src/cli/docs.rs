// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed docs`: rewrite the generated pages of docs/ (ports.md, registers.md) for the
//! default parameters.

use clap::Args;
use golden::params::{Params, Spec};
use std::path::{Path, PathBuf};

use super::Outcome;

/// Options of `encspeed docs`.
#[derive(Args)]
pub struct DocsArgs {
    /// The docs directory.
    #[arg(long, default_value = "docs")]
    out: PathBuf,
}

/// `encspeed docs`.
pub fn run(args: &DocsArgs) -> Outcome {
    docs(&args.out)
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
