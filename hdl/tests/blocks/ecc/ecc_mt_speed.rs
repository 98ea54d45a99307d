// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::ecc::ecc_mt_speed`.

use hdl::ecc::ecc_mt_speed::*;
use rust_hdl::prelude::*;

type Uut = hdl::ecc_mt_speed_type!(24, 16);

fn step(uut: &mut Uut, start: bool, m: u64, t: u64, dt: u64, delta: i64, neg: bool) {
    uut.reset.next = false;
    uut.start.next = start;
    uut.mt_m.next = m.into();
    uut.mt_t.next = t.into();
    uut.mt_negative.next = neg;
    uut.ecc_delta.next = ((delta as u64) & ((1 << 40) - 1)).into();
    uut.cfg_dt.next = dt.into();
    uut.mode_shift.next = 0.into();
    uut.clock.next = Clock { clk: false };
    assert!(simulate(uut, 100));
    uut.clock.next = Clock { clk: true };
    assert!(simulate(uut, 100));
}

/// 41-bit raw port bits as a signed value.
fn signed(raw: u64) -> i64 {
    ((raw << 23) as i64) >> 23
}

#[test]
fn known_answer_by_hand_in_68_cycles() {
    let _: fn() -> EccMtSpeed<24, 16, 41, 41> = Uut::default;
    let mut uut = Uut::default();
    uut.connect_all();
    // m = 100 steps, δ = 0.5 step, dt = 10 000, t = 1 000 000, x1, reverse:
    // (99.5·10 000/1e6)·2^16 = 0.995·65536 = 65208.32 → −65208.
    let r = (100, 1_000_000, 10_000, 1 << 15, true);
    step(&mut uut, true, r.0, r.1, r.2, r.3, r.4);
    // Busy after edges 0 (the start) to 67, valid after edge 68.
    for k in 1..=68 {
        assert!(uut.busy.val() && !uut.valid.val(), "after edge {}", k - 1);
        step(&mut uut, false, r.0, r.1, r.2, r.3, r.4);
    }
    assert!(uut.valid.val() && !uut.busy.val());
    assert_eq!(signed(uut.speed_mtc.val().to_u64()), -65_208);
}

#[test]
fn synthesises() {
    let mut uut = Uut::default();
    uut.connect_all();
    yosys_validate("encspeed_ecc_mt_speed", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    let lint = |v: String| crate::support::verilator_lint("ecc_mt_speed", &v);
    lint(ecc_mt_speed_verilog::<8, 2, 11, 40>("ecc_mt_speed"));
    lint(ecc_mt_speed_verilog::<8, 16, 25, 40>("ecc_mt_speed"));
    lint(ecc_mt_speed_verilog::<23, 16, 40, 40>("ecc_mt_speed"));
    lint(ecc_mt_speed_verilog::<24, 16, 41, 41>("ecc_mt_speed"));
    lint(ecc_mt_speed_verilog::<32, 24, 57, 49>("ecc_mt_speed"));
}
