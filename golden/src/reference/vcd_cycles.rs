//! A VCD read as a stream of clock cycles: at each rising edge of the clock, the inputs just
//! before it (the values the edge samples) and the outputs just before it (the values the
//! previous edge left). Memory does not grow with the file.
//!
//! The header is read with the `vcd` crate. The value changes are scanned here, token by
//! token over a buffered reader, because the crate's parser reads byte by byte through
//! `io::Bytes` and allocates every vector value: too slow for the gigabyte VCDs users have.
//!
//! Sampling: a rising edge is a change of the clock from 0 to 1 within one timestamp. The
//! values "just before" it are those at the end of the previous timestamp, so inputs that a
//! testbench changes at the edge's own timestamp (non-blocking assignments) count for the
//! next edge, as in the simulator. x or z reads as unknown.

use super::RefPort;
use std::collections::HashMap;
use std::fmt;
use std::io::{self, BufRead, BufReader, Read};

/// The clock's port name.
pub const CLOCK: &str = "clock";

/// Inputs a VCD must have; the others (configuration, coefficients, pulses) read as 0 when
/// absent, which selects the generation defaults.
pub const REQUIRED_INPUTS: [&str; 4] = ["reset", "enc_a", "enc_b", "enc_z"];

/// What makes a VCD unusable: malformed, truncated, or lacking a needed signal.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VcdError(pub String);

impl fmt::Display for VcdError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for VcdError {}

fn err<T>(msg: impl Into<String>) -> Result<T, VcdError> {
    Err(VcdError(msg.into()))
}

/// One rising edge of the clock.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VcdEdge {
    /// Edges before this one.
    pub cycle: u64,
    /// Its time, in the VCD's timescale.
    pub time: u64,
    /// The inputs the edge samples (unknown and absent ones as 0).
    pub inputs: Vec<u128>,
    /// The first input that is x or z at this edge, if any.
    pub unknown_input: Option<&'static str>,
    /// The outputs just before the edge (those the previous edge left): None where x or z
    /// or where the VCD does not have the output.
    pub outputs: Vec<Option<u128>>,
}

/// A whitespace-separated token scanner over a buffered reader.
struct Tokens<R: Read> {
    reader: BufReader<R>,
    token: Vec<u8>,
}

impl<R: Read> Tokens<R> {
    /// The next token, or None at the end of the file.
    fn next(&mut self) -> io::Result<Option<&[u8]>> {
        self.token.clear();
        loop {
            let buf = self.reader.fill_buf()?;
            if buf.is_empty() {
                break;
            }
            let mut used = 0;
            let mut done = false;
            for &b in buf {
                used += 1;
                if b.is_ascii_whitespace() {
                    if !self.token.is_empty() {
                        done = true;
                        break;
                    }
                } else {
                    self.token.push(b);
                }
            }
            self.reader.consume(used);
            if done {
                break;
            }
        }
        Ok((!self.token.is_empty()).then_some(&self.token[..]))
    }
}

/// Every scope of a header as (dotted path, its variables).
fn scopes(items: &[vcd::ScopeItem], prefix: &str, out: &mut Vec<(String, Vec<vcd::Var>)>) {
    for item in items {
        if let vcd::ScopeItem::Scope(s) = item {
            let path = if prefix.is_empty() {
                s.identifier.clone()
            } else {
                format!("{prefix}.{}", s.identifier)
            };
            let vars = s
                .children
                .iter()
                .filter_map(|i| match i {
                    vcd::ScopeItem::Var(v) => Some(v.clone()),
                    _ => None,
                })
                .collect();
            out.push((path.clone(), vars));
            scopes(&s.children, &path, out);
        }
    }
}

