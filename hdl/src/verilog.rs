// SPDX-License-Identifier: MIT OR Apache-2.0
//! The Verilog text of a rust-hdl block with its top module named, the one way every block,
//! top and simulation asks rust-hdl for Verilog. A leaf: it knows no block.

use rust_hdl::prelude::{check_all, Block, ModuleDefines};

/// The Verilog of any connected block, checked by rust-hdl, with its top module named
/// `module_name` (rust-hdl's own `generate_verilog` always names it `top`).
pub fn named_verilog(uut: &dyn Block, module_name: &str) -> String {
    check_all(uut).expect("rust-hdl design check");
    let mut defines = ModuleDefines::default();
    uut.accept(module_name, &mut defines);
    defines.defines()
}

/// The Verilog of a block built by `Default` (the standalone blocks), connected and checked,
/// top module named `module_name`.
pub fn default_block_verilog<B: Block + Default>(module_name: &str) -> String {
    let mut uut = B::default();
    uut.connect_all();
    named_verilog(&uut, module_name)
}
