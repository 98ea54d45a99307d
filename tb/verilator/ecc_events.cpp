// SPDX-License-Identifier: MIT OR Apache-2.0
// The event mode of encspeed_ecc's harness (a part of it: see stream_main.cpp), for runs of
// hundreds of millions of cycles (a revolution at 30 r/min is 2e8 cycles at 100 MHz) that
// the stream mode would print line by line (tb::ecc_verilator::EccVerilated::run_events).
//
// "--events CYCLES ARM_DELAY" reads one line of inputs in the stream mode's form (the
// configuration, held throughout), then lines "k a b z" (the levels of A, B, Z from cycle k
// on, k increasing). It runs CYCLES cycles with reset for the first 3, raises ident_arm for
// one cycle ARM_DELAY cycles after the first index (ARM_DELAY < 0: never), and prints, in
// the stream mode's form of the outputs, "I k OUTPUTS" in the cycle k in which ident_done
// rises and "k OUTPUTS" for every cycle k in which a speed strobe is high.
#include <cstdlib>

#define MODE_FLAG "--events"
#define MODE_ARGS 2
#define MODE_USAGE " | --events CYCLES ARM_DELAY"

static int mode(Top& top, char** args) {
    u cycles = strtoull(args[0], nullptr, 10);
    long long arm_delay = strtoll(args[1], nullptr, 10);
    char line[LINE_CHARS];
    if (!fgets(line, sizeof line, stdin) || !read_inputs(top, line)) {
        fprintf(stderr, "--events: no configuration line\n");
        return 2;
    }
    long long arm_at = -1;
    bool was_done = false;
    u next_k = 0;
    unsigned a = 0, b = 0, z = 0;
    bool have = scanf("%llu %u %u %u", &next_k, &a, &b, &z) == 4;
    for (u k = 0; k < cycles; ++k) {
        while (have && next_k <= k) {
            top.enc_a = a;
            top.enc_b = b;
            top.enc_z = z;
            have = scanf("%llu %u %u %u", &next_k, &a, &b, &z) == 4;
        }
        top.reset = k < 3;
        top.ident_arm = arm_at >= 0 && (u)arm_at == k;
        top.clock = 0;
        top.eval();
        top.clock = 1;
        top.eval();
        if (top.index && arm_at < 0 && arm_delay >= 0) arm_at = (long long)k + 1 + arm_delay;
        if (top.ident_done && !was_done) {
            printf("I %llu ", k);
            print_outputs(top);
        }
        was_done = top.ident_done;
        if (top.baseline_strobe || top.mtc_strobe || top.speed_strobe || top.n3c_strobe) {
            printf("%llu ", k);
            print_outputs(top);
        }
    }
    return 0;
}
