// SPDX-License-Identifier: MIT OR Apache-2.0
//! The serial protocol of the UART-to-Wishbone bridge (`hdl::board::uart_wb_bridge`): binary,
//! byte-oriented, one command at a time (the host sends a command and waits for its whole
//! response before the next).
//!
//! | command | bytes host → bridge | response bridge → host | Wishbone access |
//! |---|---|---|---|
//! | read | `0x52` (`'R'`), `addr` | `d0 d1 d2 d3`: the word read, least significant byte first | read, `wb_adr_o` = `addr`, `wb_sel_o` = `0xF` |
//! | write | `0x57` (`'W'`), `addr`, `sel`, `d0 d1 d2 d3` (least significant first) | `0x4B` (`'K'`) once the write was acknowledged | write, `wb_adr_o` = `addr`, `wb_sel_o` = `sel & 0xF`, `wb_dat_o` = d3:d2:d1:d0 |
//!
//! - `addr` is the Wishbone byte address, passed as sent (a slave with 32-bit words ignores
//!   its bits 1:0, as `encspeed_wb` does). The high four bits of `sel` are ignored.
//! - **Resynchronisation.** While idle, the bridge ignores every byte that is not a command
//!   byte (`0x52`, `0x57`), so noise between commands is harmless. A framing error (a stop
//!   bit received 0) inside a command abandons that command, and no response is sent; a
//!   framing error while idle is ignored. So a host that lost track sends a break (the line
//!   low for at least one frame), discards what it receives until nothing has arrived for a
//!   frame time, and starts again (padding with bytes instead could complete a write).
//! - Bytes that arrive while the bridge executes a command or sends its response are
//!   ignored: the protocol is stop-and-wait.
//! - There is no time-out: a Wishbone slave that never acknowledges stalls the bridge until
//!   its reset.
//!
//! [`Parser`] is the byte-level model of the bridge's command decoder; the host uses
//! [`Command::encode`] and [`parse_response`].

use crate::board::uart::RxEvent;
use std::fmt;

/// Command byte of a read, `'R'`.
pub const READ: u8 = 0x52;
/// Command byte of a write, `'W'`.
pub const WRITE: u8 = 0x57;
/// The response to a write, `'K'`.
pub const WRITE_ACK: u8 = 0x4B;
/// Bytes after the command byte: a read's address.
pub const READ_ARGS: usize = 1;
/// Bytes after the command byte: a write's address, byte lanes and 4 data bytes.
pub const WRITE_ARGS: usize = 6;

/// One request of the host.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// Read the word at byte address `addr` (all four byte lanes).
    Read {
        /// Wishbone byte address.
        addr: u8,
    },
    /// Write `data` to the byte lanes `sel` (bits 3:0) of the word at `addr`.
    Write {
        /// Wishbone byte address.
        addr: u8,
        /// The word; only the lanes of `sel` are written.
        data: u32,
        /// Byte lanes, bit i for bits 8i + 7..8i (the high four bits are ignored).
        sel: u8,
    },
}

impl Command {
    /// The command's bytes, host to bridge.
    pub fn encode(&self) -> Vec<u8> {
        match *self {
            Command::Read { addr } => vec![READ, addr],
            Command::Write { addr, data, sel } => {
                let mut v = vec![WRITE, addr, sel];
                v.extend(data.to_le_bytes());
                v
            }
        }
    }

    /// Bytes of its response: 4 for a read, 1 for a write.
    pub fn response_len(&self) -> usize {
        match self {
            Command::Read { .. } => 4,
            Command::Write { .. } => 1,
        }
    }
}

/// [`Command::encode`].
pub fn encode(cmd: &Command) -> Vec<u8> {
    cmd.encode()
}

/// The bridge's answer to one command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Response {
    /// The word a read returned.
    Data(u32),
    /// A write was acknowledged.
    WriteAck,
}

impl Response {
    /// The response's bytes, bridge to host.
    pub fn encode(&self) -> Vec<u8> {
        match *self {
            Response::Data(d) => d.to_le_bytes().to_vec(),
            Response::WriteAck => vec![WRITE_ACK],
        }
    }
}

/// A response that does not answer its command.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ResponseError {
    /// Fewer or more bytes than the command's response has.
    Length {
        /// Bytes expected.
        expected: usize,
        /// Bytes received.
        got: usize,
    },
    /// A write answered by another byte than [`WRITE_ACK`].
    NotAck(u8),
}

impl fmt::Display for ResponseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ResponseError::Length { expected, got } => {
                write!(f, "response of {got} bytes, expected {expected}")
            }
            ResponseError::NotAck(b) => write!(f, "write answered {b:#04x}, not 0x4b"),
        }
    }
}

