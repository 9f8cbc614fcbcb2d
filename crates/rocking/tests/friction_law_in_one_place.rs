//! The foundation's friction law is written once, in `body/building.rs`
//! (`Friction`: the kinetic law, the static margin and `sticks`), and the
//! library's tower, stack and both impact laws call it. This test reads the
//! library's sources and fails where a friction coefficient is read anywhere
//! else (`.mu_static()`, `.mu_kinetic()` or a copy of one in a field such as
//! `.mu_s`): a change of the law made in one place would then not reach the
//! other. The coefficients' public getters stay, for the reports that print
//! them (the CLI's `check`, the page), outside this crate.

use std::fs;
use std::path::{Path, PathBuf};

/// The one file allowed to read the coefficients.
const LAW: &str = "body/building.rs";

/// The reads of a friction coefficient on one line of Rust, comments
/// stripped: a method call, a field or a path ending in `mu_static`,
/// `mu_kinetic`, `mu_s` or `mu_k` (a local variable of that name, as tests
/// construct buildings with, is not a read of the law's coefficient).
fn coefficient_reads(line: &str) -> usize {
    let code = line.split("//").next().unwrap_or("");
    let mut found = 0;
    for name in ["mu_static", "mu_kinetic", "mu_s", "mu_k"] {
        for sep in [".", "::"] {
            let needle = format!("{sep}{name}");
            found += code
                .match_indices(&needle)
                .filter(|(at, _)| {
                    let after = code[at + needle.len()..].chars().next();
                    !after.is_some_and(|c| c.is_alphanumeric() || c == '_')
                })
                .count();
        }
    }
    found
}

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let path = entry.unwrap_or_else(|e| panic!("{e}")).path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn the_scan_sees_a_read() {
    // The reads the library had in seven places before the law moved to the
    // building and the forms a new one could take (one read each), and lines
    // that read nothing.
    let lines = [
        ("let friction = self.building.map_or(0.0, |b| b.mu_kinetic()) * sigma;", 1),
        ("if p_stick.abs() <= building.mu_static() * n_stick.max(0.0) {", 1),
        ("normal * (-self.mu_k * sigma)", 1),
        ("map(Building::mu_static)", 1),
        ("let building = Building::new(2.0e6, mu_s, mu_k, normal);", 0),
        ("// b.mu_kinetic() in a comment", 0),
        ("self.friction.kinetic_friction(sigma, normal)", 0),
        ("let x = self.mu_static_margin;", 0),
    ];
    for (line, reads) in lines {
        assert_eq!(coefficient_reads(line), reads, "{line}");
    }
}

#[test]
fn friction_coefficients_are_read_only_by_the_law() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&root, &mut files);
    assert!(files.len() > 20, "the library's sources not found under {}", root.display());
    let mut reads = Vec::new();
    for file in &files {
        let relative = file.strip_prefix(&root).unwrap_or(file).to_string_lossy().replace('\\', "/");
        if relative == LAW {
            continue;
        }
        let text = fs::read_to_string(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        for (number, line) in text.lines().enumerate() {
            if coefficient_reads(line) > 0 {
                reads.push(format!("{relative}:{}: {}", number + 1, line.trim()));
            }
        }
    }
    assert!(
        reads.is_empty(),
        "a friction coefficient read outside {LAW}: call its `Friction` law instead\n{}",
        reads.join("\n")
    );
}
