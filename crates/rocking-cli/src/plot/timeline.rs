//! What happened when in a run (the stretches where the building slides, the
//! impacts, the overturning) and the time panels that show it: stacked charts
//! sharing the time axis, with the same left margin so that their time axes
//! line up.

use super::legend::{Entry, Swatch};
use super::scale;
use super::style::{size, text, GREY, INK, ORANGE, VERMILION};
use crate::format::sig;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use rocking::{BuildingRegime, EventKind};
use rocking_scenario::Outcome;

/// A chart of a time panel.
pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Width of the label area left of every panel (px): the same for all, so the panels align.
const Y_LABEL_AREA: u32 = 92;
/// Left margin of every panel (px).
const MARGIN_LEFT: u32 = 8;
/// Where the plotting area of every panel starts (px from the left edge).
pub const PLOT_LEFT: i32 = (MARGIN_LEFT + Y_LABEL_AREA) as i32;

/// The marks of a run on its time axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Timeline {
    /// The time axis, `0 … end` (s).
    pub range: (f64, f64),
    /// The stretches `[start, end]` (s) where the building slides on its foundation.
    pub slides: Vec<(f64, f64)>,
    /// The instants of the tower's impacts (s).
    pub impacts: Vec<f64>,
    /// When the tower overturned (s).
    pub overturn: Option<f64>,
}

impl Timeline {
    /// The marks of `outcome`, from its events (exact instants, not the history's samples).
    pub fn of(outcome: &Outcome) -> Self {
        let last_sample = outcome.history.as_ref().and_then(|h| h.samples.last()).map(|s| s.t);
        let end = [Some(outcome.summary.end_time), last_sample]
            .into_iter()
            .flatten()
            .filter(|t| t.is_finite())
            .fold(0.0, f64::max);
        let range = scale::time_range(end);
        let mut slides = Vec::new();
        let mut sliding_since: Option<f64> = None;
        let mut impacts = Vec::new();
        let mut overturn = None;
        for e in outcome.events.iter().filter(|e| e.time.is_finite()) {
            match e.kind {
                // The tower's: a block's impacts are drawn by its own curve.
                EventKind::Impact if e.block == 0 => impacts.push(e.time),
                EventKind::Overturn => overturn = Some(e.time),
                _ => {}
            }
            let slides_now = matches!(e.regime.building, BuildingRegime::Slip(_));
            match (sliding_since, slides_now) {
                (None, true) => sliding_since = Some(e.time),
                (Some(start), false) => {
                    slides.push((start, e.time));
                    sliding_since = None;
                }
                _ => {}
            }
        }
        if let Some(start) = sliding_since {
            slides.push((start, range.1.max(start)));
        }
        let overturn = overturn.or(outcome.summary.overturn_time.filter(|t| t.is_finite()));
        Self {
            range,
            slides,
            impacts,
            overturn,
        }
    }
}

/// A panel over `t` with the value range `y`, described by `y_desc`. The
/// bottom panel shows the time labels (`show_time`); panels above it only the grid.
/// The legend of a time panel: its `curve`, the impact ticks (if `impacts`),
/// `extra` (a level line of the panel), the slip bands and the overturn line,
/// each only when the run has them.
pub fn legend_entries(timeline: &Timeline, curve: Entry, impacts: bool, extra: Option<Entry>) -> Vec<Entry> {
    let mut entries = vec![curve];
    if impacts && !timeline.impacts.is_empty() {
        entries.push(Entry::new(Swatch::Tick(INK), "impact"));
    }
    entries.extend(extra);
    if !timeline.slides.is_empty() {
        entries.push(Entry::new(Swatch::Band(ORANGE, 0.3), "building slides"));
    }
    if timeline.overturn.is_some() {
        entries.push(Entry::new(Swatch::Line(VERMILION), "overturned"));
    }
    entries
}

pub fn time_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    t: (f64, f64),
    y: (f64, f64),
    y_desc: &str,
    show_time: bool,
) -> anyhow::Result<Chart<'a, DB>>
where
    DB::ErrorType: 'static,
{
    let mut chart = ChartBuilder::on(area)
        .margin_left(MARGIN_LEFT)
        .margin_right(24)
        .margin_top(8)
        .margin_bottom(if show_time { 4 } else { 2 })
        .y_label_area_size(Y_LABEL_AREA)
        .x_label_area_size(if show_time { 56 } else { 6 })
        .build_cartesian_2d(t.0..t.1, y.0..y.1)?;
    let no_label = |_: &f64| String::new();
    let y_tick = |v: &f64| scale::tick(*v, y.1 - y.0);
    let t_tick = |v: &f64| scale::tick(*v, t.1 - t.0);
    let mut mesh = chart.configure_mesh();
    mesh.label_style(text(size::TICK, INK))
        .axis_desc_style(text(size::AXIS, INK))
        .bold_line_style(GREY.mix(0.25))
        .light_line_style(GREY.mix(0.08))
        .y_desc(y_desc)
        .y_labels(7)
        .y_label_formatter(&y_tick)
        .x_labels(12);
    if show_time {
        mesh.x_desc("time t (s)").x_label_formatter(&t_tick);
    } else {
        mesh.x_label_formatter(&no_label);
    }
    mesh.draw()?;
    Ok(chart)
}

