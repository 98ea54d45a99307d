// Verilator harness for the emitted encspeed_ecc.v (the core with the corrected M/T).
//
// Stream mode (default): one line per clock cycle on stdin,
//   "reset enc_a enc_b enc_z cfg_dt cfg_timeout cfg_filter cfg_mode cfg_z_mode clear_faults
//    ecc_c ecc_d ident_arm"   (ecc_c, ecc_d as unsigned 32-bit port values)
// applies the inputs, gives one rising edge and prints the core's 32 outputs in the order of
// harness.cpp, then "speed_mtc mtc_strobe speed_n3c n3c_strobe" and the identification
// (IDENT below) (raw unsigned port values).
//
// Event mode: "--events CYCLES CFG_DT CFG_MODE CFG_Z_MODE ECC_C ECC_D ARM_DELAY" reads lines
// "k a b z" (levels of A, B, Z from cycle k on, k increasing), runs CYCLES cycles (reset for
// the first 3), raises ident_arm for one cycle ARM_DELAY cycles after the first index
// (ARM_DELAY < 0: never), and prints one line per cycle in which a speed strobe is high:
//   "cycle baseline_strobe speed_mt mtc_strobe speed_mtc speed_strobe speed_n3 n3c_strobe
//    speed_n3c position speed_nep speed_ndt"
// and, in the cycle ident_done rises, "I cycle IDENT"
// (the form of a long run: a revolution at 30 r/min is 2e8 cycles at 100 MHz).
//
// IDENT: "ident_done ident_overflow ident_count ident_t_min ident_p_min ident_t_max
// ident_p_max" then ident_sum_t, ident_sum_sin, ident_sum_cos as three 32-bit words each,
// least significant first (72-bit ports).
//
// Optional "--vcd PATH" (stream mode) writes a VCD of every signal.
#include "Vencspeed_ecc.h"
#include "verilated.h"
#if VM_TRACE
#include "verilated_vcd_c.h"
#endif
#include <cstdio>
#include <cstdlib>
#include <cstring>

typedef unsigned long long u;

static void edge(Vencspeed_ecc& top) {
    top.clock = 0;
    top.eval();
    top.clock = 1;
    top.eval();
}

static void print_ident(Vencspeed_ecc& top) {
    printf("%u %u %u %u %u %u %u", (unsigned)top.ident_done, (unsigned)top.ident_overflow,
           (unsigned)top.ident_count, (unsigned)top.ident_t_min, (unsigned)top.ident_p_min,
           (unsigned)top.ident_t_max, (unsigned)top.ident_p_max);
    for (int w = 0; w < 3; ++w) printf(" %u", (unsigned)top.ident_sum_t[w]);
    for (int w = 0; w < 3; ++w) printf(" %u", (unsigned)top.ident_sum_sin[w]);
    for (int w = 0; w < 3; ++w) printf(" %u", (unsigned)top.ident_sum_cos[w]);
    printf("\n");
}

