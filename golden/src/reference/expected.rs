// SPDX-License-Identifier: MIT OR Apache-2.0
//! Running the model on a stimulus and writing what every output port should carry: as CSV
//! (a row at every cycle where an output changes) or as a VCD for GTKWave.

use super::stimulus::StimulusResult;
use super::{RefPort, Reference};
use std::io::{self, Write};

/// Where the expected outputs go, cycle by cycle.
pub trait ExpectedSink {
    /// The inputs sampled at the rising edge of `cycle`, and the outputs just after it.
    fn cycle(&mut self, cycle: u64, inputs: &[u128], outputs: &[u128]) -> io::Result<()>;
    /// After the last cycle.
    fn finish(&mut self, cycles: u64) -> io::Result<()>;
}

/// CSV: a header `cycle,<output>,...`; a row at cycle 0 and at every later cycle where any
/// output changes, each value the port's just after that cycle's rising edge, in decimal
/// (signed ports signed).
pub struct CsvExpected<W: Write> {
    out: W,
    ports: Vec<RefPort>,
    last: Option<Vec<u128>>,
}

impl<W: Write> CsvExpected<W> {
    /// Writes the header for the outputs `ports`.
    pub fn new(mut out: W, ports: &[RefPort]) -> io::Result<CsvExpected<W>> {
        let names: Vec<&str> = ports.iter().map(|p| p.name).collect();
        writeln!(out, "cycle,{}", names.join(","))?;
        Ok(CsvExpected {
            out,
            ports: ports.to_vec(),
            last: None,
        })
    }
}

impl<W: Write> ExpectedSink for CsvExpected<W> {
    fn cycle(&mut self, cycle: u64, _inputs: &[u128], outputs: &[u128]) -> io::Result<()> {
        if self.last.as_deref() == Some(outputs) {
            return Ok(());
        }
        write!(self.out, "{cycle}")?;
        for (p, &v) in self.ports.iter().zip(outputs) {
            write!(self.out, ",{}", p.decimal(v))?;
        }
        writeln!(self.out)?;
        self.last = Some(outputs.to_vec());
        Ok(())
    }

    fn finish(&mut self, _cycles: u64) -> io::Result<()> {
        self.out.flush()
    }
}

/// A VCD with the clock, the inputs and the outputs in one scope named as the top, in
/// picoseconds: the rising edge of cycle k at (k + ½)·T (T the clock period, rounded to a
/// whole even number of picoseconds), the inputs of cycle k set at k·T (the falling edge
/// before it), the outputs changing at the edge.
pub struct VcdExpected<W: Write> {
    vcd: vcd::Writer<W>,
    period_ps: u64,
    clock: vcd::IdCode,
    inputs: Vec<(vcd::IdCode, u32)>,
    outputs: Vec<(vcd::IdCode, u32)>,
    last_inputs: Option<Vec<u128>>,
    last_outputs: Option<Vec<u128>>,
}

/// The clock period in whole picoseconds, even so that the edge falls on a whole one.
pub fn period_ps(clock_hz: f64) -> u64 {
    let ps = (1e12 / clock_hz / 2.0).round().max(1.0) as u64;
    2 * ps
}

impl<W: Write> VcdExpected<W> {
    /// Writes the header: `module` holding `clock`, the `inputs` and the `outputs`.
    pub fn new(
        out: W,
        module: &str,
        clock_hz: f64,
        inputs: &[RefPort],
        outputs: &[RefPort],
    ) -> io::Result<VcdExpected<W>> {
        let mut vcd = vcd::Writer::new(out);
        vcd.timescale(1, vcd::TimescaleUnit::PS)?;
        vcd.add_module(module)?;
        let clock = vcd.add_wire(1, super::vcd_cycles::CLOCK)?;
        let mut add = |ports: &[RefPort]| -> io::Result<Vec<(vcd::IdCode, u32)>> {
            ports
                .iter()
                .map(|p| Ok((vcd.add_wire(p.width, p.name)?, p.width)))
                .collect()
        };
        let (inputs, outputs) = (add(inputs)?, add(outputs)?);
        vcd.upscope()?;
        vcd.enddefinitions()?;
        Ok(VcdExpected {
            vcd,
            period_ps: period_ps(clock_hz),
            clock,
            inputs,
            outputs,
            last_inputs: None,
            last_outputs: None,
        })
    }

    fn change(
        vcd: &mut vcd::Writer<W>,
        (id, width): (vcd::IdCode, u32),
        value: u128,
    ) -> io::Result<()> {
        if width == 1 {
            vcd.change_scalar(id, value & 1 == 1)
        } else {
            let bits: Vec<vcd::Value> = (0..width)
                .rev()
                .map(|b| (value >> b & 1 == 1).into())
                .collect();
            vcd.change_vector(id, &bits)
        }
    }

    /// The changes of `values` against `last` (all of them the first time).
    fn changes(
        vcd: &mut vcd::Writer<W>,
        ids: &[(vcd::IdCode, u32)],
        values: &[u128],
        last: &mut Option<Vec<u128>>,
    ) -> io::Result<()> {
        for (k, (&id, &v)) in ids.iter().zip(values).enumerate() {
            if last.as_ref().is_none_or(|l| l[k] != v) {
                Self::change(vcd, id, v)?;
            }
        }
        *last = Some(values.to_vec());
        Ok(())
    }
}

