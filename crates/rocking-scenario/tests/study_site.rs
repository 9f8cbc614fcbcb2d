//! A study's `[site]` (risk at a site): the hazard curve at the grid's nine
//! return periods, and the refusals that name their key.

mod support;

use rocking_scenario::Study;

/// A 2 × 2 grid 0.1° apart from (10 E, 45 N), every node with ag = 0.05·(k+1) g, F0 2.5 at return period k.
fn grid() -> String {
    let mut text = String::from("LON LAT");
    for tr in rocking_codes::GRID_RETURN_PERIODS {
        text += &format!(" ag{tr} F0{tr} Tc{tr}");
    }
    for (lon, lat) in [(10.0, 45.0), (10.1, 45.0), (10.0, 45.1), (10.1, 45.1)] {
        text += &format!("\n{lon} {lat}");
        for k in 0..9 {
            text += &format!(" {} 2.5 0.3", 0.5 * (k + 1) as f64);
        }
    }
    text
}

fn study_with(site: &str, measure: &str) -> Result<Study, rocking_scenario::Error> {
    let dir = tempfile::tempdir().expect("a temporary folder");
    std::fs::write(dir.path().join("a.AT2"), support::at2(0.3)).expect("a.AT2");
    std::fs::write(dir.path().join("grid.txt"), grid()).expect("grid.txt");
    let text = support::study(r#""*.AT2""#, "max_theta_over_alpha", "").replace("measure = \"pga\"", &format!("measure = \"{measure}\"")) + site;
    Study::from_toml_str(&text, &dir.path().join("study.toml"))
}

#[test]
fn the_sites_curve_is_ag_times_s_at_the_nine_return_periods() {
    // Every node alike: the site takes the nodes' ag; soil A and T1: S = 1, pga = ag.
    let study = study_with("[site]\nsoil = \"A\"\ngrid = \"grid.txt\"\nlon = 10.03\nlat = 45.07\n", "pga").unwrap_or_else(|e| panic!("{e}"));
    let site = study.site().expect("a site");
    for (k, p) in site.curve.points().iter().enumerate() {
        assert!((p.pga - 0.05 * (k + 1) as f64).abs() < 1e-15, "{k}: {}", p.pga);
        assert!((p.annual_frequency * p.return_period - 1.0).abs() < 1e-15);
    }
    // VN and CU not given: no reference period besides 50 years.
    assert!(site.reference_period.is_none());
    let given = study_with("[site]\nsoil = \"A\"\ngrid = \"grid.txt\"\nlon = 10.03\nlat = 45.07\nCU = 1.5\n", "pga").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(given.site().and_then(|s| s.reference_period), Some(75.0));
}

#[test]
fn a_site_needs_pga_and_a_grid() {
    let e = study_with("[site]\nsoil = \"A\"\ngrid = \"grid.txt\"\nlon = 10.03\nlat = 45.07\n", "pgv")
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.contains("site: ") && e.contains("study.measure = \"pga\""), "{e}");
    let e = study_with("[site]\nsoil = \"A\"\n[site.SLV]\nag = 0.1\nF0 = 2.5\nTc_star = 0.3\n", "pga")
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.contains("site.grid") && e.contains("no hazard curve"), "{e}");
    let e = study_with("[site]\nsoil = \"A\"\ngrid = \"grid.txt\"\nlon = 12.0\nlat = 45.07\n", "pga")
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.contains("site.lon"), "{e}");
}
