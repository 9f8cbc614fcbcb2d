//! `rocking assess ASSESS.toml [--out DIR]`: the assessment of a tower to the
//! code (Circolare 2019 §C8.7.1.2.1, NTC 2018 or EN 1998). The file, the
//! capacity and the checks are `rocking_assess`'s; this file writes
//! `assessment.json` and `capacity.csv` in a staging folder moved into place at
//! the end, and prints one line per check.

use crate::format::sig;
use crate::output;
use anyhow::Context;
use rocking_assess::{Assessment, AssessmentInput, Check};
use std::path::{Path, PathBuf};

/// The verdict: capacity, sites, checks, governing check.
pub const ASSESSMENT_JSON: &str = "assessment.json";
/// The capacity curve d*, a*.
pub const CAPACITY_CSV: &str = "capacity.csv";
/// One row per limit state and record of the dynamic checks.
pub const RECORDS_CSV: &str = "records.csv";
/// The code spectra and the fitted records' spectra.
pub const SPECTRA_CSV: &str = "spectra.csv";
/// The page to attach to a report.
pub const REPORT_HTML: &str = "report.html";

/// Arguments of `rocking assess`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The assessment file: a scenario without [ground] plus [site] and [assessment].
    pub assessment: PathBuf,
    /// Output folder, created if needed [default: out/<file stem>]. The files
    /// of an earlier run of this tool there are replaced once the assessment
    /// ends; other files and inputs never are.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Also write the report's figures as files beside it, SVG and PNG:
    /// report_adrs (report_adrs_<mechanism> with blocks), and with a record
    /// set report_set_<LS> and report_lambda_<LS>[_<mechanism>].
    #[arg(long)]
    pub plot: bool,
    /// Worker threads of the dynamic checks [default: one per core].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub threads: Option<u32>,
}

/// One line of a check for the terminal.
fn check_line(c: &Check) -> String {
    format!(
        "  {:4} {:20} demand {} {} / capacity {} {}: ag capacity {}{} g, ζ_E {}{} {}",
        c.limit_state.as_str(),
        c.method.as_str(),
        sig(c.demand, 4),
        c.unit.as_str(),
        sig(c.capacity, 4),
        c.unit.as_str(),
        if c.ag_capacity.is_lower_bound() { "≥ " } else { "" },
        sig(c.ag_capacity.value(), 4),
        if c.ag_capacity.is_lower_bound() { "≥ " } else { "" },
        sig(c.zeta_e, 3),
        if c.holds { "holds" } else { "FAILS" }
    )
}

/// Assesses the tower and writes the files.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.map_or(0, |n| n as usize))
        .build()
        .context("starting the worker threads")?;
    pool.install(|| assess(args))
}

/// Writes the files of an assessment into `dir` (`shown` is the folder errors
/// name): assessment.json, capacity.csv, report.html, and with a record set
/// records.csv and spectra.csv.
pub fn write_files(dir: &Path, shown: &Path, input: &AssessmentInput, done: &Assessment) -> anyhow::Result<()> {
    write_files_plotted(dir, shown, input, done, false).map(|_| ())
}

/// As [`write_files`], and with `plot` the report's figures as SVG and PNG beside it; returns the figures' file names.
pub fn write_files_plotted(dir: &Path, shown: &Path, input: &AssessmentInput, done: &Assessment, plot: bool) -> anyhow::Result<Vec<String>> {
    let write = |name: &str, text: String| std::fs::write(dir.join(name), text).with_context(|| format!("cannot write {}", shown.join(name).display()));
    output::write_summary(&dir.join(ASSESSMENT_JSON), &shown.join(ASSESSMENT_JSON), &done.json(input))?;
    write(CAPACITY_CSV, done.capacity_csv())?;
    if let Some((records, spectra)) = done.set_csvs() {
        write(RECORDS_CSV, records)?;
        write(SPECTRA_CSV, spectra)?;
    }
    let (html, figures) = super::assess_report::report_and_figures(input, done)?;
    write(REPORT_HTML, html)?;
    if plot {
        return figures.write(dir).context("drawing the figures");
    }
    Ok(Vec::new())
}

