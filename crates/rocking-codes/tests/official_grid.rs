//! The official hazard grid (Tabella 1 of Allegato B, embedded in the library)
//! against the repository's copy and its provenance's check values
//! (`data/hazard/README.md`), a second copy of 25 rows, and Allegato A's
//! interpolation on the decree's lattice computed by hand in Python.

use approx::assert_relative_eq;
use rocking_codes::{Error, GridNode, HazardGrid, Island, LimitState, ReturnPeriodOfAg, SiteHazard, GRID_RETURN_PERIODS};

fn repository(path: &str) -> String {
    let path = format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"))
}

fn official() -> &'static HazardGrid {
    HazardGrid::ntc2018()
}

fn by_id(id: &str) -> &'static GridNode {
    official()
        .nodes()
        .iter()
        .find(|n| n.id.as_deref() == Some(id))
        .unwrap_or_else(|| panic!("no node {id}"))
}

#[test]
fn the_embedded_grid_is_the_repositorys_table() {
    // The embedded table parses to the same nodes as the repository's text
    // (pack_grid.py deflated it; a stale pack differs here).
    let text = repository("data/hazard/ntc2008-allegato-b-tabella1-with-id.txt");
    let from_text = HazardGrid::parse(&text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(from_text.nodes(), official().nodes());
    let islands = repository("data/hazard/ntc2008-allegato-b-tabella2-isole.txt");
    let embedded = include_str!("../data/ntc2018-tabella2.txt");
    assert_eq!(islands, embedded);
}

#[test]
fn the_check_values_of_the_provenance() {
    let nodes = official().nodes();
    // 10,751 rows (each of 29 numbers, or parse refuses it), no repeated coordinates.
    assert_eq!(nodes.len(), 10_751);
    let mut places: Vec<(i64, i64)> = nodes.iter().map(|n| ((n.lon * 1e4).round() as i64, (n.lat * 1e4).round() as i64)).collect();
    places.sort_unstable();
    places.dedup();
    assert_eq!(places.len(), 10_751);
    // The ranges are the table's own tokens: exact.
    let least = |f: &dyn Fn(&GridNode) -> f64| nodes.iter().map(f).fold(f64::INFINITY, f64::min);
    let most = |f: &dyn Fn(&GridNode) -> f64| nodes.iter().map(f).fold(f64::NEG_INFINITY, f64::max);
    assert_eq!((least(&|n| n.lon), most(&|n| n.lon)), (6.5448, 18.594));
    assert_eq!((least(&|n| n.lat), most(&|n| n.lat)), (36.573, 47.178));
    let f0 = |n: &GridNode| n.sites.map(|s| s.f0);
    let tc = |n: &GridNode| n.sites.map(|s| s.tc_star);
    assert!(nodes.iter().all(|n| f0(n).iter().all(|&v| (2.20..=3.25).contains(&v))));
    assert!(nodes.iter().all(|n| tc(n).iter().all(|&v| (0.10..=0.60).contains(&v))));
    // ag grows with the return period at every node.
    assert!(nodes.iter().all(|n| n.sites.windows(2).all(|w| w[1].ag > w[0].ag)));
    // The largest ag (TR 2475 years) is 6.247 g/10; the reader's /10 is one rounding.
    assert_relative_eq!(most(&|n| n.sites[8].ag), 0.6247, max_relative = 1e-15);
}

#[test]
fn the_nearest_nodes_of_six_places() {
    // (lon, lat) of the place, its node's ID where the provenance gives it,
    // ag (g), F0, Tc* at 475 years; the node is the nearest by great-circle
    // distance, and the coordinates given are its own (distance 0).
    type Place = (f64, f64, Option<&'static str>, f64, f64, f64);
    let places: [Place; 6] = [
        (13.423, 42.335, Some("26528"), 0.261, 2.36, 0.35),  // L'Aquila
        (12.483, 41.880, None, 0.1201, 2.64, 0.29),          // Rome (0.120 in the provenance, 1.201 g/10 in the table)
        (9.2174, 45.459, None, 0.0515, 2.65, 0.28),          // Milan
        (14.283, 40.832, None, 0.1687, 2.37, 0.34),          // Naples
        (14.352, 41.082, None, 0.1334, 2.49, 0.42),          // Caserta
        (14.418, 41.031, Some("32315"), 0.1521, 2.46, 0.38), // Cervino
    ];
    for (lon, lat, id, ag, f0, tc) in places {
        let nearest = official()
            .nodes()
            .iter()
            .min_by(|a, b| {
                let d = |n: &GridNode| rocking_codes::great_circle_distance_km(lon, lat, n.lon, n.lat);
                d(a).total_cmp(&d(b))
            })
            .unwrap_or_else(|| panic!("no nodes"));
        assert_eq!((nearest.lon, nearest.lat), (lon, lat));
        if let Some(id) = id {
            assert_eq!(nearest.id.as_deref(), Some(id));
        }
        // The /10 of g/10 to g: one rounding.
        let s = nearest.sites[6];
        assert_relative_eq!(s.ag, ag, max_relative = 1e-15);
        assert_eq!((s.f0, s.tc_star), (f0, tc));
        // A site on a node takes its values (Allegato A's weights: 1/d → the node).
        let at = official().site(lon, lat).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(at.sites[6], s);
    }
}

#[test]
fn a_second_copy_rounds_to_the_table() {
    // 25 rows of a copy with more digits: each ag rounds to the table's 3
    // decimals, each F0 and Tc* to its 2 (half a unit of the last place, and
    // 1e-12 for the binary form of both), LON and LAT to the table's digits.
    let text = repository("data/hazard/second-copy-25-rows.csv");
    let mut rows = 0;
    for line in text.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f.len(), 31, "{line}");
        let node = by_id(f[1]);
        let number = |c: usize| f[c].parse::<f64>().unwrap_or_else(|e| panic!("{line}: {e}"));
        let table_digits = |v: f64| format!("{v}").split('.').nth(1).map_or(0, str::len) as i32;
        for (c, v) in [(2, node.lon), (3, node.lat)] {
            assert!((number(c) - v).abs() <= 0.5 * 10f64.powi(-table_digits(v)) + 1e-12, "{line}: column {c}");
        }
        for (k, s) in node.sites.iter().enumerate() {
            let c = 4 + 3 * k;
            assert!((number(c) - s.ag * 10.0).abs() <= 0.5e-3 + 1e-12, "{line}: ag at {}", GRID_RETURN_PERIODS[k]);
            assert!((number(c + 1) - s.f0).abs() <= 0.5e-2 + 1e-12, "{line}: F0");
            assert!((number(c + 2) - s.tc_star).abs() <= 0.5e-2 + 1e-12, "{line}: Tc*");
        }
        rows += 1;
    }
    assert_eq!(rows, 25);
}

