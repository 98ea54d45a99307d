// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::frontend::position_counter`.

use crate::support::verilator_lint;
use hdl::frontend::position_counter::*;
use rust_hdl::prelude::*;

/// Reset at edge 0, then (step, forward, z) with R = `cpr`: positions after each edge.
fn run(cpr: u64, z_mode: u64, ins: &[(u8, u8, u8)]) -> Vec<(u64, bool)> {
    let mut uut = PositionCounter::<4, 2>::default();
    uut.connect_all();
    let mut out = vec![];
    // The decoder's `first`: no step since reset, or against the last step.
    let mut last: Option<bool> = None;
    for k in 0..=ins.len() {
        let (s, f, z) = if k == 0 { (0, 0, 0) } else { ins[k - 1] };
        uut.reset.next = k == 0;
        uut.step.next = s == 1;
        uut.forward.next = f == 1;
        uut.first.next = s == 1 && last != Some(f == 1);
        if k == 0 {
            last = None;
        } else if s == 1 {
            last = Some(f == 1);
        }
        uut.z.next = z == 1;
        let (limit, limit_less_one, limit_less_two) =
            golden::frontend::position_counter::limits(cpr, 4);
        uut.limit.next = limit.into();
        uut.limit_less_one.next = limit_less_one.into();
        uut.limit_less_two.next = limit_less_two.into();
        uut.cfg_z_mode.next = z_mode.into();
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 100));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 100));
        if k > 0 {
            out.push((uut.position.val().to_u64(), uut.index.val()));
        }
    }
    out
}

#[test]
fn wraps_and_resets_on_the_index() {
    // R = 3: forward 1 2 0 1, backward 0 2. R = 0 is 2^4 = 16: backward from 0 to 15.
    let f = (1, 1, 0);
    let b = (1, 0, 0);
    let pos = |o: Vec<(u64, bool)>| o.iter().map(|p| p.0).collect::<Vec<_>>();
    assert_eq!(pos(run(3, 0, &[f, f, f, f, b, b])), [1, 2, 0, 1, 0, 2]);
    assert_eq!(pos(run(0, 0, &[b, b, f])), [15, 14, 15]);
    // z sampled high at edge 3 (low at 1, 2): the rise is processed at edge 4, with the
    // step of that edge: position 0 instead of 4.
    let got = run(10, 1, &[f, f, (1, 1, 1), f, f]);
    assert_eq!(
        got,
        [(1, false), (2, false), (3, false), (0, true), (1, false)]
    );
}

#[test]
fn synthesises() {
    let mut uut = PositionCounter::<16, 8>::default();
    uut.connect_all();
    yosys_validate("encspeed_position_counter", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint(
        "position_counter",
        &position_counter_verilog::<16, 8>("position_counter"),
    );
    verilator_lint(
        "position_counter",
        &position_counter_verilog::<1, 1>("position_counter"),
    );
}
