// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed monitor --serial PORT`: a board top's registers live over its USB UART
//! (docs/boards.md): identifies the IP from its own registers (`golden::board::host`), then
//! prints position, the six speeds in r/min and the status flags, one line per interval.

use clap::Args;
use golden::board::boards::BOARD_BAUD;
use golden::board::host::{identify, sample, Bridge};
use std::time::Duration;

use super::Outcome;

/// Options of `encspeed monitor`.
#[derive(Args)]
pub struct MonitorArgs {
    /// The board's serial port (the second of the two an FT2232H board adds, e.g.
    /// /dev/ttyUSB1).
    #[arg(long, value_name = "PORT")]
    serial: String,
    /// Line speed; the board tops run 115 200 baud.
    #[arg(long, default_value_t = BOARD_BAUD as u32)]
    baud: u32,
    /// Time between two lines, ms.
    #[arg(long, default_value_t = 200)]
    interval_ms: u64,
    /// Stop after this many lines (0: until interrupted).
    #[arg(long, default_value_t = 0)]
    count: u64,
}

/// `encspeed monitor`.
pub fn run(args: &MonitorArgs) -> Outcome {
    let port = serialport::new(&args.serial, args.baud)
        .timeout(Duration::from_millis(500))
        .open()
        .map_err(|e| (1, format!("cannot open {}: {e}", args.serial)))?;
    let mut bridge = Bridge::new(port);
    let fail = |e: golden::board::host::HostError| (1, format!("{}: {e}", args.serial));
    let info = identify(&mut bridge).map_err(fail)?;
    println!(
        "encspeed at {}: {} lines, {} Hz clock, {}-bit counters, dt {} cycles by default",
        args.serial, info.lines, info.clock_hz, info.counter_bits, info.dt_default
    );
    let mut printed = 0;
    while args.count == 0 || printed < args.count {
        let s = sample(&mut bridge, &info).map_err(fail)?;
        println!("{}", s.line(&info));
        printed += 1;
        std::thread::sleep(Duration::from_millis(args.interval_ms));
    }
    Ok(())
}