/// A VCD's rising edges, in order.
pub struct VcdCycles<R: Read> {
    tokens: Tokens<R>,
    scope: String,
    timescale: (u32, vcd::TimescaleUnit),
    /// The slots (index into the values) each identifier carries: one signal may carry
    /// several ports, and several signals of other scopes may share its identifier.
    ids: HashMap<Vec<u8>, Vec<usize>>,
    inputs: Vec<RefPort>,
    defaulted: Vec<&'static str>,
    output_widths: Vec<Option<u32>>,
    /// Values and their unknown flags: the clock, the inputs, the outputs.
    values: Vec<u128>,
    unknown: Vec<bool>,
    /// Values as they were before the current timestamp changed them.
    undo: Vec<(usize, u128, bool)>,
    changed: Vec<bool>,
    time: Option<u64>,
    edges: u64,
    ended: bool,
}

impl<R: Read> VcdCycles<R> {
    /// Reads the header of a VCD and finds the clock, `inputs` and `outputs` in `scope`
    /// (a dotted path such as `tb.dut`; None: the scope that holds the clock and the
    /// [`REQUIRED_INPUTS`] and the most of the other ports, the shallowest of equals).
    /// `map` renames: (their signal name, port name).
    pub fn new(
        reader: R,
        inputs: &[RefPort],
        outputs: &[RefPort],
        scope: Option<&str>,
        map: &[(String, String)],
    ) -> Result<VcdCycles<R>, VcdError> {
        let mut reader = BufReader::with_capacity(1 << 16, reader);
        let header = vcd::Parser::new(&mut reader)
            .parse_header()
            .map_err(|e| VcdError(format!("the VCD's header is malformed: {e}")))?;
        let their_name = |port: &str| -> String {
            map.iter()
                .find(|(_, p)| p == port)
                .map_or(port.to_string(), |(theirs, _)| theirs.clone())
        };
        let mut all = Vec::new();
        scopes(&header.items, "", &mut all);
        let has = |vars: &[vcd::Var], port: &str| {
            let name = their_name(port);
            vars.iter().any(|v| v.reference == name)
        };
        let needed: Vec<&str> = std::iter::once(CLOCK).chain(REQUIRED_INPUTS).collect();
        let (path, vars) = match scope {
            Some(s) => all.iter().find(|(p, _)| p == s).ok_or_else(|| {
                VcdError(format!(
                    "the VCD has no scope `{s}` (scopes: {})",
                    all.iter()
                        .map(|(p, _)| p.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ))
            })?,
            None => {
                let score = |vars: &[vcd::Var]| {
                    inputs
                        .iter()
                        .chain(outputs)
                        .filter(|p| has(vars, p.name))
                        .count()
                };
                let mut best: Option<&(String, Vec<vcd::Var>)> = None;
                for candidate in all.iter().filter(|(_, v)| needed.iter().all(|n| has(v, n))) {
                    let deeper = |a: &str| a.matches('.').count();
                    if best.is_none_or(|b| {
                        let (s, t) = (score(&candidate.1), score(&b.1));
                        s > t || (s == t && deeper(&candidate.0) < deeper(&b.0))
                    }) {
                        best = Some(candidate);
                    }
                }
                best.ok_or_else(|| {
                    VcdError(format!(
                        "no scope of the VCD holds {} (give --scope, and --map where the names \
                         differ)",
                        needed
                            .iter()
                            .map(|n| their_name(n))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ))
                })?
            }
        };
        let find = |port: &str| {
            let name = their_name(port);
            vars.iter().find(|v| v.reference == name).cloned()
        };
        // Slots: the clock, then the inputs, then the outputs.
        let mut ids: HashMap<Vec<u8>, Vec<usize>> = HashMap::new();
        let mut bind = |var: &vcd::Var, index: usize| {
            ids.entry(var.code.to_string().into_bytes())
                .or_default()
                .push(index);
        };
        let missing: Vec<String> = needed
            .iter()
            .filter(|n| find(n).is_none())
            .map(|n| their_name(n))
            .collect();
        if !missing.is_empty() {
            return err(format!("scope `{path}` lacks {}", missing.join(", ")));
        }
        let clock = find(CLOCK).expect("checked");
        if clock.size != 1 {
            return err(format!(
                "the clock `{}` is {} bits wide",
                their_name(CLOCK),
                clock.size
            ));
        }
        bind(&clock, 0);
        let mut defaulted = Vec::new();
        for (k, port) in inputs.iter().enumerate() {
            match find(port.name) {
                Some(var) if var.size > 128 => {
                    return err(format!(
                        "{} is {} bits wide in the VCD",
                        port.name, var.size
                    ))
                }
                Some(var) => bind(&var, 1 + k),
                None => defaulted.push(port.name),
            }
        }
        let mut output_widths = Vec::with_capacity(outputs.len());
        for (k, port) in outputs.iter().enumerate() {
            match find(port.name) {
                Some(var) if var.size > 128 => {
                    return err(format!(
                        "{} is {} bits wide in the VCD",
                        port.name, var.size
                    ))
                }
                Some(var) => {
                    bind(&var, 1 + inputs.len() + k);
                    output_widths.push(Some(var.size));
                }
                None => output_widths.push(None),
            }
        }
        let n = 1 + inputs.len() + outputs.len();
        Ok(VcdCycles {
            tokens: Tokens {
                reader,
                token: Vec::new(),
            },
            scope: path.clone(),
            timescale: header.timescale.unwrap_or((1, vcd::TimescaleUnit::S)),
            ids,
            inputs: inputs.to_vec(),
            defaulted,
            output_widths,
            values: vec![0; n],
            unknown: vec![true; n],
            undo: Vec::new(),
            changed: vec![false; n],
            time: None,
            edges: 0,
            ended: false,
        })
    }

    /// The scope the ports were read from.
    pub fn scope(&self) -> &str {
        &self.scope
    }

    /// The VCD's timescale (1 s if it gives none).
    pub fn timescale(&self) -> (u32, vcd::TimescaleUnit) {
        self.timescale
    }

    /// The inputs the VCD does not have (they read as 0).
    pub fn defaulted_inputs(&self) -> Vec<&'static str> {
        self.defaulted.clone()
    }

