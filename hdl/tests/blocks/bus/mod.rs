// SPDX-License-Identifier: MIT OR Apache-2.0
mod const_cell;
mod ecc_snapshot;
mod irq_cell;
mod pulse_cell;
mod read_cell;
mod read_data;
mod reg_file;
mod rw_cell;
mod shadow_cell;
mod wb_front;
mod wb_regs;
