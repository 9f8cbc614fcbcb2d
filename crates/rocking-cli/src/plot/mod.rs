//! Figures of a run and of a sweep, as SVG and PNG (being written: these
//! entry points are the interface the commands call).

use rocking_scenario::Outcome;
use std::path::{Path, PathBuf};

/// Draws the figures of one run into `dir` (`theta.svg`/`.png`: θ/α and the
/// ground acceleration against time; `slip.svg`/`.png`: building slip and top
/// displacement against time), returning the files written.
pub fn run_figures(dir: &Path, outcome: &Outcome) -> anyhow::Result<Vec<PathBuf>> {
    let _ = (dir, outcome);
    anyhow::bail!("plots are not available yet")
}

/// Draws the figures of a sweep from its `sweep.csv` into `dir`: max θ/α
/// against the first axis with one curve per value of the second, and for two
/// numeric axes a heat map; `axis_keys` are the swept dotted keys in order.
#[allow(dead_code)] // called by `rocking sweep --plot`, which is being written
pub fn sweep_figures(dir: &Path, title: &str, csv: &Path, axis_keys: &[String]) -> anyhow::Result<Vec<PathBuf>> {
    let _ = (dir, title, csv, axis_keys);
    anyhow::bail!("plots are not available yet")
}
