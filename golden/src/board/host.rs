// SPDX-License-Identifier: MIT OR Apache-2.0
//! The host side of a board top: [`Bridge`] speaks the bridge's protocol
//! ([`crate::board::protocol`]) over any byte stream (a serial port in `encspeed monitor`,
//! a simulated board in the benches); [`identify`] reads what the IP was generated with
//! from its own registers, and [`sample`] takes a snapshot and reads its position, status
//! and speeds, scaled to r/min with that. Nothing here knows the board: it works on any `encspeed_wb` behind the
//! bridge.

use crate::board::protocol::{parse_response, Command, Response, ResponseError};
use crate::bus::regmap::{self, ID_MAGIC, MAP_VERSION};
use std::fmt;
use std::io::{Read, Write};

/// Why a host access failed.
#[derive(Debug)]
pub enum HostError {
    /// The byte stream failed (a serial port's time-out: no board, wrong port or baud).
    Io(std::io::Error),
    /// The bridge answered something else than the command's response.
    Response(ResponseError),
    /// `ID` is not "ENCS": not an encspeed register file at this port.
    NotEncspeed(u32),
    /// `VERSION`'s major number is not the one this program reads.
    Version(u32),
}

impl fmt::Display for HostError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HostError::Io(e) => write!(f, "serial line: {e} (board connected, right port, 115200 baud?)"),
            HostError::Response(e) => write!(f, "bridge: {e}"),
            HostError::NotEncspeed(id) => write!(
                f,
                "ID reads {id:#010x}, not {ID_MAGIC:#010x} (\"ENCS\"): no encspeed IP behind this port"
            ),
            HostError::Version(v) => write!(
                f,
                "register map version {v:#010x}: this program reads major version {}",
                MAP_VERSION >> 16
            ),
        }
    }
}

impl std::error::Error for HostError {}

impl From<std::io::Error> for HostError {
    fn from(e: std::io::Error) -> Self {
        HostError::Io(e)
    }
}

/// The bridge's protocol over the byte stream `port`: one command at a time, each waiting
/// for its whole response (stop-and-wait, as the bridge requires).
pub struct Bridge<T: Read + Write> {
    port: T,
}

impl<T: Read + Write> Bridge<T> {
    /// A bridge behind `port` (already at the right baud).
    pub fn new(port: T) -> Bridge<T> {
        Bridge { port }
    }

    /// The byte stream, for the caller's own use.
    pub fn port(&mut self) -> &mut T {
        &mut self.port
    }

    fn command(&mut self, cmd: Command) -> Result<Response, HostError> {
        self.port.write_all(&cmd.encode())?;
        self.port.flush()?;
        let mut bytes = vec![0u8; cmd.response_len()];
        self.port.read_exact(&mut bytes)?;
        parse_response(&cmd, &bytes).map_err(HostError::Response)
    }

    /// The word at byte offset `addr`.
    pub fn read(&mut self, addr: u32) -> Result<u32, HostError> {
        match self.command(Command::Read { addr: addr as u8 })? {
            Response::Data(d) => Ok(d),
            Response::WriteAck => unreachable!("parse_response answers a read with data"),
        }
    }

    /// Write `data` to the byte lanes `sel` of the word at `addr`.
    pub fn write(&mut self, addr: u32, data: u32, sel: u8) -> Result<(), HostError> {
        self.command(Command::Write {
            addr: addr as u8,
            data,
            sel,
        })
        .map(|_| ())
    }

    /// A speed's value: its LO register (which latches the HI word), then its HI register,
    /// as the sign-extended 64-bit value of the register map.
    pub fn read_speed(&mut self, lo: u32, hi: u32) -> Result<i64, HostError> {
        let low = self.read(lo)?;
        let high = self.read(hi)?;
        Ok(((u64::from(high) << 32) | u64::from(low)) as i64)
    }
}

