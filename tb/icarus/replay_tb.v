// Self-checking replay bench for the emitted encspeed_core.v, run in Icarus Verilog.
//
// Reads `vectors.txt` (one line per clock cycle, written by tb::icarus from the bit-true
// golden model): "reset enc_a enc_b enc_z cfg_dt nep ndt update stalled cfg_error" in
// decimal, applies the inputs, gives one rising clock edge and compares every output with
// the expected values. Ends with "N passed, M failed" and exits through $finish.
// Compile with -DW=<counter_bits>.
module replay_tb;
    reg clock = 0;
    reg reset, enc_a, enc_b, enc_z;
    reg [`W-1:0] cfg_dt;
    wire [`W-1:0] nep, ndt;
    wire update, stalled, cfg_error;

    encspeed_core dut (
        .clock(clock), .reset(reset), .enc_a(enc_a), .enc_b(enc_b), .enc_z(enc_z),
        .cfg_dt(cfg_dt), .nep(nep), .ndt(ndt), .update(update), .stalled(stalled),
        .cfg_error(cfg_error)
    );

    integer fd, n, passed, failed;
    reg [63:0] r, a, b, z, dt, e_nep, e_ndt, e_update, e_stalled, e_cfg_error;
    initial begin
        passed = 0;
        failed = 0;
        fd = $fopen("vectors.txt", "r");
        if (fd == 0) begin
            $display("cannot open vectors.txt");
            $finish;
        end
        while (!$feof(fd)) begin
            n = $fscanf(fd, "%d %d %d %d %d %d %d %d %d %d\n",
                        r, a, b, z, dt, e_nep, e_ndt, e_update, e_stalled, e_cfg_error);
            if (n == 10) begin
                reset = r[0]; enc_a = a[0]; enc_b = b[0]; enc_z = z[0]; cfg_dt = dt[`W-1:0];
                #5 clock = 1;
                #1;
                if (nep === e_nep[`W-1:0] && ndt === e_ndt[`W-1:0] && update === e_update[0]
                    && stalled === e_stalled[0] && cfg_error === e_cfg_error[0]) begin
                    passed = passed + 1;
                end else begin
                    if (failed < 10)
                        $display("cycle %0d: expected nep=%0d ndt=%0d update=%0d stalled=%0d cfg_error=%0d, got %0d %0d %0d %0d %0d",
                                 passed + failed, e_nep, e_ndt, e_update, e_stalled, e_cfg_error,
                                 nep, ndt, update, stalled, cfg_error);
                    failed = failed + 1;
                end
                #4 clock = 0;
            end
        end
        $fclose(fd);
        $display("%0d passed, %0d failed", passed, failed);
        $finish;
    end
endmodule
