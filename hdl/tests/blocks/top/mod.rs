// SPDX-License-Identifier: MIT OR Apache-2.0
mod core;
mod fault_flags;
mod mode_reset;
