//! `sweep_max_theta.svg`/`.png`: max θ/α against the first swept key, one
//! curve per value of the second (the paper's Figure 6). Failed cases leave a
//! gap; overturned cases are crosses on an "overturned" line above the curves,
//! whose θ/α (up to π/2α) would otherwise flatten them.

use super::labels;
use super::legend::{self, Entry, Swatch};
use super::scale;
use super::style::{self, curve_color, Figure, INK, OVERTURN};
use super::sweep_table::{number, Case, SweepTable};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Size of the figure (px).
pub const SIZE: (u32, u32) = (1000, 650);

/// The most curves named in the legend.
const MAX_LEGEND: usize = 10;

/// Left margin plus label area of the chart (px): where the legend starts.
const PLOT_LEFT: i32 = 100;

/// The figure of max θ/α against the first axis.
pub struct CurvesFigure<'a> {
    /// The sweep's name.
    pub title: &'a str,
    /// Its cases.
    pub table: &'a SweepTable,
}

/// A point of a curve.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Point {
    /// Max θ/α of a case that ran and stood.
    Value(f64, f64),
    /// A case whose tower overturned.
    Overturned(f64),
    /// A failed case, or one without a value: a gap.
    Gap(f64),
}

/// The x position of the values of the first axis: the numbers, or for text
/// values their rank 0, 1, 2, … (with the values as tick labels).
struct XAxis {
    categories: Option<Vec<String>>,
}

impl XAxis {
    fn new(cases: &[&Case]) -> Self {
        let values = SweepTable::values(cases, 0);
        let numeric = values.iter().all(|v| number(v).is_some());
        Self {
            categories: (!numeric).then(|| values.iter().map(|v| v.to_string()).collect()),
        }
    }

    fn position(&self, value: &str) -> Option<f64> {
        match &self.categories {
            None => number(value),
            Some(c) => c.iter().position(|x| x == value).map(|k| k as f64),
        }
    }

    fn label(&self, x: f64) -> String {
        match &self.categories {
            None => crate::format::sig(x, 4),
            Some(c) => {
                let k = x.round();
                let near = (x - k).abs() < 1e-6 && k >= 0.0;
                c.get(k as usize).filter(|_| near).cloned().unwrap_or_default()
            }
        }
    }
}

impl CurvesFigure<'_> {
    /// The curves: a label (the second axis' value, or none) and the points
    /// sorted by x; for a block on the tower (`block` its place in
    /// [`SweepTable::blocks`]), its own max θ/α instead of the tower's.
    fn curves(&self, cases: &[&Case], x: &XAxis, block: Option<usize>) -> Vec<(Option<String>, Vec<Point>)> {
        let groups: Vec<Option<&str>> = if self.table.axes.len() > 1 {
            SweepTable::values(cases, 1).into_iter().map(Some).collect()
        } else {
            vec![None]
        };
        groups
            .into_iter()
            .map(|group| {
                let mut points: Vec<Point> = cases
                    .iter()
                    .filter(|c| group.is_none_or(|g| c.keys.get(1).map(String::as_str) == Some(g)))
                    .filter_map(|c| {
                        let px = x.position(c.keys.first()?)?;
                        let value = match block {
                            None => c.value,
                            Some(b) => c.blocks.get(b).copied().flatten(),
                        };
                        Some(match value {
                            _ if c.overturned => Point::Overturned(px),
                            Some(v) if !c.failed => Point::Value(px, v),
                            _ => Point::Gap(px),
                        })
                    })
                    .collect();
                points.sort_by(|a, b| at(a).total_cmp(&at(b)));
                let label = group.map(|g| labels::value(&self.table.axes[1], g));
                (label, points)
            })
            .collect()
    }

    fn subtitle(&self, fixed: &[(String, String)], failed: usize) -> String {
        let axes = &self.table.axes;
        let mut parts = vec![format!("max θ/α against {}", labels::axis(&axes[0]))];
        if axes.len() > 1 {
            parts.push(format!("one curve per {}", labels::axis(&axes[1])));
        }
        if !fixed.is_empty() {
            let at: Vec<String> = fixed.iter().map(|(k, v)| labels::value(k, v)).collect();
            parts.push(format!("at the first value of the further keys: {}", at.join(", ")));
        }
        if failed > 0 {
            parts.push(format!("{failed} failed case{} left out", if failed == 1 { "" } else { "s" }));
        }
        parts.join(" · ")
    }
}

fn at(p: &Point) -> f64 {
    match *p {
        Point::Value(x, _) | Point::Overturned(x) | Point::Gap(x) => x,
    }
}

