// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::emit::wb`.

use golden::bus::regmap;
use golden::params::{Params, Spec};
use hdl::emit::wb::*;

#[test]
fn markdown_keeps_every_register_and_has_one_title() {
    let p = Params::new(Spec::default()).unwrap();
    let md = registers_markdown(&p);
    assert_eq!(md.lines().filter(|l| l.starts_with("# ")).count(), 1);
    for (name, off) in regmap::LAYOUT {
        assert!(md.contains(&format!("### {name} (0x{off:02X})")), "{name}");
    }
    assert_eq!(md, default_registers_markdown());
}