impl std::error::Error for ResponseError {}

/// The response to `cmd` in `bytes` (exactly its bytes).
pub fn parse_response(cmd: &Command, bytes: &[u8]) -> Result<Response, ResponseError> {
    if bytes.len() != cmd.response_len() {
        return Err(ResponseError::Length {
            expected: cmd.response_len(),
            got: bytes.len(),
        });
    }
    match cmd {
        Command::Read { .. } => Ok(Response::Data(u32::from_le_bytes([
            bytes[0], bytes[1], bytes[2], bytes[3],
        ]))),
        Command::Write { .. } if bytes[0] == WRITE_ACK => Ok(Response::WriteAck),
        Command::Write { .. } => Err(ResponseError::NotAck(bytes[0])),
    }
}

/// The bridge's command decoder at byte level: received bytes (and framing errors) in,
/// complete commands out. It models the bridge between commands; the bytes the bridge
/// ignores while it executes a command are the caller's to leave out (stop-and-wait).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Parser {
    /// The command byte and the arguments so far; empty while idle.
    frame: Vec<u8>,
}

impl Parser {
    /// An idle decoder.
    pub fn new() -> Parser {
        Parser::default()
    }

    /// Take one received event; the command it completes, if any.
    pub fn push(&mut self, event: RxEvent) -> Option<Command> {
        let byte = match event {
            RxEvent::FrameError => {
                self.frame.clear();
                return None;
            }
            RxEvent::Byte(b) => b,
        };
        if self.frame.is_empty() {
            if byte == READ || byte == WRITE {
                self.frame.push(byte);
            }
            return None;
        }
        self.frame.push(byte);
        let f = &self.frame;
        let cmd = match f[0] {
            READ if f.len() == 1 + READ_ARGS => Command::Read { addr: f[1] },
            WRITE if f.len() == 1 + WRITE_ARGS => Command::Write {
                addr: f[1],
                sel: f[2],
                data: u32::from_le_bytes([f[3], f[4], f[5], f[6]]),
            },
            _ => return None,
        };
        self.frame.clear();
        Some(cmd)
    }

    /// True while no command is under way.
    pub fn idle(&self) -> bool {
        self.frame.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The known answer of docs/uart-bridge.md: write 0x12345678 to 0x10, all lanes, then
    /// read 0x10.
    #[test]
    fn known_frames() {
        let w = Command::Write {
            addr: 0x10,
            data: 0x1234_5678,
            sel: 0xF,
        };
        assert_eq!(w.encode(), [0x57, 0x10, 0x0F, 0x78, 0x56, 0x34, 0x12]);
        assert_eq!(encode(&Command::Read { addr: 0x10 }), [0x52, 0x10]);
        assert_eq!(
            Response::Data(0x1234_5678).encode(),
            [0x78, 0x56, 0x34, 0x12]
        );
        assert_eq!(Response::WriteAck.encode(), [0x4B]);
        assert_eq!(
            parse_response(&Command::Read { addr: 0 }, &[0x78, 0x56, 0x34, 0x12]),
            Ok(Response::Data(0x1234_5678))
        );
        assert_eq!(parse_response(&w, &[0x4B]), Ok(Response::WriteAck));
        assert_eq!(
            parse_response(&w, &[0x4C]),
            Err(ResponseError::NotAck(0x4C))
        );
        assert_eq!(
            parse_response(&w, &[]),
            Err(ResponseError::Length {
                expected: 1,
                got: 0
            })
        );
    }

    #[test]
    fn parser_skips_garbage_and_drops_a_broken_command() {
        let mut p = Parser::new();
        let mut out = Vec::new();
        let mut feed = |p: &mut Parser, events: &[RxEvent]| {
            for &e in events {
                out.extend(p.push(e));
            }
        };
        let b = RxEvent::Byte;
        // Garbage, a read, a write cut by a framing error, garbage, a write.
        feed(
            &mut p,
            &[
                b(0x00),
                b(0x4B),
                b(0x52),
                b(0x57),
                b(0x57),
                b(0x01),
                RxEvent::FrameError,
            ],
        );
        assert!(p.idle());
        feed(
            &mut p,
            &[
                b(0x10),
                RxEvent::FrameError,
                b(0x57),
                b(4),
                b(3),
                b(1),
                b(2),
                b(3),
                b(4),
            ],
        );
        assert_eq!(
            out,
            [
                Command::Read { addr: 0x57 },
                Command::Write {
                    addr: 4,
                    sel: 3,
                    data: 0x0403_0201
                }
            ]
        );
    }
}
