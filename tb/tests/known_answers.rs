// SPDX-License-Identifier: MIT OR Apache-2.0
//! Known answers of Rairán's Table 1 at constant speed, from hand calculations.
//!
//! The vectors in `tb/vectors/table1_known_answers.toml` are worked by hand from Table 1
//! and eqs. (6), (11), (13) of the paper (each case carries its calculation). The stimulus
//! is an exact square wave (pulses on clock edges), so the steady-state answers are exact
//! and every layer must reproduce them to the cycle:
//! - the float ideal model in continuous time (`golden::ideal::RairanIdeal`),
//! - the bit-true golden model (`golden::top::core::CoreModel`),
//! - the rust-hdl simulation, and the emitted Verilog in Verilator, which must both be
//!   identical to the golden model on every cycle.
//!
//! The second half checks the update interval against the paper's eq. (1) over a grid of
//! speeds, with the hand-derived interval ⌈r⌉·T as the expected value.

use golden::ideal::RairanIdeal;
use golden::params::{Params, Spec};
use golden::top::core::{CoreInputs, CoreModel, CoreOutputs};
use serde::Deserialize;
use std::collections::HashMap;
use tb::cosim::{assert_same, run_golden, run_hdl};
use tb::stimulus::square_wave;
use tb::verilator::Verilated;

const VECTORS: &str = include_str!("../vectors/table1_known_answers.toml");

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct VectorFile {
    case: Vec<Case>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Case {
    name: String,
    source: String,
    dt: u64,
    period: u64,
    phase: u64,
    nep1: u64,
    ndt1: u64,
    update_period: u64,
    write_period: u64,
    n3: [u64; 2],
    rel_err: [u64; 2],
}

fn cases() -> Vec<Case> {
    let f: VectorFile = toml::from_str(VECTORS).expect("table1_known_answers.toml parses");
    f.case
}

/// 1 MHz clock, 100 lines, 16-bit counters, zero-speed timeout 50 dt (far beyond the
/// longest pulse interval of any case, so `stalled` never rises in steady state).
fn params(dt: u64) -> Params {
    Params::new(Spec {
        clock_hz: 1e6,
        lines: 100,
        dt_cycles: dt,
        counter_bits: 16,
        timeout_s: 50.0 * dt as f64 / 1e6,
        ..Spec::default()
    })
    .unwrap()
}

/// Cycles ignored at the start: reset, the first pulse (within one period), and then
/// several update cycles (each at most 2·dt for r ≥ 1, T for r < 1).
fn settle_cycles(dt: u64, period: u64) -> usize {
    (6 * dt.max(period) + 10) as usize
}

/// Steady-state cycles examined after settling: at least 6 update cycles.
fn window_cycles(dt: u64, period: u64) -> usize {
    (12 * dt.max(period)) as usize
}

/// Eq. (13) of the paper, restated: worst-case relative error of n3 as a function of n1.
fn eq13_er3_max(n1: f64) -> f64 {
    if n1 <= 1.0 {
        1.0 / (1.0 + 2.0 / n1)
    } else {
        1.0 / (2.0 * n1 - 1.0)
    }
}

/// Eq. (1) of the paper, restated: the update interval dt_a for ω ≥ ω_lim, r = ω/ω_lim.
fn eq1_dt_a(r: f64, dt: f64) -> f64 {
    let fl = r.floor();
    (-r / fl + 2.0 + 1.0 / fl) * dt
}

/// Which register the golden model wrote in a cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Write {
    None,
    /// Nep1 written at a dt tick (Cdt ≥ 1 after the step).
    Nep,
    /// Ndt1 written at a restarting pulse (Cdt = 0 after the step).
    Ndt,
}

/// Run the golden model and classify each update: a tick leaves Cdt ≥ 1, a restart
/// (a pulse) leaves Cdt = 0, and the two never happen in the same step.
fn golden_with_writes(p: &Params, inputs: &[CoreInputs]) -> (Vec<CoreOutputs>, Vec<Write>) {
    let mut m = CoreModel::new(p);
    inputs
        .iter()
        .map(|i| {
            let o = m.step(*i);
            let w = match (o.update, m.engine().state().cdt) {
                (false, _) => Write::None,
                (true, 0) => Write::Ndt,
                (true, _) => Write::Nep,
            };
            (o, w)
        })
        .unzip()
}

