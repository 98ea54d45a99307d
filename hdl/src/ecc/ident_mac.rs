// SPDX-License-Identifier: MIT OR Apache-2.0
//! Stage-2 arithmetic of the identification gatherer ([`crate::ecc::ident_gatherer`]): two
//! T × 24-bit multiply-adds written as `Verilog::Custom` (rust-hdl multiplies only 16 bits),
//! with an `update()` that repeats the Verilog in the same widths, written independently of
//! the golden model; rust-hdl and Icarus are both checked against
//! `golden::ecc::ident_gatherer` through the gatherer's tests. Combinational.

use rust_hdl::prelude::*;

/// The stage-2 arithmetic, combinational: `nxt_t` = `acc_t` + `t`, `nxt_s` = `acc_s` +
/// `t`·`s`, `nxt_c` = `acc_c` + `t`·`c` (`t` unsigned, `s`, `c` and the sums signed, W-bit
/// wrap-around; the gatherer never lets them wrap). Each product is an unsigned T × 24-bit
/// multiply of `t` by the entry's bits, minus `t`·2^24 when the entry is negative (T + 25
/// bits, two's complement), sign-extended to W: yosys keeps the multipliers T × 24.
#[derive(LogicBlock, Default)]
pub struct IdentMac<const T: usize, const W: usize> {
    /// Period, unsigned.
    pub t: Signal<In, Bits<T>>,
    /// Sine entry, signed.
    pub s: Signal<In, Bits<24>>,
    /// Cosine entry, signed.
    pub c: Signal<In, Bits<24>>,
    /// Σ T so far.
    pub acc_t: Signal<In, Bits<W>>,
    /// Σ T·S so far, signed.
    pub acc_s: Signal<In, Bits<W>>,
    /// Σ T·C so far, signed.
    pub acc_c: Signal<In, Bits<W>>,
    /// `acc_t` + `t`.
    pub nxt_t: Signal<Out, Bits<W>>,
    /// `acc_s` + `t`·`s`.
    pub nxt_s: Signal<Out, Bits<W>>,
    /// `acc_c` + `t`·`c`.
    pub nxt_c: Signal<Out, Bits<W>>,
}

fn mask(bits: usize) -> u128 {
    if bits >= 128 {
        u128::MAX
    } else {
        (1u128 << bits) - 1
    }
}

fn sext(v: u128, bits: usize) -> u128 {
    let shift = 128 - bits;
    (((v << shift) as i128) >> shift) as u128
}

impl<const T: usize, const W: usize> Logic for IdentMac<T, W> {
    fn update(&mut self) {
        // The Verilog below, operation by operation, in its widths.
        let p = T + 25;
        let t_w = self.t.val().to_u128();
        let mul = |x: u128| {
            let pu = t_w.wrapping_mul(x) & mask(T + 24);
            let corr = if (x >> 23) & 1 == 1 { t_w << 24 } else { 0 };
            let prod = pu.wrapping_sub(corr) & mask(p);
            sext(prod, p) & mask(W)
        };
        let ps = mul(self.s.val().to_u128());
        let pc = mul(self.c.val().to_u128());
        let add = |a: u128, b: u128| a.wrapping_add(b) & mask(W);
        self.nxt_t.next = add(self.acc_t.val().to_u128(), t_w).to_bits();
        self.nxt_s.next = add(self.acc_s.val().to_u128(), ps).to_bits();
        self.nxt_c.next = add(self.acc_c.val().to_u128(), pc).to_bits();
    }

    fn connect(&mut self) {
        self.nxt_t.connect();
        self.nxt_s.connect();
        self.nxt_c.connect();
    }

    fn hdl(&self) -> Verilog {
        let p = T + 25;
        Verilog::Custom(format!(
            "\
wire [{um}:0] t_x = {{24'd0, t}};
wire [{um}:0] s_x = {{{{{t}{{1'b0}}}}, s}};
wire [{um}:0] c_x = {{{{{t}{{1'b0}}}}, c}};
wire [{um}:0] pu_s = t_x * s_x;
wire [{um}:0] pu_c = t_x * c_x;
wire [{pm}:0] t_hi = {{1'b0, t, 24'd0}};
wire [{pm}:0] ps = {{1'b0, pu_s}} - (s[23] ? t_hi : {p}'d0);
wire [{pm}:0] pc = {{1'b0, pu_c}} - (c[23] ? t_hi : {p}'d0);

always @(*) begin
   nxt_t = acc_t + {{{{{z}{{1'b0}}}}, t}};
   nxt_s = acc_s + {{{{{x}{{ps[{pm}]}}}}, ps}};
   nxt_c = acc_c + {{{{{x}{{pc[{pm}]}}}}, pc}};
end",
            pm = p - 1,
            um = T + 23,
            t = T,
            p = p,
            z = W - T,
            x = W - p,
        ))
    }
}
