// SPDX-License-Identifier: MIT OR Apache-2.0
//! The licence as a package states it: both licence texts at the root, the Cargo licence
//! field naming them, an SPDX line at the top of every source file the repository tracks,
//! and every generated file starting with the command that regenerates it and the SPDX line.

use golden::provenance::{command_of, SPDX};
use std::path::Path;
use std::process::Command;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn both_licence_texts_are_at_the_root_and_cargo_names_them() {
    let mit = std::fs::read_to_string(root().join("LICENSE-MIT")).unwrap();
    assert!(mit.contains("Permission is hereby granted, free of charge"));
    let apache = std::fs::read_to_string(root().join("LICENSE-APACHE")).unwrap();
    assert!(apache.contains("Apache License") && apache.contains("Version 2.0, January 2004"));
    let cargo = std::fs::read_to_string(root().join("Cargo.toml")).unwrap();
    assert!(cargo.contains("license = \"MIT OR Apache-2.0\""));
    assert_eq!(SPDX, "SPDX-License-Identifier: MIT OR Apache-2.0");
}

/// The files git tracks, and the new ones it does not ignore.
fn repository_files() -> Vec<String> {
    let o = Command::new("git")
        .args(["ls-files", "--cached", "--others", "--exclude-standard"])
        .current_dir(root())
        .output()
        .expect("git ls-files");
    assert!(o.status.success());
    String::from_utf8(o.stdout)
        .unwrap()
        .lines()
        .filter(|f| root().join(f).is_file())
        .map(str::to_string)
        .collect()
}

#[test]
fn every_source_file_carries_the_spdx_line_at_its_top() {
    let sources = [
        "rs", "cpp", "h", "v", "vlt", "toml", "py", "sdc", "pcf", "lpf", "core",
    ];
    let mut checked = 0;
    let mut missing = Vec::new();
    for f in repository_files() {
        let ext = Path::new(&f).extension().and_then(|e| e.to_str());
        if !(ext.is_some_and(|e| sources.contains(&e)) || f == ".ci/run") {
            continue;
        }
        let text = std::fs::read_to_string(root().join(&f)).unwrap();
        if !text.lines().take(3).any(|l| l.contains(SPDX)) {
            missing.push(f);
        }
        checked += 1;
    }
    assert!(
        missing.is_empty(),
        "no SPDX line in the first 3 lines of {missing:?}"
    );
    assert!(checked > 200, "{checked} files");
}

#[test]
fn every_generated_file_starts_with_its_command_and_the_spdx_line() {
    let mut files: Vec<String> = std::fs::read_dir(root().join("generated"))
        .unwrap()
        .map(|e| format!("generated/{}", e.unwrap().file_name().to_string_lossy()))
        .collect();
    files.extend(
        [
            "docs/ports.md",
            "docs/registers.md",
            "encspeed.example.toml",
        ]
        .map(String::from),
    );
    for f in &files {
        let text = std::fs::read_to_string(root().join(f)).unwrap();
        let command = command_of(&text).unwrap_or_else(|| panic!("{f}: no command first"));
        assert!(command.starts_with("encspeed "), "{f}: {command}");
        let second = text.lines().nth(1).unwrap_or_default();
        assert!(second.contains(SPDX), "{f}: second line {second}");
    }
    // Four tops with .v, _inst.v, .toml, .vlt; two C headers; three board tops with .v and
    // .vlt; three pages above.
    assert_eq!(files.len(), 4 * 4 + 2 + 3 * 2 + 3);
}
