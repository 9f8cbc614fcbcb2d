//! The hazard grid of NTC 2018 (Allegato B's table) and Allegato A's
//! interpolation of the site parameters `ag`, `F0`, `Tc*`.
//!
//! The file: a header line, then one node per line, the columns separated by
//! whitespace, tabs, commas or semicolons (the header's separator: a semicolon
//! if it has one, else a comma if it has one, else whitespace; with a
//! semicolon or whitespace a number may have a decimal comma, as a
//! spreadsheet saved in Italian writes it; a byte-order mark is skipped): an
//! optional node `ID` (told by the header's first name), `LON`, `LAT`
//! (degrees), then `ag` (in g/10, as published), `F0`, `Tc*` (s) for each of
//! the return periods 30, 50, 72, 101, 140, 201, 475, 975 and 2475 years.
//! Lines starting with `#` and blank lines are skipped.
//!
//! The cells: a grid regular in longitude and latitude (it need not be full)
//! has its cells by its rows and columns. The official grid is not regular
//! (its nodes lie on lines of constant ED50 coordinates, 7,216 distinct
//! longitudes): its cells are those of the decree's lattice of node IDs, which
//! grow by 1 one column east and by 222 one row south, the cell of node `i`
//! being the quadrilateral of `i, i+1, i+223, i+222`.
//!
//! A site's parameters (Allegato A): the four nodes of the cell that holds it,
//! each parameter `p = Σ(p_i / d_i) / Σ(1 / d_i)` with `d_i` the great-circle
//! distance to node i, at each tabulated return period; then log-log in the
//! return period between the two that bracket it.
//!
//! [`HazardGrid::ntc2018`] is the official grid (Tabella 1 of Allegato B, 10,751
//! nodes), embedded in the library deflated; [`Island`] gives Tabella 2's values
//! for the small islands outside it.

use crate::code::{return_period, LimitState};
use crate::error::{invalid, Error};
use crate::ntc::NtcSite;
use std::collections::HashMap;
use std::sync::OnceLock;

/// The return periods (years) of the grid's columns, in order (NTC 2018 Allegato B).
pub const GRID_RETURN_PERIODS: [f64; 9] = [30.0, 50.0, 72.0, 101.0, 140.0, 201.0, 475.0, 975.0, 2475.0];

/// The mean Earth radius (km) of the great-circle distances.
pub const EARTH_RADIUS_KM: f64 = 6371.0;

/// How far (as a fraction of the spacing) a node may lie off its lattice line:
/// the official table gives coordinates to 4 decimals (±0.00005°) on a spacing
/// of about 0.05°, 0.1% of it; 1% leaves room and still refuses a node that
/// belongs to no line.
const LATTICE_TOLERANCE: f64 = 0.01;

/// One node of the grid: its coordinates and the site parameters at each return period.
#[derive(Debug, Clone, PartialEq)]
pub struct GridNode {
    /// The node's `ID`, if the file has the column.
    pub id: Option<String>,
    /// Longitude (degrees east).
    pub lon: f64,
    /// Latitude (degrees north).
    pub lat: f64,
    /// `ag` (g, converted from the file's g/10), `F0`, `Tc*` (s) at each of [`GRID_RETURN_PERIODS`].
    pub sites: [NtcSite; 9],
}

/// A hazard grid read from a file in the layout of NTC 2018 Allegato B.
#[derive(Debug, Clone, PartialEq)]
pub struct HazardGrid {
    nodes: Vec<GridNode>,
    cells: Cells,
}

