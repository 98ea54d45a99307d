// SPDX-License-Identifier: MIT OR Apache-2.0
//! `UartTx` against the golden line model: random bytes started at random times (and
//! `start` pulses while busy, which must be ignored); the line decoded by
//! `golden::board::uart::decode` gives the bytes taken, each frame is exactly
//! `frame_levels` (10·D cycles, LSB first, stop 1), starting right after the edge that
//! took `start`, and the line is high everywhere else.

use crate::common;

use golden::board::uart::{decode, frame_levels, RxEvent, UartTiming};
use hdl::{uart_tx_verilog, UartTx};
use proptest::prelude::*;
use rust_hdl::prelude::*;

proptest! {
    #![proptest_config(common::proptest_config(24))]

    #[test]
    fn tx_frames_equal_golden(
        sends in prop::collection::vec((any::<u8>(), 0u32..40), 1..10),
        odd in any::<bool>(),
    ) {
        let t = if odd {
            UartTiming::new(9_000_000, 1_000_000).unwrap()
        } else {
            UartTiming::new(8_000_000, 1_000_000).unwrap()
        };
        let d = t.divisor();
        let mut uut = UartTx::new(&t);
        uut.connect_all();
        let mut line = Vec::new();
        // (cycle whose outputs first show the start bit, byte) of each byte taken.
        let mut taken = Vec::new();
        let mut queue = sends.clone();
        queue.reverse();
        let mut wait = 0;
        let mut c = 0usize;
        while !queue.is_empty() || uut.busy.val() || c < 3 {
            let busy = uut.busy.val();
            let mut start = false;
            let mut data = 0u8;
            if let Some(&(byte, gap)) = queue.last() {
                if wait >= gap {
                    start = true;
                    data = byte;
                } else if !busy {
                    wait += 1;
                }
            }
            // A start while busy is ignored: give one now and then.
            let spurious = busy && c.is_multiple_of(7);
            uut.start.next = start || spurious;
            uut.data.next = u64::from(data).into();
            uut.reset.next = c < 2;
            common::edge(&mut uut, |u, l| u.clock.next = Clock { clk: l });
            if start && !busy && c >= 2 {
                taken.push((c, data));
                queue.pop();
                wait = 0;
            }
            line.push(uut.tx.val());
            c += 1;
            prop_assert!(c < 200_000);
        }
        line.extend(std::iter::repeat_n(true, 2 * d as usize));
        let bytes: Vec<u8> = taken.iter().map(|x| x.1).collect();
        let sent: Vec<u8> = sends.iter().map(|x| x.0).collect();
        prop_assert_eq!(&bytes, &sent);
        let dec = decode(d, &line);
        let got: Vec<(usize, RxEvent)> = dec.iter().map(|x| (x.start, x.event)).collect();
        let want: Vec<(usize, RxEvent)> =
            taken.iter().map(|&(c, b)| (c, RxEvent::Byte(b))).collect();
        prop_assert_eq!(got, want);
        // Exactly the golden frame, and high outside the frames.
        let mut covered = vec![false; line.len()];
        for &(c, b) in &taken {
            let f = frame_levels(d, b, true);
            prop_assert_eq!(&line[c..c + f.len()], &f[..]);
            covered[c..c + f.len()].iter_mut().for_each(|x| *x = true);
        }
        for (k, (&level, &cov)) in line.iter().zip(&covered).enumerate() {
            prop_assert!(cov || level, "line low outside a frame at cycle {}", k);
        }
    }
}

#[test]
fn verilog_lints_clean() {
    let t = UartTiming::new(12_000_000, 115_200).unwrap();
    common::lint_with_waivers("uart_tx", &uart_tx_verilog(&t, "uart_tx"), &[]);
}
