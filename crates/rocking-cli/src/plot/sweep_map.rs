//! `sweep_map.svg`/`.png`: a heat map of max θ/α over the first two swept
//! keys when both are numeric, in viridis with a colour bar; overturned cases
//! in red with a white ×, failed cases grey with a diagonal. One equal cell per
//! case, labelled by the swept values (the spacing of a grid need not be even).

use super::labels;
use super::legend::{self, Entry, Swatch};
use super::style::{self, size, text, text_on, viridis, Figure, GREY, INK, OVERTURN};
use super::sweep_table::{number, Case, SweepTable};
use crate::format::sig;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Size of the figure (px).
pub const SIZE: (u32, u32) = (1000, 700);

/// Width of the colour bar's area at the right (px).
const BAR_AREA: u32 = 130;
/// Left margin plus label area of the map (px).
const PLOT_LEFT: i32 = 100;
/// Grey of a failed case.
const FAILED: RGBColor = RGBColor(205, 205, 205);
/// Values are written in the cells up to this many cells a side.
const MAX_LABELLED: usize = 12;

/// A cell of the map.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Cell {
    Value(f64),
    Overturned,
    Failed,
}

/// The heat map.
pub struct MapFigure<'a> {
    title: &'a str,
    axes: (&'a str, &'a str),
    fixed: Vec<(String, String)>,
    /// The sorted distinct values of each axis.
    xs: Vec<f64>,
    ys: Vec<f64>,
    /// `(i, j, cell)`: the cell at `xs[i]`, `ys[j]`.
    cells: Vec<(usize, usize, Cell)>,
}

/// The sorted distinct numbers of `values` (all numeric, or `None`).
fn numeric_axis(values: &[&str]) -> Option<Vec<f64>> {
    let mut xs: Vec<f64> = values.iter().map(|v| number(v)).collect::<Option<_>>()?;
    xs.sort_by(f64::total_cmp);
    xs.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * a.abs().max(b.abs()));
    Some(xs)
}

/// The tick label at cell position `v` of `values`: the value at a cell's
/// centre (a whole number), nothing between cells.
fn cell_label(values: &[f64], v: f64) -> String {
    let k = v.round();
    if (v - k).abs() > 1e-6 || k < 0.0 {
        return String::new();
    }
    values.get(k as usize).map(|x| sig(*x, 4)).unwrap_or_default()
}

fn index(values: &[f64], x: f64) -> Option<usize> {
    values.iter().position(|v| (v - x).abs() <= 1e-12 * v.abs().max(x.abs()))
}

impl<'a> MapFigure<'a> {
    /// The map of `table`, or `None` unless its first two keys are numeric.
    pub fn new(title: &'a str, table: &'a SweepTable) -> Option<Self> {
        if table.axes.len() < 2 {
            return None;
        }
        let (cases, fixed) = table.selection();
        let xs = numeric_axis(&SweepTable::values(&cases, 0))?;
        let ys = numeric_axis(&SweepTable::values(&cases, 1))?;
        let cells = cases
            .iter()
            .filter_map(|c: &&Case| {
                let i = index(&xs, number(c.keys.first()?)?)?;
                let j = index(&ys, number(c.keys.get(1)?)?)?;
                let cell = match c.value {
                    _ if c.failed => Cell::Failed,
                    _ if c.overturned => Cell::Overturned,
                    Some(v) => Cell::Value(v),
                    None => Cell::Failed,
                };
                Some((i, j, cell))
            })
            .collect();
        Some(Self {
            title,
            axes: (&table.axes[0], &table.axes[1]),
            fixed,
            xs,
            ys,
            cells,
        })
    }

    fn subtitle(&self) -> String {
        let mut parts = vec!["max θ/α of each case".to_string()];
        if !self.fixed.is_empty() {
            let at: Vec<String> = self.fixed.iter().map(|(k, v)| labels::value(k, v)).collect();
            parts.push(format!("at the first value of the further keys: {}", at.join(", ")));
        }
        parts.join(" · ")
    }

