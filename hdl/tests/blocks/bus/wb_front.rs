// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::wb_front`.

use hdl::bus::wb_front::*;

#[test]
fn synthesises_and_lints_clean() {
    crate::support::synthesises_and_lints("encspeed_wb_front", WbFront::default());
}
