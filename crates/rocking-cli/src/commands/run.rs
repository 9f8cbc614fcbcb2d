//! `rocking run SCENARIO.toml [--out DIR] [--plot]`: one analysis.

use crate::format::sig;
use crate::output;
use anyhow::Context;
use rocking_scenario::{summary_json, Outcome, RunOptions};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `rocking run`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scenario file (TOML).
    pub scenario: PathBuf,
    /// Output folder, created if needed [default: out/<scenario file stem>].
    /// The tool's own files there (summary.json, history.csv, events.csv) are
    /// overwritten; an input file (the scenario, a record) never is.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Also draw the figures theta.svg/.png (θ/α and the ground acceleration
    /// against time) and slip.svg/.png (building slip and top displacement).
    #[arg(long)]
    pub plot: bool,
}

/// `out/<stem>` for `scenario`.
pub fn default_out(scenario: &Path) -> PathBuf {
    let stem = scenario.file_stem().map_or_else(|| "scenario".into(), |s| s.to_os_string());
    Path::new("out").join(stem)
}

/// Runs the scenario and writes its files.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let scenario = super::load_scenario(&args.scenario)?;
    let case = scenario.build()?;
    let dir = args.out.clone().unwrap_or_else(|| default_out(&args.scenario));
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create the output folder {}", dir.display()))?;
    let mut files: Vec<PathBuf> = [output::SUMMARY, output::HISTORY, output::EVENTS].iter().map(|f| dir.join(f)).collect();
    if args.plot {
        files.extend(crate::plot::RUN_FILES.iter().map(|f| dir.join(f)));
    }
    let mut inputs = vec![args.scenario.clone()];
    inputs.extend(case.inputs.iter().cloned());
    output::refuse_to_overwrite_inputs(&files, &inputs)?;

    let start = Instant::now();
    let outcome = case.run(RunOptions::ALL)?;
    let wall = start.elapsed().as_secs_f64();
    let summary = summary_json(&outcome, wall);
    output::write_summary(&files[0], &summary)?;
    if let Some(history) = &outcome.history {
        output::write_history(&files[1], history, case.points.len())?;
    }
    output::write_events(&files[2], &outcome.events)?;
    super::print(&report(&outcome, wall, &dir))?;
    if args.plot {
        let figures = crate::plot::run_figures(&dir, &outcome).context("drawing the figures")?;
        let names: Vec<String> = figures.iter().filter_map(|f| f.file_name()).map(|n| n.to_string_lossy().into_owned()).collect();
        super::print(&format!("drew {} in {}\n", names.join(", "), dir.display()))?;
    }
    Ok(())
}

/// A few lines for people: how far the tower rocked, whether it fell, how far the building slid.
fn report(outcome: &Outcome, wall: f64, dir: &Path) -> String {
    let s = &outcome.summary;
    let d = &outcome.derived;
    let mut lines = vec![format!("{}: {} s simulated in {} s", outcome.name, sig(s.end_time, 6), sig(wall, 2))];
    if let Some(alpha) = d.alpha {
        let fate = match s.overturn_time {
            Some(t) => format!("OVERTURNED at t = {} s", sig(t, 6)),
            None => "did not overturn".into(),
        };
        let uplift = match s.first_uplift_time {
            Some(t) => format!(", first uplift at t = {} s", sig(t, 6)),
            // An initial rotation rocks without an uplift.
            None if s.max_abs_theta() > 0.0 => String::new(),
            None => ", never lifted".into(),
        };
        lines.push(format!(
            "  tower:    max θ/α = {} (max |θ| = {} rad), {} impacts{uplift}, {fate}",
            sig(s.max_abs_theta() / alpha, 4),
            sig(s.max_abs_theta(), 4),
            s.impacts
        ));
    }
    if d.slip_acceleration_g.is_some() {
        let slip = match s.first_slip_time {
            Some(t) => format!(
                "max |slip| = {} m, final slip = {} m, first slip at t = {} s",
                sig(s.max_abs_slip, 4),
                sig(s.final_slip, 4),
                sig(t, 6)
            ),
            None => "did not slip".into(),
        };
        lines.push(format!("  building: {slip}"));
    }
    lines.push(format!(
        "wrote {}, {}, {} in {}",
        output::SUMMARY,
        output::HISTORY,
        output::EVENTS,
        dir.display()
    ));
    lines.join("\n") + "\n"
}
