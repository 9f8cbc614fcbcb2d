//! Every bell tower of a town assessed as one assessment file assesses one
//! tower: the inventory behind `rocking inventory`, `rocking.inventory` in
//! Python and the page's town tab.
//!
//! Each row of the towers' CSV is the assessment file's table with the row's
//! cells set in it (a dotted column is a key, `soil`, `topography`, `ag_SLV`…
//! are the site's, `lon`, `lat` the place on the hazard grid), read by the
//! same functions as the file, so a tower's numbers are those of the
//! assessment of a file with the same values. The hazard grid and each record
//! file are read once for all the towers ([`GridCache`], [`RecordCache`]).
//! An [`Inventory`] is the [`Cases`] of the sweep's engine (one row per
//! tower, in input order); a bad row gets its `error` (one line naming the
//! file, the row, the column and what is wrong) and the others go on.

use crate::assess::Assessment;
use crate::check::Method;
use crate::input::AssessmentInput;
use crate::site::Role;
use crate::town::IDENTITY;
use crate::RecordSet;
use rocking_codes::LimitState;
use rocking_scenario::{
    block_names, closest, named_block_keys, one_line, set_dotted, set_named_key, AssessmentFile, BlockNames, Cases, Cell, Code, ErrorKind, GridCache,
    RecordCache, Row, ASSESSMENT_KEY_DOCS, BLOCK, SCENARIO_KEYS, SECTIONS,
};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// The kinematic checks in the order of their columns, by the role of their limit state.
const KINEMATIC: [(Role, Method); 4] = [
    (Role::Damage, Method::Activation),
    (Role::LifeSafety, Method::LinearKinematic),
    (Role::LifeSafety, Method::NonlinearKinematic),
    (Role::Collapse, Method::NonlinearKinematic),
];
/// The dynamic checks, after the kinematic ones when the assessment file has a record set.
const DYNAMIC: [(Role, Method); 2] = [(Role::LifeSafety, Method::NonlinearDynamic), (Role::Collapse, Method::NonlinearDynamic)];
/// Site columns that are keys of `[site]` under the same name.
const SITE_COLUMNS: [&str; 5] = ["soil", "topography", "ST", "VN", "CU"];
/// The inputs every tower's row repeats, whether or not the towers' file has
/// their columns: the tower's width and height, the site's soil and topography.
const INPUTS: [&str; 4] = ["tower.width", "tower.height", "soil", "topography"];
/// The keys of `[site]` that give the parameters from a hazard grid.
const GRID_KEYS: [&str; 6] = ["grid", "island", "lon", "lat", "VN", "CU"];

/// Why an inventory cannot start: the assessment file is not valid by itself
/// (its error names the file, the key and the cause), a record of its set
/// cannot be read, or the towers' file cannot be read or has a bad header
/// (one line naming the file and the column).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum InventoryError {
    /// The assessment file, or a record of its set.
    #[error(transparent)]
    Assessment(#[from] rocking_scenario::Error),
    /// The towers' file.
    #[error("{0}")]
    Towers(String),
}

/// An error of the towers' file (a column's name may hold a line break), on one line.
fn towers_error(text: String) -> InventoryError {
    InventoryError::Towers(one_line(&text).into_owned())
}

/// What a column of the towers' file sets.
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
fn columns(header: &csv::StringRecord, code: Code, file: &Path) -> Result<Vec<Column>, String> {
    let mut seen = HashMap::new();
    let mut out = Vec::new();
    for (i, name) in header.iter().enumerate() {
        if let Some(first) = seen.insert(name, i) {
            return Err(format!("{}: column {name} appears twice (columns {} and {})", file.display(), first + 1, i + 1));
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
            return Err(format!(
                "{}: unknown column {name:?}; a column is id, name, lon, lat, soil, topography, ST, VN, CU, a limit state's site parameter \
                 (ag_SLV, F0_SLV, Tc_star_SLV with code = \"ntc2018\"; ag_SD with \"ec8\") or a dotted key of the assessment file (tower.width)",
                file.display()
            ));
        });
    }
    for required in ["id", "lon", "lat"] {
        if !seen.contains_key(required) {
            return Err(format!("{}: no column {required} (a tower needs id, lon and lat)", file.display()));
        }
    }
    Ok(out)
}

