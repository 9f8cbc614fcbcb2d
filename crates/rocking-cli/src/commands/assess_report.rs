//! `report.html` of `rocking assess`: one self-contained page (no link, no
//! script; figures inline as SVG) that an engineer can attach to a report and
//! a reviewer can follow: the tower and its capacity, the site, each check
//! with its formula, numbers and verdict, the capacity curve in the ADRS plane
//! with the demand points, and for the dynamic checks the fitted spectra, the
//! responses record by record and the response against λ. Printed to A4, no
//! figure is cut (each figure avoids a page break inside it).

use crate::format::sig;
use crate::plot::{chart_svg, spectra_svg, Band, Curve, Ink, LineChart, Marker, Shape, SpectraFigure, BLUE, GREEN, OVERTURN, VERMILION};
use rocking_assess::{
    capacity_json, d0_meaning, linear_kinematic_demand, soil_factor, Assessment, AssessmentInput, Capacity, Check, DynamicCheck, MechanismView, Method,
    RecordSet, Role, CAPACITY_QUANTITIES,
};
use rocking_codes::{CodeSpectrum, LimitState, COMPATIBILITY_LOWER, COMPATIBILITY_UPPER};
use std::fmt::Write;
use std::path::Path;

/// Escapes text for HTML.
pub(crate) fn esc(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The pages' style sheet (A4 when printed).
pub(crate) const STYLE: &str = "body{font-family:'DejaVu Sans',Arial,sans-serif;max-width:190mm;margin:1em auto;color:#222;font-size:10.5pt;line-height:1.4}\
h1{font-size:17pt}h2{font-size:13pt;border-bottom:1px solid #999;margin-top:1.4em}h3{font-size:11pt}\
table{border-collapse:collapse;margin:.5em 0;break-inside:avoid}td,th{border:1px solid #bbb;padding:2px 6px;text-align:left;vertical-align:top}\
th{background:#eee}td.n{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}\
.wide{overflow-x:auto;max-width:100%}table.records{font-size:8.5pt}table.records td,table.records th{padding:1px 4px}table.records td:first-child{overflow-wrap:anywhere}@media print{.wide{overflow:visible}table{font-size:8.5pt}}.holds{color:#08693f;font-weight:bold}.fails{color:#b00020;font-weight:bold}\
figure{margin:.8em 0;break-inside:avoid;page-break-inside:avoid}figure svg{width:100%;height:auto;display:block}figcaption{font-size:9.5pt;color:#444}\
code{font-size:9.5pt}.note{font-size:9.5pt;color:#444}@page{size:A4;margin:14mm}\
#fingerprints{font-size:8.5pt;width:100%;table-layout:fixed}#fingerprints td{overflow-wrap:anywhere}";

/// The SVG of a figure with a viewBox, so that it scales to the page's width.
pub(crate) fn scalable(svg: String, size: (u32, u32)) -> String {
    if svg.contains("viewBox") {
        svg
    } else {
        svg.replacen("<svg ", &format!("<svg viewBox=\"0 0 {} {}\" ", size.0, size.1), 1)
    }
}

/// A figure of the report, kept to be written as files too (`rocking assess --plot`).
pub enum ReportFigure {
    /// A chart on linear axes (the ADRS plane, the λ scans).
    Chart(LineChart),
    /// Spectra on log axes (a record set fitted to a limit state).
    Spectra(SpectraFigure),
}

/// The report's figures in the order of the page, each with its file stem
/// (`report_adrs`, `report_set_SLV`, `report_lambda_SLV_belfry`).
#[derive(Default)]
pub struct Figures(pub Vec<(String, ReportFigure)>);

impl Figures {
    /// The figure's SVG for the page (scalable), the figure kept under `stem`.
    fn inline(&mut self, stem: String, figure: ReportFigure) -> anyhow::Result<String> {
        let svg = match &figure {
            ReportFigure::Chart(chart) => scalable(chart_svg(chart)?, crate::plot::CHART_SIZE),
            ReportFigure::Spectra(spectra) => scalable(spectra_svg(spectra)?, crate::plot::SPECTRA_SIZE),
        };
        self.0.push((stem, figure));
        Ok(svg)
    }

    /// Writes every figure into `dir` as `<stem>.svg` and `<stem>.png`, returning their file names.
    pub fn write(&self, dir: &Path) -> anyhow::Result<Vec<String>> {
        let mut names = Vec::new();
        for (stem, figure) in &self.0 {
            match figure {
                ReportFigure::Chart(chart) => crate::plot::chart_figure(dir, stem, chart)?,
                ReportFigure::Spectra(spectra) => crate::plot::spectra_figure(dir, stem, spectra)?,
            };
            names.extend([format!("{stem}.svg"), format!("{stem}.png")]);
        }
        Ok(names)
    }
}

/// A name's part of a figure's file stem: ASCII letters, digits, `-` and `_` kept, any other character `_`.
fn stem_part(name: &str) -> String {
    name.chars()
        .map(|c| if c.is_ascii_alphanumeric() || c == '-' || c == '_' { c } else { '_' })
        .collect()
}

/// The file name of a record's path (the whole path when it has none), so
/// that a table of records fits the page's column; the paths are listed once.
fn file_name(path: &str) -> &str {
    std::path::Path::new(path).file_name().and_then(|n| n.to_str()).unwrap_or(path)
}

fn verdict(c: &Check) -> String {
    if c.holds {
        "<span class=\"holds\">holds</span>".into()
    } else {
        "<span class=\"fails\">fails</span>".into()
    }
}

/// Which method carries the verdict of each ultimate limit state, and why the others are information.
fn verdict_basis(done: &Assessment, input: &AssessmentInput) -> String {
    let q = input.file.q;
    let tower = &done.mechanisms()[0];
    let carried: Vec<String> = tower
        .verdicts(done.verdict_method)
        .iter()
        .map(|v| format!("{} by the {} check", v.check.limit_state, v.check.method.text(q).name))
        .collect();
    let why = match done.verdict_method {
        Some(m) => format!(
            "assessment.verdict_method names the {} check; a limit state without it takes the most refined method computed",
            m.text(q).name
        ),
        None => "the most refined method computed carries it (non-linear dynamic, else non-linear kinematic, else linear kinematic; assessment.verdict_method may name another)".to_string(),
    };
    format!(
        "The verdict is carried per limit state by one method: {} ({why}). The Circolare 2019 offers the linear and the non-linear analyses as alternatives for the ultimate limit states (§C8.7.1.2.1.7–C8.7.1.2.1.9), not as checks to be met together: the other checks of a limit state are computed and shown as information. The verdict is the worse of the limit states{}; the damage state's activation is reported beside it, not mixed into it.",
        carried.join(", "),
        if done.mechanisms().len() > 1 { " over every mechanism" } else { "" }
    )
}

fn check_row(out: &mut String, c: &Check, q: f64) {
    let bound = if c.ag_capacity.is_lower_bound() { "≥ " } else { "" };
    let text = c.method.text_at(q, c.level, LimitState::EC8.contains(&c.limit_state));
    let _ = writeln!(
        out,
        "<tr><td>{}</td><td>{}</td><td>{}</td><td class=\"n\">{} {}</td><td class=\"n\">{} {}</td><td class=\"n\">{}</td><td class=\"n\">{bound}{}</td><td class=\"n\">{bound}{}</td><td>{}</td></tr>",
        c.limit_state,
        text.name,
        text.formula_html,
        sig(c.demand, 4),
        c.unit.as_str().replace("m/s2", "m/s²"),
        sig(c.capacity, 4),
        c.unit.as_str().replace("m/s2", "m/s²"),
        sig(c.ag, 4),
        sig(c.ag_capacity.value(), 4),
        sig(c.zeta_e, 3),
        verdict(c)
    );
}

/// The capacity curve in the ADRS plane with the ultimate displacements and the demands.
///
/// Each kind of point has its own look: the colour is the limit state's (blue
/// the life-safety one, vermilion the collapse one), the shape what the point
/// is (a square the ultimate displacement, a triangle the non-linear kinematic
/// demand that the capacity meets, a cross a demand beyond it).
fn adrs_figure(figs: &mut Figures, stem: String, capacity: &Capacity, checks: &[Check], life_safety: LimitState, of: &str) -> anyhow::Result<String> {
    let points = capacity.curve_points(201);
    let mut markers = vec![
        Marker {
            label: format!("ultimate d_SLV = 0.4 d0 = {} m", sig(capacity.d_slv, 3)),
            at: (capacity.d_slv, capacity.acceleration_at(capacity.d_slv)),
            shape: Shape::Square,
            color: BLUE,
        },
        Marker {
            label: format!("ultimate d_SLC = 0.6 d0 = {} m", sig(capacity.d_slc, 3)),
            at: (capacity.d_slc, capacity.acceleration_at(capacity.d_slc)),
            shape: Shape::Square,
            color: VERMILION,
        },
    ];
    for c in checks.iter().filter(|c| c.method == Method::NonlinearKinematic) {
        markers.push(Marker {
            label: format!(
                "{} non-linear demand {} m ({})",
                c.limit_state,
                sig(c.demand, 3),
                if c.holds { "holds" } else { "fails" }
            ),
            at: (c.demand, capacity.acceleration_at(c.demand.min(capacity.d0))),
            shape: if c.holds { Shape::Triangle } else { Shape::Cross },
            color: if c.limit_state == life_safety { BLUE } else { VERMILION },
        });
    }
    let chart = LineChart {
        title: format!("Capacity curve in the ADRS plane{of}"),
        subtitle: format!("{} curve, FC = {}, e* = 1", capacity.curve, capacity.confidence_factor),
        x_label: "spectral displacement d* (m)".into(),
        y_label: "spectral acceleration a* (m/s²)".into(),
        curves: vec![Curve {
            label: Some("capacity a*(d*)".into()),
            ink: Ink::Mean,
            width: 3,
            dashed: false,
            points,
        }],
        markers,
    };
    figs.inline(stem, ReportFigure::Chart(chart))
}

fn spectra_figure(figs: &mut Figures, set: &RecordSet, d: &DynamicCheck) -> anyhow::Result<String> {
    let (a, b) = set.range;
    let mut curves: Vec<Curve> = set
        .records
        .iter()
        .zip(&d.fitted.scales)
        .enumerate()
        .map(|(i, (r, s))| Curve {
            label: (i == 0).then(|| format!("the {} records, each scaled", set.records.len())),
            ink: Ink::Faint,
            width: 1,
            dashed: false,
            points: set.periods.iter().zip(&r.psa_g).map(|(t, p)| (*t, s * p)).collect(),
        })
        .collect();
    curves.push(Curve {
        label: Some("mean of the scaled set".into()),
        ink: Ink::Mean,
        width: 3,
        dashed: false,
        points: set.periods.iter().copied().zip(d.fitted.mean.iter().copied()).collect(),
    });
    curves.push(Curve {
        label: Some(format!("{} code spectrum, 5%", d.limit_state)),
        ink: Ink::Target,
        width: 3,
        dashed: true,
        points: set.periods.iter().copied().zip(d.target_g.iter().copied()).collect(),
    });
    curves.extend(super::assess_floor::floor_curves(set, d));
    let band = Band {
        label: format!("{COMPATIBILITY_LOWER}–{COMPATIBILITY_UPPER} × the code spectrum"),
        points: set
            .periods
            .iter()
            .zip(&d.target_g)
            .filter(|(t, _)| **t >= a && **t <= b)
            .map(|(t, s)| (*t, COMPATIBILITY_LOWER * s, COMPATIBILITY_UPPER * s))
            .collect(),
    };
    let figure = SpectraFigure {
        title: format!("Record set fitted to {}", d.limit_state),
        subtitle: format!("pseudo-acceleration at 5% damping; fitted over {}–{} s", sig(a, 3), sig(b, 3)),
        y_label: "PSA, Se (g)".into(),
        curves,
        band: Some(band),
        range: Some((a, b)),
    };
    figs.inline(format!("report_set_{}", d.limit_state), ReportFigure::Spectra(figure))
}

/// Why the check fails at the scan's point `lambda`: the records that reach
/// d0 there, by their files' names (each alone fails the check), else the
/// set's combined response beyond d_LS, else a record that did not run.
fn failure_reason(d: &DynamicCheck, set: &RecordSet, lambda: f64, d_ls: f64, d0: f64) -> String {
    let Some(p) = d.scan.iter().find(|p| (p.lambda - lambda).abs() < 1e-12) else {
        return String::new();
    };
    let names: Vec<&str> = p
        .reaching_d0(d0)
        .iter()
        .filter_map(|&i| set.records.get(i))
        .map(|r| file_name(&r.path))
        .collect();
    match names.as_slice() {
        [] if !p.complete => ": a record did not run".into(),
        [] => format!(
            ": the {} response {} m is beyond d_{} = {} m",
            match d.fitted.rule {
                rocking_codes::SetRule::Mean => "mean",
                rocking_codes::SetRule::Largest => "largest",
            },
            sig(p.combined, 3),
            d.limit_state,
            sig(d_ls, 3)
        ),
        [one] => format!(": {one} reaches d0"),
        [a, b] => format!(": {a} and {b} reach d0"),
        [a, b, rest @ ..] => format!(": {a}, {b} and {} more reach d0", rest.len()),
    }
}

fn lambda_figure(figs: &mut Figures, d: &DynamicCheck, set: &RecordSet, d_ls: f64, d0: f64, name: &str) -> anyhow::Result<String> {
    let mut scan: Vec<(f64, f64)> = d.scan.iter().map(|p| (p.lambda, p.combined)).collect();
    scan.sort_by(|x, y| x.0.total_cmp(&y.0));
    let top = scan.last().map_or(1.0, |p| p.0);
    let mut markers = Vec::new();
    if let Some((lo, hi)) = d.bracket {
        let at = |l: f64| d.scan.iter().find(|p| (p.lambda - l).abs() < 1e-12).map_or(d_ls, |p| p.combined);
        markers.push(Marker {
            label: format!("holds at λ = {}", sig(lo, 4)),
            at: (lo, at(lo)),
            shape: Shape::Circle,
            color: GREEN,
        });
        markers.push(Marker {
            label: format!("fails at λ = {}{}", sig(hi, 4), failure_reason(d, set, hi, d_ls, d0)),
            at: (hi, at(hi)),
            shape: Shape::Cross,
            color: OVERTURN,
        });
    }
    let chart = LineChart {
        title: if name.is_empty() {
            format!("{}: the set's response against λ", d.limit_state)
        } else {
            format!("{}, {name}: the set's response against λ", d.limit_state)
        },
        subtitle: "every record at λ times its fitted scale; overturning counted as d0".into(),
        x_label: "λ (multiplier of the fitted scales)".into(),
        y_label: "response d* (m)".into(),
        curves: vec![
            Curve {
                label: Some(match d.fitted.rule {
                    rocking_codes::SetRule::Mean => "mean response of the set".into(),
                    rocking_codes::SetRule::Largest => "largest response of the set".into(),
                }),
                ink: Ink::Mean,
                width: 2,
                dashed: false,
                points: scan,
            },
            Curve {
                label: Some(format!("d_{} = {} m", d.limit_state, sig(d_ls, 3))),
                ink: Ink::Target,
                width: 2,
                dashed: true,
                points: vec![(0.0, d_ls), (top, d_ls)],
            },
            Curve {
                label: Some(format!("d0 = {} m", sig(d0, 3))),
                ink: Ink::Series { index: 2, of: 7 },
                width: 1,
                dashed: true,
                points: vec![(0.0, d0), (top, d0)],
            },
        ],
        markers,
    };
    let stem = if name.is_empty() {
        format!("report_lambda_{}", d.limit_state)
    } else {
        format!("report_lambda_{}_{}", d.limit_state, stem_part(name))
    };
    figs.inline(stem, ReportFigure::Chart(chart))
}

fn site_rows(out: &mut String, input: &AssessmentInput) {
    let ntc = input.site.is_ntc();
    if ntc {
        let _ = writeln!(out, "<table><tr><th>limit state</th><th>a<sub>g</sub> (g)</th><th>F<sub>0</sub></th><th>T<sub>C</sub>* (s)</th><th>S<sub>S</sub></th><th>S<sub>T</sub></th><th>S</th><th>C<sub>C</sub></th><th>T<sub>B</sub> (s)</th><th>T<sub>C</sub> (s)</th><th>T<sub>D</sub> (s)</th></tr>");
    } else {
        let _ = writeln!(out, "<table><tr><th>limit state</th><th>a<sub>g</sub> (g)</th><th>S</th><th>T<sub>B</sub> (s)</th><th>T<sub>C</sub> (s)</th><th>T<sub>D</sub> (s)</th></tr>");
    }
    for role in Role::ALL {
        let n = |x: f64| format!("<td class=\"n\">{}</td>", sig(x, 4));
        let cells = match input.site.spectrum(role) {
            CodeSpectrum::Ntc(s) => [
                s.site().ag,
                s.site().f0,
                s.site().tc_star,
                s.ss(),
                s.st(),
                s.s(),
                s.cc(),
                s.tb(),
                s.tc(),
                s.td(),
            ]
            .map(n)
            .join(""),
            CodeSpectrum::Ec8(s) => {
                let p = s.parameters();
                [s.ag(), p.s, p.tb, p.tc, p.td].map(n).join("")
            }
        };
        let _ = writeln!(out, "<tr><td>{}</td>{cells}</tr>", input.site.limit_state(role));
    }
    let _ = writeln!(out, "</table>");
}

/// Where the site's parameters come from: the file's tables, or the grid
/// (official or the user's file; the site, the four nodes of its cell and
/// their distances) or the island group, with `VN`, `CU` and each limit
/// state's return period.
fn site_source(input: &AssessmentInput) -> String {
    use rocking_scenario::SiteSource;
    let periods = |nominal_life: f64, use_coefficient: f64| -> String {
        let states: Vec<String> = Role::ALL
            .iter()
            .filter_map(|&role| {
                let state = input.site.limit_state(role);
                let p = state.probability_of_exceedance()?;
                Some(format!(
                    "{} years at {state} (P<sub>VR</sub> = {}%)",
                    sig(rocking_codes::return_period(nominal_life, use_coefficient, p), 4),
                    sig(100.0 * p, 2)
                ))
            })
            .collect();
        format!(
            "V<sub>N</sub> = {} years, C<sub>U</sub> = {}: V<sub>R</sub> = {} years and T<sub>R</sub> = −V<sub>R</sub> / ln(1 − P<sub>VR</sub>) (NTC 2018 §3.2.1) = {}.",
            sig(nominal_life, 4),
            sig(use_coefficient, 4),
            sig(nominal_life * use_coefficient, 4),
            states.join(", ")
        )
    };
    match &input.file.site.source {
        SiteSource::Tables => "The site parameters of each limit state as the assessment file gives them.".to_string(),
        SiteSource::Grid {
            path,
            lon,
            lat,
            nominal_life,
            use_coefficient,
        } => {
            let read;
            let (grid, named) = match path {
                None => (
                    Some(rocking_codes::HazardGrid::ntc2018()),
                    "the official hazard grid of NTC 2018 (Tabella 1 of Allegato B to the D.M. 14 gennaio 2008, kept by the D.M. 17 gennaio 2018)".to_string(),
                ),
                Some(file) => {
                    read = std::fs::read_to_string(file).ok().and_then(|t| rocking_codes::HazardGrid::parse(&t).ok());
                    (read.as_ref(), format!("the hazard grid of the file {}", esc(&file.display().to_string())))
                }
            };
            let nodes = grid
                .and_then(|g| g.cell_nodes(*lon, *lat).ok())
                .map(|cell| {
                    let each: Vec<String> = cell
                        .iter()
                        .map(|(n, d)| match &n.id {
                            Some(id) => format!("{} ({} km)", esc(id), sig(*d, 3)),
                            None => format!("({}, {}) ({} km)", n.lon, n.lat, sig(*d, 3)),
                        })
                        .collect();
                    format!(" over the four nodes of the cell that holds the site, {},", each.join(", "))
                })
                .unwrap_or_default();
            format!(
                "The site parameters from {named} at lon {lon}, lat {lat}, interpolated as its Allegato A says: each the mean{nodes} weighted by the inverse of the distances, at the grid's return periods, then log-log in the return period. {}",
                periods(*nominal_life, *use_coefficient)
            )
        }
        SiteSource::Island {
            group,
            nominal_life,
            use_coefficient,
        } => format!(
            "The site parameters of the island group {group} ({}) in Tabella 2 of Allegato B to the D.M. 14 gennaio 2008 (kept by the NTC 2018), log-log in the return period (Allegato A). {}",
            group.places(),
            periods(*nominal_life, *use_coefficient)
        ),
    }
}

/// The table of a capacity and its curve's formula; `block` names what the mechanism turns (`the tower`, `the belfry`).
fn capacity_table(out: &mut String, capacity: &Capacity, block: &str) {
    let b = capacity.radius * capacity.alpha.sin();
    let h = capacity.radius * capacity.alpha.cos();
    let _ = writeln!(out, "<table><tr><th>quantity</th><th>meaning</th><th>value</th></tr>");
    let _ = writeln!(
        out,
        "<tr><td>b, h</td><td>corner to centre of mass, horizontal and vertical</td><td class=\"n\">{} m, {} m</td></tr>",
        sig(b, 4),
        sig(h, 4)
    );
    let values = capacity_json(capacity);
    for q in CAPACITY_QUANTITIES {
        let value = values[q.key].as_f64().map_or_else(String::new, |v| sig(v, 4));
        let unit = if q.unit.is_empty() { String::new() } else { format!(" {}", q.unit) };
        let meaning = if q.key == "d0_m" { esc(&d0_meaning(block)) } else { q.meaning.to_string() };
        let _ = writeln!(out, "<tr><td>{}</td><td>{meaning}</td><td class=\"n\">{value}{unit}</td></tr>", q.symbol_html);
    }
    let _ = writeln!(out, "</table>");
    let _ = writeln!(
        out,
        "<p class=\"note\">Capacity curve: {}.</p>",
        match capacity.curve {
            rocking_assess::CurveKind::Linear => "linear, a*(d) = a<sub>0</sub>* (1 − d/d<sub>0</sub>)",
            rocking_assess::CurveKind::Exact => "exact, a*(θ) = g tan(α − θ)/FC, d*(θ) = R (sin α − sin(α − θ))",
        }
    );
}

/// The note under a mechanism's checks on its linear kinematic check, with
/// its own a0* (`of`: ` of the belfry` in a stacked report, else empty).
fn linear_note(out: &mut String, input: &AssessmentInput, capacity: &Capacity, of: &str) {
    let life_safety = input.site.spectrum(Role::LifeSafety);
    let _ = writeln!(
        out,
        "<p class=\"note\">The linear kinematic check's capacity is q times the activation's, both in g (§C8.7.1.2.1.7). Written as the 2009 Circolare wrote it, with the {} spectrum's own soil factor, it reads a<sub>g</sub> S / q = {} m/s² against a<sub>0</sub>*{} = {} m/s² at the site's a<sub>g</sub> = {} g (S = {}); the two differ where S there differs from S at activation (NTC subsoils B–E, where S moves with a<sub>g</sub> and F<sub>0</sub>). The 2019 text's eq. C8.7.1.9 is the check of elements free to vibrate (parapets, pinnacles), not used here.</p>",
        input.site.limit_state(Role::LifeSafety),
        sig(linear_kinematic_demand(&life_safety, input.file.q, capacity.g), 4),
        esc(of),
        sig(capacity.a0_star, 4),
        sig(life_safety.ag(), 4),
        sig(soil_factor(&life_safety), 4)
    );
}

/// The table of a mechanism's checks.
fn checks_table(out: &mut String, m: &MechanismView<'_>, q: f64) {
    let _ = writeln!(out, "<table><tr><th>LS</th><th>method</th><th>stops holding when</th><th>demand at a<sub>g</sub></th><th>capacity</th><th>a<sub>g</sub> (g)</th><th>a<sub>g,capacity</sub> (g)</th><th>ζ<sub>E</sub></th><th>verdict</th></tr>");
    for c in &m.completed() {
        check_row(out, c, q);
    }
    for c in m.dynamic.iter().filter(|c| c.check.is_none()) {
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td>{}</td><td colspan=\"7\" class=\"fails\">could not be completed: {}</td></tr>",
            c.limit_state,
            Method::NonlinearDynamic.text(q).name,
            esc(c.error.as_deref().unwrap_or("a record failed"))
        );
    }
    let _ = writeln!(out, "</table>");
}

