// SPDX-License-Identifier: MIT OR Apache-2.0
// Eccentric encoder disc at constant speed, for `encspeed identify --vcd`
// (tests/identify_cli.rs). It writes enc_a, enc_b, enc_z to eccentric_disc.vcd in the
// working directory; every edge instant is computed here, in Verilog real arithmetic, from
// the rigid-disc law, so the truth of the identification test (e, theta0) comes from this
// file and the plusargs, not from the Rust code under test.
//
// Law (docs/eccentricity.md, "Conventions"): a rigid disc whose centre is e*R off the
// shaft, read by a fixed head at radius R. Disc position x (lines) is the apparent disc
// angle phi = 2*pi*x/K; the head sees apparent phase psi' = phi + theta0 (theta0 = the
// apparent phase of the Z line, x = 0). The sine rule in the triangle shaft - disc centre -
// head gives the shaft phase psi = psi' - asin(e*sin(psi')), and the shaft angle is
// theta = psi - theta0. At constant speed w (rad/s) the head reaches x at
// t(x) = (theta(x) - theta(x_start))/w.
//
// Levels: A high iff frac(x) in [0, 1/2), B iff frac(x) in [1/4, 3/4), Z iff
// (x mod K) in [1/4, 1/2): each changes at a quarter line q = m/4 (forward: m = 0 mod 4
// A rises, 1 B rises, 2 A falls, 3 B falls; Z rises at m = 1 and falls at m = 2 mod 4K).
//
// Defines (iverilog -D): LINES (K), E_REL (e), THETA0_DEG, RPM, REVS (revolutions of disc
// position simulated after the start at x = -1.2 lines).
`timescale 1ps / 1ps

module eccentric_disc_tb;
  reg enc_a = 1'b0;  // frac(-1.2) = 0.8: A and B low, Z low
  reg enc_b = 1'b0;
  reg enc_z = 1'b0;

  localparam real PI = 3.14159265358979323846;
  localparam integer K = `LINES;
  localparam real E = `E_REL;
  localparam real THETA0 = `THETA0_DEG * PI / 180.0;
  localparam real W = `RPM * 2.0 * PI / 60.0;  // rad/s
  localparam real X_START = -1.2;

  // Shaft angle (rad) at which the head sees disc position x (lines).
  function real shaft_angle(input real x);
    real psi_app;
    begin
      psi_app = 2.0 * PI * x / K + THETA0;
      shaft_angle = psi_app - $asin(E * $sin(psi_app)) - THETA0;
    end
  endfunction

  integer m, m_end, q4, qz;
  real t_s;
  reg [63:0] t_ps;

  initial begin
    $dumpfile("eccentric_disc.vcd");
    $dumpvars(1, enc_a, enc_b, enc_z);
    // Quarter levels m/4 with X_START < m/4 <= X_START + REVS*K; floor(4*X_START) = -5.
    m_end = $rtoi(4.0 * (X_START + `REVS * K));
    for (m = -4; m <= m_end; m = m + 1) begin
      t_s = (shaft_angle(m / 4.0) - shaft_angle(X_START)) / W;
      t_ps = t_s * 1.0e12;  // real to integer rounds to the nearest ps
      #(t_ps - $time);
      q4 = ((m % 4) + 4) % 4;
      qz = ((m % (4 * K)) + 4 * K) % (4 * K);
      case (q4)
        0: enc_a = 1'b1;
        1: enc_b = 1'b1;
        2: enc_a = 1'b0;
        default: enc_b = 1'b0;
      endcase
      if (qz == 1) enc_z = 1'b1;
      if (qz == 2) enc_z = 1'b0;
    end
    #1000;
    $display("eccentric_disc_tb: %0d quarter-line edges, last at %0d ps", m_end + 5, t_ps);
    $finish;
  end
endmodule
