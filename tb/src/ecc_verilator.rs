// SPDX-License-Identifier: MIT OR Apache-2.0
//! The emitted `encspeed_ecc.v` (the core with the corrected speeds and the eccentricity
//! identification) in Verilator, with the harness [`crate::verilator`] generates from its
//! port list: per-cycle streaming ([`crate::verilator::Simulator::run`]) for cycle-by-cycle
//! comparison with [`golden::top::ecc_top::EccTopModel`], and the event mode of
//! `tb/verilator/ecc_events.cpp` ([`EccVerilated::run_events`]) for revolutions of hundreds
//! of millions of cycles. A missing `verilator` is an error, never a skip: `.ci/run`
//! installs it.

use crate::verilator::{converse, counter_bits_of, Simulator};
use golden::ecc::ident_gatherer::GatherOutputs;
use golden::ideal::plant::Sample;
use golden::params::speed_bits_for;
use golden::top::core::CoreInputs;
use golden::top::ecc_top::{EccTopInputs, EccTopOutputs};
use golden::top::ports::ecc_ports;
use hdl::sim::ecc_sim::ECC_TOP_MODULE as MODULE;

/// The event mode (`--events`).
const EVENTS: &str = include_str!("../verilator/ecc_events.cpp");

/// The waivers of `encspeed_ecc.v`, as shipped in `generated/encspeed_ecc.vlt`.
pub fn waivers() -> String {
    hdl::Top::Ecc.waivers()
}

/// A compiled simulator of one emitted `encspeed_ecc`.
pub type EccVerilated = Simulator<EccTopInputs, EccTopOutputs>;

/// One line of the event mode: a cycle with a strobe.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EccStrobe {
    /// Cycle (edge) index, from 0.
    pub cycle: u64,
    /// `speed_mt` if `baseline_strobe` was high.
    pub speed_mt: Option<i64>,
    /// `speed_mtc` if `mtc_strobe` was high.
    pub speed_mtc: Option<i64>,
    /// `speed_n3` if `speed_strobe` was high.
    pub speed_n3: Option<i64>,
    /// `speed_n3c` if `n3c_strobe` was high.
    pub speed_n3c: Option<i64>,
    /// `position` in that cycle.
    pub position: u64,
    /// `speed_nep` in that cycle (what the last n3 was computed from).
    pub speed_nep: u64,
    /// `speed_ndt` in that cycle.
    pub speed_ndt: u64,
}

impl EccStrobe {
    /// The event-mode line of the outputs `o` after edge `cycle`, as the harness prints
    /// it: `None` if no speed strobe is high.
    pub fn of(cycle: u64, o: &EccTopOutputs) -> Option<EccStrobe> {
        let c = &o.core;
        (c.baseline_strobe || o.mtc_strobe || c.speed_strobe || o.n3c_strobe).then_some(EccStrobe {
            cycle,
            speed_mt: c.baseline_strobe.then_some(c.speed_mt),
            speed_mtc: o.mtc_strobe.then_some(o.speed_mtc),
            speed_n3: c.speed_strobe.then_some(c.speed_n3),
            speed_n3c: o.n3c_strobe.then_some(o.speed_n3c),
            position: c.position,
            speed_nep: c.speed_nep,
            speed_ndt: c.speed_ndt,
        })
    }
}

/// The configuration of an event-mode run.
#[derive(Clone, Copy, Debug)]
pub struct EventRun {
    /// Cycles to run (reset for the first 3).
    pub cycles: u64,
    /// `cfg_dt`.
    pub cfg_dt: u64,
    /// `cfg_mode`.
    pub cfg_mode: u8,
    /// `cfg_z_mode`.
    pub cfg_z_mode: u8,
    /// `ecc_c`, Q15.16.
    pub ecc_c: i64,
    /// `ecc_d`, Q15.16.
    pub ecc_d: i64,
    /// Raise `ident_arm` this many cycles after the first `index` (the position is aligned
    /// from then on); `None`: never.
    pub arm_delay: Option<u64>,
}

/// What an event-mode run printed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EventLog {
    /// Every cycle with a speed strobe.
    pub strobes: Vec<EccStrobe>,
    /// (cycle, results) at each rise of `ident_done`.
    pub ident: Vec<(u64, GatherOutputs)>,
}

impl EccVerilated {
    /// Compile `verilog` (module `encspeed_ecc`, speeds of `speed_bits` bits: checked against
    /// its ports) with its harness, or reuse the build.
    pub fn build(verilog: &str, speed_bits: u32) -> Result<EccVerilated, String> {
        let counter_bits = counter_bits_of(verilog, MODULE)?;
        if speed_bits_for(counter_bits) != speed_bits {
            return Err(format!(
                "{speed_bits}-bit speeds asked of a Verilog with {counter_bits}-bit counters"
            ));
        }
        Simulator::compile(
            verilog,
            MODULE,
            &ecc_ports(counter_bits),
            &waivers(),
            Some(EVENTS),
        )
    }

    /// Run `run.cycles` cycles of the levels `initial` then `changes` (cycle, levels from
    /// it on); the cycles with a strobe and the identifications.
    pub fn run_events(
        &self,
        run: &EventRun,
        initial: Sample,
        changes: &[(u64, Sample)],
    ) -> Result<EventLog, String> {
        let config = EccTopInputs {
            core: CoreInputs {
                cfg_dt: run.cfg_dt,
                cfg_mode: run.cfg_mode,
                cfg_z_mode: run.cfg_z_mode,
                ..CoreInputs::default()
            },
            ecc_c: run.ecc_c,
            ecc_d: run.ecc_d,
            ident_arm: false,
        };
        let levels =
            |k: u64, s: &Sample| format!("{k} {} {} {}\n", s.a as u8, s.b as u8, s.z as u8);
        let mut text = self.input_line(&config) + "\n";
        text.push_str(&levels(0, &initial));
        for (k, s) in changes {
            text.push_str(&levels(*k, s));
        }
        let args = [
            "--events".to_string(),
            run.cycles.to_string(),
            run.arm_delay.map_or(-1, |d| d as i64).to_string(),
        ];
        let mut log = EventLog::default();
        converse(self.exe(), &args, text, |line| {
            let (ident, rest) = match line.strip_prefix("I ") {
                Some(rest) => (true, rest),
                None => (false, line),
            };
            let (cycle, outputs) = rest
                .split_once(' ')
                .ok_or_else(|| format!("bad harness output {line:?}"))?;
            let cycle: u64 = cycle
                .parse()
                .map_err(|e| format!("bad harness output {line:?}: {e}"))?;
            let o = self.outputs_of(outputs)?;
            if ident {
                log.ident.push((cycle, o.ident));
            } else {
                let strobe = EccStrobe::of(cycle, &o)
                    .ok_or_else(|| format!("a line without a strobe: {line:?}"))?;
                log.strobes.push(strobe);
            }
            Ok(())
        })?;
        Ok(log)
    }
}
