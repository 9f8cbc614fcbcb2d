//! Regression (issue 48, item 8, the towers' file): a `towers.csv` as a
//! spreadsheet writes it was refused: with `;` or TAB between the fields,
//! "no column id"; with a UTF-8 byte-order mark the first column's name was
//! `\u{feff}id`. Such a file is now read (the separator the header holds most
//! of, the mark skipped), its rows the same as the comma file's; a number
//! with a decimal comma is refused with a line that says so.

use rocking_assess::Inventory;
use rocking_scenario::Cases;
use std::path::Path;

fn assess() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap_or_else(|e| panic!("{e}"))
}

/// The rows of a towers' file as CSV lines.
fn rows(towers: &[u8]) -> Vec<String> {
    let inventory = Inventory::new(&assess(), Path::new("assess.toml"), towers, Path::new("towers.csv")).unwrap_or_else(|e| panic!("{e}"));
    (0..Cases::len(&inventory))
        .map(|i| {
            inventory
                .run_case_until(i, &|| false)
                .unwrap_or_else(|| panic!("row {i} stopped"))
                .to_csv_line()
        })
        .collect()
}

#[test]
fn semicolons_tabs_and_a_byte_order_mark_read_as_commas() {
    let comma = "id,name,lon,lat,tower.width\nA,San Rocco,14.4,41.0,4.5\nB,\"Santa Maria, Assunta\",14.5,41.1,3.5\n";
    let expected = rows(comma.as_bytes());
    assert_eq!(expected.len(), 2);
    // The widths reach the assessment: the two towers' rows differ.
    assert_ne!(expected[0].split_once(',').map(|p| p.1), expected[1].split_once(',').map(|p| p.1));
    let semicolon = "\u{feff}id;name;lon;lat;tower.width\nA;San Rocco;14.4;41.0;4.5\nB;Santa Maria, Assunta;14.5;41.1;3.5\n";
    let tab = "id\tname\tlon\tlat\ttower.width\nA\tSan Rocco\t14.4\t41.0\t4.5\nB\tSanta Maria, Assunta\t14.5\t41.1\t3.5\n";
    let bom_comma = format!("\u{feff}{comma}");
    for text in [semicolon, tab, bom_comma.as_str()] {
        assert_eq!(rows(text.as_bytes()), expected, "{text:?}");
    }
}

#[test]
fn a_decimal_comma_is_refused_naming_its_row_and_column() {
    let towers = "id;lon;lat;tower.width\nA;14,4;41.0;4.5\nB;14.5;41.1;4,5\n";
    let lines = rows(towers.as_bytes());
    assert!(
        lines[0].contains("towers.csv row 1 (id A), column lon: \"\"14,4\"\" has a decimal comma: write numbers with a decimal point (14.4)"),
        "{}",
        lines[0]
    );
    assert!(
        lines[1].contains("row 2 (id B), column tower.width: \"\"4,5\"\" has a decimal comma"),
        "{}",
        lines[1]
    );
}
