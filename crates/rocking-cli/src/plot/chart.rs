//! A chart on linear axes from zero: curves and labelled points (the
//! capacity curve in the ADRS plane with the demand points, the response of a
//! record set against λ), for the pages that inline their figures.

use super::legend::{self, Entry, Shape, Swatch};
use super::spectra::Curve;
use super::style::{self, size, text, Figure, GREY, INK};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Size of the charts (px).
pub const SIZE: (u32, u32) = (1000, 620);

/// Left margin plus label area of the chart (px).
const PLOT_LEFT: i32 = 90;

/// A labelled point.
#[derive(Debug, Clone)]
pub struct Marker {
    /// Its label, written beside it and in the legend.
    pub label: String,
    /// x, y in the axes' units.
    pub at: (f64, f64),
    /// Its shape (a cross for a failure).
    pub shape: Shape,
    /// Its colour.
    pub color: RGBColor,
}

/// A chart of curves and markers on linear axes.
#[derive(Debug, Clone)]
pub struct LineChart {
    /// Title.
    pub title: String,
    /// Subtitle.
    pub subtitle: String,
    /// x axis label with its unit.
    pub x_label: String,
    /// y axis label with its unit.
    pub y_label: String,
    /// The curves.
    pub curves: Vec<Curve>,
    /// The markers.
    pub markers: Vec<Marker>,
}

impl Figure for LineChart {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let rest = style::title_band(root, &self.title, &self.subtitle)?;
        let mut entries: Vec<Entry> = self.curves.iter().filter_map(Curve::legend_entry).collect();
        for m in &self.markers {
            entries.push(Entry::new(Swatch::Point(m.shape, m.color), m.label.clone()));
        }
        let panel = legend::above(&rest, PLOT_LEFT, &entries)?;
        let finite = |v: &f64| v.is_finite();
        let xs = self
            .curves
            .iter()
            .flat_map(|c| c.points.iter().map(|p| p.0))
            .chain(self.markers.iter().map(|m| m.at.0));
        let ys = self
            .curves
            .iter()
            .flat_map(|c| c.points.iter().map(|p| p.1))
            .chain(self.markers.iter().map(|m| m.at.1));
        let x_hi = xs.filter(finite).fold(0.0f64, f64::max);
        let y_hi = ys.filter(finite).fold(0.0f64, f64::max);
        if !(x_hi > 0.0 && y_hi > 0.0) {
            style::note(&panel, "nothing to draw: no positive value")?;
            return Ok(());
        }
        let mut chart = ChartBuilder::on(&panel)
            .margin_left(8)
            .margin_right(24)
            .margin_top(8)
            .margin_bottom(6)
            .y_label_area_size(PLOT_LEFT - 8)
            .x_label_area_size(56)
            .build_cartesian_2d(0.0..x_hi * 1.05, 0.0..y_hi * 1.1)?;
        chart
            .configure_mesh()
            .label_style(text(size::TICK, INK))
            .axis_desc_style(text(size::AXIS, INK))
            .bold_line_style(GREY.mix(0.25))
            .light_line_style(GREY.mix(0.08))
            .x_desc(self.x_label.clone())
            .y_desc(self.y_label.clone())
            .x_label_formatter(&|v| crate::format::sig(*v, 3))
            .y_label_formatter(&|v| crate::format::sig(*v, 3))
            .draw()?;
        for c in &self.curves {
            let line = c.ink_color().stroke_width(c.width);
            let points: Vec<(f64, f64)> = c.points.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
            if c.dashed {
                chart.draw_series(DashedLineSeries::new(points, 8, 5, line))?;
            } else {
                chart.draw_series(LineSeries::new(points, line))?;
            }
        }
        for m in &self.markers {
            legend::point(chart.plotting_area(), m.at, m.shape, m.color)?;
        }
        Ok(())
    }
}
