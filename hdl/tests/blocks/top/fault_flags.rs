// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::top::fault_flags`.

use crate::support::verilator_lint;
use hdl::top::fault_flags::*;
use rust_hdl::prelude::*;

#[test]
fn flags_are_sticky_until_cleared_and_an_event_wins() {
    let mut uut = FaultFlags::default();
    uut.connect_all();
    // (reset, clear, illegal, rej_a, rej_b, rej_z, rev) → (illegal, overspeed, rev, count)
    type Row = ([bool; 7], (bool, bool, bool, u64));
    let rows: [Row; 6] = [
        (
            [true, false, false, false, false, false, false],
            (false, false, false, 0),
        ),
        (
            [false, false, true, false, true, true, false],
            (true, true, false, 2),
        ),
        (
            [false, false, false, false, false, false, true],
            (true, true, true, 2),
        ),
        (
            [false, true, false, false, false, false, false],
            (false, false, false, 2),
        ),
        (
            [false, true, true, true, true, true, false],
            (true, true, false, 5),
        ),
        (
            [true, false, true, true, true, true, true],
            (false, false, false, 0),
        ),
    ];
    for (k, (i, want)) in rows.iter().enumerate() {
        uut.reset.next = i[0];
        uut.clear_faults.next = i[1];
        uut.illegal.next = i[2];
        uut.rejected_a.next = i[3];
        uut.rejected_b.next = i[4];
        uut.rejected_z.next = i[5];
        uut.rev_fault.next = i[6];
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
        let got = (
            uut.fault_illegal.val(),
            uut.fault_overspeed.val(),
            uut.fault_revolution.val(),
            uut.glitch_count.val().to_u64(),
        );
        assert_eq!(got, *want, "row {k}");
    }
}

/// The count saturates at 2^16 − 1 = 65535 whatever the number of rejections in the
/// cycle that reaches it: 21 844 cycles of three give 65 532, two more give 65 534,
/// three more would be 65 537 and give 65 535, and it stays there.
#[test]
fn the_glitch_count_saturates() {
    let mut uut = FaultFlags::default();
    uut.connect_all();
    let edge = |uut: &mut FaultFlags, reset: bool, rejected: [bool; 3]| {
        uut.reset.next = reset;
        uut.rejected_a.next = rejected[0];
        uut.rejected_b.next = rejected[1];
        uut.rejected_z.next = rejected[2];
        uut.clock.next = Clock { clk: false };
        assert!(simulate(uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(uut, 10));
        uut.glitch_count.val().to_u64()
    };
    edge(&mut uut, true, [false; 3]);
    for _ in 0..21_844 {
        edge(&mut uut, false, [true; 3]);
    }
    assert_eq!(uut.glitch_count.val().to_u64(), 65_532);
    assert_eq!(edge(&mut uut, false, [false, true, true]), 65_534);
    assert_eq!(edge(&mut uut, false, [true; 3]), 65_535);
    assert_eq!(edge(&mut uut, false, [true, false, false]), 65_535);
    assert_eq!(edge(&mut uut, false, [false; 3]), 65_535);
    assert_eq!(edge(&mut uut, true, [true; 3]), 0);
}

#[test]
fn synthesises_and_lints() {
    let mut uut = FaultFlags::default();
    uut.connect_all();
    let v = generate_verilog(&uut);
    yosys_validate("encspeed_fault_flags", &v).unwrap();
    verilator_lint("top", &v);
}