/// Whether `text` is a number written with a decimal comma (`4,5`, `-0,25`),
/// as a spreadsheet of an Italian or a French locale writes it.
fn decimal_comma(text: &str) -> bool {
    let digits = text.strip_prefix(['-', '+']).unwrap_or(text);
    digits.split_once(',').is_some_and(|(whole, part)| {
        !whole.is_empty() && !part.is_empty() && whole.bytes().all(|b| b.is_ascii_digit()) && part.bytes().all(|b| b.is_ascii_digit())
    })
}

/// Refuses a cell of `row` holding a number with a decimal comma, naming its row and column.
fn refuse_decimal_comma(row: &Line, file: &Path, name: &str, text: &str) -> Result<(), String> {
    if decimal_comma(text) {
        return Err(row.fault(
            file,
            name,
            format!(
                "{text:?} has a decimal comma: write numbers with a decimal point ({})",
                text.replacen(',', ".", 1)
            ),
        ));
    }
    Ok(())
}

/// The field separator of a towers' file: the comma, or the `;` or the TAB
/// a spreadsheet writes (in a locale whose decimal mark is a comma), whichever
/// of the three the header line holds most of (the comma on a tie).
fn separator(text: &[u8]) -> u8 {
    let header = text.split(|&b| b == b'\n').next().unwrap_or_default();
    let count = |sep: u8| header.iter().filter(|&&b| b == sep).count();
    [b';', b'\t']
        .into_iter()
        .fold(b',', |best, sep| if count(sep) > count(best) { sep } else { best })
}

/// A cell as a TOML value: a number, a boolean or a quoted string as TOML reads it, else the text as a string.
fn cell_value(cell: &str) -> Value {
    format!("v = {cell}")
        .parse::<Table>()
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| Value::String(cell.to_string()))
}

/// One cell given in a row: its column's name, what the column sets, its text.
#[derive(Debug, Clone)]
struct Given {
    name: String,
    column: Column,
    text: String,
}

/// The cells of one row by column name (empty cells left out).
#[derive(Debug, Clone)]
struct Line {
    /// Its row number in the file (1 the first after the header).
    number: usize,
    cells: Vec<Given>,
}

impl Line {
    fn get(&self, name: &str) -> Option<&str> {
        self.cells.iter().find(|c| c.name == name).map(|c| c.text.as_str())
    }
    /// `TOWERS.csv row N (id X): what`, on one line ([`one_line`]: an id may hold a line break).
    fn failure(&self, file: &Path, what: impl std::fmt::Display) -> String {
        let id = self.get("id").map(|id| format!(" (id {id})")).unwrap_or_default();
        one_line(&format!("{} row {}{id}: {what}", file.display(), self.number)).into_owned()
    }
    /// `TOWERS.csv row N (id X), column C: what`, on one line.
    fn fault(&self, file: &Path, column: &str, what: impl std::fmt::Display) -> String {
        let id = self.get("id").map(|id| format!(" (id {id})")).unwrap_or_default();
        one_line(&format!("{} row {}{id}, column {column}: {what}", file.display(), self.number)).into_owned()
    }
}

/// The coordinate of a row: a number within ±`limit` degrees.
fn coordinate(row: &Line, file: &Path, name: &str, limit: f64) -> Result<f64, String> {
    let text = row
        .get(name)
        .ok_or_else(|| row.fault(file, name, "missing: a tower needs its place (WGS84 degrees)"))?;
    refuse_decimal_comma(row, file, name, text)?;
    crate::town::degrees(text, limit).ok_or_else(|| match text.trim().parse::<f64>() {
        Ok(x) => row.fault(file, name, format!("must be within ±{limit} degrees, got {x}")),
        Err(_) => row.fault(file, name, format!("not a number: {text:?}")),
    })
}

