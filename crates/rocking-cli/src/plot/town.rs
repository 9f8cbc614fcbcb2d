//! The figures of a town's inventory: `town_map` (the towers at their
//! longitude and latitude, each named, coloured by their governing ζ_E on a
//! scale that turns from red to blue at ζ_E = 1, with a colour bar; no map tiles) and `town_ranking` (the towers of least ζ_E as bars, the
//! colour of each its governing check, the line ζ_E = 1).

use super::legend::{self, Entry, Swatch};
use super::style::{self, fails_holds, size, text, Figure, CYCLE, GREY, INK};
use crate::format::sig;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use rocking_assess::{ranking, Ranked};

/// Size of the map (px).
pub const MAP_SIZE: (u32, u32) = (1000, 820);
/// Width of the ranking (px); its height grows with the towers shown.
pub const RANKING_WIDTH: u32 = 1000;
/// Towers shown in the ranking at most (those of least ζ_E).
pub const RANKED_SHOWN: usize = 40;
/// Towers named on the map at most (more would cover the points).
const NAMED_ON_MAP: usize = 40;
/// Width of the colour bar's area at the right of the map (px).
const BAR_AREA: u32 = 130;
/// Left margin plus label area (px) of the map.
const MAP_LEFT: i32 = 100;
/// Left margin plus label area (px) of the ranking: the towers' names.
const RANKING_LEFT: i32 = 300;
/// The top of the colour scale: the largest ζ_E, within these bounds (a
/// single very strong tower would otherwise wash out the others' colours).
const TOP_BOUNDS: (f64, f64) = (1.2, 3.0);
/// Grey of a tower that was not assessed.
const NOT_ASSESSED: RGBColor = RGBColor(170, 170, 170);

/// The top of the colour scale for `towers`.
fn colour_top(towers: &[Ranked]) -> f64 {
    let top = towers.iter().filter_map(|t| t.zeta).filter(|z| z.is_finite()).fold(0.0, f64::max);
    top.clamp(TOP_BOUNDS.0, TOP_BOUNDS.1)
}

/// The colour of each governing check, by the order of the checks' columns.
fn check_colour(checks: &[String], governing: &str) -> RGBColor {
    let key = governing.replace(' ', "_");
    checks.iter().position(|c| *c == key).map_or(GREY, |k| CYCLE[k % CYCLE.len()])
}

/// The map.
pub struct MapFigure<'a> {
    /// The title (the towers' file).
    pub title: &'a str,
    /// Every tower, in input order.
    pub towers: &'a [Ranked],
}

impl MapFigure<'_> {
    /// The ranges of longitude and latitude shown: the towers' with a margin,
    /// widened so that a degree of longitude is as long as on the ground
    /// (cos φ of a degree of latitude) in a plot `w` × `h` px.
    fn ranges(&self, w: f64, h: f64) -> ((f64, f64), (f64, f64)) {
        let points: Vec<(f64, f64)> = self.towers.iter().filter_map(|t| t.point).collect();
        if points.is_empty() {
            return ((-1.0, 1.0), (-1.0, 1.0));
        }
        let fold = |f: fn(&(f64, f64)) -> f64| {
            points
                .iter()
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)))
        };
        let (lon, lat) = (fold(|p| p.0), fold(|p| p.1));
        let cos = ((lat.0 + lat.1) / 2.0).to_radians().cos().max(0.05);
        // Half-spans in km-like units (degrees of latitude), with a margin and a floor of ~100 m.
        let half_x = ((lon.1 - lon.0) * cos / 2.0 * 1.15).max(1e-3);
        let half_y = ((lat.1 - lat.0) / 2.0 * 1.15).max(1e-3);
        // Widen one of them to the plot's aspect.
        let (half_x, half_y) = if half_x / half_y > w / h {
            (half_x, half_x * h / w)
        } else {
            (half_y * w / h, half_y)
        };
        let (cx, cy) = ((lon.0 + lon.1) / 2.0, (lat.0 + lat.1) / 2.0);
        ((cx - half_x / cos, cx + half_x / cos), (cy - half_y, cy + half_y))
    }

    fn subtitle(&self) -> String {
        let placed = self.towers.iter().filter(|t| t.point.is_some()).count();
        let mut parts = vec!["colour: the governing ζ_E = ag capacity / ag; red fails (below 1), blue holds".to_string()];
        if placed < self.towers.len() {
            parts.push(format!("{} without a place not shown", self.towers.len() - placed));
        }
        parts.join(" · ")
    }
}

