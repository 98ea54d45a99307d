// SPDX-License-Identifier: MIT OR Apache-2.0
// table1_lite: an independent, hand-written implementation of Rairán's Table 1
// synchronised estimator, with n3 (the harmonic mean of n1 and n2) on its output.
//
// It is the example "other implementation" for `encspeed check --mode bound`: it shares
// no code with encspeed_core, so it shows the checker judging a design by its ports and
// the estimator's proven error bound only, never by bit-equality with our core. To make
// that point it is deliberately different from encspeed_core:
//   - x1 decoding only (a step is an A edge while B is low); no glitch filter, no index,
//     no fault detection, no zero-speed timeout, no valid flag, no n1/n2 or baselines;
//   - the time base dt is a parameter (DT clock cycles), not a run-time input;
//   - n3 is in lines per dt with FRAC fractional bits (Q.8 by default) on W bits, and
//     its magnitude is truncated (floor) rather than rounded;
//   - its own serial restoring divider, one quotient bit per clock, so n3 is written
//     2*CW + FRAC + 3 clock edges (43 by default) after the edge that wrote Nep1 or
//     Ndt1, where encspeed_core has another latency.
// Define TABLE1_LITE_BROKEN to output q + q/32 instead of q, a 3 % gain error: a test
// uses it to show that the checker rejects a wrong implementation.
`timescale 1ns/1ps
module table1_lite #(
    parameter DT = 1000,  // dt in clock cycles; 2 .. 2^CW - 1
    parameter CW = 16,    // width of ts, Cep, Cdt, Nep1, Ndt1
    parameter FRAC = 8,   // fractional bits of n3
    parameter W = 24      // width of n3
) (
    input wire clk,
    input wire rst,
    input wire a,
    input wire b,
    output reg signed [W-1:0] n3,
    output reg n3_stb
);
    // The largest numerator is 2*Nep1*(Nep1 - 1)*2^FRAC and the largest denominator
    // Ndt1*(2*Nep1 - 1): these widths hold them for any CW-bit Nep1 and Ndt1.
    localparam NW = 2 * CW + FRAC + 1;
    localparam DW = 2 * CW + 1;
    localparam KW = $clog2(NW + 1);
    localparam [CW-1:0] DT_C = DT;
    localparam [CW-1:0] CMAX = {CW{1'b1}};
    localparam [KW-1:0] NW_K = NW;
    localparam [KW-1:0] ONE_K = 1;

    // Synchroniser: A and B are asynchronous, so two flops before anything uses them;
    // a_d is the previous synchronised A, for edge detection.
    reg a_m, a_s, a_d, b_m, b_s;
    always @(posedge clk) begin
        a_m <= a;
        a_s <= a_m;
        a_d <= a_s;
        b_m <= b;
        b_s <= b_m;
    end

    // x1: one step per line, at the A edge that happens while B is low. Forward when the
    // previous A equals the new B (A rising, B low).
    wire lep = (a_s != a_d) && !b_s;
    wire lep_fwd = (a_d == b_s);

    // Table 1. Nep1/Ndt1 are written by a restart (a pulse after at least one dt tick,
    // which also restarts the time base so that it follows the pulses) or by a tick that
    // closes a window holding pulses. Either write is an "update".
    reg [CW-1:0] ts, Cep, Cdt, Nep1, Ndt1;
    reg fwd;  // direction of the last pulse
    reg [CW-1:0] ts_n, Cep_n, Cdt_n, Nep1_n, Ndt1_n;
    reg upd_n;

    // Snapshot of an update, handed to the divider.
    reg [CW-1:0] s_nep, s_ndt;
    reg s_fwd, go;

    // One Table 1 step, in the paper's order, on next-value variables: each condition
    // sees the effect of the ones before it (ts is the value after its increment).
    always @* begin
        // Saturating, not wrapping: a count that wrapped would read as a high speed.
        ts_n = (ts == CMAX) ? ts : ts + 1'b1;
        Cep_n = Cep;
        Cdt_n = Cdt;
        Nep1_n = Nep1;
        Ndt1_n = Ndt1;
        upd_n = 1'b0;
        if (lep && Cdt != 0) begin
            Ndt1_n = Cdt;
            ts_n = 0;
            upd_n = 1'b1;
        end
        if (ts_n == DT_C && Cep != 0) begin
            Nep1_n = Cep;
            upd_n = 1'b1;
        end
        if (lep) begin
            Cep_n = (Cep == CMAX) ? Cep : Cep + 1'b1;
            Cdt_n = 0;
        end
        if (ts_n == DT_C) begin
            Cdt_n = (Cdt_n == CMAX) ? Cdt_n : Cdt_n + 1'b1;
            Cep_n = 0;
            ts_n = 0;
        end
    end

    always @(posedge clk) begin
        if (rst) begin
            ts <= 0;
            Cep <= 0;
            Cdt <= 0;
            Nep1 <= 0;
            Ndt1 <= 1;
            fwd <= 1'b1;
            go <= 1'b0;
            s_nep <= 0;
            s_ndt <= 1;
            s_fwd <= 1'b1;
        end else begin
            ts <= ts_n;
            Cep <= Cep_n;
            Cdt <= Cdt_n;
            Nep1 <= Nep1_n;
            Ndt1 <= Ndt1_n;
            if (lep)
                fwd <= lep_fwd;
            go <= upd_n;
            if (upd_n) begin
                s_nep <= Nep1_n;
                s_ndt <= Ndt1_n;
                s_fwd <= lep ? lep_fwd : fwd;
            end
        end
    end

    // n3 = 2*Nep1/(2*Ndt1 + 1) when 2*Ndt1 > Nep1 (n1 < 2), else
    // 2*Nep1*(Nep1 - 1)/(Ndt1*(2*Nep1 - 1)); the numerator carries the 2^FRAC scale.
    // A new update while the divider is busy restarts it with the newer snapshot (no
    // queue): the output follows the newest estimate. Table 1 cannot starve the divider:
    // a restart zeroes the time base, so at least DT cycles without an update follow it,
    // and ticks are DT apart; a division abandoned for a newer update is thus replaced by
    // one that completes, as long as DT > NW + 2. A result already complete is still
    // published when a new division starts on the same edge.
    reg [NW-1:0] num_sh;  // numerator bits leave at the top, quotient bits enter below
    reg [DW-1:0] rem, den;
    reg [KW-1:0] cnt;
    reg busy, fin, d_fwd;

    // The high-speed products; only used when Nep1 >= 2*Ndt1 >= 2, so Nep1 - 1 >= 1.
    wire [2*CW-1:0] prod = {{CW{1'b0}}, s_nep} * {{CW{1'b0}}, s_nep - 1'b1};
    wire [CW:0] twice_nep_m1 = {s_nep, 1'b0} - 1'b1;
    wire [DW-1:0] den_hi = {{CW{1'b0}}, s_ndt} * {{(CW - 1){1'b0}}, twice_nep_m1};
    reg [NW-1:0] num_n;
    reg [DW-1:0] den_n;

    always @* begin
        if (s_nep == 0) begin
            num_n = 0;
            den_n = 1;
        end else if ({s_ndt, 1'b0} > {1'b0, s_nep}) begin
            num_n = {{(NW - CW - FRAC - 1){1'b0}}, s_nep, 1'b0, {FRAC{1'b0}}};
            den_n = {{CW{1'b0}}, s_ndt, 1'b1};
        end else begin
            num_n = {prod, 1'b0, {FRAC{1'b0}}};
            den_n = den_hi;
        end
    end

    // Restoring step: the partial remainder is always below den, so rem fits DW bits
    // and trial - den, taken modulo 2^DW, is exact.
    wire [DW:0] trial = {rem, num_sh[NW-1]};
    wire fits = trial >= {1'b0, den};
    wire [DW-1:0] rem_sub = trial[DW-1:0] - den;

`ifdef TABLE1_LITE_BROKEN
    wire [NW:0] qx = {1'b0, num_sh} + {6'b0, num_sh[NW-1:5]};
