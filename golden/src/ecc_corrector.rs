//! Bit-true model of the first-harmonic eccentricity corrector `hdl::EccCorrector<A>`.
//!
//! It computes, in hardware, the corrected line count of
//! [`crate::eccentric::correct`]: N_c = ΔM − E·(S\[m_b\] − S\[m_a\]), S\[m\] = sin(2π(m + m0)/K),
//! E = K·e/(2π) lines (first order, rigid disc, scale 1).
//!
//! # Formats
//! | signal | width | format |
//! |---|---|---|
//! | `delta_m` ΔM | 24 | signed integer (lines), two's complement (the core's 24-bit counters) |
//! | `m_a`, `m_b`, `m0` | A | unsigned line positions, < K |
//! | `e_coef` | 16 | signed, E_reg = round(E·2^13·2^23/Q) ([`e_register`]): Q2.13 of E (scaled by 2^23/Q = 1 + 1.2e-7), \|E\| < 4 lines, i.e. e < 8π/K (2.45 % at K = 1024) |
//! | S (two [`crate::sine_rom::SineRom`]s) | 24 | signed, round(sin·Q), Q = 2^23 − 1 |
//! | `n_c` | 49 | signed Q25.24: N_c·2^24 |
//!
//! The scale 2^23/Q folded into E_reg lets the hardware divide by a power of two:
//! E_reg·S_int/2^36 = E·sin up to quantisation. The hardware computes
//! N_c·2^24 = ΔM·2^24 − ⌊(E_reg·(S_b − S_a) + 2^11)/2^12⌋
//! (one multiply, 16 × 25 bits: |E_reg·(S_b − S_a)| < 2^39 fits in 40 bits; rounding half
//! up). |N_c·2^24| < 2^47 + 2^27: 49 bits never wrap. A later divider forms the
//! corrected speed as N_c/T with 24 more fractional bits in the numerator than ΔM/T.
//!
//! # Semantics and latency (per rising clock edge)
//! Edge j samples `start`, ΔM and E_reg into stage registers and reads the two ROMs at
//! (m_a + m0) mod K and (m_b + m0) mod K. Edge j + 1 computes N_c from those registers and
//! writes `n_c`, with `valid` high until the next edge. Latency: the request sampled by edge
//! j is in `n_c` after edge j + 1 (two register stages); a new request may come every cycle.
//! `n_c` holds between results. Reset (synchronous, active high) clears `valid`, `n_c` and
//! the stage registers; the ROM outputs are not reset (they are ignored until a request).
//!
//! # Error budget against the f64 correction (lines), see [`error_budget`]
//! With E' = E_reg·Q/2^36 (|E' − E| ≤ 2^-14·Q/2^23 < 2^-14) and S' = S_int/Q
//! (|S' − S| ≤ 1/(2Q) at each end):
//! |N_c − N_c,f64| ≤ |E'|·|ΔS' − ΔS| + |ΔS|·|E' − E| + ½·2^-24
//!               ≤ (|E| + 2^-14)/Q + |ΔS|·2^-14 + 2^-25,
//! the three terms being the table, the E quantisation and the output rounding. For one line
//! at K = 1024 and E = 1.90 lines (e = 0.35/30), |ΔS| ≤ 2·sin(π/K): 2.3e-7 + 3.7e-7 + 3e-8
//! = 6.3e-7 lines. The phase m0 is an integer number of lines: θ0 off that grid is an
//! identification matter, outside this budget.

use crate::sine_rom::SineRom;

/// Width of ΔM.
pub const DM_BITS: u32 = 24;
/// Width of the table entries.
pub const S_BITS: u32 = 24;
/// Fractional bits of E_reg.
pub const E_FRAC: u32 = 13;
/// Fractional bits F of N_c.
pub const NC_FRAC: u32 = 24;
/// Width of N_c.
pub const NC_BITS: u32 = 49;
/// Right shift of the product: 13 + 23 − F.
pub const SHIFT: u32 = E_FRAC + S_BITS - 1 - NC_FRAC;

