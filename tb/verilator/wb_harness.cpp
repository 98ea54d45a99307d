// Verilator harness for the emitted encspeed_wb.v (the core behind its Wishbone register
// file).
//
// Stream mode (the only mode): reads one line per clock cycle on stdin,
//   "reset enc_a enc_b enc_z wb_cyc_i wb_stb_i wb_we_i wb_adr_i wb_dat_i wb_sel_i"
// (all decimal), applies the inputs, gives one rising clock edge, and prints the outputs
// after the edge,
//   "wb_ack_o wb_dat_o irq"
// exactly as golden::top::wb_top::WbTopModel::step does, so the Rust side compares line by line.
//
// Optional "--vcd PATH" writes a VCD of every signal of the emitted Verilog.
#include "Vencspeed_wb.h"
#include "verilated.h"
#if VM_TRACE
#include "verilated_vcd_c.h"
#endif
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    VerilatedContext ctx;
    Vencspeed_wb top{&ctx};
    const char* vcd_path = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--vcd") && i + 1 < argc) {
            vcd_path = argv[++i];
        } else {
            fprintf(stderr, "usage: %s [--vcd PATH]\n", argv[0]);
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
    top.clock = 0;
    top.eval();
    static char out_buf[1 << 16];
    setvbuf(stdout, out_buf, _IOFBF, sizeof out_buf);
    char line[256];
    unsigned long long cycle = 0;
    while (fgets(line, sizeof line, stdin)) {
        unsigned r, a, b, z, cyc, stb, we, adr, sel;
        unsigned long dat;
        if (sscanf(line, "%u %u %u %u %u %u %u %u %lu %u", &r, &a, &b, &z, &cyc, &stb, &we,
                   &adr, &dat, &sel) != 10) {
            fprintf(stderr, "bad input line %llu: %s", cycle, line);
            return 2;
        }
        top.reset = r;
        top.enc_a = a;
        top.enc_b = b;
        top.enc_z = z;
        top.wb_cyc_i = cyc;
        top.wb_stb_i = stb;
        top.wb_we_i = we;
        top.wb_adr_i = adr;
        top.wb_dat_i = (uint32_t)dat;
        top.wb_sel_i = sel;
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
        printf("%u %lu %u\n", (unsigned)top.wb_ack_o, (unsigned long)top.wb_dat_o,
               (unsigned)top.irq);
        ++cycle;
    }
#if VM_TRACE
    if (tfp) tfp->close();
#endif
    top.final();
    return 0;
}
