//! `ida.svg`/`.png`: the response field of the first limit state against the
//! intensity level, one line per record (an incremental dynamic analysis
//! plot); the limit state's threshold as a dashed line, overturned cases as
//! crosses, failed cases as gaps.

use super::legend::{self, Entry, Swatch};
use super::scale;
use super::style::{self, curve_color, Figure, INK, OVERTURN};
use super::StudyFigures;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Size of the figure (px).
pub const SIZE: (u32, u32) = (1000, 650);

/// Left margin plus label area of the chart (px): where the legend starts.
const PLOT_LEFT: i32 = 100;

/// The most records named in the legend.
const MAX_LEGEND: usize = 8;

/// The IDA figure of a study.
pub struct IdaFigure<'a>(pub &'a StudyFigures);

impl Figure for IdaFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let s = self.0;
        let n = s.ida.len();
        let subtitle = format!("{} against {}, one line per record ({n} records)", s.ida_field, s.measure_label());
        let rest = style::title_band(root, &s.title, &subtitle)?;
        let values: Vec<f64> = s
            .ida
            .iter()
            .flat_map(|c| c.points.iter().filter_map(|p| p.1))
            .filter(|v| v.is_finite())
            .collect();
        let levels: Vec<f64> = s.ida.iter().flat_map(|c| c.points.iter().map(|p| p.0)).collect();
        let top = values.iter().copied().chain(s.ida_threshold).fold(0.0, f64::max);
        let top = if top > 0.0 { top } else { 1.0 };
        let bottom = values.iter().copied().fold(0.0, f64::min);
        let (x_lo, x_hi) = levels.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        let x_range = if x_lo.is_finite() {
            scale::padded(x_lo.min(0.0), x_hi, 0.03)
        } else {
            (0.0, 1.0)
        };

        let mut entries: Vec<Entry> = s
            .ida
            .iter()
            .enumerate()
            .filter(|(k, _)| n <= MAX_LEGEND || *k < MAX_LEGEND - 1)
            .map(|(k, c)| Entry::new(Swatch::LineDots(curve_color(k, n)), short(&c.record)))
            .collect();
        if n > MAX_LEGEND {
            entries.push(Entry::new(Swatch::Line(WHITE), format!("(and {} more)", n - entries.len())));
        }
        if s.ida_threshold.is_some() {
            entries.push(Entry::new(Swatch::Dashed(OVERTURN), "limit state"));
        }
        if s.ida.iter().any(|c| c.points.iter().any(|p| p.2)) {
            entries.push(Entry::new(Swatch::Cross(INK), "overturned"));
        }
        let panel = legend::above(&rest, PLOT_LEFT, &entries)?;

        let mut chart = style::xy_chart(&panel, PLOT_LEFT, x_range, (bottom.min(0.0), 1.1 * top))?;
        style::xy_mesh(&mut chart, s.measure_label(), s.ida_field.clone())
            .x_label_formatter(&|v| crate::format::sig(*v, 3))
            .y_label_formatter(&|v| crate::format::sig(*v, 3))
            .draw()?;
        if let Some(limit) = s.ida_threshold {
            chart.draw_series(DashedLineSeries::new(
                vec![(x_range.0, limit), (x_range.1, limit)],
                8,
                6,
                OVERTURN.mix(0.7).stroke_width(1),
            ))?;
        }
        if values.is_empty() {
            style::note(&panel, "no case has a value of this field")?;
        }
        for (k, curve) in s.ida.iter().enumerate() {
            let color = curve_color(k, n);
            let line = curve.points.iter().map(|&(x, v, _)| (x, v.unwrap_or(f64::NAN)));
            for segment in scale::segments(line) {
                chart.draw_series(LineSeries::new(segment.clone(), color.stroke_width(2)))?;
                chart.draw_series(segment.into_iter().map(|p| Circle::new(p, 2, color.filled())))?;
            }
            let crosses = curve
                .points
                .iter()
                .filter(|p| p.2)
                .filter_map(|&(x, v, _)| v.filter(|v| v.is_finite()).map(|v| (x, v)));
            chart.draw_series(crosses.map(|p| Cross::new(p, 5, color.stroke_width(2))))?;
        }
        Ok(())
    }
}

/// The file name of a record path (the legend has little room).
fn short(path: &str) -> String {
    path.rsplit('/').next().unwrap_or(path).to_string()
}