impl Figure for MapFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let rest = style::title_band(root, self.title, &self.subtitle())?;
        let top = colour_top(self.towers);
        let mut entries = vec![
            Entry::new(Swatch::Square(fails_holds(0.5, top)), "ζ_E < 1: fails"),
            Entry::new(Swatch::Square(fails_holds((1.0 + top) / 2.0, top)), "ζ_E ≥ 1: holds"),
        ];
        if self.towers.iter().any(|t| t.zeta.is_none() && t.point.is_some()) {
            entries.push(Entry::new(Swatch::Square(NOT_ASSESSED), "not assessed (see its error)"));
        }
        let body = legend::above(&rest, MAP_LEFT, &entries)?;
        let (w, h) = body.dim_in_pixel();
        let (map, bar) = body.split_horizontally(w.saturating_sub(BAR_AREA));
        style::colour_bar(&bar, top, "governing ζ_E (–): fails below 1", Some(1.0), &|z| fails_holds(z, top))?;

        // The plot's own size: the map less its label areas and margins.
        let plot_w = f64::from(w.saturating_sub(BAR_AREA)) - f64::from(MAP_LEFT) - 24.0;
        let plot_h = f64::from(h) - 56.0 - 14.0;
        let (x, y) = self.ranges(plot_w.max(1.0), plot_h.max(1.0));
        let mut chart = style::xy_chart(&map, MAP_LEFT, x, y)?;
        style::xy_mesh(&mut chart, "longitude (° E, WGS84)", "latitude (° N)")
            .x_label_formatter(&|v| sig(*v, 6))
            .y_label_formatter(&|v| sig(*v, 6))
            .draw()?;
        let named = self.towers.len() <= NAMED_ON_MAP;
        // The weakest towers last, on top of the others.
        let mut order: Vec<&Ranked> = self.towers.iter().filter(|t| t.point.is_some()).collect();
        order.sort_by(|a, b| b.zeta.unwrap_or(f64::INFINITY).total_cmp(&a.zeta.unwrap_or(f64::INFINITY)));
        for t in order {
            let Some(p) = t.point else { continue };
            match t.zeta {
                Some(z) => {
                    chart.draw_series(std::iter::once(Circle::new(p, 8, fails_holds(z, top).filled())))?;
                    chart.draw_series(std::iter::once(Circle::new(p, 8, INK.stroke_width(1))))?;
                }
                None => {
                    chart.draw_series(std::iter::once(Circle::new(p, 6, NOT_ASSESSED.filled())))?;
                }
            }
            if named {
                // The name (the id when it has none) right of the point, 11 px off.
                let label = if t.name.trim().is_empty() { &t.id } else { &t.name };
                let style = text(size::TICK, INK).pos(Pos::new(HPos::Left, VPos::Center));
                chart.draw_series(std::iter::once(EmptyElement::at(p) + Text::new(style::printable(label), (11, 0), style)))?;
            }
        }
        Ok(())
    }
}

/// The ranking.
pub struct RankingFigure<'a> {
    /// The title (the towers' file).
    pub title: &'a str,
    /// Every tower, in input order.
    pub towers: &'a [Ranked],
    /// The checks' names (`SLV_linear_kinematic`), in the order of the columns.
    pub checks: &'a [String],
}

impl RankingFigure<'_> {
    /// The figure's size for `shown` bars and a legend of `checks` entries.
    pub fn size(towers: &[Ranked]) -> (u32, u32) {
        let shown = ranking(towers).len().min(RANKED_SHOWN);
        (RANKING_WIDTH, 230 + 26 * u32::try_from(shown.max(1)).unwrap_or(1))
    }
}

impl Figure for RankingFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let ranked = ranking(self.towers);
        let shown = &ranked[..ranked.len().min(RANKED_SHOWN)];
        let subtitle = if ranked.len() > shown.len() {
            format!("the {} of least governing ζ_E of {} assessed towers", shown.len(), ranked.len())
        } else {
            format!("the {} assessed towers, least governing ζ_E first", ranked.len())
        };
        let rest = style::title_band(root, self.title, &subtitle)?;
        let mut entries: Vec<Entry> = self
            .checks
            .iter()
            .filter(|c| shown.iter().any(|t| t.governing.replace(' ', "_") == **c))
            .map(|c| Entry::new(Swatch::Square(check_colour(self.checks, c)), format!("governed by {}", c.replacen('_', " ", 1))))
            .collect();
        entries.push(Entry::new(Swatch::Dashed(INK), "ζ_E = 1: below it the check fails"));
        let body = legend::above(&rest, RANKING_LEFT, &entries)?;

        let n = shown.len().max(1) as f64;
        let x_top = shown.iter().filter_map(|t| t.zeta).fold(1.0, f64::max) * 1.15;
        let mut chart = style::xy_chart(&body, RANKING_LEFT, (0.0, x_top), (-0.5, n - 0.5))?;
        // Rank k (0 the least ζ_E) at the top: y = n − 1 − k.
        let label = |v: &f64| {
            let k = v.round();
            if (v - k).abs() > 1e-6 || k < 0.0 {
                return String::new();
            }
            let rank = shown.len().checked_sub(1 + k as usize);
            rank.and_then(|r| shown.get(r)).map_or_else(String::new, |t| {
                let name: String = t.name.chars().take(22).collect();
                style::printable(&format!("{} {name}", t.id))
            })
        };
        style::xy_mesh(&mut chart, "governing ζ_E = ag capacity / ag (–)", "")
            .disable_y_mesh()
            .y_labels(shown.len().clamp(2, RANKED_SHOWN + 1))
            .y_label_formatter(&label)
            .x_label_formatter(&|v| sig(*v, 3))
            .draw()?;
        // The line ζ_E = 1 first, under the bars and their values.
        let dash = (0..40).map(|i| (-0.5 + (n / 40.0) * i as f64, -0.5 + (n / 40.0) * (i as f64 + 0.5)));
        chart.draw_series(dash.map(|(a, b)| PathElement::new(vec![(1.0, a), (1.0, b)], INK.stroke_width(2))))?;
        for (k, t) in shown.iter().enumerate() {
            let Some(z) = t.zeta else { continue };
            let y = n - 1.0 - k as f64;
            let colour = check_colour(self.checks, &t.governing);
            chart.draw_series(std::iter::once(Rectangle::new([(0.0, y - 0.36), (z, y + 0.36)], colour.filled())))?;
            let style = text(size::TICK, INK).pos(Pos::new(HPos::Left, VPos::Center));
            chart.draw_series(std::iter::once(Text::new(format!(" {}", sig(z, 3)), (z, y), style)))?;
        }
        Ok(())
    }
}
