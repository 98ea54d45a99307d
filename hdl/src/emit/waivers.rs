// SPDX-License-Identifier: MIT OR Apache-2.0
//! The Verilator lint waivers of each shipped top (`generated/<top>.vlt`): with them,
//! `verilator --lint-only -Wall <top>.vlt <top>.v` is clean. The tests lint and build every
//! top with exactly this text, so the shipped file is the one that was tested.
//!
//! Each source file in `lint/` explains each of its waivers. A top that contains another
//! carries the waivers of what it contains, retargeted to its own file: `encspeed_wb` those
//! of the core and of the Wishbone register file, `encspeed_ecc` the core's,
//! `encspeed_ecc_wb` `encspeed_ecc`'s and the register file's, each board top
//! `encspeed_wb`'s.

use super::tops::Top;

/// `encspeed_core.v`'s waivers.
pub const CORE: &str = include_str!("lint/core.vlt");
/// What `encspeed_wb.v` adds to the core's and the register file's.
const WB: &str = include_str!("lint/wb.vlt");
/// What the Wishbone register file (`WbRegs`) of `encspeed_wb` and `encspeed_ecc_wb` adds.
const REGS: &str = include_str!("lint/regs.vlt");
/// What `encspeed_ecc.v` adds.
const ECC: &str = include_str!("lint/ecc.vlt");
/// What `encspeed_ecc_wb.v` adds.
const ECC_WB: &str = include_str!("lint/ecc_wb.vlt");
/// What a board top `encspeed_board_<board>.v` adds to `encspeed_wb.v`'s.
const BOARD: &str = include_str!("lint/board.vlt");

/// The waivers of `top`: a Verilator configuration file (it starts with
/// `` `verilator_config ``), every section retargeted to `<module>.v`.
pub fn waivers(top: Top) -> String {
    let (sources, from): (&[&str], &str) = match top {
        Top::Core => (&[CORE], "encspeed_core.v"),
        Top::Wb => (&[CORE, WB, REGS], "encspeed_wb.v"),
        Top::Ecc => (&[CORE, ECC], "encspeed_ecc.v"),
        Top::EccWb => (&[CORE, ECC, REGS, ECC_WB], "encspeed_ecc_wb.v"),
    };
    retarget(sources, from, &top.verilog_file())
}

/// The waivers of the board top `module` (`<module>.v`): `encspeed_wb`'s and the board's.
pub fn board_waivers(module: &str) -> String {
    retarget(
        &[CORE, WB, REGS, BOARD],
        "encspeed_board.v",
        &format!("{module}.v"),
    )
}

/// `sources` as one Verilator configuration file, every section retargeted from
/// `encspeed_core.v`, `encspeed_ecc.v`, `encspeed_wb.v` or `from` to `file`.
fn retarget(sources: &[&str], from: &str, file: &str) -> String {
    let to = format!("\"*{file}\"");
    let mut text = String::from("`verilator_config\n");
    for source in sources {
        // Drop each source's own SPDX and `verilator_config lines: the file has one of each.
        let body: String = source
            .lines()
            .skip_while(|l| l.contains("SPDX-License-Identifier") || l.starts_with('`'))
            .map(|l| format!("{l}\n"))
            .collect();
        text.push_str(
            &body
                .replace("\"*encspeed_core.v\"", &to)
                .replace("\"*encspeed_ecc.v\"", &to)
                .replace("\"*encspeed_wb.v\"", &to)
                .replace(&format!("\"*{from}\""), &to),
        );
    }
    text
}
