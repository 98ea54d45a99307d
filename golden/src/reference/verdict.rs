// SPDX-License-Identifier: MIT OR Apache-2.0
//! A verdict on another implementation's VCD: the model runs on the inputs the VCD's clock
//! edges sample, and every output the VCD has is compared, bit for bit, with the model's
//! after each edge from the first reset on.

use super::vcd_cycles::{VcdCycles, VcdError};
use super::Reference;
use std::io::Read;

/// How to read the VCD and how much to report.
#[derive(Clone, Debug, Default)]
pub struct CheckOptions {
    /// The scope of the implementation's ports (`tb.dut`); None: found (see
    /// [`VcdCycles::new`]).
    pub scope: Option<String>,
    /// (their signal name, port name) for each signal named otherwise.
    pub map: Vec<(String, String)>,
    /// Mismatches kept for the report (all are counted).
    pub report: usize,
}

/// One output that differs from the model.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mismatch {
    /// The rising edge after which the output differs (edges counted from the VCD's first).
    pub cycle: u64,
    /// That edge's time, in the VCD's timescale.
    pub time: u64,
    /// The port.
    pub port: &'static str,
    /// The model's value (decimal).
    pub expected: String,
    /// The VCD's value (decimal, or `x`).
    pub got: String,
}

/// What a comparison found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// The scope read.
    pub scope: String,
    /// The VCD's timescale, e.g. `1ps`.
    pub timescale: String,
    /// The first compared edge: the first at which reset was 1.
    pub first_cycle: u64,
    /// Edges whose outputs were compared.
    pub cycles: u64,
    /// Output values compared.
    pub values: u64,
    /// Output values that differ.
    pub mismatches: u64,
    /// The first of them (at most [`CheckOptions::report`]).
    pub first: Vec<Mismatch>,
    /// Outputs the VCD does not have.
    pub not_compared: Vec<&'static str>,
    /// Inputs the VCD does not have (run as 0: the generation defaults).
    pub defaulted_inputs: Vec<&'static str>,
}

/// Compares the VCD `reader` with `model` (fresh, in its reset state) bit for bit. An
/// unusable VCD is an error: malformed or truncated, no clock, a needed input missing or x
/// after the first reset, an output of another width than the port, no reset.
pub fn check_exact<R: Read + Send>(
    reader: R,
    model: &mut Reference,
    options: &CheckOptions,
) -> Result<Verdict, VcdError> {
    let ports = model.outputs().to_vec();
    let edges = VcdCycles::new(
        reader,
        model.inputs(),
        &ports,
        options.scope.as_deref(),
        &options.map,
    )?;
    for (port, width) in ports.iter().zip(edges.output_widths()) {
        if let Some(w) = *width {
            if w != port.width {
                return Err(VcdError(format!(
                    "{} is {w} bits in the VCD and {} in {}: --mode exact compares bit for bit",
                    port.name,
                    port.width,
                    model.top().module()
                )));
            }
        }
    }
    let reset = model
        .inputs()
        .iter()
        .position(|p| p.name == "reset")
        .expect("every top has a reset");
    let (n, unit) = edges.timescale();
    let mut verdict = Verdict {
        scope: edges.scope().to_string(),
        timescale: format!("{n}{unit}"),
        first_cycle: 0,
        cycles: 0,
        values: 0,
        mismatches: 0,
        first: Vec::new(),
        not_compared: ports
            .iter()
            .zip(edges.output_widths())
            .filter(|(_, w)| w.is_none())
            .map(|(p, _)| p.name)
            .collect(),
        defaulted_inputs: edges.defaulted_inputs(),
    };
    let present: Vec<usize> = (0..ports.len())
        .filter(|&k| edges.output_widths()[k].is_some())
        .collect();
    // The comparison of an edge is that of the edge before when neither side changed and
    // that one found no mismatch: most edges, at a few nanoseconds each.
    let mut clean = false;
    let mut compare = |verdict: &mut Verdict,
                       (cycle, time): (u64, u64),
                       expected: &[u128],
                       got: &[Option<u128>],
                       unchanged: bool| {
        verdict.cycles += 1;
        verdict.values += present.len() as u64;
        if unchanged && clean {
            return;
        }
        let before = verdict.mismatches;
        for &k in &present {
            let port = &ports[k];
            if got[k] != Some(expected[k]) {
                verdict.mismatches += 1;
                if verdict.first.len() < options.report {
                    verdict.first.push(Mismatch {
                        cycle,
                        time,
                        port: port.name,
                        expected: port.decimal(expected[k]),
                        got: got[k].map_or("x".to_string(), |g| port.decimal(g)),
                    });
                }
            }
        }
        clean = verdict.mismatches == before;
    };
    let mut started = false;
    // The edge whose outputs are compared with the values before the next edge, and the
    // model's outputs after it.
    let mut pending: Option<(u64, u64)> = None;
    let mut expected: Vec<u128> = Vec::with_capacity(ports.len());
    let mut expected_changed = true;
    let mut any_edge = false;
    let timescale = verdict.timescale.clone();
    let final_outputs = edges.each_edge_threaded(|edge| {
        any_edge = true;
        if let Some(at) = pending.take() {
            let unchanged = !expected_changed && !edge.outputs_changed;
            compare(&mut verdict, at, &expected, &edge.outputs, unchanged);
        }
        if !started && edge.inputs[reset] == 1 {
            started = true;
            verdict.first_cycle = edge.cycle;
        }
        if started {
            if let Some(name) = edge.unknown_input {
                return Err(VcdError(format!(
                    "input {name} is x or z at the rising edge {} (time {}{timescale}) after \
                     the first reset",
                    edge.cycle, edge.time
                )));
            }
        }
        model.step_ref(&edge.inputs);
        if started {
            expected_changed = model.outputs_changed() || expected.is_empty();
            if expected_changed {
                expected.clear();
                expected.extend_from_slice(model.last_outputs());
            }
            pending = Some((edge.cycle, edge.time));
        }
        Ok(())
    })?;
    if !any_edge {
        return Err(VcdError("the clock never rises in the VCD".into()));
    }
    if !started {
        return Err(VcdError(
            "reset is never 1 at a rising edge: the comparison starts at the first reset".into(),
        ));
    }
    if let Some(at) = pending.take() {
        compare(&mut verdict, at, &expected, &final_outputs, false);
    }
    Ok(verdict)
}
