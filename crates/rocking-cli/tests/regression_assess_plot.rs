//! Regression (issue 47, item 4): `rocking assess --plot` exited 2 (no such
//! option) while `inventory` and `spectrum` take it. It now writes the
//! report's figures beside it, SVG and PNG, listed in the folder's manifest
//! (so that a later run without `--plot` removes them).

use super::regression_belfry_d0_row::belfry_report;
use crate::util::{read, tempdir};

/// The width and height of a PNG from its IHDR chunk (bytes 16–23, big-endian: the PNG specification).
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "not a PNG");
    let word = |at: usize| u32::from_be_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    (word(16), word(20))
}

#[test]
fn assess_plot_writes_the_reports_figures_beside_it() {
    let dir = tempdir();
    belfry_report(dir.path(), &["--plot"]);
    let out = dir.path().join("out");
    // Without records: one ADRS figure per mechanism, the tower's and the belfry's.
    for stem in ["report_adrs_tower", "report_adrs_belfry"] {
        let svg = read(&out.join(format!("{stem}.svg")));
        assert!(svg.contains("<svg") && svg.contains("Capacity curve in the ADRS plane"), "{stem}.svg");
        let png = std::fs::read(out.join(format!("{stem}.png"))).unwrap_or_else(|e| panic!("{stem}.png: {e}"));
        // The report's charts are 1000 × 620 px.
        assert_eq!(png_size(&png), (1000, 620), "{stem}.png");
    }
    let manifest = read(&out.join(".rocking-manifest"));
    for name in [
        "report_adrs_tower.svg",
        "report_adrs_tower.png",
        "report_adrs_belfry.svg",
        "report_adrs_belfry.png",
    ] {
        assert!(manifest.lines().any(|l| l == name), "{name} not in the manifest: {manifest}");
    }
    // A run without --plot removes the figures of the earlier one, and keeps the report.
    belfry_report(dir.path(), &[]);
    assert!(!out.join("report_adrs_tower.svg").exists() && !out.join("report_adrs_belfry.png").exists());
    assert!(out.join("report.html").exists());
}