/// The keys a column can set under `head` (a section of the scenario, or a
/// block by its name): `tower.width`, …, `belfry.width`, … (`block`: every
/// block's); `None` where `head` is another section (`assessment`, whose
/// keys its parser checks) or none.
fn keys_under(head: &str, blocks: &BlockNames) -> Option<Vec<String>> {
    if head == BLOCK {
        return Some(blocks.iter().flat_map(named_block_keys).collect());
    }
    if blocks.position(head).is_some() {
        return Some(named_block_keys(head));
    }
    SECTIONS
        .contains(&head)
        .then(|| SCENARIO_KEYS.iter().filter(|k| k.section() == Some(head)).map(|k| k.key.to_string()).collect())
}

/// Every key a column can set in the assessment file (the scenario's but
/// `[ground]`'s, its blocks' by their names, `[assessment]`'s): the
/// candidates of a misspelt column's "did you mean".
fn column_keys(blocks: &BlockNames) -> Vec<String> {
    let sections = SECTIONS.iter().filter(|s| **s != "ground").filter_map(|s| keys_under(s, blocks));
    let assessment = ASSESSMENT_KEY_DOCS
        .iter()
        .map(|k| k.key)
        .filter(|k| (k.starts_with("assessment.") || k.starts_with("support.")) && !k.contains('<'));
    sections.flatten().chain(assessment.map(String::from)).collect()
}

/// What is wrong with a dotted column's key `key` whatever its cells hold,
/// if anything, in an assessment file whose blocks are `blocks`: a block's
/// name (which names its outputs, as a sweep cannot vary it either), a
/// misspelt key of a section or a block, a head that is neither. A misspelt
/// key gets the column suggested as it would be written (`belfry.width`).
fn key_fault(key: &str, blocks: &BlockNames) -> Option<String> {
    let head = key.split('.').next().unwrap_or_default();
    let known = SECTIONS.contains(&head) || ["site", "assessment", "support"].contains(&head);
    if !known && key.ends_with(".name") {
        return Some("a block's name cannot be set per tower: its outputs are named by it".into());
    }
    if let Some(valid) = keys_under(head, blocks).filter(|v| !v.is_empty()) {
        return (!valid.iter().any(|k| k == key)).then(|| ErrorKind::unknown_key(key, &valid).to_string());
    }
    if known || blocks.position(head).is_some() {
        return None;
    }
    let candidates = column_keys(blocks);
    let suggestion = closest(key, &candidates.iter().map(String::as_str).collect::<Vec<_>>()).map(|c| format!("; did you mean `{c}`?"));
    Some(format!(
        "`{head}` is no section of the assessment file ({}, site, assessment) and no block on its tower (a block's key is its name and the key: belfry.width){}",
        SECTIONS.join(", "),
        suggestion.unwrap_or_default()
    ))
}

/// The key of `[site]` that a site column (`soil`, `ag_SLV`) replaces, if it is one of [`SITE_COLUMNS`].
fn site_key(name: &str) -> Option<String> {
    SITE_COLUMNS.contains(&name).then(|| format!("site.{name}"))
}

/// The value of a dotted key (`tower.width`, `site.SLV.ag`) in `table`, if it holds one.
fn dotted_value<'a>(table: &'a Table, key: &str) -> Option<&'a Value> {
    let mut parts = key.split('.');
    let mut value = table.get(parts.next()?)?;
    for part in parts {
        value = value.as_table()?.get(part)?;
    }
    Some(value)
}

/// The assessment file's table as it is checked by itself: with a hazard
/// grid and no `site.lon`, `site.lat` (every tower gives its own: a column
/// replaces the key it names, and nothing is required twice), at the grid's
/// central node ([`GridCache::central_node`]), a place inside it whatever
/// the towers' places. A grid that cannot be read leaves the table as
/// given, and its check names the grid.
fn placed(base: &Table, origin: &Path, grids: &GridCache) -> Table {
    let mut table = base.clone();
    let Some(Value::Table(site)) = table.get_mut("site") else { return table };
    if site.contains_key("lon") && site.contains_key("lat") {
        return table;
    }
    let Some(Value::String(grid)) = site.get("grid") else { return table };
    let file = origin.parent().unwrap_or(Path::new("")).join(grid);
    if let Some((lon, lat)) = grids.central_node(&file) {
        site.entry("lon").or_insert(Value::Float(lon));
        site.entry("lat").or_insert(Value::Float(lat));
    }
    table
}

