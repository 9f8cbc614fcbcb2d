//! `rocking inventory TOWERS.csv --assess ASSESS.toml [--out DIR] [--threads N]`:
//! every bell tower of a town assessed as `rocking assess` assesses one, with
//! the kinematic checks. Each row of TOWERS.csv is the assessment file's table
//! with the row's cells set in it (a dotted column is a key, `soil`,
//! `topography`, `ag_SLV`… are the site's, `lon`, `lat` the place on the
//! hazard grid), read by the same functions as the file, so a tower's numbers
//! are those of `rocking assess` on a file with the same values. The rows run
//! on all cores and are written in input order; a bad row gets its `error`
//! and the others go on. Writes `inventory.csv` and `inventory.geojson`.

use crate::format::sig;
use crate::output;
use anyhow::Context;
use rayon::prelude::*;
use rocking_assess::{governing, AssessmentInput, Check, Method, Role};
use rocking_codes::LimitState;
use rocking_scenario::{set_dotted, AssessmentFile, Code};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// One row per tower: each check's ag capacity and ζ_E, the governing one, the error.
pub const INVENTORY_CSV: &str = "inventory.csv";
/// The same as RFC 7946 points.
pub const INVENTORY_GEOJSON: &str = "inventory.geojson";

/// The kinematic checks in the order of their columns, by the role of their limit state.
const CHECKS: [(Role, Method); 4] = [
    (Role::Damage, Method::Activation),
    (Role::LifeSafety, Method::LinearKinematic),
    (Role::LifeSafety, Method::NonlinearKinematic),
    (Role::Collapse, Method::NonlinearKinematic),
];
/// The columns of a tower's identity and place.
const IDENTITY: [&str; 4] = ["id", "name", "lon", "lat"];
/// Site columns that are keys of `[site]` under the same name.
const SITE_COLUMNS: [&str; 5] = ["soil", "topography", "ST", "VN", "CU"];
/// The keys of `[site]` that give the parameters from a hazard grid.
const GRID_KEYS: [&str; 5] = ["grid", "lon", "lat", "VN", "CU"];

/// Arguments of `rocking inventory`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The towers: one row each, with id, name, lon, lat (WGS84 degrees), and
    /// any scenario key (tower.width), soil, topography or ag_SLV, F0_SLV,
    /// Tc_star_SLV… as columns; empty cells take the assessment file's values.
    pub towers: PathBuf,
    /// The assessment file every tower starts from (its site from the hazard grid at each tower's lon, lat).
    #[arg(long, value_name = "ASSESS.toml")]
    pub assess: PathBuf,
    /// Output folder, created if needed [default: out/<towers file stem>]. The
    /// files of an earlier run of this tool there are replaced once the
    /// inventory ends; other files and inputs never are.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub threads: Option<u32>,
}

/// What a column of TOWERS.csv sets.
#[derive(Debug, Clone, PartialEq)]
enum Column {
    /// `id`, `name`, `lon` or `lat`.
    Identity,
    /// A key of `[site]` (`site.soil`, `site.SLV.ag`).
    Site(String),
    /// Any other dotted key of the assessment file (`tower.width`).
    Key(String),
}