    /// The width of each output in the VCD, None where it does not have it.
    pub fn output_widths(&self) -> &[Option<u32>] {
        &self.output_widths
    }

    /// The outputs at the end of the file (after the last edge), None where unknown.
    pub fn final_outputs(&self) -> Vec<Option<u128>> {
        self.outputs_of(&self.values, &self.unknown)
    }

    fn outputs_of(&self, values: &[u128], unknown: &[bool]) -> Vec<Option<u128>> {
        let first = 1 + self.inputs.len();
        (first..values.len())
            .map(|k| (!unknown[k] && self.output_widths[k - first].is_some()).then_some(values[k]))
            .collect()
    }

    fn set(&mut self, k: usize, value: u128, unknown: bool) {
        if !self.changed[k] {
            self.changed[k] = true;
            self.undo.push((k, self.values[k], self.unknown[k]));
        }
        self.values[k] = value;
        self.unknown[k] = unknown;
    }

    /// Applies a value change of the signal `id`; `bits` MSB first, `0 1 x z`.
    fn change(&mut self, bits: &[u8], id: &[u8]) -> Result<(), VcdError> {
        let Some(slots) = self.ids.get(id) else {
            return Ok(());
        };
        let mut value = 0u128;
        let mut unknown = false;
        if bits.len() > 128 && bits[..bits.len() - 128].iter().any(|&b| b != b'0') {
            return err(format!("a value of {} bits does not fit 128", bits.len()));
        }
        for &b in bits {
            value = value.wrapping_shl(1);
            match b {
                b'0' => {}
                b'1' => value |= 1,
                b'x' | b'X' | b'z' | b'Z' => unknown = true,
                _ => {
                    return err(format!(
                        "`{}` is not a VCD value",
                        String::from_utf8_lossy(bits)
                    ))
                }
            }
        }
        for k in slots.clone() {
            self.set(k, value, unknown);
        }
        Ok(())
    }

