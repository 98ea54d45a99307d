// SPDX-License-Identifier: MIT OR Apache-2.0
//! Unit tests of `hdl::emit::prefix`.

use hdl::emit::prefix::*;

#[test]
fn prefixes_are_validated() {
    assert_eq!(Prefix::new("").unwrap(), Prefix::none());
    assert_eq!(Prefix::new("acme_").unwrap().as_str(), "acme_");
    assert_eq!(Prefix::new("_x9").unwrap().as_str(), "_x9");
    for bad in ["9a_", "a-b", "a$b", "a b", "é_", &"a".repeat(33)] {
        let e = Prefix::new(bad).unwrap_err();
        assert!(e.contains("--prefix"), "{bad}: {e}");
    }
}

#[test]
fn only_words_that_start_with_the_stem_are_prefixed() {
    let p = Prefix::new("acme_").unwrap();
    let text = "// Command: encspeed generate --lines 8\n\
                module encspeed_core$baseline(x);\n\
                encspeed_core$baseline baseline(.x(my_encspeed_x));\n\
                #define ENCSPEED_ID 1u /* see encspeed_regs.h, encspeed-golden */\n\
                -file \"*encspeed_core.v\"";
    assert_eq!(
        p.apply(text, "encspeed generate --lines 8"),
        "// Command: encspeed generate --lines 8 --prefix acme_\n\
         module acme_encspeed_core$baseline(x);\n\
         acme_encspeed_core$baseline baseline(.x(my_encspeed_x));\n\
         #define ACME_ENCSPEED_ID 1u /* see acme_encspeed_regs.h, encspeed-golden */\n\
         -file \"*acme_encspeed_core.v\""
    );
    assert_eq!(Prefix::none().apply(text, "x"), text);
}
