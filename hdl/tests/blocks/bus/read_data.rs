// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::read_data`.

use hdl::bus::read_data::*;

#[test]
fn synthesises_and_lints_clean() {
    crate::support::synthesises_and_lints("encspeed_read_data", ReadData::default());
}