`else
    wire [NW:0] qx = {1'b0, num_sh};
`endif
    // n3 is W bits signed: clamp the magnitude so a huge Nep1 cannot wrap the sign.
    wire [W-1:0] mag = (|qx[NW:W-1]) ? {1'b0, {(W - 1){1'b1}}} : qx[W-1:0];

    always @(posedge clk) begin
        n3_stb <= 1'b0;
        fin <= 1'b0;
        if (rst) begin
            busy <= 1'b0;
            n3 <= 0;
            cnt <= 0;
            num_sh <= 0;
            rem <= 0;
            den <= 1;
            d_fwd <= 1'b1;
        end else begin
            if (fin) begin
                n3 <= d_fwd ? $signed(mag) : -$signed(mag);
                n3_stb <= 1'b1;
            end
            if (go) begin
                num_sh <= num_n;
                den <= den_n;
                rem <= 0;
                d_fwd <= s_fwd;
                cnt <= NW_K;
                busy <= 1'b1;
            end else if (busy) begin
                rem <= fits ? rem_sub : trial[DW-1:0];
                num_sh <= {num_sh[NW-2:0], fits};
                cnt <= cnt - 1'b1;
                if (cnt == ONE_K) begin
                    busy <= 1'b0;
                    fin <= 1'b1;
                end
            end
        end
    end
endmodule
