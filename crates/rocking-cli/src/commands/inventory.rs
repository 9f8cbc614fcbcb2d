//! `rocking inventory TOWERS.csv --assess ASSESS.toml [--out DIR] [--plot]
//! [--threads N] [--shard K/N]`: every bell tower of a town assessed as
//! `rocking assess` assesses one: the kinematic checks, and the dynamic ones
//! when the assessment file has a record set. Each row of TOWERS.csv is the
//! assessment file's table with the row's cells set in it (a dotted column is
//! a key, `soil`, `topography`, `ag_SLV`… are the site's, `lon`, `lat` the
//! place on the hazard grid), read by the same functions as the file, so a
//! tower's numbers are those of `rocking assess` on a file with the same
//! values. The hazard grid and each record file are read once for all the
//! towers. The towers run on the sweep's engine (all cores, rows written in
//! input order as they finish, memory flat, a progress bar, Ctrl-C keeping
//! the rows finished); a bad row gets its `error` and the others go on.
//! Writes `inventory.csv` and `inventory.geojson` (`town.rs`), with `--plot`
//! the map and the ranking, and `report.html`.

use super::assess::REPORT_HTML;
use super::rows::{write_rows, RowsFile, Written};
use super::sweep::Interrupted;
use super::town::{ranking, Ranked, Town, IDENTITY, INVENTORY_CSV, INVENTORY_GEOJSON};
use super::town_report::{town_html, TownPage};
use crate::format::sig;
use crate::output;
use crate::shard::{fingerprint, Manifest, SHARD_JSON};
use anyhow::Context;
use rocking_assess::{Assessment, AssessmentInput, Method, RecordSet, Role};
use rocking_codes::LimitState;
use rocking_scenario::{csv_line, run_cases, set_dotted, AssessmentFile, Cases, Cell, Code, GridCache, RecordCache, Row, Shard};
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
/// The keys of `[site]` that give the parameters from a hazard grid.
const GRID_KEYS: [&str; 5] = ["grid", "lon", "lat", "VN", "CU"];
/// Towers listed on the terminal.
const LISTED: usize = 10;

/// Arguments of `rocking inventory`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The towers: one row each, with id, name, lon, lat (WGS84 degrees), and
    /// any scenario key (tower.width), soil, topography or ag_SLV, F0_SLV,
    /// Tc_star_SLV… as columns; empty cells take the assessment file's values.
    pub towers: PathBuf,
    /// The assessment file every tower starts from (its site from the hazard
    /// grid at each tower's lon, lat; with assessment.records, the dynamic checks too).
    #[arg(long, value_name = "ASSESS.toml")]
    pub assess: PathBuf,
    /// Output folder, created if needed [default: out/<towers file stem>]. The
    /// files of an earlier run of this tool there are replaced once the
    /// inventory ends; other files and inputs never are.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Also draw the map of the towers coloured by ζ_E and their ranking (town_map, town_ranking: SVG and PNG).
    #[arg(long)]
    pub plot: bool,
    /// Also write each tower's assessment as `rocking assess` writes it
    /// (assessment.json, capacity.csv, report.html…) in towers/<id>/, linked from report.html.
    #[arg(long, conflicts_with = "shard")]
    pub details: bool,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub threads: Option<u32>,
    /// Assess only the K-th of N equal contiguous blocks of towers (1 <= K <= N),
    /// and write shard.json for `rocking merge`.
    #[arg(long, value_name = "K/N", value_parser = parse_shard, conflicts_with = "plot")]
    pub shard: Option<Shard>,
}