/// How the nodes of a grid make its cells.
#[derive(Debug, Clone, PartialEq)]
enum Cells {
    /// A lattice regular in longitude and latitude: the node at lattice index
    /// (i, j) is at `lon = lon0 + i dlon`, `lat = lat0 + j dlat`.
    Regular {
        index: HashMap<(i64, i64), usize>,
        lon0: f64,
        lat0: f64,
        dlon: f64,
        dlat: f64,
        imax: i64,
        jmax: i64,
    },
    /// The decree's lattice of node IDs: each cell the nodes (by their index
    /// in `nodes`) of IDs `i, i+1, i+223, i+222`, in increasing `i`; `buckets`
    /// the cells whose bounding box meets each square of [`BUCKET_DEGREES`].
    Lattice {
        cells: Vec<[usize; 4]>,
        buckets: HashMap<(i64, i64), Vec<usize>>,
    },
}

/// The IDs of the official lattice grow by this much one row south (and by 1 one column east).
pub const LATTICE_ROW: i64 = 222;

/// The side (degrees) of the squares by which the cells of an ID lattice are
/// found: about two cells of the official grid (0.05°) across, so a square
/// holds a dozen of them.
const BUCKET_DEGREES: f64 = 0.1;

/// How far (degrees²) a site may lie outside a cell's edge by the sign of a
/// cross product and still count as on it: the round-off of products of
/// coordinates of about 50° (1e-14), far below the 4-decimal precision of the
/// table's coordinates (1e-4° × 0.05° = 5e-6 degrees²).
const EDGE_TOLERANCE: f64 = 1e-12;

/// The site parameters of one site at each of the grid's return periods.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SiteHazard {
    /// `ag` (g), `F0`, `Tc*` (s) at each of [`GRID_RETURN_PERIODS`].
    pub sites: [NtcSite; 9],
}

/// The great-circle distance (km) between two points given in degrees, by the
/// haversine formula on a sphere of radius [`EARTH_RADIUS_KM`] (the distance of
/// NTC 2018 Allegato A's interpolation).
pub fn great_circle_distance_km(lon1: f64, lat1: f64, lon2: f64, lat2: f64) -> f64 {
    let (phi1, phi2) = (lat1.to_radians(), lat2.to_radians());
    let dphi = phi2 - phi1;
    let dlambda = (lon2 - lon1).to_radians();
    let h = libm::sin(dphi / 2.0).powi(2) + libm::cos(phi1) * libm::cos(phi2) * libm::sin(dlambda / 2.0).powi(2);
    2.0 * EARTH_RADIUS_KM * libm::asin(h.sqrt().min(1.0))
}

/// A parameter at a site from its values `p_i` at the four nodes of the cell and
/// the distances `d_i` (km) to them: `p = Σ(p_i / d_i) / Σ(1 / d_i)`; a site on
/// a node (`d_i` under a micrometre) takes that node's value (NTC 2018 Allegato A, eq. 1).
pub fn inverse_distance_weighting(values: [f64; 4], distances: [f64; 4]) -> f64 {
    if let Some(k) = distances.iter().position(|&d| d < 1e-9) {
        return values[k];
    }
    let num: f64 = values.iter().zip(distances).map(|(p, d)| p / d).sum();
    let den: f64 = distances.iter().map(|d| 1.0 / d).sum();
    num / den
}

/// A parameter at the return period `tr` from its values `p1`, `p2` at the
/// tabulated `tr1 < tr2` that bracket it (NTC 2018 Allegato A, eq. 2):
/// `log p = log p1 + log(p2/p1) · log(tr/tr1) / log(tr2/tr1)`.
pub fn log_log_interpolation(tr: f64, tr1: f64, tr2: f64, p1: f64, p2: f64) -> f64 {
    libm::exp(libm::log(p1) + libm::log(p2 / p1) * libm::log(tr / tr1) / libm::log(tr2 / tr1))
}

/// The return period at which a parameter reaches `p`, from its values `p1`,
/// `p2` at the tabulated `tr1 < tr2` (years): the inverse of
/// [`log_log_interpolation`], `TR = tr1 · exp(log(p/p1) · log(tr2/tr1) / log(p2/p1))`.
pub fn log_log_return_period(p: f64, tr1: f64, tr2: f64, p1: f64, p2: f64) -> f64 {
    tr1 * libm::exp(libm::log(p / p1) * libm::log(tr2 / tr1) / libm::log(p2 / p1))
}

