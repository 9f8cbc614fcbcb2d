//! The hazard grid of NTC 2018 (Allegato B's table) and Allegato A's
//! interpolation of the site parameters `ag`, `F0`, `Tc*`.
//!
//! The file: a header line, then one node per line, the columns separated by
//! whitespace, tabs, commas or semicolons: an optional node `ID` (told by the
//! header's first name), `LON`, `LAT` (degrees), then `ag` (in g/10, as
//! published), `F0`, `Tc*` (s) for each of the return periods 30, 50, 72, 101,
//! 140, 201, 475, 975 and 2475 years. Lines starting with `#` and blank lines
//! are skipped. The nodes lie on a lattice regular in longitude and latitude;
//! it need not be full (the official grid covers Italy's land only).
//!
//! A site's parameters (Allegato A): the four nodes of the lattice cell that
//! holds it, each parameter `p = Σ(p_i / d_i) / Σ(1 / d_i)` with `d_i` the
//! great-circle distance to node i, at each tabulated return period; then
//! log-log in the return period between the two that bracket it.

use crate::code::{return_period, LimitState};
use crate::error::{invalid, Error};
use crate::ntc::NtcSite;
use std::collections::HashMap;

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
    /// The node at lattice index (i, j): `lon = lon0 + i dlon`, `lat = lat0 + j dlat`.
    index: HashMap<(i64, i64), usize>,
    lon0: f64,
    lat0: f64,
    dlon: f64,
    dlat: f64,
    imax: i64,
    jmax: i64,
}

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

impl SiteHazard {
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

/// The fields of a line, split at whitespace, commas and semicolons.
fn fields(line: &str) -> Vec<&str> {
    line.split(|c: char| c.is_whitespace() || c == ',' || c == ';')
        .filter(|s| !s.is_empty())
        .collect()
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
        let mut lines = text.lines().enumerate().map(|(k, l)| (k + 1, l)).filter(|(_, l)| {
            let t = l.trim();
            !t.is_empty() && !t.starts_with('#')
        });
        let (header_line, header) = lines.next().ok_or_else(|| Error::GridShape("the grid file is empty: no header line".into()))?;
        let header = fields(header);
        if header.first().is_some_and(|h| h.parse::<f64>().is_ok()) {
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
            let f = fields(text);
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
                f[c].parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(|| Error::Grid {
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

    /// A grid of the given nodes, checked to lie on a lattice regular in longitude and latitude.
    pub fn from_nodes(nodes: Vec<GridNode>) -> Result<Self, Error> {
        if nodes.is_empty() {
            return Err(Error::GridShape("the grid has no nodes".into()));
        }
        let (lon0, dlon, nlon) = lattice_axis(nodes.iter().map(|n| n.lon));
        let (lat0, dlat, nlat) = lattice_axis(nodes.iter().map(|n| n.lat));
        if nlon < 2 || nlat < 2 {
            return Err(Error::GridShape(format!(
                "the grid needs at least two longitudes and two latitudes to hold a cell, got {nlon} and {nlat}"
            )));
        }
        let mut index = HashMap::new();
        let (mut imax, mut jmax) = (0, 0);
        for (k, node) in nodes.iter().enumerate() {
            let fi = (node.lon - lon0) / dlon;
            let fj = (node.lat - lat0) / dlat;
            let (i, j) = (fi.round(), fj.round());
            if (fi - i).abs() > LATTICE_TOLERANCE || (fj - j).abs() > LATTICE_TOLERANCE {
                return Err(Error::GridShape(format!(
                    "node {} (lon {}, lat {}) is off the lattice of spacing {dlon}° × {dlat}° from ({lon0}, {lat0}): the nodes must be regular in longitude and latitude",
                    k + 1,
                    node.lon,
                    node.lat
                )));
            }
            // Lattice indices are whole numbers well inside i64 (a lattice of at least 1e-9° spacing on the globe).
            let (i, j) = (i as i64, j as i64);
            if let Some(other) = index.insert((i, j), k) {
                return Err(Error::GridShape(format!(
                    "nodes {} and {} are at the same place (lon {}, lat {})",
                    other + 1,
                    k + 1,
                    node.lon,
                    node.lat
                )));
            }
            imax = imax.max(i);
            jmax = jmax.max(j);
        }
        Ok(Self {
            nodes,
            index,
            lon0,
            lat0,
            dlon,
            dlat,
            imax,
            jmax,
        })
    }

    /// The nodes, in the file's order.
    pub fn nodes(&self) -> &[GridNode] {
        &self.nodes
    }

    /// The lattice spacing (degrees of longitude, of latitude).
    pub fn spacing(&self) -> (f64, f64) {
        (self.dlon, self.dlat)
    }

    /// The four nodes of the lattice cell that holds the site, or `None` when one is missing.
    fn cell(&self, lon: f64, lat: f64) -> Option<[&GridNode; 4]> {
        // A site on the last line of the lattice belongs to the cell before it.
        let locate = |f: f64, max: i64| -> Option<i64> {
            let tol = 1e-9;
            if !(f >= -tol && f <= max as f64 + tol) {
                return None;
            }
            Some((f.floor() as i64).clamp(0, max - 1))
        };
        let i = locate((lon - self.lon0) / self.dlon, self.imax)?;
        let j = locate((lat - self.lat0) / self.dlat, self.jmax)?;
        let node = |di: i64, dj: i64| self.index.get(&(i + di, j + dj)).map(|&k| &self.nodes[k]);
        Some([node(0, 0)?, node(1, 0)?, node(0, 1)?, node(1, 1)?])
    }

    /// The site parameters at (`lon`, `lat`) (degrees) at each tabulated return
    /// period, weighted over the four nodes of its cell by inverse distance; a
    /// site outside the grid (a node of its cell missing) is an error.
    pub fn site(&self, lon: f64, lat: f64) -> Result<SiteHazard, Error> {
        if !(lon.is_finite() && lat.is_finite()) {
            return Err(invalid(
                "lon",
                format!("the site's coordinates must be finite numbers, got lon {lon}, lat {lat}"),
            ));
        }
        let cell = self.cell(lon, lat).ok_or(Error::OutsideGrid { lon, lat })?;
        let distances = cell.map(|n| great_circle_distance_km(lon, lat, n.lon, n.lat));
        let sites = std::array::from_fn(|k| NtcSite {
            ag: inverse_distance_weighting(cell.map(|n| n.sites[k].ag), distances),
            f0: inverse_distance_weighting(cell.map(|n| n.sites[k].f0), distances),
            tc_star: inverse_distance_weighting(cell.map(|n| n.sites[k].tc_star), distances),
        });
        Ok(SiteHazard { sites })
    }
}
