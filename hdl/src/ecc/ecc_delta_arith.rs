// SPDX-License-Identifier: MIT OR Apache-2.0
//! Combinational datapath of [`EccDelta`](crate::EccDelta), written as `Verilog::Custom`
//! because `#[hdl_gen]` does not emit sign extension, arithmetic shifts and mixed-width
//! sums with the right widths (docs/design-decisions.md#rust-hdl-rules, D10 and R5). Its
//! `update()` repeats the Verilog operation by operation in the same widths, written
//! independently of the golden model; rust-hdl and Icarus are both checked against
//! `golden::ecc::ecc_delta` through the `EccDelta` tests. No multiplier wider than 3 bits:
//! the wide product is the shift-add sequence of `EccDelta`, one addition of this block per
//! clock.
//!
//! Four independent functions (A = address bits, D = table width, 8 ≤ D ≤ 24):
//! 1. **decode** a position h (33-bit half-steps) at s = min(`shift`, 2): line
//!    l = h\[A+s:s+1\], fraction t = (h mod 2^(s+1))·2^(2−s) in eighths (3 bits);
//! 2. **load**: `mcand_load` = sign-extend(`coef`) << `coef_shift`, 63 bits;
//! 3. **interpolate and accumulate**: `acc_t_next` = `acc_t` ∓ (8·v0 + t·(v1 − v0)), all in
//!    28 bits (v0, v1 sign-extended from D bits; t·x as three gated shifted terms);
//! 4. **accumulate**: `acc_next` = `acc` + operand (or − for `op` = 1) in 63 bits, operand by
//!    `op`: 0 and 1 `mul_bit`·`mcand`, 2 `acc` >>> (D − 1) (the table's 1/Q scale), 3 `mcand`;
//!    `delta_next` = (`acc_next` >>> (D + 2)) in 40 bits; plus the shifts `mcand_shl` =
//!    `mcand` << 1, `sx_shr` = `sx` >> 1, `cx_shr` = `cx` >> 1 (logical).

use rust_hdl::prelude::*;

/// The datapath (module docs), combinational.
#[derive(LogicBlock, Default)]
pub struct EccDeltaArith<const A: usize, const D: usize> {
    /// First position, half-steps.
    pub h_a: Signal<In, Bits<33>>,
    /// Second position, half-steps.
    pub h_b: Signal<In, Bits<33>>,
    /// Decoder shift (3 = 2).
    pub shift: Signal<In, Bits<2>>,
    /// Line of `h_a`.
    pub l_a: Signal<Out, Bits<A>>,
    /// Eighths of `h_a`.
    pub t_a: Signal<Out, Bits<3>>,
    /// Line of `h_b`.
    pub l_b: Signal<Out, Bits<A>>,
    /// Eighths of `h_b`.
    pub t_b: Signal<Out, Bits<3>>,
    /// min(`shift`, 2).
    pub s_eff: Signal<Out, Bits<2>>,
    /// A coefficient, signed Q15.16.
    pub coef: Signal<In, Bits<32>>,
    /// Its shift (0..=2).
    pub coef_shift: Signal<In, Bits<2>>,
    /// sign-extend(`coef`) << `coef_shift`.
    pub mcand_load: Signal<Out, Bits<63>>,
    /// Table entry at l, signed.
    pub v0: Signal<In, Bits<D>>,
    /// Table entry at l + 1, signed.
    pub v1: Signal<In, Bits<D>>,
    /// Fraction in eighths.
    pub t: Signal<In, Bits<3>>,
    /// ΔS8 or ΔC8 so far, signed.
    pub acc_t: Signal<In, Bits<28>>,
    /// Subtract (end a) rather than add (end b).
    pub sub_t: Signal<In, Bit>,
    /// `acc_t` ∓ (8·v0 + t·(v1 − v0)).
    pub acc_t_next: Signal<Out, Bits<28>>,
    /// The accumulator, signed.
    pub acc: Signal<In, Bits<63>>,
    /// The multiplicand, signed.
    pub mcand: Signal<In, Bits<63>>,
    /// Operation (module docs).
    pub op: Signal<In, Bits<2>>,
    /// The multiplier bit.
    pub mul_bit: Signal<In, Bit>,
    /// The accumulator after the operation.
    pub acc_next: Signal<Out, Bits<63>>,
    /// `acc_next` >>> (D + 2), 40 bits.
    pub delta_next: Signal<Out, Bits<40>>,
    /// `mcand` << 1.
    pub mcand_shl: Signal<Out, Bits<63>>,
    /// ΔS8 register.
    pub sx: Signal<In, Bits<28>>,
    /// `sx` >> 1.
    pub sx_shr: Signal<Out, Bits<28>>,
    /// ΔC8 register.
    pub cx: Signal<In, Bits<28>>,
    /// `cx` >> 1.
    pub cx_shr: Signal<Out, Bits<28>>,
}

