// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::ecc::sine_rom`.

use crate::support::verilator_lint;
use hdl::ecc::sine_rom::*;
use rust_hdl::prelude::*;

#[test]
fn synthesises() {
    let mut uut = SineRom::<10, 16>::new(1000);
    uut.connect_all();
    yosys_validate("encspeed_sine_rom", &generate_verilog(&uut)).unwrap();
}

#[test]
fn verilator_lint_is_clean() {
    verilator_lint("sine_rom", &sine_rom_verilog::<10, 16>(1024, "sine_rom"));
    verilator_lint("sine_rom", &sine_rom_verilog::<10, 16>(1000, "sine_rom"));
    verilator_lint("sine_rom", &sine_rom_verilog::<2, 4>(4, "sine_rom"));
}