/// The report's warning when a run of the dynamic checks of a stack broke the
/// model's assumption that a seated block stays seated through an impact
/// elsewhere (its seat impulse ratio above 1, docs/src/model.md): how many
/// runs, and the largest ratio with its record and λ. `None` when none did.
fn seat_impulse_warning(done: &Assessment) -> Option<String> {
    let set = done.set.as_ref()?;
    let mut runs = 0;
    let mut largest: Option<(f64, &str, f64)> = None;
    for check in &done.dynamic {
        for point in std::iter::once(&check.at_one).chain(&check.scan) {
            for (response, record) in point.responses.iter().zip(&set.records) {
                let Some(ratio) = response.as_ref().ok().and_then(|r| r.max_seat_impulse_ratio) else {
                    continue;
                };
                if ratio > 1.0 {
                    runs += 1;
                    if largest.is_none_or(|(r, _, _)| ratio > r) {
                        largest = Some((ratio, record.name.as_str(), point.lambda));
                    }
                }
            }
        }
    }
    let (ratio, record, lambda) = largest?;
    Some(format!(
        "<p class=\"note\"><b>Warning: {runs} run{} of the dynamic checks break{} the model's assumption that a seated block stays seated through an impact elsewhere</b> (a seat impulse ratio |M<sub>imp</sub>| / (V<sub>imp</sub> B/2) above 1; the largest {} for {} at λ = {}): the dynamic verdicts resting on {} are outside the model's validity. Each record's ratio at λ = 1 is in records.csv (<code>max_seat_impulse_ratio</code>).</p>",
        if runs == 1 { "" } else { "s" },
        if runs == 1 { "s" } else { "" },
        sig(ratio, 3),
        esc(record),
        sig(lambda, 3),
        if runs == 1 { "it" } else { "them" }
    ))
}

