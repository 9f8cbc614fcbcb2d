//! Regression (issue 47, item 4): the λ figures of the dynamic checks said
//! "fails at λ = 1.995" with a mean response far below d_LS, without saying
//! that a record had reached d0 there, nor which. The failing marker now
//! names the records that reach d0, or says that the set's response is
//! beyond d_LS. Checked here against `rocking run` of each record at the
//! failing λ: the one named overturns, the others do not.

use crate::assess::{synthetic_records, tower_on_b};
use crate::util::{arg, read, rocking, tempdir, write};
use serde_json::Value;

/// A slender tower (1.5 m × 12 m) of the tests' file, the three synthetic records, λ from 0.5 to 4.
fn slender_with_records() -> String {
    tower_on_b().replace("width = 4.0", "width = 1.5") + "records = [\"records/*.AT2\"]\nfree_after = 2.0\nlambda = { from = 0.5, to = 4.0, step = 0.5 }\n"
}

#[test]
fn the_failing_lambda_names_the_record_that_reached_d0() {
    let dir = tempdir();
    synthetic_records(dir.path(), "records");
    let file = write(dir.path(), "slender.toml", &slender_with_records());
    let out = dir.path().join("out");
    let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let json: Value = serde_json::from_str(&read(&out.join("assessment.json"))).unwrap_or_else(|e| panic!("{e}"));
    let report = read(&out.join("report.html"));
    let dynamic = json["dynamic"].as_array().unwrap_or_else(|| panic!("no dynamic checks"));
    let mut named = 0;
    for d in dynamic {
        let state = d["limit_state"].as_str().unwrap_or_default();
        let fails = d["lambda_fails"].as_f64().unwrap_or_else(|| panic!("{state}: no failing λ"));
        let scales: Vec<f64> = d["scales"]
            .as_array()
            .unwrap_or_else(|| panic!("no scales"))
            .iter()
            .filter_map(Value::as_f64)
            .collect();
        let records: Vec<&str> = d["records"]
            .as_array()
            .unwrap_or_else(|| panic!("no records"))
            .iter()
            .filter_map(Value::as_str)
            .collect();
        // Each record at the failing λ through the plain simulation: the
        // record's 2001 samples at 0.01 s (20 s) and free_after's 2 s, as the check runs it.
        let overturns: Vec<bool> = records
            .iter()
            .zip(&scales)
            .map(|(record, scale)| {
                let scenario = format!(
                    "name = \"one record\"\n[tower]\nwidth = 1.5\nheight = 12.0\nmass = 1.5e5\n[ground]\ntype = \"record\"\nfile = \"{record}\"\nscale = {:?}\n[simulation]\nduration = 22.0\n",
                    fails * scale
                );
                let run_file = write(dir.path(), "one.toml", &scenario);
                let run_out = dir.path().join("run");
                let r = rocking(&["run", arg(&run_file), "--out", arg(&run_out)]);
                assert_eq!(r.code, Some(0), "{}", r.stderr);
                let summary: Value = serde_json::from_str(&read(&run_out.join("summary.json"))).unwrap_or_else(|e| panic!("{e}"));
                summary["overturned"].as_bool().unwrap_or_else(|| panic!("no overturned"))
            })
            .collect();
        // The label of the figure: "fails at λ = <4 digits>: <why>".
        let label = format!("fails at λ = {}", format_sig4(fails));
        let at = report.find(&label).unwrap_or_else(|| panic!("{state}: no {label:?} in the report"));
        let text = report[at..at + report[at..].find('<').unwrap_or(0)].trim();
        let overturned: Vec<&str> = records
            .iter()
            .zip(&overturns)
            .filter(|(_, o)| **o)
            .map(|(r, _)| r.rsplit('/').next().unwrap_or(r))
            .collect();
        match overturned.as_slice() {
            [] => assert!(text.contains("response") && text.contains(&format!("beyond d_{state}")), "{state}: {text}"),
            [one] => {
                assert!(text.ends_with(&format!(": {one} reaches d0")), "{state}: {text}");
                named += 1;
            }
            more => assert!(more.iter().all(|r| text.contains(r)) && text.ends_with("reach d0"), "{state}: {text}"),
        }
    }
    // The example's SLC check fails where one record overturns (kt_02, at λ ≈ 1.995).
    assert!(named >= 1, "no check failed on a record reaching d0: the test would not see the fault");
}

/// `x` to 4 significant digits as the report writes them (1.995, 1.425).
fn format_sig4(x: f64) -> String {
    let digits = 3 - x.abs().log10().floor() as i32;
    let text = format!("{:.*}", digits.max(0) as usize, x);
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}