fn parse_shard(text: &str) -> Result<Shard, String> {
    text.parse()
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

/// The cells of one row by column name (empty cells left out).
struct Line<'a> {
    number: usize,
    cells: Vec<(&'a str, &'a Column, &'a str)>,
}

impl Line<'_> {
    fn get(&self, name: &str) -> Option<&str> {
        self.cells.iter().find(|(n, _, _)| *n == name).map(|(_, _, v)| *v)
    }
    /// `TOWERS.csv row N (id X): what`.
    fn failure(&self, file: &Path, what: impl std::fmt::Display) -> String {
        let id = self.get("id").map(|id| format!(" (id {id})")).unwrap_or_default();
        format!("{} row {}{id}: {what}", file.display(), self.number)
    }
    /// `TOWERS.csv row N (id X), column C: what`.
    fn fault(&self, file: &Path, column: &str, what: impl std::fmt::Display) -> String {
        let id = self.get("id").map(|id| format!(" (id {id})")).unwrap_or_default();
        format!("{} row {}{id}, column {column}: {what}", file.display(), self.number)
    }
}

/// The coordinate of a row: a number within ±`limit` degrees.
fn coordinate(row: &Line<'_>, file: &Path, name: &str, limit: f64) -> Result<f64, String> {
    let text = row
        .get(name)
        .ok_or_else(|| row.fault(file, name, "missing: a tower needs its place (WGS84 degrees)"))?;
    super::town::degrees(text, limit).ok_or_else(|| match text.trim().parse::<f64>() {
        Ok(x) => row.fault(file, name, format!("must be within ±{limit} degrees, got {x}")),
        Err(_) => row.fault(file, name, format!("not a number: {text:?}")),
    })
}

/// The assessment file's table with the row's cells set in it.
fn row_table(base: &Table, row: &Line<'_>, file: &Path, lon: f64, lat: f64) -> Result<Table, String> {
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

/// The towers of TOWERS.csv, assessed on the sweep's engine: one [`Row`] each.
struct Inventory<'a> {
    /// The assessment file's table and the file.
    base: &'a Table,
    origin: &'a Path,
    /// TOWERS.csv, which errors name.
    file: &'a Path,
    lines: Vec<Line<'a>>,
    /// The first row of the same id, for a repeated one.
    repeats: Vec<Option<usize>>,
    /// A row whose number of cells is not the header's.
    short: Vec<Option<String>>,
    /// The checks of the columns, in order.
    checks: Vec<(LimitState, Method)>,
    /// The hazard grid and the records, read once for all the towers.
    grids: GridCache,
    records: RecordCache,
    /// Where each tower's own assessment is written (`--details`): the staging folder and the final one.
    details: Option<(PathBuf, PathBuf)>,
}

impl Inventory<'_> {
    /// The header of `inventory.csv`.
    fn header(&self) -> Vec<String> {
        let mut header: Vec<String> = IDENTITY.iter().map(|s| s.to_string()).collect();
        for (state, method) in &self.checks {
            header.push(format!("{state}_{method}_ag_capacity_g"));
            header.push(format!("{state}_{method}_zeta_E"));
        }
        header.extend(["zeta_E", "governing", "error"].map(String::from));
        header
    }

    /// The identity cells of row `index`: id, name, lon, lat as given.
    fn identity(&self, index: usize) -> Vec<Cell> {
        let line = &self.lines[index];
        IDENTITY.iter().map(|n| Cell::Text(line.get(n).unwrap_or("").to_string())).collect()
    }

    /// Assesses row `index`: its input and its assessment, or the one line of its error.
    fn assess(&self, index: usize) -> Result<(AssessmentInput, Assessment), String> {
        let (row, file) = (&self.lines[index], self.file);
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
        let table = row_table(self.base, row, file, lon?, lat?)?;
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
                .map_or_else(|| format!("{key} (of {})", self.origin.display()), |(n, _, v)| format!("{n} ({v:?})"));
            row.fault(file, &column, e.kind())
        };
        let input = AssessmentFile::from_table_on(table, self.origin, &self.grids)
            .and_then(AssessmentInput::new)
            .map_err(fault)?;
        let done = Assessment::run_cached(&input, &self.records).map_err(fault)?;
        Ok((input, done))
    }

    /// The row of tower `index`.
    fn row(&self, index: usize) -> Row {
        let (input, done) = match self.assess(index) {
            Ok(assessed) => assessed,
            Err(e) => return self.failed_row(index, &e),
        };
        if let Some((staging, shown)) = &self.details {
            let folder = tower_folder(self.lines[index].get("id").unwrap_or(""));
            let written = std::fs::create_dir_all(staging.join(&folder))
                .with_context(|| format!("cannot create {}", shown.join(&folder).display()))
                .and_then(|()| super::assess::write_files(&staging.join(&folder), &shown.join(&folder), &input, &done));
            if let Err(e) = written {
                return self.failed_row(index, &self.lines[index].failure(self.file, format!("{e:#}")));
            }
        }
        let mut cells = self.identity(index);
        let completed = done.completed();
        for (state, method) in &self.checks {
            match completed.iter().find(|c| c.limit_state == *state && c.method == *method) {
                Some(c) => cells.extend([Cell::Float(c.ag_capacity.value()), Cell::Float(c.zeta_e)]),
                None => cells.extend([Cell::Empty, Cell::Empty]),
            }
        }
        match done.governing() {
            Some(g) => cells.extend([Cell::Float(g.zeta_e), Cell::Text(format!("{} {}", g.limit_state, g.method))]),
            None => cells.extend([Cell::Empty, Cell::Empty]),
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
            Cell::Text(self.lines[index].failure(self.file, incomplete.join("; ")))
        });
        Row { index, cells }
    }
}

