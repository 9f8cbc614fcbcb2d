//! `rocking`: the seismic response of a rigid tower rocking on a building that
//! may slide on its foundation (Housner's rocking block on a Coulomb slider).
//!
//! ```text
//! rocking run SCENARIO.toml [--out DIR] [--plot]   # one analysis
//! rocking sweep SWEEP.toml [--out DIR] [--plot] [--threads N]   # a parametric study
//! rocking fragility STUDY.toml [--out DIR] [--plot] [--threads N]   # a fragility study
//! rocking assess ASSESS.toml [--out DIR]           # the checks of the code (Circolare 2019, EC8)
//! rocking inventory TOWERS.csv --assess ASSESS.toml [--out DIR] [--plot] [--threads N] [--shard K/N]   # every tower of a town, ranked by ζ_E
//! rocking check SCENARIO.toml                      # validate, print derived quantities
//! rocking spectrum RECORD... [--damping PCT] [--periods FROM,TO,N] [--out DIR] [--plot]   # response spectra
//! rocking spectrum --site ASSESS.toml [--out DIR] [--plot]   # code spectra, the record set fitted
//! rocking sweep SWEEP.toml --shard K/N [--out DIR]  # one block of a sweep's cases
//! rocking merge DIR1 DIR2 ... --out DIR             # the shards' rows in one sweep.csv
//! rocking keys [--markdown]                        # every scenario key, unit, default, range
//! rocking --version
//! ```
//!
//! Exit status: 0 on success, 1 on an input or physics error (one line on
//! stderr naming the file, the key and what is wrong), 2 on bad usage, 130
//! when a sweep or a study is interrupted by Ctrl-C (after writing the rows finished) or
//! a run, an assessment or an inventory is (writing nothing); 143 for SIGTERM, 129 for SIGHUP.

mod commands;
mod format;
mod output;
mod plot;
mod shard;
mod signals;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Rocking of a slender rigid tower on a building that may slide on its foundation, under horizontal ground acceleration.
#[derive(Debug, Parser)]
#[command(name = "rocking", version)]
#[command(after_help = "Exit status: 0 on success, 1 on an input or physics error (one line on stderr), 2 on bad usage.")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run one scenario: writes summary.json, history.csv and events.csv.
    Run(commands::run::Args),
    /// Run a parametric sweep: every combination of the [sweep] values is one case, one row of sweep.csv.
    Sweep(commands::sweep::Args),
    /// Merge the folders of `rocking sweep --shard K/N` (or `rocking inventory --shard K/N`) into one sweep.csv (inventory.csv), identical to the unsharded one.
    Merge(commands::merge::Args),
    /// Run a fragility study: a suite of records scaled to levels of an intensity measure; stripes, fitted fragility curves.
    Fragility(commands::fragility::Args),
    /// Assess a tower to the code (Circolare 2019 §C8.7.1.2.1, NTC 2018 or EN 1998): capacity, checks, ζ_E; writes assessment.json, capacity.csv, records.csv and spectra.csv with a record set, and report.html.
    Assess(commands::assess::Args),
    /// Assess every tower of a town (one row of a CSV each) as `rocking assess` does; writes inventory.csv and inventory.geojson, ranked by ζ_E.
    Inventory(commands::inventory::Args),
    /// Validate a scenario and print its derived quantities (α, R, p, r, uplift and slip thresholds, ground motion).
    Check(commands::check::Args),
    /// Response spectra of records, or the code spectra of an assessment file's site and its record set fitted to them.
    Spectrum(commands::spectrum::Args),
    /// List every scenario key with its unit, default and valid range (--markdown: the documentation's reference page).
    Keys(commands::keys::Args),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // --help and --version print to stdout and exit 0; usage errors exit 2.
            let _ = e.print();
            return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
        }
    };
    let result = match &cli.command {
        Command::Run(args) => commands::run::execute(args),
        Command::Check(args) => commands::check::execute(args),
        Command::Sweep(args) => commands::sweep::execute(args),
        Command::Merge(args) => commands::merge::execute(args),
        Command::Keys(args) => commands::keys::execute(args),
        Command::Fragility(args) => commands::fragility::execute(args),
        Command::Assess(args) => commands::assess::execute(args),
        Command::Inventory(args) => commands::inventory::execute(args),
        Command::Spectrum(args) => commands::spectrum::execute(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is::<commands::sweep::Interrupted>() || e.is::<commands::run::Interrupted>() => {
            eprintln!("{e}");
            ExitCode::from(crate::signals::exit_status())
        }
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