/// Minimal period of a set of strobe instants (sorted), from its own differences: the
/// smallest j such that idx[i + j] − idx[i] is the same for every i. Needs at least three
/// repetitions of the pattern in the window to call it a period.
fn pattern_period(idx: &[usize]) -> Option<usize> {
    (1..idx.len())
        .take_while(|&j| idx.len() > 3 * j)
        .find_map(|j| {
            let p = idx[j] - idx[0];
            idx.windows(j + 1).all(|w| w[j] - w[0] == p).then_some(p)
        })
}

/// The one gap between consecutive instants, if they are evenly spaced (≥ 3 gaps).
fn constant_gap(idx: &[usize]) -> Option<usize> {
    let gaps: Vec<usize> = idx.windows(2).map(|w| w[1] - w[0]).collect();
    (gaps.len() >= 3 && gaps.iter().all(|&g| g == gaps[0])).then(|| gaps[0])
}

/// What the steady state of one golden run looks like.
#[derive(Debug, PartialEq, Eq)]
struct Steady {
    /// Every (Nep1, Ndt1) value seen in the window, in order of first appearance.
    values: Vec<(u64, u64)>,
    strobe_period: Option<usize>,
    nep_write_period: Option<usize>,
    ndt_write_period: Option<usize>,
    stalled: bool,
}

fn steady(outs: &[CoreOutputs], writes: &[Write], from: usize) -> Steady {
    let mut values = vec![];
    let (mut strobes, mut nep_w, mut ndt_w) = (vec![], vec![], vec![]);
    for (k, (o, w)) in outs.iter().zip(writes).enumerate().skip(from) {
        if !values.contains(&(o.nep, o.ndt)) {
            values.push((o.nep, o.ndt));
        }
        if o.update {
            strobes.push(k);
        }
        match w {
            Write::Nep => nep_w.push(k),
            Write::Ndt => ndt_w.push(k),
            Write::None => {}
        }
    }
    Steady {
        values,
        strobe_period: pattern_period(&strobes),
        nep_write_period: constant_gap(&nep_w),
        ndt_write_period: constant_gap(&ndt_w),
        stalled: outs[from..].iter().any(|o| o.stalled),
    }
}

fn run_case_golden(c: &Case) -> (Vec<CoreInputs>, Vec<CoreOutputs>, Steady) {
    let p = params(c.dt);
    let settle = settle_cycles(c.dt, c.period);
    let inputs = square_wave(
        c.period,
        c.phase,
        settle + window_cycles(c.dt, c.period),
        c.dt,
    );
    let (outs, writes) = golden_with_writes(&p, &inputs);
    let s = steady(&outs, &writes, settle);
    (inputs, outs, s)
}