fn mask(bits: usize) -> u128 {
    (1u128 << bits) - 1
}

/// Sign-extends the low `bits` of `v` to 128 bits (as u128).
fn sext(v: u128, bits: usize) -> u128 {
    let sh = 128 - bits;
    (((v << sh) as i128) >> sh) as u128
}

impl<const A: usize, const D: usize> EccDeltaArith<A, D> {
    fn decode(h: u128, s: u128) -> (u128, u128) {
        let l = (h >> (s + 1)) & mask(A);
        let t = (h & mask(s as usize + 1)) << (2 - s);
        (l, t)
    }
}

impl<const A: usize, const D: usize> Logic for EccDeltaArith<A, D> {
    fn update(&mut self) {
        // The Verilog below, operation by operation, in its widths.
        let sh = self.shift.val().to_u128();
        let s = if sh == 3 { 2 } else { sh };
        let (la, ta) = Self::decode(self.h_a.val().to_u128(), s);
        let (lb, tb) = Self::decode(self.h_b.val().to_u128(), s);
        self.l_a.next = la.to_bits();
        self.t_a.next = ta.to_bits();
        self.l_b.next = lb.to_bits();
        self.t_b.next = tb.to_bits();
        self.s_eff.next = s.to_bits();

        let coef_w = sext(self.coef.val().to_u128(), 32) & mask(63);
        self.mcand_load.next = ((coef_w << self.coef_shift.val().to_u128()) & mask(63)).to_bits();

        let m28 = mask(28);
        let v0 = sext(self.v0.val().to_u128(), D) & m28;
        let v1 = sext(self.v1.val().to_u128(), D) & m28;
        let dv = v1.wrapping_sub(v0) & m28;
        let t = self.t.val().to_u128();
        let mut tdv = 0u128;
        for b in 0..3 {
            if (t >> b) & 1 == 1 {
                tdv = tdv.wrapping_add(dv << b) & m28;
            }
        }
        let val = ((v0 << 3) & m28).wrapping_add(tdv) & m28;
        let at = self.acc_t.val().to_u128();
        self.acc_t_next.next = if self.sub_t.val() {
            at.wrapping_sub(val) & m28
        } else {
            at.wrapping_add(val) & m28
        }
        .to_bits();

        let m63 = mask(63);
        let acc = self.acc.val().to_u128();
        let mcand = self.mcand.val().to_u128();
        let op = self.op.val().to_u128();
        let sra = (sext(acc, 63) >> (D - 1)) & m63;
        let gated = if self.mul_bit.val() { mcand } else { 0 };
        let operand = match op {
            2 => sra,
            3 => mcand,
            _ => gated,
        };
        let sum = if op == 1 {
            acc.wrapping_sub(operand) & m63
        } else {
            acc.wrapping_add(operand) & m63
        };
        self.acc_next.next = sum.to_bits();
        self.delta_next.next = ((sext(sum, 63) >> (D + 2)) & mask(40)).to_bits();
        self.mcand_shl.next = ((mcand << 1) & m63).to_bits();
        self.sx_shr.next = (self.sx.val().to_u128() >> 1).to_bits();
        self.cx_shr.next = (self.cx.val().to_u128() >> 1).to_bits();
    }