/// Where a site's `ag` reaches a given acceleration in the grid's return periods.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ReturnPeriodOfAg {
    /// Below the `ag` of 30 years.
    Below30,
    /// At this return period (years), 30 to 2475.
    At(f64),
    /// Beyond the `ag` of 2475 years.
    Beyond2475,
}

impl SiteHazard {
    /// The return period at which the site's `ag` reaches `ag` (g): the
    /// inverse of Allegato A's log-log interpolation in the return period, on
    /// the first pair of tabulated return periods whose `ag` bracket it (the
    /// `T_R,C` of a capacity).
    pub fn return_period_of_ag(&self, ag: f64) -> ReturnPeriodOfAg {
        let periods = GRID_RETURN_PERIODS;
        if ag < self.sites[0].ag {
            return ReturnPeriodOfAg::Below30;
        }
        for k in 0..8 {
            let (a1, a2) = (self.sites[k].ag, self.sites[k + 1].ag);
            if ag >= a1 && ag <= a2 && a2 > a1 {
                return ReturnPeriodOfAg::At(log_log_return_period(ag, periods[k], periods[k + 1], a1, a2));
            }
        }
        ReturnPeriodOfAg::Beyond2475
    }

    /// The site parameters at the return period `tr` (years): log-log between the
    /// two tabulated return periods that bracket it; outside 30–2475 years, those
    /// of the nearest one (Allegato A).
    pub fn at_return_period(&self, tr: f64) -> NtcSite {
        let periods = GRID_RETURN_PERIODS;
        if tr <= periods[0] {
            return self.sites[0];
        }
        if tr >= periods[8] {
            return self.sites[8];
        }
        let k = periods.partition_point(|&p| p <= tr) - 1;
        let (a, b) = (self.sites[k], self.sites[k + 1]);
        let (tr1, tr2) = (periods[k], periods[k + 1]);
        NtcSite {
            ag: log_log_interpolation(tr, tr1, tr2, a.ag, b.ag),
            f0: log_log_interpolation(tr, tr1, tr2, a.f0, b.f0),
            tc_star: log_log_interpolation(tr, tr1, tr2, a.tc_star, b.tc_star),
        }
    }

    /// The site parameters of an NTC limit state for the nominal life `VN`
    /// (years, > 0) and the coefficient of use `CU` (> 0): at `TR = −VN CU / ln(1 − P_VR)`.
    pub fn for_limit_state(&self, state: LimitState, nominal_life: f64, use_coefficient: f64) -> Result<NtcSite, Error> {
        crate::error::positive("VN", nominal_life)?;
        crate::error::positive("CU", use_coefficient)?;
        let p = state.probability_of_exceedance().ok_or_else(|| {
            invalid(
                "limit_state",
                format!("{state} has no return period in NTC 2018: the hazard grid serves SLO, SLD, SLV, SLC"),
            )
        })?;
        Ok(self.at_return_period(return_period(nominal_life, use_coefficient, p)))
    }
}

/// How the columns of a grid file are separated, told by its header line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Separator {
    /// Semicolons (a spreadsheet's CSV in a locale with the decimal comma).
    Semicolon,
    /// Commas.
    Comma,
    /// Spaces and tabs.
    Whitespace,
}

impl Separator {
    /// The separator of a file whose header line is `header`.
    fn of_header(header: &str) -> Self {
        if header.contains(';') {
            Separator::Semicolon
        } else if header.contains(',') {
            Separator::Comma
        } else {
            Separator::Whitespace
        }
    }

    /// The fields of a line.
    fn fields(self, line: &str) -> Vec<&str> {
        let split: Box<dyn Iterator<Item = &str>> = match self {
            Separator::Semicolon => Box::new(line.split(';')),
            Separator::Comma => Box::new(line.split(',')),
            Separator::Whitespace => Box::new(line.split(char::is_whitespace)),
        };
        split.map(str::trim).filter(|s| !s.is_empty()).collect()
    }

