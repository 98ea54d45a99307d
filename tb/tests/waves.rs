// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed simulate` writes a VCD under target/; reading it back with the `vcd` crate
//! gives, cycle for cycle, the ports and the internal counters of the golden model.

use golden::params::{Params, Spec};
use golden::top::core::CoreModel;
use std::collections::HashMap;

/// Value of a signal at time `t` from its change list.
fn at(changes: &[(u64, u64)], t: u64) -> u64 {
    match changes.partition_point(|&(when, _)| when <= t) {
        0 => panic!("no value at {t}"),
        i => changes[i - 1].1,
    }
}

#[test]
fn vcd_holds_ports_and_internal_counters_of_every_cycle() {
    let p = Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: 50,
        counter_bits: 12,
        timeout_s: 8.0 * 50.0 / 1e6,
        ..Spec::default()
    })
    .unwrap();
    let inputs = tb::scenarios::find("speed-steps")
        .unwrap()
        .inputs(&p)
        .unwrap();
    let path = tools::target_dir().join("waves/test-speed-steps.vcd");
    let outs = tb::waves::simulate_to_vcd(&p, &inputs, &path).unwrap();

    let names = [
        "uut.enc_a",
        "uut.nep",
        "uut.ndt",
        "uut.update",
        // The block keeps the ts count + 2, mod 2^12 (its tick is compared an edge early).
        "uut.timebase.ts_plus_two.q",
        "uut.timebase.cdt_count.q",
        "uut.table1.cep.q",
    ];
    let w: HashMap<String, Vec<(u64, u64)>> = tb::waves::read_vcd(&path, &names).unwrap();
    let period = (1e12 / p.clock_hz()) as u64;
    let mut model = CoreModel::new(&p);
    for (k, inp) in inputs.iter().enumerate() {
        let o = model.step(*inp);
        assert_eq!(o, outs[k]);
        let s = model.engine().state();
        // After the k-th rising edge, at time (k + 1) periods.
        let t = (k as u64 + 1) * period;
        let got: Vec<u64> = names.iter().map(|n| at(&w[*n], t)).collect();
        let want = vec![
            inp.enc_a as u64,
            o.nep,
            o.ndt,
            o.update as u64,
            (s.clock + 2) % (1 << 12),
            s.cdt,
            s.cep,
        ];
        assert_eq!(got, want, "cycle {k}: VCD {names:?}");
    }
    // The speed steps reach 8 ω_lim: Nep1 = 8 appears in the VCD.
    assert!(w["uut.nep"].iter().any(|&(_, v)| v == 8));
}
