// SPDX-License-Identifier: MIT OR Apache-2.0
//! UART 8N1 line timing: the baud divisor ([`UartTiming`]), the line level per clock cycle of
//! a byte sequence ([`line_levels`], for benches that drive a receiver) and the bytes of a
//! line waveform ([`decode`], for benches that check a transmitter).
//!
//! A frame is a start bit (0), the 8 data bits least significant first, and a stop bit (1),
//! each held for `divisor` clock cycles; the line idles at 1. A receiver finds the falling
//! edge of the start bit and samples every bit at its middle: `divisor / 2` cycles after
//! the edge for the start bit (which must still be 0, or the edge was a glitch), then every
//! `divisor` cycles. A stop bit sampled 0 is a framing error, and the receiver then waits
//! for the line to go back to 1 before it looks for the next start bit.
//!
//! Baud limits ([`UartTiming::new`]): the divisor is the rounded ratio clock / baud, at least
//! [`MIN_DIVISOR`] and at most [`MAX_DIVISOR`], and the baud it gives must be within
//! [`MAX_ERROR_PERCENT`] % of the asked one. Why 2 %: the last sample (the stop bit) is 9.5
//! bits after the edge, so a rate mismatch e moves it by 9.5·e bits; with the host's own
//! error (another 2 % at most) and the receiver's uncertainty of the edge (one clock of
//! the synchroniser, ≤ 1/8 bit at the minimum divisor) the sample stays within
//! 9.5·0.04 + 0.125 = 0.505 ≈ half a bit of the middle.

use std::fmt;

/// Smallest divisor: at 8 cycles a bit, the synchroniser's one cycle of uncertainty on the
/// start edge is 1/8 bit of the sampling margin (the rest is left for the baud errors).
pub const MIN_DIVISOR: u32 = 8;
/// Largest divisor: the hardware's bit counters are 16 bits wide.
pub const MAX_DIVISOR: u32 = 65_535;
/// Largest accepted difference between the asked baud and clock / divisor, in percent.
pub const MAX_ERROR_PERCENT: u64 = 2;
/// Bits of one 8N1 frame: start, 8 data, stop.
pub const FRAME_BITS: u32 = 10;

/// A validated UART bit time: clock cycles per bit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UartTiming {
    clock_hz: u64,
    baud: u64,
    divisor: u32,
}

/// Why a clock and a baud cannot be used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UartTimingError {
    /// The clock or the baud is 0.
    Zero,
    /// The rounded divisor is below [`MIN_DIVISOR`]: the baud is too fast for the clock.
    DivisorTooSmall {
        /// The rounded divisor.
        divisor: u64,
    },
    /// The rounded divisor is above [`MAX_DIVISOR`]: the baud is too slow for the clock.
    DivisorTooLarge {
        /// The rounded divisor.
        divisor: u64,
    },
    /// clock / divisor is more than [`MAX_ERROR_PERCENT`] % from the baud.
    BaudError {
        /// The rounded divisor.
        divisor: u64,
        /// |clock / divisor − baud| / baud, in parts per million (rounded down).
        error_ppm: u64,
    },
}

impl fmt::Display for UartTimingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UartTimingError::Zero => write!(f, "the clock and the baud must be non-zero"),
            UartTimingError::DivisorTooSmall { divisor } => write!(
                f,
                "baud too fast for the clock: {divisor} cycles per bit, at least {MIN_DIVISOR} needed"
            ),
            UartTimingError::DivisorTooLarge { divisor } => write!(
                f,
                "baud too slow for the clock: {divisor} cycles per bit, at most {MAX_DIVISOR}"
            ),
            UartTimingError::BaudError { divisor, error_ppm } => write!(
                f,
                "{divisor} cycles per bit is {}.{:04} % off the baud, more than {MAX_ERROR_PERCENT} %",
                error_ppm / 10_000,
                error_ppm % 10_000
            ),
        }
    }
}

impl std::error::Error for UartTimingError {}

