//! The page's town tab: every tower of a towers' CSV assessed as `rocking
//! inventory` assesses it ([`rocking_assess::Inventory`]), a few towers at a
//! time by the page's Web Worker (which reports progress between them), and
//! the towers ranked for the map and the table ([`rocking_assess::Town`]): the
//! rows of the command's `inventory.csv`, field for field.

use rocking_assess::{ranking, Inventory, Town};
use rocking_scenario::{csv_line, Cases, Cell, GridCache};
use serde_json::{json, Value};
use std::path::Path;
use toml::Table;
use wasm_bindgen::prelude::*;

/// A town being assessed: the inventory and the rows done so far (their fields' text).
#[wasm_bindgen]
pub struct WebTown {
    inventory: Inventory,
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl WebTown {
    /// The inventory of the towers' CSV text `towers` (named `towers_name` in
    /// errors) on the assessment file's TOML text `assess` (named `origin`,
    /// the folder its grid's path is relative to), with the hazard grid's text
    /// `grid` when the file names one (picked as `grid_name`, when given: its
    /// file name must be the one `site.grid` names), and `records` the JSON text of the
    /// record set `[{ "name", "text" }, …]` to put in `assessment.records`
    /// (`null` or empty: the kinematic checks only, whatever the file says;
    /// when the file names its records, those of the set with their file names).
    pub fn create(
        assess: &str,
        origin: &str,
        towers: &str,
        towers_name: &str,
        grid: Option<String>,
        grid_name: Option<String>,
        records: &str,
    ) -> Result<Self, String> {
        let origin = Path::new(origin);
        let mut table = rocking_scenario::parse_toml(assess, origin).map_err(|e| e.to_string())?;
        set_records(&mut table, records, origin)?;
        let grids = match (grid, grid_path(&table, origin)) {
            (Some(text), Some(path)) => {
                let named = file_name(&path.to_string_lossy()).to_string();
                if let Some(picked) = grid_name.as_deref().map(file_name).filter(|p| *p != named) {
                    return Err(format!("{}: site.grid: names {named}, not {picked}", origin.display()));
                }
                GridCache::holding(&path, &text).map_err(|e| format!("{}: site.grid: {e}", origin.display()))?
            }
            (None, Some(path)) => {
                let named = file_name(&path.to_string_lossy()).to_string();
                return Err(format!("{}: site.grid: names {named}, which is not picked", origin.display()));
            }
            _ => GridCache::default(),
        };
        let inventory = Inventory::from_table(table, origin, towers.as_bytes(), Path::new(towers_name), grids).map_err(|e| e.to_string())?;
        let header = inventory.header();
        Ok(Self {
            inventory,
            header,
            rows: Vec::new(),
        })
    }
}

/// The file the site's `grid` resolves to, as the assessment file's reader resolves it.
fn grid_path(table: &Table, origin: &Path) -> Option<std::path::PathBuf> {
    let grid = table.get("site")?.get("grid")?.as_str()?;
    // The official grid is the library's: no file to pick.
    if grid == rocking_scenario::OFFICIAL_GRID {
        return None;
    }
    Some(origin.parent().unwrap_or(Path::new("")).join(grid))
}

/// The part of a path after its last `/` (or backslash).
fn file_name(path: &str) -> &str {
    path.rsplit(['/', '\\']).next().unwrap_or(path)
}

/// The records of `given` (`{ name, text }` values) that the patterns of
/// `assessment.records` (a string or strings, file paths or globs) match by
/// file name, in the patterns' order; a pattern that matches none of them is
/// an error naming it.
fn named_records(patterns: &toml::Value, given: Vec<Value>, origin: &Path) -> Result<Vec<Value>, String> {
    let patterns: Vec<&str> = match patterns {
        toml::Value::String(p) => vec![p.as_str()],
        toml::Value::Array(items) => items.iter().filter_map(toml::Value::as_str).collect(),
        _ => Vec::new(),
    };
    let name = |v: &Value| file_name(v.get("name").and_then(Value::as_str).unwrap_or("")).to_string();
    let mut chosen: Vec<Value> = Vec::new();
    let mut missing: Vec<&str> = Vec::new();
    for pattern in patterns {
        let wanted = file_name(pattern);
        let glob = glob::Pattern::new(wanted).map_err(|e| format!("{}: assessment.records: {pattern}: {e}", origin.display()))?;
        let matched: Vec<&Value> = given.iter().filter(|v| glob.matches(&name(v))).collect();
        if matched.is_empty() {
            missing.push(wanted);
        }
        for v in matched {
            if !chosen.iter().any(|c| name(c) == name(v)) {
                chosen.push(v.clone());
            }
        }
    }
    if missing.is_empty() {
        Ok(chosen)
    } else {
        Err(format!(
            "{}: assessment.records: no record file picked for {}",
            origin.display(),
            missing.join(", ")
        ))
    }
}

/// Puts the record set `records` (JSON text of `[{ name, text }, …]`) in
/// `assessment.records`: all of them, or when the file names its records
/// (paths or globs), those of them with the file names it names. Takes the
/// records out when the set is empty.
fn set_records(table: &mut Table, records: &str, origin: &Path) -> Result<(), String> {
    let given: Value = serde_json::from_str(records).map_err(|e| format!("{}: assessment.records: not JSON: {e}", origin.display()))?;
    let assessment = table
        .entry("assessment")
        .or_insert_with(|| toml::Value::Table(Table::new()))
        .as_table_mut()
        .ok_or_else(|| format!("{}: assessment: expected a table", origin.display()))?;
    match given {
        Value::Array(items) if !items.is_empty() => {
            let items = match assessment.get("records") {
                Some(named) if !named.as_array().is_some_and(|a| a.iter().any(toml::Value::is_table)) => named_records(named, items, origin)?,
                _ => items,
            };
            let value: toml::Value = serde_json::from_value(Value::Array(items)).map_err(|e| format!("{}: assessment.records: {e}", origin.display()))?;
            assessment.insert("records".into(), value);
        }
        _ => {
            assessment.remove("records");
        }
    }
    Ok(())
}

#[wasm_bindgen]
impl WebTown {
    /// See [`WebTown::create`].
    #[wasm_bindgen(constructor)]
    pub fn new(
        assess: &str,
        origin: &str,
        towers: &str,
        towers_name: &str,
        grid: Option<String>,
        grid_name: Option<String>,
        records: &str,
    ) -> Result<WebTown, JsError> {
        Self::create(assess, origin, towers, towers_name, grid, grid_name, records).map_err(|e| JsError::new(&e))
    }

