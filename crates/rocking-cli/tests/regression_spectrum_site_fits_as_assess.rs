//! Regression (issue 46, item 4): `rocking spectrum --site` fitted the record
//! set over 0.15–2 s while `rocking assess` of the same file fits it over the
//! range stretched to the longest T_SLC of the tower's mechanisms (5.45 s for
//! the tests' tower), so that an engineer documented scales the checks never
//! used. With a [tower] in the file, the spectrum now fits as the assessment
//! does: the same range and the same scales, to the bit (the same periods
//! and the same arithmetic), checked here against the assessment's own
//! records.csv and assessment.json.

use crate::assess::{synthetic_records, tower_on_b};
use crate::util::{arg, csv_table, read, rocking, tempdir, write};

#[test]
fn the_spectrum_of_an_assessment_file_fits_as_the_assessment() {
    let dir = tempdir();
    synthetic_records(dir.path(), "records");
    let text = tower_on_b() + "records = [\"records/*.AT2\"]\nfree_after = 2.0\nlambda = { from = 0.5, to = 1.0, step = 0.5 }\n";
    let file = write(dir.path(), "assess.toml", &text);
    let (spectrum, assess) = (dir.path().join("spectrum"), dir.path().join("assess"));
    let r = rocking(&["spectrum", "--site", arg(&file), "--out", arg(&spectrum)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let r = rocking(&["assess", arg(&file), "--out", arg(&assess)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);

    let json: serde_json::Value = read(&assess.join("assessment.json")).parse().unwrap_or_else(|e| panic!("{e}"));
    let range = &json["dynamic"][0]["period_range_s"];
    let upper = range[1].as_f64().unwrap_or(f64::NAN);
    assert!(upper > 2.0, "the assessment's range is stretched beyond 2 s: {range}");
    let (fit_header, fits) = csv_table(&spectrum.join("fit.csv"));
    let (rec_header, records) = csv_table(&assess.join("records.csv"));
    let col = |h: &[String], name: &str| h.iter().position(|x| x == name).unwrap_or_else(|| panic!("no {name}"));
    let scales = |rows: &[Vec<String>], h: &[String]| -> Vec<(String, String)> {
        rows.iter().map(|r| (r[col(h, "limit_state")].clone(), r[col(h, "scale")].clone())).collect()
    };
    assert_eq!(fits.len(), 6);
    assert_eq!(scales(&fits, &fit_header), scales(&records, &rec_header));
    // The spectrum says the range it fitted over: the assessment's.
    let listed = read(&spectrum.join("fit.json"));
    assert!(listed.contains(&format!("{upper}")), "fit.json does not give {upper}: {listed}");
}
