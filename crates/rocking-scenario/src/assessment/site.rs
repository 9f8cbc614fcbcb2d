//! The `[site]` table of an assessment file: the code, the soil, the
//! topography and the site parameters of each limit state, given per limit
//! state (`[site.SLV]`) or from a hazard grid at the site's coordinates.

use crate::error::{ErrorKind, Fault};
use crate::read::{positive, Section};
use rocking_codes::{CodeSpectrum, Ec8Spectrum, Ec8Type, HazardGrid, Island, LimitState, NtcSite, NtcSpectrum, Soil, Topography, DEFAULT_DAMPING_PCT};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};
use toml::Value;

/// The keys of `[site]`, its limit states' tables included.
pub const SITE_KEYS: &[&str] = &[
    "code",
    "soil",
    "topography",
    "ST",
    "spectrum_type",
    "grid",
    "island",
    "lon",
    "lat",
    "VN",
    "CU",
    "SLO",
    "SLD",
    "SLV",
    "SLC",
    "DL",
    "SD",
    "NC",
];
/// The keys of an NTC limit state's table (`[site.SLV]`).
pub const NTC_STATE_KEYS: &[&str] = &["ag", "F0", "Tc_star"];
/// The keys of an EN 1998 limit state's table (`[site.SD]`).
pub const EC8_STATE_KEYS: &[&str] = &["ag"];

/// Nominal life `VN` (years) when not given: an ordinary building (NTC 2018 Tab. 2.4.I).
pub const DEFAULT_NOMINAL_LIFE: f64 = 50.0;
/// Coefficient of use `CU` when not given: class II (NTC 2018 Tab. 2.4.II).
pub const DEFAULT_USE_COEFFICIENT: f64 = 1.0;

/// The code an assessment follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Code {
    /// NTC 2018 (Italy), limit states SLO, SLD, SLV, SLC.
    Ntc2018,
    /// EN 1998-1 spectra, EN 1998-3 limit states DL, SD, NC.
    Ec8,
}

impl Code {
    /// Its name in the file: `ntc2018`, `ec8`.
    pub fn as_str(self) -> &'static str {
        match self {
            Code::Ntc2018 => "ntc2018",
            Code::Ec8 => "ec8",
        }
    }
    /// The limit states it has tables for, in order.
    pub fn limit_states(self) -> &'static [LimitState] {
        match self {
            Code::Ntc2018 => &LimitState::NTC,
            Code::Ec8 => &LimitState::EC8,
        }
    }
}

/// Where the site parameters came from.
#[derive(Debug, Clone, PartialEq)]
pub enum SiteSource {
    /// The limit states' tables of the file.
    Tables,
    /// A hazard grid at a site.
    Grid {
        /// The grid file, resolved against the assessment file's folder;
        /// `None` for the official grid (`grid = "ntc2018"`), which the library holds.
        path: Option<PathBuf>,
        /// Longitude of the site (degrees east).
        lon: f64,
        /// Latitude (degrees north).
        lat: f64,
        /// Nominal life `VN` (years).
        nominal_life: f64,
        /// Coefficient of use `CU`.
        use_coefficient: f64,
    },
    /// A group of small islands outside the official grid (Tabella 2 of Allegato B).
    Island {
        /// The group.
        group: Island,
        /// Nominal life `VN` (years).
        nominal_life: f64,
        /// Coefficient of use `CU`.
        use_coefficient: f64,
    },
}

/// The name of the official grid in `[site] grid`.
pub const OFFICIAL_GRID: &str = "ntc2018";

impl SiteSource {
    /// The nominal life `VN` and coefficient of use `CU` of a site from the grid or an island.
    pub fn reference_life(&self) -> Option<(f64, f64)> {
        match self {
            SiteSource::Tables => None,
            SiteSource::Grid {
                nominal_life, use_coefficient, ..
            }
            | SiteSource::Island {
                nominal_life, use_coefficient, ..
            } => Some((*nominal_life, *use_coefficient)),
        }
    }

    /// The grid file read, if one was (not the official grid, not an island).
    pub fn grid_file(&self) -> Option<&Path> {
        match self {
            SiteSource::Grid { path: Some(path), .. } => Some(path),
            _ => None,
        }
    }
}

