// SPDX-License-Identifier: MIT OR Apache-2.0
//! The ports of the shipped tops, each top's list declared once: the emitted Verilog's
//! header, the manifest and docs/ports.md are written from [`core_ports`] and [`ecc_ports`]
//! (and `encspeed_wb`'s from [`crate::top::wb_top::wb_top_ports`]), the benches' harnesses
//! are generated from them, and the Rust structs of one cycle's values map onto them
//! ([`crate::top::port_fields`]). The latencies are [`Latency`].

use crate::baselines::baseline_speeds;
use crate::estimator::speed_calc;
use crate::params::{speed_bits_for, Params, ERROR_COUNT_BITS, FILTER_BITS, POSITION_BITS};
use serde::Serialize;

/// One port of a top.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Port {
    /// Verilog name.
    pub name: &'static str,
    /// "input" or "output".
    pub direction: &'static str,
    /// Width in bits.
    pub width: u32,
    /// Meaning, unit and timing.
    pub description: &'static str,
}

/// Name of every top's clock input: the harnesses drive it, no cycle's values carry it.
pub const CLOCK: &str = "clock";

impl Port {
    /// An input port.
    pub fn input(name: &'static str, width: u32, description: &'static str) -> Port {
        Port {
            name,
            direction: "input",
            width,
            description,
        }
    }

    /// An output port.
    pub fn output(name: &'static str, width: u32, description: &'static str) -> Port {
        Port {
            name,
            direction: "output",
            width,
            description,
        }
    }

    /// The port is an input.
    pub fn is_input(&self) -> bool {
        self.direction == "input"
    }
}

/// The ports one cycle's inputs carry: every input of `ports` but the [`CLOCK`], in order.
pub fn cycle_inputs(ports: &[Port]) -> Vec<Port> {
    ports
        .iter()
        .filter(|p| p.is_input() && p.name != CLOCK)
        .cloned()
        .collect()
}

/// The ports one cycle's outputs carry: every output of `ports`, in order.
pub fn cycle_outputs(ports: &[Port]) -> Vec<Port> {
    ports.iter().filter(|p| !p.is_input()).cloned().collect()
}

/// The encoder's inputs, which every top has after its clock and reset.
pub fn encoder_inputs() -> [Port; 3] {
    let i = Port::input;
    [
        i(
            "enc_a",
            1,
            "encoder channel A, asynchronous (two-flop synchronised inside)",
        ),
        i(
            "enc_b",
            1,
            "encoder channel B, asynchronous; forward = A leads B by 90 degrees",
        ),
        i("enc_z", 1, "encoder index Z, asynchronous"),
    ]
}

