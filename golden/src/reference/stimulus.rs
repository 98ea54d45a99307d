// SPDX-License-Identifier: MIT OR Apache-2.0
//! Stimuli: the inputs of a top at its rising clock edges, read as a stream from a CSV file
//! (one row per change) or from a VCD (sampled at the clock's rising edges).
//!
//! CSV: a header `cycle,<input>,...` naming the column of every input of the top (any
//! order; `#` starts a comment line), then rows of decimal integers with strictly
//! increasing cycles starting at 0. A row gives the inputs sampled at the rising edge of
//! its cycle and holds until the next row; the last row's cycle is the last one run.

use super::vcd_cycles::{VcdCycles, VcdError};
use super::RefPort;
use std::io::Read;

/// The inputs of the top from one cycle on: `cycle` and one bit pattern per input of the
/// top, in port-list order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StimulusRow {
    /// The first cycle these inputs apply to.
    pub cycle: u64,
    /// One bit pattern per input.
    pub inputs: Vec<u128>,
}

/// A stimulus: rows in increasing cycle order, or an error that names the file's line.
pub type StimulusResult = Result<StimulusRow, String>;

/// A CSV stimulus, read row by row.
pub struct CsvStimulus<R: Read> {
    records: csv::StringRecordsIntoIter<R>,
    /// Column of `cycle`, and of each input in port-list order.
    cycle_column: usize,
    columns: Vec<usize>,
    inputs: Vec<RefPort>,
    last_cycle: Option<u64>,
    failed: bool,
}

impl<R: Read> CsvStimulus<R> {
    /// Reads the header of a CSV stimulus for a top with `inputs`: every input must have a
    /// column, and no column may name anything else.
    pub fn new(reader: R, inputs: &[RefPort]) -> Result<CsvStimulus<R>, String> {
        let mut csv = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .comment(Some(b'#'))
            .from_reader(reader);
        let header = csv
            .headers()
            .map_err(|e| format!("stimulus header: {e}"))?
            .clone();
        let find = |name: &str| header.iter().position(|h| h == name);
        let cycle_column = find("cycle").ok_or("the stimulus header has no `cycle` column")?;
        let missing: Vec<&str> = inputs
            .iter()
            .filter(|p| find(p.name).is_none())
            .map(|p| p.name)
            .collect();
        if !missing.is_empty() {
            return Err(format!(
                "the stimulus header lacks the inputs {}; a stimulus gives every input of the \
                 top (0 selects a configuration input's generation default)",
                missing.join(", ")
            ));
        }
        if let Some(unknown) = header
            .iter()
            .find(|h| *h != "cycle" && !inputs.iter().any(|p| p.name == *h))
        {
            return Err(format!(
                "the stimulus column `{unknown}` is not an input of the top (inputs: {})",
                inputs.iter().map(|p| p.name).collect::<Vec<_>>().join(", ")
            ));
        }
        let columns = inputs
            .iter()
            .map(|p| find(p.name).expect("checked above"))
            .collect();
        Ok(CsvStimulus {
            records: csv.into_records(),
            cycle_column,
            columns,
            inputs: inputs.to_vec(),
            last_cycle: None,
            failed: false,
        })
    }

    fn row(&mut self, record: csv::StringRecord) -> StimulusResult {
        let line = record.position().map_or(0, |p| p.line());
        let at = |e: String| format!("stimulus line {line}: {e}");
        let field = |k: usize| {
            record
                .get(k)
                .ok_or_else(|| at(format!("no column {}", k + 1)))
        };
        let cycle_text = field(self.cycle_column)?;
        let cycle: u64 = cycle_text
            .parse()
            .map_err(|_| at(format!("cycle `{cycle_text}` is not a cycle number")))?;
        match self.last_cycle {
            None if cycle != 0 => return Err(at(format!("the first row is cycle {cycle}, not 0"))),
            Some(last) if cycle <= last => {
                return Err(at(format!("cycle {cycle} does not follow cycle {last}")))
            }
            _ => {}
        }
        self.last_cycle = Some(cycle);
        let mut inputs = Vec::with_capacity(self.columns.len());
        for (port, &k) in self.inputs.iter().zip(&self.columns) {
            inputs.push(port.parse(field(k)?).map_err(at)?);
        }
        Ok(StimulusRow { cycle, inputs })
    }
}