impl Cases for Inventory<'_> {
    fn len(&self) -> usize {
        self.lines.len()
    }
    /// A tower is not stopped part-way: Ctrl-C stops the run after the towers under way.
    fn run_case_until(&self, index: usize, _halted: &dyn Fn() -> bool) -> Option<Row> {
        Some(self.row(index))
    }
    fn failed_row(&self, index: usize, message: &str) -> Row {
        let mut cells = self.identity(index);
        cells.extend(std::iter::repeat_n(Cell::Empty, 2 * self.checks.len() + 2));
        cells.push(Cell::Text(message.to_string()));
        Row { index, cells }
    }
}

/// The folder of a tower's own assessment under `towers/`: its id, every
/// byte but ASCII letters, digits, `-` and `_` written `.XX` (hex), so that
/// distinct ids get distinct folders and none is `..` or holds a `/`.
pub fn tower_folder(id: &str) -> String {
    let mut name = String::new();
    for b in id.bytes() {
        if b.is_ascii_alphanumeric() || b == b'-' || b == b'_' {
            name.push(char::from(b));
        } else {
            name.push_str(&format!(".{b:02X}"));
        }
    }
    name
}

/// The folder of the towers' own assessments.
pub const TOWERS_DIR: &str = "towers";

/// The fingerprint of an inventory: of both files' bytes, so that shards merge only when they came from the same two.
fn inventory_fingerprint(towers: &[u8], assess: &[u8]) -> String {
    fingerprint(format!("{}\n{}\n", fingerprint(towers), fingerprint(assess)).as_bytes())
}