/// Every port of `encspeed_core` with `counter_bits`-bit counters (the only parameter its
/// widths depend on), in Verilog order of importance (clock first).
pub fn core_ports(counter_bits: u32) -> Vec<Port> {
    let n = counter_bits;
    let s = speed_bits_for(counter_bits);
    let g = ERROR_COUNT_BITS;
    let (i, o) = (Port::input, Port::output);
    let mut v = vec![
        i(
            "clock",
            1,
            "core clock; everything happens at its rising edge",
        ),
        i(
            "reset",
            1,
            "synchronous, active high, registered: the core resets at the edge after each edge that samples it high (and at the first edge after power-up)",
        ),
    ];
    v.extend(encoder_inputs());
    v.extend([
        i("cfg_dt", n, "dt in clock cycles (Rairan's time base and the PC/M/T window); 0 = the generation default dt_cycles, 1 = used as 2 and flags cfg_error; registered: dt_active shows a change one edge later, the dt windows use it from the edge after that"),
        i("cfg_timeout", n, "zero-speed timeout in dt intervals; 0 = the generation default; registered: stalled and valid, themselves registered, show a new timeout from the edge after the one that samples it"),
        i("cfg_filter", FILTER_BITS, "glitch filter length in clock cycles on A, B and Z (a level must be seen this many cycles to pass); 0 = off; registered (acts one edge later)"),
        i("cfg_mode", 2, "decoding: 0 = x1 (A edge while B low), 1 = x2 (A edges), 2 = x4 (A and B edges); 3 = x4 and cfg_error. Registered: a change resets the whole core (as reset) at the edge after the one that samples it, with the new mode in place"),
        i("cfg_z_mode", 2, "index: 0 = ignore, 1 = a Z edge resets the position, 2 = latches it into z_latch, 3 = latch then reset; registered (acts one edge later)"),
        i("clear_faults", 1, "clears fault_illegal, fault_overspeed, fault_revolution (an event in the same cycle wins)"),
        o("position", POSITION_BITS, "position in decoder steps, 0 .. lines*2^s - 1 (s = 0, 1, 2 in x1, x2, x4); wraps at a revolution, which is its definition"),
        o("z_latch", POSITION_BITS, "position latched at the last index edge (cfg_z_mode 2, 3)"),
        o("index", 1, "one cycle: an index edge was processed"),
        o("direction", 1, "direction of the last step: 1 = forward"),
        o("nep", n, "Nep1 of Rairan's Table 1, in decoder steps; 0 after reset or a reversal"),
        o("ndt", n, "Ndt1 of Rairan's Table 1, dt intervals; 1 after reset or a reversal"),
        o("update", 1, "one cycle: nep or ndt has just been written"),
        o("speed_n1", s, "Rairan n1 = Nep/Ndt, two's complement, speed_frac_bits fractional bits, units of omega_lim (one line per dt)"),
        o("speed_n2", s, "Rairan n2, eq. (6); format as speed_n1"),
        o("speed_n3", s, "Rairan n3, eq. (11): the estimate to use; format as speed_n1; negative = backward"),
        o("speed_strobe", 1, "one cycle: speed_n1, speed_n2, speed_n3 have just been written"),
        o("speed_pc", s, "fixed-time (pulse count) speed of the last cfg_dt window; format as speed_n1"),
        o("speed_et", s, "fixed-space (elapsed time) speed dt/period of the last period at the window end; 0 before a period of the current direction; format as speed_n1"),
        o("speed_mt", s, "M/T speed: steps of the window over the exact clock count spanning them, times dt; 0 for a window without steps; format as speed_n1"),
        o("baseline_strobe", 1, "one cycle: speed_pc, speed_et, speed_mt have just been written"),
        o("valid", 1, "speed_n3 is a measurement of the current direction (one since reset or the last reversal), not stalled, legal configuration; a register, one edge after those conditions"),
        o("stalled", 1, "no step for the zero-speed timeout: the speed is below one step per timeout; a register, one edge after Cdt reaches the timeout"),
        o("fault_illegal", 1, "sticky: A and B changed between two samples (an illegal transition)"),
        o("fault_overspeed", 1, "sticky: the A or B filter rejected a level shorter than cfg_filter cycles (a glitch, or edges closer than the filter can pass)"),
        o("fault_revolution", 1, "sticky: a revolution of one direction between two index edges had a count other than lines*2^s"),
        o("cfg_error", 1, "cfg_dt = 1 or cfg_mode = 3 at the last edge"),
        o("glitch_count", g, "pulses rejected by the A, B and Z filters since reset, saturating"),
        o("illegal_count", g, "illegal transitions since reset, saturating"),
        o("rev_error_count", g, "revolutions with a wrong count since reset, saturating"),
        o("speed_position", POSITION_BITS, "with speed_strobe, held: the end of the span of disc the speeds measure: for nep = 1 the position of the restart pulse that wrote ndt, for nep >= 2 that of the last pulse of the window that wrote nep (which started nep - 1 steps before it); for an eccentricity correction; 0 after reset or a reversal"),
        o("speed_nep", n, "with speed_strobe, held: the nep the speeds were computed from"),
        o("speed_ndt", n, "with speed_strobe, held: the ndt the speeds were computed from"),
        o("mt_strobe", 1, "one cycle: the M/T counter closed a window; mt_m, mt_t, mt_negative were just written and position in this cycle is that of the window's last step; speed_mt follows at baseline_strobe"),
        o("mt_m", n, "M/T: steps of the last window (0: none)"),
        o("mt_t", n, "M/T: clock cycles from the step before the window's first to its last (mt_m > 0), else cycles since the last step"),
        o("mt_negative", 1, "M/T: the last window's steps were backward"),
        o("dt_active", n, "the dt in use, clock cycles: cfg_dt after its default and minimum, registered"),
    ]);
    v
}

