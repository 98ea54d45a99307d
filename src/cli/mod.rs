// SPDX-License-Identifier: MIT OR Apache-2.0
//! The subcommands of `encspeed`, one module each (its options and what it runs), and
//! the generation parameters they share (`spec`).

pub mod accuracy;
pub mod bench;
pub mod bode;
pub mod check;
pub mod docs;
pub mod ecc_ripple;
pub mod generate;
pub mod identify;
pub mod monitor;
pub mod simulate;
pub mod spec;
pub mod synth;
pub mod vectors;

/// What a command returns: on failure the exit code and the message.
pub type Outcome = Result<(), (u8, String)>;
