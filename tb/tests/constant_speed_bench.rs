// SPDX-License-Identifier: MIT OR Apache-2.0
//! The shipped `generated/encspeed_core.v` under a plain Verilog bench of the kind an outside
//! engineer writes (`tb/icarus/constant_speed_tb.v`): quadrature at constant speeds, every
//! configuration input tied low but `cfg_dt`, `speed_n3` read as a real number with
//! `speed_frac_bits` taken from the manifest. Each reported speed must be within the
//! computed error budget of the true speed: Rairán's eq. (13) at the measured n1 range, the
//! clock term of `golden::estimator::bounds::n3_error_budget`, and half an output LSB.

use golden::estimator::bounds::n3_error_budget;
use golden::estimator::speed_calc::speed_lsb_error;
use std::path::PathBuf;

const DT: u64 = 1000;

fn generated(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../generated")
        .join(name)
}

/// Speeds printed by the bench (value, valid) for a line period of `period` cycles.
fn run(period: u64, cycles: u64) -> Vec<(f64, bool)> {
    let manifest: toml::Value =
        toml::from_str(&std::fs::read_to_string(generated("encspeed_core.toml")).unwrap()).unwrap();
    let frac = manifest["speed_frac_bits"].as_integer().unwrap();
    let bits = manifest["speed_bits"].as_integer().unwrap();
    let n = manifest["spec"]["counter_bits"].as_integer().unwrap();
    let dir = tools::work_dir("icarus", &format!("constant-speed-{period}")).unwrap();
    std::fs::copy(generated("encspeed_core.v"), dir.join("encspeed_core.v")).unwrap();
    std::fs::write(
        dir.join("constant_speed_tb.v"),
        include_str!("../icarus/constant_speed_tb.v"),
    )
    .unwrap();
    tools::iverilog(
        &dir,
        &[
            &format!("-DW={n}"),
            &format!("-DS={bits}"),
            &format!("-DFRAC={frac}"),
            &format!("-DPERIOD={period}"),
            &format!("-DDT={DT}"),
            &format!("-DCYCLES={cycles}"),
        ],
        &["constant_speed_tb.v", "encspeed_core.v"],
        "bench.vvp",
    )
    .unwrap();
    let text = tools::vvp(&dir, "bench.vvp", &[]).unwrap();
    assert!(text.contains("done"), "bench did not finish:\n{text}");
    text.lines()
        .filter_map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            (f.len() == 4 && f[0] == "speed").then(|| (f[1].parse().unwrap(), f[3] == "1"))
        })
        .collect()
}

#[test]
fn speed_n3_of_the_shipped_file_is_within_budget_at_constant_speeds() {
    // r = dt/period: 25 (the fastest x1 quadrature at 4 cycles a line is 250; 40 cycles keeps
    // Icarus quick), 10, 10/7, 1/3.
    let periods = [40u64, 100, 700, 3000];
    // Icarus runs one bench per thread (a few seconds each).
    let runs: Vec<Vec<(f64, bool)>> = std::thread::scope(|scope| {
        let handles: Vec<_> = periods
            .iter()
            .map(|&period| scope.spawn(move || run(period, 10 * DT.max(period))))
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for (&period, speeds) in periods.iter().zip(runs) {
        let r = DT as f64 / period as f64;
        // Eq. (13) bounds the error in terms of the estimate's n1 = Nep1/Ndt1, which takes
        // the values next to r: above 1, Nep1 ∈ {⌊r⌋, ⌈r⌉} (worst: the smaller); below 1,
        // Ndt1 ≥ ⌈1/r⌉ − 1 (a pulse on a tick restarts and cancels that tick, so at 1/r = 3
        // Ndt1 = 2), worst at the largest n1 = 1/(⌈1/r⌉ − 1).
        let n1_worst = if r >= 1.0 {
            r.floor()
        } else {
            1.0 / ((1.0 / r).ceil() - 1.0).max(1.0)
        };
        let budget = n3_error_budget(n1_worst, DT) + speed_lsb_error(16) / r;
        // Skip the first two updates: they may come before the estimator is synchronised.
        let settled: Vec<(f64, bool)> = speeds.iter().skip(2).copied().collect();
        assert!(settled.len() >= 4, "r = {r}: only {} updates", speeds.len());
        let worst = settled
            .iter()
            .map(|(v, valid)| {
                assert!(*valid, "r = {r}: speed {v} without valid");
                (v - r).abs() / r
            })
            .fold(0.0, f64::max);
        println!(
            "r = {r:.4}: {} updates, max relative error {worst:.5} (budget {budget:.5})",
            settled.len()
        );
        assert!(worst <= budget, "r = {r}: error {worst} > budget {budget}");
    }
}