/// The assessment file's table with the row's cells set in it.
fn row_table(base: &Table, row: &Line, file: &Path, lon: f64, lat: f64) -> Result<Table, String> {
    let mut table = base.clone();
    let site = match table.entry("site").or_insert_with(|| Value::Table(Table::new())) {
        Value::Table(t) => t,
        _ => return Err(row.fault(file, "site", "the assessment file's site is not a table")),
    };
    let has = |name: &str| row.get(name).is_some();
    // A row's own limit-state parameters replace the grid; its topography or ST replaces the other.
    if row.cells.iter().any(|c| matches!(&c.column, Column::Site(k) if k.matches('.').count() == 2)) {
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
    for given in &row.cells {
        let key = match &given.column {
            Column::Identity => continue,
            Column::Site(key) | Column::Key(key) => key,
        };
        let value = if matches!(given.name.as_str(), "soil" | "topography") {
            Value::String(given.text.clone())
        } else {
            refuse_decimal_comma(row, file, &given.name, &given.text)?;
            cell_value(&given.text)
        };
        // A block's key by its name (`belfry.width`), as a sweep's axis names
        // it; the header's names are known keys ([`key_fault`]).
        if set_named_key(&mut table, key, value.clone()) {
            continue;
        }
        set_dotted(&mut table, key, value).map_err(|e| row.fault(file, &given.name, e))?;
    }
    Ok(table)
}

/// What is done with each tower's assessment besides its row (`rocking
/// inventory --details` writes its files): the tower's index and its id, its
/// input and its assessment; an error becomes the tower's.
pub type OnAssessed = dyn Fn(usize, &str, &AssessmentInput, &Assessment) -> Result<(), String> + Send + Sync;

/// The towers of a town and the assessment file they start from: one [`Row`]
/// per tower in the order of [`Inventory::header`].
pub struct Inventory {
    /// The assessment file's table and the file.
    base: Table,
    origin: PathBuf,
    /// The towers' file, which errors name.
    file: PathBuf,
    lines: Vec<Line>,
    /// The first row of the same id, for a repeated one.
    repeats: Vec<Option<usize>>,
    /// A row whose number of cells is not the header's.
    short: Vec<Option<String>>,
    /// The checks of the columns, in order.
    checks: Vec<(LimitState, Method)>,
    /// The damage, life-safety and collapse limit states of the site.
    states: [LimitState; 3],
    /// The inputs repeated in each row: the column's name and the key of the
    /// assessment file it replaces (whose value an empty cell takes).
    repeated: Vec<(String, String)>,
    /// The files the assessment file reads (its grid, its records).
    inputs: Vec<PathBuf>,
    /// The hazard grid and the records, read once for all the towers.
    grids: GridCache,
    records: RecordCache,
    on_assessed: Option<Box<OnAssessed>>,
}

impl std::fmt::Debug for Inventory {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Inventory")
            .field("origin", &self.origin)
            .field("file", &self.file)
            .field("towers", &self.lines.len())
            .field("checks", &self.checks)
            .finish_non_exhaustive()
    }
}

impl Inventory {
    /// The inventory of the towers' CSV text `towers` (`file` names it in
    /// errors) on the assessment file's TOML text `assess` (`origin`: the file,
    /// named in errors, the folder of its grid and records). The assessment
    /// file must be valid by itself, and every record of its set is read here:
    /// a bad record stops the inventory before it starts.
    pub fn new(assess: &str, origin: &Path, towers: &[u8], file: &Path) -> Result<Self, InventoryError> {
        let table = rocking_scenario::parse_toml(assess, origin)?;
        Self::from_table(table, origin, towers, file, GridCache::default())
    }