    /// The number of towers.
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.inventory.len()
    }

    /// The columns of `inventory.csv`, as a JSON array.
    pub fn header(&self) -> String {
        json!(self.header).to_string()
    }

    /// Assesses the next `count` towers (in input order; fewer at the end):
    /// the number of towers done.
    pub fn advance(&mut self, count: usize) -> usize {
        let start = self.rows.len();
        let end = start.saturating_add(count).min(self.inventory.len());
        for index in start..end {
            let row = self.inventory.row(index);
            self.rows.push(row.cells.iter().map(|c: &Cell| c.text().into_owned()).collect());
        }
        self.rows.len()
    }

    /// The towers done, as `inventory.csv` holds them: its text, header first.
    pub fn csv(&self) -> String {
        let mut out = csv_line(self.header.iter().cloned());
        out.push('\n');
        for row in &self.rows {
            out.push_str(&csv_line(row.iter().cloned()));
            out.push('\n');
        }
        out
    }

    /// The towers done as the map and the ranking show them: the JSON text of
    /// `{ checks: [name…], towers: [{ index, id, name, lon, lat, zeta_E,
    /// governing, check_zetas, error }…] (input order), ranking: [index…]
    /// (least ζ_E first, towers without one left out), geojson: "…" }`, the
    /// GeoJSON as `inventory.geojson` holds it.
    pub fn town(&self) -> Result<String, JsError> {
        let io = |e: std::io::Error| JsError::new(&e.to_string());
        let mut town = Town::new(&self.header, Vec::new()).map_err(io)?;
        for row in &self.rows {
            town.push(&row.iter().map(String::as_str).collect::<Vec<_>>()).map_err(io)?;
        }
        let checks = town.checks();
        let (towers, geojson) = town.finish().map_err(io)?;
        let order: Vec<usize> = ranking(&towers).iter().map(|t| t.index).collect();
        let towers: Vec<Value> = towers
            .iter()
            .map(|t| {
                json!({
                    "index": t.index,
                    "id": t.id,
                    "name": t.name,
                    "lon": t.point.map(|p| p.0),
                    "lat": t.point.map(|p| p.1),
                    "zeta_E": t.zeta,
                    "governing": t.governing,
                    "check_zetas": t.check_zetas,
                    "error": t.error,
                })
            })
            .collect();
        Ok(json!({
            "checks": checks,
            "towers": towers,
            "ranking": order,
            "geojson": String::from_utf8_lossy(&geojson),
        })
        .to_string())
    }
}
