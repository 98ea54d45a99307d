// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::estimator::timebase`.

use hdl::estimator::timebase::*;
use rust_hdl::prelude::*;

#[test]
fn ticks_every_dt_and_restarts_on_a_pulse_after_a_tick() {
    let mut uut = Timebase::<8>::default();
    uut.connect_all();
    let mut ticks = vec![];
    let mut restarts = vec![];
    // dt = 5; pulses at edges 7 (Cdt = 1 after the tick at 5: restart) and 8 (Cdt = 0).
    for k in 0..20 {
        uut.reset.next = k == 0;
        uut.dt.next = 5.into();
        uut.lep.next = k == 7 || k == 8;
        uut.clock.next = Clock { clk: false };
        assert!(simulate(&mut uut, 10));
        // During the reset cycle the outputs decode power-up values; the core holds its
        // consumers in reset then.
        if uut.tick.val() && k > 0 {
            ticks.push(k);
        }
        if uut.restart.val() {
            restarts.push(k);
        }
        uut.clock.next = Clock { clk: true };
        assert!(simulate(&mut uut, 10));
    }
    // By hand: reset at edge 0 (dt register loaded too); count 1..5 → tick at edge 5;
    // restart at 7 (count 0), then ticks at 12 and 17.
    assert_eq!(ticks, vec![5, 12, 17]);
    assert_eq!(restarts, vec![7]);
}

#[test]
fn synthesises() {
    let mut uut = Timebase::<8>::default();
    uut.connect_all();
    yosys_validate("encspeed_timebase", &generate_verilog(&uut)).unwrap();
}