impl<R: Read> Iterator for CsvStimulus<R> {
    type Item = StimulusResult;

    fn next(&mut self) -> Option<StimulusResult> {
        if self.failed {
            return None;
        }
        let item = match self.records.next()? {
            Ok(record) => self.row(record),
            Err(e) => Err(format!("stimulus: {e}")),
        };
        self.failed = item.is_err();
        Some(item)
    }
}

/// A VCD stimulus: the inputs sampled at each rising edge of the clock, one row per edge
/// (the edges numbered from 0). Inputs the VCD lacks are refused unless `optional` says
/// they may read as 0.
pub struct VcdStimulus<R: Read> {
    cycles: VcdCycles<R>,
    failed: bool,
}

impl<R: Read> VcdStimulus<R> {
    /// Reads the VCD's header and finds the inputs (see [`VcdCycles::new`] for `scope` and
    /// `map`).
    pub fn new(
        reader: R,
        inputs: &[RefPort],
        scope: Option<&str>,
        map: &[(String, String)],
    ) -> Result<VcdStimulus<R>, VcdError> {
        let cycles = VcdCycles::new(reader, inputs, &[], scope, map)?;
        Ok(VcdStimulus {
            cycles,
            failed: false,
        })
    }

    /// The scope the inputs were read from, and the inputs that read as 0 because the VCD
    /// does not have them.
    pub fn found(&self) -> (&str, Vec<&'static str>) {
        (self.cycles.scope(), self.cycles.defaulted_inputs())
    }
}

impl<R: Read> Iterator for VcdStimulus<R> {
    type Item = StimulusResult;

    fn next(&mut self) -> Option<StimulusResult> {
        if self.failed {
            return None;
        }
        let item = match self.cycles.next()? {
            Ok(edge) => Ok(StimulusRow {
                cycle: edge.cycle,
                inputs: edge.inputs,
            }),
            Err(e) => Err(e.to_string()),
        };
        self.failed = item.is_err();
        Some(item)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inputs() -> Vec<RefPort> {
        vec![
            RefPort {
                name: "reset",
                width: 1,
                signed: false,
            },
            RefPort {
                name: "cfg_dt",
                width: 24,
                signed: false,
            },
        ]
    }

    fn read(text: &str) -> Result<Vec<StimulusRow>, String> {
        CsvStimulus::new(text.as_bytes(), &inputs())?.collect()
    }

    #[test]
    fn rows_in_any_column_order() {
        let rows = read("# a comment\ncfg_dt, cycle ,reset\n0,0,1\n100,3,0\n").unwrap();
        assert_eq!(
            rows,
            vec![
                StimulusRow {
                    cycle: 0,
                    inputs: vec![1, 0]
                },
                StimulusRow {
                    cycle: 3,
                    inputs: vec![0, 100]
                }
            ]
        );
    }

    #[test]
    fn bad_stimuli_are_refused_with_their_line() {
        let e = read("cycle,reset\n0,1\n").unwrap_err();
        assert!(e.contains("lacks the inputs cfg_dt"), "{e}");
        let e = read("cycle,reset,cfg_dt,enc_q\n").unwrap_err();
        assert!(e.contains("`enc_q` is not an input"), "{e}");
        let e = read("cycle,reset,cfg_dt\n1,1,0\n").unwrap_err();
        assert!(e.contains("line 2") && e.contains("not 0"), "{e}");
        let e = read("cycle,reset,cfg_dt\n0,1,0\n0,0,0\n").unwrap_err();
        assert!(e.contains("line 3") && e.contains("does not follow"), "{e}");
        let e = read("cycle,reset,cfg_dt\n0,1,16777216\n").unwrap_err();
        assert!(e.contains("does not fit the port's 24 bits"), "{e}");
        let e = read("cycle,reset,cfg_dt\n0,1\n").unwrap_err();
        assert!(e.contains("line: 2") && e.contains("2 fields"), "{e}");
    }
}
