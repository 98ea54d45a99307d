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
use std::io::{self, BufReader, Read};
use std::ops::Range;

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
    /// Whether any output differs from the previous edge's (true at the first edge).
    pub outputs_changed: bool,
    /// The reader and edge that filled this edge: a reader skips copying what has not
    /// changed into the edge it filled last.
    filled_by: Option<(u64, u64)>,
}

/// A whitespace-separated token scanner with its own buffer: a token is a range of the
/// buffer, valid until the next call, so nothing is copied per token.
struct Tokens<R: Read> {
    reader: BufReader<R>,
    buf: Vec<u8>,
    /// The unread bytes are `buf[pos..end]`.
    pos: usize,
    end: usize,
}

impl<R: Read> Tokens<R> {
    fn new(reader: BufReader<R>) -> Tokens<R> {
        Tokens {
            reader,
            buf: vec![0; 1 << 16],
            pos: 0,
            end: 0,
        }
    }

    /// Keeps the unread bytes, moved to the front, and reads more after them (the buffer
    /// grows when a token fills it); false at the end of the file.
    fn fill(&mut self) -> io::Result<bool> {
        if self.pos > 0 {
            self.buf.copy_within(self.pos..self.end, 0);
            self.end -= self.pos;
            self.pos = 0;
        }
        if self.end == self.buf.len() {
            self.buf.resize(2 * self.buf.len(), 0);
        }
        loop {
            match self.reader.read(&mut self.buf[self.end..]) {
                Ok(n) => {
                    self.end += n;
                    return Ok(n > 0);
                }
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            }
        }
    }

    /// The next token as a range of `buf`, or None at the end of the file.
    fn next(&mut self) -> io::Result<Option<Range<usize>>> {
        loop {
            while self.pos < self.end && self.buf[self.pos].is_ascii_whitespace() {
                self.pos += 1;
            }
            if self.pos < self.end {
                break;
            }
            if !self.fill()? {
                return Ok(None);
            }
        }
        let mut len = 0;
        loop {
            let rest = &self.buf[self.pos + len..self.end];
            match rest.iter().position(|b| b.is_ascii_whitespace()) {
                Some(n) => {
                    len += n;
                    break;
                }
                None => {
                    len += rest.len();
                    if !self.fill()? {
                        break;
                    }
                }
            }
        }
        let token = self.pos..self.pos + len;
        self.pos += len;
        Ok(Some(token))
    }
}

/// A value's bits, MSB first, `0 1 x z`: its number (x and z as 0) and whether any bit is
/// x or z.
fn parse_value(bits: &[u8]) -> Result<(u128, bool), VcdError> {
    if bits.len() > 128 && bits[..bits.len() - 128].iter().any(|&b| b != b'0') {
        return err(format!("a value of {} bits does not fit 128", bits.len()));
    }
    let mut value = 0u128;
    let mut unknown = false;
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
    Ok((if unknown { 0 } else { value }, unknown))
}

