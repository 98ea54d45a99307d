// SPDX-License-Identifier: MIT OR Apache-2.0
//! Golden model of encspeed.
//!
//! Layer 1 (float ideal, [`ideal`]): [`ideal::plant`] turns shaft motion into exact A/B/Z
//! edge instants and clock samples; [`ideal`] runs Rairán's estimator and the classical PC/ET
//! estimators in continuous time, [`ideal::mt`] the M/T estimator; [`eccentric`] holds the
//! eccentric-disc plants, identification and correction in f64; [`smallsignal`] the
//! small-signal models and the measured frequency responses.
//!
//! Layer 2 (bit-true), one folder per subsystem, each block's model named as its hardware
//! twin in `hdl`: [`frontend`], [`estimator`] (Table 1, the speed calculator, the bounds),
//! [`baselines`] (PC, ET, M/T), [`arith`] (the divider), [`ecc`] (eccentricity correction and
//! identification), [`bus`] (register maps and register files) and [`top`] (the shipped tops,
//! cycle for cycle, and their ports). [`board`] is the UART-to-Wishbone bridge of the board
//! tops: its serial protocol and UART line timing. [`params`] is the one validated parameter
//! type shared by the golden model, the HDL constructors and the generated manifest.
//!
//! This crate never depends on rust-hdl.
//!
//! [`reference`](mod@reference) makes the model a reference for other implementations: stimuli and
//! expected outputs as CSV or VCD, and a verdict on another simulator's VCD.
#![doc = include_str!("../README.md")]

pub mod arith;
pub mod baselines;
pub mod board;
pub mod bus;
pub mod ecc;
pub mod eccentric;
pub mod estimator;
pub mod freqresp;
pub mod frontend;
pub mod ideal;
pub mod params;
pub mod provenance;
pub mod reference;
pub mod smallsignal;
pub mod splitmix;
pub mod top;
