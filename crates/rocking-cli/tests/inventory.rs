//! `rocking inventory`: every row of inventory.csv is `rocking assess` of an
//! assessment file written out by hand with that tower's values (the second
//! route: the file's text, not the row's table), bit for bit; bad rows each get
//! their own error while the others are still right; inventory.geojson read
//! back by the `geojson` crate.

use crate::util::{arg, assert_shards_merge_to_whole, csv_table, read, rocking, root, tempdir, write};
use std::path::Path;

/// The town's assessment file: its own tower, subsoil B, the synthetic grid at `lon`, `lat`.
pub fn base(grid: &Path) -> String {
    format!(
        "[tower]\nwidth = 4.5\nheight = 24.0\nmass = 4.0e5\n\n[site]\nsoil = \"B\"\ngrid = '{}'\nlon = 14.33\nlat = 41.07\nCU = 1.5\n\n[assessment]\nconfidence_factor = 1.35\n",
        grid.display()
    )
}

/// One tower's assessment file, written from its values as an engineer would.
fn tower_file(grid: &Path, width: f64, height: f64, mass: f64, soil: &str, lon: f64, lat: f64) -> String {
    format!(
        "[tower]\nwidth = {width:?}\nheight = {height:?}\nmass = {mass:?}\n\n[site]\nsoil = \"{soil}\"\ngrid = '{}'\nlon = {lon:?}\nlat = {lat:?}\nCU = 1.5\n\n[assessment]\nconfidence_factor = 1.35\n",
        grid.display()
    )
}

/// `rocking assess` of `text`: each check's (column prefix, ag capacity, ζ_E), and the governing (ζ_E, check).
fn assess(dir: &Path, name: &str, text: &str) -> (Vec<(String, f64, f64)>, f64, String) {
    let file = write(dir, &format!("{name}.toml"), text);
    let out = dir.join(format!("out-{name}"));
    let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let json: serde_json::Value = serde_json::from_str(&read(&out.join("assessment.json"))).unwrap_or_else(|e| panic!("{e}"));
    let num = |v: &serde_json::Value| v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"));
    let checks = json["checks"]
        .as_array()
        .unwrap_or_else(|| panic!("no checks"))
        .iter()
        .map(|c| {
            let prefix = format!("{}_{}", c["limit_state"].as_str().unwrap_or(""), c["method"].as_str().unwrap_or(""));
            (prefix, num(&c["ag_capacity_g"]), num(&c["zeta_E"]))
        })
        .collect();
    let g = &json["governing"];
    let governing = format!("{} {}", g["limit_state"].as_str().unwrap_or(""), g["method"].as_str().unwrap_or(""));
    (checks, num(&g["zeta_E"]), governing)
}

/// inventory.csv of `out` as (header, rows).
fn inventory_csv(out: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    csv_table(&out.join("inventory.csv"))
}

fn cell<'a>(header: &[String], row: &'a [String], name: &str) -> &'a str {
    let i = header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    &row[i]
}

fn number(text: &str) -> f64 {
    text.parse().unwrap_or_else(|_| panic!("not a number: {text:?}"))
}

/// The row's numbers are `rocking assess`'s, to the bit: the same functions on the same values.
fn assert_row_is_assess(header: &[String], row: &[String], expected: &(Vec<(String, f64, f64)>, f64, String)) {
    let (checks, zeta, governing) = expected;
    // Every check of the assessment has its columns, and no other.
    assert_eq!(checks.len(), header.iter().filter(|h| h.ends_with("_zeta_E")).count());
    for (prefix, ag, z) in checks {
        assert_eq!(
            number(cell(header, row, &format!("{prefix}_ag_capacity_g"))).to_bits(),
            ag.to_bits(),
            "{prefix} of {row:?}"
        );
        assert_eq!(
            number(cell(header, row, &format!("{prefix}_zeta_E"))).to_bits(),
            z.to_bits(),
            "{prefix} of {row:?}"
        );
    }
    assert_eq!(number(cell(header, row, "zeta_E")).to_bits(), zeta.to_bits());
    assert_eq!(cell(header, row, "governing"), governing);
    assert_eq!(cell(header, row, "error"), "");
}

