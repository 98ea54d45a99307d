// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::arith::two_cycle_adder`.

use hdl::arith::two_cycle_adder::*;

#[test]
fn synthesises_and_lints_clean() {
    crate::support::synthesises_and_lints(
        "encspeed_two_cycle_adder",
        TwoCycleAdder::<49>::default(),
    );
    crate::support::synthesises_and_lints(
        "encspeed_two_cycle_adder_5",
        TwoCycleAdder::<5>::default(),
    );
    crate::support::synthesises_and_lints(
        "encspeed_two_cycle_adder_127",
        TwoCycleAdder::<127>::default(),
    );
}
