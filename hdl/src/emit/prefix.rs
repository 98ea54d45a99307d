// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed generate --prefix acme_`: a name prefix for everything a generated file
//! declares, so that several configurations of the IP load into one design.
//!
//! Every name the generator gives starts with `encspeed_`: the top modules and, because
//! rust-hdl names a sub-module by its path from the top (`encspeed_core$baseline`), every
//! sub-module; the C headers' macros start with `ENCSPEED_` and their include guards with
//! it; the file names start with `encspeed_`. The prefix is put in front of each of those
//! names (upper-cased for the C macros) wherever one starts a word, in every generated file
//! and its name, and the files' first line gains `--prefix <prefix>`. Nothing else changes:
//! ports, parameters and behaviour are those of the unprefixed files. `tb/tests/prefix.rs`
//! proves two prefixed cores of different parameters lint and synthesise together and two
//! prefixed headers compile together.

use std::fmt;

/// The stem every generated name starts with.
const STEM: &str = "encspeed_";
/// The stem of the C headers' macros.
const MACRO_STEM: &str = "ENCSPEED_";
/// Longest prefix accepted (Verilog tools take far longer names; this keeps file names sane).
pub const MAX_PREFIX_LEN: usize = 32;

/// A validated name prefix: empty (no prefix), or a Verilog and C identifier start,
/// `[A-Za-z_][A-Za-z0-9_]*`, of at most [`MAX_PREFIX_LEN`] characters.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Prefix(String);

impl Prefix {
    /// No prefix: the shipped names.
    pub fn none() -> Prefix {
        Prefix(String::new())
    }

    /// `prefix`, or why it cannot prefix a Verilog module and a C macro.
    pub fn new(prefix: &str) -> Result<Prefix, String> {
        let bad = |why: &str| {
            Err(format!(
                "--prefix {prefix:?}: {why} (a prefix is a letter or '_' followed by letters, digits or '_', at most {MAX_PREFIX_LEN} characters, e.g. acme_)"
            ))
        };
        let mut chars = prefix.chars();
        match chars.next() {
            None => return Ok(Prefix::none()),
            Some(c) if !(c.is_ascii_alphabetic() || c == '_') => {
                return bad("it must start with a letter or '_'")
            }
            _ => {}
        }
        if let Some(c) = chars.find(|c| !(c.is_ascii_alphanumeric() || *c == '_')) {
            return bad(&format!("{c:?} is not allowed"));
        }
        if prefix.len() > MAX_PREFIX_LEN {
            return bad("it is too long");
        }
        Ok(Prefix(prefix.to_string()))
    }

    /// The prefix as given.
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// No prefix.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// A generated file's name under this prefix.
    pub fn file_name(&self, name: &str) -> String {
        format!("{}{name}", self.0)
    }

    /// A generated file's text under this prefix: `command` (the regenerating command its
    /// first line names) gains `--prefix`, and every word that starts with `encspeed_` or
    /// `ENCSPEED_` gets the prefix (upper-cased before `ENCSPEED_`).
    pub fn apply(&self, text: &str, command: &str) -> String {
        if self.is_empty() {
            return text.to_string();
        }
        let text = text.replace(command, &format!("{command} --prefix {}", self.0));
        let text = prefix_words(&text, STEM, &self.0);
        prefix_words(&text, MACRO_STEM, &self.0.to_ascii_uppercase())
    }
}

impl fmt::Display for Prefix {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// `text` with `prefix` inserted before every occurrence of `stem` that starts a word (is
/// not preceded by a letter, digit, `_` or `$`).
fn prefix_words(text: &str, stem: &str, prefix: &str) -> String {
    let mut out = String::with_capacity(text.len() + text.len() / 16);
    let mut rest = text;
    let mut previous: Option<char> = None;
    while let Some(at) = rest.find(stem) {
        let before = rest[..at].chars().next_back().or(previous);
        out.push_str(&rest[..at]);
        if !before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == '$') {
            out.push_str(prefix);
        }
        out.push_str(stem);
        previous = stem.chars().next_back();
        rest = &rest[at + stem.len()..];
    }
    out.push_str(rest);
    out
}