/// `rocking inventory` of the example town into `out`, with `extra` arguments; it must succeed.
fn example_town(out: &Path, extra: &[&str]) {
    let mut args = vec![
        "inventory",
        "examples/town/towers.csv",
        "--assess",
        "examples/town/assess.toml",
        "--out",
        arg(out),
    ];
    args.extend(extra);
    let r = rocking(&args);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
}

#[test]
fn every_tower_of_the_example_town_is_rocking_assess_of_it() {
    let dir = tempdir();
    let out = dir.path().join("out");
    example_town(&out, &[]);
    let (header, rows) = inventory_csv(&out);
    assert_eq!(rows.len(), 12);
    // The example's grid: the official one.
    let grid = Path::new("ntc2018");
    let towers = read(&root().join("examples/town/towers.csv"));
    let mut given = csv::Reader::from_reader(towers.as_bytes());
    let given_header: Vec<String> = given.headers().unwrap_or_else(|e| panic!("{e}")).iter().map(String::from).collect();
    for (input, row) in given.records().zip(&rows) {
        let input: Vec<String> = input.unwrap_or_else(|e| panic!("{e}")).iter().map(String::from).collect();
        let get = |name: &str| cell(&given_header, &input, name).to_string();
        // Input order, the identity as given.
        assert_eq!(cell(&header, row, "id"), get("id"));
        // The example's cells as an engineer would write each tower's file; empty cells are the town file's values.
        let or = |name: &str, default: &str| Some(get(name)).filter(|v| !v.is_empty()).unwrap_or_else(|| default.to_string());
        let mut text = tower_file(
            grid,
            number(&get("tower.width")),
            number(&get("tower.height")),
            number(&get("tower.mass")),
            &or("soil", "B"),
            number(&get("lon")),
            number(&get("lat")),
        );
        text = text.replace(
            "confidence_factor = 1.35",
            &format!("confidence_factor = {}", or("assessment.confidence_factor", "1.35")),
        );
        text = text.replace("[site]\n", &format!("[site]\ntopography = \"{}\"\n", or("topography", "T1")));
        assert_row_is_assess(&header, row, &assess(dir.path(), &get("id"), &text));
    }
}

#[test]
fn each_bad_row_gets_its_own_error_and_the_others_are_right() {
    let dir = tempdir();
    let grid = root().join("data/hazard/synthetic_grid.txt");
    let assess_file = write(dir.path(), "town.toml", &base(&grid));
    let towers = write(
        dir.path(),
        "towers.csv",
        "id,name,lon,lat,tower.width,tower.height,soil\n\
         A,good,14.34,41.06,5.0,30.0,\n\
         B,negative width,14.35,41.07,-4.0,30.0,\n\
         C,outside the grid,13.90,41.07,5.0,30.0,\n\
         D,not a number,14.36,41.08,5.0,tall,\n\
         A,the same id,14.37,41.09,5.0,30.0,\n\
         E,no lon,,41.09,5.0,30.0,\n\
         F,good on C,14.41,41.10,4.0,20.0,C\n",
    );
    let out = dir.path().join("out");
    let r = rocking(&["inventory", arg(&towers), "--assess", arg(&assess_file), "--out", arg(&out)]);
    // Bad input: exit 1, one line per bad row on stderr, the files written all the same.
    assert_eq!(r.code, Some(1), "{}", r.stderr);
    let (header, rows) = inventory_csv(&out);
    assert_eq!(rows.len(), 7);
    assert!(r.stderr.contains("5 of 7 towers with an error (in the error column of "), "{}", r.stderr);
    assert!(r.stderr.trim_end().ends_with("; the others are assessed"), "{}", r.stderr);
    let errors: Vec<&str> = rows.iter().map(|row| cell(&header, row, "error")).collect();
    let expect = [
        (1, "(id B), column tower.width (\"-4.0\"):", "-4"),
        (2, "(id C), column lon (\"13.90\"):", "outside"),
        (3, "(id D), column tower.height (\"tall\"):", "string"),
        (4, "(id A), column id:", "the same id as row 1"),
        (5, "(id E), column lon:", "missing"),
    ];
    for (i, column, what) in expect {
        let e = errors[i];
        assert!(e.contains(&format!("row {} {column}", i + 1)) && e.contains(what), "row {}: {e:?}", i + 1);
        assert!(!e.contains('\n'), "one line: {e:?}");
        assert!(r.stderr.contains(e), "{e:?} not on stderr: {}", r.stderr);
        assert_eq!(cell(&header, &rows[i], "zeta_E"), "");
    }
    let good_a = assess(dir.path(), "a", &tower_file(&grid, 5.0, 30.0, 4.0e5, "B", 14.34, 41.06));
    assert_row_is_assess(&header, &rows[0], &good_a);
    let good_f = assess(dir.path(), "f", &tower_file(&grid, 4.0, 20.0, 4.0e5, "C", 14.41, 41.10));
    assert_row_is_assess(&header, &rows[6], &good_f);
}

