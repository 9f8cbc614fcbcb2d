//! Regression (issue 48, item 5): names and ids beginning with `=`, `+`, `-`
//! or `@` (`=HYPERLINK(...)`) were written verbatim into `inventory.csv`, and
//! a record's file name into `spectra.csv`'s header: a spreadsheet opening the
//! file runs them as formulas. Every CSV the tool writes now gives such a
//! text cell (and one beginning with a TAB or a CR) a leading `'`, OWASP's
//! rule, so that a spreadsheet shows it as text; numbers (`-2`) are left as
//! they are.

use crate::util::{arg, csv_table, read, rocking, root, tempdir, write};

const HOSTILE: [&str; 4] = ["=HYPERLINK(\"http://x.example\",\"click\")", "+1+cmd", "-2+3", "@SUM(A1)"];

#[test]
fn a_cell_a_spreadsheet_would_run_is_written_as_text_and_numbers_are_not_touched() {
    for text in HOSTILE.iter().chain(&["\tx", "\rx"]) {
        // The line read back by a CSV reader: one field, the text behind a `'`.
        let line = rocking_scenario::csv_line([*text, "1"]);
        let mut reader = csv::ReaderBuilder::new().has_headers(false).from_reader(line.as_bytes());
        let record = reader
            .records()
            .next()
            .and_then(Result::ok)
            .unwrap_or_else(|| panic!("{line:?} does not read back"));
        assert_eq!(record.iter().collect::<Vec<_>>(), [format!("'{text}").as_str(), "1"], "{text:?}");
        assert_eq!(rocking_scenario::spreadsheet_text(text), format!("'{text}"));
    }
    // Numbers and plain names as they were: a negative number is a number to a spreadsheet too.
    assert_eq!(
        rocking_scenario::csv_line(["-2", "+1e-3", "-0.5", "San Michele", "a=b", ""]),
        "-2,+1e-3,-0.5,San Michele,a=b,"
    );
}

#[test]
fn inventory_names_and_ids_are_written_as_text() {
    let dir = tempdir();
    let grid = root().join("data/hazard/synthetic_grid.txt");
    let assess = write(
        dir.path(),
        "assess.toml",
        &format!(
            "[tower]\nwidth = 4.5\nheight = 24.0\nmass = 4.0e5\n\n[site]\nsoil = \"B\"\ngrid = '{}'\nlon = 14.33\nlat = 41.07\nCU = 1.5\n\n[assessment]\nconfidence_factor = 1.35\n",
            grid.display()
        ),
    );
    let rows: String = HOSTILE
        .iter()
        .enumerate()
        .map(|(k, name)| format!("\"{}{k}\",\"{}\",14.33,41.07\n", name.replace('"', "\"\""), name.replace('"', "\"\"")))
        .collect();
    let towers = write(dir.path(), "towers.csv", &format!("id,name,lon,lat\n{rows}"));
    let out = dir.path().join("out");
    let r = rocking(&["inventory", arg(&towers), "--assess", arg(&assess), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let (header, table) = csv_table(&out.join("inventory.csv"));
    let column = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    let (id, name) = (column("id"), column("name"));
    let mut names: Vec<&str> = table.iter().map(|row| row[name].as_str()).collect();
    names.sort_unstable();
    let mut expected: Vec<String> = HOSTILE.iter().map(|h| format!("'{h}")).collect();
    expected.sort_unstable();
    assert_eq!(names, expected);
    assert!(table.iter().all(|row| row[id].starts_with('\'')), "{table:?}");
    // Every other cell of the rows is a number, a check's name or empty, never a text beginning a formula.
    for row in &table {
        for cell in row {
            assert!(!cell.starts_with(['=', '+', '@', '\t', '\r']), "{cell:?}");
        }
    }
}

#[test]
fn a_record_named_like_a_formula_heads_its_spectrum_column_as_text() {
    let dir = tempdir();
    let rows: String = (0..=80).map(|k| format!("{},0.3\n", 0.005 * k as f64)).collect();
    let record = write(dir.path(), "=1+1.csv", &format!("time,acceleration\n{rows}"));
    let out = dir.path().join("out");
    let r = rocking(&["spectrum", arg(&record), "--periods", "0.2,0.5,3", "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert_eq!(read(&out.join("spectra.csv")).lines().next(), Some("period_s,'=1+1.csv"));
}