/// A validated `[site]`: the code spectrum (at 5%) of each limit state given.
#[derive(Debug, Clone, PartialEq)]
pub struct Site {
    /// The code.
    pub code: Code,
    /// The subsoil category (ground type).
    pub soil: Soil,
    /// Where the parameters came from.
    pub source: SiteSource,
    /// Each limit state's elastic spectrum at 5% damping, in the code's order.
    pub spectra: Vec<(LimitState, CodeSpectrum)>,
    /// The site parameters at the grid's nine return periods, when from a grid (a study's hazard curve).
    pub hazard: Option<rocking_codes::SiteHazard>,
}

impl Site {
    /// The spectrum of `state`, if the site has it.
    pub fn spectrum(&self, state: LimitState) -> Option<&CodeSpectrum> {
        self.spectra.iter().find(|(s, _)| *s == state).map(|(_, c)| c)
    }
}

/// The fault of a library error on `key`, the library naming the parameter.
fn codes_fault(prefix: &str, e: rocking_codes::Error) -> Fault {
    match e {
        rocking_codes::Error::InvalidParameter { name, reason } => Fault::invalid(format!("{prefix}.{name}"), reason),
        other => Fault::invalid(prefix, other.to_string()),
    }
}

/// Parses `[site]`; `folder` resolves the grid's path.
pub(crate) fn parse(value: &Value, folder: &Path, grids: &GridCache) -> Result<Site, Fault> {
    let site = Section::new("site", value)?;
    site.only(SITE_KEYS)?;
    let code = site.choice("code", &[("ntc2018", Code::Ntc2018), ("ec8", Code::Ec8)])?.unwrap_or(Code::Ntc2018);
    let soil: Soil = match site.string("soil")? {
        Some(s) => s.parse().map_err(|e| codes_fault("site", e))?,
        None => {
            return Err(Fault::new(
                "site.soil",
                ErrorKind::Missing("required: the subsoil category, \"A\" to \"E\"".into()),
            ))
        }
    };
    let other_code = |key: &str| -> Result<(), Fault> {
        if site.has(key) {
            return Err(Fault::new(
                site.key(key),
                ErrorKind::NotApplicable(format!("does not apply with code = \"{}\"", code.as_str())),
            ));
        }
        Ok(())
    };
    for state in LimitState::NTC.iter().chain(&LimitState::EC8) {
        if !code.limit_states().contains(state) {
            other_code(state.as_str())?;
        }
    }
    let tables: Vec<LimitState> = code.limit_states().iter().copied().filter(|s| site.has(s.as_str())).collect();
    let grid = site.string("grid")?;
    let island = match site.string("island")? {
        Some(name) => Some(name.parse::<Island>().map_err(|e| codes_fault("site", e))?),
        None => None,
    };
    if island.is_some() {
        for key in ["grid", "lon", "lat"] {
            if site.has(key) {
                return Err(Fault::new(
                    site.key(key),
                    ErrorKind::NotApplicable("does not apply with island: an island group of Tabella 2 takes the place of the grid and the site on it".into()),
                ));
            }
        }
    } else if grid.is_none() {
        for key in ["lon", "lat", "VN", "CU"] {
            if site.has(key) {
                return Err(Fault::new(site.key(key), ErrorKind::NotApplicable("applies only with grid (or island)".into())));
            }
        }
    }
    let mut kept_hazard = None;
    let spectra = match code {
        Code::Ntc2018 => {
            other_code("spectrum_type")?;
            site.exclusive("topography", "ST")?;
            let topography = match (site.string("topography")?, site.number("ST")?) {
                (Some(t), _) => t.parse().map_err(|e| codes_fault("site", e))?,
                (None, Some(st)) => Topography::factor(st).map_err(|e| codes_fault("site", e))?,
                (None, None) => Topography::T1,
            };
            let build = |state: LimitState, ntc: NtcSite, prefix: &str| {
                NtcSpectrum::new(ntc, soil, topography, DEFAULT_DAMPING_PCT)
                    .map(|s| (state, CodeSpectrum::Ntc(s)))
                    .map_err(|e| codes_fault(prefix, e))
            };
            let on_grid = match (grid, island) {
                (Some(path), _) => Some(grid_site(&site, path, folder, grids)?),
                (None, Some(group)) => {
                    let (nominal_life, use_coefficient) = reference_life(&site)?;
                    Some((
                        group.hazard(),
                        nominal_life,
                        use_coefficient,
                        SiteSource::Island {
                            group,
                            nominal_life,
                            use_coefficient,
                        },
                    ))
                }
                (None, None) => None,
            };
            match on_grid {
                Some((hazard, nominal_life, use_coefficient, source)) => {
                    if let Some(state) = tables.first() {
                        return Err(Fault::new(
                            site.key(state.as_str()),
                            ErrorKind::NotApplicable("give either the limit states' tables or grid (or island), not both".into()),
                        ));
                    }
                    kept_hazard = Some(hazard);
                    // The checks' limit states.
                    [LimitState::Sld, LimitState::Slv, LimitState::Slc]
                        .into_iter()
                        .map(|state| {
                            let ntc = hazard
                                .for_limit_state(state, nominal_life, use_coefficient)
                                .map_err(|e| codes_fault("site", e))?;
                            build(state, ntc, "site.grid")
                        })
                        .collect::<Result<Vec<_>, Fault>>()
                        .map(|spectra| (spectra, source))
                }
                None => tables
                    .iter()
                    .map(|&state| {
                        let name = state.as_str();
                        let table = Section::new(static_key(state), site.get(name).unwrap_or(&Value::Boolean(false)))?;
                        table.only(NTC_STATE_KEYS)?;
                        let mut values = [0.0; 3];
                        for (v, key) in values.iter_mut().zip(NTC_STATE_KEYS) {
                            *v = table
                                .number(key)?
                                .ok_or_else(|| Fault::new(table.key(key), ErrorKind::Missing("required".into())))?;
                        }
                        let ntc = NtcSite::new(values[0], values[1], values[2]).map_err(|e| codes_fault(table.name(), e))?;
                        build(state, ntc, table.name())
                    })
                    .collect::<Result<Vec<_>, Fault>>()
                    .map(|spectra| (spectra, SiteSource::Tables)),
            }
        }
        Code::Ec8 => {
            for key in ["topography", "ST", "grid", "island"] {
                other_code(key)?;
            }
            let kind = match site.number("spectrum_type")? {
                Some(n) => Ec8Type::from_number(n).map_err(|e| codes_fault("site", e))?,
                None => Ec8Type::Type1,
            };
            tables
                .iter()
                .map(|&state| {
                    let table = Section::new(static_key(state), site.get(state.as_str()).unwrap_or(&Value::Boolean(false)))?;
                    table.only(EC8_STATE_KEYS)?;
                    let ag = table
                        .number("ag")?
                        .ok_or_else(|| Fault::new(table.key("ag"), ErrorKind::Missing("required: γI agR (g)".into())))?;
                    Ec8Spectrum::new(ag, soil, kind, DEFAULT_DAMPING_PCT)
                        .map(|s| (state, CodeSpectrum::Ec8(s)))
                        .map_err(|e| codes_fault(table.name(), e))
                })
                .collect::<Result<Vec<_>, Fault>>()
                .map(|spectra| (spectra, SiteSource::Tables))
        }
    };
    let (spectra, source) = spectra?;
    if spectra.is_empty() {
        let names: Vec<String> = code.limit_states().iter().map(|s| format!("[site.{s}]")).collect();
        let grid = if code == Code::Ntc2018 {
            " or grid, lon, lat (grid = \"ntc2018\", the official grid)"
        } else {
            ""
        };
        return Err(Fault::new(
            "site",
            ErrorKind::Missing(format!("give the site parameters: {}{grid}", names.join(", "))),
        ));
    }
    Ok(Site {
        code,
        soil,
        source,
        spectra,
        hazard: kept_hazard,
    })
}