    /// A field as a number: with semicolons or whitespace between the fields,
    /// a decimal comma is read as a point (`0,263`).
    fn number(self, field: &str) -> Option<f64> {
        let parsed = match self {
            Separator::Comma => field.parse::<f64>().ok(),
            _ if field.contains(',') && !field.contains('.') => field.replacen(',', ".", 1).parse::<f64>().ok(),
            _ => field.parse::<f64>().ok(),
        };
        parsed.filter(|v| v.is_finite())
    }
}

/// The distinct values of `xs` (sorted; values closer than 1e-9 are one) and the
/// least gap between them.
fn lattice_axis(xs: impl Iterator<Item = f64>) -> (f64, f64, usize) {
    let mut v: Vec<f64> = xs.collect();
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    let gap = v.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
    (v[0], gap, v.len())
}

impl HazardGrid {
    /// Reads a grid from the text of its file (see the module's documentation).
    pub fn parse(text: &str) -> Result<Self, Error> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut lines = text.lines().enumerate().map(|(k, l)| (k + 1, l)).filter(|(_, l)| {
            let t = l.trim();
            !t.is_empty() && !t.starts_with('#')
        });
        let (header_line, header) = lines.next().ok_or_else(|| Error::GridShape("the grid file is empty: no header line".into()))?;
        let separator = Separator::of_header(header);
        let header = separator.fields(header);
        if header.first().is_some_and(|h| separator.number(h).is_some()) {
            return Err(Error::Grid {
                line: header_line,
                column: None,
                reason: "the first line must be a header (ID LON LAT, then ag F0 Tc* at each return period), not numbers".into(),
            });
        }
        let has_id = header.first().is_some_and(|h| h.eq_ignore_ascii_case("id"));
        let first = usize::from(has_id);
        let expected = first + 2 + 3 * GRID_RETURN_PERIODS.len();
        let column_name = |c: usize| -> String {
            if header.len() == expected {
                let tr = if c >= first + 2 {
                    format!(" (TR {} years)", GRID_RETURN_PERIODS[(c - first - 2) / 3])
                } else {
                    String::new()
                };
                format!("{}{tr}", header[c])
            } else {
                format!("{}", c + 1)
            }
        };
        let mut nodes = Vec::new();
        for (line, text) in lines {
            let f = separator.fields(text);
            if f.len() != expected {
                let missing = if f.len() < expected && (expected - f.len()).is_multiple_of(3) {
                    ": a return period's ag, F0, Tc* are missing"
                } else {
                    ""
                };
                return Err(Error::Grid {
                    line,
                    column: None,
                    reason: format!(
                        "expected {expected} columns ({}LON, LAT, then ag, F0, Tc* at each of the 9 return periods 30 to 2475 years), got {}{missing}",
                        if has_id { "ID, " } else { "" },
                        f.len()
                    ),
                });
            }
            let number = |c: usize| -> Result<f64, Error> {
                separator.number(f[c]).ok_or_else(|| Error::Grid {
                    line,
                    column: Some(column_name(c)),
                    reason: format!("not a number: {:?}", f[c]),
                })
            };
            let (lon, lat) = (number(first)?, number(first + 1)?);
            if !(-180.0..=180.0).contains(&lon) {
                return Err(Error::Grid {
                    line,
                    column: Some(column_name(first)),
                    reason: format!("longitude {lon} outside [-180, 180]"),
                });
            }
            if !(-90.0..=90.0).contains(&lat) {
                return Err(Error::Grid {
                    line,
                    column: Some(column_name(first + 1)),
                    reason: format!("latitude {lat} outside [-90, 90]"),
                });
            }
            let mut sites = [NtcSite {
                ag: 0.0,
                f0: 0.0,
                tc_star: 0.0,
            }; 9];
            for (k, site) in sites.iter_mut().enumerate() {
                let c = first + 2 + 3 * k;
                let mut values = [0.0; 3];
                for (m, v) in values.iter_mut().enumerate() {
                    *v = number(c + m)?;
                    if *v <= 0.0 {
                        return Err(Error::Grid {
                            line,
                            column: Some(column_name(c + m)),
                            reason: format!("must be > 0, got {v}"),
                        });
                    }
                }
                // ag is published in g/10.
                *site = NtcSite {
                    ag: values[0] / 10.0,
                    f0: values[1],
                    tc_star: values[2],
                };
            }
            nodes.push(GridNode {
                id: has_id.then(|| f[0].to_string()),
                lon,
                lat,
                sites,
            });
        }
        Self::from_nodes(nodes)
    }

    /// A grid of the given nodes: a lattice regular in longitude and latitude,
    /// else (the official grid) the lattice of the nodes' IDs; neither is an error.
    pub fn from_nodes(nodes: Vec<GridNode>) -> Result<Self, Error> {
        if nodes.is_empty() {
            return Err(Error::GridShape("the grid has no nodes".into()));
        }
        let with_ids = nodes.iter().all(|n| n.id.is_some());
        let cells = match regular_cells(&nodes) {
            // A grid whose coordinates are given to 4 decimals is regular on a
            // lattice of 0.0001°, with no cell of four nodes: one with the
            // decree's IDs then has its cells by them.
            Ok(regular) if with_ids && !regular.has_a_cell() => lattice_cells(&nodes).unwrap_or(regular),
            Ok(regular) => regular,
            Err(irregular) if with_ids => lattice_cells(&nodes).map_err(|why| {
                Error::GridShape(format!(
                    "{irregular}; nor do the IDs make cells of the decree's lattice (IDs i, i+1, i+{}, i+{}): {why}",
                    LATTICE_ROW + 1,
                    LATTICE_ROW
                ))
            })?,
            Err(irregular) => {
                return Err(Error::GridShape(format!(
                    "{irregular}; a grid that is not (the official one) needs the decree's node IDs in an ID column"
                )))
            }
        };
        Ok(Self { nodes, cells })
    }

    /// The official hazard grid of NTC 2018: Tabella 1 of Allegato B to the
    /// D.M. 14 gennaio 2008, kept by the D.M. 17 gennaio 2018 (10,751 nodes,
    /// with the node IDs of the decree's lattice), embedded in the library.
    /// Read once, on the first call.
    pub fn ntc2018() -> &'static HazardGrid {
        static GRID: OnceLock<HazardGrid> = OnceLock::new();
        GRID.get_or_init(|| {
            // The embedded table is the library's own, checked by its tests to
            // inflate and parse: a failure here is a broken build, not bad input.
            #[allow(clippy::expect_used)]
            let text = miniz_oxide::inflate::decompress_to_vec_zlib(OFFICIAL_TABLE).expect("the embedded grid inflates");
            #[allow(clippy::expect_used)]
            let text = String::from_utf8(text).expect("the embedded grid is UTF-8");
            #[allow(clippy::expect_used)]
            HazardGrid::parse(&text).expect("the embedded grid parses")
        })
    }

    /// The nodes, in the file's order.
    pub fn nodes(&self) -> &[GridNode] {
        &self.nodes
    }

    /// The lattice spacing (degrees of longitude, of latitude) of a grid
    /// regular in longitude and latitude; `None` for one whose cells are by ID.
    pub fn spacing(&self) -> Option<(f64, f64)> {
        match &self.cells {
            Cells::Regular { dlon, dlat, .. } => Some((*dlon, *dlat)),
            Cells::Lattice { .. } => None,
        }
    }

    /// The four nodes of the cell that holds the site (of a lattice by ID,
    /// around it in the order `i, i+1, i+223, i+222`), or `None`.
    fn cell(&self, lon: f64, lat: f64) -> Option<[usize; 4]> {
        match &self.cells {
            Cells::Regular {
                index,
                lon0,
                lat0,
                dlon,
                dlat,
                imax,
                jmax,
            } => {
                // A site on the last line of the lattice belongs to the cell before it.
                let locate = |f: f64, max: i64| -> Option<i64> {
                    let tol = 1e-9;
                    if !(f >= -tol && f <= max as f64 + tol) {
                        return None;
                    }
                    Some((f.floor() as i64).clamp(0, max - 1))
                };
                let i = locate((lon - lon0) / dlon, *imax)?;
                let j = locate((lat - lat0) / dlat, *jmax)?;
                let node = |di: i64, dj: i64| index.get(&(i + di, j + dj)).copied();
                Some([node(0, 0)?, node(1, 0)?, node(0, 1)?, node(1, 1)?])
            }
            Cells::Lattice { cells, buckets } => {
                // Of the cells holding the site (two or four when it is on an
                // edge or a node), the one of the least `i`: one answer for
                // every site.
                let candidates = buckets.get(&bucket(lon, lat))?;
                candidates
                    .iter()
                    .map(|&c| cells[c])
                    .find(|cell| contains(cell.map(|k| (self.nodes[k].lon, self.nodes[k].lat)), (lon, lat)))
            }
        }
    }

    /// The four nodes of the cell that holds the site and its great-circle
    /// distances (km) to them, or [`Error::OutsideGrid`].
    pub fn cell_nodes(&self, lon: f64, lat: f64) -> Result<[(&GridNode, f64); 4], Error> {
        if !(lon.is_finite() && lat.is_finite()) {
            return Err(invalid(
                "lon",
                format!("the site's coordinates must be finite numbers, got lon {lon}, lat {lat}"),
            ));
        }
        let cell = self.cell(lon, lat).ok_or(Error::OutsideGrid { lon, lat })?;
        Ok(cell.map(|k| {
            let n = &self.nodes[k];
            (n, great_circle_distance_km(lon, lat, n.lon, n.lat))
        }))
    }

    /// The site parameters at (`lon`, `lat`) (degrees) at each tabulated return
    /// period, weighted over the four nodes of its cell by inverse distance; a
    /// site outside the grid (a node of its cell missing) is an error.
    pub fn site(&self, lon: f64, lat: f64) -> Result<SiteHazard, Error> {
        let cell = self.cell_nodes(lon, lat)?;
        let distances = cell.map(|(_, d)| d);
        let nodes = cell.map(|(n, _)| n);
        let sites = std::array::from_fn(|k| NtcSite {
            ag: inverse_distance_weighting(nodes.map(|n| n.sites[k].ag), distances),
            f0: inverse_distance_weighting(nodes.map(|n| n.sites[k].f0), distances),
            tc_star: inverse_distance_weighting(nodes.map(|n| n.sites[k].tc_star), distances),
        });
        Ok(SiteHazard { sites })
    }
}

