//! `risk.svg`/`.png` of a fragility study with a site: above, the site's
//! hazard curve of surface PGA (the grid's return periods as points, the
//! power laws extended beyond them dashed); below, for each fitted limit
//! state, where its mean annual frequency comes from — the integrand of
//! `λ_LS = ∫ Φ(ln(a/θ)/β) |dλ/d ln a| d ln a` divided by `λ_LS`
//! ([`HazardCurve::limit_state_density`]), whose area is 1 — with its
//! fragility on the right axis. A reader sees whether the weight lies within
//! the grid's 30–2475 years or in the extrapolation.

use super::legend::{self, Entry, Swatch};
use super::style::{self, size, text, Figure, CYCLE, GREY, INK};
use super::StudyFigures;
use crate::format::sig;
use plotters::coord::Shift;
use plotters::prelude::*;
use rocking_codes::HazardCurve;
use rocking_scenario::fragility_probability;

/// Size of the figure (px).
pub const SIZE: (u32, u32) = (1000, 820);

/// Left margin plus label area of the charts (px): where the legend starts.
const PLOT_LEFT: i32 = 100;

/// Points of each curve, log-spaced over the PGA axis.
const CURVE_POINTS: usize = 400;

/// The risk figure of a study whose site has the hazard curve `curve`.
pub struct RiskFigure<'a> {
    /// The study's figures (its name, limit states and fits).
    pub study: &'a StudyFigures,
    /// The site's hazard curve.
    pub curve: &'a HazardCurve,
}

/// A limit state's curve in the lower chart: its colour's index, its share of
/// λ_LS per unit of ln PGA at log-spaced PGAs, and its fit.
struct Share {
    k: usize,
    points: Vec<(f64, f64)>,
    theta: f64,
    beta: f64,
}

/// `count` log-spaced values from `lo` to `hi` (both > 0).
fn log_spaced(lo: f64, hi: f64, count: usize) -> Vec<f64> {
    let (a, b) = (lo.ln(), hi.ln());
    (0..count).map(|i| (a + (b - a) * i as f64 / (count - 1) as f64).exp()).collect()
}

impl RiskFigure<'_> {
    /// The PGA axis (g): the grid's points and each fit's θ e^(±2.5β), with a margin.
    fn pga_range(&self) -> (f64, f64) {
        let points = self.curve.points();
        let (first, last) = (points[0].pga, points[points.len() - 1].pga);
        self.fits().fold((first / 2.0, last * 1.5), |(lo, hi), (_, _, theta, beta)| {
            (lo.min(theta * (-2.5 * beta).exp()), hi.max(theta * (2.5 * beta).exp()))
        })
    }

    /// The limit states with a fit: (index, name, θ, β).
    fn fits(&self) -> impl Iterator<Item = (usize, &str, f64, f64)> {
        self.study
            .states
            .iter()
            .enumerate()
            .filter_map(|(k, s)| s.fit.map(|(m, b)| (k, s.name.as_str(), m, b)))
    }
}

