// SPDX-License-Identifier: MIT OR Apache-2.0
//! Bit-true model of the sine table `hdl::SineRom<A, D>`, and the one definition of its
//! contents ([`sine_table`], which the HDL constructor calls).
//!
//! # Contents
//! K lines per revolution (2 ≤ K ≤ 2^A, any K, a constructor argument), D-bit signed
//! entries (2 ≤ D ≤ 32): entry i < K is round(sin(2π·i/K)·Q), Q = 2^(D−1) − 1 (rounded half
//! away from zero); entries K..2^A are 0 (so the whole 2^A address space is defined, in
//! both simulators). The table error is at most ½ LSB: |S\[i\]/Q − sin(2πi/K)| ≤ 1/(2Q)
//! ([`table_error_bound`]).
//!
//! # Semantics (per rising clock edge)
//! Inputs `m` (position) and `m0` (phase offset), A bits, unsigned, nominally both < K.
//! The address is (m + m0) mod K computed without a divider, by compare-and-subtract in A
//! bits ([`sine_index`]): wrap = m0 > (K − 1 − m) mod 2^A; address = (m + m0 − wrap·K)
//! mod 2^A. For m, m0 < K this is exactly (m + m0) mod K. Out-of-contract inputs still give
//! a defined address (the same A-bit arithmetic in both models), read as 0 beyond K.
//! The registered output `data` (D-bit two's complement) takes the entry at that address:
//! one cycle of latency. There is no reset (a ROM); `data` is 0 before the first edge in
//! this model and in rust-hdl, undefined in Verilog.

/// Largest supported address width A.
pub const MAX_ADDR_BITS: u32 = 16;

/// Full scale Q = 2^(D−1) − 1 of a D-bit table.
pub fn full_scale(data_bits: u32) -> i64 {
    assert!(
        (2..=32).contains(&data_bits),
        "D = {data_bits} outside 2..=32"
    );
    (1i64 << (data_bits - 1)) - 1
}

/// Checks 2 ≤ K ≤ 2^A, 1 ≤ A ≤ 16.
fn check(lines: u32, addr_bits: u32) {
    assert!(
        (1..=MAX_ADDR_BITS).contains(&addr_bits),
        "A = {addr_bits} outside 1..={MAX_ADDR_BITS}"
    );
    assert!(
        lines >= 2 && u64::from(lines) <= 1u64 << addr_bits,
        "K = {lines} outside 2..=2^{addr_bits}"
    );
}

/// The 2^A entries of the table (module docs), as signed integers.
pub fn sine_table(lines: u32, addr_bits: u32, data_bits: u32) -> Vec<i64> {
    check(lines, addr_bits);
    let q = full_scale(data_bits) as f64;
    (0..1u64 << addr_bits)
        .map(|i| {
            if i < u64::from(lines) {
                let x = std::f64::consts::TAU * i as f64 / f64::from(lines);
                (x.sin() * q).round() as i64
            } else {
                0
            }
        })
        .collect()
}

/// Worst-case table error, ½ LSB of full scale: 1/(2·(2^(D−1) − 1)).
pub fn table_error_bound(data_bits: u32) -> f64 {
    0.5 / full_scale(data_bits) as f64
}

/// The ROM address for position `m` and phase offset `m0` (A-bit inputs), as the hardware
/// computes it (module docs): (m + m0) mod K when both are < K.
pub fn sine_index(lines: u32, addr_bits: u32, m: u64, m0: u64) -> u64 {
    check(lines, addr_bits);
    let mask = (1u64 << addr_bits) - 1;
    let (m, m0, k) = (m & mask, m0 & mask, u64::from(lines) & mask);
    let limit = (k.wrapping_sub(1).wrapping_sub(m)) & mask;
    let sum = (m + m0) & mask;
    if m0 > limit {
        sum.wrapping_sub(k) & mask
    } else {
        sum
    }
}

/// Sine table, bit-true model of `hdl::SineRom<A, D>` (module docs).
#[derive(Clone, Debug)]
pub struct SineRom {
    lines: u32,
    addr_bits: u32,
    table: Vec<i64>,
    data: i64,
}

impl SineRom {
    /// A table of K = `lines` entries, A = `addr_bits`, D = `data_bits`; `data` = 0.
    pub fn new(lines: u32, addr_bits: u32, data_bits: u32) -> Self {
        Self {
            lines,
            addr_bits,
            table: sine_table(lines, addr_bits, data_bits),
            data: 0,
        }
    }

    /// The table (2^A entries).
    pub fn table(&self) -> &[i64] {
        &self.table
    }

    /// The registered output as it stands (signed).
    pub fn data(&self) -> i64 {
        self.data
    }

    /// One rising clock edge with `m`, `m0` applied; the output after it.
    pub fn step(&mut self, m: u64, m0: u64) -> i64 {
        self.data = self.table[sine_index(self.lines, self.addr_bits, m, m0) as usize];
        self.data
    }
}