/// The deflated text of the official grid (`data/hazard/pack_grid.py` writes it
/// from the repository's copy of Tabella 1).
static OFFICIAL_TABLE: &[u8] = include_bytes!("../data/ntc2018-tabella1.zlib");

impl Cells {
    /// Whether any cell has its four nodes.
    fn has_a_cell(&self) -> bool {
        match self {
            Cells::Regular { index, .. } => index
                .keys()
                .any(|&(i, j)| [(i + 1, j), (i, j + 1), (i + 1, j + 1)].iter().all(|k| index.contains_key(k))),
            Cells::Lattice { cells, .. } => !cells.is_empty(),
        }
    }
}

/// The cells of a grid regular in longitude and latitude, or why it is not one.
fn regular_cells(nodes: &[GridNode]) -> Result<Cells, String> {
    let (lon0, dlon, nlon) = lattice_axis(nodes.iter().map(|n| n.lon));
    let (lat0, dlat, nlat) = lattice_axis(nodes.iter().map(|n| n.lat));
    if nlon < 2 || nlat < 2 {
        return Err(format!(
            "the grid needs at least two longitudes and two latitudes to hold a cell, got {nlon} and {nlat}"
        ));
    }
    let mut index = HashMap::new();
    let (mut imax, mut jmax) = (0, 0);
    for (k, node) in nodes.iter().enumerate() {
        let fi = (node.lon - lon0) / dlon;
        let fj = (node.lat - lat0) / dlat;
        let (i, j) = (fi.round(), fj.round());
        if (fi - i).abs() > LATTICE_TOLERANCE || (fj - j).abs() > LATTICE_TOLERANCE {
            return Err(format!(
                "node {} (lon {}, lat {}) is off the lattice of spacing {dlon}° × {dlat}° from ({lon0}, {lat0}): the nodes are not regular in longitude and latitude",
                k + 1,
                node.lon,
                node.lat
            ));
        }
        // Lattice indices are whole numbers well inside i64 (a lattice of at least 1e-9° spacing on the globe).
        let (i, j) = (i as i64, j as i64);
        if let Some(other) = index.insert((i, j), k) {
            return Err(format!(
                "nodes {} and {} are at the same place (lon {}, lat {})",
                other + 1,
                k + 1,
                node.lon,
                node.lat
            ));
        }
        imax = imax.max(i);
        jmax = jmax.max(j);
    }
    Ok(Cells::Regular {
        index,
        lon0,
        lat0,
        dlon,
        dlat,
        imax,
        jmax,
    })
}

