//! `rocking fragility STUDY.toml [--out DIR] [--plot] [--threads N] [--shard K/N]`:
//! a fragility study (README, "Fragility studies"). With `--shard K/N` only
//! the K-th block of cases runs and `shard.json` names the study file, whose
//! fits `rocking merge` makes from the merged stripes ([`fit_merged`]). The study and its
//! cases are `rocking_scenario::Study`, run on the sweep's engine; this file
//! writes `stripes.csv` row by row (with a progress bar and a clean stop on
//! Ctrl-C), then `fragility.csv` and `fractions.csv` from the exceedances
//! counted on the way, and with `--plot` the figures `ida` and `fragility`,
//! all in a staging folder moved into place at the end.

use super::rows::{write_rows, RowsFile, Written};
use super::sweep::{peak_memory_kb, Interrupted};
use crate::format::sig;
use crate::output;
use crate::plot::{IdaCurve, StateCurve, StudyFigures};
use crate::shard::{Manifest, SHARD_JSON};
use anyhow::Context;
use rocking_scenario::{Cell, Row, Shard, Study, Threshold};
use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;

/// One row per case.
pub const STRIPES_CSV: &str = "stripes.csv";
/// One row per limit state: the fitted fragility.
pub const FRAGILITY_CSV: &str = "fragility.csv";
/// One row per limit state and level: the observed fraction.
pub const FRACTIONS_CSV: &str = "fractions.csv";
/// With a `[site]`: the site's hazard curve, one row per return period of the grid.
pub const HAZARD_CSV: &str = "hazard.csv";
/// With a `[site]`: one row per limit state, its mean annual frequency over the hazard curve.
pub const RISK_CSV: &str = "risk.csv";

/// The files of the fits: `fragility.csv`, `fractions.csv`, and with a site `hazard.csv`, `risk.csv`.
fn fit_files(study: &Study, tally: &rocking_scenario::Tally, fits: &[rocking_scenario::Fit]) -> Vec<(&'static str, String)> {
    let mut files = vec![(FRAGILITY_CSV, tally.fragility_csv(fits)), (FRACTIONS_CSV, tally.fractions_csv())];
    if let Some(site) = study.site() {
        files.push((HAZARD_CSV, site.hazard_csv()));
        files.push((RISK_CSV, site.risk_csv(study.limit_states(), fits)));
    }
    files
}

/// Arguments of `rocking fragility`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The study file: a scenario without [ground] plus a [study] table (records, measure, levels, limit states).
    pub study: PathBuf,
    /// Output folder, created if needed [default: out/<study file stem>].
    /// The files of an earlier run of this tool there are replaced (stale
    /// figures removed) once the study ends; other files and inputs never are.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Also draw the response against the level per record (ida) and the fragility curves (fragility).
    #[arg(long)]
    pub plot: bool,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub threads: Option<u32>,
    /// Also print the threads used, the time per case and the peak memory.
    #[arg(long, short)]
    pub verbose: bool,
    /// Run only the K-th of N equal contiguous blocks of cases (1 <= K <= N)
    /// and write shard.json; `rocking merge` of all N writes stripes.csv and its fits.
    #[arg(long, value_name = "K/N", value_parser = parse_shard, conflicts_with = "plot")]
    pub shard: Option<Shard>,
}

fn parse_shard(text: &str) -> Result<Shard, String> {
    text.parse()
}

/// Fits `stripes.csv` at `stripes` (the merged rows of the shards of `study`)
/// and writes `fragility.csv` and `fractions.csv` in `out`, as an unsharded
/// run writes them; each file is made under a temporary name and never
/// replaces one already there.
pub fn fit_merged(study: &Study, stripes: &Path, out: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let context = || format!("cannot read {}", stripes.display());
    let mut reader = csv::Reader::from_path(stripes).with_context(context)?;
    let mut tally = study.tally();
    for (index, record) in reader.records().enumerate() {
        let record = record.with_context(context)?;
        tally.add(&Row {
            index,
            cells: record.iter().map(Cell::from_text).collect(),
        });
    }
    let fits = tally.fits();
    let mut written = Vec::new();
    for (name, text) in fit_files(study, &tally, &fits) {
        let target = out.join(name);
        let temp = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .tempfile_in(out)
            .with_context(|| format!("cannot write in {}", out.display()))?;
        std::fs::write(temp.path(), text).with_context(|| format!("cannot write {}", target.display()))?;
        temp.persist_noclobber(&target)
            .map_err(|e| e.error)
            .with_context(|| format!("cannot write {}", target.display()))?;
        written.push(target);
    }
    Ok(written)
}

