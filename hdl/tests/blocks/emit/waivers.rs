// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::emit::waivers`.

use hdl::emit::tops::Top;
use hdl::emit::waivers::*;

/// Every waiver of a top names that top's file and no other.
#[test]
fn each_top_waives_only_its_own_file() {
    for top in Top::ALL {
        let w = waivers(top);
        assert!(w.starts_with("`verilator_config\n"));
        assert_eq!(w.matches("`verilator_config").count(), 1, "{top:?}");
        let rules: Vec<&str> = w.lines().filter(|l| l.starts_with("lint_off")).collect();
        assert!(!rules.is_empty());
        for rule in rules {
            assert!(
                rule.contains(&format!("-file \"*{}\"", top.verilog_file())),
                "{top:?}: {rule}"
            );
        }
    }
}