/// The cells of the decree's lattice of node IDs, or why the IDs make none.
fn lattice_cells(nodes: &[GridNode]) -> Result<Cells, String> {
    let mut by_id: HashMap<i64, usize> = HashMap::with_capacity(nodes.len());
    for (k, node) in nodes.iter().enumerate() {
        let text = node.id.as_deref().unwrap_or_default();
        let id: i64 = text.parse().map_err(|_| format!("node {} has the ID {text:?}, not a whole number", k + 1))?;
        if let Some(other) = by_id.insert(id, k) {
            return Err(format!("nodes {} and {} have the same ID {id}", other + 1, k + 1));
        }
    }
    let mut ids: Vec<i64> = by_id.keys().copied().collect();
    ids.sort_unstable();
    let mut cells = Vec::new();
    let mut buckets: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    for i in ids {
        let corners = [i, i + 1, i + LATTICE_ROW + 1, i + LATTICE_ROW].map(|id| by_id.get(&id).copied());
        let [Some(a), Some(b), Some(c), Some(d)] = corners else {
            continue;
        };
        let cell = [a, b, c, d];
        let (lons, lats) = (cell.map(|k| nodes[k].lon), cell.map(|k| nodes[k].lat));
        let (low, high) = (
            bucket(
                lons.iter().copied().fold(f64::INFINITY, f64::min),
                lats.iter().copied().fold(f64::INFINITY, f64::min),
            ),
            bucket(
                lons.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                lats.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            ),
        );
        for bi in low.0..=high.0 {
            for bj in low.1..=high.1 {
                buckets.entry((bi, bj)).or_default().push(cells.len());
            }
        }
        cells.push(cell);
    }
    if cells.is_empty() {
        return Err("no node has the nodes of IDs i+1, i+222 and i+223 beside it".into());
    }
    Ok(Cells::Lattice { cells, buckets })
}

