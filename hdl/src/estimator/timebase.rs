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
//! dt comes from the runtime input `dt`, registered (as dt − 1, values below 2 used as 2) so
//! that the port is not on the critical path: a change of `dt` takes effect one clock
//! later. The comparison is `count >= dt − 1`, i.e. `count + 1 >= dt`, so that lowering dt
//! at run time ends the interval at once instead of letting the counter run to its limit;
//! with a constant dt it equals the paper's `clock == dt`. Cdt saturates at 2^N − 1
//! instead of wrapping.
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
    pub(crate) ts_count: DFF<Bits<N>>,
    cdt_count: DFF<Bits<N>>,
    dt_limit: DFF<Bits<N>>,
    restart_now: Signal<Local, Bit>,
    tick_now: Signal<Local, Bit>,
    cdt_after_pulse: Signal<Local, Bits<N>>,
    zero: Constant<Bits<N>>,
    one: Constant<Bits<N>>,
    /// The bits at or above MIN_DT_CYCLES (a power of two): dt < MIN_DT_CYCLES when none is set.
    above_min: Constant<Bits<N>>,
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
            ts_count: Default::default(),
            cdt_count: Default::default(),
            dt_limit: Default::default(),
            restart_now: Default::default(),
            tick_now: Default::default(),
            cdt_after_pulse: Default::default(),
            zero: Constant::new(0.into()),
            one: Constant::new(1.into()),
            above_min: Constant::new(above_min_dt::<N>()),
            saturated: Constant::new(((1u64 << N) - 1).into()),
        }
    }
}

impl<const N: usize> Logic for Timebase<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, ts_count, cdt_count, dt_limit);
        // Line 5: a pulse after at least one tick restarts the interval.
        self.restart_now.next = self.lep.val() & (self.cdt_count.q.val() != self.zero.val());
        // dt − 1, with dt below 2 used as 2.
        self.dt_limit.d.next = self.dt.val() - self.one.val();
        // dt < 2 as "no bit above bit 0": LUTs, not a comparator's carry chain in series
        // with the subtraction.
        if (self.dt.val() & self.above_min.val()) == self.zero.val() {
            self.dt_limit.d.next = self.one.val();
        }
        // Line 8/12: never in a restart cycle (the count was just set to zero, dt >= 2).
        self.tick_now.next =
            !self.restart_now.val() & (self.ts_count.q.val() >= self.dt_limit.q.val());
        // count + 1 cannot overflow: the count never exceeds the largest dt − 1.
        self.ts_count.d.next = self.ts_count.q.val() + self.one.val();
        if self.restart_now.val() | self.tick_now.val() {
            self.ts_count.d.next = self.zero.val();
        }
        // Line 11 then 13, saturating.
        self.cdt_after_pulse.next = self.cdt_count.q.val();
        if self.lep.val() {
            self.cdt_after_pulse.next = self.zero.val();
        }
        self.cdt_count.d.next = self.cdt_after_pulse.val();
        if self.tick_now.val() & (self.cdt_after_pulse.val() != self.saturated.val()) {
            self.cdt_count.d.next = self.cdt_after_pulse.val() + self.one.val();
        }
        if self.reset.val() {
            self.ts_count.d.next = self.zero.val();
            self.cdt_count.d.next = self.zero.val();
        }
        self.tick.next = self.tick_now.val();
        self.restart.next = self.restart_now.val();
        self.cdt.next = self.cdt_count.q.val();
        self.stalled.next = self.cdt_count.q.val() >= self.timeout.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_every_dt_and_restarts_on_a_pulse_after_a_tick() {
        let mut uut = Timebase::<8>::default();
        uut.connect_all();
        let mut ticks = vec![];
        let mut restarts = vec![];
        // dt = 5; pulses at edges 7 (Cdt = 1 after the tick at 5: restart) and 8 (Cdt = 0).
        for k in 0..20 {
            uut.reset.next = k == 0;
            uut.dt.next = 5.into();
            uut.lep.next = k == 7 || k == 8;
            uut.clock.next = Clock { clk: false };
            assert!(simulate(&mut uut, 10));
            // During the reset cycle the outputs decode power-up values; the core holds its
            // consumers in reset then.
            if uut.tick.val() && k > 0 {
                ticks.push(k);
            }
            if uut.restart.val() {
                restarts.push(k);
            }
            uut.clock.next = Clock { clk: true };
            assert!(simulate(&mut uut, 10));
        }
        // By hand: reset at edge 0 (dt register loaded too); count 1..5 → tick at edge 5;
        // restart at 7 (count 0), then ticks at 12 and 17.
        assert_eq!(ticks, vec![5, 12, 17]);
        assert_eq!(restarts, vec![7]);
    }

    #[test]
    fn synthesises() {
        let mut uut = Timebase::<8>::default();
        uut.connect_all();
        yosys_validate("encspeed_timebase", &generate_verilog(&uut)).unwrap();
    }
}