/// Every port of `encspeed_ecc` with `counter_bits`-bit counters: those of
/// `encspeed_core`, then the coefficients, the corrected speeds and the identification
/// (`crate::top::ecc_top`).
pub fn ecc_ports(counter_bits: u32) -> Vec<Port> {
    let s = speed_bits_for(counter_bits);
    let (i, o) = (Port::input, Port::output);
    let mut v = core_ports(counter_bits);
    v.extend([
        i("ecc_c", 32, "eccentricity coefficient c = E cos(theta0), two's complement Q15.16 in lines (E = lines * e / 2pi, e = disc centre offset / disc radius); sampled at each mt_strobe and speed_strobe for the correction of that estimate"),
        i("ecc_d", 32, "eccentricity coefficient d = E sin(theta0), Q15.16 lines"),
        o("speed_mtc", s, "M/T speed of each window corrected for the eccentricity; format as speed_mt; needs cfg_z_mode = 1 or 3 (position counted from line 0)"),
        o("mtc_strobe", 1, "one cycle: speed_mtc has just been written"),
        o("speed_n3c", s, "Rairan n3 corrected for the eccentricity; format as speed_n3; needs cfg_z_mode = 1 or 3"),
        o("n3c_strobe", 1, "one cycle: speed_n3c has just been written"),
        i("ident_arm", 1, "one-cycle pulse: gather the next revolution (index to index) for the eccentricity identification (cfg_z_mode = 1 or 3, forward at constant speed); an arm before the first index since reset or a cfg_mode change is held until that index, which aligns the position, and takes effect there, so the revolution gathered is the one from the second index to the third; ident_done clears when the arm takes effect. In a build without the identification (generate --no-identification) it does nothing and every ident_* output reads 0"),
        o("ident_done", 1, "the ident_* results are complete: rises 2 edges after the edge that raised the closing index; sticky until the next arm takes effect"),
        o("ident_overflow", 1, "more than 2^16 lines between the index pulses (contract broken, extra lines dropped)"),
        o("ident_count", 17, "forward lines gathered N (lines per revolution for a clean revolution)"),
        o("ident_t_min", 32, "shortest line period, clock cycles (Zhao's T_min)"),
        o("ident_p_min", 16, "line number of the edge that closed it (first on ties)"),
        o("ident_t_max", 32, "longest line period, clock cycles (Zhao's T_max)"),
        o("ident_p_max", 16, "line number of the edge that closed it (first on ties)"),
        o("ident_sum_t", 72, "sum of the line periods T, clock cycles (the revolution's length)"),
        o("ident_sum_sin", 72, "sum of T * round(Q sin(2 pi p / lines)), two's complement, Q = 2^23 - 1, p the line number of the edge closing T"),
        o("ident_sum_cos", 72, "sum of T * round(Q cos(2 pi p / lines)), two's complement; e and theta0 from the three sums: golden::ecc::ident_gatherer::identify_from_sums (docs/eccentricity-hardware.md)"),
    ]);
    v
}

/// Latencies of `encspeed_core` in clock edges, for a filter length `cfg_filter`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Latency {
    /// From the edge that first samples a new level of A or B to the edge after which
    /// `position` and (for a restart) `nep`/`ndt`/`update` show it: 3 + max(L, 1).
    pub edge_to_position: u32,
    /// Speed calculator: a start to its result, 6·(N + F + 1) + 10 (its output registers
    /// are the core's speed outputs).
    pub speed_calc: u32,
    /// From the edge that first samples an A or B edge whose step restarts Table 1 (writes
    /// Ndt1) to the edge after which `speed_strobe` shows the speeds computed from it:
    /// edge_to_position + 1 + speed_calc.
    pub edge_to_speed_strobe: u32,
    /// From the edge that raised `mt_strobe` (a window end of the PC and M/T counters) to
    /// the edge after which `baseline_strobe` shows the window's speeds: the baseline
    /// block samples the start one edge later and takes 4·(N + F + 1) + 4 edges.
    pub window_to_baseline_strobe: u32,
    /// From the edge that samples `reset` to the edge at which the core's registers reset:
    /// the core registers its reset once (a flip-flop at the head of its widest fan-out), 1.
    /// A reset held for k edges resets the core at the k edges after those.
    pub reset_to_effect: u32,
    /// From the edge that samples a new `cfg_filter`, `cfg_z_mode` or `cfg_mode` to the
    /// edge at which it acts (a new `cfg_mode`: the reset of the core): the core registers
    /// its configuration inputs once, 1. (`stalled` and `valid` are registered comparisons
    /// with the registered `cfg_timeout`, so a new timeout acts in them at the edge after
    /// the one that samples it, 1 as well.)
    pub config_to_effect: u32,
    /// From the edge that samples a new `cfg_dt` to the first edge whose dt window uses it
    /// (Rairán's time base, PC and M/T): the dt register (`dt_active`), then the time bases'
    /// comparison made an edge ahead, 2.
    pub cfg_dt_to_window: u32,
}

impl Latency {
    /// The latencies for `p` and a filter of `cfg_filter` cycles.
    pub fn new(p: &Params, cfg_filter: u64) -> Latency {
        let edge_to_position = 3 + cfg_filter.max(1) as u32;
        let speed_calc = speed_calc::latency_cycles(p.counter_bits(), p.speed_frac_bits());
        let baseline = baseline_speeds::latency_cycles(p.counter_bits(), p.speed_frac_bits());
        Latency {
            edge_to_position,
            speed_calc,
            edge_to_speed_strobe: edge_to_position + 1 + speed_calc,
            window_to_baseline_strobe: 1 + baseline,
            reset_to_effect: 1,
            config_to_effect: 1,
            cfg_dt_to_window: 2,
        }
    }
}
