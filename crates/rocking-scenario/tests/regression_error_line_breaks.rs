//! Regression: an error's line could be broken by what the user wrote. A
//! string value with a line break in it (`normal_force = "const\nt"`, a TOML
//! escape) was written as it is into its error, as was a key with one (a
//! quoted key `"wid\nth"`): the error spanned two lines, while every error
//! is one line naming the file and the key (found by fuzzing the assessment
//! file). Each control character of an error is now written escaped, as in a
//! Rust or TOML string (`\n`, `\t`, `\u{1b}`), the rest of the line as before.

use rocking_scenario::{one_line, Scenario};
use std::path::Path;

/// The error of the tests' tower on its church, `building` added to `[building]`.
fn scenario_error(building: &str) -> String {
    let text = format!(
        "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n[building]\nmass = 3.0e6\nmu_static = 0.5\n{building}\n\
         [ground]\ntype = \"harmonic\"\namplitude = 0.3\nfrequency = 2.0\n"
    );
    match Scenario::from_toml_str(&text, Path::new("case.toml")) {
        Ok(_) => panic!("{building:?} should be refused"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn a_value_with_a_line_break_is_written_escaped() {
    // The string as TOML reads it holds a line feed; the error writes it `\n`, backslash and n.
    assert_eq!(
        scenario_error("normal_force = \"const\\nt\""),
        r#"case.toml: building.normal_force: "const\nt" is not one of "constant", "dynamic""#
    );
    // A tab and an escape (ESC, U+001B) likewise; printable text other than ASCII is kept.
    assert_eq!(
        scenario_error("normal_force = \"é\\t\\u001b\""),
        r#"case.toml: building.normal_force: "é\t\u{1b}" is not one of "constant", "dynamic""#
    );
}

#[test]
fn a_key_with_a_line_break_is_written_escaped() {
    let e = scenario_error("\"mu\\nkinetic\" = 0.4");
    assert!(e.starts_with(r"case.toml: building.mu\nkinetic: unknown key"), "{e}");
    assert_eq!(e.lines().count(), 1, "{e}");
}

#[test]
fn one_line_escapes_control_characters_alone() {
    // Each control character as a Rust string writes it; other text, quotes and backslashes as they are.
    assert_eq!(one_line("a\nb\r\tc\u{7f}\u{85}"), r"a\nb\r\tc\u{7f}\u{85}");
    assert_eq!(one_line("l'été \"x\" \\ y"), "l'été \"x\" \\ y");
    // The line and paragraph separators break a line in some viewers: escaped too.
    assert_eq!(one_line("a\u{2028}b\u{2029}"), r"a\u{2028}b\u{2029}");
}
