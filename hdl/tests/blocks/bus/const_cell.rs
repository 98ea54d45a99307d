// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::const_cell`.

use hdl::bus::const_cell::*;

#[test]
fn synthesises_and_lints_clean() {
    let (map, _) = crate::support::maps();
    let cell = ConstCell::new(map.reg("ID"));
    crate::support::synthesises_and_lints("encspeed_const_cell", cell);
}

#[test]
#[should_panic(expected = "has no constant value")]
fn refuses_a_live_register() {
    let (map, _) = crate::support::maps();
    ConstCell::new(map.reg("POSITION"));
}
