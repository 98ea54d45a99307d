// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::estimator::speed_calc`.

use hdl::estimator::speed_calc::*;
use rust_hdl::prelude::*;

type Calc = hdl::speed_calc_type!(24, 16);

fn step(uut: &mut Calc, start: bool, nep: u64, ndt: u64, negative: bool) {
    uut.reset.next = false;
    uut.start.next = start;
    uut.nep.next = nep.into();
    uut.ndt.next = ndt.into();
    uut.position.next = 0xDEAD_BEEFu64.into();
    uut.negative.next = negative;
    uut.clock.next = Clock { clk: false };
    assert!(simulate(uut, 100));
    uut.clock.next = Clock { clk: true };
    assert!(simulate(uut, 100));
}

#[test]
fn n3_of_4_over_1_by_hand_in_256_cycles() {
    let mut uut = Calc::default();
    uut.connect_all();
    step(&mut uut, true, 4, 1, false);
    // L = 1 + 3·(2 + 2·41) + 3 = 256: busy after edges 0 (the start) to 255, valid after
    // edge 256, with the request's tag.
    for k in 1..=256 {
        assert!(uut.busy.val() && !uut.valid.val(), "after edge {}", k - 1);
        assert!(!uut.have_speeds.val(), "after edge {}", k - 1);
        step(&mut uut, false, 0, 0, false);
    }
    assert!(uut.valid.val() && !uut.busy.val() && uut.have_speeds.val());
    assert_eq!(uut.speed_position.val().to_u64(), 0xDEAD_BEEF);
    assert_eq!(uut.speed_nep.val().to_u64(), 4);
    assert_eq!(uut.speed_ndt.val().to_u64(), 1);
    // 4, 3 and 24/7 with 16 fractional bits: 262144, 196608, 224694.857… → 224695.
    assert_eq!(uut.speed_n1.val().to_u64(), 262_144);
    assert_eq!(uut.speed_n2.val().to_u64(), 196_608);
    assert_eq!(uut.speed_n3.val().to_u64(), 224_695);
}

#[test]
fn synthesises() {
    let mut uut = Calc::default();
    uut.connect_all();
    yosys_validate("encspeed_speed_calc", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    let lint = |v: String| crate::support::verilator_lint("speed_calc", &v);
    lint(speed_calc_verilog::<8, 0, 17, 9>("speed_calc"));
    lint(speed_calc_verilog::<8, 8, 17, 17>("speed_calc"));
    lint(speed_calc_verilog::<16, 16, 33, 33>("speed_calc"));
    lint(speed_calc_verilog::<24, 16, 49, 41>("speed_calc"));
    lint(speed_calc_verilog::<32, 24, 65, 57>("speed_calc"));
}
