// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::emit::inst`.

use golden::top::ports::Port;
use hdl::emit::inst::*;

#[test]
fn every_port_is_connected_once_in_order() {
    let ports = [
        Port::input("clock", 1, "clock"),
        Port::input("cfg_dt", 24, "dt"),
        Port::output("speed_n3", 41, "n3"),
    ];
    let t = template("encspeed_core", &ports, "encspeed generate", &[]);
    let body: Vec<&str> = t.lines().filter(|l| l.starts_with("    .")).collect();
    assert_eq!(
        body,
        [
            "    .clock    (clock   ), // input: clock",
            "    .cfg_dt   (cfg_dt  ), // input [23:0]: dt",
            "    .speed_n3 (speed_n3)  // output [40:0]: n3",
        ]
    );
    assert!(t.contains("encspeed_core u_encspeed_core (\n"));
    assert!(t.ends_with(");\n"));
}
