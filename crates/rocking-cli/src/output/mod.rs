//! The files of `rocking run`: `summary.json`, `history.csv`, `events.csv`
//! (docs/src/reference/outputs.md). Numbers are written with every digit
//! (shortest round-trip form), never rounded.

mod events;
mod folder;
mod guard;
mod history;
mod lock;

pub use events::write_events;
pub use folder::{CreatedFolders, Staging};
pub use guard::refuse_to_overwrite_inputs;
pub use history::HistoryWriter;
pub use lock::{FolderLock, LOCK_FILE};

use anyhow::Context;
use rocking_scenario::columns::Value;
use std::path::Path;

/// The summary file.
pub const SUMMARY: &str = "summary.json";
/// The time-history file.
pub const HISTORY: &str = "history.csv";
/// The event file.
pub const EVENTS: &str = "events.csv";

/// Writes `summary.json`, pretty-printed, to `path`; `shown` names the file in errors.
pub fn write_summary(path: &Path, shown: &Path, summary: &serde_json::Value) -> anyhow::Result<()> {
    let mut text = serde_json::to_string_pretty(summary).context("formatting the summary")?;
    text.push('\n');
    std::fs::write(path, text).with_context(|| format!("cannot write {}", shown.display()))
}

/// Writes one CSV field: a number in its shortest form that reads back to
/// the same `f64`, or a name (as a spreadsheet shows text, `spreadsheet_text`).
fn write_value<W: std::io::Write>(w: &mut csv::Writer<W>, buffer: &mut ryu::Buffer, value: Value) -> csv::Result<()> {
    match value {
        Value::Number(x) => w.write_field(buffer.format(x)),
        Value::Text(t) => w.write_field(rocking_scenario::spreadsheet_text(t).as_bytes()),
    }
}