impl UartTiming {
    /// The divisor round(clock_hz / baud), if it lies in [`MIN_DIVISOR`]..=[`MAX_DIVISOR`]
    /// and clock_hz / divisor is within [`MAX_ERROR_PERCENT`] % of `baud`.
    pub fn new(clock_hz: u64, baud: u64) -> Result<UartTiming, UartTimingError> {
        if clock_hz == 0 || baud == 0 {
            return Err(UartTimingError::Zero);
        }
        let (c, b) = (u128::from(clock_hz), u128::from(baud));
        let divisor = (c + b / 2) / b;
        let d64 = u64::try_from(divisor).unwrap_or(u64::MAX);
        if divisor < u128::from(MIN_DIVISOR) {
            return Err(UartTimingError::DivisorTooSmall { divisor: d64 });
        }
        if divisor > u128::from(MAX_DIVISOR) {
            return Err(UartTimingError::DivisorTooLarge { divisor: d64 });
        }
        // |c/d − b| / b = |c − d·b| / (d·b); compared as integers.
        let diff = c.abs_diff(divisor * b);
        if diff * 100 > u128::from(MAX_ERROR_PERCENT) * divisor * b {
            return Err(UartTimingError::BaudError {
                divisor: d64,
                error_ppm: u64::try_from(diff * 1_000_000 / (divisor * b)).unwrap_or(u64::MAX),
            });
        }
        Ok(UartTiming {
            clock_hz,
            baud,
            divisor: u32::try_from(divisor).expect("divisor ≤ MAX_DIVISOR"),
        })
    }

    /// Clock cycles per bit.
    pub fn divisor(&self) -> u32 {
        self.divisor
    }

    /// The clock frequency, Hz.
    pub fn clock_hz(&self) -> u64 {
        self.clock_hz
    }

    /// The asked baud.
    pub fn baud(&self) -> u64 {
        self.baud
    }

    /// The baud the divisor gives, clock / divisor.
    pub fn actual_baud(&self) -> f64 {
        self.clock_hz as f64 / f64::from(self.divisor)
    }

    /// (actual − asked) / asked, in percent.
    pub fn error_percent(&self) -> f64 {
        (self.actual_baud() / self.baud as f64 - 1.0) * 100.0
    }

    /// Clock cycles of one frame: 10 bits.
    pub fn frame_cycles(&self) -> u64 {
        u64::from(FRAME_BITS * self.divisor)
    }
}

/// The line level of one frame, one entry per clock cycle: start bit 0, `byte` least
/// significant bit first, then the stop bit `stop` (1 for a good frame, 0 to make a
/// framing error), each for `divisor` cycles.
pub fn frame_levels(divisor: u32, byte: u8, stop: bool) -> Vec<bool> {
    let mut bits = vec![false];
    bits.extend((0..8).map(|i| (byte >> i) & 1 == 1));
    bits.push(stop);
    bits.iter()
        .flat_map(|&b| std::iter::repeat_n(b, divisor as usize))
        .collect()
}

/// One frame of a line waveform: a byte with its stop bit, after some idle cycles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineFrame {
    /// Idle (1) cycles before the start bit.
    pub idle_cycles: u32,
    /// The data byte.
    pub byte: u8,
    /// The stop bit (false: a framing error).
    pub stop: bool,
}

/// The line level per clock cycle of `frames`, one after the other (each after its idle
/// cycles).
pub fn line_levels(divisor: u32, frames: &[LineFrame]) -> Vec<bool> {
    let mut levels = Vec::new();
    for f in frames {
        levels.extend(std::iter::repeat_n(true, f.idle_cycles as usize));
        levels.extend(frame_levels(divisor, f.byte, f.stop));
    }
    levels
}

/// What a receiver takes from a line: a byte, or a frame whose stop bit was 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RxEvent {
    /// A frame with a good stop bit.
    Byte(u8),
    /// A frame whose stop bit was sampled 0 (its data is discarded).
    FrameError,
}

/// One decoded frame: what was received, and the cycle of its start bit's falling edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Decoded {
    /// Index in the level sequence of the first 0 of the start bit.
    pub start: usize,
    /// The byte, or the framing error.
    pub event: RxEvent,
}

