//! Figures of `rocking spectrum`, on log-log axes: the records' response
//! spectra (`spectra`), the code spectra of the limit states (`code_spectra`),
//! and for each limit state a record set is fitted to, the scaled records, their
//! mean and the target with the code's 0.90–1.30 band over the fitting range
//! (`fit_<LS>`).

use super::legend::{self, Entry, Swatch};
use super::style::{self, size, text, Figure, GREY, INK};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Size of the figures (px).
pub const SIZE: (u32, u32) = (1000, 680);

/// Left margin plus label area of the chart (px): where the legend starts.
const PLOT_LEFT: i32 = 90;

/// The colour of a curve, by its role.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ink {
    /// The `index`-th of `of` curves of the same kind (records, limit states).
    Series {
        /// Its place.
        index: usize,
        /// How many there are.
        of: usize,
    },
    /// A target spectrum.
    Target,
    /// The mean of a set.
    Mean,
    /// One of many records behind a mean.
    Faint,
}

impl Ink {
    fn color(self) -> RGBColor {
        match self {
            Ink::Series { index, of } => style::curve_color(index, of),
            Ink::Target => style::VERMILION,
            Ink::Mean => BLACK,
            Ink::Faint => style::SKY,
        }
    }
}

impl Curve {
    /// Its colour.
    pub fn ink_color(&self) -> RGBColor {
        self.ink.color()
    }

    /// Its legend entry, if it has a label: a line, dashed as the curve is.
    pub fn legend_entry(&self) -> Option<Entry> {
        let swatch = if self.dashed {
            Swatch::Dashed(self.ink_color())
        } else {
            Swatch::Line(self.ink_color())
        };
        self.label.as_ref().map(|l| Entry::new(swatch, l.clone()))
    }
}

/// One curve of a spectra figure.
#[derive(Debug, Clone)]
pub struct Curve {
    /// Its legend (`None`: not in the legend, e.g. the records of a fitted set).
    pub label: Option<String>,
    /// Its colour.
    pub ink: Ink,
    /// Its width (px).
    pub width: u32,
    /// Dashed or solid.
    pub dashed: bool,
    /// `(period s, value)`, increasing periods; values ≤ 0 are left out on log axes.
    pub points: Vec<(f64, f64)>,
}

/// A shaded band of a spectra figure: the code's tolerance about a target.
#[derive(Debug, Clone)]
pub struct Band {
    /// Its legend.
    pub label: String,
    /// `(period s, low, high)`, increasing periods.
    pub points: Vec<(f64, f64, f64)>,
}

/// A figure of spectra against the period, log-log.
#[derive(Debug, Clone)]
pub struct SpectraFigure {
    /// The title.
    pub title: String,
    /// The line under it.
    pub subtitle: String,
    /// The y axis's name with its unit.
    pub y_label: String,
    /// The curves, drawn in order (the last on top).
    pub curves: Vec<Curve>,
    /// A shaded band under the curves.
    pub band: Option<Band>,
    /// The fitting range (s), marked by two vertical lines.
    pub range: Option<(f64, f64)>,
}

/// Powers of ten and their halves and fifths within `[lo, hi]`: the ticks of a log axis.
fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    (a..=b)
        .flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
        .filter(|v| *v >= lo * (1.0 - 1e-9) && *v <= hi * (1.0 + 1e-9))
        .collect()
}

impl Figure for SpectraFigure {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let rest = style::title_band(root, &self.title, &self.subtitle)?;
        let mut entries: Vec<Entry> = self.curves.iter().filter_map(Curve::legend_entry).collect();
        if let Some(band) = &self.band {
            entries.push(Entry::new(Swatch::Band(style::VERMILION, 0.15), band.label.clone()));
        }
        if self.range.is_some() {
            entries.push(Entry::new(Swatch::Tick(GREY), "fitting range"));
        }
        let panel = legend::above(&rest, PLOT_LEFT, &entries)?;

        let positive = |v: f64| v.is_finite() && v > 0.0;
        let xs = self.curves.iter().flat_map(|c| c.points.iter().map(|p| p.0)).filter(|x| positive(*x));
        let (x_lo, x_hi) = xs.fold((f64::INFINITY, 0.0f64), |(lo, hi), x| (lo.min(x), hi.max(x)));
        let mut ys: Vec<f64> = self.curves.iter().flat_map(|c| c.points.iter().map(|p| p.1)).filter(|y| positive(*y)).collect();
        if let Some(band) = &self.band {
            ys.extend(band.points.iter().flat_map(|b| [b.1, b.2]).filter(|y| positive(*y)));
        }
        let (y_lo, y_hi) = ys.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &y| (lo.min(y), hi.max(y)));
        if !(x_lo < x_hi && y_lo <= y_hi) {
            style::note(&panel, "nothing to draw: no positive value")?;
            return Ok(());
        }
        // A margin of 10% in log on y, and at least a decade shown.
        let (y_lo, y_hi) = if y_hi / y_lo < 10.0 {
            ((y_lo * y_hi).sqrt() / 10f64.sqrt(), (y_lo * y_hi).sqrt() * 10f64.sqrt())
        } else {
            (y_lo / 1.3, y_hi * 1.3)
        };
        let mut chart = ChartBuilder::on(&panel)
            .margin_left(8)
            .margin_right(24)
            .margin_top(8)
            .margin_bottom(6)
            .y_label_area_size(PLOT_LEFT - 8)
            .x_label_area_size(56)
            .build_cartesian_2d(
                (x_lo..x_hi).log_scale().with_key_points(log_ticks(x_lo, x_hi)),
                (y_lo..y_hi).log_scale().with_key_points(log_ticks(y_lo, y_hi)),
            )?;
        chart
            .configure_mesh()
            .label_style(text(size::TICK, INK))
            .axis_desc_style(text(size::AXIS, INK))
            .bold_line_style(GREY.mix(0.25))
            .light_line_style(GREY.mix(0.08))
            .x_desc("period T (s)")
            .y_desc(self.y_label.clone())
            .x_label_formatter(&|v| crate::format::sig(*v, 2))
            .y_label_formatter(&|v| crate::format::sig(*v, 2))
            .draw()?;
        if let Some(band) = &self.band {
            let upper = band.points.iter().map(|b| (b.0, b.2));
            let lower = band.points.iter().rev().map(|b| (b.0, b.1));
            let outline: Vec<(f64, f64)> = upper.chain(lower).collect();
            chart.draw_series(std::iter::once(Polygon::new(outline, style::VERMILION.mix(0.15).filled())))?;
        }
        if let Some((a, b)) = self.range {
            for t in [a, b] {
                chart.draw_series(LineSeries::new([(t, y_lo), (t, y_hi)], GREY.stroke_width(1)))?;
            }
        }
        for c in &self.curves {
            let points: Vec<(f64, f64)> = c.points.iter().copied().filter(|p| positive(p.0) && positive(p.1)).collect();
            let line = c.ink.color().stroke_width(c.width);
            if c.dashed {
                chart.draw_series(DashedLineSeries::new(points, 8, 5, line))?;
            } else {
                chart.draw_series(LineSeries::new(points, line))?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::log_ticks;

    #[test]
    fn ticks_of_a_log_axis() {
        assert_eq!(log_ticks(0.02, 4.0), [0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0]);
    }
}
