// SPDX-License-Identifier: MIT OR Apache-2.0
//! How the Rust structs of one cycle's values (`CoreInputs`, `EccTopOutputs`, …) map onto
//! their top's port list ([`crate::top::ports`]): every field carries one port, and the
//! fields are visited in the order of the list ([`PortFields`]). The benches turn a struct
//! into the ports' bit patterns and back by walking the list ([`to_port_bits`],
//! [`from_port_bits`]), so no harness, bench or parser names the ports again.
//!
//! A struct whose fields are exactly its ports is declared through `port_struct!`, so that
//! its declaration is the one list of its fields; a struct that nests another (`EccTopInputs`
//! holds `CoreInputs`) or a struct of another module (`WbBus`, `GatherOutputs`) lists them
//! in its own [`PortFields`] (`visit_fields!`). Either way a field that is not the next port
//! of the list panics at the first conversion, and the tests below check every top's
//! structs against its list: names, order, and that each port's width fits its field's
//! type.

use crate::top::ports::Port;

/// A value one port carries, as the port's bit pattern and back.
pub trait PortValue {
    /// Bits the Rust type holds: a port wider than this does not fit it.
    fn capacity(&self) -> u32;
    /// The low `width` bits of the value (two's complement for a signed type).
    fn bits(&self, width: u32) -> u128;
    /// Set the value from the `width`-bit pattern `bits` (sign-extended for a signed type).
    fn set_bits(&mut self, bits: u128, width: u32);
    /// The field holds a signed value (its port carries it as two's complement).
    fn signed(&self) -> bool;
}

/// The low `width` bits of `v`.
fn low_bits(v: u128, width: u32) -> u128 {
    if width >= u128::BITS {
        v
    } else {
        v & ((1u128 << width) - 1)
    }
}

impl PortValue for bool {
    fn capacity(&self) -> u32 {
        1
    }
    fn bits(&self, _width: u32) -> u128 {
        u128::from(*self)
    }
    fn set_bits(&mut self, bits: u128, _width: u32) {
        *self = bits != 0;
    }
    fn signed(&self) -> bool {
        false
    }
}

/// [`PortValue`] of integers: an unsigned value is its bit pattern, a signed one (`MIN` ≠ 0)
/// is carried as two's complement.
macro_rules! integer_port_value {
    ($($t:ty),*) => {$(
        impl PortValue for $t {
            fn capacity(&self) -> u32 {
                <$t>::BITS
            }
            fn bits(&self, width: u32) -> u128 {
                low_bits(*self as i128 as u128, width)
            }
            fn set_bits(&mut self, bits: u128, width: u32) {
                let shift = u128::BITS - width;
                *self = if <$t>::MIN != 0 {
                    (((bits << shift) as i128) >> shift) as $t
                } else {
                    low_bits(bits, width) as $t
                };
            }
            fn signed(&self) -> bool {
                <$t>::MIN != 0
            }
        }
    )*};
}
integer_port_value!(u8, u32, u64, i64, i128);

