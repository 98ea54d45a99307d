// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::bus::irq_cell`.

use hdl::bus::irq_cell::*;

#[test]
fn synthesises_and_lints_clean() {
    let (map, _) = crate::support::maps();
    let cell = IrqCell::new(map.reg("IRQ_ENABLE"), map.reg("IRQ_STATUS"));
    crate::support::synthesises_and_lints("encspeed_irq_cell", cell);
}
