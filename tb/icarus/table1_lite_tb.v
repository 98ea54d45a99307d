// SPDX-License-Identifier: MIT OR Apache-2.0
// Constant-speed bench for table1_lite, the example input of `encspeed check --mode bound`.
//
// An ideal x1 quadrature encoder (A high for the first half of each line, B a quarter line
// behind A when moving forward) runs through nine constant-speed segments, its phase
// continuous across them: +0.37, +0.8, +1.6, +3.3, +7.9, +23.5, +61.2, -5.3, +0.55 lines
// per dt (dt = 1000 cycles of 10 ns = 10 us). Each lasts max(30 dt, 12 line periods).
// The edge instants are computed in real arithmetic and reached with real-valued delays,
// so they fall between clock edges, as a real encoder's would. The VCD holds tb.dut only:
//   vvp <sim> +vcd=<file>
`timescale 1ns/1ps
module tb;
    localparam real DT_NS = 10000.0;  // dt = 1000 cycles of 10 ns
    localparam NSEG = 9;

    reg clk = 1'b0;
    reg rst = 1'b1;
    reg a = 1'b0;
    reg b = 1'b0;
    wire signed [23:0] n3;
    wire n3_stb;

    table1_lite #(.DT(1000)) dut (
        .clk(clk), .rst(rst), .a(a), .b(b), .n3(n3), .n3_stb(n3_stb)
    );

    always #5 clk = ~clk;

    initial begin
        repeat (20) @(posedge clk);
        rst <= 1'b0;
    end

    function real speed;
        input integer k;
        begin
            case (k)
                0: speed = 0.37;
                1: speed = 0.8;
                2: speed = 1.6;
                3: speed = 3.3;
                4: speed = 7.9;
                5: speed = 23.5;
                6: speed = 61.2;
                7: speed = -5.3;
                default: speed = 0.55;
            endcase
        end
    endfunction

    // An instant on (or rounded by the 1 ps precision onto) a clock edge would race with
    // the synchroniser's sampling; push such an instant 1.5 ps later.
    function real off_clock;
        input real t;
        real ps, r;
        begin
            ps = t * 1000.0;
            r = ps - 5000.0 * $floor(ps / 5000.0);
            off_clock = (r < 0.5 || r >= 4999.5) ? t + 0.0015 : t;
        end
    endfunction

    // The encoder's phase is theta lines; it lies in quarter q, [q/4, (q+1)/4]. Quarter
    // q mod 4 = 0: A high, B low; 1: both high; 2: A low, B high; 3: both low.
    reg [8*512-1:0] path;
    real t, t_end, t_edge, theta, v, rate, len;
    integer k, q, m;
    reg seg_done;

    task drive;
        begin
            m = ((q % 4) + 4) % 4;
            a = (m == 0 || m == 1);
            b = (m == 1 || m == 2);
        end
    endtask

    initial begin
        if (!$value$plusargs("vcd=%s", path))
            $fatal(1, "give the VCD file: +vcd=<path>");
        $dumpfile(path);
        $dumpvars(1, tb.dut);

        theta = 0.9;
        q = 3;
        drive;
        t = 0.0;
        for (k = 0; k < NSEG; k = k + 1) begin
            v = speed(k);
            rate = v / DT_NS;  // lines per ns
            len = 12.0 / (v < 0.0 ? -v : v);
            len = DT_NS * (len > 30.0 ? len : 30.0);
            t_end = t + len;
            seg_done = 1'b0;
            while (!seg_done) begin
                if (v > 0.0)
                    t_edge = t + ((q + 1) / 4.0 - theta) / rate;
                else
                    t_edge = t + (q / 4.0 - theta) / rate;
                if (t_edge >= t_end) begin
                    theta = theta + rate * (t_end - t);
                    t = t_end;
                    seg_done = 1'b1;
                end else begin
                    #(off_clock(t_edge) - $realtime);
                    if (v > 0.0) begin
                        q = q + 1;
                        theta = q / 4.0;
                    end else begin
                        theta = q / 4.0;
                        q = q - 1;
                    end
                    t = t_edge;
                    drive;
                end
            end
        end
        #(t_end - $realtime);
        $finish;
    end
endmodule
