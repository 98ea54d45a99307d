// SPDX-License-Identifier: MIT OR Apache-2.0
// The bench mode of encspeed_core's harness (a part of it: see stream_main.cpp), for
// `encspeed bench` (tb::verilator::Verilated::bench): a benchmark, not a test.
//
// "--bench CYCLES PERIOD DT" drives x1 quadrature (A, and B a quarter period behind) of
// PERIOD cycles with cfg_dt = DT for CYCLES cycles and prints
// "cycles seconds cycles_per_second checksum".
#include <chrono>
#include <cstdlib>

#define MODE_FLAG "--bench"
#define MODE_ARGS 3
#define MODE_USAGE " | --bench CYCLES PERIOD DT"

static int mode(Top& top, char** args) {
    u cycles = strtoull(args[0], nullptr, 10);
    u period = strtoull(args[1], nullptr, 10);
    u dt = strtoull(args[2], nullptr, 10);
    if (period < 2) {
        fprintf(stderr, "PERIOD must be >= 2\n");
        return 2;
    }
    top.cfg_dt = dt;
    top.reset = 1;
    top.clock = 1;
    top.eval();
    top.clock = 0;
    top.reset = 0;
    top.eval();
    u checksum = 0;
    auto t0 = std::chrono::steady_clock::now();
    for (u k = 0; k < cycles; ++k) {
        u m = k % period;
        top.enc_a = m < period / 2;
        top.enc_b = ((m + period - period / 4) % period) < period / 2;
        top.clock = 0;
        top.eval();
        top.clock = 1;
        top.eval();
        checksum += top.speed_strobe;
    }
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    printf("%llu %.6f %.0f %llu\n", cycles, s, cycles / s, checksum);
    return 0;
}