static int events(Vencspeed_ecc& top, char** a) {
    u cycles = strtoull(a[0], nullptr, 10);
    top.cfg_dt = strtoull(a[1], nullptr, 10);
    top.cfg_mode = strtoull(a[2], nullptr, 10);
    top.cfg_z_mode = strtoull(a[3], nullptr, 10);
    top.ecc_c = strtoull(a[4], nullptr, 10);
    top.ecc_d = strtoull(a[5], nullptr, 10);
    long long arm_delay = strtoll(a[6], nullptr, 10);
    long long arm_at = -1;
    bool was_done = false;
    top.cfg_timeout = 0;
    top.cfg_filter = 0;
    top.clear_faults = 0;
    static char out_buf[1 << 16];
    setvbuf(stdout, out_buf, _IOFBF, sizeof out_buf);
    u next_k = 0;
    unsigned na = 0, nb = 0, nz = 0;
    bool have = false;
    auto read_next = [&]() {
        have = scanf("%llu %u %u %u", &next_k, &na, &nb, &nz) == 4;
    };
    read_next();
    for (u k = 0; k < cycles; ++k) {
        while (have && next_k <= k) {
            top.enc_a = na;
            top.enc_b = nb;
            top.enc_z = nz;
            read_next();
        }
        top.reset = k < 3;
        top.ident_arm = arm_at >= 0 && (u)arm_at == k;
        edge(top);
        if (top.index && arm_at < 0 && arm_delay >= 0) arm_at = (long long)k + 1 + arm_delay;
        if (top.ident_done && !was_done) {
            printf("I %llu ", k);
            print_ident(top);
        }
        was_done = top.ident_done;
        if (top.baseline_strobe || top.mtc_strobe || top.speed_strobe || top.n3c_strobe) {
            printf("%llu %u %llu %u %llu %u %llu %u %llu %llu %llu %llu\n", k,
                   (unsigned)top.baseline_strobe, (u)top.speed_mt, (unsigned)top.mtc_strobe,
                   (u)top.speed_mtc, (unsigned)top.speed_strobe, (u)top.speed_n3,
                   (unsigned)top.n3c_strobe, (u)top.speed_n3c, (u)top.position,
                   (u)top.speed_nep, (u)top.speed_ndt);
        }
    }
    return 0;
}

int main(int argc, char** argv) {
    VerilatedContext ctx;
    Vencspeed_ecc top{&ctx};
    const char* vcd_path = nullptr;
    top.clock = 0;
    top.eval();
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--vcd") && i + 1 < argc) {
            vcd_path = argv[++i];
        } else if (!strcmp(argv[i], "--events") && i + 7 < argc) {
            int rc = events(top, argv + i + 1);
            top.final();
            return rc;
        } else {
            fprintf(stderr, "usage: %s [--vcd PATH] | --events CYCLES DT MODE ZMODE C D ARM_DELAY\n",
                    argv[0]);
            return 2;
        }
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
    char line[320];
    u cycle = 0;
    while (fgets(line, sizeof line, stdin)) {
        unsigned r, a, b, z, filter, mode, zmode, clear, arm;
        u dt, timeout, c, d;
        if (sscanf(line, "%u %u %u %u %llu %llu %u %u %u %u %llu %llu %u", &r, &a, &b, &z, &dt,
                   &timeout, &filter, &mode, &zmode, &clear, &c, &d, &arm) != 13) {
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
        top.ecc_c = c;
        top.ecc_d = d;
        top.ident_arm = arm;
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
        printf("%llu %llu %u %u %llu %llu %u %llu %llu %llu %u %llu %llu %llu %u %u %u %u %u %u %u "
               "%u %u %u %llu %llu %llu %u %llu %llu %u %llu %llu %u %llu %u ",
               (u)top.position, (u)top.z_latch, (unsigned)top.index, (unsigned)top.direction,
               (u)top.nep, (u)top.ndt, (unsigned)top.update, (u)top.speed_n1, (u)top.speed_n2,
               (u)top.speed_n3, (unsigned)top.speed_strobe, (u)top.speed_pc, (u)top.speed_et,
               (u)top.speed_mt, (unsigned)top.baseline_strobe, (unsigned)top.valid,
               (unsigned)top.stalled, (unsigned)top.fault_illegal, (unsigned)top.fault_overspeed,
               (unsigned)top.fault_revolution, (unsigned)top.cfg_error, (unsigned)top.glitch_count,
               (unsigned)top.illegal_count, (unsigned)top.rev_error_count,
               (u)top.speed_position, (u)top.speed_nep, (u)top.speed_ndt,
               (unsigned)top.mt_strobe, (u)top.mt_m, (u)top.mt_t, (unsigned)top.mt_negative,
               (u)top.dt_active, (u)top.speed_mtc, (unsigned)top.mtc_strobe,
               (u)top.speed_n3c, (unsigned)top.n3c_strobe);
        print_ident(top);
        ++cycle;
    }
#if VM_TRACE
    if (tfp) tfp->close();
#endif
    top.final();
    return 0;
}