    /// Closes the current timestamp: the edge it held, if the clock rose in it.
    fn close_timestamp(&mut self) -> Option<VcdEdge> {
        let clock_was = self.undo.iter().find(|u| u.0 == 0).map(|u| (u.1, u.2));
        let rose = matches!(clock_was, Some((0, false))) && self.values[0] == 1 && !self.unknown[0];
        let edge = if rose {
            let mut values = self.values.clone();
            let mut unknown = self.unknown.clone();
            for &(k, v, u) in &self.undo {
                values[k] = v;
                unknown[k] = u;
            }
            let inputs: Vec<u128> = (0..self.inputs.len())
                .map(|k| if unknown[1 + k] { 0 } else { values[1 + k] })
                .collect();
            let unknown_input = (0..self.inputs.len())
                .find(|&k| unknown[1 + k] && !self.defaulted.contains(&self.inputs[k].name))
                .map(|k| self.inputs[k].name);
            let e = VcdEdge {
                cycle: self.edges,
                time: self.time.unwrap_or(0),
                inputs,
                unknown_input,
                outputs: self.outputs_of(&values, &unknown),
            };
            self.edges += 1;
            Some(e)
        } else {
            None
        };
        for &(k, _, _) in &self.undo {
            self.changed[k] = false;
        }
        self.undo.clear();
        edge
    }

    /// Reads on to the next rising edge; None at the end of the file.
    fn next_edge(&mut self) -> Result<Option<VcdEdge>, VcdError> {
        let io = |e: io::Error| VcdError(format!("reading the VCD: {e}"));
        loop {
            let Some(token) = self.tokens.next().map_err(io)? else {
                self.ended = true;
                return Ok(self.close_timestamp());
            };
            match token[0] {
                b'#' => {
                    let t: u64 = std::str::from_utf8(&token[1..])
                        .ok()
                        .and_then(|s| s.parse().ok())
                        .ok_or_else(|| {
                            VcdError(format!(
                                "`{}` is not a timestamp",
                                String::from_utf8_lossy(token)
                            ))
                        })?;
                    if self.time.is_some_and(|old| t < old) {
                        return err(format!("time goes back to {t}"));
                    }
                    let edge = self.close_timestamp();
                    self.time = Some(t);
                    if edge.is_some() {
                        return Ok(edge);
                    }
                }
                b'0' | b'1' | b'x' | b'X' | b'z' | b'Z' => {
                    let (value, id) = (token[0], token[1..].to_vec());
                    if id.is_empty() {
                        return err("a scalar change without an identifier");
                    }
                    self.change(&[value], &id)?;
                }
                b'b' | b'B' => {
                    let bits = token[1..].to_vec();
                    let id = self
                        .tokens
                        .next()
                        .map_err(io)?
                        .ok_or_else(|| VcdError("the VCD ends inside a value change".into()))?
                        .to_vec();
                    self.change(&bits, &id)?;
                }
                b'r' | b'R' | b's' | b'S' => {
                    // Real and string values: not ports of a top; skip the identifier.
                    if self.tokens.next().map_err(io)?.is_none() {
                        return err("the VCD ends inside a value change");
                    }
                }
                b'$' => {
                    if token == b"$comment" {
                        loop {
                            match self.tokens.next().map_err(io)? {
                                Some(b"$end") => break,
                                Some(_) => {}
                                None => return err("the VCD ends inside a $comment"),
                            }
                        }
                    }
                    // $dumpvars, $dumpall, $dumpon, $dumpoff and their $end: the values
                    // inside are ordinary changes.
                }
                _ => {
                    return err(format!(
                        "`{}` is not a VCD command (at time {:?})",
                        String::from_utf8_lossy(token),
                        self.time
                    ))
                }
            }
        }
    }
}

