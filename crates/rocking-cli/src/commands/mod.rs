//! One file per subcommand; each has its clap `Args` and an `execute`.

pub mod assess;
pub mod assess_floor;
pub mod assess_report;
pub mod check;
pub mod fragility;
pub mod inventory;
pub mod keys;
pub mod merge;
pub mod rows;
pub mod run;
pub mod spectrum;
pub mod sweep;
pub mod town;
pub mod town_report;

use anyhow::Context;
use rocking_scenario::Scenario;
use std::io::Write;
use std::path::Path;

/// Reads and validates a scenario file.
pub fn load_scenario(path: &Path) -> anyhow::Result<Scenario> {
    let text = rocking_scenario::file::read_text(path, rocking_scenario::file::MAX_INPUT_BYTES).with_context(|| format!("cannot read {}", path.display()))?;
    // The scenario's errors already name the file, the key and the cause.
    Ok(Scenario::from_toml_str(&text, path)?)
}

/// Writes `text` to stdout; a closed pipe (`rocking check x.toml | head -1`) is not an error.
pub fn print(text: &str) -> anyhow::Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(e).context("writing to stdout"),
        _ => Ok(()),
    }
}
