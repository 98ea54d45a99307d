// SPDX-License-Identifier: MIT OR Apache-2.0
//! The ts/dt time base of Rairán's Table 1: the ts counter ("clock" in the paper) and the
//! dt-interval counter Cdt.
//!
//! The ts counter raises `tick` for one cycle when dt clock cycles have passed since the
//! last tick or restart (Table 1 lines 4, 8, 12, 14). Cdt counts ticks since the last pulse
//! (lines 11, 13). A pulse that comes after at least one tick (Cdt ≠ 0) restarts the
//! interval: `restart` is high, the ts counter returns to zero and the tick of that cycle
//! is cancelled (lines 5-7). A pulse on a tick clears Cdt and the tick then counts it to 1.
//!
//! dt comes from the runtime input `dt` (values below 2 used as 2); a change of `dt` takes
//! effect one clock later. The comparison is `count >= dt − 1`, i.e. `count + 1 >= dt`, so
//! that lowering dt at run time ends the interval at once instead of letting the counter
//! run to its limit; with a constant dt it equals the paper's `clock == dt`. Cdt saturates
//! at 2^N − 1 instead of wrapping.
//!
//! The comparison is made one edge ahead and registered (`due`), so that `tick` does not
//! come out of a carry chain: it drives the enables of Table 1's registers. For the count
//! after an edge, count' ≥ max(dt, 2) − 1 is false when the count returns to zero, and
//! otherwise (count' = count + 1) it is count + 2 ≥ max(dt, 2), i.e. count + 2 ≥ dt (the
//! left side is at least 2). The block therefore keeps
//! count + 2 (`ts_plus_two`, mod 2^N) instead of the count: it wraps only at count =
//! 2^N − 2, the largest dt − 1, where `due` is already set and the count returns to zero.
//!
//! `tick` and `restart` are combinational (from `lep` and the registers); `cdt` and
//! `stalled` come from the Cdt register.

use rust_hdl::prelude::*;

/// The mask of the bits at or above `MIN_DT_CYCLES` in N bits: a dt is below the minimum
/// exactly when it has none of them (the minimum is a power of two).
pub(crate) fn above_min_dt<const N: usize>() -> Bits<N> {
    const { assert!(golden::params::MIN_DT_CYCLES.is_power_of_two()) };
    let below = golden::params::MIN_DT_CYCLES - 1;
    (((1u64 << N) - 1) & !below).into()
}

/// ts counter with a runtime dt, and the Cdt counter of dt intervals.
#[derive(LogicBlock)]
pub struct Timebase<const N: usize> {
    /// Clock of the core (one ts step per cycle).
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset.
    pub reset: Signal<In, Bit>,
    /// Encoder pulse.
    pub lep: Signal<In, Bit>,
    /// dt in clock cycles.
    pub dt: Signal<In, Bits<N>>,
    /// Zero-speed timeout in dt intervals (compared with Cdt).
    pub timeout: Signal<In, Bits<N>>,
    /// High in the cycle in which `clock == dt`.
    pub tick: Signal<Out, Bit>,
    /// High in the cycle of a pulse that follows at least one tick (the dt base restarts).
    pub restart: Signal<Out, Bit>,
    /// Cdt: ticks since the last pulse.
    pub cdt: Signal<Out, Bits<N>>,
    /// Cdt has reached the zero-speed timeout.
    pub stalled: Signal<Out, Bit>,
    /// The ts count + 2, mod 2^N (the count is ts_plus_two − 2).
    pub(crate) ts_plus_two: DFF<Bits<N>>,
    cdt_count: DFF<Bits<N>>,
    /// Cdt ≠ 0, kept beside `cdt_count` so that no reduction of its N bits lies in front of
    /// `restart` and `tick`, which drive the enables of Table 1's registers.
    cdt_nonzero: DFF<Bit>,
    /// count ≥ max(dt, 2) − 1 for the count and the dt of this cycle.
    due: DFF<Bit>,
    restart_now: Signal<Local, Bit>,
    tick_now: Signal<Local, Bit>,
    /// Cdt + 1, from the register (the pulse's clear is applied after it, so that `lep`
    /// is not in front of the carry chain).
    cdt_plus_one: Signal<Local, Bits<N>>,
    zero: Constant<Bits<N>>,
    one: Constant<Bits<N>>,
    two: Constant<Bits<N>>,
    saturated: Constant<Bits<N>>,
}

impl<const N: usize> Default for Timebase<N> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            reset: Default::default(),
            lep: Default::default(),
            dt: Default::default(),
            timeout: Default::default(),
            tick: Default::default(),
            restart: Default::default(),
            cdt: Default::default(),
            stalled: Default::default(),
            ts_plus_two: Default::default(),
            cdt_count: Default::default(),
            cdt_nonzero: Default::default(),
            due: Default::default(),
            restart_now: Default::default(),
            tick_now: Default::default(),
            cdt_plus_one: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            two: Constant::new(2.into()),
            saturated: Constant::new(((1u64 << N) - 1).into()),
        }
    }
}

impl<const N: usize> Logic for Timebase<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, ts_plus_two, cdt_count, cdt_nonzero, due);
        // Line 5: a pulse after at least one tick restarts the interval.
        self.restart_now.next = self.lep.val() & self.cdt_nonzero.q.val();
        // Line 8/12: never in a restart cycle (the count was just set to zero, dt >= 2).
        self.tick_now.next = !self.restart_now.val() & self.due.q.val();
        // The next count is count + 1: due then when count + 2 ≥ max(dt, 2), i.e. when
        // count + 2 ≥ dt (count + 2 wraps to 0 only where `due` is already set).
        self.ts_plus_two.d.next = self.ts_plus_two.q.val() + self.one.val();
        self.due.d.next = self.ts_plus_two.q.val() >= self.dt.val();
        // The next count is 0, below every max(dt, 2) − 1.
        if self.restart_now.val() | self.tick_now.val() {
            self.ts_plus_two.d.next = self.two.val();
            self.due.d.next = false;
        }
        // Line 11 then 13, saturating: a pulse clears Cdt, then a tick counts it; after a
        // pulse Cdt is 0 or, with a tick, 1 (0 is never the saturated value).
        self.cdt_plus_one.next = self.cdt_count.q.val() + self.one.val();
        self.cdt_count.d.next = self.cdt_count.q.val();
        if self.tick_now.val() & (self.cdt_count.q.val() != self.saturated.val()) {
            self.cdt_count.d.next = self.cdt_plus_one.val();
        }
        self.cdt_nonzero.d.next = self.cdt_nonzero.q.val() | self.tick_now.val();
        if self.lep.val() {
            self.cdt_count.d.next = self.zero.val();
            if self.tick_now.val() {
                self.cdt_count.d.next = self.one.val();
            }
            self.cdt_nonzero.d.next = self.tick_now.val();
        }
        if self.reset.val() {
            self.ts_plus_two.d.next = self.two.val();
            self.due.d.next = false;
            self.cdt_count.d.next = self.zero.val();
            self.cdt_nonzero.d.next = false;
        }
        self.tick.next = self.tick_now.val();
        self.restart.next = self.restart_now.val();
        self.cdt.next = self.cdt_count.q.val();
        self.stalled.next = self.cdt_count.q.val() >= self.timeout.val();
    }
}
