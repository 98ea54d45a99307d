// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::ecc::table_rom`.

use hdl::ecc::table_rom::*;
use rust_hdl::prelude::*;

#[test]
fn index_bits_by_hand() {
    assert_eq!(index_bits(1), 1);
    assert_eq!(index_bits(2), 1);
    assert_eq!(index_bits(4), 2);
    assert_eq!(index_bits(1000), 10);
    assert_eq!(index_bits(1024), 10);
    assert_eq!(index_bits(1025), 11);
    assert_eq!(index_bits(65_536), 16);
}

#[test]
fn declares_k_words() {
    let mut uut = TableRom::<24, 16>::new(&[1, 2, 3, 0xff_ffff_ffff]);
    uut.connect_all();
    let v = hdl::verilog::named_verilog(&uut, "table_rom");
    assert!(v.contains("reg [23:0] mem [3:0];"), "{v}");
    assert!(v.contains("mem[3] = 24'hffffff;"), "{v}");
    assert!(v.contains("word <= mem[address[1:0]];"), "{v}");
    assert!(v.contains("in_range <= {1'b0, address} < 17'd4;"), "{v}");
}
