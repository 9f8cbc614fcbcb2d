//! Regression: `rocking spectrum` on a CSV record of one (acceleration)
//! column said the file "needs `dt`", but the command had no way to give it.
//! It now takes `--dt` and `--units`, as `[ground]` and `[assessment]` do.

use crate::util::{arg, csv_table, rocking_in, tempdir, write};
use rocking_scenario::DEFAULT_G;

/// A short record, m/s²: a few cycles of a decaying sine, 400 samples.
fn values() -> Vec<f64> {
    (0..400).map(|k| (f64::from(k) * 0.3).sin() * (-f64::from(k) / 150.0).exp()).collect()
}

/// The columns of `spectra.csv` in `out` after the period column, each value's bits.
fn spectra_bits(dir: &std::path::Path, out: &str) -> Vec<Vec<u64>> {
    let (_, rows) = csv_table(&dir.join(out).join("spectra.csv"));
    rows.iter()
        .map(|row| row.iter().map(|v| v.parse::<f64>().unwrap_or_else(|e| panic!("{v}: {e}")).to_bits()).collect())
        .collect()
}

#[test]
fn a_one_column_csv_record_takes_dt_and_units() {
    let dir = tempdir();
    let dt = 0.01;
    let values = values();
    let one: String = values.iter().map(|a| format!("{a}\n")).collect();
    // The same samples with their times, written so that each reads back as
    // the k·dt the one-column reader computes (Display is the shortest text
    // that parses back to the same f64).
    let two: String = std::iter::once("time,acceleration\n".to_string())
        .chain(values.iter().enumerate().map(|(k, a)| format!("{},{a}\n", k as f64 * dt)))
        .collect();
    let one_path = write(dir.path(), "one.csv", &one);
    let two_path = write(dir.path(), "two.csv", &two);

    // Without --dt: one line naming the file and the missing time step.
    let r = rocking_in(dir.path(), &["spectrum", arg(&one_path), "--out", "none"]);
    assert_eq!(r.code, Some(1), "{}", r.stderr);
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
    assert!(r.stderr.contains("one.csv") && r.stderr.contains("`dt`"), "{}", r.stderr);

    // With --dt, the spectrum of the one-column file is that of the same
    // samples given with their times, bit for bit (same record, same code).
    let r = rocking_in(dir.path(), &["spectrum", arg(&one_path), "--dt", "0.01", "--units", "m/s2", "--out", "one"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let r = rocking_in(dir.path(), &["spectrum", arg(&two_path), "--units", "m/s2", "--out", "two"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let one_bits = spectra_bits(dir.path(), "one");
    assert_eq!(one_bits.len(), 100, "the default grid of 100 periods");
    assert_eq!(one_bits, spectra_bits(dir.path(), "two"));

    // --units: the same numbers read as g (the default) give a spectrum g
    // (DEFAULT_G, m/s²) times that in m/s², the response being linear in the
    // record. Tolerance 1e-12 relative: the two are computed separately and
    // differ by the rounding of a few thousand operations (~1e-15 each).
    let r = rocking_in(dir.path(), &["spectrum", arg(&one_path), "--dt", "0.01", "--out", "g"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let (_, in_g) = csv_table(&dir.path().join("g/spectra.csv"));
    let (_, in_si) = csv_table(&dir.path().join("one/spectra.csv"));
    for (a, b) in in_g.iter().zip(&in_si) {
        let (a, b): (f64, f64) = (a[1].parse().unwrap_or(f64::NAN), b[1].parse().unwrap_or(f64::NAN));
        assert!((a - DEFAULT_G * b).abs() <= 1e-12 * a.abs(), "{a} g vs {b} g × {DEFAULT_G}");
    }

    // --dt is refused when it is not a time step, and --units when not a unit.
    for bad in [["--dt", "0"], ["--dt", "-0.01"], ["--units", "ms"]] {
        let r = rocking_in(dir.path(), &["spectrum", arg(&one_path), bad[0], bad[1], "--out", "none"]);
        assert_eq!(r.code, Some(2), "{bad:?}: a usage error; {}", r.stderr);
        assert!(r.stderr.contains(bad[0]), "{}", r.stderr);
    }
    assert!(!dir.path().join("none").exists(), "nothing written for a refused record");
}
