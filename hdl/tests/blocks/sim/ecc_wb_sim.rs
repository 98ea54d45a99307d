// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::sim::ecc_wb_sim`.

use golden::params::Params;
use golden::params::Spec;
use hdl::sim::ecc_wb_sim::*;

#[test]
fn refuses_line_counts_the_sine_table_cannot_hold() {
    let p = Params::new(Spec {
        lines: 1000 + 2,
        ..Spec::default()
    })
    .unwrap();
    let e = build_ecc_wb(&p)
        .err()
        .expect("K = 1002 is not a multiple of 4");
    assert!(e.contains("encspeed_ecc"), "{e}");
}
