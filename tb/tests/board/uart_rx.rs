// SPDX-License-Identifier: MIT OR Apache-2.0
//! `UartRx` on golden line waveforms (`golden::board::uart::line_levels`): random bytes,
//! bad stop bits, gaps and one-cycle glitches; every byte and framing error the golden
//! decoder finds on the same line comes out, at the cycle the module docs give
//! (first low of the start bit + 2 + ⌊D/2⌋ + 9·D), and nothing else.

use crate::common;

use golden::board::uart::{decode, line_levels, LineFrame, RxEvent, UartTiming};
use hdl::{uart_rx_verilog, UartRx};
use proptest::prelude::*;
use rust_hdl::prelude::*;

fn frames() -> impl Strategy<Value = Vec<(LineFrame, Option<u32>)>> {
    prop::collection::vec(
        (
            0u32..30,
            any::<u8>(),
            prop::bool::weighted(0.85),
            prop::option::weighted(0.15, 0u32..20),
        )
            .prop_map(|(idle_cycles, byte, stop, glitch)| {
                (
                    LineFrame {
                        // After a bad stop bit the line must go high again first.
                        idle_cycles: idle_cycles + 1,
                        byte,
                        stop,
                    },
                    glitch,
                )
            }),
        1..12,
    )
}

/// The line with a one-cycle low glitch `g` cycles into the idle gap before each frame
/// that has one (where the gap is long enough for it to be a glitch, not a start).
fn levels(divisor: u32, frames: &[(LineFrame, Option<u32>)]) -> Vec<bool> {
    let mut v = Vec::new();
    for (f, glitch) in frames {
        let start = v.len();
        v.extend(line_levels(divisor, &[*f]));
        if let Some(g) = glitch {
            let g = *g as usize;
            if g + 2 < f.idle_cycles as usize {
                v[start + g] = false;
            }
        }
    }
    v.extend(std::iter::repeat_n(true, 12 * divisor as usize));
    v
}

fn run(divisor_timing: &UartTiming, line: &[bool]) -> Vec<(usize, RxEvent)> {
    let mut uut = UartRx::new(divisor_timing);
    uut.connect_all();
    let mut got = Vec::new();
    for (c, &level) in line.iter().enumerate() {
        uut.rx.next = level;
        uut.reset.next = false;
        common::edge(&mut uut, |u, l| u.clock.next = Clock { clk: l });
        assert!(!(uut.valid.val() && uut.frame_error.val()));
        if uut.valid.val() {
            got.push((c, RxEvent::Byte(uut.data.val().index() as u8)));
        }
        if uut.frame_error.val() {
            got.push((c, RxEvent::FrameError));
        }
    }
    got
}

proptest! {
    #![proptest_config(common::proptest_config(24))]

    #[test]
    fn rx_equals_golden_decoder(f in frames(), odd in any::<bool>()) {
        // 8 and 9 cycles a bit: the even and odd halves of the start bit.
        let t = if odd {
            UartTiming::new(9_000_000, 1_000_000).unwrap()
        } else {
            UartTiming::new(8_000_000, 1_000_000).unwrap()
        };
        let d = t.divisor() as usize;
        let line = levels(t.divisor(), &f);
        let want: Vec<(usize, RxEvent)> = decode(t.divisor(), &line)
            .iter()
            .map(|x| (x.start + 2 + d / 2 + 9 * d, x.event))
            .collect();
        let expected_frames = f.len();
        prop_assert_eq!(want.len(), expected_frames, "the golden decoder finds every frame");
        prop_assert_eq!(run(&t, &line), want);
    }
}

/// 0xA5 at 8 cycles a bit after 5 idle cycles: `valid` after edge 5 + 2 + 4 + 72 = 83.
#[test]
fn known_byte_and_latency() {
    let t = UartTiming::new(8_000_000, 1_000_000).unwrap();
    let mut line = vec![true; 5];
    // 0xA5 = 1010_0101: LSB first 1 0 1 0 0 1 0 1.
    for bit in [0, 1, 0, 1, 0, 0, 1, 0, 1, 1] {
        line.extend(std::iter::repeat_n(bit == 1, 8));
    }
    line.extend([true; 20]);
    assert_eq!(run(&t, &line), [(83, RxEvent::Byte(0xA5))]);
}

#[test]
fn verilog_lints_clean() {
    let t = UartTiming::new(12_000_000, 115_200).unwrap();
    common::lint_with_waivers("uart_rx", &uart_rx_verilog(&t, "uart_rx"), &[]);
}

/// A break (the line low for 100 cycles, longer than a frame of 80) at 8 cycles a bit is
/// one framing error (after edge 3 + 78), and the receiver waits for the line to go high
/// before the next start bit: 0x3C from cycle 113 is received after edge 113 + 78.
#[test]
fn break_is_one_frame_error() {
    let t = UartTiming::new(8_000_000, 1_000_000).unwrap();
    let mut line = vec![true; 3];
    line.extend([false; 100]);
    line.extend([true; 10]);
    line.extend(golden::board::uart::frame_levels(8, 0x3C, true));
    line.extend([true; 20]);
    assert_eq!(
        run(&t, &line),
        [(81, RxEvent::FrameError), (191, RxEvent::Byte(0x3C))]
    );
}
