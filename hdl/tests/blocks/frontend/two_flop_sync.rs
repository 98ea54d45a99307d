// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::frontend::two_flop_sync`.

use hdl::frontend::two_flop_sync::*;
use rust_hdl::prelude::*;

#[test]
fn delays_by_two_edges_and_resets() {
    let mut uut = TwoFlopSync::default();
    uut.connect_all();
    let input = [1, 0, 1, 1, 0, 0];
    let reset = [0, 0, 0, 1, 0, 0];
    // By hand: out after edge k = in at edge k−1, except cleared through a reset edge.
    let expect = [0, 1, 0, 0, 0, 0];
    for k in 0..input.len() {
        uut.level_in.next = input[k] == 1;
        uut.reset.next = reset[k] == 1;
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
        assert_eq!(uut.level_out.val(), expect[k] == 1, "after edge {k}");
    }
}

#[test]
fn synthesises() {
    let mut uut = TwoFlopSync::default();
    uut.connect_all();
    yosys_validate("encspeed_two_flop_sync", &generate_verilog(&uut)).unwrap();
}
