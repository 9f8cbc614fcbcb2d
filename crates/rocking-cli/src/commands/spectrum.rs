//! `rocking spectrum`: response spectra of records, or the code spectra of an
//! assessment file's site with its record set fitted to them.
//!
//! ```text
//! rocking spectrum RECORD... [--dt S] [--units g|m/s2|cm/s2] [--damping PCT] [--periods FROM,TO,N] [--out DIR] [--plot]
//! rocking spectrum --site ASSESS.toml [--periods FROM,TO,N] [--out DIR] [--plot]
//! ```
//!
//! The first form writes `spectra.csv` (`period_s`, then each record's PSA in
//! g); the second the code spectra of each limit state (`Se_<LS>_g`,
//! `SDe_<LS>_m` at 5%, and at the damping of its kinematic check), and with a
//! record set, the set fitted to SLV and SLC (EC8: SD, NC): `fit.csv`,
//! `fit.json`, the scaled spectra and their mean in `spectra.csv`. The
//! formulas are in `rocking_codes`.

use crate::format::sig;
use crate::output;
use crate::plot::{Band, Curve, Ink, SpectraFigure};
use anyhow::Context;
use rocking::{AccelerationUnit, CsvOptions, Record};
use rocking_codes::{default_period_range, fit_record_set, FittedSet, LimitState, PeriodGrid, SetRule, DEFAULT_DAMPING_PCT, DEFAULT_PERIODS};
use rocking_scenario::{
    code_spectra_columns, csv_line, dynamic_limit_states, read_record_with, record_names, record_spectra_in_g, same_record_twice, spreadsheet_text,
    AssessmentFile, SpectrumKind, ACCELERATION_UNITS, DEFAULT_G,
};
use std::path::{Path, PathBuf};

/// The spectra, one column per record or per spectrum.
pub const SPECTRA_CSV: &str = "spectra.csv";
/// One row per limit state and record: the fitted scales.
pub const FIT_CSV: &str = "fit.csv";
/// Each limit state's compatibility.
pub const FIT_JSON: &str = "fit.json";

/// Arguments of `rocking spectrum`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Record files (AT2, ESM ASCII, CSV with a time column in g; the format is guessed).
    #[arg(required_unless_present = "site", conflicts_with = "site")]
    pub records: Vec<PathBuf>,
    /// An assessment file: the code spectra of its [site] and its record set fitted to them.
    #[arg(long, value_name = "ASSESS.toml")]
    pub site: Option<PathBuf>,
    /// Time step of a CSV record with one (acceleration) column, s (an AT2 or ESM file carries its own).
    #[arg(long, value_name = "S", value_parser = time_step, allow_negative_numbers = true, conflicts_with = "site")]
    pub dt: Option<f64>,
    /// Units of a CSV record's acceleration: g, m/s2 or cm/s2 [default: g] (an AT2 or ESM file carries its own).
    #[arg(long, value_name = "UNITS", value_parser = units, conflicts_with = "site")]
    pub units: Option<AccelerationUnit>,
    /// Damping of the records' spectra, % of critical [default: 5].
    #[arg(long, value_name = "PCT", allow_negative_numbers = true, conflicts_with = "site")]
    pub damping: Option<f64>,
    /// Periods: FROM,TO,N, N log-spaced values from FROM to TO seconds (N at most 10,000) [default: 0.02,4,100].
    #[arg(long, value_name = "FROM,TO,N", allow_hyphen_values = true)]
    pub periods: Option<String>,
    /// Output folder, created if needed [default: out/spectra, or out/<assessment file stem>].
    /// The files of an earlier run of this tool there are replaced; other files never are.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Also draw the figures (log-log): spectra, code_spectra, fit_<LS>.
    #[arg(long)]
    pub plot: bool,
}

/// Parses `--dt`: a time step in s, finite and > 0, as `[ground].dt`.
fn time_step(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(dt) if dt.is_finite() && dt > 0.0 => Ok(dt),
        _ => Err(format!("expected a time step in s, a number > 0, got {text:?}")),
    }
}

