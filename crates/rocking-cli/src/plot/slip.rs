//! `slip.svg`/`.png`: how far the building slides on its foundation, and how
//! far the tower's top moves relative to the building, against time; each in
//! mm or m by its size.

use super::legend::{self, Entry, Swatch};
use super::scale;
use super::style::{self, Figure, GREEN, PURPLE};
use super::timeline::{self, Timeline, PLOT_LEFT};
use crate::format::sig;
use plotters::coord::Shift;
use plotters::prelude::*;
use rocking::Sample;
use rocking_scenario::Outcome;

/// Size of the figure (px).
pub const SIZE: (u32, u32) = (1000, 700);

/// The figure of the slip and the top displacement.
pub struct SlipFigure<'a> {
    /// The run.
    pub outcome: &'a Outcome,
    /// Its samples.
    pub samples: &'a [Sample],
    /// Its marks.
    pub timeline: &'a Timeline,
}

/// One quantity against time, in a length unit chosen by its size.
struct Curve<'a> {
    what: &'a str,
    axis: &'a str,
    color: RGBColor,
    points: Vec<(f64, f64)>,
}

impl SlipFigure<'_> {
    fn has_building(&self) -> bool {
        self.outcome.derived.slip_acceleration_g.is_some()
    }

    fn has_tower(&self) -> bool {
        self.outcome.derived.alpha.is_some()
    }

    fn subtitle(&self) -> String {
        let s = &self.outcome.summary;
        let mut parts = Vec::new();
        if self.has_building() {
            let u = scale::length_unit(s.max_abs_slip);
            match s.first_slip_time {
                Some(t) => parts.push(format!(
                    "max |u| = {} {n}, final u = {} {n}, first slip at t = {} s",
                    sig(s.max_abs_slip * u.per_metre, 3),
                    sig(s.final_slip * u.per_metre, 3),
                    sig(t, 4),
                    n = u.name
                )),
                None => parts.push("the building did not slide".into()),
            }
        }
        if self.has_tower() {
            let u = scale::length_unit(s.max_top_displacement);
            parts.push(format!("max |top Δx| = {} {}", sig(s.max_top_displacement * u.per_metre, 3), u.name));
        }
        if !self.has_building() {
            parts.push("no building in this scenario: the tower stands on a fixed base".into());
        }
        if !self.has_tower() {
            parts.push("no tower in this scenario".into());
        }
        parts.join(" · ")
    }

    fn panel<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, curve: Curve<'_>, show_time: bool, impacts: bool) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let tl = self.timeline;
        let peak_m = scale::max_abs(curve.points.iter().map(|p| p.1));
        let unit = scale::length_unit(peak_m);
        // From 0 to the extremes: a slip one way only keeps the whole panel.
        let finite = || curve.points.iter().map(|p| p.1 * unit.per_metre).filter(|v| v.is_finite());
        let y = scale::padded(finite().fold(0.0, f64::min), finite().fold(0.0, f64::max), 0.08);
        let entries = timeline::legend_entries(tl, Entry::new(Swatch::Line(curve.color), curve.what), impacts, None);
        let panel = legend::above(area, PLOT_LEFT, &entries)?;

        let y_desc = format!("{} ({})", curve.axis, unit.name);
        let mut chart = timeline::time_chart(&panel, tl.range, y, &y_desc, show_time)?;
        timeline::draw_slides(&mut chart, tl, y)?;
        let scaled = curve.points.iter().map(|&(t, v)| (t, v * unit.per_metre));
        for segment in scale::segments(scaled) {
            chart.draw_series(LineSeries::new(segment, curve.color.stroke_width(2)))?;
        }
        if impacts {
            timeline::draw_impacts(&mut chart, tl, 0.0, 0.05 * (y.1 - y.0))?;
        }
        timeline::draw_overturn(&mut chart, tl, y)?;
        if peak_m <= 0.0 {
            style::note(&panel, &format!("{} stayed 0", curve.axis))?;
        }
        Ok(())
    }
}

impl Figure for SlipFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let rest = style::title_band(root, &self.outcome.name, &self.subtitle())?;
        let slip = Curve {
            what: "building slip u (relative to the ground)",
            axis: "slip u",
            color: GREEN,
            points: self.samples.iter().map(|s| (s.t, s.state.slip)).collect(),
        };
        let top = Curve {
            what: "top displacement Δx relative to the building",
            axis: "top Δx",
            color: PURPLE,
            points: self.samples.iter().map(|s| (s.t, s.top_dx)).collect(),
        };
        // An absent body has no panel (the subtitle says so).
        match (self.has_building(), self.has_tower()) {
            (true, true) => {
                let (_, h) = rest.dim_in_pixel();
                let (upper, lower) = rest.split_vertically(h / 2);
                self.panel(&upper, slip, false, false)?;
                self.panel(&lower, top, true, true)
            }
            (true, false) => self.panel(&rest, slip, true, false),
            (false, _) => self.panel(&rest, top, true, true),
        }
    }
}