    fn connect(&mut self) {
        self.l_a.connect();
        self.t_a.connect();
        self.l_b.connect();
        self.t_b.connect();
        self.s_eff.connect();
        self.mcand_load.connect();
        self.acc_t_next.connect();
        self.acc_next.connect();
        self.delta_next.connect();
        self.mcand_shl.connect();
        self.sx_shr.connect();
        self.cx_shr.connect();
    }

    fn hdl(&self) -> Verilog {
        // δ: bits D + 2 … of the 63-bit sum, sign-extended to 40 when fewer remain.
        let avail = 63 - (D + 2);
        let delta = if avail >= 40 {
            format!("sum[{}:{}]", D + 41, D + 2)
        } else {
            format!("{{{{{}{{sum[62]}}}}, sum[62:{}]}}", 40 - avail, D + 2)
        };
        Verilog::Custom(format!(
            "\
wire [1:0] s_e = (shift == 2'd3) ? 2'd2 : shift;
wire [62:0] coef_w = {{{{31{{coef[31]}}}}, coef}};
wire [27:0] v0_w = {{{{{ext}{{v0[{dm}]}}}}, v0}};
wire [27:0] v1_w = {{{{{ext}{{v1[{dm}]}}}}, v1}};
wire [27:0] dv = v1_w - v0_w;
wire [27:0] tdv = (t[0] ? dv : 28'd0) + (t[1] ? {{dv[26:0], 1'b0}} : 28'd0)
    + (t[2] ? {{dv[25:0], 2'b00}} : 28'd0);
wire [27:0] val = {{v0_w[24:0], 3'b000}} + tdv;
wire [62:0] sra = {{{{{dm}{{acc[62]}}}}, acc[62:{dm}]}};
wire [62:0] gated = mul_bit ? mcand : 63'd0;
wire [62:0] operand = op[1] ? (op[0] ? mcand : sra) : gated;
// One adder for both signs: acc + (operand ^ sub) + sub, the carry-in from an extra LSB.
wire sub = (op == 2'd1);
wire [63:0] sum_x = {{acc, sub}} + {{operand ^ {{63{{sub}}}}, sub}};
wire [62:0] sum = sum_x[63:1];
wire [28:0] at_x = {{acc_t, sub_t}} + {{val ^ {{28{{sub_t}}}}, sub_t}};
// Bits deliberately unused (Verilator ignores signals named *unused*).
wire _unused_ok = &{{1'b0, h_a[32:{a3}], h_b[32:{a3}], sx[0], cx[0], sum_x[0], at_x[0], 1'b0}};

always @(*) begin
   s_eff = s_e;
   case (s_e)
      2'd0: begin
         l_a = h_a[{a0}:1]; t_a = {{h_a[0], 2'b00}};
         l_b = h_b[{a0}:1]; t_b = {{h_b[0], 2'b00}};
      end
      2'd1: begin
         l_a = h_a[{a1}:2]; t_a = {{h_a[1:0], 1'b0}};
         l_b = h_b[{a1}:2]; t_b = {{h_b[1:0], 1'b0}};
      end
      default: begin
         l_a = h_a[{a2}:3]; t_a = h_a[2:0];
         l_b = h_b[{a2}:3]; t_b = h_b[2:0];
      end
   endcase
   mcand_load = coef_w << coef_shift;
   acc_t_next = at_x[28:1];
   acc_next = sum;
   delta_next = {delta};
   mcand_shl = {{mcand[61:0], 1'b0}};
   sx_shr = {{1'b0, sx[27:1]}};
   cx_shr = {{1'b0, cx[27:1]}};
end",
            ext = 28 - D,
            dm = D - 1,
            a0 = A,
            a1 = A + 1,
            a2 = A + 2,
            a3 = A + 3,
            delta = delta,
        ))
    }
}