/// One cycle's values of a top's inputs, or of its outputs: every field carries one port.
pub trait PortFields: Default {
    /// `visit(port name, field)` for every field, in the order of the top's port list.
    fn visit_ports(&mut self, visit: &mut dyn FnMut(&'static str, &mut dyn PortValue));
}

/// Declares a struct whose fields are named as the ports they carry, in the order of the
/// port list, with its [`PortFields`] visiting them in declaration order.
macro_rules! port_struct {
    (
        $(#[$meta:meta])*
        $vis:vis struct $name:ident {
            $($(#[$field_meta:meta])* $field_vis:vis $field:ident: $ty:ty,)*
        }
    ) => {
        $(#[$meta])*
        $vis struct $name {
            $($(#[$field_meta])* $field_vis $field: $ty,)*
        }

        impl $crate::top::port_fields::PortFields for $name {
            fn visit_ports(
                &mut self,
                visit: &mut dyn FnMut(&'static str, &mut dyn $crate::top::port_fields::PortValue),
            ) {
                $crate::top::port_fields::visit_fields!(visit, self, "": $($field),*);
            }
        }
    };
}
pub(crate) use port_struct;

/// `visit(prefix + field name, field of target)` for each of `fields`, in order: the body of
/// a [`PortFields`] for fields named as their ports (after `prefix`).
macro_rules! visit_fields {
    ($visit:ident, $target:expr, $prefix:literal: $($field:ident),*) => {
        $($visit(concat!($prefix, stringify!($field)), &mut $target.$field);)*
    };
}
pub(crate) use visit_fields;

/// Port `k` of `ports`, which the field `field` must carry.
fn port_of_field<'a>(ports: &'a [Port], k: usize, field: &str) -> &'a Port {
    match ports.get(k) {
        Some(port) if port.name == field => port,
        other => panic!(
            "the field for port {field} stands where the port list has {:?}: the struct and \
             the list disagree",
            other.map(|p| p.name)
        ),
    }
}

/// The bit patterns of `values`' fields, in the order of `ports` (the inputs or the outputs
/// they carry: [`crate::top::ports::cycle_inputs`], [`crate::top::ports::cycle_outputs`]).
pub fn to_port_bits<T: PortFields + Clone>(values: &T, ports: &[Port]) -> Vec<u128> {
    let mut bits = Vec::with_capacity(ports.len());
    values.clone().visit_ports(&mut |field, v| {
        let port = port_of_field(ports, bits.len(), field);
        bits.push(v.bits(port.width));
    });
    assert_eq!(bits.len(), ports.len(), "a port without a field");
    bits
}

/// The values whose bit patterns are `bits`, in the order of `ports`.
pub fn from_port_bits<T: PortFields>(bits: &[u128], ports: &[Port]) -> T {
    assert_eq!(bits.len(), ports.len(), "one bit pattern per port");
    let mut values = T::default();
    let mut k = 0;
    values.visit_ports(&mut |field, v| {
        let port = port_of_field(ports, k, field);
        v.set_bits(bits[k], port.width);
        k += 1;
    });
    assert_eq!(k, ports.len(), "a port without a field");
    values
}

/// The bit patterns of `values`' fields into `out` (cleared first), the k-th field `widths[k]`
/// bits wide: [`to_port_bits`] without the names checked, for per-cycle use once
/// [`to_port_bits`] has checked the struct against the list.
pub fn port_bits_into<T: PortFields + Clone>(values: &T, widths: &[u32], out: &mut Vec<u128>) {
    out.clear();
    values.clone().visit_ports(&mut |_, v| {
        let k = out.len();
        out.push(v.bits(widths[k]));
    });
}

/// The values whose bit patterns are `bits`, the k-th `widths[k]` bits wide: [`from_port_bits`]
/// without the names checked.
pub fn from_port_bits_unchecked<T: PortFields>(bits: &[u128], widths: &[u32]) -> T {
    let mut values = T::default();
    let mut k = 0;
    values.visit_ports(&mut |_, v| {
        v.set_bits(bits[k], widths[k]);
        k += 1;
    });
    values
}

/// Whether each field of `T` holds a signed value, in the order of its ports.
pub fn signed_fields<T: PortFields>() -> Vec<bool> {
    let mut signed = Vec::new();
    T::default().visit_ports(&mut |_, v| signed.push(v.signed()));
    signed
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{MAX_COUNTER_BITS, MIN_COUNTER_BITS};
    use crate::top::core::{CoreInputs, CoreOutputs};
    use crate::top::ecc_top::{EccTopInputs, EccTopOutputs};
    use crate::top::ports::{core_ports, cycle_inputs, cycle_outputs, ecc_ports};
    use crate::top::wb_top::{wb_top_ports, WbTopInputs, WbTopOutputs};

    /// The fields of `T` as (port name, bits the field holds), in visiting order.
    fn fields<T: PortFields>() -> Vec<(&'static str, u32)> {
        let mut out = Vec::new();
        T::default().visit_ports(&mut |name, v| out.push((name, v.capacity())));
        out
    }

    /// `T` carries exactly `ports`, in order, each in a field that holds its width.
    fn assert_carries<T: PortFields>(ports: &[Port]) {
        let f = fields::<T>();
        let names: Vec<&str> = f.iter().map(|(n, _)| *n).collect();
        let expected: Vec<&str> = ports.iter().map(|p| p.name).collect();
        assert_eq!(names, expected, "{}", std::any::type_name::<T>());
        for ((name, capacity), port) in f.iter().zip(ports) {
            assert!(
                port.width <= *capacity,
                "{name}: {} bits in a field of {capacity}",
                port.width
            );
        }
    }

    #[test]
    fn every_tops_structs_carry_its_port_list_in_order() {
        for n in [MIN_COUNTER_BITS, 24, MAX_COUNTER_BITS] {
            let core = core_ports(n);
            assert_carries::<CoreInputs>(&cycle_inputs(&core));
            assert_carries::<CoreOutputs>(&cycle_outputs(&core));
            let ecc = ecc_ports(n);
            assert_carries::<EccTopInputs>(&cycle_inputs(&ecc));
            assert_carries::<EccTopOutputs>(&cycle_outputs(&ecc));
        }
        let wb = wb_top_ports();
        assert_carries::<WbTopInputs>(&cycle_inputs(&wb));
        assert_carries::<WbTopOutputs>(&cycle_outputs(&wb));
    }

    #[test]
    fn values_survive_their_bit_patterns_signed_ones_sign_extended() {
        let ports = cycle_outputs(&ecc_ports(24));
        let mut o = EccTopOutputs::default();
        o.core.position = 0xffff_fffe;
        o.core.speed_n3 = -3;
        o.core.mt_negative = true;
        o.speed_n3c = -(1 << 39);
        o.ident.sum_sin = -5;
        o.ident.sum_t = (1 << 70) + 7;
        let bits = to_port_bits(&o, &ports);
        let speed = ports.iter().position(|p| p.name == "speed_n3").unwrap();
        assert_eq!(bits[speed], (1 << 41) - 3, "41-bit two's complement");
        let sum_sin = ports
            .iter()
            .position(|p| p.name == "ident_sum_sin")
            .unwrap();
        assert_eq!(bits[sum_sin], (1 << 72) - 5, "72-bit two's complement");
        assert_eq!(from_port_bits::<EccTopOutputs>(&bits, &ports), o);
    }

    #[test]
    #[should_panic(expected = "disagree")]
    fn a_struct_that_is_not_the_list_is_refused() {
        let ports = cycle_inputs(&wb_top_ports());
        from_port_bits::<CoreInputs>(&vec![0; ports.len()], &ports);
    }
}