/// The dotted name of a limit state's table.
fn static_key(state: LimitState) -> &'static str {
    match state {
        LimitState::Slo => "site.SLO",
        LimitState::Sld => "site.SLD",
        LimitState::Slv => "site.SLV",
        LimitState::Slc => "site.SLC",
        LimitState::Dl => "site.DL",
        LimitState::Sd => "site.SD",
        LimitState::Nc => "site.NC",
    }
}

/// The hazard grid last read, kept so that the sites of many files on the
/// same grid (the towers of an inventory) read and parse it once.
#[derive(Debug, Default)]
pub struct GridCache(Mutex<Option<(PathBuf, Arc<HazardGrid>)>>);

impl GridCache {
    /// A cache holding the grid of `file` read from its text (the page has
    /// the text of a grid, not the file): a site whose grid resolves to
    /// `file` takes it, and reads no file. An error says what is wrong with the text.
    pub fn holding(file: &Path, text: &str) -> Result<Self, String> {
        let grid = HazardGrid::parse(text).map_err(|e| format!("{}: {e}", file.display()))?;
        Ok(Self(Mutex::new(Some((file.to_path_buf(), Arc::new(grid))))))
    }

    /// The node of the grid of `file` nearest the mean of all its nodes'
    /// places: a place inside the grid, where a file that gives none
    /// (`rocking inventory`'s, whose towers give theirs) is checked by itself.
    pub fn central_node(&self, file: &Path) -> Option<(f64, f64)> {
        let grid = self.grid(file).ok()?;
        let nodes = grid.nodes();
        let count = nodes.len() as f64;
        let (lon, lat) = nodes.iter().fold((0.0, 0.0), |(x, y), n| (x + n.lon / count, y + n.lat / count));
        nodes
            .iter()
            .min_by(|a, b| ((a.lon - lon).powi(2) + (a.lat - lat).powi(2)).total_cmp(&((b.lon - lon).powi(2) + (b.lat - lat).powi(2))))
            .map(|n| (n.lon, n.lat))
    }

