//! `report.html` of `rocking inventory`: the town on one self-contained page
//! (no script; figures inline as SVG, in the look of `rocking assess`'s page):
//! the map, the ranking, the table of every assessed tower least ζ_E first
//! (each check's ζ_E, the governing one, a link to the tower's own assessment
//! when `--details` wrote it), and the towers not assessed with their error.

use super::assess_report::{esc, scalable, STYLE};
use rocking_assess::{ranking, rounded, Ranked, DEGREE_DECIMALS, ZETA_DECIMALS};
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

/// A ζ_E as the table shows it: to 3 decimals ([`ZETA_DECIMALS`]), `≥` before a lower bound.
fn zeta_text(z: f64, lower_bound: bool) -> String {
    format!("{}{:.*}", if lower_bound { "≥ " } else { "" }, ZETA_DECIMALS, z)
}

/// A ζ_E cell: its value, red when the check fails.
fn zeta_cell(z: Option<f64>, lower_bound: bool) -> String {
    match z {
        Some(z) if z < 1.0 && !lower_bound => format!("<td class=\"n fails\">{}</td>", zeta_text(z, false)),
        Some(z) => format!("<td class=\"n\">{}</td>", zeta_text(z, lower_bound)),
        None => "<td class=\"n\">—</td>".into(),
    }
}

/// A coordinate's cell: to 6 decimals ([`DEGREE_DECIMALS`], a tenth of a metre), or empty.
fn degree_cell(x: Option<f64>) -> String {
    x.map_or_else(|| "<td></td>".into(), |x| format!("<td class=\"n\">{}</td>", rounded(x, DEGREE_DECIMALS)))
}

/// The table of the assessed towers, least ζ_E first: one heading per column and, in the same order, one cell per heading in each row.
fn towers_table(out: &mut String, page: &TownPage<'_>, ranked: &[&Ranked]) {
    let mut headings: Vec<String> = ["rank", "id", "name", "lon", "lat"].map(String::from).to_vec();
    headings.extend(page.checks.iter().map(|c| format!("ζ<sub>E</sub> {}", esc(&c.replace('_', " ")))));
    headings.extend(["ζ<sub>E</sub>".to_string(), "governing".to_string()]);
    if page.details.is_some() {
        headings.push("its page".into());
    }
    let _ = write!(out, "<table id=\"towers\"><tr>");
    for h in &headings {
        let _ = write!(out, "<th>{h}</th>");
    }
    let _ = writeln!(out, "</tr>");
    for (rank, t) in ranked.iter().enumerate() {
        let mut cells = vec![
            format!("<td class=\"n\">{}</td>", rank + 1),
            format!("<td>{}</td>", esc(&t.id)),
            format!("<td>{}</td>", esc(&t.name)),
            degree_cell(t.point.map(|p| p.0)),
            degree_cell(t.point.map(|p| p.1)),
        ];
        cells.extend(t.check_zetas.iter().map(|z| zeta_cell(*z, false)));
        cells.push(zeta_cell(t.zeta, t.lower_bound));
        cells.push(format!("<td>{}</td>", esc(&t.governing.replace('_', " "))));
        if let Some(link) = page.details {
            cells.push(format!("<td><a href=\"{}\">report</a></td>", esc(&link(t.index))));
        }
        debug_assert_eq!(cells.len(), headings.len());
        let _ = writeln!(out, "<tr>{}</tr>", cells.concat());
        if !t.error.is_empty() {
            let _ = writeln!(out, "<tr><td colspan=\"{}\" class=\"note\">{}</td></tr>", headings.len(), esc(&t.error));
        }
    }
    let _ = writeln!(out, "</table>");
    if ranked.iter().any(|t| t.lower_bound) {
        let _ = writeln!(
            out,
            "<p class=\"note\">≥: the governing ζ<sub>E</sub> is a lower bound: its a<sub>g,capacity</sub> is the top of the search (2 g) or of the λ scan, which the tower bore (<code>zeta_E_is_lower_bound</code> in <code>inventory.csv</code>).</p>"
        );
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
        "<figure>{}<figcaption>Each tower at its longitude and latitude (WGS84, a degree of longitude drawn as long as on the ground), named, and coloured by its governing ζ<sub>E</sub>: red where a check fails (ζ<sub>E</sub> &lt; 1), blue where all hold, the hue turning at the line across the colour bar, ζ<sub>E</sub> = 1.</figcaption></figure>",
        scalable(map, map_size)
    );
    let _ = writeln!(out, "<h2>2. The ranking</h2>");
    let _ = writeln!(
        out,
        "<figure>{}<figcaption>The towers of least governing ζ<sub>E</sub>, each bar coloured by its governing check.</figcaption></figure>",
        scalable(bars, bars_size)
    );
    towers_table(&mut out, page, &ranked);
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The columns a row of the page spans: its cells, each counted by its colspan.
    fn spans(row: &str) -> usize {
        row.split("<t")
            .skip(1)
            .filter(|c| c.starts_with('d') || c.starts_with('h'))
            .map(|c| {
                c.split("colspan=\"")
                    .nth(1)
                    .and_then(|s| s.split('"').next())
                    .map_or(1, |s| s.parse().unwrap_or(0))
            })
            .sum()
    }

    #[test]
    fn an_error_row_spans_the_header_as_a_towers_row_does() -> anyhow::Result<()> {
        // A tower whose dynamic check could not be completed: a ζ_E and an error.
        let tower = Ranked {
            index: 0,
            id: "A".into(),
            name: "a tower".into(),
            point: Some((14.3320000001, 41.074)),
            zeta: Some(0.885),
            lower_bound: false,
            governing: "SLV nonlinear_kinematic".into(),
            check_zetas: vec![Some(1.5), Some(0.885)],
            error: "towers.csv row 1 (id A): SLV nonlinear_dynamic: could not be completed".into(),
        };
        let checks = ["SLV_linear_kinematic".to_string(), "SLV_nonlinear_kinematic".to_string()];
        let link = |_: usize| "towers/A/report.html".to_string();
        for details in [None, Some(&link as &dyn Fn(usize) -> String)] {
            let page = TownPage {
                title: "1 tower",
                towers_file: "towers.csv",
                assess_file: "assess.toml",
                checks: &checks,
                details,
            };
            let mut out = String::new();
            towers_table(&mut out, &page, &[&tower]);
            let rows: Vec<&str> = out.lines().filter(|l| l.contains("<tr")).collect();
            // rank, id, name, lon, lat, two checks, ζ_E, governing (and the link): 9 or 10.
            let width = 9 + usize::from(details.is_some());
            assert_eq!(rows.len(), 3, "{out}");
            for row in rows {
                assert_eq!(spans(row), width, "{row}");
            }
            // The place to 6 decimals, ζ_E to 3.
            assert!(
                out.contains("<td class=\"n\">14.332</td><td class=\"n\">41.074</td><td class=\"n\">1.500</td><td class=\"n fails\">0.885</td>"),
                "{out}"
            );
        }
        Ok(())
    }
}
