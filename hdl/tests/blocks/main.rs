// SPDX-License-Identifier: MIT OR Apache-2.0
//! The blocks' unit tests: one module per block, laid out as `hdl/src`. They live here, not
//! in `#[cfg(test)]` modules, so that `cargo test` compiles the `hdl` crate once instead of
//! twice (library and unit-test harness), which saves minutes of CI.

mod arith;
mod baselines;
mod bus;
mod ecc;
mod emit;
mod estimator;
mod frontend;
mod sim;
mod support;
mod top;
