// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::pulse_cell`.

use golden::bus::ecc_regmap::ECC_CTRL;
use hdl::bus::pulse_cell::*;

#[test]
fn synthesises_and_lints_clean() {
    let (_, ecc) = crate::support::maps();
    let ctrl = ecc.iter().find(|r| r.offset == ECC_CTRL).unwrap();
    let cell = PulseCell::new(ctrl, ctrl.field("IDENT_ARM").mask());
    crate::support::synthesises_and_lints("encspeed_pulse_cell", cell);
}

#[test]
#[should_panic(expected = "is not a set of its fields")]
fn refuses_bits_outside_the_fields() {
    let (map, _) = crate::support::maps();
    PulseCell::new(map.reg("STATUS"), 1 << 31);
}
