//! Figures of a run and of a sweep, each written as SVG and PNG
//! (docs/src/reference/commands.md, `--plot`), drawn with plotters and an embedded font.
//!
//! A run: `theta` (θ/α and a_g against time, the paper's Figure 7) and `slip`
//! (the building's slip and the top displacement). A sweep: `sweep_max_theta`
//! (max θ/α against the first swept key, one curve per value of the second,
//! the paper's Figure 6) and, for two numeric keys, `sweep_map` (a heat map).
//! A fragility study: `ida` (the response against the level, one line per
//! record) and `fragility` (observed fractions and fitted curves). A town's
//! inventory: `town_map` and `town_ranking`.

mod chart;
mod fragility;
mod ida;
mod labels;
mod legend;
mod raster;
mod risk;
mod scale;
mod slip;
mod spectra;
mod style;
mod sweep_curves;
mod sweep_map;
mod sweep_table;
mod theta;
mod timeline;
mod town;

pub use chart::{LineChart, Marker};
pub use legend::Shape;
use rocking_scenario::{Measure, Outcome, Stripe};
pub use spectra::{Band, Curve, Ink, SpectraFigure};
use std::path::{Path, PathBuf};
pub use style::{BLUE, GREEN, OVERTURN, VERMILION};
pub use sweep_table::SweepTable;

/// Draws a figure of spectra (log-log) into `dir/<stem>.svg` and `.png`, returning the files.
pub fn spectra_figure(dir: &Path, stem: &str, figure: &SpectraFigure) -> anyhow::Result<Vec<PathBuf>> {
    style::render(dir, stem, spectra::SIZE, figure)
}

/// A figure of spectra (log-log) as an SVG string, for a page.
pub fn spectra_svg(figure: &SpectraFigure) -> anyhow::Result<String> {
    style::render_svg(spectra::SIZE, figure)
}

/// The size (px) of a chart on linear axes.
pub const CHART_SIZE: (u32, u32) = chart::SIZE;
/// The size (px) of a figure of spectra.
pub const SPECTRA_SIZE: (u32, u32) = spectra::SIZE;

/// Draws a chart on linear axes into `dir/<stem>.svg` and `.png`, returning the files.
pub fn chart_figure(dir: &Path, stem: &str, chart: &LineChart) -> anyhow::Result<Vec<PathBuf>> {
    style::render(dir, stem, chart::SIZE, chart)
}

/// A chart on linear axes as an SVG string, for a page.
pub fn chart_svg(chart: &LineChart) -> anyhow::Result<String> {
    style::render_svg(chart::SIZE, chart)
}

/// The files `run_figures` writes.
pub const RUN_FILES: [&str; 4] = ["theta.svg", "theta.png", "slip.svg", "slip.png"];

/// Draws the figures of one run into `dir` (`theta.svg`/`.png`: θ/α and the
/// ground acceleration against time; `slip.svg`/`.png`: building slip and top
/// displacement against time), returning the files written.
pub fn run_figures(dir: &Path, outcome: &Outcome) -> anyhow::Result<Vec<PathBuf>> {
    let Some(history) = &outcome.history else {
        anyhow::bail!("the run kept no time history to draw");
    };
    let timeline = timeline::Timeline::of(outcome);
    let theta = theta::ThetaFigure {
        outcome,
        samples: &history.samples,
        timeline: &timeline,
    };
    let mut files = style::render(dir, "theta", theta::SIZE, &theta)?;
    let slip = slip::SlipFigure {
        outcome,
        samples: &history.samples,
        timeline: &timeline,
    };
    files.extend(style::render(dir, "slip", slip::SIZE, &slip)?);
    Ok(files)
}

/// Draws the figures of a sweep from its `sweep.csv` into `dir`: max θ/α
/// against the first axis with one curve per value of the second, and for two
/// numeric axes a heat map; `axis_keys` are the swept dotted keys in order.
#[cfg(test)]
pub fn sweep_figures(dir: &Path, title: &str, csv: &Path, axis_keys: &[String]) -> anyhow::Result<Vec<PathBuf>> {
    sweep_figures_of(dir, title, &sweep_table::SweepTable::read(csv, axis_keys)?)
}

/// Draws the figures of a sweep from its rows in memory (see [`sweep_figures`]).
pub fn sweep_figures_of(dir: &Path, title: &str, table: &SweepTable) -> anyhow::Result<Vec<PathBuf>> {
    let curves = sweep_curves::CurvesFigure { title, table };
    let mut files = style::render(dir, "sweep_max_theta", sweep_curves::SIZE, &curves)?;
    if let Some(map) = sweep_map::MapFigure::new(title, table) {
        files.extend(style::render(dir, "sweep_map", sweep_map::SIZE, &map)?);
    }
    Ok(files)
}

/// The figures `town_figures` writes.
pub const TOWN_FIGURES: [&str; 4] = ["town_map.svg", "town_map.png", "town_ranking.svg", "town_ranking.png"];