/// Both principal directions: the plan's two dimensions, and the verdict of
/// each with the checks of the other direction (those below are the file's).
fn other_direction(done: &Assessment, turned: &Assessment, input: &AssessmentInput) -> String {
    let line = |a: &Assessment| {
        a.mechanisms()
            .into_iter()
            .filter_map(|m| m.verdict(a.verdict_method).map(|v| (m, v)))
            .reduce(|best, x| if x.1.check.zeta_e < best.1.check.zeta_e { x } else { best })
            .map_or_else(
                || "no check completed".to_string(),
                |(m, v)| {
                    let g = v.check;
                    format!(
                        "{}{} {}, ζ<sub>E</sub> = {}{} ({})",
                        if a.blocks.is_empty() { String::new() } else { format!("{}, ", esc(m.name)) },
                        g.limit_state,
                        g.method.text(input.file.q).name,
                        if g.ag_capacity.is_lower_bound() { "≥ " } else { "" },
                        sig(g.zeta_e, 3),
                        verdict(&g)
                    )
                },
            )
    };
    let mut rows = String::new();
    for m in turned.mechanisms() {
        for c in m.completed() {
            let _ = write!(
                rows,
                "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}{}</td><td>{}</td></tr>",
                esc(m.name),
                c.limit_state,
                c.method.text(input.file.q).name,
                if c.ag_capacity.is_lower_bound() { "≥ " } else { "" },
                sig(c.zeta_e, 3),
                verdict(&c)
            );
        }
    }
    format!(
        "<section id=\"directions\"><h2>Both principal directions</h2><p>A body of the tower is not square in plan (its depth differs from its width): the tower is assessed rocking across each body's width, the file's direction, whose checks the sections below give, and across each body's depth, the bodies turned a quarter, whose checks are in this table. The verdict is the worse of the two.</p>\
         <p>Across the width: {}.<br>Across the depth: {}.</p>\
         <table><tr><th>mechanism</th><th>LS</th><th>method</th><th>ζ<sub>E</sub></th><th>verdict</th></tr>{rows}</table></section>",
        line(done),
        line(turned)
    )
}

