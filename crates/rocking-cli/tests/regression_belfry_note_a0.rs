//! Regression (issue 47, item 4): the note under the belfry's checks quoted
//! the tower's a0*. Each mechanism's checks now have their own note with
//! their own a0*, the belfry's worked out here by hand.

use super::regression_belfry_d0_row::belfry_report;
use crate::util::tempdir;

/// The note on the linear kinematic check after the heading of `mechanism` in section 3.
fn note_of<'a>(report: &'a str, mechanism: &str) -> &'a str {
    let checks = &report[report.find("<h2>3. The checks</h2>").unwrap_or_else(|| panic!("no section 3"))..];
    let after = &checks[checks
        .find(&format!("<h3>{mechanism}</h3>"))
        .unwrap_or_else(|| panic!("no {mechanism} in section 3"))..];
    let note = &after[after
        .find("The linear kinematic check's capacity")
        .unwrap_or_else(|| panic!("no note for {mechanism}"))..];
    &note[..note.find("</p>").unwrap_or(note.len())]
}

#[test]
fn the_note_under_the_belfrys_checks_quotes_the_belfrys_a0() {
    let dir = tempdir();
    let report = belfry_report(dir.path(), &[]);
    // a0* = α0 g / (e* FC) = (1/2) 9.81 / 1.35 = 3.6333… m/s² (eq. C8.7.1.8), the report's 4 digits.
    let belfry_a0 = 0.5 * 9.81 / 1.35;
    assert_eq!(format!("{belfry_a0:.3}"), "3.633");
    let note = note_of(&report, "belfry");
    assert!(note.contains("a<sub>0</sub>* of the belfry = 3.633 m/s²"), "{note}");
    // The tower's note quotes the tower's (the stack turning as one: α0 below the belfry's 1/2).
    let tower = note_of(&report, "tower");
    assert!(tower.contains("a<sub>0</sub>* of the tower = ") && !tower.contains("3.633"), "{tower}");
}