/// Draws the figures of a town's inventory into `dir`: `town_map` (the towers
/// at their place coloured by ζ_E) and `town_ranking` (the towers of least ζ_E
/// and their governing checks); `checks` are the checks' names in column order.
pub fn town_figures(dir: &Path, title: &str, towers: &[rocking_assess::Ranked], checks: &[String]) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = style::render(dir, "town_map", town::MAP_SIZE, &town::MapFigure { title, towers })?;
    let ranking = town::RankingFigure { title, towers, checks };
    files.extend(style::render(dir, "town_ranking", town::RankingFigure::size(towers), &ranking)?);
    Ok(files)
}

/// The town's map and ranking as SVG strings with their sizes, for its page.
pub fn town_svgs(title: &str, towers: &[rocking_assess::Ranked], checks: &[String]) -> anyhow::Result<[(String, (u32, u32)); 2]> {
    let map = style::render_svg(town::MAP_SIZE, &town::MapFigure { title, towers })?;
    let size = town::RankingFigure::size(towers);
    let ranking = style::render_svg(size, &town::RankingFigure { title, towers, checks })?;
    Ok([(map, town::MAP_SIZE), (ranking, size)])
}

/// One record's line of the IDA figure: `(level, value, overturned)` per case in level order.
#[derive(Debug, Clone)]
pub struct IdaCurve {
    /// The record's path as `stripes.csv` names it.
    pub record: String,
    /// Per case: the level, the response field (`None` for a failed case), whether it overturned.
    pub points: Vec<(f64, Option<f64>, bool)>,
}

/// What the figures of a fragility study show.
#[derive(Debug, Clone)]
pub struct StudyFigures {
    /// The study's name.
    pub title: String,
    /// The intensity measure (the x axis).
    pub measure: Measure,
    /// The field of the first limit state (the y axis of the IDA figure).
    pub ida_field: String,
    /// Its threshold, if numeric.
    pub ida_threshold: Option<f64>,
    /// One line per record.
    pub ida: Vec<IdaCurve>,
    /// One entry per limit state.
    pub states: Vec<StateCurve>,
    /// The site's hazard curve, when the study names a site (the risk figure).
    pub site: Option<rocking_codes::HazardCurve>,
}

/// A limit state's points and curve in the fragility figure.
#[derive(Debug, Clone)]
pub struct StateCurve {
    /// The limit state's name.
    pub name: String,
    /// Its cases and exceedances per level.
    pub stripes: Vec<Stripe>,
    /// The fitted `(median, β)`, if a fit exists.
    pub fit: Option<(f64, f64)>,
}

impl StudyFigures {
    /// The label of the x axis: the measure and its unit.
    fn measure_label(&self) -> String {
        match self.measure {
            Measure::Pga => "PGA (g)".into(),
            Measure::Pgv => "PGV (m/s)".into(),
            Measure::PgaRatio => "PGA / (g tan α) (–)".into(),
        }
    }
}