/// The square of [`BUCKET_DEGREES`] that holds a point.
fn bucket(lon: f64, lat: f64) -> (i64, i64) {
    // Coordinates on the globe, divided by 0.1°: whole numbers well inside i64.
    ((lon / BUCKET_DEGREES).floor() as i64, (lat / BUCKET_DEGREES).floor() as i64)
}

/// Whether the point lies in the convex quadrilateral of the four corners
/// (in order around it, either way), edges included, in the plane of
/// longitude and latitude.
fn contains(corners: [(f64, f64); 4], point: (f64, f64)) -> bool {
    let side = |k: usize| {
        let (a, b) = (corners[k], corners[(k + 1) % 4]);
        (b.0 - a.0) * (point.1 - a.1) - (b.1 - a.1) * (point.0 - a.0)
    };
    let sides = [side(0), side(1), side(2), side(3)];
    sides.iter().all(|&s| s <= EDGE_TOLERANCE) || sides.iter().all(|&s| s >= -EDGE_TOLERANCE)
}

/// The groups of small islands outside the grid, each with one set of values
/// (Tabella 2 of Allegato B).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Island {
    /// Arcipelago Toscano, Egadi, Pantelleria, Sardegna, Lampedusa and Linosa, Ponza, Palmarola and Zannone.
    G1,
    /// Ventotene, Santo Stefano.
    G2,
    /// Ustica, Tremiti.
    G3,
    /// Alicudi, Filicudi.
    G4,
    /// Panarea, Stromboli, Lipari, Vulcano, Salina.
    G5,
}