/// What the IP behind a bridge was generated with, read from its registers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceInfo {
    /// N: width of the counters and of `cfg_dt` (`PARAM0.COUNTER_BITS`).
    pub counter_bits: u32,
    /// F: fractional bits of every speed (`PARAM0.SPEED_FRAC_BITS`).
    pub speed_frac_bits: u32,
    /// Lines per revolution (`LINES`).
    pub lines: u32,
    /// The IP's clock, Hz (`CLOCK_HZ`).
    pub clock_hz: u32,
    /// The generated dt, cycles (`DT_DEFAULT`), used while `CFG_DT` is 0.
    pub dt_default: u32,
}

/// Check `ID` and `VERSION`, then read the generation parameters.
pub fn identify<T: Read + Write>(bridge: &mut Bridge<T>) -> Result<DeviceInfo, HostError> {
    let id = bridge.read(regmap::ID)?;
    if id != ID_MAGIC {
        return Err(HostError::NotEncspeed(id));
    }
    let version = bridge.read(regmap::VERSION)?;
    if version >> 16 != MAP_VERSION >> 16 {
        return Err(HostError::Version(version));
    }
    let param0 = bridge.read(regmap::PARAM0)?;
    Ok(DeviceInfo {
        counter_bits: param0 & 0xFF,
        speed_frac_bits: (param0 >> 8) & 0xFF,
        lines: bridge.read(regmap::LINES)?,
        clock_hz: bridge.read(regmap::CLOCK_HZ)?,
        dt_default: bridge.read(regmap::DT_DEFAULT)?,
    })
}

/// One reading of the IP: the registers a drive engineer watches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// `SNAP_COUNT` after the sample's trigger: which snapshot the values are.
    pub snapshot: u32,
    /// `POSITION`.
    pub position: u32,
    /// `STATUS`, as read (bits: `VALID` 0, `STALLED` 1, `DIRECTION` 2 (1 forward), `CFG_ERROR` 3,
    /// sticky faults `ILLEGAL` 4, `OVERSPEED` 5, `REVOLUTION` 6).
    pub status: u32,
    /// The dt in force, cycles: `CFG_DT`, or `DT_DEFAULT` while it is 0.
    pub dt_cycles: u32,
    /// The six speeds as read (raw fixed point, units of 2^−F ω_lim), in register order:
    /// n1, n2, n3, PC, ET, M/T.
    pub speeds_raw: [i64; 6],
}

/// The speeds' names, in [`Sample::speeds_raw`]'s order.
pub const SPEED_NAMES: [&str; 6] = ["n1", "n2", "n3", "pc", "et", "mt"];

/// `CTRL`'s byte lane 1 as [`sample`] writes it: `SAMPLED`, `HOLD` and `TRIGGER`.
pub const SNAPSHOT_NOW: u32 = (1 << regmap::CTRL_SAMPLED_LSB)
    | (1 << regmap::CTRL_HOLD_LSB)
    | (1 << regmap::CTRL_TRIGGER_LSB);

/// Take a snapshot and read it as one [`Sample`]: a write of [`SNAPSHOT_NOW`] to `CTRL`'s
/// byte lane 1 alone (the modes in lane 0 stay) takes the snapshot and keeps it (`HOLD`)
/// for the reads that follow, which read it (`SAMPLED`): `SNAP_COUNT`, position, status,
/// dt, then each speed LO before HI, all of one clock cycle however slow the line.
pub fn sample<T: Read + Write>(
    bridge: &mut Bridge<T>,
    info: &DeviceInfo,
) -> Result<Sample, HostError> {
    bridge.write(regmap::CTRL, SNAPSHOT_NOW, 0b0010)?;
    let snapshot = bridge.read(regmap::SNAP_COUNT)?;
    let position = bridge.read(regmap::POSITION)?;
    let status = bridge.read(regmap::STATUS)?;
    let cfg_dt = bridge.read(regmap::CFG_DT)?;
    let mut speeds_raw = [0i64; 6];
    for (k, (lo, hi, _)) in regmap::SPEEDS.iter().enumerate() {
        speeds_raw[k] = bridge.read_speed(*lo, *hi)?;
    }
    Ok(Sample {
        snapshot,
        position,
        status,
        dt_cycles: if cfg_dt == 0 { info.dt_default } else { cfg_dt },
        speeds_raw,
    })
}