impl Figure for CurvesFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let (cases, fixed) = self.table.selection();
        let failed = cases.iter().filter(|c| c.failed).count();
        let rest = style::title_band(root, self.title, &self.subtitle(&fixed, failed))?;
        let x = XAxis::new(&cases);
        let curves = self.curves(&cases, &x, None);
        let n = curves.len();
        // Each block on the tower: the same curves, dashed, of its own max θ/α.
        let blocks: Vec<Vec<(Option<String>, Vec<Point>)>> = (0..self.table.blocks.len()).map(|b| self.curves(&cases, &x, Some(b))).collect();

        let values: Vec<f64> = curves
            .iter()
            .chain(blocks.iter().flatten())
            .flat_map(|(_, p)| p.iter())
            .filter_map(|p| if let Point::Value(_, v) = p { Some(*v) } else { None })
            .collect();
        let any_overturned = curves.iter().flat_map(|(_, p)| p.iter()).any(|p| matches!(p, Point::Overturned(_)));
        let xs: Vec<f64> = curves.iter().flat_map(|(_, p)| p.iter().map(at)).collect();
        let top = values.iter().copied().filter(|v| v.is_finite()).fold(0.0, f64::max);
        let top = if top > 0.0 { top } else { 1.0 };
        // Overturned cases sit on a line above the largest value that stood.
        let overturn_level = 1.2 * top;
        let y = (0.0, if any_overturned { 1.3 * top } else { 1.1 * top });
        let (x_lo, x_hi) = xs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        let x_range = scale::padded(x_lo, x_hi, 0.03);

        // Many curves (colours along viridis): a legend of at most MAX_LEGEND of them, evenly spread.
        let shown = |k: usize| n <= MAX_LEGEND || (0..MAX_LEGEND).any(|j| j * (n - 1) / (MAX_LEGEND - 1) == k);
        let mut entries: Vec<Entry> = curves
            .iter()
            .enumerate()
            .filter(|(k, _)| shown(*k))
            .filter_map(|(k, (label, _))| label.as_ref().map(|l| Entry::new(Swatch::LineDots(curve_color(k, n)), l.clone())))
            .collect();
        if n > MAX_LEGEND {
            entries.push(Entry::new(Swatch::Line(WHITE), format!("(and {} more curves between)", n - entries.len())));
        }
        if entries.is_empty() {
            entries.push(Entry::new(Swatch::LineDots(curve_color(0, 1)), "max θ/α"));
        }
        if !blocks.is_empty() {
            entries.insert(0, Entry::new(Swatch::LineDots(INK), "tower (its own α)"));
        }
        for (b, name) in self.table.blocks.iter().enumerate() {
            let swatch = if b == 0 { Swatch::Dashed(INK) } else { Swatch::Square(INK) };
            entries.insert(b + 1, Entry::new(swatch, format!("{name} on the block below (its own α)")));
        }
        if any_overturned {
            entries.push(Entry::new(Swatch::Cross(INK), "overturned (on the dashed line: off scale)"));
        }
        let panel = legend::above(&rest, PLOT_LEFT, &entries)?;

        let mut chart = style::xy_chart(&panel, PLOT_LEFT, x_range, y)?;
        let x_label = |v: &f64| x.label(*v);
        let y_label = |v: &f64| {
            if any_overturned && *v > 1.1 * top {
                String::new()
            } else {
                crate::format::sig(*v, 3)
            }
        };
        let mut mesh = style::xy_mesh(&mut chart, labels::axis(&self.table.axes[0]), "max θ/α (–)");
        mesh.x_label_formatter(&x_label).y_label_formatter(&y_label);
        if let Some(c) = &x.categories {
            mesh.x_labels(c.len().max(2));
        }
        mesh.draw()?;

        if any_overturned {
            chart.draw_series(DashedLineSeries::new(
                vec![(x_range.0, overturn_level), (x_range.1, overturn_level)],
                8,
                6,
                OVERTURN.mix(0.6).stroke_width(1),
            ))?;
        }
        if values.is_empty() && !any_overturned {
            style::note(&panel, "no case has a max θ/α (no tower, or every case failed)")?;
        }
        for (k, (_, points)) in curves.iter().enumerate() {
            let color = curve_color(k, n);
            let line = points.iter().map(|p| match *p {
                Point::Value(x, v) => (x, v),
                Point::Overturned(x) | Point::Gap(x) => (x, f64::NAN),
            });
            for segment in scale::segments(line) {
                chart.draw_series(LineSeries::new(segment.clone(), color.stroke_width(2)))?;
                chart.draw_series(segment.into_iter().map(|p| Circle::new(p, 3, color.filled())))?;
            }
            // Each curve's crosses a little apart, in its colour, so that coinciding ones stay apart.
            let step = (0.08 / n as f64).min(0.012) * top;
            let level = overturn_level + (k as f64 - (n as f64 - 1.0) / 2.0) * step;
            let crosses = points
                .iter()
                .filter_map(|p| if let Point::Overturned(x) = p { Some((*x, level)) } else { None });
            chart.draw_series(crosses.map(|p| Cross::new(p, 6, color.stroke_width(2))))?;
            for (b, block) in blocks.iter().enumerate() {
                let line = block[k].1.iter().map(|p| match *p {
                    Point::Value(x, v) => (x, v),
                    Point::Overturned(x) | Point::Gap(x) => (x, f64::NAN),
                });
                for segment in scale::segments(line) {
                    chart.draw_series(DashedLineSeries::new(segment.clone(), 8, 5, color.stroke_width(2)))?;
                    if b > 0 {
                        chart.draw_series(segment.into_iter().map(|p| Rectangle::new([(p.0, p.1), (p.0, p.1)], color.stroke_width(6))))?;
                    }
                }
            }
        }
        Ok(())
    }
}
