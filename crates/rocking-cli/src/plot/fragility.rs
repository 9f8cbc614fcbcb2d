//! `fragility.svg`/`.png`: for every limit state, the observed fraction of
//! cases exceeding it at each level (points) and the fitted lognormal
//! fragility `Φ(ln(x/θ)/β)` (a curve; none where no fit exists).

use super::legend::{self, Entry, Swatch};
use super::scale;
use super::style::{self, Figure, CYCLE};
use super::StudyFigures;
use plotters::coord::Shift;
use plotters::prelude::*;
use rocking_scenario::fragility_probability;

/// Size of the figure (px).
pub const SIZE: (u32, u32) = (1000, 650);

/// Left margin plus label area of the chart (px): where the legend starts.
const PLOT_LEFT: i32 = 90;

/// Points of each fitted curve.
const CURVE_POINTS: usize = 200;

/// The fragility figure of a study.
pub struct FragilityFigure<'a>(pub &'a StudyFigures);

impl Figure for FragilityFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let s = self.0;
        let subtitle = format!(
            "probability of exceeding each limit state against {}: observed fractions and lognormal fits",
            s.measure_label()
        );
        let rest = style::title_band(root, &s.title, &subtitle)?;
        let color = |k: usize| CYCLE[k % CYCLE.len()];
        let entries: Vec<Entry> = s
            .states
            .iter()
            .enumerate()
            .map(|(k, state)| {
                let (name, fit) = (&state.name, &state.fit);
                let label = match fit {
                    Some((m, b)) => format!("{name}: median {}, β {}", crate::format::sig(*m, 3), crate::format::sig(*b, 2)),
                    None => format!("{name}: no fit"),
                };
                Entry::new(Swatch::LineDots(color(k)), label)
            })
            .collect();
        let panel = legend::above(&rest, PLOT_LEFT, &entries)?;
        let levels: Vec<f64> = s.states.iter().flat_map(|st| st.stripes.iter().map(|p| p.level)).collect();
        let x_hi = levels.iter().copied().fold(0.0, f64::max);
        let x_range = scale::padded(0.0, if x_hi > 0.0 { x_hi } else { 1.0 }, 0.03);
        let mut chart = style::xy_chart(&panel, PLOT_LEFT, x_range, (0.0, 1.02))?;
        style::xy_mesh(&mut chart, s.measure_label(), "probability of exceedance")
            .x_label_formatter(&|v| crate::format::sig(*v, 3))
            .y_label_formatter(&|v| crate::format::sig(*v, 2))
            .draw()?;
        if s.states.is_empty() {
            style::note(&panel, "the study has no limit state")?;
        }
        for (k, state) in s.states.iter().enumerate() {
            let (stripes, fit) = (&state.stripes, &state.fit);
            let c = color(k);
            if let Some((m, b)) = fit {
                let curve = (1..=CURVE_POINTS).map(|i| {
                    let x = x_range.1 * i as f64 / CURVE_POINTS as f64;
                    (x, fragility_probability(x, *m, *b))
                });
                chart.draw_series(LineSeries::new(curve, c.stroke_width(2)))?;
            }
            let points = stripes.iter().filter(|p| p.cases > 0).map(|p| (p.level, p.exceeded as f64 / p.cases as f64));
            chart.draw_series(points.map(|p| Circle::new(p, 4, c.filled())))?;
        }
        Ok(())
    }
}