/// Where each column goes, from the header; a header fault is one line naming the file and the column.
fn columns(header: &csv::StringRecord, code: Code, file: &Path) -> anyhow::Result<Vec<Column>> {
    let mut seen = HashMap::new();
    let mut out = Vec::new();
    for (i, name) in header.iter().enumerate() {
        if let Some(first) = seen.insert(name, i) {
            anyhow::bail!("{}: column {name} appears twice (columns {} and {})", file.display(), first + 1, i + 1);
        }
        let state_param = name.rsplit_once('_').and_then(|(param, state)| {
            let state = code.limit_states().iter().find(|s| s.as_str() == state)?;
            let keys = if code == Code::Ntc2018 {
                rocking_scenario::NTC_STATE_KEYS
            } else {
                rocking_scenario::EC8_STATE_KEYS
            };
            keys.contains(&param).then(|| format!("site.{state}.{param}"))
        });
        out.push(if IDENTITY.contains(&name) {
            Column::Identity
        } else if SITE_COLUMNS.contains(&name) {
            Column::Site(format!("site.{name}"))
        } else if let Some(key) = state_param {
            Column::Site(key)
        } else if name.contains('.') && !name.starts_with("site.") && !name.starts_with("ground.") {
            Column::Key(name.to_string())
        } else {
            anyhow::bail!(
                "{}: unknown column {name:?}; a column is id, name, lon, lat, soil, topography, ST, VN, CU, a limit state's site parameter \
                 (ag_SLV, F0_SLV, Tc_star_SLV with code = \"ntc2018\"; ag_SD with \"ec8\") or a dotted key of the assessment file (tower.width)",
                file.display()
            );
        });
    }
    for required in ["id", "lon", "lat"] {
        if !seen.contains_key(required) {
            anyhow::bail!("{}: no column {required} (a tower needs id, lon and lat)", file.display());
        }
    }
    Ok(out)
}

/// A cell as a TOML value: a number, a boolean or a quoted string as TOML reads it, else the text as a string.
fn cell_value(cell: &str) -> Value {
    format!("v = {cell}")
        .parse::<Table>()
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| Value::String(cell.to_string()))
}

/// One tower's result: its cells as given and its checks, or the one line of its error.
#[derive(Debug)]
struct Tower {
    id: String,
    name: String,
    lon: String,
    lat: String,
    /// The place, when both coordinates are numbers.
    point: Option<(f64, f64)>,
    checks: Result<Vec<Check>, String>,
}

/// The cells of one row by column name (empty cells left out).
struct Row<'a> {
    number: usize,
    cells: Vec<(&'a str, &'a Column, &'a str)>,
}

impl Row<'_> {
    fn get(&self, name: &str) -> Option<&str> {
        self.cells.iter().find(|(n, _, _)| *n == name).map(|(_, _, v)| *v)
    }
    /// `TOWERS.csv row N (id X), column C: what`.
    fn fault(&self, file: &Path, column: &str, what: impl std::fmt::Display) -> String {
        let id = self.get("id").map(|id| format!(" (id {id})")).unwrap_or_default();
        format!("{} row {}{id}, column {column}: {what}", file.display(), self.number)
    }
}

/// A coordinate of the row: a number within ±`limit` degrees.
fn coordinate(row: &Row<'_>, file: &Path, name: &str, limit: f64) -> Result<f64, String> {
    let text = row
        .get(name)
        .ok_or_else(|| row.fault(file, name, "missing: a tower needs its place (WGS84 degrees)"))?;
    let x: f64 = text.trim().parse().map_err(|_| row.fault(file, name, format!("not a number: {text:?}")))?;
    if !x.is_finite() || x.abs() > limit {
        return Err(row.fault(file, name, format!("must be within ±{limit} degrees, got {x}")));
    }
    Ok(x)
}

/// The assessment file's table with the row's cells set in it.
fn row_table(base: &Table, row: &Row<'_>, file: &Path, lon: f64, lat: f64) -> Result<Table, String> {
    let mut table = base.clone();
    let site = match table.entry("site").or_insert_with(|| Value::Table(Table::new())) {
        Value::Table(t) => t,
        _ => return Err(row.fault(file, "site", "the assessment file's site is not a table")),
    };
    let has = |name: &str| row.get(name).is_some();
    // A row's own limit-state parameters replace the grid; its topography or ST replaces the other.
    if row.cells.iter().any(|(_, c, _)| matches!(c, Column::Site(k) if k.matches('.').count() == 2)) {
        for key in GRID_KEYS {
            site.remove(key);
        }
    }
    if has("topography") {
        site.remove("ST");
    }
    if has("ST") {
        site.remove("topography");
    }
    if site.contains_key("grid") {
        site.insert("lon".into(), Value::Float(lon));
        site.insert("lat".into(), Value::Float(lat));
    }
    for (name, column, cell) in &row.cells {
        let key = match column {
            Column::Identity => continue,
            Column::Site(key) | Column::Key(key) => key,
        };
        let value = if matches!(*name, "soil" | "topography") {
            Value::String(cell.to_string())
        } else {
            cell_value(cell)
        };
        set_dotted(&mut table, key, value).map_err(|e| row.fault(file, name, e))?;
    }
    Ok(table)
}