/// E_reg for E = `e_lines` (module docs); panics if it does not fit 16 bits.
pub fn e_register(e_lines: f64) -> i64 {
    let q = crate::sine_rom::full_scale(S_BITS) as f64;
    let r = (e_lines * f64::from(1u32 << E_FRAC) * f64::from(1u32 << (S_BITS - 1)) / q).round();
    assert!(
        (-32768.0..=32767.0).contains(&r),
        "E = {e_lines} lines does not fit Q2.13"
    );
    r as i64
}

/// Worst-case |N_c − N_c,f64| (lines) for |E| = `e_lines` and |S_b − S_a| = `delta_s`.
pub fn error_budget(e_lines: f64, delta_s: f64) -> f64 {
    let q = crate::sine_rom::full_scale(S_BITS) as f64;
    let lsb_e = 1.0 / f64::from(1u32 << (E_FRAC + 1));
    (e_lines.abs() + lsb_e) / q + delta_s.abs() * lsb_e + 0.5 / f64::from(1u32 << NC_FRAC)
}

/// The arithmetic of the second stage: N_c·2^16 from ΔM, E_reg and the two table entries
/// (all signed integers).
pub fn corrected(delta_m: i64, e_reg: i64, s_a: i64, s_b: i64) -> i64 {
    let d = e_reg * (s_b - s_a);
    debug_assert!(d.abs() < 1 << 39);
    let w = (d + (1 << (SHIFT - 1))) >> SHIFT;
    (delta_m << NC_FRAC) - w
}

/// Inputs of an [`EccCorrector`] during one clock cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccInputs {
    /// Synchronous active-high reset.
    pub reset: bool,
    /// A correction request this cycle.
    pub start: bool,
    /// ΔM (signed, 24 bits).
    pub delta_m: i64,
    /// Position of the first edge (A bits).
    pub m_a: u64,
    /// Position of the second edge (A bits).
    pub m_b: u64,
    /// Phase offset (A bits).
    pub m0: u64,
    /// E_reg (signed, 16 bits).
    pub e_coef: i64,
}

/// Outputs of an [`EccCorrector`] after a clock edge (registers).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EccOutputs {
    /// N_c·2^16 (signed).
    pub n_c: i64,
    /// A new N_c this cycle.
    pub valid: bool,
}

/// First-harmonic corrector, bit-true model of `hdl::EccCorrector<A>` (module docs).
#[derive(Clone, Debug)]
pub struct EccCorrector {
    rom_a: SineRom,
    rom_b: SineRom,
    busy: bool,
    dm: i64,
    e: i64,
    out: EccOutputs,
}

impl EccCorrector {
    /// A corrector for K = `lines`, A = `addr_bits`, after reset.
    pub fn new(lines: u32, addr_bits: u32) -> Self {
        Self {
            rom_a: SineRom::new(lines, addr_bits, S_BITS),
            rom_b: SineRom::new(lines, addr_bits, S_BITS),
            busy: false,
            dm: 0,
            e: 0,
            out: EccOutputs::default(),
        }
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: EccInputs) -> EccOutputs {
        let dm_half = 1i64 << (DM_BITS - 1);
        assert!(
            (-dm_half..dm_half).contains(&inp.delta_m),
            "ΔM does not fit"
        );
        assert!((-32768..32768).contains(&inp.e_coef), "E_reg does not fit");
        // Stage 2 from the registers before the edge.
        if self.busy {
            self.out.n_c = corrected(self.dm, self.e, self.rom_a.data(), self.rom_b.data());
        }
        self.out.valid = self.busy;
        // Stage 1.
        self.rom_a.step(inp.m_a, inp.m0);
        self.rom_b.step(inp.m_b, inp.m0);
        self.busy = inp.start;
        self.dm = inp.delta_m;
        self.e = inp.e_coef;
        if inp.reset {
            self.busy = false;
            self.dm = 0;
            self.e = 0;
            self.out = EccOutputs::default();
        }
        self.out
    }
}
