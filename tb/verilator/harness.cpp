// Verilator harness for the emitted encspeed_core.v.
//
// Stream mode (default): reads one line per clock cycle on stdin,
//   "reset enc_a enc_b enc_z cfg_dt cfg_timeout cfg_filter cfg_mode cfg_z_mode clear_faults"
// applies the inputs, gives one rising clock edge, and prints the outputs after the edge
// (speeds as raw unsigned port values; the Rust side sign-extends them),
//   "position z_latch index direction nep ndt update speed_n1 speed_n2 speed_n3
//    speed_strobe speed_pc speed_et speed_mt baseline_strobe valid stalled fault_illegal
//    fault_overspeed fault_revolution cfg_error glitch_count illegal_count rev_error_count
//    speed_position speed_nep speed_ndt mt_strobe mt_m mt_t mt_negative dt_active"
// exactly as golden::top::core::CoreModel::step does, so the Rust side compares line by line.
//
// Bench mode: "--bench CYCLES PERIOD DT" drives x1 quadrature (A, and B a quarter period
// behind) of PERIOD cycles with cfg_dt = DT for CYCLES cycles and prints "cycles seconds
// cycles_per_second checksum" (a benchmark, not a test).
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
            unsigned long long m = k % bench_period;
            top.enc_a = m < bench_period / 2;
            top.enc_b = ((m + bench_period - bench_period / 4) % bench_period) < bench_period / 2;
            top.clock = 0;
            top.eval();
            top.clock = 1;
            top.eval();
            checksum += top.speed_strobe;
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
        unsigned r, a, b, z, filter, mode, zmode, clear;
        unsigned long long dt, timeout;
        if (sscanf(line, "%u %u %u %u %llu %llu %u %u %u %u", &r, &a, &b, &z, &dt, &timeout,
                   &filter, &mode, &zmode, &clear) != 10) {
            fprintf(stderr, "bad input line %llu: %s", cycle, line);
            return 2;
        }
        top.reset = r;
        top.enc_a = a;
        top.enc_b = b;
        top.enc_z = z;
        top.cfg_dt = dt;
        top.cfg_timeout = timeout;
        top.cfg_filter = filter;
        top.cfg_mode = mode;
        top.cfg_z_mode = zmode;
        top.clear_faults = clear;
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
        typedef unsigned long long u;
        printf("%llu %llu %u %u %llu %llu %u %llu %llu %llu %u %llu %llu %llu %u %u %u %u %u %u %u "
               "%u %u %u %llu %llu %llu %u %llu %llu %u %llu\n",
               (u)top.position, (u)top.z_latch, (unsigned)top.index, (unsigned)top.direction,
               (u)top.nep, (u)top.ndt, (unsigned)top.update, (u)top.speed_n1, (u)top.speed_n2,
               (u)top.speed_n3, (unsigned)top.speed_strobe, (u)top.speed_pc, (u)top.speed_et,
               (u)top.speed_mt, (unsigned)top.baseline_strobe, (unsigned)top.valid,
               (unsigned)top.stalled, (unsigned)top.fault_illegal, (unsigned)top.fault_overspeed,
               (unsigned)top.fault_revolution, (unsigned)top.cfg_error, (unsigned)top.glitch_count,
               (unsigned)top.illegal_count, (unsigned)top.rev_error_count,
               (u)top.speed_position, (u)top.speed_nep, (u)top.speed_ndt,
               (unsigned)top.mt_strobe, (u)top.mt_m, (u)top.mt_t, (unsigned)top.mt_negative,
               (u)top.dt_active);
        ++cycle;
    }
#if VM_TRACE
    if (tfp) tfp->close();
#endif
    top.final();
    return 0;
}
