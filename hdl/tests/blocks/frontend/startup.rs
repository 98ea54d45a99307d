// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::frontend::startup`.

use hdl::frontend::startup::*;
use rust_hdl::prelude::*;

/// `hold` after each edge k = 1, 2, … following a reset edge, for filter length `l`.
fn holds(l: u64, edges: usize) -> Vec<bool> {
    let mut uut = Startup::default();
    uut.connect_all();
    let mut out = vec![];
    for k in 0..=edges {
        uut.reset.next = k == 0;
        uut.cfg_filter.next = l.into();
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
        if k > 0 {
            out.push(uut.front_reset.val());
        }
    }
    out
}

#[test]
fn holds_for_two_plus_the_filter_delay() {
    // By hand: after edge j, j edges have passed; the rule holds while j < 2 + max(L, 1)
    // and the register applies it one edge later: held after edge j while j ≤ n.
    for l in [0u64, 1, 2, 5] {
        let h = holds(l, 12);
        let n = (2 + l.max(1)) as usize;
        for (k, &held) in h.iter().enumerate() {
            assert_eq!(held, k < n, "L = {l}, edge {}", k + 1);
        }
    }
}

#[test]
fn raising_the_filter_later_does_not_hold_again() {
    let mut uut = Startup::default();
    uut.connect_all();
    for k in 0..20u64 {
        uut.reset.next = k == 0;
        // Filter 1 until edge 10 (the rule ends after edge 3, the hold after edge 4),
        // then 1000.
        uut.cfg_filter.next = if k < 10 { 1u64 } else { 1000 }.into();
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
        assert_eq!(uut.front_reset.val(), k < 4, "after edge {k}");
    }
}

#[test]
fn synthesises() {
    let mut uut = Startup::default();
    uut.connect_all();
    yosys_validate("encspeed_startup", &generate_verilog(&uut)).unwrap();
}