impl Figure for RiskFigure<'_> {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static,
    {
        let subtitle = "the site's hazard curve of surface PGA, and where each limit state's mean annual frequency λ_LS comes from";
        let rest = style::title_band(root, &self.study.title, subtitle)?;
        let color = |k: usize| CYCLE[k % CYCLE.len()];
        let mut entries = vec![
            Entry::new(Swatch::LineDots(INK), "hazard curve λ(PGA), the grid's return periods as points"),
            Entry::new(Swatch::Dashed(INK), "extended beyond 30 and 2475 years"),
        ];
        for (k, name, theta, beta) in self.fits() {
            let r = self.curve.limit_state_frequency(theta, beta);
            entries.push(Entry::new(
                Swatch::Line(color(k)),
                format!(
                    "{name}: λ_LS = {} per year, {}% of it beyond 2475 years (θ = {} g, β = {})",
                    sig(r.annual_frequency, 3),
                    sig(100.0 * r.share_above, 3),
                    sig(theta, 3),
                    sig(beta, 2)
                ),
            ));
        }
        entries.push(Entry::new(Swatch::Dashed(GREY), "fragility P(limit state | PGA), right axis, in its colour"));
        let panel = legend::above(&rest, PLOT_LEFT, &entries)?;
        let (x_lo, x_hi) = self.pga_range();
        let (upper, lower) = panel.split_vertically(panel.dim_in_pixel().1 * 48 / 100);
        let points = self.curve.points();
        let (first, last) = (points[0].pga, points[points.len() - 1].pga);

        // Above: λ(a), log–log.
        let (y_hi, y_lo) = (self.curve.annual_frequency(x_lo) * 2.0, self.curve.annual_frequency(x_hi).max(1e-9) / 2.0);
        let mut hazard = ChartBuilder::on(&upper)
            .margin_left(8)
            .margin_right(80)
            .margin_top(8)
            .margin_bottom(6)
            .y_label_area_size(PLOT_LEFT - 8)
            .x_label_area_size(50)
            .build_cartesian_2d((x_lo..x_hi).log_scale(), (y_lo..y_hi).log_scale())?;
        hazard
            .configure_mesh()
            .label_style(text(size::TICK, INK))
            .axis_desc_style(text(size::AXIS, INK))
            .bold_line_style(GREY.mix(0.25))
            .light_line_style(GREY.mix(0.08))
            .y_desc("λ: exceedances per year")
            .x_label_formatter(&|v| sig(*v, 2))
            .y_label_formatter(&|v| sig(*v, 2))
            .draw()?;
        let line = |a: f64| (a, self.curve.annual_frequency(a));
        hazard.draw_series(LineSeries::new(
            log_spaced(first, last, CURVE_POINTS).into_iter().map(line),
            INK.stroke_width(2),
        ))?;
        for (a, b) in [(x_lo, first), (last, x_hi)] {
            hazard.draw_series(DashedLineSeries::new(
                log_spaced(a, b, CURVE_POINTS).into_iter().map(line).collect::<Vec<_>>(),
                8,
                5,
                INK.stroke_width(2),
            ))?;
        }
        hazard.draw_series(points.iter().map(|p| Circle::new((p.pga, p.annual_frequency), 4, INK.filled())))?;
        for (a, label) in [(first, "30 years"), (last, "2475 years")] {
            hazard.draw_series(LineSeries::new([(a, y_lo), (a, y_hi)], GREY.stroke_width(1)))?;
            hazard.draw_series(std::iter::once(Text::new(label, (a, y_hi), text(size::TICK, GREY))))?;
        }

        // Below: each limit state's share of λ_LS per unit of ln PGA, and its fragility on the right.
        let shares: Vec<Share> = self
            .fits()
            .map(|(k, _, theta, beta)| {
                let total = self.curve.limit_state_frequency(theta, beta).annual_frequency;
                let points = log_spaced(x_lo, x_hi, CURVE_POINTS)
                    .into_iter()
                    .map(|a| (a, self.curve.limit_state_density(theta, beta, a) / total))
                    .collect();
                Share { k, points, theta, beta }
            })
            .collect();
        let top = shares.iter().flat_map(|s| s.points.iter().map(|p| p.1)).fold(0.0, f64::max);
        let mut weight = ChartBuilder::on(&lower)
            .margin_left(8)
            .margin_right(8)
            .margin_top(8)
            .margin_bottom(6)
            .y_label_area_size(PLOT_LEFT - 8)
            .right_y_label_area_size(72)
            .x_label_area_size(56)
            .build_cartesian_2d((x_lo..x_hi).log_scale(), 0.0..if top > 0.0 { top * 1.08 } else { 1.0 })?
            .set_secondary_coord((x_lo..x_hi).log_scale(), 0.0..1.02);
        weight
            .configure_mesh()
            .label_style(text(size::TICK, INK))
            .axis_desc_style(text(size::AXIS, INK))
            .bold_line_style(GREY.mix(0.25))
            .light_line_style(GREY.mix(0.08))
            .y_desc("share of λ_LS per ln PGA (–)")
            .x_desc("surface PGA = ag · S (g)")
            .x_label_formatter(&|v| sig(*v, 2))
            .y_label_formatter(&|v| sig(*v, 2))
            .draw()?;
        weight
            .configure_secondary_axes()
            .label_style(text(size::TICK, INK))
            .axis_desc_style(text(size::AXIS, INK))
            .y_desc("fragility (–)")
            .y_label_formatter(&|v| sig(*v, 2))
            .draw()?;
        if shares.is_empty() {
            style::note(&lower, "no limit state has a fit: nothing to integrate")?;
        }
        for a in [first, last] {
            weight.draw_series(LineSeries::new([(a, 0.0), (a, top * 1.08)], GREY.stroke_width(1)))?;
        }
        for Share { k, points, theta, beta } in &shares {
            weight.draw_series(LineSeries::new(points.iter().copied(), color(*k).stroke_width(2)))?;
            let fragility: Vec<(f64, f64)> = log_spaced(x_lo, x_hi, CURVE_POINTS)
                .into_iter()
                .map(|a| (a, fragility_probability(a, *theta, *beta)))
                .collect();
            weight.draw_secondary_series(DashedLineSeries::new(fragility, 8, 5, color(*k).stroke_width(1)))?;
        }
        Ok(())
    }
}