    /// As [`Inventory::new`], the assessment file given as its table (a Python
    /// dict, the page's JSON give one), the hazard grid taken from `grids`
    /// when it holds it (the page gives the grid's text, not a file).
    pub fn from_table(base: Table, origin: &Path, towers: &[u8], file: &Path, grids: GridCache) -> Result<Self, InventoryError> {
        let input = AssessmentInput::new(AssessmentFile::from_table_on(placed(&base, origin, &grids), origin, &grids)?)?;
        let ntc = input.site.is_ntc();
        let records = RecordCache::with_capacity(input.file.records.len());
        let mut checks: Vec<(LimitState, Method)> = KINEMATIC.iter().map(|&(role, method)| (role.limit_state(ntc), method)).collect();
        if !input.file.records.is_empty() {
            // Every record read once, here.
            RecordSet::read_cached(&input, input.capacity()?.t_slc, &records)?;
            checks.extend(DYNAMIC.iter().map(|&(role, method)| (role.limit_state(ntc), method)));
        }

        let cannot_read = |e: csv::Error| towers_error(format!("cannot read {}: {e}", file.display()));
        // A spreadsheet's file: a UTF-8 byte-order mark, a `;` or a TAB between fields.
        let towers = towers.strip_prefix(b"\xEF\xBB\xBF".as_slice()).unwrap_or(towers);
        let mut reader = csv::ReaderBuilder::new()
            .flexible(true)
            .trim(csv::Trim::All)
            .delimiter(separator(towers))
            .from_reader(towers);
        let header = reader.headers().map_err(cannot_read)?.clone();
        let columns = columns(&header, input.file.site.code, file).map_err(towers_error)?;
        // A column that names no key is the header's fault, told once (not on every row).
        // The assessment file is valid by itself (its input was built above): its blocks are well formed.
        let blocks = block_names(&base).unwrap_or_default();
        for (name, column) in header.iter().zip(&columns) {
            if let Some(what) = matches!(column, Column::Key(_)).then(|| key_fault(name, &blocks)).flatten() {
                return Err(towers_error(format!("{}: column {name}: {what}", file.display())));
            }
        }
        // The inputs each row repeats: INPUTS, then the file's own columns, each once.
        let mut repeated: Vec<(String, String)> = INPUTS
            .iter()
            .map(|name| (name.to_string(), site_key(name).unwrap_or_else(|| name.to_string())))
            .collect();
        for (name, column) in header.iter().zip(&columns) {
            if let Column::Site(key) | Column::Key(key) = column {
                if !repeated.iter().any(|(n, _)| n == name) {
                    repeated.push((name.to_string(), key.clone()));
                }
            }
        }
        let rows = reader.records().collect::<Result<Vec<_>, _>>().map_err(cannot_read)?;
        let lines: Vec<Line> = rows
            .iter()
            .enumerate()
            .map(|(i, r)| Line {
                number: i + 1,
                cells: header
                    .iter()
                    .zip(&columns)
                    .zip(r.iter())
                    .filter(|(_, text)| !text.is_empty())
                    .map(|((name, column), text)| Given {
                        name: name.to_string(),
                        column: column.clone(),
                        text: text.to_string(),
                    })
                    .collect(),
            })
            .collect();
        // The first row of each id; a later row with the same id is refused.
        let mut first_of: HashMap<&str, usize> = HashMap::new();
        let repeats: Vec<Option<usize>> = lines
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
        let short: Vec<Option<String>> = rows
            .iter()
            .zip(&lines)
            .map(|(r, row)| {
                (r.len() != header.len()).then(|| format!("{} row {}: {} cells, the header has {}", file.display(), row.number, r.len(), header.len()))
            })
            .collect();
        Ok(Self {
            base,
            origin: origin.to_path_buf(),
            file: file.to_path_buf(),
            lines,
            repeats,
            short,
            checks,
            states: Role::ALL.map(|role| role.limit_state(ntc)),
            repeated,
            inputs: input.inputs(),
            grids,
            records,
            on_assessed: None,
        })
    }

    /// Calls `f` with each tower's assessment (after it, before its row).
    pub fn on_assessed(&mut self, f: Box<OnAssessed>) {
        self.on_assessed = Some(f);
    }

    /// The files the assessment file reads: its hazard grid, its records.
    pub fn inputs(&self) -> &[PathBuf] {
        &self.inputs
    }

    /// The checks of the columns, in order (the dynamic ones with a record set).
    pub fn checks(&self) -> &[(LimitState, Method)] {
        &self.checks
    }