#[test]
fn vector_file_agrees_with_the_papers_equations() {
    // Checks of the hand calculations themselves, in exact integer arithmetic: the n3
    // fraction is eqs. (6)+(11) of the file's Nep1/Ndt1, the error fraction is
    // |n3 − r|/r with r = dt/period, and it is within eq. (13).
    let cases = cases();
    assert!(cases.len() >= 14, "only {} cases", cases.len());
    for c in &cases {
        assert!(
            c.source.contains("Table 1") && !c.name.is_empty(),
            "{}: no source",
            c.name
        );
        let (nep, ndt) = (c.nep1 as u128, c.ndt1 as u128);
        let [a, b] = [c.n3[0] as u128, c.n3[1] as u128];
        // n1 = nep/ndt takes no value strictly between 1 and 2 (the paper, under Table 1).
        assert!(nep <= ndt || nep >= 2 * ndt, "{}: n1 in (1, 2)", c.name);
        // Eq. (11) with eq. (6): n3 = 2·nep·(nep−1)/(ndt·(2·nep−1)) for n1 ≥ 2,
        // 2·nep/(2·ndt+1) otherwise.
        let (num, den) = if nep >= 2 * ndt {
            (2 * nep * (nep - 1), ndt * (2 * nep - 1))
        } else {
            (2 * nep, 2 * ndt + 1)
        };
        assert_eq!(a * den, num * b, "{}: n3 = {a}/{b} vs {num}/{den}", c.name);
        // |a/b − dt/T| / (dt/T) = |a·T − b·dt| / (b·dt)
        let (dt, t) = (c.dt as u128, c.period as u128);
        let diff = (a * t).abs_diff(b * dt);
        let [e, f] = [c.rel_err[0] as u128, c.rel_err[1] as u128];
        assert_eq!(diff * f, e * b * dt, "{}: rel_err", c.name);
        // Eq. (13): Er3 = nep/(nep + 2·ndt) for n1 ≤ 1, ndt/(2·nep − ndt) for n1 ≥ 2.
        let (g, h) = if nep <= ndt {
            (nep, nep + 2 * ndt)
        } else {
            (ndt, 2 * nep - ndt)
        };
        assert!(
            e * h <= g * f,
            "{}: error {e}/{f} above Er3 {g}/{h}",
            c.name
        );
        // The update interval of the hand calculation, in closed form: ⌈r⌉·T for
        // non-integer r > 1, (r + 1)·T at integer r ≥ 1, T for r < 1.
        let cycle = if c.period > c.dt {
            c.period
        } else if c.dt.is_multiple_of(c.period) {
            c.dt + c.period
        } else {
            c.dt.div_ceil(c.period) * c.period
        };
        assert_eq!(c.write_period, cycle, "{}: write_period", c.name);
        assert!(
            c.update_period == c.write_period || 2 * c.update_period == c.write_period,
            "{}: strobe period",
            c.name
        );
    }
}

#[test]
fn known_answers_in_golden_rust_hdl_and_verilator() {
    let mut verilated: HashMap<u64, Verilated> = HashMap::new();
    for c in cases() {
        let p = params(c.dt);
        let (inputs, outs, s) = run_case_golden(&c);
        // The same inputs through the three layers: identical on every cycle.
        assert_eq!(outs, run_golden(&p, &inputs), "{}: run_golden", c.name);
        assert_same(
            &format!("{} rust-hdl", c.name),
            &inputs,
            &outs,
            &run_hdl(&p, &inputs),
        );
        let v = verilated
            .entry(c.dt)
            .or_insert_with(|| Verilated::build(&hdl::emit_core(&p).verilog).unwrap());
        let vout = v.run(&inputs, None).unwrap();
        assert_same(&format!("{} verilator", c.name), &inputs, &outs, &vout);

        // Steady state: exactly the hand-calculated registers at every cycle.
        assert_eq!(s.values, vec![(c.nep1, c.ndt1)], "{}: (Nep1, Ndt1)", c.name);
        assert_eq!(
            s.strobe_period,
            Some(c.update_period as usize),
            "{}: strobe period",
            c.name
        );
        assert_eq!(
            s.nep_write_period,
            Some(c.write_period as usize),
            "{}: Nep1 write period",
            c.name
        );
        assert_eq!(
            s.ndt_write_period,
            Some(c.write_period as usize),
            "{}: Ndt1 write period",
            c.name
        );
        assert!(!s.stalled, "{}: stalled at constant speed", c.name);

        // n3 at exact instants: the file's fraction and within eq. (13).
        let r = c.dt as f64 / c.period as f64;
        let n1 = c.nep1 as f64 / c.ndt1 as f64;
        let n3 = golden::ideal::n3(c.nep1, c.ndt1);
        assert!(
            (n3 - c.n3[0] as f64 / c.n3[1] as f64).abs() < 1e-12 * n3,
            "{}: n3 = {n3}",
            c.name
        );
        let err = (n3 - r).abs() / r;
        let expect_err = c.rel_err[0] as f64 / c.rel_err[1] as f64;
        assert!((err - expect_err).abs() < 1e-12, "{}: error {err}", c.name);
        let bound = eq13_er3_max(n1);
        assert!(
            err <= bound + 1e-12,
            "{}: error {err} > Er3 {bound}",
            c.name
        );
        assert!((golden::estimator::bounds::er3_max(n1) - bound).abs() < 1e-15);
        println!(
            "{:<48} dt {:>4} T {:>4}: Nep1 {:>3} Ndt1 {} strobes/{} writes/{} n3 {:.6} err {:.5} <= Er3 {:.5}; {} cycles identical in 3 layers",
            c.name,
            c.dt,
            c.period,
            c.nep1,
            c.ndt1,
            c.update_period,
            c.write_period,
            n3,
            err,
            bound,
            inputs.len()
        );
    }
}

