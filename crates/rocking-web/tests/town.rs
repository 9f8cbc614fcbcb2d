//! The page's town against the command's path: the example town with its
//! hazard grid and its records given as text (as the page has them) gives the
//! rows of the inventory read from the files (as `rocking inventory` reads
//! them), field for field; the ranking is the towers sorted by ζ_E, worked out
//! here from the rows; a bad row's error names the towers' file, its row and column.

#![allow(clippy::unwrap_used)]

use rocking_assess::Inventory;
use rocking_scenario::csv_line;
use rocking_web::WebTown;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn read(path: &str) -> String {
    std::fs::read_to_string(root().join(path)).unwrap()
}

/// The rows of the inventory read from files, as `inventory.csv` holds them.
fn from_files(assess: &str, towers: &str) -> String {
    let inventory = Inventory::new(assess, &root().join("examples/town/assess.toml"), towers.as_bytes(), Path::new("towers.csv")).unwrap();
    let mut out = csv_line(inventory.header());
    out.push('\n');
    for index in 0..rocking_scenario::Cases::len(&inventory) {
        out.push_str(&inventory.row(index).to_csv_line());
        out.push('\n');
    }
    out
}

#[test]
fn the_example_town_from_text_is_the_town_from_files() {
    let assess = read("examples/town/assess.toml");
    let towers = read("examples/town/towers.csv");
    // The example's grid is the official one, held by the library: no grid file.
    let mut town = WebTown::create(&assess, "examples/town/assess.toml", &towers, "towers.csv", None, None, "null").unwrap();
    assert_eq!(town.length(), 12);
    // A few at a time, as the page's worker runs them.
    assert_eq!(town.advance(5), 5);
    assert_eq!(town.advance(100), 12);
    assert_eq!(town.csv(), from_files(&assess, &towers));

    let shown: Value = serde_json::from_str(&town.town().map_err(|_| "town").unwrap()).unwrap();
    let towers = shown["towers"].as_array().unwrap();
    let zeta = |i: usize| towers[i]["zeta_E"].as_f64().unwrap();
    let ranking: Vec<usize> = shown["ranking"].as_array().unwrap().iter().map(|v| v.as_u64().unwrap() as usize).collect();
    // Every tower ranked, least ζ_E first.
    let mut expected: Vec<usize> = (0..12).collect();
    expected.sort_by(|&a, &b| zeta(a).total_cmp(&zeta(b)));
    assert_eq!(ranking, expected);
    // The example's least: CE07 (Santa Lucia), its SLV non-linear kinematic
    // check, the most refined computed without records (the docs' table).
    assert_eq!(towers[ranking[0]]["id"], "CE07");
    assert_eq!(towers[ranking[0]]["governing"], "SLV nonlinear_kinematic");
    assert_eq!(towers[0]["lon"], json!(14.332));
    let geojson: Value = serde_json::from_str(shown["geojson"].as_str().unwrap()).unwrap();
    assert_eq!(geojson["features"].as_array().unwrap().len(), 12);
}

#[test]
fn records_given_as_text_give_the_dynamic_checks_of_the_files() {
    let records = ["kt_01.AT2", "kt_02.AT2", "kt_03.AT2"];
    let base = read("examples/town/assess.toml");
    let with_files = base.replace(
        "q = 2.0\n",
        &format!(
            "q = 2.0\nrecords = {}\nlambda = {{ from = 0.5, to = 3.0, step = 0.5 }}\n",
            json!(records.map(|r| format!("../../data/records/synthetic/{r}")))
        ),
    );
    let with_text = base.replace("q = 2.0\n", "q = 2.0\nlambda = { from = 0.5, to = 3.0, step = 0.5 }\n");
    let given = json!(records.map(|r| json!({ "name": r, "text": read(&format!("data/records/synthetic/{r}")) })));
    let towers = "id,name,lon,lat,tower.width,tower.height\nA,slender,14.34,41.06,3.6,30.0\n";
    let mut town = WebTown::create(&with_text, "examples/town/assess.toml", towers, "towers.csv", None, None, &given.to_string()).unwrap();
    town.advance(1);
    let csv = town.csv();
    assert!(csv.contains("SLC_nonlinear_dynamic_zeta_E"), "{csv}");
    assert_eq!(csv, from_files(&with_files, towers));
}

#[test]
fn a_bad_row_names_the_towers_file_its_row_and_column() {
    let assess = read("examples/town/assess.toml");
    let towers = "id,name,lon,lat,tower.width\nA,,14.34,41.06,-4\nB,,14.35,41.07,\n";
    let mut town = WebTown::create(&assess, "examples/town/assess.toml", towers, "mine.csv", None, None, "[]").unwrap();
    town.advance(2);
    let csv = town.csv();
    assert!(csv.contains("mine.csv row 1 (id A), column tower.width"), "{csv}");
    let shown: Value = serde_json::from_str(&town.town().map_err(|_| "town").unwrap()).unwrap();
    // The bad tower is not ranked; the good one is.
    assert_eq!(shown["ranking"], json!([1]));
}

#[test]
fn a_users_file_takes_the_records_it_names_from_those_picked_by_file_name() {
    let records = ["kt_01.AT2", "kt_02.AT2", "kt_03.AT2"];
    // A grid file of the user's (the synthetic one): the page takes it picked by file name.
    let with_files = read("examples/town/assess.toml")
        .replace("grid = \"ntc2018\"", "grid = \"../../data/hazard/synthetic_grid.txt\"")
        .replace(
            "q = 2.0\n",
            &format!(
                "q = 2.0\nrecords = {}\nlambda = {{ from = 0.5, to = 3.0, step = 0.5 }}\n",
                json!(records.map(|r| format!("../../data/records/synthetic/{r}")))
            ),
        );
    let picked = |names: &[&str]| {
        json!(names
            .iter()
            .map(|r| json!({ "name": r, "text": read(&format!("data/records/synthetic/{r}")) }))
            .collect::<Vec<_>>())
        .to_string()
    };
    let towers = "id,name,lon,lat,tower.width,tower.height\nA,slender,14.34,41.06,3.6,30.0\n";
    let grid = || Some(read("data/hazard/synthetic_grid.txt"));
    let grid_name = || Some("synthetic_grid.txt".to_string());
    // Picked in another order, with one the file does not name: the file's three, in its order.
    let set = picked(&["kt_04.AT2", "kt_03.AT2", "kt_02.AT2", "kt_01.AT2"]);
    let mut town = WebTown::create(&with_files, "ASSESS.toml", towers, "towers.csv", grid(), grid_name(), &set).unwrap();
    town.advance(1);
    assert_eq!(town.csv(), from_files(&with_files, towers));
    // One the file names is not picked: one line naming it.
    let err = WebTown::create(
        &with_files,
        "ASSESS.toml",
        towers,
        "towers.csv",
        grid(),
        grid_name(),
        &picked(&["kt_01.AT2", "kt_02.AT2"]),
    )
    .err();
    assert_eq!(err.as_deref(), Some("ASSESS.toml: assessment.records: no record file picked for kt_03.AT2"));
    // The grid: the one the file names, or a line saying which it names.
    let err = WebTown::create(&with_files, "ASSESS.toml", towers, "towers.csv", None, None, "[]").err();
    assert_eq!(err.as_deref(), Some("ASSESS.toml: site.grid: names synthetic_grid.txt, which is not picked"));
    let err = WebTown::create(&with_files, "ASSESS.toml", towers, "towers.csv", grid(), Some("other.txt".into()), "[]").err();
    assert_eq!(err.as_deref(), Some("ASSESS.toml: site.grid: names synthetic_grid.txt, not other.txt"));
}
