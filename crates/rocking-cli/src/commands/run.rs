//! `rocking run SCENARIO.toml [--out DIR] [--plot]`: one analysis.

use crate::format::sig;
use crate::output;
use anyhow::Context;
use rocking::{Flow, Halt, Observer, Sample, Sampler, Step};
use rocking_scenario::{summary_json, ErrorKind, Outcome, RunOptions};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// Arguments of `rocking run`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scenario file (TOML).
    pub scenario: PathBuf,
    /// Output folder, created if needed [default: out/<scenario file stem>].
    /// The files of an earlier run of this tool there are overwritten (and
    /// its figures removed) only once this run has succeeded; other files and
    /// an input file (the scenario, a record) never are.
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

/// The run was stopped by Ctrl-C; the output folder was left as it was.
#[derive(Debug)]
pub struct Interrupted;

impl std::fmt::Display for Interrupted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "interrupted: nothing written")
    }
}

impl std::error::Error for Interrupted {}

/// Stops the run at its next step when Ctrl-C was pressed (or SIGTERM came).
struct CtrlC(&'static AtomicBool);

impl Observer for CtrlC {
    fn on_step(&mut self, _: &Step<'_>) -> Flow {
        if self.0.load(Ordering::Relaxed) {
            Flow::Break(Halt::Stop)
        } else {
            Flow::Continue(())
        }
    }
}

/// Runs the scenario and writes its files: under a staging folder, moved into
/// the output folder only when everything is written (output::Staging).
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let scenario = super::load_scenario(&args.scenario)?;
    let case = scenario.build()?;
    let dir = args.out.clone().unwrap_or_else(|| default_out(&args.scenario));
    let mut names = vec![output::SUMMARY, output::HISTORY, output::EVENTS];
    if args.plot {
        names.extend(crate::plot::RUN_FILES);
    }
    let files: Vec<PathBuf> = names.iter().map(|f| dir.join(f)).collect();
    let mut inputs = vec![args.scenario.clone()];
    inputs.extend(case.inputs.iter().cloned());
    output::refuse_to_overwrite_inputs(&files, &inputs)?;
    let staging = output::Staging::new(&dir, &inputs)?;
    let interrupted = crate::signals::interrupted();

    let mut history = output::HistoryWriter::create(&staging.path(output::HISTORY), &files[1], case.layout())?;
    let mut sampler = Sampler::new(case.output_dt, case.points.clone(), |sample: &Sample, points: &[(f64, f64)]| {
        history.row(sample, points)
    });
    // The figures need the samples in memory; without --plot nothing grows with the history.
    let options = RunOptions {
        history: args.plot,
        events: true,
    };
    let start = Instant::now();
    let result = case.run_observed(options, &mut (&mut sampler, CtrlC(interrupted)));
    let wall = start.elapsed().as_secs_f64();
    drop(sampler);
    let outcome = match result {
        Ok(outcome) => outcome,
        Err(e) => {
            return Err(match e.kind() {
                ErrorKind::Simulation(rocking::Error::Stopped { .. }) => Interrupted.into(),
                // The writer's own error, with the file it could not write.
                ErrorKind::Simulation(rocking::Error::Observer { .. }) => history.finish().err().unwrap_or_else(|| e.into()),
                _ => e.into(),
            });
        }
    };
    history.finish()?;
    output::write_summary(&staging.path(output::SUMMARY), &files[0], &summary_json(&outcome, wall))?;
    output::write_events(&staging.path(output::EVENTS), &files[2], &outcome.layout, &outcome.events)?;
    let figures = if args.plot {
        crate::plot::run_figures(staging.folder(), &outcome).context("drawing the figures")?
    } else {
        Vec::new()
    };
    staging.commit()?;
    super::print(&report(&outcome, wall, &dir))?;
    if args.plot {
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
    // The block that overturned (0 the tower), if one did.
    let overturned = match s.stack {
        Some(stack) => stack.overturned_block,
        None => s.overturn_time.map(|_| 0),
    };
    let fate = |k: usize| match (overturned, s.overturn_time) {
        (Some(o), Some(t)) if o == k => format!("OVERTURNED at t = {} s", sig(t, 6)),
        _ => "did not overturn".to_string(),
    };
    if let Some(alpha) = d.alpha {
        let fate = fate(0);
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
    if let Some(stack) = s.stack {
        for (i, (block, summary)) in outcome.blocks.iter().zip(stack.blocks()).enumerate() {
            let uplift = match summary.first_uplift_time {
                Some(t) => format!(", first uplift at t = {} s", sig(t, 6)),
                None => ", never lifted".into(),
            };
            lines.push(format!(
                "  {}: max θ/α = {} (max |θ| = {} rad on the block below), {} impacts{uplift}, {}",
                outcome.layout.blocks.name(i + 1),
                sig(summary.max_abs_theta / block.alpha(), 4),
                sig(summary.max_abs_theta, 4),
                summary.impacts,
                fate(i + 1)
            ));
        }
        lines.push(format!(
            "  seated interfaces: max impulse ratio {} (above 1 the model's assumption fails)",
            sig(stack.max_seat_impulse_ratio, 4)
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
