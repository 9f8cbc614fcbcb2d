//! The page's dynamic checks against `rocking assess`'s path: the same
//! assessment with its record set given as files (read from disk, as the
//! command reads them) and as texts with their names (as the page gives the
//! files a user picks) gives the same `assessment.json`, `records.csv` and
//! `spectra.csv`, to the last bit: both reach the same reader and the same
//! checks. The progress told along the way counts every record's run.

#![allow(clippy::unwrap_used)]

use rocking_assess::{Assessment, AssessmentInput};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

const RECORDS: [&str; 3] = ["records/synthetic/kt_01.AT2", "records/synthetic/kt_02.AT2", "records/synthetic/kt_03.AT2"];

/// The assessment tests' tower (crates/rocking-assess/tests/data/tower_on_b.toml)
/// as a slender block 1 m × 5 m, so that it rocks under the synthetic records,
/// with a short λ scan (a test's run, not an engineer's).
fn file_text() -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../rocking-assess/tests/data/tower_on_b.toml");
    let file = std::fs::read_to_string(path).unwrap();
    let from = "width = 4.0\nheight = 12.0\nmass = 1.5e5\n";
    assert!(file.contains(from), "tower_on_b.toml has no {from:?}");
    // [assessment] is the file's last table.
    file.replace(from, "width = 1.0\nheight = 5.0\nmass = 1.0e4\n") + "free_after = 2.0\nlambda = { from = 0.5, to = 4.0, step = 0.5 }\n"
}

/// Where the file is taken to be: the records are relative to it.
fn origin() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/assess.toml")
}

#[test]
fn records_given_as_text_give_the_commands_numbers() {
    // The command's path: the records as files.
    let with_files = format!("{}records = {}\n", file_text(), json!(RECORDS));
    let input = AssessmentInput::from_toml_str(&with_files, &origin()).unwrap();
    let command = Assessment::run(&input).unwrap();
    let expected = command.json(&input);
    let (records_csv, spectra_csv) = command.set_csvs().unwrap();

    // The page's: the same table as JSON, each record's text given with its name.
    let mut table: Value = serde_json::to_value(rocking_scenario::parse_toml(&file_text(), &origin()).unwrap()).unwrap();
    let folder = origin().parent().unwrap().to_path_buf();
    table["assessment"]["records"] = RECORDS
        .iter()
        .map(|r| json!({ "name": r, "text": std::fs::read_to_string(folder.join(r)).unwrap() }))
        .collect();
    let ticks = Mutex::new(Vec::new());
    let out = rocking_web::assess_dynamic_json(&table.to_string(), &|done, most| ticks.lock().unwrap().push((done, most))).unwrap();
    let mut page: Value = serde_json::from_str(&out).unwrap();
    let map = page.as_object_mut().unwrap();
    assert_eq!(map.remove("records_csv"), Some(json!(records_csv)));
    assert_eq!(map.remove("spectra_csv"), Some(json!(spectra_csv)));
    assert!(map.remove("curve").is_some());
    // One curve per mechanism: a tower alone has one.
    assert_eq!(map.remove("curves").and_then(|c| c.as_array().map(Vec::len)), Some(1));
    // The chart's points of the one mechanism: d_SLV, d_SLC and the demands of
    // the two non-linear kinematic and the two dynamic checks.
    assert_eq!(map.remove("adrs").and_then(|c| c[0].as_array().map(Vec::len)), Some(6));
    // The rows of records.csv as objects: one per limit state and record.
    let responses = map.remove("responses").unwrap();
    assert_eq!(responses.as_array().map(Vec::len), Some(2 * RECORDS.len()));
    assert_eq!(records_csv.lines().count(), 1 + 2 * RECORDS.len());
    // The name: the command's is the file stem, the page's that of its origin.
    let mut expected = expected;
    expected["name"] = page["name"].clone();
    assert_eq!(page, expected);
    // The check ran somewhere interesting: a failure inside the scan, bisected.
    assert!(page["dynamic"][0]["lambda_fails"].is_number(), "{}", page["dynamic"][0]);

    // Every run told once, in order: the set at λ = 1, each λ of the scan and
    // each of the bisection, for both checks (counted from the outputs).
    let runs: usize = page["dynamic"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| RECORDS.len() * (1 + d["scan"].as_array().unwrap().len()))
        .sum();
    let ticks = ticks.into_inner().unwrap();
    assert_eq!(ticks.len(), runs);
    assert!(ticks.iter().enumerate().all(|(i, &(done, most))| done == i + 1 && done <= most), "{ticks:?}");
}

#[test]
fn records_given_as_text_are_checked_as_keys() {
    let table = |records: Value| {
        let mut t: Value = serde_json::to_value(rocking_scenario::parse_toml(&file_text(), &origin()).unwrap()).unwrap();
        t["assessment"]["records"] = records;
        rocking_web::assess_dynamic_json(&t.to_string(), &|_, _| {}).err().unwrap_or_default()
    };
    let text = "not a record";
    let e = table(json!([{ "name": "a.AT2", "text": text }, "records/*.AT2"]));
    assert!(e.starts_with("assess.toml: assessment.records[1]: expected a table { name, text }"), "{e}");
    let e = table(json!([{ "name": "a.AT2" }]));
    assert!(e.starts_with("assess.toml: assessment.records[0].text: "), "{e}");
    let e = table(json!([{ "name": "a.AT2", "text": text, "scale": 2 }]));
    assert!(e.starts_with("assess.toml: assessment.records[0].scale: "), "{e}");
    let e = table(json!([{ "name": "a.AT2", "text": text }, { "name": "a.AT2", "text": text }, { "name": "b.AT2", "text": text }]));
    assert_eq!(e, "assess.toml: assessment.records[1].name: \"a.AT2\" is given twice");
    // A record that cannot be read is named, as a file that cannot be is.
    let e = table(json!([{ "name": "a.AT2", "text": text }, { "name": "b.AT2", "text": text }, { "name": "c.AT2", "text": text }]));
    assert!(e.starts_with("assess.toml: assessment.records: a.AT2: cannot tell the format"), "{e}");
    let e = table(json!([{ "name": "a.AT2", "text": text }]));
    assert!(e.starts_with("assess.toml: assessment.records: a record set needs at least 3 records"), "{e}");
}
