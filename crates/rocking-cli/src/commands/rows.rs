//! The rows of a sweep, a fragility study or an inventory written to their CSV file as the
//! cases finish: the header first, a progress bar on a terminal, a clean stop
//! on Ctrl-C (the rows finished so far kept, complete and in order), and every
//! write error named by the file the user will look for.

use anyhow::Context;
use indicatif::{ProgressBar, ProgressStyle};
use rocking_scenario::{Finished, Row, RunError};
use std::fs::File;
use std::io::{BufWriter, IsTerminal, Write};
use std::path::Path;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// The CSV file being written.
pub struct RowsFile<'a> {
    /// Where it is written (a staging folder's copy, or the file itself).
    pub path: &'a Path,
    /// The name errors give (the final path).
    pub shown: &'a Path,
    /// Its header line.
    pub header: String,
    /// What a row is, for the progress bar: `cases`, `towers`.
    pub counted: &'static str,
}

/// How the cases ended, and the wall time they took (s).
pub struct Written {
    /// Rows written, failures, cancellation, threads.
    pub done: Finished,
    /// Seconds from the first case to the last row.
    pub wall: f64,
}

/// Creates `file` and writes its header, then runs `total` cases by `run`,
/// which is given the cancel flag and the sink of the rows: each row is
/// written as one line, then shown to `each` (the figures' tables, a study's
/// tally), and advances the progress bar.
pub fn write_rows(
    file: &RowsFile<'_>,
    total: usize,
    mut each: impl FnMut(&Row),
    run: impl FnOnce(&AtomicBool, &mut dyn FnMut(Row) -> std::io::Result<()>) -> Result<Finished, RunError<std::io::Error>>,
) -> anyhow::Result<Written> {
    let context = || format!("cannot write {}", file.shown.display());
    let mut csv = BufWriter::new(File::create(file.path).with_context(context)?);
    // The header on disk at once: the file is the sweep's from its start.
    writeln!(csv, "{}", file.header).and_then(|()| csv.flush()).with_context(context)?;

    // The first Ctrl-C stops the cases; a second ends the process at once (crate::signals).
    let interrupted = crate::signals::interrupted();
    let progress = progress_bar(total, file.counted);
    let start = Instant::now();
    let result = run(interrupted, &mut |row: Row| {
        writeln!(csv, "{}", row.to_csv_line())?;
        each(&row);
        progress.inc(1);
        Ok(())
    });
    progress.finish_and_clear();
    let flushed = csv.flush();
    let done = match result {
        Ok(done) => done,
        Err(RunError::Stopped(e)) => return Err(e).with_context(context),
        Err(e) => return Err(e.into()),
    };
    flushed.with_context(context)?;
    Ok(Written {
        done,
        wall: start.elapsed().as_secs_f64(),
    })
}

/// A bar with the rate and the time left on stderr, when stderr is a terminal; hidden otherwise.
fn progress_bar(len: usize, counted: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(len as u64);
    if let Ok(style) = ProgressStyle::with_template(&format!("{{bar:40}} {{pos}}/{{len}} {counted}  {{per_sec}}  {{elapsed}} elapsed, {{eta}} left")) {
        bar.set_style(style);
    }
    bar
}
