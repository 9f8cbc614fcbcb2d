//! `report.html` of `rocking inventory`: the town on one self-contained page
//! (no script; figures inline as SVG, in the look of `rocking assess`'s page):
//! the map, the ranking, the table of every assessed tower least ζ_E first
//! (each check's ζ_E, the governing one, a link to the tower's own assessment
//! when `--details` wrote it), and the towers not assessed with their error.

use super::assess_report::{esc, scalable, STYLE};
use crate::format::sig;
use rocking_assess::{ranking, Ranked};
use std::fmt::Write;

/// What the page says besides the towers.
pub struct TownPage<'a> {
    /// Its title (`12 towers of towers.csv`).
    pub title: &'a str,
    /// The towers' file and the assessment file, as given.
    pub towers_file: &'a str,
    /// The assessment file.
    pub assess_file: &'a str,
    /// The checks' names (`SLV_linear_kinematic`), in column order.
    pub checks: &'a [String],
    /// The link to each tower's own page, by its index in input order, if written.
    pub details: Option<&'a dyn Fn(usize) -> String>,
}

/// A ζ_E cell: its value, red when the check fails.
fn zeta_cell(z: Option<f64>) -> String {
    match z {
        Some(z) if z < 1.0 => format!("<td class=\"n fails\">{}</td>", sig(z, 3)),
        Some(z) => format!("<td class=\"n\">{}</td>", sig(z, 3)),
        None => "<td class=\"n\">—</td>".into(),
    }
}

/// The page.
pub fn town_html(page: &TownPage<'_>, towers: &[Ranked]) -> anyhow::Result<String> {
    let mut out = String::new();
    let title = esc(page.title);
    let _ = writeln!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Bell towers: {title}</title><style>{STYLE}</style></head><body>"
    );
    let _ = writeln!(out, "<h1>The bell towers of {}: their ranking by ζ<sub>E</sub></h1>", esc(page.towers_file));
    let ranked = ranking(towers);
    let failing = ranked.iter().filter(|t| t.zeta.is_some_and(|z| z < 1.0)).count();
    let _ = writeln!(
        out,
        "<p class=\"note\">Made by rocking {} from <code>{}</code> and <code>{}</code>: each tower assessed as <code>rocking assess</code> assesses one, the site's hazard at its coordinates. ζ<sub>E</sub> = a<sub>g,capacity</sub> / a<sub>g</sub>, the ground acceleration a tower can bear over the site's; a check holds when ζ<sub>E</sub> ≥ 1, and the governing check is the one of least ζ<sub>E</sub>.</p>",
        env!("CARGO_PKG_VERSION"),
        esc(page.towers_file),
        esc(page.assess_file)
    );
    let _ = writeln!(
        out,
        "<p>{} towers: {} assessed, {failing} of them with a check that fails (ζ<sub>E</sub> &lt; 1), {} not assessed.</p>",
        towers.len(),
        ranked.len(),
        towers.len() - ranked.len()
    );
    let [(map, map_size), (bars, bars_size)] = crate::plot::town_svgs(page.title, towers, page.checks)?;
    let _ = writeln!(out, "<h2>1. The map</h2>");
    let _ = writeln!(
        out,
        "<figure>{}<figcaption>Each tower at its longitude and latitude (WGS84, a degree of longitude drawn as long as on the ground), coloured by its governing ζ<sub>E</sub>; the line across the colour bar is ζ<sub>E</sub> = 1.</figcaption></figure>",
        scalable(map, map_size)
    );
    let _ = writeln!(out, "<h2>2. The ranking</h2>");
    let _ = writeln!(
        out,
        "<figure>{}<figcaption>The towers of least governing ζ<sub>E</sub>, each bar coloured by its governing check.</figcaption></figure>",
        scalable(bars, bars_size)
    );
    let _ = write!(out, "<table><tr><th>rank</th><th>id</th><th>name</th><th>lon</th><th>lat</th>");
    for c in page.checks {
        let _ = write!(out, "<th>ζ<sub>E</sub> {}</th>", esc(&c.replacen('_', " ", 1).replace('_', " ")));
    }
    let _ = writeln!(
        out,
        "<th>ζ<sub>E</sub></th><th>governing</th>{}</tr>",
        if page.details.is_some() { "<th>its page</th>" } else { "" }
    );
    for (rank, t) in ranked.iter().enumerate() {
        let _ = write!(out, "<tr><td class=\"n\">{}</td><td>{}</td><td>{}</td>", rank + 1, esc(&t.id), esc(&t.name));
        for z in &t.check_zetas {
            out.push_str(&zeta_cell(*z));
        }
        out.push_str(&zeta_cell(t.zeta));
        let _ = write!(out, "<td>{}</td>", esc(&t.governing.replace('_', " ")));
        if let Some(link) = page.details {
            let _ = write!(out, "<td><a href=\"{}\">report</a></td>", esc(&link(t.index)));
        }
        let _ = writeln!(out, "</tr>");
        if !t.error.is_empty() {
            let _ = writeln!(
                out,
                "<tr><td></td><td colspan=\"{}\" class=\"note\">{}</td></tr>",
                page.checks.len() + 4,
                esc(&t.error)
            );
        }
    }
    let _ = writeln!(out, "</table>");
    let bad: Vec<&Ranked> = towers.iter().filter(|t| t.zeta.is_none()).collect();
    if !bad.is_empty() {
        let _ = writeln!(out, "<h2>3. Towers not assessed</h2>");
        let _ = writeln!(out, "<table><tr><th>id</th><th>name</th><th>error</th></tr>");
        for t in bad {
            let _ = writeln!(out, "<tr><td>{}</td><td>{}</td><td>{}</td></tr>", esc(&t.id), esc(&t.name), esc(&t.error));
        }
        let _ = writeln!(out, "</table>");
    }
    let _ = writeln!(out, "</body></html>");
    Ok(out)
}
