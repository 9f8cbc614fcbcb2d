//! Regression: a row's error could span several lines. A tower's id is
//! written into each error of its row (`towers.csv row 2 (id CE02), column
//! lon: …`), and a quoted cell of the CSV may hold a line break; so may a
//! column's name in an error of the header, or a cell's text in the error of
//! the key it sets. Every error of the towers' file is one line naming the
//! file (and the row and the column): a control character in it is written
//! escaped (`\n`), the rest as before.

use rocking_assess::Inventory;
use std::path::Path;

/// The tests' tower (tests/data/tower_on_b.toml).
fn assess() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap_or_else(|e| panic!("{e}"))
}

fn inventory(towers: &str) -> Result<Inventory, String> {
    Inventory::new(&assess(), Path::new("assess.toml"), towers.as_bytes(), Path::new("towers.csv")).map_err(|e| e.to_string())
}

#[test]
fn an_id_with_a_line_break_keeps_its_rows_error_on_one_line() {
    let towers = inventory("id,lon,lat\n\"CE\n01\",200,41.0\n").unwrap_or_else(|e| panic!("{e}"));
    let e = towers.assess(0).err().unwrap_or_else(|| panic!("lon 200 should be refused"));
    assert_eq!(e, r"towers.csv row 1 (id CE\n01), column lon: must be within ±180 degrees, got 200");
}

#[test]
fn a_cell_with_a_line_break_keeps_its_rows_error_on_one_line() {
    // The cell sets a choice of the assessment file: its error names the column and the cell.
    let towers = inventory("id,lon,lat,assessment.capacity\nA,14.4,41.0,\"lin\near\"\n").unwrap_or_else(|e| panic!("{e}"));
    let e = towers.assess(0).err().unwrap_or_else(|| panic!("capacity \"lin\\near\" should be refused"));
    assert_eq!(
        e,
        r#"towers.csv row 1 (id A), column assessment.capacity ("lin\near"): "lin\near" is not one of "linear", "exact""#
    );
}

#[test]
fn a_header_with_a_line_break_is_refused_on_one_line() {
    let e = inventory("id,lon,lat,\"tower.\nwidth\",\"tower.\nwidth\"\n")
        .err()
        .unwrap_or_else(|| panic!("a repeated column should be refused"));
    assert_eq!(e, r"towers.csv: column tower.\nwidth appears twice (columns 4 and 5)");
    let e = inventory("id,lon,lat,\"tower.wid\nth\"\n")
        .err()
        .unwrap_or_else(|| panic!("a misspelt column should be refused"));
    assert!(e.starts_with(r"towers.csv: column tower.wid\nth: unknown key"), "{e}");
    assert_eq!(e.lines().count(), 1, "{e}");
}
