# SPDX-License-Identifier: MIT OR Apache-2.0
# nextpnr-ice40 pre-pack script for encspeed_core (used by `encspeed synth`).
# Board: none (the core alone, I/O placed by the tool); part: any iCE40 nextpnr supports.
# Clock: `clock` at 100 MHz, the default clock_hz of the generator. Change it to your
# clock when you synthesise with another --clock-hz.
ctx.addClock("clock", 100)