/// The page (`report.html`) and its figures, to be written as files too (`--plot`).
pub fn report_and_figures(input: &AssessmentInput, done: &Assessment) -> anyhow::Result<(String, Figures)> {
    let mut kept = Figures::default();
    let html = report(input, done, &mut kept)?;
    Ok((html, kept))
}

/// The page, each figure kept in `figs` as it is drawn.
fn report(input: &AssessmentInput, done: &Assessment, figs: &mut Figures) -> anyhow::Result<String> {
    let (capacity, checks, dynamic) = (&done.capacity, &done.checks, done.dynamic_part());
    let mechanisms = done.mechanisms();
    let stacked = mechanisms.len() > 1;
    let mut out = String::new();
    let name = esc(input.name());
    let code = if input.site.is_ntc() {
        "NTC 2018 and the Circolare 21 gennaio 2019 n. 7 (§C8.7.1.2.1)"
    } else {
        "EN 1998-1 spectra, EN 1998-3 limit states, the Circolare's checks"
    };
    let _ = writeln!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Assessment: {name}</title><style>{STYLE}</style></head><body>"
    );
    let _ = writeln!(out, "<h1>Assessment of {name}: the tower's local mechanism to {code}</h1>");
    let _ = writeln!(
        out,
        "<p class=\"note\">Made by rocking {} from <code>{}</code>. The tower is one rigid block overturning about a base corner at its springing level. {}</p>",
        env!("CARGO_PKG_VERSION"),
        esc(&input.origin().display().to_string()),
        super::assess_floor::level_sentence(input)
    );
    if stacked {
        let _ = writeln!(
            out,
            "<p class=\"note\">The tower carries {} block{} ({}). Each is a mechanism of its own: the block and those above it turning as one rigid body about a corner of its base on the block below; the tower's mechanism is the whole stack turning about a corner of the tower's base. The kinematic checks of a block take {}, that is up to the tower's activation at a<sub>g</sub> = {} g; beyond it the shaft's rocking changes the demand on the block, which only the dynamic checks (the whole stack run through the model) see.</p>",
            mechanisms.len() - 1,
            if mechanisms.len() > 2 { "s" } else { "" },
            mechanisms[1..].iter().map(|m| esc(m.name)).collect::<Vec<_>>().join(", "),
            if input.at_height() {
                "the floor spectrum of the support's top for the motion of the shaft's top: exact while the shaft does not rock (the tower is rigid and seated on the support)"
            } else {
                "the ground's spectra for the motion of the shaft's top: exact while the shaft does not rock (the tower and the church are rigid here, and the church sticks)"
            },
            sig(checks[0].ag_capacity.value(), 4)
        );
    }
    if let Some((m, v)) = done.governing_verdict() {
        let g = v.check;
        let _ = writeln!(
            out,
            "<p><b>Verdict: {}{} {}{}, ζ<sub>E</sub> = {}{}</b> ({}).</p>",
            if stacked { format!("{}, ", esc(m.name)) } else { String::new() },
            g.limit_state,
            g.method.text(input.file.q).name,
            if done.turned.is_some() {
                format!(", rocking across its {}", m.direction.as_str())
            } else {
                String::new()
            },
            if g.ag_capacity.is_lower_bound() { "≥ " } else { "" },
            sig(g.zeta_e, 3),
            verdict(&g)
        );
        let _ = writeln!(out, "<p class=\"note\">{}</p>", verdict_basis(done, input));
    }
    if let Some((m, d)) = done.damage() {
        let _ = writeln!(
            out,
            "<p>Damage limit state, beside the verdict: {}{} {}{}, ζ<sub>E</sub> = {}{} ({}).</p>",
            if stacked { format!("{}, ", esc(m.name)) } else { String::new() },
            d.limit_state,
            d.method.text(input.file.q).name,
            if done.turned.is_some() {
                format!(", rocking across its {}", m.direction.as_str())
            } else {
                String::new()
            },
            if d.ag_capacity.is_lower_bound() { "≥ " } else { "" },
            sig(d.zeta_e, 3),
            verdict(&d)
        );
    }
    let _ = writeln!(out, "{}", super::assess_floor::rigid_comparison(input, done)?);
    if let Some(turned) = &done.turned {
        let _ = writeln!(out, "{}", other_direction(done, turned, input));
    }
    if let Some(warning) = seat_impulse_warning(done) {
        let _ = writeln!(out, "{warning}");
    }

    if stacked {
        let _ = writeln!(out, "<h2>1. The mechanisms and their capacities</h2>");
        for m in &mechanisms {
            let what = if m.block == 0 {
                "the tower with every block on it, one rigid body turning about a corner of the tower's base; M* the whole stack's mass".to_string()
            } else {
                let below = if m.block == 1 {
                    "the tower".to_string()
                } else {
                    esc(mechanisms[m.block - 1].name)
                };
                if m.block + 1 < mechanisms.len() {
                    format!(
                        "{} with the blocks above it, one rigid body turning about a corner of its base on {below}; M* their mass",
                        esc(m.name)
                    )
                } else {
                    format!("{}, a rigid body turning about a corner of its base on {below}; M* its mass", esc(m.name))
                }
            };
            let _ = writeln!(out, "<h3>{}</h3>\n<p>{what}.</p>", esc(m.name));
            capacity_table(&mut out, m.capacity, &format!("the {}", m.name));
        }
    } else {
        let _ = writeln!(out, "<h2>1. The tower and its capacity</h2>");
        capacity_table(&mut out, capacity, "the tower");
    }
    let _ = writeln!(out, "<h2>2. The site</h2>");
    let _ = writeln!(
        out,
        "<p>Soil {}; spectra at 5% damping. Each check moves a<sub>g</sub> with every site parameter that depends on it (S<sub>S</sub>, T<sub>D</sub>) and takes the <em>least</em> a<sub>g</sub> at which it stops holding: the demand need not grow with a<sub>g</sub>.</p>",
        input.file.site.soil
    );
    let _ = writeln!(out, "<p>{}</p>", site_source(input));
    site_rows(&mut out, input);
    let _ = writeln!(out, "{}", super::assess_floor::support_html(input)?);

    let _ = writeln!(out, "<h2>3. The checks</h2>");
    for m in &mechanisms {
        if stacked {
            let _ = writeln!(out, "<h3>{}</h3>", esc(m.name));
        }
        checks_table(&mut out, m, input.file.q);
        if stacked {
            linear_note(&mut out, input, m.capacity, &format!(" of the {}", m.name));
            let _ = writeln!(out, "<figure>{}<figcaption>The capacity curve of {} with its ultimate displacements and the non-linear kinematic demands at the site's a<sub>g</sub>: blue the life-safety limit state, vermilion the collapse one; a square the ultimate displacement, a triangle a demand that holds, a cross one that fails.</figcaption></figure>", adrs_figure(figs, format!("report_adrs_{}", stem_part(m.name)), m.capacity, m.checks, input.site.limit_state(Role::LifeSafety), &format!(": {}", m.name))?, esc(m.name));
        }
    }
    let _ = writeln!(
        out,
        "<p class=\"note\">ζ<sub>E</sub> = a<sub>g,capacity</sub> / a<sub>g</sub>; a check holds when ζ<sub>E</sub> ≥ 1. The non-linear kinematic capacity is not taken below the activation's. “≥” marks a capacity beyond the search (2 g, or the last λ).</p>"
    );
    if !stacked {
        linear_note(&mut out, input, capacity, "");
    }
    if !stacked {
        let _ = writeln!(out, "<figure>{}<figcaption>The capacity curve with the ultimate displacements and the non-linear kinematic demands at the site's a<sub>g</sub>: blue the life-safety limit state, vermilion the collapse one; a square the ultimate displacement, a triangle a demand that holds, a cross one that fails.</figcaption></figure>", adrs_figure(figs, "report_adrs".into(), capacity, checks, input.site.limit_state(Role::LifeSafety), "")?);
    }

    if let Some((set, dynamic)) = dynamic {
        let _ = writeln!(out, "<h2>4. The non-linear dynamic checks</h2>");
        let _ = writeln!(
            out,
            "<p>{} records, each fitted to the limit state's spectrum by its own scale (the least squares of the log spectra over {}–{} s), run through the full model{} for its duration plus {} s. The response of a record is its largest d*(θ) = R (sin α − sin(α − |θ|)).</p>",
            set.records.len(),
            sig(set.range.0, 3),
            sig(set.range.1, 3),
            if input.model().building().is_some() { " (the tower, and the church sliding on its foundation)" } else { "" },
            input.file.free_after
        );
        let _ = writeln!(out, "{}", super::assess_floor::dynamic_note(input));
        let _ = writeln!(
            out,
            "<p class=\"note\">The record files, from the assessment file's folder (the tables below name each by its file's name): {}.</p>",
            set.records
                .iter()
                .map(|r| format!("<code>{}</code>", esc(&r.path)))
                .collect::<Vec<_>>()
                .join(", ")
        );
        if stacked {
            let _ = writeln!(
                out,
                "<p>Each mechanism reads the same runs: its control point is its own block's rotation θ on the block below, over its own capacity (R, α); a record makes it collapse when its block or one under it overturns. An overturning ends the run, so that the blocks under the one that fell give their largest d* up to then. The tables give each mechanism's largest d* in its column, or <span class=\"fails\">fell</span> where the record made it collapse.</p>"
            );
        }
        for (i, d) in dynamic.iter().enumerate() {
            let c = &d.fitted.compatibility;
            let _ = writeln!(out, "<h3>{}</h3>", d.limit_state);
            let _ = writeln!(
                out,
                "<p>Mean of the scaled set over the code spectrum, over the fitting range: {} to {} ({} the code's {}–{}).</p>",
                sig(c.least_ratio, 3),
                sig(c.greatest_ratio, 3),
                if c.holds { "within" } else { "<span class=\"fails\">outside</span>" },
                COMPATIBILITY_LOWER,
                COMPATIBILITY_UPPER
            );
            if !c.holds {
                let _ = writeln!(
                    out,
                    "<p class=\"fails\">{}</p>",
                    if done.accept_incompatible_set {
                        "The set is not compatible with the code's spectrum (NTC 2018 §3.2.3.6): assessment.accept_incompatible_set lets this check carry the verdict all the same."
                    } else {
                        "Not valid: the set is not compatible with the code's spectrum (NTC 2018 §3.2.3.6), so this check stays out of the verdict (assessment.accept_incompatible_set = true would let it in, with a warning)."
                    }
                );
            }
            let _ = writeln!(out, "<figure>{}</figure>", spectra_figure(figs, set, d)?);
            // A stack's table: one max d* column per mechanism under a shared
            // head, a fall marked in its cell, so that the five blocks a tower
            // may carry fit the printed page's width as the tower alone does.
            let cells = |resp: &Result<rocking_assess::RecordResponse, String>| match resp {
                Ok(x) => (x.max_displacement.map_or("—".into(), |v| sig(v, 4)), x.overturned),
                Err(_) => (String::new(), false),
            };
            if stacked {
                let _ = write!(
                    out,
                    "<div class=\"wide\"><table class=\"records\"><tr><th rowspan=\"2\">record</th><th rowspan=\"2\">scale</th><th colspan=\"{}\">max d* (m)</th><th rowspan=\"2\">max slip of the building (m)</th><th rowspan=\"2\">error</th></tr><tr>",
                    mechanisms.len()
                );
                for m in &mechanisms {
                    let _ = write!(out, "<th>{}</th>", esc(m.name));
                }
                let _ = writeln!(out, "</tr>");
            } else {
                let _ = writeln!(
                    out,
                    "<div class=\"wide\"><table class=\"records\"><tr><th>record</th><th>scale</th><th>max d* (m)</th><th>overturned</th><th>max slip of the building (m)</th><th>error</th></tr>"
                );
            }
            for (k, ((r, s), resp)) in set.records.iter().zip(&d.fitted.scales).zip(&d.at_one.responses).enumerate() {
                let responses = if stacked {
                    let mut row = String::new();
                    for m in &mechanisms {
                        // A mechanism that collapsed has no d* (its block or one under it fell).
                        let (dm, fell) = cells(&m.dynamic[i].at_one.responses[k]);
                        let _ = write!(
                            row,
                            "<td class=\"n\">{}</td>",
                            if fell { "<span class=\"fails\">fell</span>".into() } else { dm }
                        );
                    }
                    row
                } else {
                    let (dm, overturned) = cells(resp);
                    let overturned = if resp.is_ok() { overturned.to_string() } else { String::new() };
                    format!("<td class=\"n\">{dm}</td><td>{overturned}</td>")
                };
                let (slip, err) = match resp {
                    Ok(x) => (x.max_slip.map_or("—".into(), |v| sig(v, 4)), String::new()),
                    Err(e) => (String::new(), esc(e)),
                };
                let _ = writeln!(
                    out,
                    "<tr><td title=\"{}\">{}</td><td class=\"n\">{}</td>{responses}<td class=\"n\">{slip}</td><td>{err}</td></tr>",
                    esc(&r.path),
                    esc(file_name(&r.path)),
                    sig(*s, 4)
                );
            }
            let _ = writeln!(out, "</table></div>");
            for m in &mechanisms {
                let d = &m.dynamic[i];
                let d_ls = if d.limit_state == input.site.limit_state(Role::LifeSafety) {
                    m.capacity.d_slv
                } else {
                    m.capacity.d_slc
                };
                let of = if stacked { format!(" of {}", esc(m.name)) } else { String::new() };
                let _ = writeln!(out, "<figure>{}<figcaption>The response{of} at each λ of the scan and of the bisection; the first λ at which the check fails is the one reported, and the legend says why: the records that reach d<sub>0</sub> there (each alone fails the check), else the set's response beyond d<sub>{}</sub>.</figcaption></figure>", lambda_figure(figs, d, set, d_ls, m.capacity.d0, if stacked { m.name } else { "" })?, d.limit_state);
            }
        }
    }
    let _ = writeln!(out, "{}", provenance(input));
    let _ = writeln!(out, "</body></html>");
    Ok(out)
}

