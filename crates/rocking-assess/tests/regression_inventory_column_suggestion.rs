//! Regression: a misspelt column of a town's towers' file got no "did you
//! mean": `towr.width` (a misspelt section) was refused naming the sections
//! alone, and `belfry.widht` under a belfry suggested the bare `width`, not
//! the column to write. A column misspelling a key of a section or of a block
//! (by its name, as a sweep's axis gives it) now suggests the column as it is
//! written (`tower.width`, `belfry.width`), among the keys of the blocks the
//! assessment file has, by the scenario's own "did you mean".

use rocking_assess::Inventory;
use std::path::Path;

/// The tests' tower (tests/data/tower_on_b.toml) with `blocks` on it.
fn assess(blocks: &str) -> String {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap_or_else(|e| panic!("{e}"));
    let text = file.replacen("[site]\n", &format!("{blocks}\n[site]\n"), 1);
    assert_ne!(text, file, "tower_on_b.toml has no [site]");
    text
}

const BELFRY: &str = "[[block]]\nname = \"belfry\"\nwidth = 1.6\nheight = 8.0\nmass = 2.0e4\n";

/// The error of a file whose last column is `column`, set to `cell` for its
/// one tower: the header's (see regression_inventory_misspelt_column_once.rs).
fn error(blocks: &str, column: &str, cell: &str) -> String {
    let towers = format!("id,lon,lat,{column}\nA,14.4,41.0,{cell}\n");
    let e = match Inventory::new(&assess(blocks), Path::new("assess.toml"), towers.as_bytes(), Path::new("towers.csv")) {
        Ok(_) => panic!("the column {column} should be refused"),
        Err(e) => e.to_string(),
    };
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(e.starts_with(&format!("towers.csv: column {column}: ")), "{e}");
    e
}

#[test]
fn a_misspelt_column_is_suggested_as_it_is_written() {
    // One transposition from `width`, under the belfry: the belfry's keys listed.
    let e = error(BELFRY, "belfry.widht", "1.2");
    assert!(
        e.contains("unknown key (did you mean `belfry.width`?); valid keys: belfry.width, belfry.height, belfry.mass,"),
        "{e}"
    );
    assert!(!e.contains("tower."), "{e}");
    // One deletion from `tower`, from `belfry`, from `assessment`: the column suggested.
    for (column, cell, meant) in [
        ("towr.width", "4.0", "tower.width"),
        ("belfr.width", "1.2", "belfry.width"),
        ("assesment.q", "2.0", "assessment.q"),
    ] {
        let e = error(BELFRY, column, cell);
        let head = column.split('.').next().unwrap_or_default();
        assert!(e.contains(&format!("`{head}` is no section of the assessment file")), "{e}");
        assert!(e.ends_with(&format!("; did you mean `{meant}`?")), "{e}");
    }
    // A tower's key: the column, not the bare key, suggested.
    let e = error(BELFRY, "tower.hieght", "12.0");
    assert!(
        e.contains("unknown key (did you mean `tower.height`?); valid keys: tower.width, tower.height,"),
        "{e}"
    );

    // The keys of the blocks the file has, no other: a tower alone has no
    // `belfry.width` to suggest.
    let e = error("", "belfry.widht", "1.2");
    assert!(e.contains("no block on its tower") && !e.contains("did you mean"), "{e}");

    // Spelt right, the same columns are the tower's: no error.
    let towers = "id,lon,lat,belfry.width,tower.width,assessment.q\nA,14.4,41.0,1.2,4.0,2.0\n";
    let inventory = Inventory::new(&assess(BELFRY), Path::new("assess.toml"), towers.as_bytes(), Path::new("towers.csv")).unwrap_or_else(|e| panic!("{e}"));
    assert!(inventory.assess(0).is_ok(), "{:?}", inventory.assess(0).err());
}
