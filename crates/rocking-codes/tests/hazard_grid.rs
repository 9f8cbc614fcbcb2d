//! The hazard grid (NTC 2018 Allegato B's layout) and Allegato A's interpolation
//! against values computed by hand: a separate transcription of the haversine and
//! of the inverse-distance and log-log formulas, in Python, on the grid below.

use approx::assert_relative_eq;
use rocking_codes::{great_circle_distance_km, return_period, Error, HazardGrid, LimitState, GRID_RETURN_PERIODS};

// Each hand value has 16 digits; the code's differ from them by the round-off of
// a haversine, four quotients and a log-exp: 1e-12 is a thousand times that.
const TIGHT: f64 = 1e-12;

/// The values of node `n` (0–3) at return period `k` (0–8): `ag` in g/10, `F0`, `Tc*`.
fn node_values(n: usize, k: usize) -> (f64, f64, f64) {
    let (n, k) = (n as f64, k as f64);
    ((1.0 + 0.5 * n) * (1.0 + 0.3 * k), 2.3 + 0.05 * n + 0.01 * k, 0.25 + 0.02 * n + 0.01 * k)
}

/// A 2 × 2 grid, 0.1° apart, from (10.0 E, 45.0 N); `sep` separates the columns;
/// `skip` leaves a node out; `with_id` writes the ID column.
fn grid_text(sep: &str, with_id: bool, skip: Option<usize>) -> String {
    let coords = [(10.0, 45.0), (10.1, 45.0), (10.0, 45.1), (10.1, 45.1)];
    let mut header = vec!["LON".to_string(), "LAT".to_string()];
    if with_id {
        header.insert(0, "ID".into());
    }
    for tr in GRID_RETURN_PERIODS {
        header.extend([format!("ag{tr}"), format!("F0{tr}"), format!("Tc{tr}")]);
    }
    let mut text = format!("# a comment\n{}\n", header.join(sep));
    for (n, (lon, lat)) in coords.iter().enumerate() {
        if skip == Some(n) {
            continue;
        }
        let mut row = vec![lon.to_string(), lat.to_string()];
        if with_id {
            row.insert(0, format!("{}", 100 + n));
        }
        for k in 0..9 {
            let (ag, f0, tc) = node_values(n, k);
            row.extend([ag.to_string(), f0.to_string(), tc.to_string()]);
        }
        text += &row.join(sep);
        text += "\n";
    }
    text
}

