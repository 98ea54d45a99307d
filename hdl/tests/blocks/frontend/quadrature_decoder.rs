// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::frontend::quadrature_decoder`.

use crate::support::verilator_lint;
use hdl::frontend::quadrature_decoder::*;
use rust_hdl::prelude::*;

/// Reset at edge 0, then (A, B) samples; the signed step after each edge.
fn decode(mode: u64, ab: &[(u8, u8)]) -> Vec<i8> {
    let mut uut = QuadratureDecoder::<4>::default();
    uut.connect_all();
    let mut out = vec![];
    for k in 0..=ab.len() {
        let (a, b) = if k == 0 { (0, 0) } else { ab[k - 1] };
        uut.reset.next = k == 0;
        uut.a.next = a == 1;
        uut.b.next = b == 1;
        uut.cfg_mode.next = mode.into();
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 100));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 100));
        if k > 0 {
            out.push(
                match (uut.step.val(), uut.forward.val(), uut.backward.val()) {
                    (false, false, false) => 0,
                    (true, true, false) => 1,
                    (true, false, true) => -1,
                    other => panic!("step, forward, backward = {other:?} after edge {k}"),
                },
            );
        }
    }
    out
}

#[test]
fn gray_cycles_in_every_mode() {
    // Prime on 00, then a forward cycle and a reverse cycle (by hand: x4 every
    // transition, x2 the A changes, x1 the A change with B low).
    let seq = [
        (0, 0),
        (1, 0),
        (1, 1),
        (0, 1),
        (0, 0),
        (0, 1),
        (1, 1),
        (1, 0),
        (0, 0),
    ];
    assert_eq!(decode(2, &seq), [0, 1, 1, 1, 1, -1, -1, -1, -1]);
    assert_eq!(decode(3, &seq), [0, 1, 1, 1, 1, -1, -1, -1, -1]);
    assert_eq!(decode(1, &seq), [0, 1, 0, 1, 0, 0, -1, 0, -1]);
    assert_eq!(decode(0, &seq), [0, 1, 0, 0, 0, 0, 0, 0, -1]);
    // 00 → 11 is illegal: no step.
    assert_eq!(decode(2, &[(0, 0), (1, 1), (0, 1)]), [0, 0, 1]);
}

#[test]
fn synthesises() {
    let mut uut = QuadratureDecoder::<8>::default();
    uut.connect_all();
    yosys_validate("encspeed_quadrature_decoder", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint(
        "quadrature_decoder",
        &quadrature_decoder_verilog::<16>("quadrature_decoder"),
    );
    verilator_lint(
        "quadrature_decoder",
        &quadrature_decoder_verilog::<1>("quadrature_decoder"),
    );
}