#[test]
fn known_answers_of_the_float_ideal_model() {
    // Layer 1: Table 1 in continuous time, fed the same pulse train as exact instants
    // (time unit: one clock cycle, so every instant is an exact integer in f64).
    for c in cases() {
        let ideal = RairanIdeal::new(c.dt as f64, 100).unwrap();
        let settle = settle_cycles(c.dt, c.period) as f64;
        let end = settle + window_cycles(c.dt, c.period) as f64;
        let first = (c.period - c.phase % c.period) % c.period + 1;
        let pulses: Vec<f64> = (0..)
            .map(|k| (first + k * c.period) as f64)
            .take_while(|&t| t <= end)
            .collect();
        let updates = ideal.run(&pulses, end).unwrap();
        let late: Vec<_> = updates.iter().filter(|u| u.t >= settle).collect();
        assert!(late.len() >= 6, "{}: {} updates", c.name, late.len());
        for u in &late {
            assert_eq!(
                (u.nep1, u.ndt1),
                (c.nep1, c.ndt1),
                "{}: at t = {}",
                c.name,
                u.t
            );
        }
        let nep_w: Vec<usize> = late
            .iter()
            .filter(|u| u.wrote_nep)
            .map(|u| u.t as usize)
            .collect();
        let ndt_w: Vec<usize> = late
            .iter()
            .filter(|u| u.wrote_ndt)
            .map(|u| u.t as usize)
            .collect();
        let w = Some(c.write_period as usize);
        assert_eq!(constant_gap(&nep_w), w, "{}: Nep1 write period", c.name);
        assert_eq!(constant_gap(&ndt_w), w, "{}: Ndt1 write period", c.name);
    }
}

/// Golden steady state at dt = 1000 for a square wave of `period` cycles.
fn measure(period: u64) -> (Vec<CoreInputs>, Vec<CoreOutputs>, Steady) {
    const DT: u64 = 1000;
    let p = params(DT);
    let settle = settle_cycles(DT, period);
    let inputs = square_wave(period, period / 3, settle + window_cycles(DT, period), DT);
    let (outs, writes) = golden_with_writes(&p, &inputs);
    let s = steady(&outs, &writes, settle);
    (inputs, outs, s)
}

#[test]
fn eq1_is_an_upper_bound_on_the_update_interval() {
    // dt = 1000, every integer period T with 1.05 ≤ r = dt/T ≤ 20 and r not an integer.
    // Hand derivation: a pulse restarts the dt base, the tick dt later writes Nep1 = ⌈r⌉
    // (the restarting pulse and the next ⌊r⌋ are inside the window), and the first pulse
    // after the tick — the ⌈r⌉-th after the restart — restarts again and writes Ndt1 = 1.
    // So both registers are written every ⌈r⌉·T cycles. Eq. (1),
    // dt_a = (−r/⌊r⌋ + 2 + 1/⌊r⌋)·dt, is the chord of the convex ⌈r⌉/r·dt between
    // consecutive integers, so it must lie strictly above it here.
    const DT: u64 = 1000;
    let p = params(DT);
    let v = Verilated::build(&hdl::emit_core(&p).verilog).unwrap();
    let (mut n, mut min_margin, mut max_ratio) = (0, f64::INFINITY, 0.0f64);
    for period in 50..=952u64 {
        if DT.is_multiple_of(period) {
            continue;
        }
        let r = DT as f64 / period as f64;
        assert!((1.05..=20.0).contains(&r));
        let expect = DT.div_ceil(period) * period;
        let (inputs, outs, s) = measure(period);
        assert_eq!(s.values, vec![(DT.div_ceil(period), 1)], "T = {period}");
        let e = Some(expect as usize);
        assert_eq!(s.strobe_period, e, "T = {period}: strobes");
        assert_eq!(s.nep_write_period, e, "T = {period}: Nep1 writes");
        assert_eq!(s.ndt_write_period, e, "T = {period}: Ndt1 writes");
        let eq1 = eq1_dt_a(r, DT as f64);
        assert!(
            (expect as f64) < eq1,
            "T = {period}: update interval {expect} not below eq. (1) {eq1}"
        );
        assert!((expect as f64) > DT as f64, "T = {period}: interval ≤ dt");
        // The float model's closed form, golden::ideal::update_interval, agrees.
        let ideal = golden::ideal::update_interval(r) * DT as f64;
        assert!(
            (ideal - expect as f64).abs() < 1e-9,
            "T = {period}: {ideal}"
        );
        min_margin = min_margin.min(eq1 - expect as f64);
        max_ratio = max_ratio.max(expect as f64 / eq1);
        // A sample of the grid through the emitted Verilog too.
        if period % 50 == 7 {
            let vout = v.run(&inputs, None).unwrap();
            assert_same(&format!("T = {period} verilator"), &inputs, &outs, &vout);
        }
        n += 1;
    }
    // 903 periods, less the six divisors of 1000 (r = 20, 10, 8, 5, 4, 2).
    assert_eq!(n, 903 - 6);
    println!(
        "{n} non-integer r in [1.05, 20]: update interval = ⌈r⌉·T < eq. (1) everywhere; \
         smallest gap {min_margin:.3} cycles, largest interval/eq. (1) = {max_ratio:.6}"
    );
}

