// Verilator harness for the emitted encspeed_core.v.
//
// Stream mode (default): reads one line per clock cycle on stdin,
//   "reset enc_a enc_b enc_z cfg_dt"
// applies the inputs, gives one rising clock edge, and prints the outputs after the edge,
//   "nep ndt update stalled cfg_error"
// exactly as golden::bittrue::CoreModel::step does, so the Rust side compares line by line.
//
// Bench mode: "--bench CYCLES PERIOD DT" drives a square wave on enc_a of PERIOD cycles with
// cfg_dt = DT for CYCLES cycles and prints "cycles seconds cycles_per_second" (a benchmark,
// not a test).
//
// Optional "--vcd PATH" (stream mode) writes a VCD of every signal of the emitted Verilog.
#include "Vencspeed_core.h"
#include "verilated.h"
#if VM_TRACE
#include "verilated_vcd_c.h"
#endif
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

int main(int argc, char** argv) {
    VerilatedContext ctx;
    Vencspeed_core top{&ctx};
    const char* vcd_path = nullptr;
    bool bench = false;
    unsigned long long bench_cycles = 0, bench_period = 0, bench_dt = 0;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--vcd") && i + 1 < argc) {
            vcd_path = argv[++i];
        } else if (!strcmp(argv[i], "--bench") && i + 3 < argc) {
            bench = true;
            bench_cycles = strtoull(argv[++i], nullptr, 10);
            bench_period = strtoull(argv[++i], nullptr, 10);
            bench_dt = strtoull(argv[++i], nullptr, 10);
        } else {
            fprintf(stderr, "usage: %s [--vcd PATH] | --bench CYCLES PERIOD DT\n", argv[0]);
            return 2;
        }
    }
    top.clock = 0;
    top.eval();
    if (bench) {
        if (bench_period < 2) {
            fprintf(stderr, "PERIOD must be >= 2\n");
            return 2;
        }
        top.cfg_dt = bench_dt;
        top.reset = 1;
        top.clock = 1;
        top.eval();
        top.clock = 0;
        top.reset = 0;
        top.eval();
        unsigned long long checksum = 0;
        auto t0 = std::chrono::steady_clock::now();
        for (unsigned long long k = 0; k < bench_cycles; ++k) {
            top.enc_a = (k % bench_period) < bench_period / 2;
            top.clock = 0;
            top.eval();
            top.clock = 1;
            top.eval();
            checksum += top.update;
        }
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        printf("%llu %.6f %.0f %llu\n", bench_cycles, s, bench_cycles / s, checksum);
        return 0;
    }
#if VM_TRACE
    VerilatedVcdC* tfp = nullptr;
    if (vcd_path) {
        ctx.traceEverOn(true);
        tfp = new VerilatedVcdC;
        top.trace(tfp, 99);
        tfp->open(vcd_path);
    }
#else
    if (vcd_path) {
        fprintf(stderr, "harness built without --trace\n");
        return 2;
    }
#endif
    static char out_buf[1 << 16];
    setvbuf(stdout, out_buf, _IOFBF, sizeof out_buf);
    char line[256];
    unsigned long long cycle = 0;
    while (fgets(line, sizeof line, stdin)) {
        unsigned r, a, b, z;
        unsigned long long dt;
        if (sscanf(line, "%u %u %u %u %llu", &r, &a, &b, &z, &dt) != 5) {
            fprintf(stderr, "bad input line %llu: %s", cycle, line);
            return 2;
        }
        top.reset = r;
        top.enc_a = a;
        top.enc_b = b;
        top.enc_z = z;
        top.cfg_dt = dt;
        top.clock = 0;
        top.eval();
#if VM_TRACE
        if (tfp) tfp->dump((uint64_t)(cycle * 10 + 5));
#endif
        top.clock = 1;
        top.eval();
#if VM_TRACE
        if (tfp) tfp->dump((uint64_t)(cycle * 10 + 10));
#endif
        printf("%llu %llu %u %u %u\n", (unsigned long long)top.nep, (unsigned long long)top.ndt,
               (unsigned)top.update, (unsigned)top.stalled, (unsigned)top.cfg_error);
        ++cycle;
    }
#if VM_TRACE
    if (tfp) tfp->close();
#endif
    top.final();
    return 0;
}
