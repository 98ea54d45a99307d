// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::top::mode_reset`.

use hdl::top::mode_reset::*;
use rust_hdl::prelude::*;

#[test]
fn a_change_resets_at_the_next_edge_with_the_new_mode() {
    let mut uut = ModeReset::default();
    uut.connect_all();
    assert!(simulate(&mut uut, 10));
    assert!(
        uut.rst.val(),
        "rst powers up high: the first edge resets the core"
    );
    // By hand (the model's test): cfg_mode 0, 0, 2, 2, 2, 1 at edges 0..5; rst and mode
    // after each edge.
    let cfg = [0u64, 0, 2, 2, 2, 1, 1];
    let expect = [
        (false, 0),
        (false, 0),
        (true, 2),
        (false, 2),
        (false, 2),
        (true, 1),
        (false, 1),
    ];
    for (k, (&c, &(rst, mode))) in cfg.iter().zip(&expect).enumerate() {
        uut.cfg_mode.next = c.into();
        uut.reset.next = false;
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
        assert_eq!(uut.rst.val(), rst, "rst after edge {k}");
        assert_eq!(uut.mode.val(), Bits::<2>::from(mode), "mode after edge {k}");
    }
    // Reset sampled at an edge (with a change 1 → 2): `rst` after that edge, not before;
    // the mode follows; no second reset.
    uut.reset.next = true;
    uut.cfg_mode.next = 2.into();
    assert!(simulate(&mut uut, 10));
    assert!(
        !uut.rst.val(),
        "reset is registered: no rst before the edge"
    );
    assert!(uut.rst_next.val(), "rst_next announces it");
    let edge = |uut: &mut ModeReset| {
        uut.clock.next = Clock { clk: false };
        assert!(simulate(uut, 10));
        uut.clock.next = Clock { clk: true };
        assert!(simulate(uut, 10));
    };
    edge(&mut uut);
    assert!(uut.rst.val(), "rst after the edge that sampled reset");
    assert_eq!(uut.mode.val(), Bits::<2>::from(2));
    uut.reset.next = false;
    edge(&mut uut);
    assert!(
        !uut.rst.val(),
        "no second reset after a change sampled with reset"
    );
    assert!(!uut.rst_next.val());
    assert_eq!(uut.mode.val(), Bits::<2>::from(2));
}

#[test]
fn synthesises() {
    let mut uut = ModeReset::default();
    uut.connect_all();
    yosys_validate("encspeed_mode_reset", &generate_verilog(&uut)).unwrap();
}