/// Allegato A at three sites, by hand in Python on the table's rows (the
/// lines below, from the repository's copy of Tabella 1; a separate
/// transcription of the cell search and of eqs. 1 and 2):
///
/// ```python
/// rows = {int(f[0]): (float(f[1]), float(f[2]), [float(x) for x in f[3:]]) for f in table}
/// def inside(i, lon, lat):   # the convex quadrilateral i, i+1, i+223, i+222
///     q = [rows[k][:2] for k in (i, i + 1, i + 223, i + 222)]
///     s = [(q[(m+1)%4][0]-q[m][0])*(lat-q[m][1]) - (q[(m+1)%4][1]-q[m][1])*(lon-q[m][0]) for m in range(4)]
///     return all(x <= 1e-12 for x in s) or all(x >= -1e-12 for x in s)
/// def hav(lon1, lat1, lon2, lat2):
///     p1, p2 = radians(lat1), radians(lat2)
///     h = sin((p2-p1)/2)**2 + cos(p1)*cos(p2)*sin(radians(lon2-lon1)/2)**2
///     return 2*6371*asin(sqrt(h))
/// i = min(c for c in cells if inside(c, lon, lat)); q = [i, i+1, i+223, i+222]
/// d = [hav(lon, lat, *rows[k][:2]) for k in q]
/// p = [sum(rows[k][2][m]/dk for k, dk in zip(q, d)) / sum(1/dk for dk in d) for m in range(27)]
/// tr = -VN*CU/log(1-P)       # P = 0.63, 0.10, 0.05
/// # between TR[k] <= tr < TR[k+1]: exp(log(p1) + log(p2/p1)*log(tr/TR[k])/log(TR[k+1]/TR[k])); beyond 2475: p at 2475
/// ```
///
/// The hand values have 16 digits; the code's differ by the round-off of
/// four haversines, the weights and a log-exp (some 1e-15): 1e-12 is a
/// thousand times that, and far inside the 1e-6 an independent
/// implementation is asked to meet.
const HAND: f64 = 1e-12;

