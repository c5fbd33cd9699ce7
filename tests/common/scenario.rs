//! Scenario texts for the tests of bad input: a valid base, and the checks that a text is
//! refused naming the file, the line of a marker, the key and the reason.

use std::path::Path;

pub use super::cli::temp_dir;

use riprap::scenario::{build, Source};

/// A valid scenario without walls or spheres: 14 lines.
pub const BASE: &str = r#"[run]
name = "case"
end_time = 0.1

[domain]
min = [0.0, 0.0, 0.0]
max = [1.0, 1.0, 1.0]

[[material]]
name = "rock"
density = 2650.0
young_modulus = 1.0e8
poisson_ratio = 0.25
friction_coefficient = 0.5
"#;

/// One sphere resting in the middle of the domain, for cases that need spheres.
pub const ONE_SPHERE: &str = r#"
[[spheres]]
kind = "list"
material = "rock"
spheres = [ { position = [0.5, 0.5, 0.5], diameter = 0.1 } ]
"#;

/// The error message for a scenario text (parse or build), or a panic if it is accepted.
pub fn error_in(text: &str, dir: &Path) -> String {
    match Source::from_str(text, "case.toml", dir.to_path_buf()) {
        Err(e) => e.to_string(),
        Ok(src) => match build(&src) {
            Err(e) => e.to_string(),
            Ok(_) => panic!("accepted:\n{text}"),
        },
    }
}

/// 1-based line of the first line of `text` containing `marker`.
pub fn line_with(text: &str, marker: &str) -> usize {
    text.lines()
        .position(|l| l.contains(marker))
        .unwrap_or_else(|| panic!("no `{marker}` in\n{text}"))
        + 1
}

/// Checks that BASE + `extra` is refused with a message that starts with `case.toml:<line>:`,
/// where <line> is the line holding `marker`, names `key` and contains every reason fragment.
#[track_caller]
pub fn refused(extra: &str, marker: &str, key: &str, reasons: &[&str]) -> String {
    refused_in(&format!("{BASE}{extra}"), marker, key, reasons)
}

#[track_caller]
pub fn refused_in(text: &str, marker: &str, key: &str, reasons: &[&str]) -> String {
    let msg = error_in(text, &temp_dir("default"));
    let line = line_with(text, marker);
    assert!(
        msg.starts_with(&format!("case.toml:{line}:")),
        "expected case.toml:{line}:, got\n{msg}\nfor\n{text}"
    );
    if !key.is_empty() {
        assert!(
            msg.contains(&format!("key `{key}`:")),
            "expected key `{key}` in\n{msg}"
        );
    }
    for r in reasons {
        assert!(msg.contains(r), "expected `{r}` in\n{msg}");
    }
    msg
}

pub fn accepted(text: &str, dir: &Path) -> riprap::scenario::Built {
    let src =
        Source::from_str(text, "case.toml", dir.to_path_buf()).unwrap_or_else(|e| panic!("{e}"));
    build(&src).unwrap_or_else(|e| panic!("{e}"))
}
