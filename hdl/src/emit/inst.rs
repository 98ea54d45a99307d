// SPDX-License-Identifier: MIT OR Apache-2.0
//! The instantiation template of a shipped top (`generated/<top>_inst.v`): the module
//! instantiated with every port connected to a signal of the same name, each with its
//! direction, width and meaning, to paste into a design. Written from the top's one port
//! list, so it cannot drift from the module; `tb/tests/prefix.rs` compiles each template
//! against its module.

use golden::provenance::{preamble, Comment};
use golden::top::ports::Port;

/// The template for `module` with `ports`; `command` regenerates it, `about` (one line per
/// item) says what the user must know to connect it.
pub fn template(module: &str, ports: &[Port], command: &str, about: &[String]) -> String {
    let mut t = preamble(Comment::Slashes, command);
    t.push_str(&format!(
        "// {module}_inst.v: instantiation template of {module} ({module}.v). Do not edit:\n\
         // copy it into your design and rename the instance and the signals.\n"
    ));
    for line in about {
        t.push_str(&format!("// {line}\n"));
    }
    let name_width = ports.iter().map(|p| p.name.len()).max().unwrap_or(0);
    t.push_str(&format!("{module} u_{module} (\n"));
    for (i, port) in ports.iter().enumerate() {
        let comma = if i + 1 < ports.len() { "," } else { " " };
        let width = if port.width == 1 {
            String::new()
        } else {
            format!(" [{}:0]", port.width - 1)
        };
        t.push_str(&format!(
            "    .{name:<w$} ({name:<w$}){comma} // {dir}{width}: {desc}\n",
            name = port.name,
            w = name_width,
            dir = port.direction,
            desc = port.description
        ));
    }
    t.push_str(");\n");
    t
}