/// The frames of the line `levels` (one per clock cycle) at `divisor` cycles per bit, as
/// the receiver of the module docs samples them: a falling edge (the line before the first
/// level counts as 1), the start bit still 0 at `divisor / 2` cycles after it, every
/// bit at the middle; after a framing error, the line must return to 1 first. A frame cut
/// off by the end of `levels` is not reported.
pub fn decode(divisor: u32, levels: &[bool]) -> Vec<Decoded> {
    let d = divisor as usize;
    let mut out = Vec::new();
    let mut prev = true;
    let mut i = 0;
    while i < levels.len() {
        let level = levels[i];
        // Wait for a falling edge.
        if !prev || level {
            prev = level;
            i += 1;
            continue;
        }
        let sample = |k: usize| levels.get(i + d / 2 + k * d).copied();
        match sample(0) {
            None => break,
            Some(true) => {
                // A glitch, not a start bit.
                prev = level;
                i += 1;
                continue;
            }
            Some(false) => {}
        }
        let Some(stop) = sample(9) else { break };
        let mut byte = 0u8;
        for k in 0..8 {
            if sample(1 + k) == Some(true) {
                byte |= 1 << k;
            }
        }
        out.push(Decoded {
            start: i,
            event: if stop {
                RxEvent::Byte(byte)
            } else {
                RxEvent::FrameError
            },
        });
        // Look for the next edge from the stop bit's sample on.
        i += d / 2 + 9 * d;
        prev = levels[i];
        i += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 12 MHz / 115 200 baud = 104.17 → 104 cycles a bit; 12e6 / 104 = 115 384.6 baud,
    /// +0.16 %.
    #[test]
    fn twelve_mhz_115200_is_104_cycles() {
        let t = UartTiming::new(12_000_000, 115_200).unwrap();
        assert_eq!(t.divisor(), 104);
        assert!((t.error_percent() - 0.160_256).abs() < 1e-5);
        assert_eq!(t.frame_cycles(), 1040);
        // 48 MHz / 115 200 = 416.67 → 417: 115 107.9 baud, −0.08 %.
        let t = UartTiming::new(48_000_000, 115_200).unwrap();
        assert_eq!(t.divisor(), 417);
        assert!((t.error_percent() + 0.079_936).abs() < 1e-5);
    }

    /// The limits: 12 MHz / 1.5 MBd = 8 (the minimum), 12 MHz / 2 MBd = 6 (too fast),
    /// 12 MHz / 100 Bd = 120 000 (too slow), 12 MHz / 1.3 MBd = 9.23 → 9, 12e6 / 9 =
    /// 1 333 333 baud, +2.564 % (refused), 12 MHz / 1 MBd = 12 exactly.
    #[test]
    fn limits_are_refused_with_their_reason() {
        assert_eq!(UartTiming::new(12_000_000, 1_500_000).unwrap().divisor(), 8);
        assert_eq!(
            UartTiming::new(12_000_000, 2_000_000),
            Err(UartTimingError::DivisorTooSmall { divisor: 6 })
        );
        assert_eq!(
            UartTiming::new(12_000_000, 100),
            Err(UartTimingError::DivisorTooLarge { divisor: 120_000 })
        );
        assert_eq!(
            UartTiming::new(12_000_000, 1_300_000),
            Err(UartTimingError::BaudError {
                divisor: 9,
                error_ppm: 25_641
            })
        );
        assert_eq!(UartTiming::new(0, 9600), Err(UartTimingError::Zero));
        assert_eq!(
            UartTiming::new(12_000_000, 1_000_000).unwrap().divisor(),
            12
        );
        let msg = UartTiming::new(12_000_000, 1_300_000)
            .unwrap_err()
            .to_string();
        assert!(msg.contains("2.5641 %"), "{msg}");
    }

    /// 0x4B = 0b0100_1011 at 2 cycles a bit (below the hardware minimum, fine for the
    /// waveform): start 0, bits 1 1 0 1 0 0 1 0 (LSB first), stop 1.
    #[test]
    fn frame_is_start_lsb_first_stop() {
        let l = frame_levels(2, 0x4B, true);
        let bits: Vec<u8> = l.chunks(2).map(|c| u8::from(c[0])).collect();
        assert_eq!(bits, [0, 1, 1, 0, 1, 0, 0, 1, 0, 1]);
        assert!(l.chunks(2).all(|c| c[0] == c[1]));
    }

    #[test]
    fn decode_reads_back_bytes_and_framing_errors() {
        let frames = [
            LineFrame {
                idle_cycles: 3,
                byte: 0x52,
                stop: true,
            },
            LineFrame {
                idle_cycles: 0,
                byte: 0xFF,
                stop: false,
            },
            LineFrame {
                idle_cycles: 9,
                byte: 0x00,
                stop: true,
            },
            LineFrame {
                idle_cycles: 1,
                byte: 0x80,
                stop: true,
            },
        ];
        let levels = line_levels(9, &frames);
        let got: Vec<RxEvent> = decode(9, &levels).iter().map(|d| d.event).collect();
        assert_eq!(
            got,
            [
                RxEvent::Byte(0x52),
                RxEvent::FrameError,
                RxEvent::Byte(0x00),
                RxEvent::Byte(0x80)
            ]
        );
        assert_eq!(decode(9, &levels)[0].start, 3);
        // A one-cycle glitch is no start bit.
        let mut glitch = vec![true; 40];
        glitch[5] = false;
        assert!(decode(9, &glitch).is_empty());
    }
}
