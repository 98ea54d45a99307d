// SPDX-License-Identifier: MIT OR Apache-2.0
//! The first two lines of every generated file (Verilog, C headers, the TOML manifest, the
//! generated Markdown pages): the command that regenerates it, then the licence as an SPDX
//! identifier, each in the file's comment syntax.

use crate::params::{Params, SpeedOutput};

/// The licence of the repository and of every file it generates.
pub const SPDX: &str = "SPDX-License-Identifier: MIT OR Apache-2.0";

/// The command that rewrites the generated pages of docs/.
pub const DOCS_COMMAND: &str = "encspeed docs";

/// A file's comment syntax.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Comment {
    /// `// …` (Verilog).
    Slashes,
    /// `/* … */` (C).
    Block,
    /// `# …` (TOML).
    Hash,
    /// `<!-- … -->` (Markdown).
    Html,
}

/// The `encspeed` command line that regenerates the files for `p`, every parameter given
/// explicitly so that it stays true whatever the defaults become.
pub fn generate_command(p: &Params) -> String {
    let s = p.spec();
    let mut command = format!(
        "encspeed generate --clock-hz {} --lines {} --dt-cycles {} --counter-bits {} --timeout-s {}",
        s.clock_hz, s.lines, s.dt_cycles, s.counter_bits, s.timeout_s
    );
    // Named only when some are left out, so that the default command stays short.
    if s.estimators != SpeedOutput::ALL {
        command.push_str(&format!(" --estimators {}", p.estimator_list()));
    }
    if s.channels > 1 {
        command.push_str(&format!(" --channels {}", s.channels));
    }
    if !s.identification {
        command.push_str(" --no-identification");
    }
    command
}

/// `Command: <command>` and the SPDX line, as comments of `comment`'s syntax.
pub fn preamble(comment: Comment, command: &str) -> String {
    [format!("Command: {command}"), SPDX.to_string()]
        .iter()
        .map(|line| match comment {
            Comment::Slashes => format!("// {line}\n"),
            Comment::Block => format!("/* {line} */\n"),
            Comment::Hash => format!("# {line}\n"),
            Comment::Html => format!("<!-- {line} -->\n"),
        })
        .collect()
}

/// The command a generated file's first line names, whatever its comment syntax.
pub fn command_of(text: &str) -> Option<&str> {
    let first = text.lines().next()?;
    let inner = first
        .strip_prefix("// ")
        .or_else(|| first.strip_prefix("# "))
        .or_else(|| {
            first
                .strip_prefix("/* ")
                .and_then(|l| l.strip_suffix(" */"))
        })
        .or_else(|| {
            first
                .strip_prefix("<!-- ")
                .and_then(|l| l.strip_suffix(" -->"))
        })?;
    inner.strip_prefix("Command: ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_syntax_names_the_command_first_and_the_licence_second() {
        for c in [
            Comment::Slashes,
            Comment::Block,
            Comment::Hash,
            Comment::Html,
        ] {
            let text = preamble(c, "encspeed docs");
            assert_eq!(command_of(&text), Some("encspeed docs"), "{c:?}");
            let second = text.lines().nth(1).unwrap();
            assert!(second.contains(SPDX), "{c:?}: {second}");
            assert_eq!(text.lines().count(), 2);
        }
    }
}
