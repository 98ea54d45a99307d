// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::rw_cell`.

use golden::bus::ecc_regmap::ECC_C;
use hdl::bus::rw_cell::*;

#[test]
fn synthesises_and_lints_clean_narrow_and_full() {
    let (map, ecc) = crate::support::maps();
    // CTRL's RW fields end at HOLD, bit 9.
    let ctrl = RwCell::<10>::new(map.reg("CTRL"));
    crate::support::synthesises_and_lints("encspeed_rw_cell_10", ctrl);
    let c = RwCell::<32>::new(ecc.iter().find(|r| r.offset == ECC_C).unwrap());
    crate::support::synthesises_and_lints("encspeed_rw_cell_32", c);
}

#[test]
#[should_panic(expected = "outside bits")]
fn refuses_fields_above_w() {
    let (map, _) = crate::support::maps();
    RwCell::<2>::new(map.reg("CTRL"));
}