/// Parses `--units`: a name of `[ground].units`.
fn units(text: &str) -> Result<AccelerationUnit, String> {
    ACCELERATION_UNITS.iter().find(|(name, _)| *name == text).map(|(_, unit)| *unit).ok_or_else(|| {
        let names: Vec<&str> = ACCELERATION_UNITS.iter().map(|(name, _)| *name).collect();
        format!("expected one of {}, got {text:?}", names.join(", "))
    })
}

/// Parses `--periods FROM,TO,N`.
fn periods(arg: Option<&str>) -> anyhow::Result<Vec<f64>> {
    let grid = match arg {
        None => DEFAULT_PERIODS,
        Some(text) => {
            let parts: Vec<&str> = text.split(',').map(str::trim).collect();
            let bad = || anyhow::anyhow!("--periods: expected FROM,TO,N (seconds, seconds, a count), e.g. 0.02,4,100; got {text:?}");
            let [from, to, n] = parts.as_slice() else { return Err(bad()) };
            PeriodGrid {
                from: from.parse().map_err(|_| bad())?,
                to: to.parse().map_err(|_| bad())?,
                count: n.parse().map_err(|_| bad())?,
            }
        }
    };
    grid.periods().map_err(|e| anyhow::anyhow!("--periods: {}", reason(&e)))
}

/// What a library error says, without the parameter's own name (the caller names the option).
fn reason(e: &rocking_codes::Error) -> String {
    match e {
        rocking_codes::Error::InvalidParameter { reason, .. } => reason.clone(),
        other => other.to_string(),
    }
}

/// Writes a CSV of `period_s` and the columns, every digit.
fn write_columns(path: &Path, shown: &Path, periods: &[f64], columns: &[(String, Vec<f64>)]) -> anyhow::Result<()> {
    let mut w = csv::Writer::from_path(path).with_context(|| format!("cannot write {}", shown.display()))?;
    let mut header = vec!["period_s".to_string()];
    header.extend(columns.iter().map(|(n, _)| spreadsheet_text(n).into_owned()));
    w.write_record(&header)?;
    let mut buffer = ryu::Buffer::new();
    for (k, t) in periods.iter().enumerate() {
        let mut row = vec![buffer.format(*t).to_string()];
        row.extend(columns.iter().map(|(_, v)| buffer.format(v[k]).to_string()));
        w.write_record(&row)?;
    }
    w.flush().with_context(|| format!("cannot write {}", shown.display()))
}

/// Runs the command.
pub fn execute(args: &Args) -> anyhow::Result<()> {
    let periods = periods(args.periods.as_deref())?;
    match &args.site {
        Some(site) => site_form(args, site, periods),
        None => records_form(args, &periods),
    }
}