/// Draws the impacts as short ticks across `level` (θ = 0 at an impact), `h` high each side.
pub fn draw_impacts<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, timeline: &Timeline, level: f64, h: f64) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    chart.draw_series(
        timeline
            .impacts
            .iter()
            .map(|&t| PathElement::new(vec![(t, level - h), (t, level + h)], INK.stroke_width(1))),
    )?;
    Ok(())
}

/// Draws the slide bands over the full height `y` (under the curves: call first).
pub fn draw_slides<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, timeline: &Timeline, y: (f64, f64)) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    if timeline.slides.is_empty() {
        return Ok(());
    }
    let fill = ORANGE.mix(0.22).filled();
    chart.draw_series(timeline.slides.iter().map(|&(a, b)| Rectangle::new([(a, y.0), (b, y.1)], fill)))?;
    Ok(())
}

/// Draws a vertical line at the overturning instant over the full height `y`.
pub fn draw_overturn<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, timeline: &Timeline, y: (f64, f64)) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let Some(t) = timeline.overturn else {
        return Ok(());
    };
    let style = VERMILION.stroke_width(3);
    chart.draw_series(std::iter::once(PathElement::new(vec![(t, y.0), (t, y.1)], style)))?;
    Ok(())
}

/// Writes "overturned at t = …" just left of the overturning line, at the top
/// of the panel or (`top` false) at its bottom.
pub fn label_overturn<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, timeline: &Timeline, y: (f64, f64), top: bool) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let Some(t) = timeline.overturn else {
        return Ok(());
    };
    let (t0, t1) = timeline.range;
    let (level, v) = if top {
        (y.1 - 0.03 * (y.1 - y.0), VPos::Top)
    } else {
        (y.0 + 0.03 * (y.1 - y.0), VPos::Bottom)
    };
    let label = text(size::LEGEND, VERMILION).pos(Pos::new(HPos::Right, v));
    chart.draw_series(std::iter::once(Text::new(
        format!("overturned at t = {} s", sig(t, 4)),
        (t - 0.006 * (t1 - t0), level),
        label,
    )))?;
    Ok(())
}

/// Draws a horizontal dashed line at `y` across the time range.
pub fn dashed_level<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, t: (f64, f64), y: f64, style: ShapeStyle) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    chart.draw_series(DashedLineSeries::new(vec![(t.0, y), (t.1, y)], 8, 6, style))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rocking::{Event, Pivot, Regime, SlipDirection, State, TowerRegime};

    fn event(time: f64, kind: EventKind, tower: TowerRegime, building: BuildingRegime) -> Event {
        let state = State {
            theta: 0.0,
            theta_dot: 0.0,
            slip: 0.0,
            slip_vel: 0.0,
        };
        Event {
            time,
            kind,
            before: state,
            after: state,
            regime: Regime { tower, building },
            block: 0,
        }
    }

    #[test]
    fn slides_open_at_slip_and_close_at_stick_or_the_end() {
        use BuildingRegime::{Slip, Stick};
        let rocks = TowerRegime::Rocking(Pivot::Positive);
        let events = [
            event(0.1, EventKind::Uplift, rocks, Stick),
            event(0.2, EventKind::Slip, rocks, Slip(SlipDirection::Positive)),
            event(0.3, EventKind::Impact, rocks, Slip(SlipDirection::Positive)),
            event(0.35, EventKind::Reverse, rocks, Slip(SlipDirection::Negative)),
            event(0.4, EventKind::Stick, rocks, Stick),
            event(0.5, EventKind::Slip, TowerRegime::Rest, Slip(SlipDirection::Negative)),
        ];
        let mut outcome = crate::plot::tests::outcome_with(&events, 0.8);
        let timeline = Timeline::of(&outcome);
        assert_eq!(timeline.slides, vec![(0.2, 0.4), (0.5, 0.8)]);
        assert_eq!(timeline.impacts, vec![0.3]);
        assert_eq!(timeline.overturn, None);
        assert_eq!(timeline.range, (0.0, 0.8));
        outcome.summary.end_time = 0.0;
        outcome.history = None;
        assert_eq!(Timeline::of(&outcome).range, (0.0, 1e-3), "an empty run still has a time axis");
    }
}