/// (lon, lat, VN, CU, the cell's first node, the four distances (km), and
/// (ag g, F0, Tc* s) of SLD, SLV, SLC).
type HandSite = (f64, f64, f64, f64, &'static str, [f64; 4], [[f64; 3]; 3]);

const HAND_SITES: [HandSite; 3] = [
    // Cervino (Sant'Anna): VN 50, CU 1.5: TR 75.4, 711.8, 1462.2 years.
    (
        14.42,
        41.04,
        50.0,
        1.5,
        "32093",
        [4.5597628886891926, 7.105246368760698, 5.460466894267936, 1.0147162575525512],
        [
            [0.07406218821884361, 2.3774450648274343, 0.33135878909354455],
            [0.17612957238062965, 2.469198715586099, 0.3934346732437728],
            [0.22083289645565013, 2.5028046473862324, 0.413526521971945],
        ],
    ),
    // L'Aquila (centre): VN 50, CU 1: TR 50.3, 474.6, 974.8 years.
    (
        13.3995,
        42.3498,
        50.0,
        1.0,
        "26305",
        [5.355885139220212, 4.32860181762025, 2.5374471754533126, 4.0105544167490415],
        [
            [0.10419922853590832, 2.329841584358026, 0.2801553665025278],
            [0.26065723173688304, 2.359952136447841, 0.3499662864839795],
            [0.3340433610930905, 2.399987703721172, 0.3599969084852783],
        ],
    ),
    // Milan: VN 100, CU 2: TR 201.2, 1898.2, and 3899.1 years for SLC, beyond
    // the table: the values at 2475 years.
    (
        9.19,
        45.4642,
        100.0,
        2.0,
        "12038",
        [6.025265821049654, 5.313110563262098, 2.213789633746805, 3.5010224784771284],
        [
            [0.03858874941658283, 2.6256871022633947, 0.25002559112310085],
            [0.07057047809505658, 2.754032894760713, 0.3100444406475905],
            [0.07538549124101665, 2.7789622484127245, 0.3141373129208506],
        ],
    ),
];

#[test]
fn allegato_a_on_the_lattice_against_a_hand_computation() {
    for (lon, lat, vn, cu, first, distances, states) in HAND_SITES {
        let cell = official().cell_nodes(lon, lat).unwrap_or_else(|e| panic!("{e}"));
        let id: i64 = first.parse().unwrap_or_else(|e| panic!("{e}"));
        let ids = [id, id + 1, id + 223, id + 222].map(|i| i.to_string());
        for ((node, d), (want_id, want_d)) in cell.iter().zip(ids.iter().zip(distances)) {
            assert_eq!(node.id.as_deref(), Some(want_id.as_str()));
            assert_relative_eq!(*d, want_d, max_relative = HAND);
        }
        let site = official().site(lon, lat).unwrap_or_else(|e| panic!("{e}"));
        for (state, [ag, f0, tc]) in [LimitState::Sld, LimitState::Slv, LimitState::Slc].into_iter().zip(states) {
            let s = site.for_limit_state(state, vn, cu).unwrap_or_else(|e| panic!("{e}"));
            assert_relative_eq!(s.ag, ag, max_relative = HAND);
            assert_relative_eq!(s.f0, f0, max_relative = HAND);
            assert_relative_eq!(s.tc_star, tc, max_relative = HAND);
        }
    }
}

#[test]
fn a_site_outside_every_cell_is_refused_and_names_tabella_2() {
    // The Tyrrhenian sea between Sardinia and Campania, and Cagliari (Sardinia, island group G1).
    for (lon, lat) in [(12.0, 40.0), (9.11, 39.22)] {
        match official().site(lon, lat) {
            Err(e @ Error::OutsideGrid { .. }) => assert!(e.to_string().contains("island = \"G1\""), "{e}"),
            other => panic!("expected outside the grid, got {other:?}"),
        }
    }
}

#[test]
fn the_islands_of_tabella_2() {
    // G1 (Sardinia…) at 475 years: ag 0.500 g/10, F0 2.88, Tc* 0.340; G5 at 2475: 3.746, 2.76, 0.324.
    let h: SiteHazard = Island::G1.hazard();
    assert_relative_eq!(h.sites[6].ag, 0.05, max_relative = 1e-15);
    assert_eq!((h.sites[6].f0, h.sites[6].tc_star), (2.88, 0.340));
    let h = Island::G5.hazard();
    assert_relative_eq!(h.sites[8].ag, 0.3746, max_relative = 1e-15);
    assert_eq!((h.sites[8].f0, h.sites[8].tc_star), (2.76, 0.324));
    assert!(matches!("G6".parse::<Island>(), Err(Error::InvalidParameter { name: "island", .. })));
    assert_eq!("G3".parse::<Island>().ok(), Some(Island::G3));
}

#[test]
fn the_return_period_of_a_capacity_at_cervino() {
    // Cervino (14.42, 41.04): ag 0.19627542285363583 g at 975 years and
    // 0.2573693779360596 g at 2475 (Allegato A's eq. 1 at the two columns, as
    // above). The ag 0.2 g is reached, inverting eq. 2 by hand in Python, at
    // 975 · exp(ln(0.2/0.196275) · ln(2475/975) / ln(0.257369/0.196275)) =
    // 1040.0858093844474 years; 1e-12 for the round-off of the logs.
    let site = official().site(14.42, 41.04).unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(site.sites[7].ag, 0.19627542285363583, max_relative = 1e-12);
    assert_relative_eq!(site.sites[8].ag, 0.2573693779360596, max_relative = 1e-12);
    match site.return_period_of_ag(0.2) {
        ReturnPeriodOfAg::At(tr) => assert_relative_eq!(tr, 1040.0858093844474, max_relative = 1e-12),
        other => panic!("expected a return period, got {other:?}"),
    }
    // Going back: the ag at that return period is 0.2 g (the interpolation and its inverse).
    let ReturnPeriodOfAg::At(tr) = site.return_period_of_ag(0.2) else { panic!() };
    assert_relative_eq!(site.at_return_period(tr).ag, 0.2, max_relative = 1e-12);
    assert_eq!(site.return_period_of_ag(0.3), ReturnPeriodOfAg::Beyond2475);
    assert_eq!(site.return_period_of_ag(0.01), ReturnPeriodOfAg::Below30);
}