#[test]
fn eq1_equals_the_update_interval_at_integer_r() {
    // r = dt/T integer: the pulse on the tick is counted and then cleared, so Nep1 = r and
    // the restart comes one period later: (r + 1)·T = (r + 1)/r·dt, which is eq. (1) at
    // ⌊r⌋ = r. At r = 1 the Nep1 and Ndt1 writes alternate every dt, so the strobes repeat
    // every T = dt while each register is written every 2·dt.
    const DT: u64 = 1000;
    for period in [50u64, 100, 125, 200, 250, 500, 1000] {
        let r = DT / period;
        let (_, _, s) = measure(period);
        let expect = (r + 1) * period;
        assert_eq!(s.values, vec![(r, 1)], "r = {r}");
        assert_eq!(s.nep_write_period, Some(expect as usize), "r = {r}");
        assert_eq!(s.ndt_write_period, Some(expect as usize), "r = {r}");
        let strobes = if r == 1 { period } else { expect };
        assert_eq!(s.strobe_period, Some(strobes as usize), "r = {r}");
        let eq1 = eq1_dt_a(r as f64, DT as f64);
        assert!(
            (eq1 - expect as f64).abs() < 1e-9,
            "r = {r}: eq. (1) = {eq1}"
        );
    }
}

#[test]
fn low_speed_update_interval_is_the_pulse_period() {
    // r < 1: every pulse restarts (Cdt ≥ 1), the tick dt later writes Nep1 = 1, so both
    // registers are written once per pulse period T — the paper's dt_a = (ω_lim/ω)·dt.
    // Ndt1 counts the ticks strictly before the next pulse: ⌈T/dt⌉ − 1; at r = 1/n the
    // restart cancels the n-th tick, so Ndt1 = n − 1.
    const DT: u64 = 1000;
    let periods: Vec<u64> = (1001..=5000u64)
        .step_by(7)
        .chain([2000, 3000, 4000, 5000])
        .collect();
    for &period in &periods {
        let (_, _, s) = measure(period);
        let ndt = period.div_ceil(DT) - 1;
        assert_eq!(s.values, vec![(1, ndt)], "T = {period}");
        if period.is_multiple_of(DT) {
            assert_eq!(ndt, period / DT - 1);
        }
        let t = Some(period as usize);
        assert_eq!(s.nep_write_period, t, "T = {period}: Nep1 writes");
        assert_eq!(s.ndt_write_period, t, "T = {period}: Ndt1 writes");
        // The writes at the restart and at the tick dt later are evenly spaced only at
        // T = 2·dt (r = 1/2): then the strobes repeat every dt.
        let strobes = if period == 2 * DT { DT } else { period };
        assert_eq!(s.strobe_period, Some(strobes as usize), "T = {period}");
        assert!(!s.stalled);
    }
    println!(
        "{} periods in (dt, 5·dt]: update interval = T",
        periods.len()
    );
}
