//! `theta.svg`/`.png`: the tower's rotation θ/α against time (the paper's
//! Figure 7) above the ground acceleration in g (and the vertical one, with
//! `[ground.vertical]`), sharing the time axis, with the impacts, the
//! stretches where the building slides and the overturning marked.

use super::legend::{self, Entry, Swatch};
use super::scale;
use super::style::{self, Figure, BLUE, GREEN, GREY, INK, ORANGE, PURPLE, VERMILION};
use super::timeline::{self, Timeline, PLOT_LEFT};
use crate::format::sig;
use plotters::coord::Shift;
use plotters::prelude::*;
use rocking::Sample;
use rocking_scenario::Outcome;

/// A block's name, colour and curve of θ/α against time.
type BlockCurve = (String, RGBColor, Vec<(f64, f64)>);

/// The colours of the blocks' curves, the lowest block first.
const BLOCK_COLOURS: [RGBColor; 3] = [VERMILION, GREEN, PURPLE];

/// Size of the figure (px).
pub const SIZE: (u32, u32) = (1000, 700);

/// The figure of θ/α and a_g.
pub struct ThetaFigure<'a> {
    /// The run.
    pub outcome: &'a Outcome,
    /// Its samples.
    pub samples: &'a [Sample],
    /// Its marks.
    pub timeline: &'a Timeline,
}

/// Gravity (m/s²) of the run, recovered from the tower's derived quantities
/// (`p² = m₂ g R / I_O`); `None` without a tower. The outcome does not carry
/// `simulation.g` itself.
pub fn gravity(outcome: &Outcome) -> Option<f64> {
    let d = &outcome.derived;
    let (p, inertia, mass, radius) = (d.p?, d.inertia_pivot?, d.tower_mass?, d.radius?);
    let g = p * p * inertia / (mass * radius);
    (g.is_finite() && g > 0.0).then_some(g)
}

/// α of the tower, if there is one.
fn alpha(outcome: &Outcome) -> Option<f64> {
    outcome.derived.alpha.filter(|a| a.is_finite() && *a > 0.0)
}

