// SPDX-License-Identifier: MIT OR Apache-2.0
//! The sine table (`golden::ecc::sine_rom`): hand-worked values, the table's ½-LSB bound against
//! f64 sin, the compare-and-subtract index against `%`, and the read latency. The
//! eccentricity correction built on it is tested in `ecc_delta.rs`.

use golden::ecc::sine_rom::{full_scale, sine_index, sine_table, table_error_bound, SineRom};
use std::f64::consts::TAU;

#[test]
fn k4_table_is_0_max_0_minus_max() {
    assert_eq!(sine_table(4, 2, 16), vec![0, 32767, 0, -32767]);
    assert_eq!(sine_table(4, 3, 8), vec![0, 127, 0, -127, 0, 0, 0, 0]);
    // K = 6, D = 8: round(127·sin 60°) = round(109.985) = 110.
    assert_eq!(sine_table(6, 3, 8), vec![0, 110, 110, 0, -110, -110, 0, 0]);
    assert_eq!(full_scale(16), 32767);
    assert_eq!(table_error_bound(16), 0.5 / 32767.0);
}

#[test]
fn table_within_half_lsb_of_sin() {
    for &(lines, a) in &[
        (3u32, 2u32),
        (4, 2),
        (1000, 10),
        (1024, 10),
        (4096, 12),
        (2500, 12),
    ] {
        for &d in &[4u32, 8, 12, 16, 24, 32] {
            let q = full_scale(d) as f64;
            let t = sine_table(lines, a, d);
            assert_eq!(t.len(), 1 << a);
            let worst = (0..lines as usize)
                .map(|i| (t[i] as f64 / q - (TAU * i as f64 / f64::from(lines)).sin()).abs())
                .fold(0.0, f64::max);
            assert!(
                worst <= table_error_bound(d) * (1.0 + 1e-9),
                "K {lines} D {d}: {worst}"
            );
            // With many entries the bound is nearly reached: it is the right bound.
            if lines >= 1000 && d <= 16 {
                assert!(
                    worst > 0.9 * table_error_bound(d),
                    "K {lines} D {d}: {worst}"
                );
            }
            assert!(t[lines as usize..].iter().all(|&v| v == 0));
        }
    }
}

#[test]
fn index_is_sum_mod_k_without_division() {
    for &(lines, a) in &[
        (2u32, 1u32),
        (4, 2),
        (5, 3),
        (1000, 10),
        (1024, 10),
        (700, 12),
    ] {
        for m in 0..u64::from(lines) {
            for m0 in 0..u64::from(lines) {
                assert_eq!(sine_index(lines, a, m, m0), (m + m0) % u64::from(lines));
            }
        }
    }
    // Out of contract (m ≥ K): still a defined A-bit address.
    assert_eq!(
        sine_index(1000, 10, 1023, 1023),
        (1023 + 1023 - 1000) & 1023
    );
}

#[test]
fn rom_has_one_cycle_latency() {
    let mut rom = SineRom::new(4, 2, 16);
    assert_eq!(rom.data(), 0);
    assert_eq!(rom.step(1, 0), 32767);
    assert_eq!(rom.step(1, 2), -32767);
    assert_eq!(rom.step(3, 3), 0);
    assert_eq!(rom.step(2, 3), 32767);
}