    /// The top of the colour scale: the largest max θ/α of a standing tower.
    fn top(&self) -> f64 {
        let top = self
            .cells
            .iter()
            .filter_map(|c| if let Cell::Value(v) = c.2 { Some(v) } else { None })
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max);
        if top > 0.0 {
            top
        } else {
            1.0
        }
    }
}

impl Figure for MapFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let rest = style::title_band(root, self.title, &self.subtitle())?;
        let mut entries = Vec::new();
        if self.cells.iter().any(|c| c.2 == Cell::Overturned) {
            entries.push(Entry::new(Swatch::Square(OVERTURN), "overturned (×)"));
        }
        if self.cells.iter().any(|c| c.2 == Cell::Failed) {
            entries.push(Entry::new(Swatch::Square(FAILED), "failed (no result)"));
        }
        let body = legend::above(&rest, PLOT_LEFT, &entries)?;
        let (w, _) = body.dim_in_pixel();
        let (map, bar) = body.split_horizontally(w.saturating_sub(BAR_AREA));
        let top = self.top();
        style::colour_bar(&bar, top, "max θ/α (–)", None, &|v| viridis(v / top))?;

        // One cell per case, equal in size, at whole-number positions (the
        // values label them): a grid of any spacing reads as a table.
        let (nx, ny) = (self.xs.len().max(1) as f64, self.ys.len().max(1) as f64);
        let mut chart = ChartBuilder::on(&map)
            .margin_left(8)
            .margin_right(16)
            .margin_top(8)
            .margin_bottom(6)
            .y_label_area_size(PLOT_LEFT - 8)
            .x_label_area_size(56)
            .build_cartesian_2d(-0.5..nx - 0.5, -0.5..ny - 0.5)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .label_style(text(size::TICK, INK))
            .axis_desc_style(text(size::AXIS, INK))
            .x_desc(labels::axis(self.axes.0))
            .y_desc(labels::axis(self.axes.1))
            .x_labels(self.xs.len().clamp(2, 12))
            .y_labels(self.ys.len().clamp(2, 12))
            .x_label_formatter(&|v| cell_label(&self.xs, *v))
            .y_label_formatter(&|v| cell_label(&self.ys, *v))
            .draw()?;
        let labelled = self.xs.len() <= MAX_LABELLED && self.ys.len() <= MAX_LABELLED;
        for &(i, j, cell) in &self.cells {
            let (a, b) = ((i as f64 - 0.5, j as f64 - 0.5), (i as f64 + 0.5, j as f64 + 0.5));
            let fill = match cell {
                Cell::Value(v) => viridis(v / top),
                Cell::Overturned => OVERTURN,
                Cell::Failed => FAILED,
            };
            chart.draw_series(std::iter::once(Rectangle::new([a, b], fill.filled())))?;
            chart.draw_series(std::iter::once(Rectangle::new([a, b], WHITE.mix(0.6).stroke_width(1))))?;
            match cell {
                Cell::Overturned => {
                    let style = WHITE.stroke_width(2);
                    chart.draw_series([PathElement::new(vec![a, b], style), PathElement::new(vec![(a.0, b.1), (b.0, a.1)], style)])?;
                }
                Cell::Failed => {
                    chart.draw_series(std::iter::once(PathElement::new(vec![a, b], GREY.stroke_width(1))))?;
                }
                Cell::Value(v) if labelled => {
                    let centre = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
                    let style = text(size::TICK, text_on(fill)).pos(Pos::new(HPos::Center, VPos::Center));
                    chart.draw_series(std::iter::once(Text::new(sig(v, 2), centre, style)))?;
                }
                Cell::Value(_) => {}
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_are_labelled_by_their_values() {
        let values = [0.4, 0.6, 0.9];
        assert_eq!(cell_label(&values, 1.0), "0.6");
        assert_eq!(cell_label(&values, 0.5), "");
        assert_eq!(cell_label(&values, 3.0), "");
        assert_eq!(cell_label(&values, -1.0), "");
    }

    #[test]
    fn only_numeric_axes_make_a_map() {
        assert_eq!(numeric_axis(&["3", "1", "3.0", "2"]), Some(vec![1.0, 2.0, 3.0]));
        assert_eq!(numeric_axis(&["constant", "dynamic"]), None);
    }
}
