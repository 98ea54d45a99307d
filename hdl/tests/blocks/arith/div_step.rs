// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::arith::div_step`.

use golden::arith::div_step::div_step;
use hdl::arith::div_step::*;
use rust_hdl::prelude::*;

/// Every input at W = 5 (32 × 2 × 32) equals the model, in rust-hdl's simulation.
#[test]
fn every_input_at_five_bits_equals_the_model() {
    let mut uut = DivStep::<5>::default();
    uut.connect_all();
    let mut checked = 0;
    for rem in 0..32u64 {
        for bit in [false, true] {
            for den in 0..32u64 {
                uut.rem.next = rem.into();
                uut.bit_in.next = bit;
                uut.den.next = den.into();
                assert!(simulate(&mut uut, 10), "settles");
                let want = div_step(rem.into(), bit, den.into(), 5);
                let got = (u128::from(uut.next_rem.val().to_u64()), uut.fits.val());
                assert_eq!(got, want, "rem {rem} bit {bit} den {den}");
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 2048);
}

#[test]
fn synthesises_and_lints_clean() {
    crate::support::synthesises_and_lints("encspeed_div_step", DivStep::<49>::default());
    crate::support::synthesises_and_lints("encspeed_div_step_65", DivStep::<65>::default());
}