/// Tabella 2 of Allegato B as the repository's copy gives it (`data/hazard/pack_grid.py` copies it here).
const ISLANDS_TABLE: &str = include_str!("../data/ntc2018-tabella2.txt");

impl Island {
    /// The five groups, in order.
    pub const ALL: [Island; 5] = [Island::G1, Island::G2, Island::G3, Island::G4, Island::G5];

    /// Its name in Tabella 2: `G1` … `G5`.
    pub fn as_str(self) -> &'static str {
        match self {
            Island::G1 => "G1",
            Island::G2 => "G2",
            Island::G3 => "G3",
            Island::G4 => "G4",
            Island::G5 => "G5",
        }
    }

    /// The islands of the group.
    pub fn places(self) -> &'static str {
        match self {
            Island::G1 => "Arcipelago Toscano, Egadi, Pantelleria, Sardegna, Lampedusa and Linosa, Ponza, Palmarola and Zannone",
            Island::G2 => "Ventotene, Santo Stefano",
            Island::G3 => "Ustica, Tremiti",
            Island::G4 => "Alicudi, Filicudi",
            Island::G5 => "Panarea, Stromboli, Lipari, Vulcano, Salina",
        }
    }

    /// The group's site parameters at each of the grid's return periods (Tabella 2).
    pub fn hazard(self) -> SiteHazard {
        static TABLE: OnceLock<Vec<(String, SiteHazard)>> = OnceLock::new();
        let table = TABLE.get_or_init(|| {
            ISLANDS_TABLE
                .lines()
                .filter(|l| !l.starts_with('#') && !l.starts_with("GROUP") && !l.trim().is_empty())
                .map(|l| {
                    let f: Vec<&str> = l.split_whitespace().collect();
                    // The embedded table is the library's own, checked by its tests.
                    #[allow(clippy::expect_used)]
                    let number = |c: usize| f.get(c).and_then(|v| v.parse::<f64>().ok()).expect("Tabella 2's numbers parse");
                    let sites = std::array::from_fn(|k| NtcSite {
                        ag: number(1 + 3 * k) / 10.0,
                        f0: number(2 + 3 * k),
                        tc_star: number(3 + 3 * k),
                    });
                    (f[0].to_string(), SiteHazard { sites })
                })
                .collect()
        });
        #[allow(clippy::expect_used)]
        table
            .iter()
            .find(|(g, _)| g == self.as_str())
            .map(|(_, h)| *h)
            .expect("Tabella 2 has the five groups")
    }
}

impl std::str::FromStr for Island {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        Island::ALL
            .into_iter()
            .find(|g| g.as_str() == s)
            .ok_or_else(|| invalid("island", format!("{s:?} is not a group of Tabella 2: \"G1\" to \"G5\"")))
    }
}

impl std::fmt::Display for Island {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}