/// `text` rounded to `decimals`: the number its decimal text so rounded reads back as.
fn rounded(text: &str, decimals: usize) -> f64 {
    format!("{:.decimals$}", number(text)).parse().unwrap_or_else(|_| panic!("{text}"))
}

#[test]
fn the_geojson_reads_back_as_points_with_the_csv_properties() {
    let dir = tempdir();
    let out = dir.path().join("out");
    example_town(&out, &[]);
    let (header, rows) = inventory_csv(&out);
    let parsed: geojson::GeoJson = read(&out.join("inventory.geojson")).parse().unwrap_or_else(|e| panic!("{e}"));
    let geojson::GeoJson::FeatureCollection(collection) = parsed else {
        panic!("not a FeatureCollection")
    };
    assert_eq!(collection.features.len(), rows.len());
    // The inputs and the site's ag of each limit state are columns, as the tower was assessed with them.
    for name in [
        "tower.width",
        "tower.height",
        "soil",
        "topography",
        "tower.mass",
        "assessment.confidence_factor",
        "ag_SLD_g",
        "ag_SLV_g",
        "ag_SLC_g",
    ] {
        assert!(header.iter().any(|h| h == name), "no column {name} in {header:?}");
    }
    for (feature, row) in collection.features.iter().zip(&rows) {
        let Some(geojson::Value::Point(position)) = feature.geometry.as_ref().map(|g| &g.value) else {
            panic!("not a point: {feature:?}")
        };
        // RFC 7946: longitude first, in degrees, the value written in towers.csv to 6 decimals (a tenth of a metre).
        assert_eq!(position.len(), 2);
        assert_eq!(position[0].to_bits(), rounded(cell(&header, row, "lon"), 6).to_bits());
        assert_eq!(position[1].to_bits(), rounded(cell(&header, row, "lat"), 6).to_bits());
        assert_eq!(feature.id, Some(geojson::feature::Id::String(cell(&header, row, "id").to_string())));
        // An acceleration in g to 4 decimals, a ζ_E to 3: the CSV's full number so rounded.
        for (suffix, decimals) in [("_g", 4), ("zeta_E", 3)] {
            for name in header.iter().filter(|h| h.ends_with(suffix)) {
                let value = feature.property(name).and_then(|v| v.as_f64()).unwrap_or_else(|| panic!("no {name}"));
                assert_eq!(value.to_bits(), rounded(cell(&header, row, name), decimals).to_bits(), "{name}");
                // No more digits than those (the 17 of a double were the fault).
                let written = serde_json::to_string(feature.property(name).unwrap_or_else(|| panic!("{name}"))).unwrap_or_default();
                assert!(written.split('.').nth(1).is_none_or(|d| d.len() <= decimals), "{name}: {written}");
            }
        }
        // The inputs: a number as a number, a category as text; an empty cell takes the assessment file's value.
        let given = |name: &str| feature.property(name).unwrap_or_else(|| panic!("no {name}"));
        assert_eq!(
            given("tower.width").as_f64().map(f64::to_bits),
            Some(number(cell(&header, row, "tower.width")).to_bits())
        );
        assert_eq!(
            given("tower.height").as_f64().map(f64::to_bits),
            Some(number(cell(&header, row, "tower.height")).to_bits())
        );
        assert_eq!(given("soil").as_str(), Some(cell(&header, row, "soil")));
        assert_eq!(
            given("zeta_E_is_lower_bound").as_bool(),
            Some(cell(&header, row, "zeta_E_is_lower_bound") == "true")
        );
        assert_eq!(feature.property("governing").and_then(|v| v.as_str()), Some(cell(&header, row, "governing")));
        assert_eq!(feature.property("name").and_then(|v| v.as_str()), Some(cell(&header, row, "name")));
        assert!(feature.property("error").is_some_and(|v| v.is_null()));
    }
    // The example's file leaves soil and topography empty on some rows: the assessment file's values fill them.
    let (given_header, given_rows) = csv_table(&root().join("examples/town/towers.csv"));
    let assess: toml::Table = read(&root().join("examples/town/assess.toml")).parse().unwrap_or_else(|e| panic!("{e}"));
    let site = |key: &str| assess["site"][key].as_str().unwrap_or_else(|| panic!("site.{key}")).to_string();
    for (input, row) in given_rows.iter().zip(&rows) {
        for (name, default) in [("soil", site("soil")), ("topography", site("topography"))] {
            let default = default.as_str();
            let cell_given = cell(&given_header, input, name);
            assert_eq!(cell(&header, row, name), if cell_given.is_empty() { default } else { cell_given });
        }
    }
}

