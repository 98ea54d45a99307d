// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::shadow_cell`.

use hdl::bus::shadow_cell::*;

#[test]
fn synthesises_and_lints_clean_narrowest_and_widest() {
    let (map, _) = crate::support::maps();
    let (lo, hi) = (map.reg("SPEED_N1_LO"), map.reg("SPEED_N1_HI"));
    crate::support::synthesises_and_lints("encspeed_shadow_11", ShadowCell::<11>::new(lo, hi));
    crate::support::synthesises_and_lints("encspeed_shadow_64", ShadowCell::<64>::new(lo, hi));
}
