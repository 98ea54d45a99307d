// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::arith::seq_divider`.

use hdl::arith::seq_divider::*;
use rust_hdl::prelude::*;

fn step<const W: usize>(uut: &mut SeqDivider<W>, start: bool, n: u64, d: u64) {
    uut.reset.next = false;
    uut.start.next = start;
    uut.numerator.next = n.into();
    uut.denominator.next = d.into();
    uut.clock.next = Clock { clk: false };
    assert!(simulate(uut, 100));
    uut.clock.next = Clock { clk: true };
    assert!(simulate(uut, 100));
}

#[test]
fn divides_355_by_113_in_w_cycles() {
    let mut uut = SeqDivider::<16>::default();
    uut.connect_all();
    step(&mut uut, true, 355, 113);
    // Busy after edges 0 (the start) to 15, done after edge 16.
    for k in 1..=16 {
        assert!(uut.busy.val() && !uut.done.val(), "after edge {}", k - 1);
        step(&mut uut, false, 0, 0);
    }
    assert!(!uut.busy.val() && uut.done.val());
    assert_eq!(uut.quotient.val().to_u64(), 3);
    assert_eq!(uut.remainder.val().to_u64(), 16);
    assert!(!uut.div_by_zero.val());
}

#[test]
fn synthesises() {
    let mut uut = SeqDivider::<24>::default();
    uut.connect_all();
    yosys_validate("encspeed_seq_divider", &generate_verilog(&uut)).unwrap();
}

fn lint<const W: usize>() {
    crate::support::verilator_lint("seq_divider", &seq_divider_verilog::<W>("seq_divider"));
}

#[test]
fn verilator_lint_is_clean() {
    lint::<2>();
    lint::<8>();
    lint::<24>();
    lint::<32>();
    lint::<33>();
    lint::<48>();
    lint::<64>();
}
