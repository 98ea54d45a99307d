// SPDX-License-Identifier: MIT OR Apache-2.0
//! The bit-true model as a reference for other implementations: a stimulus in (CSV or
//! VCD), the expected outputs out (CSV or VCD), and a verdict on another simulator's VCD.
//!
//! [`Reference`] runs the model of one top (`encspeed_core` or `encspeed_ecc`) on bit
//! patterns in the order of the top's port list ([`crate::top::ports`]), so every file
//! format here names the ports exactly as the shipped Verilog does.
//! [`stimulus`] reads stimuli, [`expected`] writes expected outputs, [`verdict`] compares a
//! VCD with the model. The conventions (cycle 0, which value a row holds, how a VCD is
//! sampled) are in docs/reference-model.md.

pub mod bound;
pub mod expected;
pub mod stimulus;
pub mod vcd_cycles;
pub mod verdict;

use crate::params::Params;
use crate::top::core::{CoreInputs, CoreModel, CoreOutputs};
use crate::top::ecc_top::{check as check_ecc, EccTopInputs, EccTopModel, EccTopOutputs};
use crate::top::port_fields::{
    from_port_bits, from_port_bits_unchecked, port_bits_into, signed_fields, to_port_bits,
    PortFields,
};
use crate::top::ports::{core_ports, cycle_inputs, cycle_outputs, ecc_ports, Port};

/// The tops the reference model runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefTop {
    /// `encspeed_core`: position, Table 1 and every speed estimator.
    Core,
    /// `encspeed_ecc`: the core with the eccentricity correction and identification.
    Ecc,
}

impl RefTop {
    /// The top's name on the command line (`core`, `ecc`).
    pub fn parse(name: &str) -> Result<RefTop, String> {
        match name {
            "core" => Ok(RefTop::Core),
            "ecc" => Ok(RefTop::Ecc),
            other => Err(format!("top `{other}` is not core or ecc")),
        }
    }

    /// The Verilog module name.
    pub fn module(self) -> &'static str {
        match self {
            RefTop::Core => "encspeed_core",
            RefTop::Ecc => "encspeed_ecc",
        }
    }
}

/// The model of one top, state included.
enum Model {
    Core(Box<Cached<CoreModel, CoreInputs, CoreOutputs>>),
    Ecc(Box<Cached<EccTopModel, EccTopInputs, EccTopOutputs>>),
}

/// A model with the conversions of its last step kept: a VCD's inputs and a model's
/// outputs stay the same for most cycles, and converting them is most of a step's cost.
struct Cached<M, I, O> {
    model: M,
    in_bits: Vec<u128>,
    input: I,
    output: Option<O>,
}

impl<M, I: PortFields + Copy, O: PortFields + Copy + PartialEq> Cached<M, I, O> {
    fn new(model: M) -> Self {
        Cached {
            model,
            in_bits: Vec::new(),
            input: I::default(),
            output: None,
        }
    }

    /// One step of `step` on the inputs `bits`, its outputs into `out`; whether they
    /// changed.
    fn step(
        &mut self,
        bits: &[u128],
        widths: (&[u32], &[u32]),
        out: &mut Vec<u128>,
        step: impl FnOnce(&mut M, I) -> O,
    ) -> bool {
        if self.in_bits != bits {
            self.input = from_port_bits_unchecked(bits, widths.0);
            self.in_bits.clear();
            self.in_bits.extend_from_slice(bits);
        }
        let o = step(&mut self.model, self.input);
        let changed = self.output != Some(o);
        if changed {
            port_bits_into(&o, widths.1, out);
            self.output = Some(o);
        }
        changed
    }
}

/// One port as the reference files carry it: its name and width, and whether its value is
/// signed (written and read as a signed decimal; two's complement on the wire).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RefPort {
    /// Verilog name.
    pub name: &'static str,
    /// Width in bits.
    pub width: u32,
    /// Two's complement.
    pub signed: bool,
}

