// SPDX-License-Identifier: MIT OR Apache-2.0
// A user's bench for the shipped encspeed_core.v, written the way an outside engineer would:
// only the ports and the manifest's speed_frac_bits are used, nothing of this repository.
//
// Drives x1 quadrature (B a quarter period behind A, forward) of `PERIOD clock cycles per
// line with cfg_dt = `DT, every other configuration input tied to 0 (filter off, x1, Z
// ignored, default timeout), and prints every speed_n3 update as a real number of ω_lim:
//   "speed <value> valid <0|1>"
// then "done". Compile with -DW=<counter_bits> -DS=<speed bits> -DFRAC=<speed_frac_bits>
// -DPERIOD=<cycles> -DDT=<cycles> -DCYCLES=<cycles to run>.
module constant_speed_tb;
    reg clock = 0, reset = 1, enc_a = 0, enc_b = 0;
    wire [`S-1:0] speed_n3;
    wire speed_strobe, valid;
    integer k, m;
    wire [`W-1:0] dt = `DT;

    encspeed_core dut (
        .clock(clock), .reset(reset), .enc_a(enc_a), .enc_b(enc_b), .enc_z(1'b0),
        .cfg_dt(dt), .cfg_timeout({`W{1'b0}}), .cfg_filter(16'd0), .cfg_mode(2'd0),
        .cfg_z_mode(2'd0), .clear_faults(1'b0),
        .position(), .z_latch(), .index(), .direction(), .nep(), .ndt(), .update(),
        .speed_n1(), .speed_n2(), .speed_n3(speed_n3), .speed_strobe(speed_strobe),
        .speed_pc(), .speed_et(), .speed_mt(), .baseline_strobe(), .valid(valid),
        .stalled(), .fault_illegal(), .fault_overspeed(), .fault_revolution(), .cfg_error(),
        .glitch_count(), .illegal_count(), .rev_error_count()
    );

    always #5 clock = ~clock;

    initial begin
        for (k = 0; k < `CYCLES; k = k + 1) begin
            @(negedge clock);
            reset = k < 4;
            m = k % `PERIOD;
            enc_a = m < `PERIOD / 2;
            enc_b = ((m + `PERIOD - `PERIOD / 4) % `PERIOD) < `PERIOD / 2;
            @(posedge clock);
            #1;
            if (speed_strobe)
                $display("speed %0.9f valid %0d", $itor($signed(speed_n3)) / (2.0 ** `FRAC), valid);
        end
        $display("done");
        $finish;
    end
endmodule