fn grid(text: &str) -> HazardGrid {
    HazardGrid::parse(text).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn haversine_distance() {
    // 0.1° of longitude at 45° N.
    assert_relative_eq!(great_circle_distance_km(10.0, 45.0, 10.1, 45.0), 7.862668167410343, max_relative = TIGHT);
    // A quarter of a meridian: π/2 · 6371 km.
    assert_relative_eq!(
        great_circle_distance_km(0.0, 0.0, 0.0, 90.0),
        std::f64::consts::FRAC_PI_2 * 6371.0,
        max_relative = TIGHT
    );
}

#[test]
fn a_site_on_a_node_takes_the_nodes_values() {
    for (sep, with_id) in [("\t", true), (" ", false), (",", true), (";", false)] {
        let g = grid(&grid_text(sep, with_id, None));
        let site = g.site(10.1, 45.0).unwrap_or_else(|e| panic!("{e}"));
        for k in 0..9 {
            let (ag, f0, tc) = node_values(1, k);
            assert_relative_eq!(site.sites[k].ag, ag / 10.0, max_relative = TIGHT);
            assert_relative_eq!(site.sites[k].f0, f0, max_relative = TIGHT);
            assert_relative_eq!(site.sites[k].tc_star, tc, max_relative = TIGHT);
        }
    }
}

#[test]
fn a_site_on_an_edge_weighs_all_four_nodes() {
    // Midway along the southern edge, at TR = 475 years (column 6).
    let site = grid(&grid_text("\t", true, None)).site(10.05, 45.0).unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(site.sites[6].ag, 0.42000509338259967, max_relative = TIGHT);
    assert_relative_eq!(site.sites[6].f0, 2.4100018190652137, max_relative = TIGHT);
    assert_relative_eq!(site.sites[6].tc_star, 0.3300007276260857, max_relative = TIGHT);
}

#[test]
fn a_site_inside_a_cell_and_its_slv_return_period() {
    let site = grid(&grid_text("\t", true, None)).site(10.03, 45.07).unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(site.sites[6].ag, 0.5164855831628014, max_relative = TIGHT);
    assert_relative_eq!(site.sites[6].f0, 2.4444591368438577, max_relative = TIGHT);
    assert_relative_eq!(site.sites[6].tc_star, 0.343783654737543, max_relative = TIGHT);
    // SLV, VN = 50, CU = 1: TR = −50 / ln 0.9 = 474.56 years, log-log between 201 and 475.
    assert_relative_eq!(return_period(50.0, 1.0, 0.10), 474.56107905149526, max_relative = TIGHT);
    let slv = site.for_limit_state(LimitState::Slv, 50.0, 1.0).unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(slv.ag, 0.5164226670934448, max_relative = TIGHT);
    assert_relative_eq!(slv.f0, 2.4444483652773563, max_relative = TIGHT);
    assert_relative_eq!(slv.tc_star, 0.3437727459269298, max_relative = TIGHT);
    // Outside the table's 30–2475 years: the nearest column.
    assert_relative_eq!(site.at_return_period(10.0).ag, site.sites[0].ag, max_relative = TIGHT);
    assert_relative_eq!(site.at_return_period(1e4).ag, site.sites[8].ag, max_relative = TIGHT);
    // On a tabulated return period: its column.
    assert_relative_eq!(site.at_return_period(975.0).f0, site.sites[7].f0, max_relative = TIGHT);
}

#[test]
fn return_periods_of_the_limit_states() {
    // VN = 50, CU = 1.5: VR = 75 years; TR = −75 / ln(1 − P_VR).
    let tr = |p: f64| -75.0 / (1.0f64 - p).ln();
    for (state, p) in [
        (LimitState::Slo, 0.81),
        (LimitState::Sld, 0.63),
        (LimitState::Slv, 0.10),
        (LimitState::Slc, 0.05),
    ] {
        assert_eq!(state.probability_of_exceedance(), Some(p));
        assert_relative_eq!(return_period(50.0, 1.5, p), tr(p), max_relative = TIGHT);
    }
    // The familiar values: SLV of an ordinary building (VN 50, CU 1) ~ 475 years, SLC ~ 975.
    assert_relative_eq!(return_period(50.0, 1.0, 0.05), 974.7862873, max_relative = 1e-9);
}

#[test]
fn sites_outside_the_grid_are_refused() {
    let g = grid(&grid_text("\t", true, None));
    assert!(matches!(g.site(10.2, 45.05), Err(Error::OutsideGrid { .. })));
    assert!(matches!(g.site(10.05, 44.99), Err(Error::OutsideGrid { .. })));
    // A cell with a node missing is outside too (the official grid covers land only).
    let holed = grid(&grid_text("\t", true, Some(3)));
    assert!(matches!(holed.site(10.05, 45.05), Err(Error::OutsideGrid { .. })));
}

#[test]
fn malformed_grids_are_refused_with_line_and_column() {
    // A return period's three columns missing from a row.
    let text = grid_text("\t", true, None);
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let cut: Vec<&str> = lines[3].split('\t').collect();
    lines[3] = cut[..cut.len() - 3].join("\t");
    match HazardGrid::parse(&lines.join("\n")) {
        Err(Error::Grid { line: 4, reason, .. }) => assert!(reason.contains("return period"), "{reason}"),
        other => panic!("expected a missing return period on line 4, got {other:?}"),
    }
    // A value that is not a number names its column by the header.
    let bad = text.replacen("\t2.3\t", "\t2.3x\t", 1);
    match HazardGrid::parse(&bad) {
        Err(e @ Error::Grid { column: Some(_), .. }) => assert!(e.to_string().contains("line 3, column F030 (TR 30 years)"), "{e}"),
        other => panic!("expected a bad number, got {other:?}"),
    }
    // A node off the lattice.
    let irregular = text.replacen("\n101\t10.1\t", "\n101\t10.13\t", 1);
    assert!(matches!(HazardGrid::parse(&irregular), Err(Error::GridShape(m)) if m.contains("regular")));
    // No header.
    assert!(matches!(HazardGrid::parse("10 45 1 2 3\n"), Err(Error::Grid { line: 1, .. })));
    assert!(matches!(HazardGrid::parse("# nothing\n"), Err(Error::GridShape(_))));
}

#[test]
fn the_synthetic_grid_of_the_repository() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/hazard/synthetic_grid.txt");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"));
    let g = grid(&text);
    assert_eq!(g.nodes().len(), 30);
    let (dlon, dlat) = g.spacing().unwrap_or_else(|| panic!("the synthetic grid is regular"));
    assert_relative_eq!(dlon, 0.05, max_relative = 1e-9);
    assert_relative_eq!(dlat, 0.05, max_relative = 1e-9);
    // Node 40001 at (14.30, 40.95): ag 1.600 g/10 at 475 years.
    let site = g.site(14.30, 40.95).unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(site.sites[6].ag, 0.16, max_relative = TIGHT);
    assert_eq!(g.nodes()[0].id.as_deref(), Some("40001"));
}

