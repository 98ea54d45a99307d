// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::frontend::glitch_filter`.

use crate::support::verilator_lint;
use hdl::frontend::glitch_filter::*;
use rust_hdl::prelude::*;

/// Reset at edge 0, then `input` with L = `l`: (level_out, glitches) after each edge.
fn run(l: u64, input: &[u8]) -> Vec<(u8, u64)> {
    let mut uut = GlitchFilter::<8, 2>::default();
    uut.connect_all();
    let mut out = vec![];
    for k in 0..=input.len() {
        uut.reset.next = k == 0;
        uut.level_in.next = k > 0 && input[k - 1] == 1;
        uut.cfg_filter.next = l.into();
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 100));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 100));
        if k > 0 {
            out.push((u8::from(uut.level_out.val()), uut.glitches.val().to_u64()));
        }
    }
    out
}

#[test]
fn rejects_short_pulses_and_passes_long_ones() {
    // L = 4: a 3-cycle pulse (run 1, 2, 3) is rejected and counted when it ends.
    assert_eq!(
        run(4, &[1, 1, 1, 0, 0]),
        [(0, 0), (0, 0), (0, 0), (0, 1), (0, 1)]
    );
    // L = 3: the same pulse passes after its 3rd sample and falls 3 edges after it ends.
    assert_eq!(
        run(3, &[1, 1, 1, 0, 0, 0]),
        [(0, 0), (0, 0), (1, 0), (1, 0), (1, 0), (0, 0)]
    );
    // L = 0: every change at the next edge. L = 2 with single-cycle pulses: the 2-bit
    // counter saturates at 3.
    assert_eq!(run(0, &[1, 0, 1]), [(1, 0), (0, 0), (1, 0)]);
    let counts: Vec<u64> = run(2, &[1, 0, 1, 0, 1, 0, 1, 0, 1, 0])
        .iter()
        .map(|o| o.1)
        .collect();
    assert_eq!(counts, [0, 1, 1, 2, 2, 3, 3, 3, 3, 3]);
}

#[test]
fn synthesises() {
    let mut uut = GlitchFilter::<8, 8>::default();
    uut.connect_all();
    yosys_validate("encspeed_glitch_filter", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint(
        "glitch_filter",
        &glitch_filter_verilog::<8, 16>("glitch_filter"),
    );
    verilator_lint(
        "glitch_filter",
        &glitch_filter_verilog::<2, 1>("glitch_filter"),
    );
}
