// SPDX-License-Identifier: MIT OR Apache-2.0
//! Sine table of K entries indexed by position plus a phase offset. Bit-true model:
//! [`golden::ecc::sine_rom::SineRom`], whose module docs give the contents, the address
//! arithmetic and the error bound; the contents come from [`golden::ecc::sine_rom::sine_table`]
//! (one definition for both).
//!
//! Per clock edge (A = address width, D = data width): address = (m + m0) mod K by
//! compare-and-subtract in A bits (wrap when m0 > K − 1 − m, then subtract K), read into the
//! registered output `data` (D-bit two's complement) by [`crate::ecc::table_rom::TableRom`], a ROM
//! of exactly K words (an address ≥ K reads 0): one cycle of latency, no reset. K (2 ≤ K ≤ 2^A) is a constructor
//! argument.
//!
//! Ports: `clock`, `m[A-1:0]`, `m0[A-1:0]`; registered output `data[D-1:0]`.

use rust_hdl::prelude::*;

/// Sine ROM with A-bit address and D-bit signed entries.
#[derive(LogicBlock)]
pub struct SineRom<const A: usize, const D: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Position, < K.
    pub m: Signal<In, Bits<A>>,
    /// Phase offset, < K.
    pub m0: Signal<In, Bits<A>>,
    /// sin(2π((m + m0) mod K)/K)·(2^(D−1) − 1), rounded, two's complement; one cycle late.
    pub data: Signal<Out, Bits<D>>,
    rom: crate::ecc::table_rom::TableRom<D, A>,
    limit: Signal<Local, Bits<A>>,
    sum: Signal<Local, Bits<A>>,
    k_minus_one: Constant<Bits<A>>,
    k_mod: Constant<Bits<A>>,
}

impl<const A: usize, const D: usize> SineRom<A, D> {
    /// A table of K = `lines` entries (2 ≤ K ≤ 2^A; 1 ≤ A ≤ 16, 2 ≤ D ≤ 32).
    pub fn new(lines: u32) -> Self {
        let table = golden::ecc::sine_rom::sine_table(lines, A as u32, D as u32);
        // The K words; entries K..2^A of the model's table are never addressed.
        let words: Vec<u64> = table[..lines as usize].iter().map(|&v| v as u64).collect();
        let amask = (1u64 << A) - 1;
        Self {
            clock: Default::default(),
            m: Default::default(),
            m0: Default::default(),
            data: Default::default(),
            rom: crate::ecc::table_rom::TableRom::new(&words),
            limit: Default::default(),
            sum: Default::default(),
            k_minus_one: Constant::new((u64::from(lines) - 1).into()),
            k_mod: Constant::new((u64::from(lines) & amask).into()),
        }
    }
}

impl<const A: usize, const D: usize> Logic for SineRom<A, D> {
    #[hdl_gen]
    fn update(&mut self) {
        self.rom.clock.next = self.clock.val();
        self.limit.next = self.k_minus_one.val() - self.m.val();
        self.sum.next = self.m.val() + self.m0.val();
        self.rom.address.next = self.sum.val();
        if self.m0.val() > self.limit.val() {
            self.rom.address.next = self.sum.val() - self.k_mod.val();
        }
        self.data.next = self.rom.data.val();
    }
}

/// The Verilog of a [`SineRom`] of K = `lines` entries, top module named `module_name`.
pub fn sine_rom_verilog<const A: usize, const D: usize>(lines: u32, module_name: &str) -> String {
    let mut uut = SineRom::<A, D>::new(lines);
    uut.connect_all();
    crate::verilog::named_verilog(&uut, module_name)
}
