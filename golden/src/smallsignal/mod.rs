// SPDX-License-Identifier: MIT OR Apache-2.0
//! Small-signal models of the incremental encoder and its speed estimators, after
//! Vázquez-Gutiérrez, O'Sullivan and Kavanagh, "Small-signal modeling of the incremental
//! optical encoder for motor control", IEEE Trans. Ind. Electron., 2019 ("the paper").
//!
//! The question these models answer: how much gain and phase does the encoder with its
//! speed estimator cost a speed loop at a given frequency, speed, resolution and sample
//! time? Everything is evaluated on the imaginary axis, s = j2πf, f in Hz.
//!
//! - [`OperatingPoint`]: resolution R (transitions per revolution), speed n̄ (r/min) and
//!   control sample time T_s (s), validated once; T_e, l and L̄ are derived from it.
//! - [`Model`]: a transfer function as a product of [`Factor`]s (zero-order hold, pure
//!   delay, moving average, lead), with constructors for the paper's equations (15), (16),
//!   (24), (27)–(29) and (33).
//! - [`Bode`]: gain (linear and dB) and phase (degrees) over a frequency vector, with
//!   deterministic CSV output.
//!
//! Phase convention (see [`BodePoint::phase_deg`]): every factor is written as a signed
//! real amplitude times e^{jφ(ω)} with φ continuous in ω (the delays' linear phase and the
//! lead's arctangents); the reported phase is Σφ in degrees plus 180° where the product of
//! the amplitudes is negative. So it never wraps by 360°, a double zero (ZOH²) leaves the
//! phase continuous, and a single sign change (a simple zero of a ZOH on the jω axis)
//! jumps by +180°, as a sampled-data Bode plot usually shows it.
//!
//! docs/small-signal.md lists the equations as implemented, where the machine-converted
//! paper was garbled and had to be derived again, the known answers and the reproduction of
//! the paper's Section IV.

mod bode;
mod error;
mod factor;
mod model;
mod operating_point;

pub use bode::{log_frequencies, Bode, BodePoint};
pub use error::{SmallSignalError, MAX_FREQUENCIES};
pub use factor::{zoh, zoh_at, Factor, Lead, Polar};
pub use model::{phase_margin_at_fixed_crossover, Model};
pub use num_complex::Complex64;
pub use operating_point::{OperatingPoint, SpeedRange};
