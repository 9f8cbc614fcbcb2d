//! `rocking inventory TOWERS.csv --assess ASSESS.toml [--out DIR] [--plot]
//! [--threads N] [--shard K/N]`: every bell tower of a town assessed as
//! `rocking assess` assesses one ([`rocking_assess::Inventory`]: the rows,
//! their errors, the hazard from the coordinates). This file is the command
//! line's part: the files read and written, the towers run on the sweep's
//! engine (all cores, rows written in input order as they finish, memory
//! flat, a progress bar, Ctrl-C keeping the rows finished), `--details`,
//! `--shard`. Writes `inventory.csv`, `inventory.geojson` and `fields.csv` (`town.rs`),
//! with `--plot` the map and the ranking, and `report.html`.

use super::assess::REPORT_HTML;
use super::rows::{write_rows, RowsFile, Written};
use super::sweep::Interrupted;
use super::town::{fields_csv, FIELDS_CSV, INVENTORY_CSV, INVENTORY_GEOJSON};
use super::town_report::{town_html, TownPage};
use crate::format::sig;
use crate::output;
use crate::shard::{fingerprint, Manifest, SHARD_JSON};
use anyhow::Context;
use rocking_assess::{ranking, Inventory, Ranked, Town};
use rocking_scenario::{csv_line, run_cases, Cases, Cell, Shard};
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

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
    // A signal: the output folder left as it was (a town cut short must not replace the last
    // whole one), exit 130 for Ctrl-C, 143 for SIGTERM.
    crate::signals::stop_at_once();
    let started = std::time::Instant::now();
    let text = std::fs::read_to_string(&args.assess).with_context(|| format!("cannot read {}", args.assess.display()))?;
    let file = &args.towers;
    let towers_bytes = std::fs::read(file).with_context(|| format!("cannot read {}", file.display()))?;
    let mut inventory = Inventory::new(&text, &args.assess, &towers_bytes, file)?;

    let dir = args.out.clone().unwrap_or_else(|| super::run::default_out(&args.towers));
    let mut names = vec![INVENTORY_CSV, INVENTORY_GEOJSON, FIELDS_CSV];
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
    inputs.extend(inventory.inputs().iter().cloned());
    output::refuse_to_overwrite_inputs(&outputs, &inputs)?;
    let staging = output::Staging::new(&dir, &inputs)?;
    if args.details {
        let staged = staging.path(TOWERS_DIR);
        let shown = dir.join(TOWERS_DIR);
        std::fs::create_dir_all(&staged).with_context(|| format!("cannot create {}", shown.display()))?;
        // Each tower's own assessment as `rocking assess` writes it, in towers/<id>/.
        inventory.on_assessed(Box::new(move |_, id, input, done| {
            let folder = tower_folder(id);
            std::fs::create_dir_all(staged.join(&folder))
                .with_context(|| format!("cannot create {}", shown.join(&folder).display()))
                .and_then(|()| super::assess::write_files(&staged.join(&folder), &shown.join(&folder), input, done))
                .map_err(|e| format!("{e:#}"))
        }));
    }

    let header = inventory.header();
    std::fs::write(staging.path(FIELDS_CSV), fields_csv(&header)).with_context(|| format!("cannot write {}", dir.join(FIELDS_CSV).display()))?;
    let geojson_shown = dir.join(INVENTORY_GEOJSON);
    let geojson_context = || format!("cannot write {}", geojson_shown.display());
    let geojson_file = File::create(staging.path(INVENTORY_GEOJSON)).with_context(geojson_context)?;
    let mut town = Town::new(&header, BufWriter::new(geojson_file)).with_context(geojson_context)?;
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
    let pool = rocking_assess::calling_pool(cases.len(), threads).context("starting the worker threads")?;
    let mut pushed = Ok(());
    let Written { done, wall } = pool.install(|| {
        write_rows(
            &rows_file,
            cases.len(),
            |row| {
                if pushed.is_ok() {
                    let texts: Vec<_> = row.cells.iter().map(Cell::text).collect();
                    pushed = town.push(&texts.iter().map(AsRef::as_ref).collect::<Vec<&str>>()).with_context(geojson_context);
                }
            },
            |cancel, sink| run_cases(&inventory, cases.clone(), threads, cancel, sink),
        )
    })?;
    pushed?;
    let check_names = town.checks();
    let (towers, _) = town.finish().with_context(geojson_context)?;
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
        let others = if bad.len() < towers.len() { "; the others are assessed" } else { "" };
        anyhow::bail!(
            "{} of {} towers with an error (in the error column of {}){others}",
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