/// Assesses one row.
fn assess_row(base: &Table, origin: &Path, file: &Path, row: &Row<'_>, first_of_id: Option<usize>) -> Tower {
    let text = |name: &str| row.get(name).unwrap_or("").to_string();
    let lon = coordinate(row, file, "lon", 180.0);
    let lat = coordinate(row, file, "lat", 90.0);
    let point = lon.as_ref().ok().zip(lat.as_ref().ok()).map(|(x, y)| (*x, *y));
    let checks = (|| {
        if row.get("id").is_none() {
            return Err(row.fault(file, "id", "missing: each tower needs an id"));
        }
        if let Some(first) = first_of_id {
            return Err(row.fault(file, "id", format!("the same id as row {first}")));
        }
        let (lon, lat) = (lon.clone()?, lat.clone()?);
        let table = row_table(base, row, file, lon, lat)?;
        // A fault names the key; the row's column that set it, else the assessment file's key.
        let fault = |e: rocking_scenario::Error| {
            let key = e.key().unwrap_or("");
            let column = row
                .cells
                .iter()
                .find(|(n, c, _)| match c {
                    Column::Site(k) | Column::Key(k) => k == key,
                    Column::Identity => key == format!("site.{n}"),
                })
                .map_or_else(|| format!("{key} (of {})", origin.display()), |(n, _, v)| format!("{n} ({v:?})"));
            row.fault(file, &column, e.kind())
        };
        let input = AssessmentFile::from_table(table, origin).and_then(AssessmentInput::new).map_err(fault)?;
        let capacity = input.capacity().map_err(fault)?;
        input.kinematic_checks(&capacity).map_err(fault)
    })();
    Tower {
        id: text("id"),
        name: text("name"),
        lon: text("lon"),
        lat: text("lat"),
        point,
        checks,
    }
}

/// The check of a role and method among a tower's checks.
fn find(checks: &[Check], state: LimitState, method: Method) -> Option<&Check> {
    checks.iter().find(|c| c.limit_state == state && c.method == method)
}

/// The column prefix of each check: `SLV_nonlinear_kinematic`.
fn check_names(ntc: bool) -> Vec<(LimitState, Method, String)> {
    CHECKS
        .iter()
        .map(|&(role, method)| {
            let state = role.limit_state(ntc);
            (state, method, format!("{state}_{method}"))
        })
        .collect()
}

/// `inventory.csv`: one row per tower in input order.
fn write_csv(path: &Path, shown: &Path, towers: &[Tower], ntc: bool) -> anyhow::Result<()> {
    let names = check_names(ntc);
    let mut header: Vec<String> = IDENTITY.iter().map(|s| s.to_string()).collect();
    for (_, _, n) in &names {
        header.push(format!("{n}_ag_capacity_g"));
        header.push(format!("{n}_zeta_E"));
    }
    header.extend(["zeta_E", "governing", "error"].map(String::from));
    let mut w = csv::Writer::from_path(path).with_context(|| format!("cannot write {}", shown.display()))?;
    w.write_record(&header).with_context(|| format!("cannot write {}", shown.display()))?;
    let mut buffer = ryu::Buffer::new();
    let mut number = |x: f64| buffer.format(x).to_string();
    for t in towers {
        let mut record = vec![t.id.clone(), t.name.clone(), t.lon.clone(), t.lat.clone()];
        match &t.checks {
            Ok(checks) => {
                for (state, method, _) in &names {
                    match find(checks, *state, *method) {
                        Some(c) => record.extend([number(c.ag_capacity.value()), number(c.zeta_e)]),
                        None => record.extend([String::new(), String::new()]),
                    }
                }
                match governing(checks) {
                    Some(g) => record.extend([number(g.zeta_e), format!("{} {}", g.limit_state, g.method)]),
                    None => record.extend([String::new(), String::new()]),
                }
                record.push(String::new());
            }
            Err(e) => {
                record.extend(std::iter::repeat_n(String::new(), 2 * names.len() + 2));
                record.push(e.clone());
            }
        }
        w.write_record(&record).with_context(|| format!("cannot write {}", shown.display()))?;
    }
    w.flush().with_context(|| format!("cannot write {}", shown.display()))
}

