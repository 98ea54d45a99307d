// Self-checking replay bench for the emitted encspeed_core.v, run in Icarus Verilog.
//
// Reads `vectors.txt` (one line per clock cycle, written by tb::icarus from the bit-true
// golden model), in decimal: the inputs
//   reset enc_a enc_b enc_z cfg_dt cfg_timeout cfg_filter cfg_mode cfg_z_mode clear_faults
// then the expected outputs after the edge (speeds as raw S-bit two's complement)
//   position z_latch index direction nep ndt update speed_n1 speed_n2 speed_n3 speed_strobe
//   speed_pc speed_et speed_mt baseline_strobe valid stalled fault_illegal fault_overspeed
//   fault_revolution cfg_error glitch_count illegal_count rev_error_count
// applies the inputs, gives one rising clock edge and compares every output. Ends with
// "N passed, M failed" and exits through $finish. Compile with -DW=<counter_bits> and
// -DS=<speed bits>.
module replay_tb;
    reg clock = 0;
    reg reset, enc_a, enc_b, enc_z, clear_faults;
    reg [`W-1:0] cfg_dt, cfg_timeout;
    reg [15:0] cfg_filter;
    reg [1:0] cfg_mode, cfg_z_mode;
    wire [31:0] position, z_latch;
    wire index, direction, update, speed_strobe, baseline_strobe, valid, stalled;
    wire fault_illegal, fault_overspeed, fault_revolution, cfg_error;
    wire [`W-1:0] nep, ndt;
    wire [`S-1:0] speed_n1, speed_n2, speed_n3, speed_pc, speed_et, speed_mt;
    wire [15:0] glitch_count, illegal_count, rev_error_count;

    encspeed_core dut (
        .clock(clock), .reset(reset), .enc_a(enc_a), .enc_b(enc_b), .enc_z(enc_z),
        .cfg_dt(cfg_dt), .cfg_timeout(cfg_timeout), .cfg_filter(cfg_filter),
        .cfg_mode(cfg_mode), .cfg_z_mode(cfg_z_mode), .clear_faults(clear_faults),
        .position(position), .z_latch(z_latch), .index(index), .direction(direction),
        .nep(nep), .ndt(ndt), .update(update), .speed_n1(speed_n1), .speed_n2(speed_n2),
        .speed_n3(speed_n3), .speed_strobe(speed_strobe), .speed_pc(speed_pc),
        .speed_et(speed_et), .speed_mt(speed_mt), .baseline_strobe(baseline_strobe),
        .valid(valid), .stalled(stalled), .fault_illegal(fault_illegal),
        .fault_overspeed(fault_overspeed), .fault_revolution(fault_revolution),
        .cfg_error(cfg_error), .glitch_count(glitch_count), .illegal_count(illegal_count),
        .rev_error_count(rev_error_count)
    );

    integer fd, n, k, passed, failed;
    reg [63:0] v [0:33];
    reg [63:0] got [0:23];
    reg ok;
    initial begin
        passed = 0;
        failed = 0;
        fd = $fopen("vectors.txt", "r");
        if (fd == 0) begin
            $display("cannot open vectors.txt");
            $finish;
        end
        while (!$feof(fd)) begin
            n = 0;
            for (k = 0; k < 34; k = k + 1)
                n = n + $fscanf(fd, "%d", v[k]);
            if (n == 34) begin
                reset = v[0][0]; enc_a = v[1][0]; enc_b = v[2][0]; enc_z = v[3][0];
                cfg_dt = v[4][`W-1:0]; cfg_timeout = v[5][`W-1:0]; cfg_filter = v[6][15:0];
                cfg_mode = v[7][1:0]; cfg_z_mode = v[8][1:0]; clear_faults = v[9][0];
                #5 clock = 1;
                #1;
                got[0] = position; got[1] = z_latch; got[2] = index; got[3] = direction;
                got[4] = nep; got[5] = ndt; got[6] = update; got[7] = speed_n1;
                got[8] = speed_n2; got[9] = speed_n3; got[10] = speed_strobe;
                got[11] = speed_pc; got[12] = speed_et; got[13] = speed_mt;
                got[14] = baseline_strobe; got[15] = valid; got[16] = stalled;
                got[17] = fault_illegal; got[18] = fault_overspeed; got[19] = fault_revolution;
                got[20] = cfg_error; got[21] = glitch_count; got[22] = illegal_count;
                got[23] = rev_error_count;
                ok = 1;
                for (k = 0; k < 24; k = k + 1)
                    if (got[k] !== v[10 + k]) begin
                        ok = 0;
                        if (failed < 10)
                            $display("cycle %0d: output %0d expected %0d, got %0d",
                                     passed + failed, k, v[10 + k], got[k]);
                    end
                if (ok) passed = passed + 1;
                else failed = failed + 1;
                #4 clock = 0;
            end
        end
        $fclose(fd);
        $display("%0d passed, %0d failed", passed, failed);
        $finish;
    end
endmodule
