// SPDX-License-Identifier: MIT OR Apache-2.0
//! The board tops' Verilog, `generated/encspeed_board_<board>.v` (and its lint waivers
//! `.vlt`): one top per board of
//! [`Board::ALL`], its `encspeed_wb` generated for the user's parameters at the board clock
//! ([`Board::params`]). `encspeed generate` writes them beside the IP; the FuseSoC core's
//! board targets build their bitstreams with the pins of [`Board::constraints_file`];
//! docs/boards.md.

use crate::sim::board_sim::build_board;
use golden::board::boards::{board_ports, Board};
use golden::params::Spec;
use golden::provenance::{generate_command, preamble, Comment};

/// The files of `board`'s top for the user's `spec` as (file name, contents): its Verilog
/// `<module>.v` and its lint waivers `<module>.vlt`; or why the board cannot have those
/// parameters. The first line names `command`, the command that wrote every generated
/// file (the board tops come with the IP's own files).
pub fn board_files(
    board: Board,
    spec: &Spec,
    command: &str,
) -> Result<Vec<(String, String)>, String> {
    if spec.channels != 1 {
        return Err(format!(
            "{} has one encoder PMOD, so its top has one channel (channels = {})",
            board.name(),
            spec.channels
        ));
    }
    let p = board
        .params(spec)
        .map_err(|e| format!("{} at {} Hz: {e}", board.name(), board.clock_hz()))?;
    let uart = board.uart();
    let module = board.module();
    let mut text = String::new();
    let mut line = |t: String| {
        text.push_str("// ");
        text.push_str(&t);
        text.push('\n');
    };
    line(format!(
        "Board top for {}: encspeed_wb behind a UART-to-Wishbone bridge, power-on reset, four LEDs (docs/boards.md).",
        board.name()
    ));
    line(format!(
        "IP parameters ({}): {}",
        generate_command(&p),
        p.summary()
    ));
    line(format!(
        "UART: {} baud 8N1 at {} Hz, {} cycles a bit ({:+.2} %); protocol: docs/uart-bridge.md.",
        uart.baud(),
        uart.clock_hz(),
        uart.divisor(),
        uart.error_percent()
    ));
    line(format!("Pins: {}", board.constraints_file()));
    line("Ports:".into());
    for port in board_ports() {
        line(super::port_line(&port));
    }
    let head = super::file_header(command, &module, &text);
    let body = build_board(board, &p).verilog(&module);
    let waivers = preamble(Comment::Slashes, command) + &super::waivers::board_waivers(&module);
    Ok(vec![
        (format!("{module}.v"), format!("{head}\n{body}")),
        (format!("{module}.vlt"), waivers),
    ])
}
