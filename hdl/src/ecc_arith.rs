//! Stage-2 arithmetic of the eccentricity corrector ([`crate::ecc_corrector`]): one signed
//! 16 × 25-bit multiply, an arithmetic shift and a sign-extending concatenation, written as
//! `Verilog::Custom` because `#[hdl_gen]` does not emit these with the right widths
//! (RUST-HDL-NOTES). Its `update()` repeats the Verilog operation by operation in the same
//! widths, written independently of the golden model; rust-hdl and Icarus are both checked
//! against `golden::ecc_corrector` through the corrector's tests. Combinational.

use rust_hdl::prelude::*;

/// Combinational stage-2 arithmetic: `n_c` = `delta_m`·2^24 − ⌊(`e_coef`·(`s_b` − `s_a`)
/// + 2^11)/2^12⌋, all signed two's complement.
#[derive(LogicBlock, Default)]
pub struct EccArith {
    /// ΔM, signed.
    pub delta_m: Signal<In, Bits<24>>,
    /// E_reg, signed.
    pub e_coef: Signal<In, Bits<16>>,
    /// S\[m_a\], signed.
    pub s_a: Signal<In, Bits<24>>,
    /// S\[m_b\], signed.
    pub s_b: Signal<In, Bits<24>>,
    /// N_c·2^24, signed.
    pub n_c: Signal<Out, Bits<49>>,
}

fn signed_of(v: u64, bits: u32) -> i64 {
    let shift = 64 - bits;
    ((v << shift) as i64) >> shift
}

impl Logic for EccArith {
    fn update(&mut self) {
        // The Verilog below, operation by operation, in its widths (written independently of
        // the golden model, which the tests compare it with).
        let m40 = (1u64 << 40) - 1;
        let e_w = signed_of(self.e_coef.val().to_u64(), 16) as u64 & m40;
        let sa_w = signed_of(self.s_a.val().to_u64(), 24) as u64 & m40;
        let sb_w = signed_of(self.s_b.val().to_u64(), 24) as u64 & m40;
        let ds = sb_w.wrapping_sub(sa_w) & m40;
        let d_r = e_w.wrapping_mul(ds).wrapping_add(2048) & m40;
        let w = (signed_of(d_r, 40) >> 12) as u64;
        let dm = self.delta_m.val().to_u64() << 24;
        let dm = signed_of(dm, 48) as u64;
        self.n_c.next = (dm.wrapping_sub(w) & ((1u64 << 49) - 1)).into();
    }

    fn connect(&mut self) {
        self.n_c.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(
            "\
wire signed [39:0] e_w = {{24{e_coef[15]}}, e_coef};
wire signed [39:0] sa_w = {{16{s_a[23]}}, s_a};
wire signed [39:0] sb_w = {{16{s_b[23]}}, s_b};
wire signed [39:0] ds = sb_w - sa_w;
wire signed [39:0] d_r = (e_w * ds) + 40'sd2048;
wire signed [39:0] w = d_r >>> 12;

always @(*) begin
   n_c = {delta_m[23], delta_m, 24'h000000} - {{9{w[39]}}, w};
end"
            .to_string(),
        )
    }
}