/// `inventory.geojson`: a FeatureCollection of Points (RFC 7946), the properties those of `inventory.csv`
/// (numbers as numbers, a missing one null); a tower without a place has no geometry.
fn geojson(towers: &[Tower], ntc: bool) -> geojson::GeoJson {
    use serde_json::Value as J;
    let names = check_names(ntc);
    let features = towers
        .iter()
        .map(|t| {
            let mut p = geojson::JsonObject::new();
            p.insert("id".into(), J::from(t.id.clone()));
            p.insert("name".into(), J::from(t.name.clone()));
            let checks = t.checks.as_deref().unwrap_or(&[]);
            for (state, method, n) in &names {
                let c = find(checks, *state, *method);
                p.insert(format!("{n}_ag_capacity_g"), c.map_or(J::Null, |c| J::from(c.ag_capacity.value())));
                p.insert(format!("{n}_zeta_E"), c.map_or(J::Null, |c| J::from(c.zeta_e)));
            }
            let g = governing(checks);
            p.insert("zeta_E".into(), g.map_or(J::Null, |g| J::from(g.zeta_e)));
            p.insert("governing".into(), g.map_or(J::Null, |g| J::from(format!("{} {}", g.limit_state, g.method))));
            p.insert("error".into(), t.checks.as_ref().err().map_or(J::Null, |e| J::from(e.clone())));
            geojson::Feature {
                bbox: None,
                geometry: t.point.map(|(lon, lat)| geojson::Geometry::new(geojson::Value::Point(vec![lon, lat]))),
                id: (!t.id.is_empty()).then(|| geojson::feature::Id::String(t.id.clone())),
                properties: Some(p),
                foreign_members: None,
            }
        })
        .collect();
    geojson::GeoJson::FeatureCollection(geojson::FeatureCollection {
        bbox: None,
        features,
        foreign_members: None,
    })
}

/// Assesses the towers and writes the files.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.map_or(0, |n| n as usize))
        .build()
        .context("starting the worker threads")?;
    pool.install(|| inventory(args))
}

