//! Regression: a misspelt column of the towers' file (`tower.hieght`) was
//! found row by row: every tower with a value in it failed with the same
//! line, twelve lines for the town's twelve towers, and the inventory went on
//! to write a ranking of no tower. A column that names no key is the header's
//! fault: the inventory is refused at once, with one line naming the file and
//! the column, whatever the rows hold (an empty column too).

use rocking_assess::Inventory;
use std::path::Path;

/// The tests' tower (tests/data/tower_on_b.toml).
fn assess() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap_or_else(|e| panic!("{e}"))
}

/// The error of an inventory whose towers' file is `towers`, if it is refused.
fn refused(towers: &str) -> Option<String> {
    Inventory::new(&assess(), Path::new("assess.toml"), towers.as_bytes(), Path::new("towers.csv"))
        .err()
        .map(|e| e.to_string())
}

#[test]
fn a_misspelt_column_is_refused_once_by_the_header() {
    // Twelve towers with a height each, under a misspelt column: one line.
    let rows: String = (1..=12).map(|i| format!("T{i},14.4,41.0,{}\n", 10.0 + f64::from(i))).collect();
    let e = refused(&format!("id,lon,lat,tower.hieght\n{rows}")).unwrap_or_else(|| panic!("tower.hieght should be refused"));
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(
        e.starts_with("towers.csv: column tower.hieght: unknown key (did you mean `tower.height`?)"),
        "{e}"
    );
    // An empty column is misspelt all the same.
    let e = refused("id,lon,lat,tower.hieght\nA,14.4,41.0,\n").unwrap_or_else(|| panic!("an empty tower.hieght should be refused"));
    assert!(e.starts_with("towers.csv: column tower.hieght: "), "{e}");

    // Spelt right, the same column is taken, each row's own value: no error at the start.
    let inventory = Inventory::new(
        &assess(),
        Path::new("assess.toml"),
        format!("id,lon,lat,tower.height\n{rows}").as_bytes(),
        Path::new("towers.csv"),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert!(inventory.assess(0).is_ok(), "{:?}", inventory.assess(0).err());
}