impl RefPort {
    fn of(ports: &[Port], signed: Vec<bool>) -> Vec<RefPort> {
        ports
            .iter()
            .zip(signed)
            .map(|(p, signed)| RefPort {
                name: p.name,
                width: p.width,
                signed,
            })
            .collect()
    }

    /// The value of the bit pattern `bits` as a decimal integer (signed if the port is).
    pub fn decimal(&self, bits: u128) -> String {
        if self.signed && self.width < 128 && bits >> (self.width - 1) & 1 == 1 {
            let magnitude = (1u128 << self.width) - bits;
            format!("-{magnitude}")
        } else {
            bits.to_string()
        }
    }

    /// The bit pattern of the decimal `text`: an unsigned value below 2^width, or for a
    /// signed port also a negative one down to −2^(width−1). Anything else is an error,
    /// never truncated.
    pub fn parse(&self, text: &str) -> Result<u128, String> {
        let t = text.trim();
        let mask = if self.width >= 128 {
            u128::MAX
        } else {
            (1u128 << self.width) - 1
        };
        if let Some(magnitude) = t.strip_prefix('-') {
            let m: u128 = magnitude
                .parse()
                .map_err(|_| format!("{}: `{t}` is not an integer", self.name))?;
            if !self.signed {
                return Err(format!(
                    "{}: {t} is negative; the port is unsigned",
                    self.name
                ));
            }
            if self.width < 128 && m > 1u128 << (self.width - 1) {
                return Err(format!(
                    "{}: {t} is below −2^{} (the port is {} bits)",
                    self.name,
                    self.width - 1,
                    self.width
                ));
            }
            Ok(m.wrapping_neg() & mask)
        } else {
            let v: u128 = t
                .parse()
                .map_err(|_| format!("{}: `{t}` is not an integer", self.name))?;
            if v & !mask != 0 {
                return Err(format!(
                    "{}: {v} does not fit the port's {} bits",
                    self.name, self.width
                ));
            }
            Ok(v)
        }
    }
}

/// The bit-true model of a top, stepped on bit patterns.
pub struct Reference {
    model: Model,
    top: RefTop,
    inputs: Vec<RefPort>,
    outputs: Vec<RefPort>,
    input_widths: Vec<u32>,
    output_widths: Vec<u32>,
    /// The outputs of the last step.
    last: Vec<u128>,
    /// Whether the last step changed them (true after the first).
    changed: bool,
}

impl Reference {
    /// The model of `top` for `p`, in its state after reset; an error where the top refuses
    /// the parameters (the eccentricity top needs a multiple of 4 lines).
    pub fn new(p: &Params, top: RefTop) -> Result<Reference, String> {
        let (model, ports, inputs_signed, outputs_signed) = match top {
            RefTop::Core => (
                Model::Core(Box::new(Cached::new(CoreModel::new(p)))),
                core_ports(p.counter_bits()),
                signed_fields::<CoreInputs>(),
                signed_fields::<CoreOutputs>(),
            ),
            RefTop::Ecc => {
                check_ecc(p)?;
                (
                    Model::Ecc(Box::new(Cached::new(EccTopModel::new(p)))),
                    ecc_ports(p.counter_bits()),
                    signed_fields::<EccTopInputs>(),
                    signed_fields::<EccTopOutputs>(),
                )
            }
        };
        let (input_ports, output_ports) = (cycle_inputs(&ports), cycle_outputs(&ports));
        // The structs against the port lists, names and order, once: the steps convert
        // without the names.
        let (i, o) = (vec![0; input_ports.len()], vec![0; output_ports.len()]);
        match top {
            RefTop::Core => {
                from_port_bits::<CoreInputs>(&i, &input_ports);
                to_port_bits(
                    &from_port_bits::<CoreOutputs>(&o, &output_ports),
                    &output_ports,
                );
            }
            RefTop::Ecc => {
                from_port_bits::<EccTopInputs>(&i, &input_ports);
                to_port_bits(
                    &from_port_bits::<EccTopOutputs>(&o, &output_ports),
                    &output_ports,
                );
            }
        }
        let widths = |ports: &[Port]| ports.iter().map(|p| p.width).collect();
        Ok(Reference {
            model,
            top,
            inputs: RefPort::of(&input_ports, inputs_signed),
            outputs: RefPort::of(&output_ports, outputs_signed),
            input_widths: widths(&input_ports),
            output_widths: widths(&output_ports),
            last: Vec::with_capacity(output_ports.len()),
            changed: true,
        })
    }

