// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::emit::tops`.

use golden::params::Params;
use golden::params::Spec;
use hdl::emit::tops::*;

/// Each top's Verilog file is first among its files, is named after its module, and
/// declares that module; the ECC tops are refused, with the reason, for a line count
/// the sine table cannot take.
#[test]
fn files_are_named_after_their_modules() {
    let p = Params::new(Spec {
        lines: 16,
        counter_bits: 10,
        dt_cycles: 200,
        clock_hz: 1e6,
        timeout_s: 0.1,
        ..Spec::default()
    })
    .unwrap();
    for top in Top::ALL {
        let files = top.files(&p).unwrap();
        assert_eq!(files[0].0, top.verilog_file());
        assert!(
            files[0].1.contains(&format!("module {}", top.module())),
            "{} does not declare module {}",
            files[0].0,
            top.module()
        );
    }
    let odd = Params::new(Spec {
        lines: 10,
        counter_bits: 10,
        dt_cycles: 200,
        clock_hz: 1e6,
        timeout_s: 0.1,
        ..Spec::default()
    })
    .unwrap();
    for top in Top::ALL {
        assert_eq!(top.check(&odd).is_err(), top.has_ecc(), "{top:?}");
        assert_eq!(top.files(&odd).is_err(), top.has_ecc(), "{top:?}");
    }
}
