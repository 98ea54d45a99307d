// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::reg_file`.

use hdl::bus::reg_file::*;

#[test]
fn synthesises_and_lints_clean() {
    let (map, _) = crate::support::maps();
    let file = RegFile::new(map.reg("IRQ_ENABLE"), map.reg("IRQ_STATUS"));
    crate::support::synthesises_and_lints("encspeed_reg_file", file);
}