/// `rocking spectrum RECORD...`.
fn records_form(args: &Args, periods: &[f64]) -> anyhow::Result<()> {
    let damping = args.damping.unwrap_or(DEFAULT_DAMPING_PCT);
    rocking_codes::check_damping(damping).map_err(|e| anyhow::anyhow!("--damping: {}", reason(&e)))?;
    let g = DEFAULT_G;
    let csv = CsvOptions {
        units: args.units.unwrap_or_default(),
        dt: args.dt,
    };
    if let Some((i, j)) = same_record_twice(&args.records) {
        anyhow::bail!(
            "{} is given twice (as {} and {}): a spectrum has one column per file",
            args.records[j].display(),
            args.records[i].display(),
            args.records[j].display()
        );
    }
    let records: Vec<Record> = args
        .records
        .iter()
        .map(|p| read_record_with(p, &csv, g).map_err(|kind| anyhow::anyhow!("{kind}")))
        .collect::<anyhow::Result<_>>()?;
    let paths: Vec<String> = args.records.iter().map(|p| p.display().to_string()).collect();
    let names = record_names(&paths);
    // One record at a time, so that an error names its file.
    let spectra: Vec<Vec<f64>> = records
        .iter()
        .zip(&args.records)
        .map(|(record, path)| {
            record_spectra_in_g(std::slice::from_ref(record), periods, damping, g)
                .map(|mut one| one.remove(0))
                .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))
        })
        .collect::<anyhow::Result<_>>()?;

    let dir = args.out.clone().unwrap_or_else(|| Path::new("out").join("spectra"));
    let mut outputs = vec![dir.join(SPECTRA_CSV)];
    if args.plot {
        outputs.extend(["spectra.svg", "spectra.png"].iter().map(|f| dir.join(f)));
    }
    output::refuse_to_overwrite_inputs(&outputs, &args.records)?;
    let staging = output::Staging::new(&dir, &args.records)?;
    let columns: Vec<(String, Vec<f64>)> = names.iter().cloned().zip(spectra.iter().cloned()).collect();
    write_columns(&staging.path(SPECTRA_CSV), &dir.join(SPECTRA_CSV), periods, &columns)?;
    let mut lines = Vec::new();
    for ((name, record), psa) in names.iter().zip(&records).zip(&spectra) {
        let (k, peak) = psa.iter().enumerate().fold((0, 0.0f64), |best, (k, &v)| if v > best.1 { (k, v) } else { best });
        lines.push(format!(
            "{name}: PGA {} g, peak PSA {} g at T = {} s ({damping}% damping)",
            sig(record.peak().0 / g, 4),
            sig(peak, 4),
            sig(periods[k], 3)
        ));
    }
    if args.plot {
        let figure = SpectraFigure {
            title: "Response spectra of the records".into(),
            subtitle: format!("pseudo-acceleration, {damping}% damping, exact for the piecewise-linear record"),
            y_label: "PSA (g)".into(),
            curves: spectra
                .iter()
                .zip(&names)
                .enumerate()
                .map(|(k, (psa, name))| Curve {
                    label: Some(name.clone()),
                    ink: Ink::Series { index: k, of: spectra.len() },
                    width: 2,
                    dashed: false,
                    points: periods.iter().copied().zip(psa.iter().copied()).collect(),
                })
                .collect(),
            band: None,
            range: None,
        };
        crate::plot::spectra_figure(staging.folder(), "spectra", &figure).context("drawing the figures")?;
    }
    staging.commit()?;
    lines.push(format!(
        "wrote {SPECTRA_CSV}{} in {}",
        if args.plot { ", spectra.svg, spectra.png" } else { "" },
        dir.display()
    ));
    super::print(&(lines.join("\n") + "\n"))
}

