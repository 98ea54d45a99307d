// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::ecc::line_tap`.

use crate::support::verilator_lint;
use golden::ecc::line_tap::LineTap as Model;
use hdl::ecc::line_tap::*;
use rust_hdl::prelude::*;

/// rust-hdl against the model on a walk of positions in all three shifts, with
/// reversals, index resets to 0 and resets.
#[test]
fn equals_model() {
    let mut uut = LineTap::<32>::default();
    uut.connect_all();
    let mut model = Model::new();
    let mut rng = golden::splitmix::SplitMix64(7);
    let (mut pos, mut fwd, mut lines) = (0u64, true, 0);
    for k in 0..20_000u64 {
        let shift = ((k / 5000) % 3) as u32;
        let r = 12u64 << shift;
        let reset = k % 5000 < 2 || rng.next_u64().is_multiple_of(3000);
        match rng.next_u64() % 8 {
            0 => fwd = !fwd,
            1 | 2 => {
                pos = if fwd {
                    (pos + 1) % r
                } else {
                    (pos + r - 1) % r
                }
            }
            3 if rng.next_u64().is_multiple_of(50) => pos = 0,
            4 if rng.next_u64().is_multiple_of(500) => pos = 0xffff_ffff,
            _ => {}
        }
        let want = model.outputs(pos, fwd, shift, r);
        uut.position.next = pos.into();
        uut.forward.next = fwd;
        uut.shift.next = u64::from(shift).into();
        uut.counts_per_rev.next = r.into();
        uut.reset.next = reset;
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        let got = (
            uut.line.val(),
            uut.line_position.val().to_u64(),
            uut.period.val().to_u64(),
        );
        assert_eq!(
            got,
            (want.line, want.line_position, want.period),
            "cycle {k}"
        );
        lines += usize::from(want.line);
        model.step(reset, pos, fwd, shift, r);
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
    }
    assert!(lines > 500, "{lines} line edges");
}

#[test]
fn verilator_lint_is_clean() {
    let mut uut = LineTap::<32>::default();
    uut.connect_all();
    verilator_lint("line_tap", &hdl::verilog::named_verilog(&uut, "line_tap"));
}
