//! `rocking spectrum`: the records' spectra against a closed form, the code
//! spectra and the fitted set of an assessment file against hand values and
//! against each other, and the refusals (exit 1, one line naming the key).

use crate::util::{arg, read, rocking, tempdir, write};
use std::path::Path;

/// The columns of a CSV file by name.
fn columns(path: &Path) -> Vec<(String, Vec<f64>)> {
    let text = read(path);
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap_or_default().split(',').map(String::from).collect();
    let mut out: Vec<(String, Vec<f64>)> = header.into_iter().map(|h| (h, Vec::new())).collect();
    for line in lines {
        for (k, field) in line.split(',').enumerate() {
            out[k].1.push(field.parse().unwrap_or_else(|e| panic!("{field}: {e}")));
        }
    }
    out
}

fn column<'a>(cols: &'a [(String, Vec<f64>)], name: &str) -> &'a [f64] {
    cols.iter()
        .find(|(n, _)| n == name)
        .map(|(_, v)| v.as_slice())
        .unwrap_or_else(|| panic!("no column {name}"))
}

#[test]
fn an_undamped_step_peaks_at_twice_the_ground_acceleration() {
    // 0.3 g held for 0.4 s: an undamped oscillator whose half period fits in the
    // pulse peaks at x = 2a/ω² at t = T/2, a sample instant for T = 0.2 s and 0.5 s.
    let dir = tempdir();
    let rows: String = (0..=80).map(|k| format!("{},0.3\n", 0.005 * k as f64)).collect();
    let record = write(dir.path(), "step.csv", &format!("time,acceleration\n{rows}"));
    let out = dir.path().join("out");
    let o = rocking(&["spectrum", arg(&record), "--damping", "0", "--periods", "0.2,0.5,3", "--out", arg(&out)]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    let cols = columns(&out.join("spectra.csv"));
    assert_eq!(cols.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(), ["period_s", "step.csv"]);
    let psa = column(&cols, "step.csv");
    // The samples k·0.005 s land on T/2 to an ulp: cos(ω·ulp) = 1 − 1e-26.
    assert!((psa[0] - 0.6).abs() < 1e-9, "{}", psa[0]);
    assert!((psa[2] - 0.6).abs() < 1e-9, "{}", psa[2]);
    // T = 0.316 s: T/2 falls between samples 0.005 s apart: cos(ω·0.0025) ≥ 1 − 1.3e-3.
    assert!(psa[1] <= 0.6 + 1e-12 && psa[1] >= 0.6 * (1.0 - 1.3e-3), "{}", psa[1]);
    assert!(o.stdout.contains("step.csv: PGA 0.3 g"), "{}", o.stdout);
}

#[test]
fn site_spectra_and_the_fitted_set() {
    let dir = tempdir();
    let out = dir.path().join("out");
    let site = crate::util::example("spectra/site.toml");
    let o = rocking(&["spectrum", "--site", arg(&site), "--out", arg(&out)]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    let cols = columns(&out.join("spectra.csv"));
    let periods = column(&cols, "period_s");
    assert_eq!(periods.len(), 100);
    // The SLV plateau on B: SS = 1.40 − 0.40·2.47·0.155 = 1.247 clamped to 1.20;
    // Se = ag SS F0 = 0.155·1.2·2.47 between TB and TC (0.127–0.381 s); T = 0.2 s is there.
    let k = periods.iter().position(|&t| t > 0.2).unwrap_or_else(|| panic!("no period above 0.2 s"));
    assert!((column(&cols, "Se_SLV_g")[k] - 0.155 * 1.2 * 2.47).abs() < 1e-12);
    // At 8%: η = sqrt(10/13).
    assert!((column(&cols, "Se_SLV_8pct_g")[k] - 0.155 * 1.2 * 2.47 * (10.0f64 / 13.0).sqrt()).abs() < 1e-12);
    // SDe = Se (T/2π)² below TE.
    let sde = column(&cols, "SDe_SLV_m")[k];
    let se = column(&cols, "Se_SLV_g")[k];
    assert!((sde - se * 9.81 * (periods[k] / (2.0 * std::f64::consts::PI)).powi(2)).abs() < 1e-15);

    // fit.csv: 12 records per limit state; the scaled PGA is the scale times the record's.
    let fit = read(&out.join("fit.csv"));
    let rows: Vec<Vec<&str>> = fit.lines().skip(1).map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 24);
    let elcentro = rows
        .iter()
        .find(|r| r[0] == "SLV" && r[1] == "elcentro_1940_ns.AT2")
        .unwrap_or_else(|| panic!("{fit}"));
    let scale: f64 = elcentro[2].parse().unwrap_or(f64::NAN);
    let pga: f64 = elcentro[3].parse().unwrap_or(f64::NAN);
    assert!((pga - scale * 0.31882).abs() < 1e-12 * pga.abs().max(1.0), "{pga} {scale}");

    // fit.json's ratios are those of the mean over the target on 0.15–2 s in spectra.csv.
    let json: serde_json::Value = serde_json::from_str(&read(&out.join("fit.json"))).unwrap_or_else(|e| panic!("{e}"));
    for state in ["SLV", "SLC"] {
        let mean = column(&cols, &format!("PSA_{state}_mean_g"));
        let target = column(&cols, &format!("Se_{state}_g"));
        let ratios: Vec<f64> = (0..periods.len())
            .filter(|&k| (0.15..=2.0).contains(&periods[k]))
            .map(|k| mean[k] / target[k])
            .collect();
        let least = ratios.iter().copied().fold(f64::INFINITY, f64::min);
        let greatest = ratios.iter().copied().fold(0.0, f64::max);
        let s = &json[state];
        // Both from the same doubles: the same to the last digit of the shortest form.
        assert!((s["least_ratio"].as_f64().unwrap_or(f64::NAN) - least).abs() < 1e-14);
        assert!((s["greatest_ratio"].as_f64().unwrap_or(f64::NAN) - greatest).abs() < 1e-14);
        assert_eq!(s["holds"].as_bool(), Some(least >= 0.9 && greatest <= 1.3));
        assert_eq!(s["combination"].as_str(), Some("mean"));
    }
}

#[test]
fn plots_are_drawn() {
    let dir = tempdir();
    let out = dir.path().join("out");
    let o = rocking(&[
        "spectrum",
        "--site",
        arg(&crate::util::example("spectra/site.toml")),
        "--out",
        arg(&out),
        "--plot",
        "--periods",
        "0.05,3,30",
    ]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    for f in [
        "code_spectra.svg",
        "code_spectra.png",
        "fit_SLV.svg",
        "fit_SLV.png",
        "fit_SLC.svg",
        "fit_SLC.png",
    ] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
}

/// Runs `rocking spectrum args…` in `dir` and returns its one line of stderr, asserting exit 1.
fn refused(dir: &Path, args: &[&str]) -> String {
    let mut all = vec!["spectrum"];
    all.extend(args);
    let out = dir.join("out");
    all.extend(["--out", arg(&out)]);
    let o = crate::util::rocking_in(dir, &all);
    assert_eq!(o.code, Some(1), "stdout {} stderr {}", o.stdout, o.stderr);
    assert_eq!(o.stderr.lines().count(), 1, "{}", o.stderr);
    assert!(!out.join("spectra.csv").exists());
    o.stderr
}

/// `count` copies of El Centro in `dir/rec/`: `r0.AT2`, `r1.AT2`, …
fn el_centro_copies(dir: &Path, count: usize) {
    let elcentro = crate::util::root().join("data/records/elcentro_1940_ns.AT2");
    std::fs::create_dir_all(dir.join("rec")).unwrap_or_else(|e| panic!("{e}"));
    for k in 0..count {
        std::fs::copy(&elcentro, dir.join(format!("rec/r{k}.AT2"))).unwrap_or_else(|e| panic!("{e}"));
    }
}

const SLV: &str = "[site.SLV]\nag = 0.155\nF0 = 2.47\nTc_star = 0.36\n";

#[test]
fn bad_input_is_one_line_naming_the_key() {
    let dir = tempdir();
    let root = crate::util::root();
    let elcentro = root.join("data/records/elcentro_1940_ns.AT2");
    let d = dir.path();
    assert!(refused(d, &[arg(&elcentro), "--damping", "-5"]).contains("--damping: must be a percentage of critical in [0, 100), got -5"));
    assert!(refused(d, &[arg(&elcentro), "--periods", "4,0.02,100"]).contains("--periods: need 0 < FROM < TO"));
    assert!(refused(d, &[arg(&elcentro), "--periods", "0.1,1"]).contains("--periods: expected FROM,TO,N"));
    write(d, "soil.toml", &format!("[site]\nsoil = \"Z\"\n{SLV}"));
    assert!(refused(d, &["--site", "soil.toml"]).contains("soil.toml: site.soil: unknown category \"Z\""));
    write(d, "neg.toml", "[site]\nsoil = \"B\"\n[site.SLV]\nag = 0.155\nF0 = -2.47\nTc_star = 0.36\n");
    assert!(refused(d, &["--site", "neg.toml"]).contains("neg.toml: site.SLV.F0: must be a finite number > 0"));
    // The records of these cases: three copies of El Centro.
    el_centro_copies(d, 3);
    write(
        d,
        "range.toml",
        &format!("[site]\nsoil = \"B\"\n{SLV}[assessment]\nrecords = [\"rec/*.AT2\"]\nperiod_range = [0.15, 5.0]\n"),
    );
    assert!(refused(d, &["--site", "range.toml"]).contains("period_range: [0.15, 5] s is outside the periods of the spectra, 0.02 to 4 s"));
    write(
        d,
        "empty.toml",
        &format!("[site]\nsoil = \"B\"\n{SLV}[assessment]\nrecords = [\"nothing/*.AT2\"]\n"),
    );
    assert!(refused(d, &["--site", "empty.toml"]).contains("empty.toml: assessment.records: no file matches \"nothing/*.AT2\""));
    write(
        d,
        "two.toml",
        &format!("[site]\nsoil = \"B\"\n{SLV}[assessment]\nrecords = [\"rec/r0.AT2\", \"rec/r1.AT2\"]\n"),
    );
    assert!(refused(d, &["--site", "two.toml"]).contains("needs at least 3 records"));
    let grid = root.join("data/hazard/synthetic_grid.txt");
    write(
        d,
        "far.toml",
        &format!("[site]\nsoil = \"B\"\ngrid = \"{}\"\nlon = 12.0\nlat = 41.0\n", arg(&grid)),
    );
    assert!(refused(d, &["--site", "far.toml"]).contains("far.toml: site.lon: the site (lon 12, lat 41) is outside the hazard grid"));
    // A grid with a return period missing on a row.
    let text = read(&grid);
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let fields: Vec<&str> = lines[5].split('\t').collect();
    lines[5] = fields[..fields.len() - 3].join("\t");
    write(d, "cut.txt", &(lines.join("\n") + "\n"));
    write(d, "cut.toml", "[site]\nsoil = \"B\"\ngrid = \"cut.txt\"\nlon = 14.4\nlat = 41.0\n");
    let line = refused(d, &["--site", "cut.toml"]);
    assert!(
        line.contains("cut.toml: site.grid: ")
            && line.contains("cut.txt: line 6: expected 30 columns")
            && line.contains("a return period's ag, F0, Tc* are missing"),
        "{line}"
    );
}

#[test]
fn three_records_warn_that_the_largest_response_is_used() {
    let dir = tempdir();
    let d = dir.path();
    el_centro_copies(d, 3);
    write(
        d,
        "three.toml",
        &format!("[site]\nsoil = \"B\"\n{SLV}[assessment]\nrecords = [\"rec/*.AT2\"]\n"),
    );
    let o = crate::util::rocking_in(d, &["spectrum", "--site", "three.toml", "--out", "out"]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert!(
        o.stderr.starts_with("warning: three.toml: 3 records: the checks will use the largest response"),
        "{}",
        o.stderr
    );
    // Three copies of one record: one scale, and the mean is that record scaled.
    let fit = read(&d.join("out/fit.csv"));
    let scales: Vec<&str> = fit.lines().skip(1).map(|l| l.split(',').nth(2).unwrap_or("")).collect();
    assert_eq!(scales.len(), 3);
    assert!(scales.iter().all(|s| *s == scales[0]), "{fit}");
}