/// Draws the figures of a fragility study into `dir`: `ida` and `fragility`,
/// and `risk` with a site (SVG and PNG).
pub fn study_figures(dir: &Path, figures: &StudyFigures) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = style::render(dir, "ida", ida::SIZE, &ida::IdaFigure(figures))?;
    files.extend(style::render(dir, "fragility", fragility::SIZE, &fragility::FragilityFigure(figures))?);
    if let Some(curve) = &figures.site {
        files.extend(style::render(dir, "risk", risk::SIZE, &risk::RiskFigure { study: figures, curve })?);
    }
    Ok(files)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use rocking::Event;
    use rocking_scenario::{RunOptions, Scenario};

    /// A tower on a church, 1 s of 0.6 g at 5 Hz (as the CLI tests' scenario).
    pub const SCENARIO: &str = concat!(
        "name = \"small\"\n",
        include_str!("../../../rocking-scenario/tests/data/church.toml"),
        r#"
[ground]
type = "harmonic"
amplitude = 0.6
frequency = 5.0

[simulation]
duration = 1.0
output_dt = 0.01
"#
    );

    /// The outcome of `text`, run with history and events.
    pub fn run(text: &str) -> Outcome {
        let outcome = Scenario::from_toml_str(text, Path::new("t.toml"))
            .and_then(|s| s.build())
            .and_then(|c| c.run(RunOptions::ALL));
        match outcome {
            Ok(o) => o,
            Err(e) => panic!("the test scenario does not run: {e}"),
        }
    }

    /// The outcome of [`SCENARIO`] with `events` instead of its own and ending at `end`.
    pub fn outcome_with(events: &[Event], end: f64) -> Outcome {
        let mut outcome = run(SCENARIO);
        outcome.events = events.to_vec();
        outcome.summary.end_time = end;
        if let Some(h) = &mut outcome.history {
            h.samples.retain(|s| s.t <= end);
        }
        outcome
    }

    fn draws(text: &str) {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let files = run_figures(dir.path(), &run(text)).unwrap_or_else(|e| panic!("{e:#}"));
        assert_eq!(files.len(), 4);
        for f in files {
            let size = std::fs::metadata(&f).map(|m| m.len()).unwrap_or(0);
            assert!(size > 1000, "{} has {size} bytes", f.display());
        }
    }

    /// Two axes, an overturned case and a failed one (its summary fields empty).
    pub const SWEEP_CSV: &str = "\
ground.frequency,ground.amplitude,alpha_rad,max_theta_over_alpha,max_abs_slip_m,overturned,error
3,0.5,0.32,0.40,0.0,false,
4,0.5,0.32,0.31,0.0,false,
5,0.5,0.32,0.22,0.0,false,
3,0.9,0.32,4.88,0.2,true,
4,0.9,0.32,,,,\"building.mu_static: must be a finite number > 0, got -1\"
5,0.9,0.32,0.52,0.1,false,
";

    #[test]
    fn sweep_figures_from_a_small_csv() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        let csv = dir.path().join("sweep.csv");
        std::fs::write(&csv, SWEEP_CSV)?;
        let axes = ["ground.frequency", "ground.amplitude"].map(String::from);
        let files = sweep_figures(dir.path(), "a small sweep", &csv, &axes)?;
        let names: Vec<String> = files.iter().filter_map(|f| f.file_name()).map(|n| n.to_string_lossy().into_owned()).collect();
        assert_eq!(names, ["sweep_max_theta.svg", "sweep_max_theta.png", "sweep_map.svg", "sweep_map.png"]);
        for f in &files {
            let bytes = std::fs::read(f)?;
            if f.extension().is_some_and(|e| e == "png") {
                assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "{} is not a PNG", f.display());
            } else {
                let svg = String::from_utf8(bytes)?;
                assert!(svg.contains("a small sweep") && svg.contains("max θ/α"), "{}", f.display());
                assert!(svg.contains("ground frequency (Hz)") && svg.contains("ground amplitude (g)"), "{}", f.display());
            }
        }
        let curves = std::fs::read_to_string(&files[0])?;
        assert!(
            curves.contains("A = 0.5 g") && curves.contains("A = 0.9 g"),
            "one curve per amplitude, named in the legend"
        );
        assert!(curves.contains("overturned") && curves.contains("1 failed case left out"));
        let map = std::fs::read_to_string(&files[2])?;
        assert!(map.contains("overturned") && map.contains("failed"));

        // One axis: one curve and no map; a text axis: no map either.
        let one = sweep_figures(dir.path(), "one axis", &csv, &axes[..1])?;
        assert_eq!(one.len(), 2);
        let text = dir.path().join("text.csv");
        std::fs::write(
            &text,
            "building.normal_force,ground.amplitude,max_theta_over_alpha,overturned,error\nconstant,0.5,0.4,false,\ndynamic,0.5,0.5,false,\n",
        )?;
        let keys = ["building.normal_force", "ground.amplitude"].map(String::from);
        assert_eq!(sweep_figures(dir.path(), "text axis", &text, &keys)?.len(), 2);
        // No rows at all, or every case failed: empty figures, no error.
        let empty = dir.path().join("empty.csv");
        std::fs::write(&empty, SWEEP_CSV.lines().next().unwrap_or_default())?;
        assert_eq!(sweep_figures(dir.path(), "empty", &empty, &axes)?.len(), 4);
        let failed = dir.path().join("failed.csv");
        std::fs::write(
            &failed,
            "ground.frequency,ground.amplitude,max_theta_over_alpha,overturned,error\n3,0.5,,,boom\n",
        )?;
        assert_eq!(sweep_figures(dir.path(), "failed", &failed, &axes)?.len(), 4);
        Ok(())
    }

    #[test]
    fn a_sweep_csv_without_its_columns_is_an_error() -> anyhow::Result<()> {
        let dir = tempfile::tempdir()?;
        let csv = dir.path().join("sweep.csv");
        std::fs::write(&csv, SWEEP_CSV)?;
        let e = sweep_figures(dir.path(), "x", &csv, &["tower.height".to_string()]).map(|_| ());
        assert!(format!("{e:?}").contains("no column tower.height"), "{e:?}");
        let e = sweep_figures(dir.path(), "x", &dir.path().join("missing.csv"), &["ground.frequency".to_string()]).map(|_| ());
        assert!(format!("{e:?}").contains("cannot read"), "{e:?}");
        Ok(())
    }

    #[test]
    fn edge_cases_draw_without_failing() {
        // Fixed base, no slip.
        let fixed = SCENARIO.replace("[building]\nmass = 2.0e6\nmu_static = 1.25\nmu_kinetic = 1.0\n", "");
        draws(&fixed);
        // A building alone.
        let alone = SCENARIO.replace("[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n", "");
        draws(&alone);
        // The tower overturns (a long strong pulse), the church slides.
        draws(&SCENARIO.replace(
            "type = \"harmonic\"\namplitude = 0.6\nfrequency = 5.0",
            "type = \"sine-pulse\"\namplitude = 1.4\nfrequency = 0.5",
        ));
        // Nothing moves; a run shorter than one output step.
        draws(
            &SCENARIO
                .replace("amplitude = 0.6", "amplitude = 0.1")
                .replace("duration = 1.0", "duration = 0.004"),
        );
        // No ground motion at all.
        draws(&SCENARIO.replace("type = \"harmonic\"\namplitude = 0.6\nfrequency = 5.0", "type = \"none\""));
    }
}