    /// The outputs of the last step (empty before the first).
    pub fn last_outputs(&self) -> &[u128] {
        &self.last
    }

    /// Whether the last step's outputs differ from the step's before it (true after the
    /// first step).
    pub fn outputs_changed(&self) -> bool {
        self.changed
    }

    /// The top.
    pub fn top(&self) -> RefTop {
        self.top
    }

    /// The inputs of one cycle (every input but the clock), in port-list order.
    pub fn inputs(&self) -> &[RefPort] {
        &self.inputs
    }

    /// The outputs, in port-list order.
    pub fn outputs(&self) -> &[RefPort] {
        &self.outputs
    }

    /// One rising clock edge with the inputs `bits` (one pattern per [`Self::inputs`]);
    /// the outputs just after it (one pattern per [`Self::outputs`]).
    pub fn step(&mut self, bits: &[u128]) -> Vec<u128> {
        self.step_ref(bits).to_vec()
    }

    /// [`Self::step`] without allocating: the outputs stay valid until the next step.
    pub fn step_ref(&mut self, bits: &[u128]) -> &[u128] {
        let widths = (&self.input_widths[..], &self.output_widths[..]);
        self.changed = match &mut self.model {
            Model::Core(m) => m.step(bits, widths, &mut self.last, |m, i| m.step(i)),
            Model::Ecc(m) => m.step(bits, widths, &mut self.last, |m, i| m.step(i)),
        };
        &self.last
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn port(width: u32, signed: bool) -> RefPort {
        RefPort {
            name: "p",
            width,
            signed,
        }
    }

    #[test]
    fn decimals_round_trip_and_never_truncate() {
        let s = port(41, true);
        assert_eq!(s.parse("-1").unwrap(), (1 << 41) - 1);
        assert_eq!(s.decimal((1 << 41) - 1), "-1");
        assert_eq!(s.parse("-1099511627776").unwrap(), 1 << 40, "−2^40 fits");
        assert!(s.parse("-1099511627777").is_err(), "below −2^40");
        assert_eq!(
            s.parse("2199023255551").unwrap(),
            (1 << 41) - 1,
            "raw pattern"
        );
        assert!(s.parse("2199023255552").is_err(), "2^41 does not fit");
        let u = port(8, false);
        assert_eq!(u.parse(" 255 ").unwrap(), 255);
        assert!(u.parse("256").is_err());
        assert!(u.parse("-1").is_err());
        assert!(u.parse("0x10").is_err());
        assert_eq!(u.decimal(200), "200");
    }

    #[test]
    fn the_core_reference_is_the_core_model() {
        let p = Params::new(Default::default()).unwrap();
        let mut r = Reference::new(&p, RefTop::Core).unwrap();
        let mut m = CoreModel::new(&p);
        let ports = core_ports(p.counter_bits());
        let (ip, op) = (cycle_inputs(&ports), cycle_outputs(&ports));
        // A quarter-period quadrature pattern with a reset at the start.
        for k in 0..5_000u64 {
            let i = CoreInputs {
                reset: k < 3,
                enc_a: (k / 50) % 4 < 2,
                enc_b: (k / 50 + 1) % 4 < 2,
                enc_z: k % 4000 == 100,
                ..Default::default()
            };
            let got = r.step(&to_port_bits(&i, &ip));
            assert_eq!(
                from_port_bits::<CoreOutputs>(&got, &op),
                m.step(i),
                "cycle {k}"
            );
        }
    }
}
