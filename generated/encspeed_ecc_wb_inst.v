// Command: encspeed generate --clock-hz 100000000 --lines 1024 --dt-cycles 100000 --counter-bits 24 --timeout-s 1
// SPDX-License-Identifier: MIT OR Apache-2.0
// encspeed_ecc_wb_inst.v: instantiation template of encspeed_ecc_wb (encspeed_ecc_wb.v). Do not edit:
// copy it into your design and rename the instance and the signals.
// Generated for clock_hz = 100000000, lines = 1024, dt_cycles = 100000, counter_bits = 24, timeout_s = 1, estimators = n1,n2,n3,pc,et,mt: see encspeed_ecc_wb.toml for the latencies and the error budget.
// enc_a, enc_b, enc_z may be asynchronous (synchronised inside by two flip-flops); every other port is synchronous to the rising edge of clock; reset is synchronous and active high.
// The configuration is in registers: see encspeed_regs.h and docs/registers.md.
encspeed_ecc_wb u_encspeed_ecc_wb (
    .clock    (clock   ), // input: core and bus clock; everything happens at its rising edge
    .reset    (reset   ), // input: synchronous, active high: resets every register at the edge that samples it, and the core (which registers it) at the edge after; the core also resets at the first edge after power-up
    .enc_a    (enc_a   ), // input: encoder channel A, asynchronous (two-flop synchronised inside)
    .enc_b    (enc_b   ), // input: encoder channel B, asynchronous; forward = A leads B by 90 degrees
    .enc_z    (enc_z   ), // input: encoder index Z, asynchronous
    .sample   (sample  ), // input: synchronous strobe: at the edge that samples it high (unless CTRL.HOLD) the register file takes a coherent snapshot of position, nep, ndt, the speeds and valid/stalled/direction as the core outputs them in that cycle (CTRL.SAMPLED reads it); tie to 0 if unused
    .wb_cyc_i (wb_cyc_i), // input: Wishbone B4 classic: bus cycle
    .wb_stb_i (wb_stb_i), // input: Wishbone: strobe (this slave is addressed)
    .wb_we_i  (wb_we_i ), // input: Wishbone: 1 = write, 0 = read
    .wb_adr_i (wb_adr_i), // input [7:0]: Wishbone: byte address within the register window; bits 1:0 ignored
    .wb_dat_i (wb_dat_i), // input [31:0]: Wishbone: write data
    .wb_sel_i (wb_sel_i), // input [3:0]: Wishbone: byte lanes of a write (lane j = bits 8j+7..8j)
    .wb_dat_o (wb_dat_o), // output [31:0]: Wishbone: read data, valid with wb_ack_o (0 otherwise)
    .wb_ack_o (wb_ack_o), // output: Wishbone: acknowledge, high for one cycle from the edge after the request edge
    .irq      (irq     )  // output: interrupt request, level: (IRQ_STATUS & IRQ_ENABLE) != 0, a register output
);