    /// The header of `inventory.csv`: `id`, `name`, `lon`, `lat`; the tower's
    /// inputs (`tower.width`, `tower.height`, `soil`, `topography`, then the
    /// towers' file's other columns, each the value the tower was assessed
    /// with); the site's `ag_<LS>_g` of each limit state; each check's
    /// `<LS>_<method>_ag_capacity_g` and `<LS>_<method>_zeta_E`; `zeta_E`,
    /// `zeta_E_is_lower_bound`, `governing`, `error`.
    pub fn header(&self) -> Vec<String> {
        let mut header: Vec<String> = IDENTITY.iter().map(|s| s.to_string()).collect();
        header.extend(self.repeated.iter().map(|(name, _)| name.clone()));
        header.extend(self.states.iter().map(|state| format!("ag_{state}_g")));
        for (state, method) in &self.checks {
            header.push(format!("{state}_{method}_ag_capacity_g"));
            header.push(format!("{state}_{method}_zeta_E"));
        }
        header.extend(["zeta_E", "zeta_E_is_lower_bound", "governing", "error"].map(String::from));
        header
    }

    /// The inputs row `index` repeats: each its cell, or where that is empty
    /// the assessment file's value of the key it names (empty if the file
    /// leaves it to its default); a number as a number.
    fn repeated_cells(&self, index: usize) -> Vec<Cell> {
        let line = &self.lines[index];
        self.repeated
            .iter()
            .map(|(name, key)| {
                let value = match line.get(name) {
                    Some(text) if matches!(name.as_str(), "soil" | "topography") => Value::String(text.to_string()),
                    Some(text) => cell_value(text),
                    None => match dotted_value(&self.base, key) {
                        Some(v) => v.clone(),
                        None => return Cell::Empty,
                    },
                };
                match value {
                    Value::Float(x) => Cell::Float(x),
                    Value::Integer(i) => Cell::Int(i),
                    Value::Boolean(b) => Cell::Bool(b),
                    Value::String(t) => Cell::Text(t),
                    other => Cell::Text(other.to_string()),
                }
            })
            .collect()
    }

    /// The `id` of tower `index` as given (empty if none).
    pub fn id(&self, index: usize) -> &str {
        self.lines.get(index).and_then(|l| l.get("id")).unwrap_or("")
    }

    /// The identity cells of row `index`: id, name, lon, lat as given.
    fn identity(&self, index: usize) -> Vec<Cell> {
        let line = &self.lines[index];
        IDENTITY.iter().map(|n| Cell::Text(line.get(n).unwrap_or("").to_string())).collect()
    }

    /// Assesses tower `index`: its input and its assessment, or the one line of its error.
    pub fn assess(&self, index: usize) -> Result<(AssessmentInput, Assessment), String> {
        let (row, file) = (&self.lines[index], self.file.as_path());
        if let Some(e) = &self.short[index] {
            return Err(e.clone());
        }
        let lon = coordinate(row, file, "lon", 180.0);
        let lat = coordinate(row, file, "lat", 90.0);
        if row.get("id").is_none() {
            return Err(row.fault(file, "id", "missing: each tower needs an id"));
        }
        if let Some(first) = self.repeats[index] {
            return Err(row.fault(file, "id", format!("the same id as row {first}")));
        }
        let table = row_table(&self.base, row, file, lon?, lat?)?;
        // A fault names the key; the row's column that set it, else the assessment file's key.
        let fault = |e: rocking_scenario::Error| {
            let key = e.key().unwrap_or("");
            let column = row
                .cells
                .iter()
                .find(|c| match &c.column {
                    Column::Site(k) | Column::Key(k) => k == key,
                    Column::Identity => key == format!("site.{}", c.name),
                })
                .map_or_else(|| format!("{key} (of {})", self.origin.display()), |c| format!("{} ({:?})", c.name, c.text));
            row.fault(file, &column, e.kind())
        };
        let input = AssessmentFile::from_table_on(table, &self.origin, &self.grids)
            .and_then(AssessmentInput::new)
            .map_err(fault)?;
        let done = Assessment::run_cached(&input, &self.records).map_err(fault)?;
        Ok((input, done))
    }

