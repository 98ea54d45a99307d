// SPDX-License-Identifier: MIT OR Apache-2.0
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
use std::hash::{BuildHasherDefault, Hasher};
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
#[derive(Clone, Debug, Default, PartialEq, Eq)]
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
            // Skip the whitespace before the token, then take the bytes up to the next.
            let start = if self.token.is_empty() {
                match buf.iter().position(|b| !b.is_ascii_whitespace()) {
                    Some(s) => s,
                    None => {
                        let n = buf.len();
                        self.reader.consume(n);
                        continue;
                    }
                }
            } else {
                0
            };
            match buf[start..].iter().position(|b| b.is_ascii_whitespace()) {
                Some(len) => {
                    self.token.extend_from_slice(&buf[start..start + len]);
                    self.reader.consume(start + len + 1);
                    break;
                }
                None => {
                    self.token.extend_from_slice(&buf[start..]);
                    let n = buf.len();
                    self.reader.consume(n);
                }
            }
        }
        Ok((!self.token.is_empty()).then_some(&self.token[..]))
    }
}

/// An identifier code as a number: its bytes in base 256, the last eight if it is longer
/// (identifiers of more than eight characters that share their last eight would collide;
/// VCD writers number theirs from `!` upward, so a file needs more than 94^8 signals first).
fn id_number(id: &[u8]) -> u64 {
    id.iter().fold(0u64, |n, &b| n << 8 | u64::from(b))
}

/// The hasher of the identifier numbers: they are distinct small integers already, so a
/// multiplication spreads them well enough, at a fraction of SipHash's cost per value change.
#[derive(Default)]
struct IdHasher(u64);

