// SPDX-License-Identifier: MIT OR Apache-2.0
//! Start-up hold of the quadrature front end.
//!
//! After reset the synchronisers and the glitch filters hold cleared (low) values, not
//! samples of the encoder: a filter passes a channel that is already high only after
//! max(`cfg_filter`, 1) edges of real samples, which the decoder would take for a
//! transition. This block holds the decoder and the position counter in reset (`front_reset`)
//! while fewer than 2 + max(`cfg_filter`, 1) edges have passed since reset (2 for the
//! synchronisers, then the filter's delay), and for one edge more: the hold is a register
//! (`released`, inverted), so that the comparison with the filter length does not drive
//! the resets of the decoder and the counter in the same cycle. The first sample the decoder
//! takes is then a filtered sample of the real channels (the golden rule is in
//! `golden::top::core`).
//!
//! The rule's "count ≥ max(L, 1)" is tested as "count ≥ L and count ≠ 0", and "count ≠ 0"
//! together with "the synchronisers have passed" is a register, `counting`: the settle count
//! leaves 0 at the first edge after the synchroniser count reaches 2 and only a reset brings
//! either back, so `counting` ← ¬reset ∧ (synchroniser count = 2) is exactly their
//! conjunction one edge later. `counting` is not ANDed after the comparison either: the
//! comparison is {`counting`, count} ≥ {1, L} at 17 bits, true exactly when `counting` and
//! count ≥ L, so the hold's register takes one LUT after the comparison's carry chain, with
//! `reset` and `done` (a zero test of L in front of the comparison, and then the 16-bit zero
//! test and the synchroniser test after it, were the critical path of `encspeed_wb` on two
//! seeds; `counting` ANDed after the chain, the worst path of `encspeed_core` on HX8K seed 3).
//!
//! Registers: a 2-bit count of the synchroniser edges (saturating at 2), a 16-bit count of
//! the edges after them (saturating at 2^16 − 1, the longest filter), a `done` flag set
//! when the hold rule first ends, so that raising `cfg_filter` later does not bring the hold
//! back (it would reset the decoder and the position counter), `counting`, and `released`
//! (the same value as `done`, kept apart for its name: synthesis merges the two).

use golden::params::FILTER_BITS;
use rust_hdl::prelude::*;

const FB: usize = FILTER_BITS as usize;
/// Width of the comparison: the count (or L) with one bit above it.
const CB: usize = FB + 1;

/// Start-up hold of the front end.
#[derive(LogicBlock)]
pub struct Startup {
    /// Clock of the core.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Glitch filter length L, clock cycles (0: off).
    pub cfg_filter: Signal<In, Bits<FB>>,
    /// `reset`, or the hold (registered: fewer than 2 + max(L, 1) edges had passed at the
    /// edge before, and the hold had not ended): the reset of the decoder and the counter.
    pub front_reset: Signal<Out, Bit>,
    hold: Signal<Local, Bit>,
    /// Not holding (stored inverted so that the power-up value holds, as a reset does).
    released: DFF<Bit>,
    sync_edges: DFF<Bits<2>>,
    settle_edges: DFF<Bits<FB>>,
    done: DFF<Bit>,
    /// The synchronisers have passed and the settle count is not 0.
    counting: DFF<Bit>,
    /// The edge count has reached max(L, 1).
    reached: Signal<Local, Bit>,
    /// {`counting`, count} and {1, L}: one comparison of the two is count ≥ L and
    /// `counting`, so no logic level follows its carry chain for `counting`.
    count_wide: Signal<Local, Bits<CB>>,
    filter_wide: Signal<Local, Bits<CB>>,
    two: Constant<Bits<2>>,
    sync_one: Constant<Bits<2>>,
    zero: Constant<Bits<FB>>,
    one: Constant<Bits<FB>>,
    max: Constant<Bits<FB>>,
    sync_zero: Constant<Bits<2>>,
    /// 2^FB: the bit above the count.
    top: Constant<Bits<CB>>,
    wide_one: Constant<Bits<CB>>,
    wide_zero: Constant<Bits<CB>>,
}

impl Default for Startup {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            cfg_filter: Default::default(),
            hold: Default::default(),
            released: Default::default(),
            front_reset: Default::default(),
            sync_edges: Default::default(),
            settle_edges: Default::default(),
            done: Default::default(),
            counting: Default::default(),
            reached: Default::default(),
            count_wide: Default::default(),
            filter_wide: Default::default(),
            two: Constant::new(2.into()),
            sync_one: Constant::new(1.into()),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            max: Constant::new(((1u64 << FB) - 1).into()),
            sync_zero: Constant::new(0.into()),
            top: Constant::new((1u64 << FB).into()),
            wide_one: Constant::new(1.into()),
            wide_zero: Constant::new(0.into()),
        }
    }
}

impl Logic for Startup {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            sync_edges,
            settle_edges,
            done,
            counting,
            released
        );
        // count ≥ max(L, 1) (a filter of 0 or 1 cycles delays a level by one edge), as
        // count ≥ L beside the registered count ≠ 0 (which implies the synchronisers passed).
        // Both widened by shifting their bits in at the top, LSB first (a cast would be
        // emitted as a mask of another width), then the extra bit: `counting` above the
        // count, 1 above L.
        self.count_wide.next = self.wide_zero.val();
        self.filter_wide.next = self.wide_zero.val();
        for i in 0..FB {
            self.count_wide.next = self.count_wide.val() >> self.wide_one.val();
            if self.settle_edges.q.val().get_bit(i) {
                self.count_wide.next = self.count_wide.val() | self.top.val();
            }
            self.filter_wide.next = self.filter_wide.val() >> self.wide_one.val();
            if self.cfg_filter.val().get_bit(i) {
                self.filter_wide.next = self.filter_wide.val() | self.top.val();
            }
        }
        self.count_wide.next = self.count_wide.val() >> self.wide_one.val();
        if self.counting.q.val() {
            self.count_wide.next = self.count_wide.val() | self.top.val();
        }
        self.filter_wide.next = (self.filter_wide.val() >> self.wide_one.val()) | self.top.val();
        self.reached.next = self.count_wide.val() >= self.filter_wide.val();
        self.counting.d.next = self.sync_edges.q.val() == self.two.val();
        if self.sync_edges.q.val() != self.two.val() {
            self.sync_edges.d.next = self.sync_edges.q.val() + self.sync_one.val();
        } else if self.settle_edges.q.val() != self.max.val() {
            self.settle_edges.d.next = self.settle_edges.q.val() + self.one.val();
        }
        // The hold ends once for all: raising cfg_filter later does not bring it back.
        self.done.d.next = self.done.q.val();
        if self.reached.val() {
            self.done.d.next = true;
        }
        if self.reset.val() {
            self.done.d.next = false;
            self.counting.d.next = false;
            self.sync_edges.d.next = self.sync_zero.val();
            self.settle_edges.d.next = self.zero.val();
        }
        self.hold.next = !self.done.q.val() & !self.reached.val();
        // Registered: the filter-length comparison does not reach the resets of the decoder
        // and the counter in the same cycle. Combined with `reset` here rather than in the
        // core: logic of the core that read the hold and the value it drives `reset` with
        // would form a false loop for Verilator (UNOPTFLAT).
        self.released.d.next = !(self.reset.val() | self.hold.val());
        self.front_reset.next = self.reset.val() | !self.released.q.val();
    }
}