/// The closing section: when and by what the report was made, the
/// fingerprints of the files it was made from, and the statement NTC 2018
/// §10.2 asks of a calculation made by software. On lines of their own
/// between its tags (the tests of the committed example report leave it out:
/// it is of the run).
fn provenance(input: &AssessmentInput) -> String {
    // SOURCE_DATE_EPOCH (the reproducible-builds convention) fixes the date.
    let date = std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|s| s.parse::<i64>().ok())
        .and_then(|s| jiff::Timestamp::from_second(s).ok())
        .unwrap_or_else(jiff::Timestamp::now);
    let mut files = vec![input.origin().to_path_buf()];
    files.extend(input.inputs());
    let rows: String = files
        .iter()
        .map(|f| {
            let digest = std::fs::read(f).map_or_else(|e| format!("not read: {e}"), |bytes| crate::shard::fingerprint(&bytes));
            format!(
                "<tr><td><code>{}</code></td><td><code>{}</code></td></tr>\n",
                esc(&f.display().to_string()),
                esc(&digest)
            )
        })
        .collect::<String>()
        + &match &input.file.site.source {
            // The official grid is no file of the user's: the tool holds it, so its commit fixes it.
            rocking_scenario::SiteSource::Grid { path: None, .. } | rocking_scenario::SiteSource::Island { .. } => format!(
                "<tr><td>NTC 2018 Allegato B, Tabelle 1 and 2 (the official hazard grid)</td><td>held by rocking {} itself (commit above)</td></tr>\n",
                env!("CARGO_PKG_VERSION")
            ),
            _ => String::new(),
        };
    format!(
        "<section id=\"provenance\">\n<h2>About this report</h2>\n\
         <p>Made on <span id=\"made-on\">{}</span> (UTC) by rocking {} (commit <code id=\"commit\">{}</code>), from these files:</p>\n\
         <table id=\"fingerprints\"><tr><th>file</th><th>SHA-256</th></tr>\n{rows}</table>\n\
         <p id=\"software\">NTC 2018 §10.2: the calculation was made by rocking, open-source software that integrates the rocking of rigid blocks on a sliding building and checks them to NTC 2018 and the Circolare 2019 n. 7 as its book describes (the model, its assumptions, and the checks of each formula); its validation against closed forms, papers and other programs is the book's validation page, with the tables and the commands that reproduce them. The software does not judge: whether the model fits the building, the inputs are right and the results acceptable is the judgement of the engineer who signs the calculation.</p>\n\
         </section>",
        date.strftime("%Y-%m-%d %H:%M:%S"),
        env!("CARGO_PKG_VERSION"),
        env!("ROCKING_COMMIT"),
    )
}
