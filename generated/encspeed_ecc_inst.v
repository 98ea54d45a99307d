// Command: encspeed generate --clock-hz 100000000 --lines 1024 --dt-cycles 100000 --counter-bits 24 --timeout-s 1
// SPDX-License-Identifier: MIT OR Apache-2.0
// encspeed_ecc_inst.v: instantiation template of encspeed_ecc (encspeed_ecc.v). Do not edit:
// copy it into your design and rename the instance and the signals.
// Generated for clock_hz = 100000000, lines = 1024, dt_cycles = 100000, counter_bits = 24, timeout_s = 1, estimators = n1,n2,n3,pc,et,mt: see encspeed_ecc.toml for the latencies and the error budget.
// enc_a, enc_b, enc_z may be asynchronous (synchronised inside by two flip-flops); every other port is synchronous to the rising edge of clock; reset is synchronous and active high.
// cfg_* are sampled at every edge: tie them to constants or drive them from registers (0 on cfg_dt and cfg_timeout selects the generated defaults).
encspeed_ecc u_encspeed_ecc (
    .clock            (clock           ), // input: core clock; everything happens at its rising edge
    .reset            (reset           ), // input: synchronous, active high, registered: the core resets at the edge after each edge that samples it high (and at the first edge after power-up)
    .enc_a            (enc_a           ), // input: encoder channel A, asynchronous (two-flop synchronised inside)
    .enc_b            (enc_b           ), // input: encoder channel B, asynchronous; forward = A leads B by 90 degrees
    .enc_z            (enc_z           ), // input: encoder index Z, asynchronous
    .cfg_dt           (cfg_dt          ), // input [23:0]: dt in clock cycles (Rairan's time base and the PC/M/T window); 0 = the generation default dt_cycles, 1 = used as 2 and flags cfg_error; registered: dt_active shows a change one edge later, the dt windows use it from the edge after that
    .cfg_timeout      (cfg_timeout     ), // input [23:0]: zero-speed timeout in dt intervals; 0 = the generation default; registered: stalled and valid, themselves registered, show a new timeout from the edge after the one that samples it
    .cfg_filter       (cfg_filter      ), // input [15:0]: glitch filter length in clock cycles on A, B and Z (a level must be seen this many cycles to pass); 0 = off; registered (acts one edge later)
    .cfg_mode         (cfg_mode        ), // input [1:0]: decoding: 0 = x1 (A edge while B low), 1 = x2 (A edges), 2 = x4 (A and B edges); 3 = x4 and cfg_error. Registered: a change resets the whole core (as reset) at the edge after the one that samples it, with the new mode in place
    .cfg_z_mode       (cfg_z_mode      ), // input [1:0]: index: 0 = ignore, 1 = a Z edge resets the position, 2 = latches it into z_latch, 3 = latch then reset; registered (acts one edge later)
    .clear_faults     (clear_faults    ), // input: clears fault_illegal, fault_overspeed, fault_revolution (an event in the same cycle wins)
    .position         (position        ), // output [31:0]: position in decoder steps, 0 .. lines*2^s - 1 (s = 0, 1, 2 in x1, x2, x4); wraps at a revolution, which is its definition
    .z_latch          (z_latch         ), // output [31:0]: position latched at the last index edge (cfg_z_mode 2, 3)
    .index            (index           ), // output: one cycle: an index edge was processed
    .direction        (direction       ), // output: direction of the last step: 1 = forward
    .nep              (nep             ), // output [23:0]: Nep1 of Rairan's Table 1, in decoder steps; 0 after reset or a reversal
    .ndt              (ndt             ), // output [23:0]: Ndt1 of Rairan's Table 1, dt intervals; 1 after reset or a reversal
    .update           (update          ), // output: one cycle: nep or ndt has just been written
    .speed_n1         (speed_n1        ), // output [40:0]: Rairan n1 = Nep/Ndt, two's complement, speed_frac_bits fractional bits, units of omega_lim (one line per dt)
    .speed_n2         (speed_n2        ), // output [40:0]: Rairan n2, eq. (6); format as speed_n1
    .speed_n3         (speed_n3        ), // output [40:0]: Rairan n3, eq. (11): the estimate to use; format as speed_n1; negative = backward
    .speed_strobe     (speed_strobe    ), // output: one cycle: speed_n1, speed_n2, speed_n3 have just been written
    .speed_pc         (speed_pc        ), // output [40:0]: fixed-time (pulse count) speed of the last cfg_dt window; format as speed_n1
    .speed_et         (speed_et        ), // output [40:0]: fixed-space (elapsed time) speed dt/period of the last period at the window end; 0 before a period of the current direction; format as speed_n1
    .speed_mt         (speed_mt        ), // output [40:0]: M/T speed: steps of the window over the exact clock count spanning them, times dt; 0 for a window without steps; format as speed_n1
    .baseline_strobe  (baseline_strobe ), // output: one cycle: speed_pc, speed_et, speed_mt have just been written
    .valid            (valid           ), // output: speed_n3 is a measurement of the current direction (one since reset or the last reversal), not stalled, legal configuration; a register, one edge after those conditions
    .stalled          (stalled         ), // output: no step for the zero-speed timeout: the speed is below one step per timeout; a register, one edge after Cdt reaches the timeout
    .fault_illegal    (fault_illegal   ), // output: sticky: A and B changed between two samples (an illegal transition)
    .fault_overspeed  (fault_overspeed ), // output: sticky: the A or B filter rejected a level shorter than cfg_filter cycles (a glitch, or edges closer than the filter can pass)
    .fault_revolution (fault_revolution), // output: sticky: a revolution of one direction between two index edges had a count other than lines*2^s
    .cfg_error        (cfg_error       ), // output: cfg_dt = 1 or cfg_mode = 3 at the last edge
    .glitch_count     (glitch_count    ), // output [15:0]: pulses rejected by the A, B and Z filters since reset, saturating
    .illegal_count    (illegal_count   ), // output [15:0]: illegal transitions since reset, saturating
    .rev_error_count  (rev_error_count ), // output [15:0]: revolutions with a wrong count since reset, saturating
    .speed_position   (speed_position  ), // output [31:0]: with speed_strobe, held: the end of the span of disc the speeds measure: for nep = 1 the position of the restart pulse that wrote ndt, for nep >= 2 that of the last pulse of the window that wrote nep (which started nep - 1 steps before it); for an eccentricity correction; 0 after reset or a reversal
    .speed_nep        (speed_nep       ), // output [23:0]: with speed_strobe, held: the nep the speeds were computed from
    .speed_ndt        (speed_ndt       ), // output [23:0]: with speed_strobe, held: the ndt the speeds were computed from
    .mt_strobe        (mt_strobe       ), // output: one cycle: the M/T counter closed a window; mt_m, mt_t, mt_negative were just written and position in this cycle is that of the window's last step; speed_mt follows at baseline_strobe
    .mt_m             (mt_m            ), // output [23:0]: M/T: steps of the last window (0: none)
    .mt_t             (mt_t            ), // output [23:0]: M/T: clock cycles from the step before the window's first to its last (mt_m > 0), else cycles since the last step
    .mt_negative      (mt_negative     ), // output: M/T: the last window's steps were backward
    .dt_active        (dt_active       ), // output [23:0]: the dt in use, clock cycles: cfg_dt after its default and minimum, registered
    .ecc_c            (ecc_c           ), // input [31:0]: eccentricity coefficient c = E cos(theta0), two's complement Q15.16 in lines (E = lines * e / 2pi, e = disc centre offset / disc radius); sampled at each mt_strobe and speed_strobe for the correction of that estimate
    .ecc_d            (ecc_d           ), // input [31:0]: eccentricity coefficient d = E sin(theta0), Q15.16 lines
    .speed_mtc        (speed_mtc       ), // output [40:0]: M/T speed of each window corrected for the eccentricity; format as speed_mt; needs cfg_z_mode = 1 or 3 (position counted from line 0)
    .mtc_strobe       (mtc_strobe      ), // output: one cycle: speed_mtc has just been written
    .speed_n3c        (speed_n3c       ), // output [40:0]: Rairan n3 corrected for the eccentricity; format as speed_n3; needs cfg_z_mode = 1 or 3
    .n3c_strobe       (n3c_strobe      ), // output: one cycle: speed_n3c has just been written
    .ident_arm        (ident_arm       ), // input: one-cycle pulse: gather the next revolution (index to index) for the eccentricity identification (cfg_z_mode = 1 or 3, forward at constant speed); an arm before the first index since reset or a cfg_mode change is held until that index, which aligns the position, and takes effect there, so the revolution gathered is the one from the second index to the third; ident_done clears when the arm takes effect. In a build without the identification (generate --no-identification) it does nothing and every ident_* output reads 0
    .ident_done       (ident_done      ), // output: the ident_* results are complete: rises 2 edges after the edge that raised the closing index; sticky until the next arm takes effect
    .ident_overflow   (ident_overflow  ), // output: more than 2^16 lines between the index pulses (contract broken, extra lines dropped)
    .ident_count      (ident_count     ), // output [16:0]: forward lines gathered N (lines per revolution for a clean revolution)
    .ident_t_min      (ident_t_min     ), // output [31:0]: shortest line period, clock cycles (Zhao's T_min)
    .ident_p_min      (ident_p_min     ), // output [15:0]: line number of the edge that closed it (first on ties)
    .ident_t_max      (ident_t_max     ), // output [31:0]: longest line period, clock cycles (Zhao's T_max)
    .ident_p_max      (ident_p_max     ), // output [15:0]: line number of the edge that closed it (first on ties)
    .ident_sum_t      (ident_sum_t     ), // output [71:0]: sum of the line periods T, clock cycles (the revolution's length)
    .ident_sum_sin    (ident_sum_sin   ), // output [71:0]: sum of T * round(Q sin(2 pi p / lines)), two's complement, Q = 2^23 - 1, p the line number of the edge closing T
    .ident_sum_cos    (ident_sum_cos   )  // output [71:0]: sum of T * round(Q cos(2 pi p / lines)), two's complement; e and theta0 from the three sums: golden::ecc::ident_gatherer::identify_from_sums (docs/eccentricity-hardware.md)
);