/// Assesses the towers and writes the files.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let started = std::time::Instant::now();
    let text = std::fs::read_to_string(&args.assess).with_context(|| format!("cannot read {}", args.assess.display()))?;
    // The assessment file must be valid by itself: its errors name the file, the key and the cause.
    let base = AssessmentInput::from_toml_str(&text, &args.assess)?;
    let base_table = rocking_scenario::parse_toml(&text, &args.assess)?;
    let ntc = base.site.is_ntc();
    let records = RecordCache::with_capacity(base.file.records.len());
    if !base.file.records.is_empty() {
        // Every record read once, here: a bad record file stops the inventory before it starts.
        RecordSet::read_cached(&base, base.capacity()?.t_slc, &records)?;
    }
    let mut checks: Vec<(LimitState, Method)> = KINEMATIC.iter().map(|&(role, method)| (role.limit_state(ntc), method)).collect();
    if !base.file.records.is_empty() {
        checks.extend(DYNAMIC.iter().map(|&(role, method)| (role.limit_state(ntc), method)));
    }

    let file = &args.towers;
    let towers_bytes = std::fs::read(file).with_context(|| format!("cannot read {}", file.display()))?;
    let mut reader = csv::ReaderBuilder::new()
        .flexible(true)
        .trim(csv::Trim::All)
        .from_reader(towers_bytes.as_slice());
    let header = reader.headers().with_context(|| format!("cannot read {}", file.display()))?.clone();
    let columns = columns(&header, base.file.site.code, file)?;
    let records_read = reader
        .records()
        .collect::<Result<Vec<_>, _>>()
        .with_context(|| format!("cannot read {}", file.display()))?;
    let lines: Vec<Line<'_>> = records_read
        .iter()
        .enumerate()
        .map(|(i, r)| Line {
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
    let short: Vec<Option<String>> = records_read
        .iter()
        .zip(&lines)
        .map(|(r, row)| (r.len() != header.len()).then(|| format!("{} row {}: {} cells, the header has {}", file.display(), row.number, r.len(), header.len())))
        .collect();
    let inventory = Inventory {
        base: &base_table,
        origin: &args.assess,
        file,
        lines,
        repeats,
        short,
        checks,
        grids: GridCache::default(),
        records,
        details: None,
    };

    let dir = args.out.clone().unwrap_or_else(|| super::run::default_out(&args.towers));
    let mut names = vec![INVENTORY_CSV, INVENTORY_GEOJSON];
    if args.shard.is_some() {
        names.push(SHARD_JSON);
    } else {
        names.push(REPORT_HTML);
    }
    if args.details {
        names.push(TOWERS_DIR);
    }
    if args.plot {
        names.extend(crate::plot::TOWN_FIGURES);
    }
    let outputs: Vec<PathBuf> = names.iter().map(|f| dir.join(f)).collect();
    let mut inputs = vec![args.towers.clone(), args.assess.clone()];
    inputs.extend(base.inputs());
    output::refuse_to_overwrite_inputs(&outputs, &inputs)?;
    let staging = output::Staging::new(&dir, &inputs)?;
    let mut inventory = inventory;
    if args.details {
        let folder = staging.path(TOWERS_DIR);
        std::fs::create_dir_all(&folder).with_context(|| format!("cannot create {}", dir.join(TOWERS_DIR).display()))?;
        inventory.details = Some((folder, dir.join(TOWERS_DIR)));
    }

    let header = inventory.header();
    let mut town = Town::new(&header, &staging.path(INVENTORY_GEOJSON), &dir.join(INVENTORY_GEOJSON))?;
    let csv_path = dir.join(INVENTORY_CSV);
    let rows_file = RowsFile {
        path: &staging.path(INVENTORY_CSV),
        shown: &csv_path,
        header: csv_line(header.iter().cloned()),
        counted: "towers",
    };
    let total = inventory.len();
    let cases = args.shard.map_or(0..total, |s| s.cases(total));
    let threads = args.threads.map(|n| n as usize);
    // The dynamic checks of a tower run in parallel on the pool they are
    // called from: a pool of one thread while there are towers enough for
    // every worker (the workers' own pool holds the others), all of them when fewer.
    let workers = threads.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from));
    let outer = if cases.len() >= workers { 1 } else { workers };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(outer)
        .build()
        .context("starting the worker threads")?;
    let mut pushed = Ok(());
    let Written { done, wall } = pool.install(|| {
        write_rows(
            &rows_file,
            cases.len(),
            |row| {
                if pushed.is_ok() {
                    let texts: Vec<_> = row.cells.iter().map(Cell::text).collect();
                    pushed = town.push(&texts.iter().map(AsRef::as_ref).collect::<Vec<&str>>());
                }
            },
            |cancel, sink| run_cases(&inventory, cases.clone(), threads, cancel, sink),
        )
    })?;
    pushed?;
    let check_names = town.checks();
    let towers = town.finish()?;
    if done.cancelled {
        return Err(Interrupted::keep(staging, done.written, cases.len(), csv_path, "towers"));
    }
    let mut part = String::new();
    if let Some(shard) = args.shard {
        let manifest = Manifest::new(
            "inventory",
            INVENTORY_CSV,
            shard,
            total,
            inventory_fingerprint(&towers_bytes, text.as_bytes()).as_bytes(),
        );
        std::fs::write(staging.path(SHARD_JSON), manifest.to_json()).with_context(|| format!("cannot write {}", dir.join(SHARD_JSON).display()))?;
        part = format!(" (shard {shard}: rows {}..{} of {total})", cases.start + 1, cases.end);
    }
    let title = town_title(&args.towers, towers.len());
    if args.plot {
        crate::plot::town_figures(staging.folder(), &title, &towers, &check_names).context("drawing the figures")?;
    }
    if args.shard.is_none() {
        let link = |index: usize| format!("{TOWERS_DIR}/{}/{}", tower_folder(&towers[index].id), super::assess::REPORT_HTML);
        let page = TownPage {
            title: &title,
            towers_file: &args.towers.display().to_string(),
            assess_file: &args.assess.display().to_string(),
            checks: &check_names,
            details: if args.details { Some(&link) } else { None },
        };
        std::fs::write(staging.path(REPORT_HTML), town_html(&page, &towers)?).with_context(|| format!("cannot write {}", dir.join(REPORT_HTML).display()))?;
    }
    staging.commit()?;

    let mut lines = ranking_lines(&towers);
    lines.push(format!(
        "wrote {} in {}{part} ({} s, {} towers in {} s)",
        names.join(", "),
        dir.display(),
        sig(started.elapsed().as_secs_f64(), 3),
        done.written,
        sig(wall, 3)
    ));
    super::print(&(lines.join("\n") + "\n"))?;
    let bad: Vec<&Ranked> = towers.iter().filter(|t| !t.error.is_empty()).collect();
    if !bad.is_empty() {
        for t in &bad {
            eprintln!("{}", t.error);
        }
        anyhow::bail!(
            "{} of {} towers with an error (in the error column of {}); the others are assessed",
            bad.len(),
            towers.len(),
            dir.join(INVENTORY_CSV).display()
        );
    }
    Ok(())
}

