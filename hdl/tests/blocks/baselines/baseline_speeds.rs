// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::baselines::baseline_speeds`.

use hdl::baselines::baseline_speeds::*;
use rust_hdl::prelude::*;

type Uut = hdl::baseline_speeds_type!(24, 16);

struct Req {
    pc: i64,
    period: u64,
    m: u64,
    t: u64,
    dt: u64,
    shift: u64,
    negative: bool,
}

fn step(uut: &mut Uut, start: bool, r: &Req) {
    uut.reset.next = false;
    uut.start.next = start;
    uut.pc_count.next = ((r.pc as u64) & ((1 << 24) - 1)).into();
    uut.et_period.next = r.period.into();
    uut.et_negative.next = r.negative;
    uut.et_valid.next = true;
    uut.mt_m.next = r.m.into();
    uut.mt_t.next = r.t.into();
    uut.mt_negative.next = r.negative;
    uut.cfg_dt.next = r.dt.into();
    uut.mode_shift.next = r.shift.into();
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
fn known_answers_by_hand_in_168_cycles() {
    let mut uut = Uut::default();
    uut.connect_all();
    // x2, dt = 10: PC −5 → −5·2^15 = −163840; ET period 3 → 10·32768/3 = 109226.67 →
    // −109227; M/T 3 in 7 → 30·32768/7 = 140434.29 → −140434.
    let r = Req {
        pc: -5,
        period: 3,
        m: 3,
        t: 7,
        dt: 10,
        shift: 1,
        negative: true,
    };
    step(&mut uut, true, &r);
    // Busy after edges 0 (the start) to 167, valid after edge 168 (1 take, 41 ET steps of
    // 2 edges, 1 M/T set-up, 41 M/T steps of 2 edges, 1 finish, 1 publication).
    for k in 1..=168 {
        assert!(uut.busy.val() && !uut.valid.val(), "after edge {}", k - 1);
        step(&mut uut, false, &r);
    }
    assert!(uut.valid.val() && !uut.busy.val());
    assert_eq!(signed(uut.speed_pc.val().to_u64()), -163_840);
    assert_eq!(signed(uut.speed_et.val().to_u64()), -109_227);
    assert_eq!(signed(uut.speed_mt.val().to_u64()), -140_434);
}

#[test]
fn synthesises() {
    let mut uut = Uut::default();
    uut.connect_all();
    yosys_validate("encspeed_baseline_speeds", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    let lint = |v: String| crate::support::verilator_lint("baseline_speeds", &v);
    lint(baseline_speeds_verilog::<8, 2, 11>("baseline_speeds"));
    lint(baseline_speeds_verilog::<12, 8, 21>("baseline_speeds"));
    lint(baseline_speeds_verilog::<24, 16, 41>("baseline_speeds"));
    lint(baseline_speeds_verilog::<32, 24, 57>("baseline_speeds"));
}
