// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::top::mode_reset`.

use hdl::top::mode_reset::*;
use rust_hdl::prelude::*;

#[test]
fn a_change_resets_at_the_next_edge_with_the_new_mode() {
    let mut uut = ModeReset::default();
    uut.connect_all();
    // By hand (the model's test): cfg_mode 0, 0, 2, 2, 2, 1 at edges 0..5; rst and mode
    // after each edge.
    let cfg = [0u64, 0, 2, 2, 2, 1];
    let expect = [
        (false, 0),
        (false, 0),
        (true, 2),
        (false, 2),
        (false, 2),
        (true, 1),
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
    uut.reset.next = true;
    assert!(simulate(&mut uut, 10));
    assert!(uut.rst.val(), "reset passes straight through");
    // A change sampled with reset (1 → 2): the mode follows, no second reset.
    uut.cfg_mode.next = 2.into();
    uut.clock.next = Clock { clk: false };
    assert!(simulate(&mut uut, 10));
    uut.clock.next = Clock { clk: true };
    assert!(simulate(&mut uut, 10));
    uut.reset.next = false;
    assert!(simulate(&mut uut, 10));
    assert!(!uut.rst.val(), "no reset after a change sampled with reset");
    assert_eq!(uut.mode.val(), Bits::<2>::from(2));
}

#[test]
fn synthesises() {
    let mut uut = ModeReset::default();
    uut.connect_all();
    yosys_validate("encspeed_mode_reset", &generate_verilog(&uut)).unwrap();
}