impl<W: Write> ExpectedSink for VcdExpected<W> {
    fn cycle(&mut self, cycle: u64, inputs: &[u128], outputs: &[u128]) -> io::Result<()> {
        let t = cycle * self.period_ps;
        self.vcd.timestamp(t)?;
        self.vcd.change_scalar(self.clock, false)?;
        Self::changes(&mut self.vcd, &self.inputs, inputs, &mut self.last_inputs)?;
        self.vcd.timestamp(t + self.period_ps / 2)?;
        self.vcd.change_scalar(self.clock, true)?;
        Self::changes(
            &mut self.vcd,
            &self.outputs,
            outputs,
            &mut self.last_outputs,
        )
    }

    fn finish(&mut self, cycles: u64) -> io::Result<()> {
        self.vcd.timestamp(cycles * self.period_ps)?;
        self.vcd.change_scalar(self.clock, false)?;
        Ok(())
    }
}

/// Runs `model` on `stimulus` (each row held until the next; the last row's cycle the last
/// one run) and gives every cycle to `sink`; the number of cycles run. A stimulus error is
/// returned as `Err(Ok(message))`, a write error as `Err(Err(io))`.
pub fn run_stimulus(
    model: &mut Reference,
    stimulus: impl Iterator<Item = StimulusResult>,
    sink: &mut dyn ExpectedSink,
) -> Result<u64, Result<String, io::Error>> {
    let mut held: Option<(u64, Vec<u128>)> = None;
    let mut cycle = 0u64;
    for row in stimulus {
        let row = row.map_err(Ok)?;
        if let Some((_, inputs)) = &held {
            while cycle < row.cycle {
                let outputs = model.step(inputs);
                sink.cycle(cycle, inputs, &outputs).map_err(Err)?;
                cycle += 1;
            }
        }
        held = Some((row.cycle, row.inputs));
    }
    let Some((last, inputs)) = held else {
        return Err(Ok("the stimulus has no rows".to_string()));
    };
    debug_assert_eq!(cycle, last);
    let outputs = model.step(&inputs);
    sink.cycle(cycle, &inputs, &outputs).map_err(Err)?;
    sink.finish(cycle + 1).map_err(Err)?;
    Ok(cycle + 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Params;
    use crate::reference::stimulus::CsvStimulus;
    use crate::reference::vcd_cycles::VcdCycles;
    use crate::reference::RefTop;

    /// A stimulus: reset for 3 cycles, then A and B in quadrature, 40 cycles a quarter.
    fn stimulus() -> String {
        let mut s = String::from(
            "cycle,reset,enc_a,enc_b,enc_z,cfg_dt,cfg_timeout,cfg_filter,cfg_mode,cfg_z_mode,clear_faults\n\
             0,1,0,0,0,0,0,0,2,1,0\n",
        );
        for q in 0..200u64 {
            let (a, b) = [(0, 0), (1, 0), (1, 1), (0, 1)][(q % 4) as usize];
            s.push_str(&format!("{},0,{a},{b},0,1000,0,0,2,1,0\n", 3 + 40 * q));
        }
        // A last row 40 cycles on, so that the last step reaches the outputs.
        s.push_str(&format!("{},0,0,1,0,1000,0,0,2,1,0\n", 3 + 40 * 200));
        s
    }

    #[test]
    fn the_csv_has_a_row_at_each_change_and_the_vcd_replays_to_the_same_outputs() {
        let p = Params::new(Default::default()).unwrap();
        let mut model = Reference::new(&p, RefTop::Core).unwrap();
        let outputs = model.outputs().to_vec();
        let inputs = model.inputs().to_vec();
        let text = stimulus();
        let mut csv = CsvExpected::new(Vec::new(), &outputs).unwrap();
        let rows = CsvStimulus::new(text.as_bytes(), &inputs).unwrap();
        let n = run_stimulus(&mut model, rows, &mut csv).unwrap();
        assert_eq!(n, 3 + 40 * 200 + 1, "the last row's cycle is the last run");
        let csv = String::from_utf8(csv.out).unwrap();
        let lines: Vec<&str> = csv.lines().collect();
        assert!(lines[0].starts_with("cycle,position,z_latch,index,"));
        assert!(lines[1].starts_with("0,"), "cycle 0 always has a row");
        // The position counts x4: 199 steps after the last edge reaches the counter.
        let position = |line: &str| line.split(',').nth(1).unwrap().parse::<u64>().unwrap();
        assert_eq!(position(lines.last().unwrap()), 199);
        // Every row differs from the one before it.
        for w in lines[1..].windows(2) {
            assert_ne!(
                w[0].split_once(',').unwrap().1,
                w[1].split_once(',').unwrap().1
            );
        }

        // The VCD of the same run, read back by the sampler: the inputs at each edge are the
        // stimulus's, the outputs before edge k + 1 are the model's after edge k.
        let mut model = Reference::new(&p, RefTop::Core).unwrap();
        let mut bytes = Vec::new();
        let mut vcd =
            VcdExpected::new(&mut bytes, "encspeed_core", 1e8, &inputs, &outputs).unwrap();
        let rows = CsvStimulus::new(text.as_bytes(), &inputs).unwrap();
        run_stimulus(&mut model, rows, &mut vcd).unwrap();
        drop(vcd);
        let mut replay = Reference::new(&p, RefTop::Core).unwrap();
        let mut previous: Option<Vec<u128>> = None;
        let mut edges = 0;
        for edge in VcdCycles::new(&bytes[..], &inputs, &outputs, None, &[]).unwrap() {
            let edge = edge.unwrap();
            assert_eq!(edge.time, edge.cycle * 10_000 + 5_000, "ps, 100 MHz");
            if let Some(prev) = previous {
                let got: Vec<u128> = edge.outputs.iter().map(|o| o.unwrap()).collect();
                assert_eq!(got, prev, "cycle {}", edge.cycle);
            }
            previous = Some(replay.step(&edge.inputs));
            edges += 1;
        }
        assert_eq!(edges, n);
    }
}