    /// The grid of `file`: the one kept if it is that file's, else read and parsed (and kept).
    fn grid(&self, file: &Path) -> Result<Arc<HazardGrid>, Fault> {
        let mut kept = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some((_, grid)) = kept.as_ref().filter(|(path, _)| path == file) {
            return Ok(Arc::clone(grid));
        }
        let text = std::fs::read_to_string(file).map_err(|e| {
            Fault::new(
                "site.grid",
                ErrorKind::Read {
                    path: file.to_path_buf(),
                    reason: crate::error::io_reason(&e),
                    os_error: e.raw_os_error(),
                },
            )
        })?;
        let grid = Arc::new(HazardGrid::parse(&text).map_err(|e| Fault::invalid("site.grid", format!("{}: {e}", file.display())))?);
        *kept = Some((file.to_path_buf(), Arc::clone(&grid)));
        Ok(grid)
    }
}

/// `VN` and `CU` of a site from the grid or an island (their defaults when not given).
fn reference_life(site: &Section<'_>) -> Result<(f64, f64), Fault> {
    let nominal_life = positive("site.VN", site.number("VN")?.unwrap_or(DEFAULT_NOMINAL_LIFE))?;
    let use_coefficient = positive("site.CU", site.number("CU")?.unwrap_or(DEFAULT_USE_COEFFICIENT))?;
    Ok((nominal_life, use_coefficient))
}

/// Reads the grid (or takes it from `grids`; `grid = "ntc2018"` is the
/// official one, held by the library) and interpolates it at the site: the
/// site's hazard, `VN`, `CU` and the source.
fn grid_site(site: &Section<'_>, path: &str, folder: &Path, grids: &GridCache) -> Result<(rocking_codes::SiteHazard, f64, f64, SiteSource), Fault> {
    let required = |key: &str| -> Result<f64, Fault> {
        site.number(key)?.ok_or_else(|| {
            Fault::new(
                site.key(key),
                ErrorKind::Missing(format!(
                    "required with grid: the site's {}",
                    if key == "lon" {
                        "longitude (degrees east)"
                    } else {
                        "latitude (degrees north)"
                    }
                )),
            )
        })
    };
    let (lon, lat) = (required("lon")?, required("lat")?);
    let (nominal_life, use_coefficient) = reference_life(site)?;
    let (grid, file) = if path == OFFICIAL_GRID {
        (None, None)
    } else {
        let file = folder.join(path);
        (Some(grids.grid(&file)?), Some(file))
    };
    let grid: &HazardGrid = grid.as_deref().unwrap_or_else(|| HazardGrid::ntc2018());
    let named = file
        .as_ref()
        .map_or_else(|| "the official grid of NTC 2018".to_string(), |f| f.display().to_string());
    let hazard = grid.site(lon, lat).map_err(|e| match e {
        rocking_codes::Error::OutsideGrid { .. } => Fault::invalid("site.lon", format!("{e} ({named})")),
        other => codes_fault("site", other),
    })?;
    Ok((
        hazard,
        nominal_life,
        use_coefficient,
        SiteSource::Grid {
            path: file,
            lon,
            lat,
            nominal_life,
            use_coefficient,
        },
    ))
}