fn assess(args: &Args) -> anyhow::Result<()> {
    // Ctrl-C or SIGTERM: the output folder left as it was, exit 130.
    crate::signals::stop_at_once();
    let started = std::time::Instant::now();
    let text = std::fs::read_to_string(&args.assessment).with_context(|| format!("cannot read {}", args.assessment.display()))?;
    // The file's errors already name the file, the key and the cause.
    let file = AssessmentInput::from_toml_str(&text, &args.assessment)?;
    let dir = args.out.clone().unwrap_or_else(|| super::run::default_out(&args.assessment));
    let mut names = vec![ASSESSMENT_JSON, CAPACITY_CSV, REPORT_HTML];
    if !file.file.records.is_empty() {
        names.extend([RECORDS_CSV, SPECTRA_CSV]);
    }
    let outputs: Vec<PathBuf> = names.iter().map(|f| dir.join(f)).collect();
    let mut inputs = vec![args.assessment.clone()];
    inputs.extend(file.inputs());
    output::refuse_to_overwrite_inputs(&outputs, &inputs)?;
    let staging = output::Staging::new(&dir, &inputs)?;

    let done = Assessment::run(&file)?;
    let figures = write_files_plotted(staging.folder(), &dir, &file, &done, args.plot)?;
    let figure_outputs: Vec<PathBuf> = figures.iter().map(|f| dir.join(f)).collect();
    output::refuse_to_overwrite_inputs(&figure_outputs, &inputs)?;
    staging.commit()?;
    let mut names: Vec<&str> = names;
    names.extend(figures.iter().map(String::as_str));

    let mechanisms = done.mechanisms();
    let stacked = mechanisms.len() > 1;
    let mut lines = Vec::new();
    for m in &mechanisms {
        let capacity = m.capacity;
        lines.push(format!(
            "{}: α0 = {}, a0* = {} m/s², d0 = {} m, T_SLV = {} s, T_SLC = {} s (FC {}, {} curve)",
            if stacked {
                format!("{}, {}", file.name(), m.name)
            } else {
                file.name().to_string()
            },
            sig(capacity.alpha0, 4),
            sig(capacity.a0_star, 4),
            sig(capacity.d0, 4),
            sig(capacity.t_slv, 4),
            sig(capacity.t_slc, 4),
            capacity.confidence_factor,
            capacity.curve
        ));
        lines.extend(m.checks.iter().map(check_line));
        for d in m.dynamic {
            match &d.check {
                Some(c) if !d.is_valid() => {
                    let ratios = &d.fitted.compatibility;
                    let range = done.set.as_ref().map_or((0.0, 0.0), |s| s.range);
                    let what = if done.accept_incompatible_set {
                        "accepted by assessment.accept_incompatible_set: it carries the verdict"
                    } else {
                        "not valid: the set is not compatible, out of the verdict"
                    };
                    lines.push(format!(
                        "{} ({what}: mean/code {}–{} over {}–{} s, outside 0.9–1.3, NTC 2018 §3.2.3.6)",
                        check_line(c),
                        sig(ratios.least_ratio, 3),
                        sig(ratios.greatest_ratio, 3),
                        sig(range.0, 3),
                        sig(range.1, 3)
                    ));
                    if done.accept_incompatible_set {
                        eprintln!(
                            "warning: {}: the {} non-linear dynamic check's record set is not compatible with the code's spectrum (NTC 2018 §3.2.3.6: mean/code {}–{}); assessment.accept_incompatible_set lets it carry the verdict",
                            args.assessment.display(),
                            d.limit_state,
                            sig(ratios.least_ratio, 3),
                            sig(ratios.greatest_ratio, 3)
                        );
                    }
                }
                Some(c) => lines.push(check_line(c)),
                None => lines.push(format!(
                    "  {:4} {:20} could not be completed: {}",
                    d.limit_state.as_str(),
                    "nonlinear_dynamic",
                    d.error.as_deref().unwrap_or("a record failed")
                )),
            }
        }
    }
    let relation = |c: &Check| if c.ag_capacity.is_lower_bound() { "≥" } else { "=" };
    let of = |name: &str| if stacked { format!("{name} ") } else { String::new() };
    if let Some((m, v)) = done.governing_verdict() {
        let g = v.check;
        let basis = if v.named {
            "named by assessment.verdict_method"
        } else {
            "the most refined method computed"
        };
        lines.push(format!(
            "governing: {}{} {}, ζ_E {} {} ({basis})",
            of(m.name),
            g.limit_state,
            g.method,
            relation(&g),
            sig(g.zeta_e, 3)
        ));
    }
    if let Some((m, d)) = done.damage() {
        lines.push(format!(
            "damage: {}{} {}, ζ_E {} {} (reported beside the verdict)",
            of(m.name),
            d.limit_state,
            d.method,
            relation(&d),
            sig(d.zeta_e, 3)
        ));
    }
    lines.push(format!(
        "wrote {} in {} ({} s)",
        names.join(", "),
        dir.display(),
        sig(started.elapsed().as_secs_f64(), 3)
    ));
    super::print(&(lines.join("\n") + "\n"))?;
    // A dynamic check that could not be completed gives no verdict: the files
    // say so (its row's error, "completed": false), and so does the exit status.
    if let Some(d) = done.dynamic.iter().find(|d| d.check.is_none()) {
        anyhow::bail!(
            "{}: assessment.records: the {} non-linear dynamic check could not be completed: {} (the other checks are in {})",
            args.assessment.display(),
            d.limit_state,
            d.error.as_deref().unwrap_or("a record failed to run"),
            dir.display()
        );
    }
    Ok(())
}