/// The title of a town's figures and page: `12 towers of towers.csv`.
pub fn town_title(towers_file: &Path, count: usize) -> String {
    let name = towers_file
        .file_name()
        .map_or_else(|| towers_file.display().to_string(), |n| n.to_string_lossy().into_owned());
    format!("{count} towers of {name}")
}

/// The terminal's lines: the towers of least ζ_E.
pub fn ranking_lines(towers: &[Ranked]) -> Vec<String> {
    let ranked = ranking(towers);
    let mut lines = vec![format!("{} towers, ranked by the governing ζ_E (least first):", ranked.len())];
    lines.extend(ranked.iter().take(LISTED).map(|t| {
        let zeta = t.zeta.unwrap_or(f64::NAN);
        format!(
            "  {:12} {:24} ζ_E {:>6} {}{}",
            t.id,
            t.name,
            sig(zeta, 3),
            t.governing,
            if zeta < 1.0 { " (FAILS)" } else { "" }
        )
    }));
    if ranked.len() > LISTED {
        lines.push(format!("  … {} more in {INVENTORY_CSV}", ranked.len() - LISTED));
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::tower_folder;

    #[test]
    fn tower_folders_are_distinct_and_stay_under_towers() {
        assert_eq!(tower_folder("CE01"), "CE01");
        // Distinct ids that a plain replacement would merge stay distinct.
        assert_eq!(tower_folder("a/b"), "a.2Fb");
        assert_eq!(tower_folder("a_b"), "a_b");
        assert_eq!(tower_folder("a.2Fb"), "a.2E2Fb");
        // Never a parent folder, never a path.
        assert_eq!(tower_folder(".."), ".2E.2E");
        assert_eq!(tower_folder("é"), ".C3.A9");
    }
}