impl Sample {
    /// ω_lim at the dt in force, rev/s: one line per dt.
    pub fn omega_lim_rps(&self, info: &DeviceInfo) -> f64 {
        crate::params::omega_lim_rps(
            f64::from(info.clock_hz),
            info.lines,
            u64::from(self.dt_cycles),
        )
    }

    /// Speed `k` ([`SPEED_NAMES`]) in r/min: raw · 2^−F · ω_lim · 60.
    pub fn speed_rpm(&self, info: &DeviceInfo, k: usize) -> f64 {
        self.speeds_raw[k] as f64
            * (-f64::from(info.speed_frac_bits)).exp2()
            * self.omega_lim_rps(info)
            * 60.0
    }

    /// `STATUS` bit `bit`.
    fn flag(&self, bit: u32) -> bool {
        (self.status >> bit) & 1 == 1
    }

    /// One line of `encspeed monitor`: position, the speeds in r/min, the status flags.
    pub fn line(&self, info: &DeviceInfo) -> String {
        let mut s = format!("position {:>10}", self.position);
        for (k, name) in SPEED_NAMES.iter().enumerate() {
            s += &format!("  {name} {:>11.3}", self.speed_rpm(info, k));
        }
        s += " r/min ";
        for (bit, name) in [
            (0, "valid"),
            (1, "stalled"),
            (2, "forward"),
            (3, "cfg_error"),
            (4, "illegal"),
            (5, "overspeed"),
            (6, "revolution"),
        ] {
            if self.flag(bit) {
                s += " ";
                s += name;
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::VecDeque;
    use std::io;

    /// A port that records what the host writes and answers from a queue.
    struct Scripted {
        written: Vec<u8>,
        answers: VecDeque<u8>,
    }

    impl Read for Scripted {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            match self.answers.pop_front() {
                Some(b) if !buf.is_empty() => {
                    buf[0] = b;
                    Ok(1)
                }
                _ => Err(io::Error::new(io::ErrorKind::TimedOut, "no answer")),
            }
        }
    }

    impl Write for Scripted {
        fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
            self.written.extend_from_slice(buf);
            Ok(buf.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    /// The protocol bytes of docs/uart-bridge.md, and the scaling by hand: at 12 MHz,
    /// 1024 lines and dt = 12 000, ω_lim = 12e6 / (12 000 · 1024) rev/s = 58.59 r/min, so
    /// raw 2^16 (F = 16) is 58.59375 r/min and −2^15 is −29.296875.
    #[test]
    fn bridge_bytes_and_speed_scaling_by_hand() {
        let port = Scripted {
            written: Vec::new(),
            answers: [0x78, 0x56, 0x34, 0x12, 0x4B].into_iter().collect(),
        };
        let mut b = Bridge::new(port);
        assert_eq!(b.read(0x10).unwrap(), 0x1234_5678);
        b.write(0x24, 600, 0xF).unwrap();
        assert_eq!(
            b.port().written,
            [0x52, 0x10, 0x57, 0x24, 0x0F, 0x58, 0x02, 0x00, 0x00]
        );
        assert!(matches!(b.read(0), Err(HostError::Io(_))));
        let info = DeviceInfo {
            counter_bits: 24,
            speed_frac_bits: 16,
            lines: 1024,
            clock_hz: 12_000_000,
            dt_default: 12_000,
        };
        let s = Sample {
            snapshot: 1,
            position: 7,
            status: 0b101,
            dt_cycles: 12_000,
            speeds_raw: [1 << 16, 0, -(1 << 15), 0, 0, 0],
        };
        assert!((s.speed_rpm(&info, 0) - 58.59375).abs() < 1e-9);
        assert!((s.speed_rpm(&info, 2) + 29.296875).abs() < 1e-9);
        let line = s.line(&info);
        assert!(
            line.contains("valid forward") && !line.contains("stalled"),
            "{line}"
        );
    }
}
