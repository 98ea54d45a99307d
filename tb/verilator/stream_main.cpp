// SPDX-License-Identifier: MIT OR Apache-2.0
// The part of every Verilator harness that does not depend on the top's ports. The harness
// is this file after the part tb::verilator::harness generates from the top's port list
// (golden::top::ports): the type `Top`, `u`, `LINE_CHARS`, `read_inputs` (one line of inputs,
// false if malformed) and `print_outputs` (one line of outputs), then the top's optional
// extra mode (MODE_FLAG, MODE_ARGS, MODE_USAGE and `mode(top, args)`, e.g. core_bench.cpp).
//
// Stream mode (default): reads one line of inputs per clock cycle on stdin, applies them,
// gives one rising clock edge and prints the outputs after the edge, one line per cycle, so
// the Rust side compares them with the golden model line by line.
// Optional "--vcd PATH" (stream mode) writes a VCD of every signal of the emitted Verilog.
// Optional "--line" flushes each line of outputs as soon as it is printed, so a caller can
// answer each cycle's outputs with the next cycle's inputs (an interactive session: the host
// program's bench, tb/tests/board/monitor.rs); without it, outputs go out in 64 KiB blocks.
#include "verilated.h"
#if VM_TRACE
#include "verilated_vcd_c.h"
#endif
#include <cstring>

#ifndef MODE_USAGE
#define MODE_USAGE ""
#endif

static int stream(VerilatedContext& ctx, Top& top, const char* vcd_path, bool line_mode) {
#if VM_TRACE
    VerilatedVcdC* tfp = nullptr;
    if (vcd_path) {
        ctx.traceEverOn(true);
        tfp = new VerilatedVcdC;
        top.trace(tfp, 99);
        tfp->open(vcd_path);
    }
#else
    (void)ctx;
    if (vcd_path) {
        fprintf(stderr, "harness built without --trace\n");
        return 2;
    }
#endif
    char line[LINE_CHARS];
    u cycle = 0;
    while (fgets(line, sizeof line, stdin)) {
        if (!read_inputs(top, line)) {
            fprintf(stderr, "bad input line %llu: %s", cycle, line);
            return 2;
        }
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
        print_outputs(top);
        if (line_mode) fflush(stdout);
        ++cycle;
    }
#if VM_TRACE
    if (tfp) tfp->close();
#endif
    top.final();
    return 0;
}

int main(int argc, char** argv) {
    VerilatedContext ctx;
    Top top{&ctx};
    top.clock = 0;
    top.eval();
    static char out_buf[1 << 16];
    setvbuf(stdout, out_buf, _IOFBF, sizeof out_buf);
    const char* vcd_path = nullptr;
    bool line_mode = false;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--vcd") && i + 1 < argc) {
            vcd_path = argv[++i];
        } else if (!strcmp(argv[i], "--line")) {
            line_mode = true;
#ifdef MODE_FLAG
        } else if (!strcmp(argv[i], MODE_FLAG) && i + MODE_ARGS < argc) {
            int rc = mode(top, argv + i + 1);
            top.final();
            return rc;
#endif
        } else {
            fprintf(stderr, "usage: %s [--vcd PATH] [--line]%s\n", argv[0], MODE_USAGE);
            return 2;
        }
    }
    return stream(ctx, top, vcd_path, line_mode);
}
