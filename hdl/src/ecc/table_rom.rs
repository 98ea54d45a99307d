// SPDX-License-Identifier: MIT OR Apache-2.0
//! Synchronous ROM of exactly K words behind an A-bit address: `data` ← `mem[address]` at
//! each rising edge (one cycle of latency, no reset), for [`crate::SineRom`].
//!
//! Why not rust-hdl's `SyncROM<D, A>`: it always declares 2^A words. The corrector's table
//! has a 16-bit address (any K ≤ 2^16 from one instance), so `SyncROM` emitted a 65 536-word
//! memory with 64 512 zero words for K = 1024, which no iCE40 holds and which yosys did not
//! map in half an hour. This block declares `mem[K-1:0]`, initialises its K words and
//! indexes it with the low ⌈log2 K⌉ address bits, so yosys infers K words (6 BRAMs at
//! K = 1024, D = 24).
//!
//! An address at or above K reads 0, as the model's table of 2^A entries (zeros beyond K)
//! does: the corrector's span positions are below K in its contract, and out of it the
//! result is still defined and bit-true. The range check is registered beside the memory's
//! read register and muxed after it, so that yosys still maps the read to block RAM.
//!
//! Ports: `clock`, `address[A-1:0]`; registered output `data[D-1:0]`.

use rust_hdl::prelude::*;

/// ROM of K words of D bits, A-bit address.
#[derive(LogicBlock)]
pub struct TableRom<const D: usize, const A: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Word address, < K.
    pub address: Signal<In, Bits<A>>,
    /// `mem[address]` (0 for an address ≥ K), one cycle late.
    pub data: Signal<Out, Bits<D>>,
    // Leading underscore: not a signal, skipped by `#[derive(LogicBlock)]`.
    _words: Vec<Bits<D>>,
}

/// Address bits that index K words: ⌈log2 K⌉, at least 1.
pub fn index_bits(words: usize) -> usize {
    (usize::BITS - (words.max(2) - 1).leading_zeros()) as usize
}

impl<const D: usize, const A: usize> TableRom<D, A> {
    /// A ROM holding `words` (1 ≤ K ≤ 2^A words; each the low D bits of its value).
    pub fn new(words: &[u64]) -> Self {
        assert!(
            !words.is_empty() && index_bits(words.len()) <= A,
            "TableRom: {} words do not fit a {A}-bit address",
            words.len()
        );
        let mask = if D == 64 { u64::MAX } else { (1u64 << D) - 1 };
        Self {
            clock: Default::default(),
            address: Default::default(),
            data: Default::default(),
            _words: words.iter().map(|&w| (w & mask).into()).collect(),
        }
    }
}

impl<const D: usize, const A: usize> Logic for TableRom<D, A> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let i = self.address.val().to_u64() as usize;
            self.data.next = self._words.get(i).copied().unwrap_or_default();
        }
    }

    fn connect(&mut self) {
        self.data.connect();
    }

    fn hdl(&self) -> Verilog {
        let k = self._words.len();
        let ib = index_bits(k);
        let init: String = self
            ._words
            .iter()
            .enumerate()
            .map(|(i, w)| format!("    mem[{i}] = {D}'h{:x};\n", w.to_u64()))
            .collect();
        Verilog::Custom(format!(
            "reg [{d}:0] mem [{k1}:0];\nreg [{d}:0] word;\nreg in_range;\n\ninitial begin\n{init}end\n\n\
             always @(posedge clock) begin\n    word <= mem[address[{i1}:0]];\n    \
             in_range <= {{1'b0, address}} < {a1}'d{k};\nend\n\n\
             always @(*) data = in_range ? word : {D}'d0;",
            d = D - 1,
            k1 = k - 1,
            i1 = ib - 1,
            a1 = A + 1,
        ))
    }

    fn timing(&self) -> Vec<rust_hdl::core::timing::TimingInfo> {
        vec![rust_hdl::core::timing::TimingInfo {
            name: "table_rom".to_string(),
            clock: "clock".to_string(),
            inputs: vec!["address".to_string()],
            outputs: vec!["data".to_string()],
        }]
    }
}