#[test]
fn a_grid_saved_by_a_spreadsheet_in_italian() {
    // A byte-order mark, semicolons and decimal commas: the same nodes as the tab-separated text.
    let text = grid_text("\t", true, None);
    let saved = format!("\u{feff}{}", text.replace(';', "").replace('.', ",").replace('\t', ";"));
    assert!(saved.contains(";0,25;"), "{saved}");
    assert_eq!(grid(&saved).nodes(), grid(&text).nodes());
    // Tab-separated with decimal commas too.
    assert_eq!(grid(&text.replace('.', ",")).nodes(), grid(&text).nodes());
    // A value that is no number: one line naming the row and the column.
    let bad = saved.replacen(";2,3;", ";2,3,1;", 1);
    match HazardGrid::parse(&bad) {
        Err(e) => assert_eq!(e.to_string(), "line 3, column F030 (TR 30 years): not a number: \"2,3,1\""),
        Ok(_) => panic!("2,3,1 read as a number"),
    }
}

#[test]
fn an_irregular_grid_with_the_decrees_ids_has_its_cells_by_id() {
    // Four nodes off any regular lattice, with IDs 5000, 5001, 5223, 5222 (east,
    // south-east, south): one skewed cell. A site at its centroid (the mean of
    // the corners) weighs the nodes by the inverse of its distances.
    let corners = [(5000, 10.0, 45.1), (5001, 10.11, 45.12), (5223, 10.13, 45.02), (5222, 10.02, 45.0)];
    let mut text = String::from("ID LON LAT");
    for tr in GRID_RETURN_PERIODS {
        text += &format!(" ag{tr} F0{tr} Tc{tr}");
    }
    for (n, (id, lon, lat)) in corners.iter().enumerate() {
        text += &format!("\n{id} {lon} {lat}");
        for k in 0..9 {
            let (ag, f0, tc) = node_values(n, k);
            text += &format!(" {ag} {f0} {tc}");
        }
    }
    let g = grid(&text);
    assert!(g.spacing().is_none());
    let (lon, lat) = (10.065, 45.06);
    let d = corners.map(|(_, x, y)| great_circle_distance_km(lon, lat, x, y));
    let site = g.site(lon, lat).unwrap_or_else(|e| panic!("{e}"));
    for k in 0..9 {
        let num: f64 = (0..4).map(|n| node_values(n, k).0 / 10.0 / d[n]).sum();
        let den: f64 = d.iter().map(|x| 1.0 / x).sum();
        assert_relative_eq!(site.sites[k].ag, num / den, max_relative = TIGHT);
    }
    // Outside the skewed cell though inside its bounding box.
    assert!(matches!(g.site(10.005, 45.005), Err(Error::OutsideGrid { .. })));
    // IDs that make no cell: refused, saying so.
    let broken = text.replace("\n5223 ", "\n6223 ");
    assert!(matches!(HazardGrid::parse(&broken), Err(Error::GridShape(m)) if m.contains("lattice")));
}