/// `rocking spectrum --site ASSESS.toml`.
fn site_form(args: &Args, path: &Path, periods: Vec<f64>) -> anyhow::Result<()> {
    let text = std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    // The file's errors name the file, the key and the cause.
    let assessment = AssessmentFile::from_toml_str(&text, path)?;
    // With a [tower] the records are fitted as `rocking assess` fits them (in
    // the file's direction): over its range, stretched to the longest T_SLC of
    // the tower's mechanisms, on its periods unless --periods gives others.
    // Without one, over the code's range (0.15 s to 2 s).
    let (periods, range) = if assessment.scenario.contains_key("tower") {
        let input = rocking_assess::AssessmentInput::new(assessment.clone())?;
        let range = input.fitting_range(input.longest_t_slc()?);
        let periods = match &args.periods {
            Some(_) => periods,
            None => rocking_assess::set_periods(range.1).map_err(|e| anyhow::anyhow!("{}: assessment.period_range: {e}", path.display()))?,
        };
        (periods, range)
    } else {
        (periods, assessment.period_range.unwrap_or_else(|| default_period_range(None)))
    };
    let periods = periods.as_slice();
    let g = assessment.g;
    let site = &assessment.site;
    let code_columns = code_spectra_columns(site, periods, g).map_err(|e| anyhow::anyhow!("{}: site: {e}", path.display()))?;
    let states: Vec<LimitState> = site.spectra.iter().map(|(s, _)| *s).collect();
    let code_curves: Vec<Curve> = code_columns
        .iter()
        .filter(|c| c.kind == SpectrumKind::Acceleration)
        .map(|c| {
            let index = states.iter().position(|s| *s == c.limit_state).unwrap_or(0);
            let default = (c.damping_pct - DEFAULT_DAMPING_PCT).abs() < 1e-12;
            Curve {
                label: Some(match site.spectrum(c.limit_state) {
                    Some(s) if default => format!("{}, ag {} g, 5%", c.limit_state, sig(s.ag(), 3)),
                    _ => format!("{}, {}%", c.limit_state, sig(c.damping_pct, 3)),
                }),
                ink: Ink::Series { index, of: states.len() },
                width: 2,
                dashed: !default,
                points: periods.iter().copied().zip(c.values.iter().copied()).collect(),
            }
        })
        .collect();
    let mut columns: Vec<(String, Vec<f64>)> = code_columns.into_iter().map(|c| (c.name, c.values)).collect();
    let mut lines = vec![format!(
        "{}: {} spectra, soil {}, limit states {}",
        path.display(),
        site.code.as_str(),
        site.soil,
        site.spectra.iter().map(|(s, _)| s.as_str()).collect::<Vec<_>>().join(", ")
    )];

    // The record set, fitted to each dynamic limit state the site has.
    let records = assessment.read_records()?;
    let names = record_names(&records.iter().map(|(p, _)| p.clone()).collect::<Vec<_>>());
    let mut fits: Vec<(LimitState, FittedSet)> = Vec::new();
    if !records.is_empty() {
        let set: Vec<Record> = records.iter().map(|(_, r)| r.clone()).collect();
        let spectra = record_spectra_in_g(&set, periods, DEFAULT_DAMPING_PCT, g).map_err(|e| anyhow::anyhow!("{}: assessment.records: {e}", path.display()))?;
        for state in dynamic_limit_states(site.code) {
            let Some(spectrum) = site.spectrum(state) else { continue };
            let target: Vec<f64> = periods.iter().map(|&t| spectrum.se(t)).collect();
            let fitted = fit_record_set(periods, &spectra, &target, range).map_err(|e| anyhow::anyhow!("{}: assessment.records: {e}", path.display()))?;
            for (name, (psa, f)) in names.iter().zip(spectra.iter().zip(&fitted.scales)) {
                columns.push((format!("PSA_{state}_{name}_g"), psa.iter().map(|a| f * a).collect()));
            }
            columns.push((format!("PSA_{state}_mean_g"), fitted.mean.clone()));
            let c = fitted.compatibility;
            lines.push(format!(
                "{state}: {} records fitted over {}–{} s, scales {}; mean/target {}–{}: {}",
                set.len(),
                sig(range.0, 3),
                sig(range.1, 3),
                fitted.scales.iter().map(|f| sig(*f, 3)).collect::<Vec<_>>().join(", "),
                sig(c.least_ratio, 3),
                sig(c.greatest_ratio, 3),
                if c.holds {
                    "compatible (0.90–1.30)"
                } else {
                    "NOT compatible (0.90–1.30)"
                }
            ));
            fits.push((state, fitted));
        }
        if fits.first().is_some_and(|(_, f)| f.rule == SetRule::Largest) {
            eprintln!(
                "warning: {}: {} records: the checks will use the largest response, not the mean (7 records are needed for the mean)",
                path.display(),
                records.len()
            );
        }
    }

    let dir = args.out.clone().unwrap_or_else(|| super::run::default_out(path));
    let mut names_out = vec![SPECTRA_CSV.to_string()];
    if !fits.is_empty() {
        names_out.extend([FIT_CSV.to_string(), FIT_JSON.to_string()]);
    }
    if args.plot {
        names_out.extend(["code_spectra.svg".into(), "code_spectra.png".into()]);
        for (state, _) in &fits {
            names_out.extend([format!("fit_{state}.svg"), format!("fit_{state}.png")]);
        }
    }
    let outputs: Vec<PathBuf> = names_out.iter().map(|n| dir.join(n)).collect();
    let mut inputs = vec![path.to_path_buf()];
    inputs.extend(records.iter().map(|(p, _)| assessment.folder().join(p)));
    if let Some(grid) = site.source.grid_file() {
        inputs.push(grid.to_path_buf());
    }
    output::refuse_to_overwrite_inputs(&outputs, &inputs)?;
    let staging = output::Staging::new(&dir, &inputs)?;
    write_columns(&staging.path(SPECTRA_CSV), &dir.join(SPECTRA_CSV), periods, &columns)?;
    if !fits.is_empty() {
        let mut csv = String::from("limit_state,record,scale,pga_g\n");
        let mut json = serde_json::Map::new();
        for (state, fitted) in &fits {
            for ((name, (_, record)), f) in names.iter().zip(&records).zip(&fitted.scales) {
                let (scale, pga) = (
                    ryu::Buffer::new().format(*f).to_string(),
                    ryu::Buffer::new().format(f * record.peak().0 / g).to_string(),
                );
                csv.push_str(&csv_line([state.as_str(), name, &scale, &pga]));
                csv.push('\n');
            }
            let c = fitted.compatibility;
            json.insert(
                state.to_string(),
                serde_json::json!({
                    "period_range_s": [range.0, range.1],
                    "records": fitted.scales.len(),
                    "combination": match fitted.rule { SetRule::Mean => "mean", SetRule::Largest => "largest" },
                    "least_ratio": c.least_ratio,
                    "greatest_ratio": c.greatest_ratio,
                    "holds": c.holds,
                }),
            );
        }
        std::fs::write(staging.path(FIT_CSV), csv).with_context(|| format!("cannot write {}", dir.join(FIT_CSV).display()))?;
        let text = serde_json::to_string_pretty(&serde_json::Value::Object(json)).context("formatting fit.json")? + "\n";
        std::fs::write(staging.path(FIT_JSON), text).with_context(|| format!("cannot write {}", dir.join(FIT_JSON).display()))?;
    }
    if args.plot {
        let code = SpectraFigure {
            title: format!("Code spectra: {}", path.display()),
            subtitle: format!(
                "{} elastic spectra, soil {}; dashed: at the damping of the kinematic checks",
                site.code.as_str().to_uppercase(),
                site.soil
            ),
            y_label: "Se (g)".into(),
            curves: code_curves,
            band: None,
            range: None,
        };
        crate::plot::spectra_figure(staging.folder(), "code_spectra", &code).context("drawing the figures")?;
        for (state, fitted) in &fits {
            let Some(spectrum) = site.spectrum(*state) else { continue };
            let mut curves: Vec<Curve> = fitted
                .scales
                .iter()
                .zip(
                    columns
                        .iter()
                        .filter(|(n, _)| n.starts_with(&format!("PSA_{state}_")) && !n.ends_with("_mean_g")),
                )
                .map(|(_, (_, psa))| Curve {
                    label: None,
                    ink: Ink::Faint,
                    width: 1,
                    dashed: false,
                    points: periods.iter().copied().zip(psa.iter().copied()).collect(),
                })
                .collect();
            if let Some(first) = curves.first_mut() {
                first.label = Some(format!("the {} records, each scaled", fitted.scales.len()));
            }
            curves.push(Curve {
                label: Some(format!("{state} target, 5%")),
                ink: Ink::Target,
                width: 3,
                dashed: false,
                points: periods.iter().map(|&t| (t, spectrum.se(t))).collect(),
            });
            curves.push(Curve {
                label: Some("mean of the scaled records".into()),
                ink: Ink::Mean,
                width: 3,
                dashed: false,
                points: periods.iter().copied().zip(fitted.mean.iter().copied()).collect(),
            });
            let points: Vec<(f64, f64, f64)> = fitted
                .in_range
                .clone()
                .map(|k| (periods[k], 0.9 * spectrum.se(periods[k]), 1.3 * spectrum.se(periods[k])))
                .collect();
            let c = fitted.compatibility;
            let figure = SpectraFigure {
                title: format!("Record set fitted to {state}: {}", path.display()),
                subtitle: format!(
                    "mean/target {}–{} over {}–{} s: {}",
                    sig(c.least_ratio, 3),
                    sig(c.greatest_ratio, 3),
                    sig(range.0, 3),
                    sig(range.1, 3),
                    if c.holds { "compatible" } else { "not compatible" }
                ),
                y_label: "PSA, Se (g)".into(),
                curves,
                band: Some(Band {
                    label: "0.90–1.30 × target".into(),
                    points,
                }),
                range: Some(range),
            };
            crate::plot::spectra_figure(staging.folder(), &format!("fit_{state}"), &figure).context("drawing the figures")?;
        }
    }
    staging.commit()?;
    lines.push(format!("wrote {} in {}", names_out.join(", "), dir.display()));
    super::print(&(lines.join("\n") + "\n"))
}
