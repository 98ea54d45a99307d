// SPDX-License-Identifier: MIT OR Apache-2.0
//! The speed calculator's companion: carries what a speed request was made from (the
//! position at the request, Nep1 and Ndt1) to the edge at which the calculator publishes the
//! speeds of that request. Bit-true model: the `tag` of [`golden::top::core::CoreModel`], a
//! [`golden::arith::latest_request::LatestRequest`] with the calculator's latency.
//!
//! Why a copy of the timing and not a field of the calculator: the calculator's request
//! register keeps the latest start and drops one that has not begun
//! ([`golden::arith::latest_request`]). A second machine with the same rule, the same latency and
//! the same `start` and `reset` begins and publishes at exactly the same edges, so the tag
//! it publishes is the request the calculator computed, whatever the rate of requests.
//!
//! Per rising edge (in this order, as `LatestRequest::edge`):
//! 1. running: `remaining` − 1; at 0 the active tag is published (`valid` for one cycle);
//!    idle with a pending request: it begins (`remaining` = latency − 1);
//! 2. `start` latches the inputs as the pending request (a newer one replaces it);
//! 3. `reset` abandons both and publishes nothing: `valid` stays low and `tag_*` keep the
//!    last published request, also on the edge that would have published.
//!
//! Ports: `clock`, `reset`, `start`, `position[31:0]`, `nep[N-1:0]`, `ndt[N-1:0]` in;
//! registered `tag_position`, `tag_nep`, `tag_ndt` (held) and `valid` out.

use golden::params::POSITION_BITS;
use rust_hdl::prelude::*;

const C: usize = POSITION_BITS as usize;
/// Width of the countdown: latencies up to 511 (the calculator's longest, at N = 32 and
/// F = 24, is 6·57 + 9 = 351).
const REMAINING_BITS: usize = 9;

/// The request tag of a speed calculator of `latency` edges with N-bit Nep1/Ndt1.
#[derive(LogicBlock)]
pub struct SpeedTag<const N: usize> {
    /// Clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset (the calculator's).
    pub reset: Signal<In, Bit>,
    /// The calculator's start.
    pub start: Signal<In, Bit>,
    /// Position at the request.
    pub position: Signal<In, Bits<C>>,
    /// Nep1 of the request.
    pub nep: Signal<In, Bits<N>>,
    /// Ndt1 of the request.
    pub ndt: Signal<In, Bits<N>>,
    /// Position of the request just published.
    pub tag_position: Signal<Out, Bits<C>>,
    /// Nep1 of the request just published.
    pub tag_nep: Signal<Out, Bits<N>>,
    /// Ndt1 of the request just published.
    pub tag_ndt: Signal<Out, Bits<N>>,
    /// One cycle: the tag of a finished request was just written.
    pub valid: Signal<Out, Bit>,
    req_position: DFF<Bits<C>>,
    req_nep: DFF<Bits<N>>,
    req_ndt: DFF<Bits<N>>,
    pending: DFF<Bit>,
    act_position: DFF<Bits<C>>,
    act_nep: DFF<Bits<N>>,
    act_ndt: DFF<Bits<N>>,
    running: DFF<Bit>,
    remaining: DFF<Bits<REMAINING_BITS>>,
    out_position: DFF<Bits<C>>,
    out_nep: DFF<Bits<N>>,
    out_ndt: DFF<Bits<N>>,
    out_valid: DFF<Bit>,
    first: Constant<Bits<REMAINING_BITS>>,
    one: Constant<Bits<REMAINING_BITS>>,
}

impl<const N: usize> SpeedTag<N> {
    /// A tag for a calculator publishing `latency` edges after a start (2..=511).
    pub fn new(latency: u32) -> Self {
        assert!(
            (2..=511).contains(&latency),
            "latency {latency} outside 2..=511"
        );
        Self {
            clock: Default::default(),
            reset: Default::default(),
            start: Default::default(),
            position: Default::default(),
            nep: Default::default(),
            ndt: Default::default(),
            tag_position: Default::default(),
            tag_nep: Default::default(),
            tag_ndt: Default::default(),
            valid: Default::default(),
            req_position: Default::default(),
            req_nep: Default::default(),
            req_ndt: Default::default(),
            pending: Default::default(),
            act_position: Default::default(),
            act_nep: Default::default(),
            act_ndt: Default::default(),
            running: Default::default(),
            remaining: Default::default(),
            out_position: Default::default(),
            out_nep: Default::default(),
            out_ndt: Default::default(),
            out_valid: Default::default(),
            first: Constant::new(u64::from(latency - 1).into()),
            one: Constant::new(1.into()),
        }
    }
}

impl<const N: usize> Default for SpeedTag<N> {
    fn default() -> Self {
        Self::new(2)
    }
}

impl<const N: usize> Logic for SpeedTag<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            req_position,
            req_nep,
            req_ndt,
            pending,
            act_position,
            act_nep,
            act_ndt,
            running,
            remaining,
            out_position,
            out_nep,
            out_ndt,
            out_valid
        );
        self.out_valid.d.next = false;
        if self.running.q.val() {
            self.remaining.d.next = self.remaining.q.val() - self.one.val();
            if self.remaining.q.val() == self.one.val() {
                self.running.d.next = false;
                self.out_position.d.next = self.act_position.q.val();
                self.out_nep.d.next = self.act_nep.q.val();
                self.out_ndt.d.next = self.act_ndt.q.val();
                self.out_valid.d.next = true;
            }
        } else if self.pending.q.val() {
            self.act_position.d.next = self.req_position.q.val();
            self.act_nep.d.next = self.req_nep.q.val();
            self.act_ndt.d.next = self.req_ndt.q.val();
            self.pending.d.next = false;
            self.running.d.next = true;
            self.remaining.d.next = self.first.val();
        }
        if self.start.val() {
            self.req_position.d.next = self.position.val();
            self.req_nep.d.next = self.nep.val();
            self.req_ndt.d.next = self.ndt.val();
            self.pending.d.next = true;
        }
        if self.reset.val() {
            self.pending.d.next = false;
            self.running.d.next = false;
            self.out_valid.d.next = false;
            // Nothing is published at a reset, not even on the edge that would have
            // published: the held tag stays the last one published (as the model's).
            self.out_position.d.next = self.out_position.q.val();
            self.out_nep.d.next = self.out_nep.q.val();
            self.out_ndt.d.next = self.out_ndt.q.val();
        }
        self.tag_position.next = self.out_position.q.val();
        self.tag_nep.next = self.out_nep.q.val();
        self.tag_ndt.next = self.out_ndt.q.val();
        self.valid.next = self.out_valid.q.val();
    }
}