/// Runs the study and writes its files.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let text = rocking_scenario::file::read_text(&args.study, rocking_scenario::file::MAX_INPUT_BYTES)
        .with_context(|| format!("cannot read {}", args.study.display()))?;
    // The study's errors already name the file, the key and the cause.
    let study = Study::from_toml_str(&text, &args.study)?;
    let dir = args.out.clone().unwrap_or_else(|| super::run::default_out(&args.study));
    let stripes_path = dir.join(STRIPES_CSV);
    let mut outputs: Vec<PathBuf> = [STRIPES_CSV, FRAGILITY_CSV, FRACTIONS_CSV, HAZARD_CSV, RISK_CSV, SHARD_JSON]
        .iter()
        .map(|f| dir.join(f))
        .collect();
    if args.plot {
        outputs.extend(
            ["ida.svg", "ida.png", "fragility.svg", "fragility.png", "risk.svg", "risk.png"]
                .iter()
                .map(|f| dir.join(f)),
        );
    }
    let mut inputs = vec![args.study.clone()];
    inputs.extend(study.inputs());
    output::refuse_to_overwrite_inputs(&outputs, &inputs)?;
    // Written under a staging folder and moved into place at the end (or on
    // Ctrl-C, with the rows finished): never a mix with an earlier study's files.
    let staging = output::Staging::new(&dir, &inputs)?;

    let mut tally = study.tally();
    // The response of the first limit state's field per case, for the IDA figure (one number per case).
    let header = study.header();
    let first = study.limit_states().first();
    let ida_field = first.map_or("max_theta_over_alpha", |s| s.field.as_str()).to_string();
    let ida_column = header.iter().position(|h| *h == ida_field);
    let overturned_column = header.iter().position(|h| h == "overturned");
    // Only for the figure: no curves without --plot.
    let mut ida: Vec<IdaCurve> = study
        .records()
        .iter()
        .filter(|_| args.plot)
        .map(|r| IdaCurve {
            record: r.path.clone(),
            points: Vec::with_capacity(study.levels().len()),
        })
        .collect();

    let levels = study.levels().len();
    let file = RowsFile {
        path: &staging.path(STRIPES_CSV),
        shown: &stripes_path,
        header: study.csv_header(),
        counted: "cases",
    };
    let threads = args.threads.map(|n| n as usize);
    let cases = args.shard.map_or(0..study.len(), |s| s.cases(study.len()));
    let Written { done, wall } = write_rows(
        &file,
        cases.len(),
        |row| {
            tally.add(row);
            let cell = |c: Option<usize>| c.and_then(|c| row.cells.get(c));
            let value = match cell(ida_column) {
                Some(Cell::Bool(b)) => Some(f64::from(u8::from(*b))),
                Some(c) => c.as_f64(),
                None => None,
            };
            let overturned = matches!(cell(overturned_column), Some(Cell::Bool(true)));
            // One point per case.
            if let Some(curve) = ida.get_mut(row.index / levels) {
                curve.points.push((study.levels()[row.index % levels], value, overturned));
            }
        },
        |cancel, sink| study.run_range(cases.clone(), threads, cancel, sink),
    )?;
    if done.cancelled {
        return Err(Interrupted::keep(staging, done.written, cases.len(), stripes_path, "cases"));
    }
    if let Some(shard) = args.shard {
        // The fits need every stripe: `rocking merge` makes them.
        let mut manifest = Manifest::new("fragility", STRIPES_CSV, shard, study.len(), text.as_bytes());
        let absolute = std::path::absolute(&args.study).with_context(|| format!("cannot resolve {}", args.study.display()))?;
        manifest.study = Some(absolute.display().to_string());
        std::fs::write(staging.path(SHARD_JSON), manifest.to_json()).with_context(|| format!("cannot write {}", dir.join(SHARD_JSON).display()))?;
        staging.commit()?;
        return super::print(&format!(
            "{}: {} cases (shard {shard}: cases {}..{} of {}) in {} s\nwrote {STRIPES_CSV}, {SHARD_JSON} in {}\n",
            study.name(),
            done.written,
            cases.start,
            cases.end,
            study.len(),
            sig(wall, 3),
            dir.display()
        ));
    }
    // Ctrl-C during the fits: stripes.csv is complete, the fits are not written.
    let interrupted = crate::signals::interrupted();
    let fits = tally.fits_until(interrupted);
    if interrupted.load(Ordering::Relaxed) {
        return Err(Interrupted::keep(staging, done.written, study.len(), stripes_path, "cases"));
    }
    for (name, text) in fit_files(&study, &tally, &fits) {
        std::fs::write(staging.path(name), text).with_context(|| format!("cannot write {}", dir.join(name).display()))?;
    }

    let mut lines = vec![format!(
        "{}: {} records × {} levels = {} cases in {} s{}",
        study.name(),
        study.records().len(),
        levels,
        done.written,
        sig(wall, 3),
        match done.failed {
            0 => String::new(),
            n => format!(", {n} failed (see the error column)"),
        }
    )];
    let unit = study.measure().unit();
    for (state, fit) in study.limit_states().iter().zip(&fits) {
        lines.push(match (fit.median, fit.beta) {
            (Some(m), Some(b)) => format!(
                "  {}: median {} {}{}, beta {} ({} of {} cases exceeded)",
                state.name,
                study.measure().as_str(),
                sig(m, 4),
                if unit.is_empty() { String::new() } else { format!(" {unit}") },
                sig(b, 3),
                fit.exceeded,
                fit.cases
            ),
            _ => format!("  {}: {}", state.name, fit.method),
        });
    }
    if let Some(site) = study.site() {
        for (state, fit) in study.limit_states().iter().zip(&fits) {
            if let (Some(m), Some(b)) = (fit.median, fit.beta) {
                let r = site.risk(m, b);
                lines.push(format!(
                    "  {} at the site: {} per year (return period {} years), {} in 50 years{}",
                    state.name,
                    sig(r.frequency.annual_frequency, 4),
                    sig(r.return_period, 4),
                    sig(r.probability_50y, 3),
                    match (site.reference_period, r.probability_reference) {
                        (Some(vr), Some(p)) => format!(", {} in VN·CU = {} years", sig(p, 3), sig(vr, 4)),
                        _ => String::new(),
                    }
                ));
            }
        }
    }
    if args.verbose {
        lines.push(format!(
            "  {} threads, {} ms per case ({} ms of one thread's time)",
            done.threads,
            sig(1e3 * wall / done.written.max(1) as f64, 3),
            sig(1e3 * wall * done.threads as f64 / done.written.max(1) as f64, 3)
        ));
        if let Some(kb) = peak_memory_kb() {
            lines.push(format!("  peak memory (VmHWM) {} MB", sig(kb as f64 / 1024.0, 3)));
        }
    }
    let risk_files = if study.site().is_some() {
        format!(", {HAZARD_CSV}, {RISK_CSV}")
    } else {
        String::new()
    };
    lines.push(format!(
        "wrote {STRIPES_CSV}, {FRAGILITY_CSV}, {FRACTIONS_CSV}{risk_files} in {}",
        dir.display()
    ));
    if args.plot {
        let figures = StudyFigures {
            title: study.name().to_string(),
            measure: study.measure(),
            ida_field,
            ida_threshold: first.and_then(|s| match s.threshold {
                Threshold::Above(x) => Some(x),
                Threshold::True => None,
            }),
            ida,
            states: study
                .limit_states()
                .iter()
                .enumerate()
                .map(|(i, s)| StateCurve {
                    name: s.name.clone(),
                    stripes: tally.stripes(i),
                    fit: fits[i].median.zip(fits[i].beta),
                })
                .collect(),
            site: study.site().map(|site| site.curve.clone()),
        };
        crate::plot::study_figures(staging.folder(), &figures).context("drawing the figures")?;
    }
    staging.commit()?;
    super::print(&(lines.join("\n") + "\n"))?;
    Ok(())
}
