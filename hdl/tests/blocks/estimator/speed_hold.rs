// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::estimator::speed_hold`.

use hdl::estimator::speed_hold::*;
use rust_hdl::prelude::*;

#[test]
fn loads_holds_and_clears() {
    let mut uut = SpeedHold::<8>::default();
    uut.connect_all();
    // (clear, load, n3_in) → (n3, strobe, have)
    let rows = [
        ((true, false, 0u64), (0u64, false, false)),
        ((false, true, 7), (7, true, true)),
        ((false, false, 9), (7, false, true)),
        ((true, true, 5), (0, false, false)),
    ];
    for (k, ((clear, load, v), want)) in rows.into_iter().enumerate() {
        uut.clear.next = clear;
        uut.load.next = load;
        uut.n3_in.next = v.into();
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
        let got = (
            uut.n3.val().to_u64(),
            uut.strobe.val(),
            uut.have_speed.val(),
        );
        assert_eq!(got, want, "row {k}");
    }
}

#[test]
fn synthesises() {
    let mut uut = SpeedHold::<41>::default();
    uut.connect_all();
    yosys_validate("encspeed_speed_hold", &generate_verilog(&uut)).unwrap();
}
