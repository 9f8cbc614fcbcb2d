//! `rocking keys [--markdown | --json]`: every scenario key (and assessment-file key) with its unit, default and
//! valid range, from the table the parser checks keys against. `--markdown`
//! prints the reference page of the documentation (`docs/src/reference/keys.md`);
//! `--json` the whole description of each key (symbol, choices, …), as the page reads it.

use rocking_scenario::{keys_json, keys_markdown, ASSESSMENT_KEY_DOCS, SCENARIO_KEYS};
use std::fmt::Write;

/// Arguments of `rocking keys`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Print the documentation's reference page (Markdown) instead of one line per key.
    #[arg(long, conflicts_with = "json")]
    pub markdown: bool,
    /// Print every key's description as JSON: `{ "scenario": [...], "assessment": [...] }`, each key with its
    /// unit, symbol, label, default, valid values, meaning, example, choices and whether a sweep can vary it.
    #[arg(long)]
    pub json: bool,
}

/// Prints the keys.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    if args.markdown {
        return super::print(&keys_markdown());
    }
    if args.json {
        return super::print(&format!("{:#}\n", keys_json()));
    }
    // The scenario's keys, then those of an assessment file's [site] and [assessment].
    let keys = || SCENARIO_KEYS.iter().chain(ASSESSMENT_KEY_DOCS);
    let width = keys().map(|k| k.key.chars().count()).max().unwrap_or(0);
    let mut out = String::new();
    for k in keys() {
        let unit = if k.unit.is_empty() { "-" } else { k.unit };
        // Writing to a String cannot fail.
        let _ = writeln!(out, "{:width$}  {unit:6} default: {}; valid: {}. {}", k.key, k.default, k.range, k.meaning);
    }
    super::print(&out)
}
