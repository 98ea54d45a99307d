# SPDX-License-Identifier: MIT OR Apache-2.0
# Timing constraints for encspeed_core (SDC, for vendor tools: Vivado/Quartus/Libero/Radiant).
# Part: any. Clock: `clock`, 100 MHz (the generator's default clock_hz; edit to match).
create_clock -name clock -period 10.000 [get_ports clock]

# Encoder channels are asynchronous to `clock`; each goes first through a two-flop
# synchroniser (encspeed_core$sync_a), so no timing path from these ports is meaningful.
set_false_path -from [get_ports {enc_a enc_b enc_z}]

# cfg_dt is registered inside the core (dt_limit); drive it from a register in the
# `clock` domain (or declare it static with a false path if it is set once at start-up).
