//! The files of `rocking run`: `summary.json`, `history.csv`, `events.csv`
//! (interface.md, "Outputs of `run`"). Numbers are written with every digit
//! (shortest round-trip form), never rounded.

mod events;
mod guard;
mod history;

pub use events::write_events;
pub use guard::refuse_to_overwrite_inputs;
pub use history::write_history;

use anyhow::Context;
use std::path::Path;

/// The summary file.
pub const SUMMARY: &str = "summary.json";
/// The time-history file.
pub const HISTORY: &str = "history.csv";
/// The event file.
pub const EVENTS: &str = "events.csv";

/// Writes `summary.json`, pretty-printed.
pub fn write_summary(path: &Path, summary: &serde_json::Value) -> anyhow::Result<()> {
    let mut text = serde_json::to_string_pretty(summary).context("formatting the summary")?;
    text.push('\n');
    std::fs::write(path, text).with_context(|| format!("cannot write {}", path.display()))
}

/// A number in its shortest form that reads back to the same `f64`.
fn number(buffer: &mut ryu::Buffer, x: f64) -> &str {
    buffer.format(x)
}