/// A timestamp's digits as a number (at most 19 digits: u64 holds every such number).
fn parse_time(digits: &[u8]) -> Option<u64> {
    if digits.is_empty() || digits.len() > 19 {
        return None;
    }
    let mut t = 0u64;
    for &d in digits {
        if !d.is_ascii_digit() {
            return None;
        }
        t = t * 10 + u64::from(d - b'0');
    }
    Some(t)
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
    /// The same for the one-character identifiers (VCD writers give those to their first
    /// 94 signals): indexed by the character, no hashing.
    short_ids: Vec<Vec<usize>>,
    inputs: Vec<RefPort>,
    defaulted: Vec<&'static str>,
    output_widths: Vec<Option<u32>>,
    /// The values at the end of the last closed timestamp (x and z as 0) and their unknown
    /// flags: the clock, the inputs, the outputs.
    values: Vec<u128>,
    unknown: Vec<bool>,
    /// Inputs the VCD has that are x or z at the end of the last closed timestamp.
    unknown_inputs: usize,
    /// The changes of the current timestamp, applied when it closes: until then `values`
    /// holds what an edge in it samples.
    staged: Vec<(usize, u128, bool)>,
    /// The outputs as an edge reports them, rebuilt only when `outputs_dirty` (an output
    /// changed since the last edge).
    outputs_view: Vec<Option<u128>>,
    outputs_dirty: bool,
    /// An input changed since the last edge.
    inputs_dirty: bool,
    /// This reader's number, distinct among the readers of a process (see
    /// [`VcdEdge::filled_by`]).
    reader: u64,
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
        let defaulted_count = defaulted.len();
        Ok(VcdCycles {
            tokens: Tokens::new(reader),
            scope: path.clone(),
            timescale: header.timescale.unwrap_or((1, vcd::TimescaleUnit::S)),
            short_ids: (0..128u64)
                .map(|c| ids.get(&c).cloned().unwrap_or_default())
                .collect(),
            ids,
            inputs: inputs.to_vec(),
            defaulted,
            output_widths,
            values: vec![0; n],
            unknown: vec![true; n],
            unknown_inputs: inputs.len() - defaulted_count,
            staged: Vec::new(),
            outputs_view: Vec::new(),
            outputs_dirty: true,
            inputs_dirty: true,
            reader: {
                static READERS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
                READERS.fetch_add(1, std::sync::atomic::Ordering::Relaxed)
            },
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

    /// Stages a change of the signal `id` to (`value`, `unknown`).
    fn change(&mut self, id: u64, value: u128, unknown: bool) {
        let slots = match self.short_ids.get(id as usize) {
            Some(slots) => slots,
            None => match self.ids.get(&id) {
                Some(slots) => slots,
                None => return,
            },
        };
        for &k in slots {
            self.staged.push((k, value, unknown));
        }
    }

    /// Closes the current timestamp: true (and `edge` filled with the values before it) if
    /// the clock rose in it; then applies its changes.
    fn close_timestamp(&mut self, edge: &mut VcdEdge) -> bool {
        let clock = self.staged.iter().rev().find(|c| c.0 == 0);
        let rose =
            clock.is_some_and(|&(_, v, u)| v == 1 && !u) && self.values[0] == 0 && !self.unknown[0];
        let n = self.inputs.len();
        if rose {
            // An edge this reader filled at its last edge holds every value that has not
            // changed since.
            let current = self.edges > 0 && edge.filled_by == Some((self.reader, self.edges - 1));
            edge.filled_by = Some((self.reader, self.edges));
            edge.cycle = self.edges;
            edge.time = self.time.unwrap_or(0);
            if self.inputs_dirty || !current {
                edge.inputs.clear();
                edge.inputs.extend_from_slice(&self.values[1..1 + n]);
            }
            self.inputs_dirty = false;
            edge.unknown_input = if self.unknown_inputs == 0 {
                None
            } else {
                (0..n)
                    .find(|&k| {
                        self.unknown[1 + k] && !self.defaulted.contains(&self.inputs[k].name)
                    })
                    .map(|k| self.inputs[k].name)
            };
            if self.outputs_dirty {
                self.outputs_view.clear();
                let outputs = self.values[1 + n..].iter().zip(&self.unknown[1 + n..]);
                for ((&v, &u), width) in outputs.zip(&self.output_widths) {
                    self.outputs_view.push((!u && width.is_some()).then_some(v));
                }
            }
            if self.outputs_dirty || !current {
                edge.outputs.clone_from(&self.outputs_view);
            }
            edge.outputs_changed = self.outputs_dirty;
            self.outputs_dirty = false;
            self.edges += 1;
        }
        for &(k, v, u) in &self.staged {
            if (1..=n).contains(&k) && u != self.unknown[k] {
                if u {
                    self.unknown_inputs += 1;
                } else {
                    self.unknown_inputs -= 1;
                }
            }
            if (v, u) != (self.values[k], self.unknown[k]) {
                if k > n {
                    self.outputs_dirty = true;
                } else if k > 0 {
                    self.inputs_dirty = true;
                }
            }
            self.values[k] = v;
            self.unknown[k] = u;
        }
        self.staged.clear();
        rose
    }

    /// The next token's range in the scanner's buffer; None at the end of the file.
    fn next_token(&mut self) -> Result<Option<Range<usize>>, VcdError> {
        self.tokens
            .next()
            .map_err(|e| VcdError(format!("reading the VCD: {e}")))
    }

    /// The next token, which must be there (the identifier of a vector change, a word
    /// of a comment), as a range.
    fn needed_token(&mut self, inside: &str) -> Result<Range<usize>, VcdError> {
        match self.next_token()? {
            Some(t) => Ok(t),
            None => err(format!("the VCD ends inside {inside}")),
        }
    }

    /// Reads on to the next rising edge and fills `edge` with it; false at the end of the
    /// file. Allocates nothing once `edge` has its size.
    pub fn read_edge(&mut self, edge: &mut VcdEdge) -> Result<bool, VcdError> {
        if self.ended {
            return Ok(false);
        }
        let result = self.read_edge_inner(edge);
        if result.is_err() {
            self.ended = true;
        }
        result
    }

    fn read_edge_inner(&mut self, edge: &mut VcdEdge) -> Result<bool, VcdError> {
        loop {
            let Some(t) = self.next_token()? else {
                self.ended = true;
                return Ok(self.close_timestamp(edge));
            };
            let token = &self.tokens.buf[t.clone()];
            match token[0] {
                b'#' => {
                    let Some(time) = parse_time(&token[1..]) else {
                        return err(format!(
                            "`{}` is not a timestamp",
                            String::from_utf8_lossy(token)
                        ));
                    };
                    if self.time.is_some_and(|old| time < old) {
                        return err(format!("time goes back to {time}"));
                    }
                    let rose = self.close_timestamp(edge);
                    self.time = Some(time);
                    if rose {
                        return Ok(true);
                    }
                }
                b'0' | b'1' | b'x' | b'X' | b'z' | b'Z' => {
                    if token.len() < 2 {
                        return err("a scalar change without an identifier");
                    }
                    let (value, unknown) = parse_value(&token[..1])?;
                    let id = id_number(&token[1..]);
                    self.change(id, value, unknown);
                }
                b'b' | b'B' => {
                    let (value, unknown) = parse_value(&token[1..])?;
                    let t = self.needed_token("a value change")?;
                    let id = id_number(&self.tokens.buf[t]);
                    self.change(id, value, unknown);
                }
                b'r' | b'R' | b's' | b'S' => {
                    // Real and string values: not ports of a top; skip the identifier.
                    self.needed_token("a value change")?;
                }
                b'$' => {
                    if token == b"$comment" {
                        loop {
                            let t = self.needed_token("a $comment")?;
                            if &self.tokens.buf[t] == b"$end" {
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

/// Edges a reader thread hands over at a time in [`VcdCycles::each_edge_threaded`].
const BATCH_EDGES: usize = 1024;

impl<R: Read + Send> VcdCycles<R> {
    /// Calls `each` on every edge, in order, while a thread of its own reads them: the scan
    /// and the caller's work run on two cores. Stops at the first error of either (the
    /// edges before a malformed place are all passed to `each` first); at the end, the
    /// outputs after the last edge ([`Self::final_outputs`]).
    pub fn each_edge_threaded(
        self,
        mut each: impl FnMut(&VcdEdge) -> Result<(), VcdError>,
    ) -> Result<Vec<Option<u128>>, VcdError> {
        use std::sync::mpsc::{channel, sync_channel};
        type Batch = (Vec<VcdEdge>, usize, Option<VcdError>);
        let (full_tx, full_rx) = sync_channel::<Batch>(2);
        let (empty_tx, empty_rx) = channel::<Vec<VcdEdge>>();
        for _ in 0..3 {
            empty_tx
                .send(vec![VcdEdge::default(); BATCH_EDGES])
                .expect("the receiver is here");
        }
        std::thread::scope(|scope| {
            let reader = scope.spawn(move || {
                let mut this = self;
                while let Ok(mut batch) = empty_rx.recv() {
                    let (mut n, mut error) = (0, None);
                    while n < BATCH_EDGES {
                        match this.read_edge(&mut batch[n]) {
                            Ok(true) => n += 1,
                            Ok(false) => break,
                            Err(e) => {
                                error = Some(e);
                                break;
                            }
                        }
                    }
                    let last = n < BATCH_EDGES;
                    if full_tx.send((batch, n, error)).is_err() || last {
                        break;
                    }
                }
                this
            });
            let mut result = Ok(());
            'batches: while let Ok((batch, n, error)) = full_rx.recv() {
                for edge in &batch[..n] {
                    if let Err(e) = each(edge) {
                        result = Err(e);
                        break 'batches;
                    }
                }
                if let Some(e) = error {
                    result = Err(e);
                    break;
                }
                // The reader may have stopped already: a batch it does not take is dropped.
                let _ = empty_tx.send(batch);
            }
            // Ends the reader if it still runs: its next send or receive fails.
            drop(full_rx);
            drop(empty_tx);
            let this = reader.join().expect("the VCD reader thread does not panic");
            result.map(|()| this.final_outputs())
        })
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
             #10\n0!\n#15\n1!\nb101 &\n1#\n#20\n0!\n#25\n1!\n#30\n0!\n#35\n1!\n",
        )
        .unwrap();
        assert_eq!(e.len(), 4);
        assert_eq!(e[2].outputs, vec![Some(5)]);
        assert_eq!(e[3].outputs, vec![Some(5)]);
        let changed: Vec<bool> = e.iter().map(|e| e.outputs_changed).collect();
        assert_eq!(changed, [true, true, true, false]);
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