impl Hasher for IdHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 << 8 | u64::from(b)).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        }
    }
    fn write_u64(&mut self, n: u64) {
        self.0 = n.wrapping_mul(0x9e37_79b9_7f4a_7c15);
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
    ids: HashMap<u64, Vec<usize>, BuildHasherDefault<IdHasher>>,
    inputs: Vec<RefPort>,
    defaulted: Vec<&'static str>,
    output_widths: Vec<Option<u32>>,
    /// Values and their unknown flags: the clock, the inputs, the outputs.
    values: Vec<u128>,
    unknown: Vec<bool>,
    /// For the slots the current timestamp changed (`changed`, listed in `touched`): their
    /// values before it.
    old_values: Vec<u128>,
    old_unknown: Vec<bool>,
    changed: Vec<bool>,
    touched: Vec<usize>,
    time: Option<u64>,
    edges: u64,
    ended: bool,
    /// Buffers of the scanner: the current token and a vector change's identifier.
    token: Vec<u8>,
    id: Vec<u8>,
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
        Self::with_required(reader, inputs, outputs, scope, map, &REQUIRED_INPUTS)
    }

    /// [`VcdCycles::new`] with other inputs than [`REQUIRED_INPUTS`] required (and used to
    /// find the scope): `check --mode bound` needs no `enc_z`.
    pub fn with_required(
        reader: R,
        inputs: &[RefPort],
        outputs: &[RefPort],
        scope: Option<&str>,
        map: &[(String, String)],
        required: &[&str],
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
        let needed: Vec<&str> = std::iter::once(CLOCK)
            .chain(required.iter().copied())
            .collect();
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
        let mut ids: HashMap<u64, Vec<usize>, BuildHasherDefault<IdHasher>> = HashMap::default();
        let mut bind = |var: &vcd::Var, index: usize| {
            ids.entry(id_number(var.code.to_string().as_bytes()))
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
            old_values: vec![0; n],
            old_unknown: vec![true; n],
            changed: vec![false; n],
            touched: Vec::new(),
            time: None,
            edges: 0,
            ended: false,
            token: Vec::new(),
            id: Vec::new(),
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

    /// Slot `k` as it was before the current timestamp: (value, unknown).
    fn before(&self, k: usize) -> (u128, bool) {
        if self.changed[k] {
            (self.old_values[k], self.old_unknown[k])
        } else {
            (self.values[k], self.unknown[k])
        }
    }

    /// Applies a value change of the signal `id`; `bits` MSB first, `0 1 x z`.
    fn change(&mut self, bits: &[u8], id: &[u8]) -> Result<(), VcdError> {
        let Some(slots) = self.ids.get(&id_number(id)) else {
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
        for &k in slots {
            if !self.changed[k] {
                self.changed[k] = true;
                self.touched.push(k);
                self.old_values[k] = self.values[k];
                self.old_unknown[k] = self.unknown[k];
            }
            self.values[k] = value;
            self.unknown[k] = unknown;
        }
        Ok(())
    }

    /// Closes the current timestamp: true (and `edge` filled) if the clock rose in it.
    fn close_timestamp(&mut self, edge: &mut VcdEdge) -> bool {
        let rose = self.changed[0]
            && self.old_values[0] == 0
            && !self.old_unknown[0]
            && self.values[0] == 1
            && !self.unknown[0];
        if rose {
            let n = self.inputs.len();
            edge.cycle = self.edges;
            edge.time = self.time.unwrap_or(0);
            edge.inputs.clear();
            edge.unknown_input = None;
            for k in 0..n {
                let (v, u) = self.before(1 + k);
                edge.inputs.push(if u { 0 } else { v });
                if u && edge.unknown_input.is_none()
                    && !self.defaulted.contains(&self.inputs[k].name)
                {
                    edge.unknown_input = Some(self.inputs[k].name);
                }
            }
            edge.outputs.clear();
            for (j, width) in self.output_widths.iter().enumerate() {
                let (v, u) = self.before(1 + n + j);
                edge.outputs.push((!u && width.is_some()).then_some(v));
            }
            self.edges += 1;
        }
        for &k in &self.touched {
            self.changed[k] = false;
        }
        self.touched.clear();
        rose
    }

    /// The next token into `buf` (cleared first, its capacity kept); false at the end.
    fn token_into(&mut self, buf: &mut Vec<u8>) -> Result<bool, VcdError> {
        let t = self
            .tokens
            .next()
            .map_err(|e| VcdError(format!("reading the VCD: {e}")))?;
        buf.clear();
        match t {
            Some(t) => {
                buf.extend_from_slice(t);
                Ok(true)
            }
            None => Ok(false),
        }
    }

    /// Reads on to the next rising edge and fills `edge` with it; false at the end of the
    /// file. Allocates nothing once `edge` has its size.
    pub fn read_edge(&mut self, edge: &mut VcdEdge) -> Result<bool, VcdError> {
        if self.ended {
            return Ok(false);
        }
        let mut token = std::mem::take(&mut self.token);
        let mut id = std::mem::take(&mut self.id);
        let result = self.read_edge_with(edge, &mut token, &mut id);
        (self.token, self.id) = (token, id);
        if result.is_err() {
            self.ended = true;
        }
        result
    }

    fn read_edge_with(
        &mut self,
        edge: &mut VcdEdge,
        token: &mut Vec<u8>,
        id: &mut Vec<u8>,
    ) -> Result<bool, VcdError> {
        loop {
            if !self.token_into(token)? {
                self.ended = true;
                return Ok(self.close_timestamp(edge));
            }
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
                    let rose = self.close_timestamp(edge);
                    self.time = Some(t);
                    if rose {
                        return Ok(true);
                    }
                }
                b'0' | b'1' | b'x' | b'X' | b'z' | b'Z' => {
                    if token.len() < 2 {
                        return err("a scalar change without an identifier");
                    }
                    self.change(&token[..1], &token[1..])?;
                }
                b'b' | b'B' => {
                    if !self.token_into(id)? {
                        return err("the VCD ends inside a value change");
                    }
                    self.change(&token[1..], id)?;
                }
                b'r' | b'R' | b's' | b'S' => {
                    // Real and string values: not ports of a top; skip the identifier.
                    if !self.token_into(id)? {
                        return err("the VCD ends inside a value change");
                    }
                }
                b'$' => {
                    if token.as_slice() == b"$comment" {
                        loop {
                            if !self.token_into(id)? {
                                return err("the VCD ends inside a $comment");
                            }
                            if id.as_slice() == b"$end" {
                                break;
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
        let mut edge = VcdEdge::default();
        match self.read_edge(&mut edge) {
            Ok(true) => Some(Ok(edge)),
            Ok(false) => None,
            Err(e) => Some(Err(e)),
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