#[test]
fn fields_csv_gives_every_property_a_name_a_shapefile_keeps() {
    let dir = tempdir();
    let out = dir.path().join("out");
    example_town(&out, &[]);
    let (header, _) = inventory_csv(&out);
    let (fields_header, fields) = csv_table(&out.join("fields.csv"));
    assert_eq!(fields_header, ["property", "alias"]);
    // Every property of the GeoJSON (every column but the point's lon, lat), in order.
    let properties: Vec<&String> = header.iter().filter(|h| *h != "lon" && *h != "lat").collect();
    assert_eq!(fields.iter().map(|f| &f[0]).collect::<Vec<_>>(), properties);
    // dBase: at most 10 bytes of ASCII letters, digits and _, a letter first, distinct without regard to case.
    let mut seen = std::collections::HashSet::new();
    for f in &fields {
        let alias = &f[1];
        assert!(alias.len() <= 10 && alias.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_'), "{alias}");
        assert!(alias.bytes().next().is_some_and(|b| b.is_ascii_alphabetic()), "{alias}");
        assert!(seen.insert(alias.to_ascii_lowercase()), "{alias} twice");
    }
    // The names of the checks as written by hand in the docs (guide/town.md).
    let alias = |name: &str| {
        fields
            .iter()
            .find(|f| f[0] == name)
            .map(|f| f[1].as_str())
            .unwrap_or_else(|| panic!("no {name}"))
    };
    assert_eq!(alias("SLD_activation_ag_capacity_g"), "SLD_act_ag");
    assert_eq!(alias("SLV_linear_kinematic_zeta_E"), "SLV_lk_z");
    assert_eq!(alias("SLC_nonlinear_kinematic_zeta_E"), "SLC_nk_z");
    assert_eq!(alias("zeta_E_is_lower_bound"), "zeta_E_lb");
    assert_eq!(alias("assessment.confidence_factor"), "c_factor");
    assert_eq!(alias("tower.height"), "height");
    // It is the run's own: the folder's manifest lists it.
    assert!(read(&out.join(".rocking-manifest")).lines().any(|l| l == "fields.csv"));
}

#[test]
fn one_three_and_seven_shards_merge_to_the_unsharded_files() {
    let dir = tempdir();
    let whole = dir.path().join("whole");
    example_town(&whole, &[]);
    let shard = |k: usize, n: usize, parts: &Path| {
        let out = parts.join(k.to_string());
        example_town(&out, &["--shard", &format!("{k}/{n}")]);
        out
    };
    let check_shard = |k: usize, n: usize, out: &Path| {
        // Shard k of n holds rows floor((k−1)·12/n) … floor(k·12/n) − 1.
        let rows = read(&out.join("inventory.csv")).lines().count() - 1;
        assert_eq!(rows, k * 12 / n - (k - 1) * 12 / n, "shard {k}/{n}");
    };
    assert_shards_merge_to_whole(
        dir.path(),
        &whole,
        &["inventory.csv", "inventory.geojson", "fields.csv"],
        &[1, 3, 7],
        shard,
        check_shard,
    );
}

#[test]
fn details_write_each_towers_assessment_linked_from_the_report() {
    let dir = tempdir();
    let out = dir.path().join("out");
    example_town(&out, &["--details"]);
    let (header, rows) = inventory_csv(&out);
    let report = read(&out.join("report.html"));
    for row in &rows {
        let id = cell(&header, row, "id");
        let folder = out.join("towers").join(id);
        // The tower's own files, as `rocking assess` writes them; its governing ζ_E that of its row.
        for file in ["assessment.json", "capacity.csv", "report.html"] {
            assert!(folder.join(file).is_file(), "no {file} for {id}");
        }
        let json: serde_json::Value = serde_json::from_str(&read(&folder.join("assessment.json"))).unwrap_or_else(|e| panic!("{e}"));
        let zeta = json["governing"]["zeta_E"].as_f64().unwrap_or_else(|| panic!("no governing ζ_E for {id}"));
        assert_eq!(zeta.to_bits(), number(cell(&header, row, "zeta_E")).to_bits(), "{id}");
        assert!(report.contains(&format!("href=\"towers/{id}/report.html\"")), "no link to {id}'s page");
    }
}

#[test]
fn with_a_record_set_the_dynamic_checks_are_those_of_rocking_assess() {
    let dir = tempdir();
    let grid = root().join("data/hazard/synthetic_grid.txt");
    let records = root().join("data/records/synthetic");
    // Three records (the fewest a set may have) and a coarse λ scan: the checks
    // are run in full, only with fewer runs than the defaults.
    let assessment = format!(
        "[assessment]\nconfidence_factor = 1.35\nrecords = ['{0}/kt_01.AT2', '{0}/kt_02.AT2', '{0}/kt_03.AT2']\nlambda = {{ from = 0.5, to = 3.0, step = 0.5 }}\n",
        records.display()
    );
    let town = base(&grid).replace("[assessment]\nconfidence_factor = 1.35\n", &assessment);
    let assess_file = write(dir.path(), "town.toml", &town);
    let towers = write(
        dir.path(),
        "towers.csv",
        "id,name,lon,lat,tower.width,tower.height,soil\nA,slender,14.34,41.06,3.6,30.0,\nB,stocky on C,14.41,41.10,5.0,20.0,C\n",
    );
    let out = dir.path().join("out");
    let r = rocking(&["inventory", arg(&towers), "--assess", arg(&assess_file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let (header, rows) = inventory_csv(&out);
    for state in ["SLV", "SLC"] {
        assert!(header.contains(&format!("{state}_nonlinear_dynamic_zeta_E")), "{header:?}");
    }
    let file = |width: f64, height: f64, soil: &str, lon: f64, lat: f64| {
        tower_file(&grid, width, height, 4.0e5, soil, lon, lat).replace("[assessment]\nconfidence_factor = 1.35\n", &assessment)
    };
    assert_row_is_assess(&header, &rows[0], &assess(dir.path(), "a", &file(3.6, 30.0, "B", 14.34, 41.06)));
    assert_row_is_assess(&header, &rows[1], &assess(dir.path(), "b", &file(5.0, 20.0, "C", 14.41, 41.10)));
}
