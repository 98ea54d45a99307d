// SPDX-License-Identifier: MIT OR Apache-2.0
//! Waveforms: simulate inputs through the rust-hdl core while writing a VCD of every
//! signal (ports, the synchroniser, the ts counter, Cep, Cdt, Nep1, Ndt1), and read a VCD
//! back with the `vcd` crate.

use golden::params::Params;
use golden::top::core::{CoreInputs, CoreOutputs};
use std::collections::HashMap;
use std::io::BufWriter;
use std::path::Path;

/// Simulate `inputs` through the rust-hdl core and write the VCD to `path` (directories
/// are created). Returns the outputs of every cycle.
pub fn simulate_to_vcd(
    p: &Params,
    inputs: &[CoreInputs],
    path: &Path,
) -> std::io::Result<Vec<CoreOutputs>> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let file = BufWriter::new(std::fs::File::create(path)?);
    let mut sim = hdl::build_core(p);
    let period_ps = (1e12 / p.clock_hz()).round().max(2.0) as u64;
    sim.start_vcd(Box::new(file), period_ps);
    let outs = inputs.iter().map(|i| sim.step(i)).collect();
    sim.finish_vcd()?;
    Ok(outs)
}

/// Values of the named scalar or vector signals of a VCD after every timestamp, as
/// `name → [(time, value)]` (value changes only). Names are the VCD reference names
/// with their scope path joined by '.', e.g. `uut.nep`.
pub fn read_vcd(path: &Path, names: &[&str]) -> std::io::Result<HashMap<String, Vec<(u64, u64)>>> {
    let mut parser = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(path)?));
    let header = parser.parse_header()?;
    let mut ids = HashMap::new();
    for name in names {
        let parts: Vec<&str> = name.split('.').collect();
        let var = header.find_var(&parts).ok_or_else(|| {
            std::io::Error::new(
                std::io::ErrorKind::NotFound,
                format!("no signal {name} in VCD"),
            )
        })?;
        ids.insert(var.code, name.to_string());
    }
    let mut out: HashMap<String, Vec<(u64, u64)>> =
        names.iter().map(|n| (n.to_string(), vec![])).collect();
    let mut now = 0u64;
    for cmd in parser {
        match cmd? {
            vcd::Command::Timestamp(t) => now = t,
            vcd::Command::ChangeScalar(id, v) => {
                if let Some(n) = ids.get(&id) {
                    out.get_mut(n)
                        .expect("registered")
                        .push((now, (v == vcd::Value::V1) as u64));
                }
            }
            vcd::Command::ChangeVector(id, v) => {
                if let Some(n) = ids.get(&id) {
                    let x = v
                        .iter()
                        .fold(0u64, |acc, b| (acc << 1) | (*b == vcd::Value::V1) as u64);
                    out.get_mut(n).expect("registered").push((now, x));
                }
            }
            _ => {}
        }
    }
    Ok(out)
}