impl ThetaFigure<'_> {
    fn subtitle(&self) -> String {
        let s = &self.outcome.summary;
        let Some(a) = alpha(self.outcome) else {
            return "no tower in this scenario: the ground acceleration only".into();
        };
        let names = self.outcome.layout.blocks;
        let fate = match (s.overturn_time, s.stack.and_then(|st| st.overturned_block)) {
            (Some(t), Some(k)) if k > 0 => format!("{} OVERTURNED at t = {} s", names.name(k), sig(t, 4)),
            (Some(t), _) => format!("OVERTURNED at t = {} s", sig(t, 4)),
            (None, _) => "did not overturn".into(),
        };
        let mut line = format!(
            "max θ/α = {} · {} impacts · {fate} · α = {} rad (tan α = {})",
            sig(s.max_abs_theta() / a, 3),
            s.impacts,
            sig(a, 4),
            sig(a.tan(), 3)
        );
        if let Some(stack) = s.stack {
            for (i, (block, summary)) in self.outcome.blocks.iter().zip(stack.blocks()).enumerate() {
                line.push_str(&format!(
                    " · {}: max θ/α = {}, {} impacts",
                    names.name(i + 1),
                    sig(summary.max_abs_theta / block.alpha(), 3),
                    summary.impacts
                ));
            }
        }
        line
    }

    fn theta_panel<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let tl = self.timeline;
        let Some(a) = alpha(self.outcome) else {
            return Ok(());
        };
        let points: Vec<(f64, f64)> = self.samples.iter().map(|s| (s.t, s.state.theta / a)).collect();
        // Each block on the tower: its rotation on the block below over its own α.
        let names = self.outcome.layout.blocks;
        let blocks: Vec<BlockCurve> = self
            .outcome
            .blocks
            .iter()
            .enumerate()
            .map(|(i, block)| {
                let curve = self
                    .samples
                    .iter()
                    .map(|s| (s.t, s.stack.map_or(0.0, |st| st.theta[i + 1]) / block.alpha()))
                    .collect();
                (names.name(i + 1).to_string(), BLOCK_COLOURS[i % BLOCK_COLOURS.len()], curve)
            })
            .collect();
        let peak = scale::max_abs(points.iter().chain(blocks.iter().flat_map(|b| b.2.iter())).map(|p| p.1));
        let y = scale::symmetric(peak);
        let bounds = peak > 0.0 && y.1 >= 1.0;
        let tower = if blocks.is_empty() { "θ/α" } else { "tower θ/α" };
        let mut entries = timeline::legend_entries(
            tl,
            Entry::new(Swatch::Line(BLUE), tower),
            true,
            bounds.then(|| Entry::new(Swatch::Dashed(GREY), "θ = ±α")),
        );
        for (name, colour, _) in &blocks {
            entries.insert(1, Entry::new(Swatch::Line(*colour), format!("{name} θ/α (on the block below, its own α)")));
        }
        let panel = legend::above(area, PLOT_LEFT, &entries)?;

        let mut chart = timeline::time_chart(&panel, tl.range, y, "rotation θ/α (–)", false)?;
        timeline::draw_slides(&mut chart, tl, y)?;
        if bounds {
            for level in [-1.0, 1.0] {
                timeline::dashed_level(&mut chart, tl.range, level, GREY.stroke_width(2))?;
            }
        }
        for segment in scale::segments(points) {
            chart.draw_series(LineSeries::new(segment, BLUE.stroke_width(2)))?;
        }
        for (_, colour, curve) in blocks {
            for segment in scale::segments(curve) {
                chart.draw_series(LineSeries::new(segment, colour.stroke_width(2)))?;
            }
        }
        let h = 0.05 * (y.1 - y.0);
        timeline::draw_impacts(&mut chart, tl, 0.0, h)?;
        timeline::draw_overturn(&mut chart, tl, y)?;
        // The label away from where the rotation ends (at ±π/2α, in a corner).
        let last = self.samples.last().map_or(0.0, |s| s.state.theta);
        timeline::label_overturn(&mut chart, tl, y, last <= 0.0)?;
        if peak <= 0.0 {
            style::note(&panel, "the tower did not lift off")?;
        }
        Ok(())
    }

    fn ground_panel<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let tl = self.timeline;
        let d = &self.outcome.derived;
        let g = gravity(self.outcome);
        let (per_unit, unit) = match g {
            Some(g) => (1.0 / g, "g"),
            None => (1.0, "m/s²"),
        };
        let points: Vec<(f64, f64)> = self.samples.iter().map(|s| (s.t, s.ground_acc * per_unit)).collect();
        let vertical: Vec<(f64, f64)> = if self.outcome.layout.vertical {
            self.samples.iter().map(|s| (s.t, s.ground_acc_v * per_unit)).collect()
        } else {
            Vec::new()
        };
        let peak = scale::max_abs(points.iter().chain(&vertical).map(|p| p.1));
        // The thresholds are in g: shown when the axis is in g and they are not far off the signal.
        let shown = |threshold: Option<f64>| threshold.filter(|x| g.is_some() && x.is_finite() && *x > 0.0 && peak > 0.0 && *x <= 2.0 * peak);
        let (uplift, slip) = (shown(d.uplift_acceleration_g), shown(d.slip_acceleration_g));
        let y = scale::symmetric(peak.max(uplift.unwrap_or(0.0)).max(slip.unwrap_or(0.0)));

        let mut entries = vec![Entry::new(Swatch::Line(INK), "ground acceleration a_g")];
        if !vertical.is_empty() {
            entries.push(Entry::new(Swatch::Line(PURPLE), "vertical a_v (up)"));
        }
        // Without a tower panel above, the bands are explained here.
        if alpha(self.outcome).is_none() && !tl.slides.is_empty() {
            entries.push(Entry::new(Swatch::Band(ORANGE, 0.3), "building slides"));
        }
        if let Some(x) = uplift {
            entries.push(Entry::new(Swatch::Dashed(GREEN), format!("±tan α = ±{} g: uplift", sig(x, 3))));
        }
        if let Some(x) = slip {
            entries.push(Entry::new(Swatch::Dashed(ORANGE), format!("±μs = ±{} g: slip", sig(x, 3))));
        }
        let panel = legend::above(area, PLOT_LEFT, &entries)?;

        let label = if vertical.is_empty() {
            format!("a_g ({unit})")
        } else {
            format!("a_g, a_v ({unit})")
        };
        let mut chart = timeline::time_chart(&panel, tl.range, y, &label, true)?;
        timeline::draw_slides(&mut chart, tl, y)?;
        for (level, color) in [(uplift, GREEN), (slip, ORANGE)] {
            if let Some(x) = level {
                for sign in [-1.0, 1.0] {
                    timeline::dashed_level(&mut chart, tl.range, sign * x, color.stroke_width(2))?;
                }
            }
        }
        // a_v over a_g: the smaller of the two as a rule, it would hide under it.
        for segment in scale::segments(points) {
            chart.draw_series(LineSeries::new(segment, INK.stroke_width(1)))?;
        }
        for segment in scale::segments(vertical) {
            chart.draw_series(LineSeries::new(segment, PURPLE.stroke_width(1)))?;
        }
        timeline::draw_overturn(&mut chart, tl, y)?;
        if peak <= 0.0 {
            style::note(&panel, "a_g = 0 at every sample")?;
        }
        Ok(())
    }
}

impl Figure for ThetaFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let rest = style::title_band(root, &self.outcome.name, &self.subtitle())?;
        if alpha(self.outcome).is_none() {
            return self.ground_panel(&rest);
        }
        let (_, h) = rest.dim_in_pixel();
        let (upper, lower) = rest.split_vertically((f64::from(h) * 0.58) as u32);
        self.theta_panel(&upper)?;
        self.ground_panel(&lower)?;
        Ok(())
    }
}
