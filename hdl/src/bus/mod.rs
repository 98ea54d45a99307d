// SPDX-License-Identifier: MIT OR Apache-2.0
//! Wishbone B4 register files, built from the register maps of `golden::bus`: the part
//! every window shares ([`reg_file::RegFile`]: the front end [`wb_front::WbFront`], the
//! interrupt pair [`irq_cell::IrqCell`] and the registered read data
//! [`read_data::ReadData`]) and one cell per register of the map, a kind per file
//! (constant, read-write, live word, LO/HI shadow pair, write-1 pulse).
//! [`wb_regs::WbRegs`] (the core's window) and [`ecc_regs::EccRegs`] (the eccentricity
//! window) are their maps' cells wired to a `RegFile`.

pub mod const_cell;
pub mod ecc_regs;
pub mod ecc_snapshot;
pub mod irq_cell;
pub mod pulse_cell;
pub mod read_cell;
pub mod read_data;
pub mod reg_file;
pub mod rw_cell;
pub mod shadow_cell;
pub mod snapshot;
pub mod wb_front;
pub mod wb_regs;