impl<R: Read> Iterator for VcdCycles<R> {
    type Item = Result<VcdEdge, VcdError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.ended {
            return None;
        }
        match self.next_edge() {
            Ok(Some(edge)) => Some(Ok(edge)),
            Ok(None) => None,
            Err(e) => {
                self.ended = true;
                Some(Err(e))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn port(name: &'static str, width: u32) -> RefPort {
        RefPort {
            name,
            width,
            signed: false,
        }
    }

    fn inputs() -> Vec<RefPort> {
        ["reset", "enc_a", "enc_b", "enc_z"]
            .map(|n| port(n, 1))
            .into_iter()
            .chain([port("cfg_dt", 8)])
            .collect()
    }

    const HEADER: &str = "$timescale 1ns $end\n$scope module tb $end\n\
        $var reg 1 ! clk $end\n$var reg 1 \" reset $end\n$var reg 1 # enc_a $end\n\
        $var reg 1 $ enc_b $end\n$var reg 1 % enc_z $end\n\
        $scope module dut $end\n$var wire 1 ! clk $end\n$var wire 1 \" reset $end\n\
        $var wire 1 # enc_a $end\n$var wire 1 $ enc_b $end\n$var wire 1 % enc_z $end\n\
        $var wire 8 & count [7:0] $end\n$upscope $end\n$upscope $end\n$enddefinitions $end\n";

    fn edges(body: &str) -> Result<Vec<VcdEdge>, VcdError> {
        let text = format!("{HEADER}{body}");
        let map = [("clk".to_string(), "clock".to_string())];
        VcdCycles::new(text.as_bytes(), &inputs(), &[port("count", 8)], None, &map)?.collect()
    }

    #[test]
    fn edges_sample_the_values_before_their_timestamp() {
        // The reset changes at the first edge's own timestamp: the edge samples the old 1.
        let e = edges(
            "#0\n$dumpvars\n0!\n1\"\n0#\n0$\n0%\nbx &\n$end\n#5\n1!\n0\"\nb0 &\n\
             #10\n0!\n#15\n1!\nb101 &\n1#\n#20\n0!\n",
        )
        .unwrap();
        assert_eq!(e.len(), 2);
        assert_eq!((e[0].cycle, e[0].time), (0, 5));
        assert_eq!(e[0].inputs, vec![1, 0, 0, 0, 0]);
        assert_eq!(e[0].outputs, vec![None], "x before the first edge");
        assert_eq!(e[0].unknown_input, None, "cfg_dt is absent, not unknown");
        assert_eq!((e[1].cycle, e[1].time), (1, 15));
        assert_eq!(
            e[1].inputs,
            vec![0, 0, 0, 0, 0],
            "enc_a rises at the edge: not yet"
        );
        assert_eq!(e[1].outputs, vec![Some(0)]);
    }

    #[test]
    fn the_scope_with_the_most_ports_is_chosen() {
        let text = format!("{HEADER}#0\n0!\n");
        let map = [("clk".to_string(), "clock".to_string())];
        let c =
            VcdCycles::new(text.as_bytes(), &inputs(), &[port("count", 8)], None, &map).unwrap();
        assert_eq!(c.scope(), "tb.dut");
        assert_eq!(c.defaulted_inputs(), vec!["cfg_dt"]);
    }

    #[test]
    fn unusable_vcds_are_errors_that_say_why() {
        let e = edges("#0\n0!\nb10\n").unwrap_err();
        assert!(e.0.contains("ends inside a value change"), "{e}");
        let e = edges("#0\n0!\n#5\n1! junk\n").unwrap_err();
        assert!(e.0.contains("not a VCD command"), "{e}");
        let e = edges("#5\n0!\n#4\n").unwrap_err();
        assert!(e.0.contains("time goes back"), "{e}");
        let e = edges("#0\n$comment never closed\n").unwrap_err();
        assert!(e.0.contains("$comment"), "{e}");
        let map: [(String, String); 0] = [];
        let text = format!("{HEADER}#0\n");
        let e = VcdCycles::new(text.as_bytes(), &inputs(), &[], None, &map)
            .err()
            .unwrap();
        assert!(e.0.contains("no scope of the VCD holds clock"), "{e}");
        let e = VcdCycles::new(&b"$var wire"[..], &inputs(), &[], None, &map)
            .err()
            .unwrap();
        assert!(e.0.contains("header"), "{e}");
    }
}