fn inventory(args: &Args) -> anyhow::Result<()> {
    let started = std::time::Instant::now();
    let text = std::fs::read_to_string(&args.assess).with_context(|| format!("cannot read {}", args.assess.display()))?;
    // The assessment file must be valid by itself: its errors name the file, the key and the cause.
    let base = AssessmentInput::from_toml_str(&text, &args.assess)?;
    let base_table = rocking_scenario::parse_toml(&text, &args.assess)?;
    let ntc = base.site.is_ntc();
    if !base.file.records.is_empty() {
        eprintln!(
            "note: {} has a record set; inventory runs the kinematic checks only (the dynamic checks of one tower: rocking assess)",
            args.assess.display()
        );
    }

    let file = &args.towers;
    let mut reader = csv::ReaderBuilder::new()
        .flexible(true)
        .trim(csv::Trim::All)
        .from_path(file)
        .with_context(|| format!("cannot read {}", file.display()))?;
    let header = reader.headers().with_context(|| format!("cannot read {}", file.display()))?.clone();
    let columns = columns(&header, base.file.site.code, file)?;
    let records = reader
        .records()
        .collect::<Result<Vec<_>, _>>()
        .with_context(|| format!("cannot read {}", file.display()))?;
    let rows: Vec<Row<'_>> = records
        .iter()
        .enumerate()
        .map(|(i, r)| Row {
            number: i + 1,
            cells: header
                .iter()
                .zip(&columns)
                .zip(r.iter())
                .filter(|(_, cell)| !cell.is_empty())
                .map(|((n, c), cell)| (n, c, cell))
                .collect(),
        })
        .collect();
    // The first row of each id; a later row with the same id is refused.
    let mut first_of: HashMap<&str, usize> = HashMap::new();
    let repeats: Vec<Option<usize>> = rows
        .iter()
        .map(|row| {
            let id = row.get("id")?;
            match first_of.get(id) {
                Some(&first) => Some(first),
                None => {
                    first_of.insert(id, row.number);
                    None
                }
            }
        })
        .collect();
    let short: Vec<Option<String>> = records
        .iter()
        .zip(&rows)
        .map(|(r, row)| (r.len() != header.len()).then(|| format!("{} row {}: {} cells, the header has {}", file.display(), row.number, r.len(), header.len())))
        .collect();

    let dir = args.out.clone().unwrap_or_else(|| super::run::default_out(&args.towers));
    let outputs = [INVENTORY_CSV, INVENTORY_GEOJSON].map(|f| dir.join(f));
    let mut inputs = vec![args.towers.clone(), args.assess.clone()];
    inputs.extend(base.inputs());
    output::refuse_to_overwrite_inputs(&outputs, &inputs)?;
    let staging = output::Staging::new(&dir, &inputs)?;

    let towers: Vec<Tower> = rows
        .par_iter()
        .zip(&repeats)
        .zip(&short)
        .map(|((row, repeat), short)| {
            let mut tower = assess_row(&base_table, &args.assess, file, row, *repeat);
            if let Some(e) = short {
                tower.checks = Err(e.clone());
            }
            tower
        })
        .collect();

    write_csv(&staging.path(INVENTORY_CSV), &dir.join(INVENTORY_CSV), &towers, ntc)?;
    std::fs::write(staging.path(INVENTORY_GEOJSON), geojson(&towers, ntc).to_string() + "\n")
        .with_context(|| format!("cannot write {}", dir.join(INVENTORY_GEOJSON).display()))?;
    staging.commit()?;

    let mut ranked: Vec<(&Tower, &Check)> = towers
        .iter()
        .filter_map(|t| t.checks.as_deref().ok().and_then(governing).map(|g| (t, g)))
        .collect();
    ranked.sort_by(|a, b| a.1.zeta_e.total_cmp(&b.1.zeta_e));
    let bad: Vec<&String> = towers.iter().filter_map(|t| t.checks.as_ref().err()).collect();
    let mut lines = vec![format!("{} towers, ranked by the governing ζ_E (least first):", ranked.len())];
    lines.extend(ranked.iter().take(10).map(|(t, g)| {
        format!(
            "  {:12} {:24} ζ_E {:>6} {} {}{}",
            t.id,
            t.name,
            sig(g.zeta_e, 3),
            g.limit_state,
            g.method,
            if g.holds { "" } else { " (FAILS)" }
        )
    }));
    if ranked.len() > 10 {
        lines.push(format!("  … {} more in {}", ranked.len() - 10, INVENTORY_CSV));
    }
    lines.push(format!(
        "wrote {INVENTORY_CSV}, {INVENTORY_GEOJSON} in {} ({} s)",
        dir.display(),
        sig(started.elapsed().as_secs_f64(), 3)
    ));
    super::print(&(lines.join("\n") + "\n"))?;
    if !bad.is_empty() {
        for e in &bad {
            eprintln!("{e}");
        }
        anyhow::bail!(
            "{} of {} towers not assessed (their error is in {}); the others are",
            bad.len(),
            towers.len(),
            dir.join(INVENTORY_CSV).display()
        );
    }
    Ok(())
}
