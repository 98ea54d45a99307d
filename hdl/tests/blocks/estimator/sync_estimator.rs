// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::estimator::sync_estimator`.

use hdl::estimator::sync_estimator::*;
use rust_hdl::prelude::*;

/// One clock edge with (reset, lep, tick); returns (Cep, Nep1, update) after it.
fn edge<const N: usize>(
    uut: &mut SyncEstimator<N>,
    reset: bool,
    lep: bool,
    tick: bool,
) -> (u64, u64, bool) {
    uut.reset.next = reset;
    uut.lep.next = lep;
    uut.tick.next = tick;
    uut.restart.next = false;
    uut.cdt.next = 0.into();
    uut.clock.next = Clock { clk: false };
    assert!(simulate(uut, 100));
    uut.clock.next = Clock { clk: true };
    assert!(simulate(uut, 100));
    (
        uut.cep.q.val().to_u64(),
        uut.nep.val().to_u64(),
        uut.update.val(),
    )
}

/// Cep saturates at 2^N − 1 and a tick writes Nep1 only when Cep ≠ 0 (Table 1 lines
/// 8-13), with the flags kept beside Cep: worked by hand for N = 1 and N = 2.
#[test]
fn cep_saturates_and_a_tick_writes_only_a_count() {
    let mut two = SyncEstimator::<2>::default();
    two.connect_all();
    assert_eq!(edge(&mut two, true, false, false), (0, 0, false));
    let counts: Vec<u64> = (0..5)
        .map(|_| edge(&mut two, false, true, false).0)
        .collect();
    assert_eq!(counts, [1, 2, 3, 3, 3]);
    // The tick writes Nep1 = 3 (update the cycle after) and clears Cep.
    assert_eq!(edge(&mut two, false, false, true), (0, 3, true));
    // A tick with Cep = 0 writes nothing.
    assert_eq!(edge(&mut two, false, false, true), (0, 3, false));
    // A pulse with the tick is counted and cleared with Cep (lines 10-13).
    assert_eq!(edge(&mut two, false, true, false), (1, 3, false));
    assert_eq!(edge(&mut two, false, true, true), (0, 1, true));
    // A pulse in the reset cycle starts the count at 1.
    assert_eq!(edge(&mut two, true, true, false), (1, 0, false));
    assert_eq!(edge(&mut two, false, false, true), (0, 1, true));

    let mut one = SyncEstimator::<1>::default();
    one.connect_all();
    assert_eq!(edge(&mut one, true, true, false), (1, 0, false));
    assert_eq!(edge(&mut one, false, true, false), (1, 0, false));
    assert_eq!(edge(&mut one, false, false, true), (0, 1, true));
    assert_eq!(edge(&mut one, false, true, false), (1, 1, false));
    assert_eq!(edge(&mut one, false, true, false), (1, 1, false));
}

#[test]
fn synthesises() {
    let mut uut = SyncEstimator::<8>::default();
    uut.connect_all();
    yosys_validate("encspeed_sync_estimator", &generate_verilog(&uut)).unwrap();
}
