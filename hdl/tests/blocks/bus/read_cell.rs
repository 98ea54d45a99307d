// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::read_cell`.

use golden::bus::ecc_regmap::{IDENT_P, IDENT_SUM_T_W2};
use hdl::bus::read_cell::*;

#[test]
fn synthesises_and_lints_clean_at_each_use() {
    let (map, ecc) = crate::support::maps();
    let at = |off: u32| ecc.iter().find(|r| r.offset == off).unwrap();
    use crate::support::synthesises_and_lints as lint;
    lint(
        "encspeed_read_cell_1",
        ReadCell::<1>::new(map.reg("GLITCH_COUNT")),
    );
    lint(
        "encspeed_read_cell_32",
        ReadCell::<32>::new(map.reg("STATUS")),
    );
    lint(
        "encspeed_read_cell_p",
        ReadCell::<16>::field(at(IDENT_P), "P_MAX"),
    );
    lint(
        "encspeed_read_cell_s",
        ReadCell::<8>::signed(at(IDENT_SUM_T_W2)),
    );
}

#[test]
#[should_panic(expected = "exceed the word")]
fn refuses_a_value_past_bit_31() {
    let (map, _) = crate::support::maps();
    ReadCell::<16>::build(map.reg("STATUS"), 20, false);
}
