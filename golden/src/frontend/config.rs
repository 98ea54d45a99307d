// SPDX-License-Identifier: MIT OR Apache-2.0
//! The front end's configuration values (`cfg_mode`, `cfg_z_mode`) and the register-width
//! rules its models share: widths 1..=32, counters that saturate rather than wrap.

/// `cfg_mode` value: x1, one step per line, at the A edge while B is low.
pub const MODE_X1: u8 = 0;
/// `cfg_mode` value: x2, one step per A edge.
pub const MODE_X2: u8 = 1;
/// `cfg_mode` value: x4, one step per A or B edge.
pub const MODE_X4: u8 = 2;
/// `cfg_mode` value that is not a mode: decoded as x4, flagged on `mode_error`.
pub const MODE_INVALID: u8 = 3;

/// `cfg_z_mode` value: the index does nothing (no reset, no latch, no revolution check).
pub const Z_MODE_IGNORE: u8 = 0;
/// `cfg_z_mode` value: a rising index edge sets the position to 0.
pub const Z_MODE_RESET: u8 = 1;
/// `cfg_z_mode` value: a rising index edge copies the position into `z_latch`.
pub const Z_MODE_LATCH: u8 = 2;
/// `cfg_z_mode` value: a rising index edge latches the position, then sets it to 0.
pub const Z_MODE_LATCH_RESET: u8 = 3;

/// Widest register any front-end model accepts (bits).
pub const MAX_BITS: u32 = 32;

pub(crate) fn max_of(bits: u32) -> u64 {
    assert!(
        (1..=MAX_BITS).contains(&bits),
        "register width {bits} outside 1..={MAX_BITS}"
    );
    (1u64 << bits) - 1
}

pub(crate) fn sat_inc(v: u64, max: u64) -> u64 {
    if v >= max {
        max
    } else {
        v + 1
    }
}
