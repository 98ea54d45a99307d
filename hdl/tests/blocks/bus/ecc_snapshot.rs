// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::ecc_snapshot` (its behaviour: `tb/tests/bus/ecc_regs.rs` and
//! `tb/tests/ecc_wb_top.rs`, against `golden::bus::ecc_regs::EccRegsModel`).

use hdl::bus::ecc_snapshot::*;

#[test]
fn synthesises_and_lints_clean() {
    crate::support::synthesises_and_lints("encspeed_ecc_snapshot", EccSnapshot::<41>::default());
}
