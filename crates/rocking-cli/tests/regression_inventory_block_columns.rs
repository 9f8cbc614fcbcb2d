//! Regression: a column of towers.csv naming a block's key by the block's name
//! (`belfry.width`, as a sweep's axis does) was refused as an unknown section
//! `belfry`, so a town's belfries could not differ from tower to tower. Each
//! row's block now takes the column's value; an empty cell keeps the file's.

use crate::assess::tower_on_b;
use crate::util::{arg, csv_table, rocking, tempdir, write};

#[test]
fn an_inventory_column_sets_a_blocks_key_by_its_name() {
    let dir = tempdir();
    // tower_on_b.toml (4 m × 12 m, 150 t, subsoil B, FC 1.35, q 2) with a
    // slender belfry 1.6 m × 8 m of 20 t on it; the linear kinematic check
    // named to carry the verdict (assessment.verdict_method).
    let text = tower_on_b().replacen(
        "[site]\n",
        "[[block]]\nname = \"belfry\"\nwidth = 1.6\nheight = 8.0\nmass = 2.0e4\n\n[site]\n",
        1,
    ) + "verdict_method = \"linear_kinematic\"\n";
    let assess = write(dir.path(), "assess.toml", &text);
    let towers = write(dir.path(), "towers.csv", "id,lon,lat,belfry.width\nnarrow,14.4,41.0,1.2\nfile,14.4,41.0,\n");
    let out = dir.path().join("out");
    let r = rocking(&["inventory", arg(&towers), "--assess", arg(&assess), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let (header, rows) = csv_table(&out.join("inventory.csv"));
    let at = |row: &[String], name: &str| row[header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"))].clone();
    // By hand: the belfry turns on the shaft, b = width/2, h = 4 m, α0 = b/h,
    // a0*/g = α0/1.35. Its activation falls where SS is capped at 1.2 (ag <
    // 0.2/(0.4 · 2.52) = 0.198 g): a0*/(1.2 g); the SLV linear kinematic check
    // is q = 2 times it against ag = 0.155 g, the least ζ_E of the stack (as in
    // crates/rocking-assess/tests/belfry_by_hand.rs). The activation's root is
    // bisected to 1e-12 g: 1e-9 relative leaves room for it and the printing.
    for (row, width) in rows.iter().zip([1.2, 1.6]) {
        let activation = width / 2.0 / 4.0 / 1.35 / 1.2;
        assert!(activation < 0.198, "the branch SS = 1.2");
        assert_eq!(at(row, "error"), "", "{row:?}");
        assert_eq!(at(row, "governing"), "belfry SLV linear_kinematic", "{row:?}");
        let zeta: f64 = at(row, "zeta_E").parse().unwrap_or_else(|e| panic!("{e}"));
        let by_hand = 2.0 * activation / 0.155;
        assert!((zeta / by_hand - 1.0).abs() < 1e-9, "{}: ζ_E {zeta} against {by_hand}", at(row, "id"));
    }
    // Written out: 1.19474 for the narrow belfry, 1.59299 for the file's.
    assert!(at(&rows[0], "zeta_E").starts_with("1.1947"), "{:?}", rows[0]);

    // A column naming no block, and one renaming the block (its outputs are
    // named by it, as a sweep's axis cannot rename it): the header's one
    // error line, naming the column, and nothing written.
    for (column, what) in [
        (
            "lantern.width",
            "`lantern` is no section of the assessment file (tower, block, building, ground, initial, simulation, site, assessment) and no block on its tower",
        ),
        ("belfry.name", "a block's name cannot be set per tower"),
    ] {
        let towers = write(dir.path(), "bad.csv", &format!("id,lon,lat,{column}\nok,14.4,41.0,\nset,14.4,41.0,1.0\n"));
        let out = dir.path().join("bad");
        let r = rocking(&["inventory", arg(&towers), "--assess", arg(&assess), "--out", arg(&out)]);
        assert_eq!(r.code, Some(1), "{}", r.stderr);
        assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
        assert!(r.stderr.contains(&format!("bad.csv: column {column}: {what}")), "{}", r.stderr);
        assert!(!out.exists(), "{column}: an output folder was written");
    }
}
