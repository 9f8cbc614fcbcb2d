//! Regression (issue 47, item 3): `rocking inventory`'s assessment file had to
//! name a `site.lon` and `site.lat` that every tower's own `lon`, `lat` then
//! replaced. A column replaces the key it names, and nothing is required
//! twice: the file without them assesses every tower as the file with them.

use crate::util::{arg, read, rocking, root, tempdir, write};

/// The town's assessment file on the synthetic grid, with `place` in its `[site]`.
fn town(grid: &std::path::Path, place: &str) -> String {
    format!(
        "[tower]\nwidth = 4.5\nheight = 24.0\nmass = 4.0e5\n\n[site]\nsoil = \"B\"\ngrid = '{}'\n{place}CU = 1.5\n\n[assessment]\nconfidence_factor = 1.35\n",
        grid.display()
    )
}

#[test]
fn the_assessment_file_of_a_town_needs_no_place_of_its_own() {
    let dir = tempdir();
    let grid = root().join("data/hazard/synthetic_grid.txt");
    // The first tower has no place, the second is outside the grid: each its
    // row's error, and the file is still checked by itself (inside the grid).
    let towers = write(
        dir.path(),
        "towers.csv",
        "id,lon,lat,tower.width\nA,,41.06,5.0\nB,13.90,41.07,5.0\nC,14.34,41.06,5.0\nD,14.41,41.10,4.0\n",
    );
    let run = |name: &str, place: &str| {
        let assess = write(dir.path(), &format!("{name}.toml"), &town(&grid, place));
        let out = dir.path().join(name);
        let r = rocking(&["inventory", arg(&towers), "--assess", arg(&assess), "--out", arg(&out)]);
        // Tower A has no lon: its row's error, the exit status 1, the others assessed.
        assert_eq!(r.code, Some(1), "{}", r.stderr);
        assert!(r.stderr.contains("row 1 (id A), column lon: missing"), "{}", r.stderr);
        assert!(
            r.stderr
                .contains("row 2 (id B), column lon (\"13.90\"): the site (lon 13.9, lat 41.07) is outside the hazard grid"),
            "{}",
            r.stderr
        );
        read(&out.join("inventory.csv"))
    };
    let without = run("without", "");
    let with = run("with", "lon = 14.33\nlat = 41.07\n");
    // The same rows, to the byte: each tower's place is its own either way.
    assert_eq!(without, with);
    assert_eq!(
        without.lines().filter(|l| l.ends_with(',')).count(),
        2,
        "two towers assessed, no error: {without}"
    );
}
