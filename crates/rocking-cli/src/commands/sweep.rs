//! `rocking sweep SWEEP.toml [--out DIR] [--plot] [--threads N] [--shard K/N]`:
//! a parametric study. The engine is `rocking_scenario::Sweep`; this file
//! writes `sweep.csv` row by row, shows a progress bar on a terminal and stops
//! cleanly on Ctrl-C. With `--shard K/N` it runs only the K-th of N
//! contiguous blocks of cases and writes `shard.json` next to its rows, for
//! `rocking merge` (README, "Studies beyond one machine").

use super::rows::{write_rows, RowsFile, Written};
use crate::format::sig;
use crate::output;
use crate::shard::{Manifest, SHARD_JSON};
use anyhow::Context;
use rocking_scenario::{Shard, Sweep};
use std::fmt;
use std::path::{Path, PathBuf};

/// The file of a sweep's rows.
pub const SWEEP_CSV: &str = "sweep.csv";

/// Arguments of `rocking sweep`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The sweep file: a scenario plus a [sweep] table of dotted keys and their values.
    pub sweep: PathBuf,
    /// Output folder, created if needed [default: out/<sweep file stem>].
    /// The files of an earlier run of this tool there are replaced (stale
    /// figures removed) once the sweep ends; other files and inputs never are.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Also draw max θ/α against the first swept key (and a heat map for two numeric keys).
    #[arg(long)]
    pub plot: bool,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub threads: Option<u32>,
    /// Also print the threads used, the time per case and the peak memory.
    #[arg(long, short)]
    pub verbose: bool,
    /// Run only the K-th of N equal contiguous blocks of cases (1 <= K <= N),
    /// and write shard.json for `rocking merge`.
    #[arg(long, value_name = "K/N", value_parser = parse_shard, conflicts_with = "plot")]
    pub shard: Option<Shard>,
}

fn parse_shard(text: &str) -> Result<Shard, String> {
    text.parse()
}

/// The sweep was stopped by Ctrl-C after writing `written` complete rows.
#[derive(Debug)]
pub struct Interrupted {
    /// Rows written (cases `0..written`).
    pub written: usize,
    /// Cases in the sweep.
    pub total: usize,
    /// The file holding them.
    pub csv: PathBuf,
    /// What a row is: `cases`, `towers`.
    pub counted: &'static str,
}

impl fmt::Display for Interrupted {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "interrupted: wrote {} of {} {} to {} (complete rows, in order){}",
            self.written,
            self.total,
            self.counted,
            self.csv.display(),
            if self.written == self.total { "; nothing fitted" } else { "" }
        )
    }
}

impl std::error::Error for Interrupted {}

impl Interrupted {
    /// Keeps the rows finished (moves the staging folder's files into place)
    /// and returns the error that says how many of `total` were written.
    pub fn keep(staging: output::Staging, written: usize, total: usize, csv: PathBuf, counted: &'static str) -> anyhow::Error {
        match staging.commit() {
            Ok(()) => Self { written, total, csv, counted }.into(),
            Err(e) => e,
        }
    }
}

/// Runs the sweep and writes `sweep.csv`.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let text = rocking_scenario::file::read_text(&args.sweep, rocking_scenario::file::MAX_INPUT_BYTES)
        .with_context(|| format!("cannot read {}", args.sweep.display()))?;
    // The sweep's errors already name the file, the key and the cause.
    let sweep = Sweep::from_toml_str(&text, &args.sweep)?;
    let dir = args.out.clone().unwrap_or_else(|| super::run::default_out(&args.sweep));
    let csv_path = dir.join(SWEEP_CSV);
    let shard_path = dir.join(SHARD_JSON);
    let mut inputs = vec![args.sweep.clone()];
    inputs.extend(sweep.inputs().iter().cloned());
    output::refuse_to_overwrite_inputs(&[csv_path.clone(), shard_path.clone()], &inputs)?;
    let cases = args.shard.map_or(0..sweep.len(), |s| s.cases(sweep.len()));
    // Written under a staging folder and moved into place at the end (or on
    // Ctrl-C, with the rows finished): never a mix with an earlier sweep (a
    // shard.json left by an earlier run is removed with the other files).
    let staging = output::Staging::new(&dir, &inputs)?;

    // The figures are drawn from the rows as they come, not from sweep.csv read back.
    let header = sweep.header();
    let mut table = if args.plot {
        Some(crate::plot::SweepTable::for_rows(&header, &sweep.axis_keys()).context("drawing the figures")?)
    } else {
        None
    };
    let file = RowsFile {
        path: &staging.path(SWEEP_CSV),
        shown: &csv_path,
        header: sweep.csv_header(),
        counted: "cases",
    };
    let threads = args.threads.map(|n| n as usize);
    let Written { done, wall } = write_rows(
        &file,
        cases.len(),
        |row| {
            if let Some(table) = &mut table {
                table.push(&row.cells);
            }
        },
        |cancel, sink| sweep.run_range(cases.clone(), threads, cancel, sink),
    )?;
    if done.cancelled {
        return Err(Interrupted::keep(staging, done.written, cases.len(), csv_path, "cases"));
    }

    let mut written = vec![SWEEP_CSV];
    let part = match args.shard {
        Some(shard) => {
            let manifest = Manifest::new("sweep", SWEEP_CSV, shard, sweep.len(), text.as_bytes());
            std::fs::write(staging.path(SHARD_JSON), manifest.to_json()).with_context(|| format!("cannot write {}", shard_path.display()))?;
            written.push(SHARD_JSON);
            format!(" (shard {shard}: cases {}..{} of {})", cases.start, cases.end, sweep.len())
        }
        None => String::new(),
    };
    let mut lines = vec![format!(
        "{}: {} cases{part} in {} s{}",
        sweep.name(),
        done.written,
        sig(wall, 3),
        match done.failed {
            0 => String::new(),
            n => format!(", {n} failed (see the error column)"),
        }
    )];
    if args.verbose {
        lines.push(format!(
            "  {} threads, {} ms per case ({} ms of one thread's time)",
            done.threads,
            sig(1e3 * wall / done.written.max(1) as f64, 3),
            sig(1e3 * wall * done.threads as f64 / done.written.max(1) as f64, 3)
        ));
        if let Some(kb) = peak_memory_kb() {
            lines.push(format!("  peak memory (VmHWM) {} MB", sig(kb as f64 / 1024.0, 3)));
        }
    }
    lines.push(format!("wrote {} in {}", written.join(", "), dir.display()));
    if let Some(table) = table {
        crate::plot::sweep_figures_of(staging.folder(), sweep.name(), &table.finish()).context("drawing the figures")?;
    }
    staging.commit()?;
    super::print(&(lines.join("\n") + "\n"))?;
    Ok(())
}

/// The process's peak resident memory (kB), from `/proc/self/status` (Linux only).
pub(crate) fn peak_memory_kb() -> Option<u64> {
    let status = std::fs::read_to_string(Path::new("/proc/self/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}