    /// The row of tower `index`.
    pub fn row(&self, index: usize) -> Row {
        let (input, done) = match self.assess(index) {
            Ok(assessed) => assessed,
            Err(e) => return self.failed_row(index, &e),
        };
        if let Some(f) = &self.on_assessed {
            if let Err(e) = f(index, self.id(index), &input, &done) {
                return self.failed_row(index, &self.lines[index].failure(&self.file, e));
            }
        }
        let mut cells = self.identity(index);
        cells.extend(self.repeated_cells(index));
        cells.extend(Role::ALL.map(|role| Cell::Float(input.site.spectrum(role).ag())));
        // The tower's checks, each the worse of the two principal directions when it has two.
        let mut completed = done.mechanisms()[0].completed();
        if let Some(turned) = &done.turned {
            completed.extend(turned.mechanisms()[0].completed());
        }
        for (state, method) in &self.checks {
            let worst = completed
                .iter()
                .filter(|c| c.limit_state == *state && c.method == *method)
                .reduce(|a, b| if b.zeta_e < a.zeta_e { b } else { a });
            match worst {
                Some(c) => cells.extend([Cell::Float(c.ag_capacity.value()), Cell::Float(c.zeta_e)]),
                None => cells.extend([Cell::Empty, Cell::Empty]),
            }
        }
        // The governing of every mechanism in both directions, a block's named, the depth's said;
        // its ζ_E a lower bound when its ag capacity is the top of the search or of the λ scan.
        let across = |m: &crate::MechanismView<'_>| match m.direction {
            crate::Direction::Width => String::new(),
            crate::Direction::Depth => " across the depth".to_string(),
        };
        match done.governing_mechanism() {
            Some((m, g)) => cells.extend([
                Cell::Float(g.zeta_e),
                Cell::Bool(g.ag_capacity.is_lower_bound()),
                Cell::Text(if m.block > 0 {
                    format!("{} {} {}{}", m.name, g.limit_state, g.method, across(&m))
                } else {
                    format!("{} {}{}", g.limit_state, g.method, across(&m))
                }),
            ]),
            None => cells.extend([Cell::Empty, Cell::Empty, Cell::Empty]),
        }
        // A dynamic check that could not be completed: the others stand, the reason is the error.
        let incomplete: Vec<String> = done
            .dynamic
            .iter()
            .filter_map(|d| {
                d.error
                    .as_ref()
                    .map(|e| format!("{} {}: could not be completed: {e}", d.limit_state, Method::NonlinearDynamic))
            })
            .collect();
        cells.push(if incomplete.is_empty() {
            Cell::Empty
        } else {
            Cell::Text(self.lines[index].failure(&self.file, incomplete.join("; ")))
        });
        Row { index, cells }
    }
}

/// The pool to run `cases` towers from on `threads` workers (`None`: one per
/// core), by [`rocking_scenario::run_cases`] called inside its `install`. A
/// tower's dynamic checks run in parallel on the pool they are called from: a
/// pool of one thread while there are towers enough for every worker (the
/// workers' own pool holds the others), all of them when fewer.
pub fn calling_pool(cases: usize, threads: Option<usize>) -> Result<rayon::ThreadPool, rayon::ThreadPoolBuildError> {
    let workers = threads.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from));
    let outer = if cases >= workers { 1 } else { workers };
    rayon::ThreadPoolBuilder::new().num_threads(outer).build()
}

impl Cases for Inventory {
    fn len(&self) -> usize {
        self.lines.len()
    }
    /// A tower is not stopped part-way: a cancel stops the run after the towers under way.
    fn run_case_until(&self, index: usize, _halted: &dyn Fn() -> bool) -> Option<Row> {
        Some(self.row(index))
    }
    fn failed_row(&self, index: usize, message: &str) -> Row {
        let mut cells = self.identity(index);
        cells.extend(self.repeated_cells(index));
        cells.extend(std::iter::repeat_n(Cell::Empty, self.states.len() + 2 * self.checks.len() + 3));
        cells.push(Cell::Text(message.to_string()));
        Row { index, cells }
    }
}
