//! The look shared by every figure: the embedded font, the colours, the text
//! sizes, and writing one drawing as both SVG and PNG.
//!
//! Text is drawn with DejaVu Sans, embedded in the binary and registered with
//! plotters' `ab_glyph` backend, so that no system font library (fontconfig,
//! freetype) is needed. The SVG files name the family `sans-serif`; a viewer
//! draws them with its own sans-serif font.
//!
//! Colours are the Okabe–Ito palette, distinguishable with the common forms
//! of colour blindness; continuous values use viridis.

use anyhow::Context;
use plotters::chart::MeshStyle;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{register_font, FontStyle};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// DejaVu Sans 2.37 (licence in `assets/fonts/LICENSE-DejaVu.txt`).
pub(super) static DEJAVU_SANS: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// The family every text of a figure uses.
pub const FONT: &str = "sans-serif";

/// Registers the embedded font once (every drawing needs it, SVG included:
/// plotters measures text to lay out labels).
fn register() -> anyhow::Result<()> {
    static DONE: OnceLock<Result<(), String>> = OnceLock::new();
    let result =
        DONE.get_or_init(|| register_font(FONT, FontStyle::Normal, DEJAVU_SANS).map_err(|_| "the embedded font DejaVu Sans cannot be read".to_string()));
    result.clone().map_err(anyhow::Error::msg)
}

/// Text sizes (px at the figure's native size; the PNG is drawn at that size).
pub mod size {
    /// The figure's title (the scenario or sweep name).
    pub const TITLE: u32 = 26;
    /// The line under the title.
    pub const SUBTITLE: u32 = 17;
    /// Axis descriptions.
    pub const AXIS: u32 = 18;
    /// Tick labels.
    pub const TICK: u32 = 15;
    /// Legend entries.
    pub const LEGEND: u32 = 15;
    /// A note inside a panel ("no tower in this scenario").
    pub const NOTE: u32 = 18;
}

/// Okabe–Ito blue: the tower's rotation.
pub const BLUE: RGBColor = RGBColor(0, 114, 178);
/// Okabe–Ito orange: the building's sliding (bands, μs thresholds).
pub const ORANGE: RGBColor = RGBColor(230, 159, 0);
/// Okabe–Ito vermilion: the building's slip curve, overturning.
pub const VERMILION: RGBColor = RGBColor(213, 94, 0);
/// Okabe–Ito bluish green: the uplift threshold tan α.
pub const GREEN: RGBColor = RGBColor(0, 158, 115);
/// Okabe–Ito reddish purple: the top displacement.
pub const PURPLE: RGBColor = RGBColor(204, 121, 167);
/// Okabe–Ito sky blue.
pub const SKY: RGBColor = RGBColor(86, 180, 233);
/// The ground acceleration and other neutral lines.
pub const INK: RGBColor = RGBColor(40, 40, 40);
/// Grid lines, notes and reference lines.
pub const GREY: RGBColor = RGBColor(130, 130, 130);
/// Overturned cases of a sweep: a red outside viridis.
pub const OVERTURN: RGBColor = RGBColor(200, 30, 45);

/// Curve colours for the values of a sweep's second axis, in order.
pub const CYCLE: [RGBColor; 7] = [BLUE, VERMILION, GREEN, ORANGE, PURPLE, SKY, INK];

/// The colour of curve `k` of `n`: the palette for up to 7 curves, viridis beyond.
pub fn curve_color(k: usize, n: usize) -> RGBColor {
    if n <= CYCLE.len() {
        CYCLE[k % CYCLE.len()]
    } else {
        viridis(k as f64 / (n - 1).max(1) as f64 * 0.9)
    }
}

/// Viridis at `x` in [0, 1] (clamped), by linear interpolation between nine
/// samples of matplotlib's table.
pub fn viridis(x: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 9] = [
        (68.0, 1.0, 84.0),
        (71.0, 44.0, 122.0),
        (59.0, 81.0, 139.0),
        (44.0, 113.0, 142.0),
        (33.0, 144.0, 141.0),
        (39.0, 173.0, 129.0),
        (92.0, 200.0, 99.0),
        (170.0, 220.0, 50.0),
        (253.0, 231.0, 37.0),
    ];
    let x = if x.is_finite() { x.clamp(0.0, 1.0) } else { 0.0 };
    let position = x * (STOPS.len() - 1) as f64;
    let k = (position.floor() as usize).min(STOPS.len() - 2);
    let f = position - k as f64;
    let (a, b) = (STOPS[k], STOPS[k + 1]);
    let mix = |p: f64, q: f64| (p + (q - p) * f).round().clamp(0.0, 255.0) as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Black or white, whichever reads better on `background`.
pub fn text_on(background: RGBColor) -> RGBColor {
    let RGBColor(r, g, b) = background;
    let luminance = 0.299 * f64::from(r) + 0.587 * f64::from(g) + 0.114 * f64::from(b);
    if luminance > 140.0 {
        BLACK
    } else {
        WHITE
    }
}

/// A text style of `size` px in `color`.
pub fn text(size: u32, color: RGBColor) -> TextStyle<'static> {
    (FONT, size).into_font().color(&color)
}

/// A drawing that can be put on any plotters backend.
pub trait Figure {
    /// Draws on `root`, which is already filled white.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> anyhow::Result<()>
    where
        DB::ErrorType: 'static;
}

/// Draws `figure` into `dir/<stem>.svg` and `dir/<stem>.png`, `size` px (w, h),
/// returning the two paths.
pub fn render(dir: &Path, stem: &str, size: (u32, u32), figure: &impl Figure) -> anyhow::Result<Vec<PathBuf>> {
    register()?;
    let svg = dir.join(format!("{stem}.svg"));
    let png = dir.join(format!("{stem}.png"));
    {
        let root = SVGBackend::new(&svg, size).into_drawing_area();
        draw_on(&root, figure).with_context(|| format!("cannot draw {}", svg.display()))?;
    }
    {
        let root = super::raster::Raster(BitMapBackend::new(&png, size)).into_drawing_area();
        draw_on(&root, figure).with_context(|| format!("cannot draw {}", png.display()))?;
    }
    Ok(vec![svg, png])
}

/// Draws `figure` as an SVG document in a string, `size` px (w, h): a figure
/// inlined in a page (`report.html`).
pub fn render_svg(size: (u32, u32), figure: &impl Figure) -> anyhow::Result<String> {
    register()?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        draw_on(&root, figure).context("cannot draw an inline figure")?;
    }
    Ok(svg)
}

fn draw_on<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, figure: &impl Figure) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    figure.draw(root)?;
    root.present()?;
    Ok(())
}

/// Splits off a title band at the top of `root`: the title and, under it, a
/// smaller subtitle line (if not empty). Returns the area below.
pub fn title_band<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, title: &str, subtitle: &str) -> anyhow::Result<DrawingArea<DB, Shift>>
where
    DB::ErrorType: 'static,
{
    let band = if subtitle.is_empty() { 44 } else { 70 };
    let (top, rest) = root.split_vertically(band);
    let (w, _) = top.dim_in_pixel();
    let centre = i32::try_from(w / 2).unwrap_or(0);
    let centred = |size, color| text(size, color).pos(Pos::new(HPos::Center, VPos::Top));
    top.draw(&Text::new(printable(title), (centre, 10), centred(size::TITLE, BLACK)))?;
    if !subtitle.is_empty() {
        top.draw(&Text::new(printable(subtitle), (centre, 44), centred(size::SUBTITLE, INK)))?;
    }
    Ok(rest)
}

/// `text` as a figure may show it: control characters (which XML 1.0 does
/// not allow, even escaped, so one in a scenario's `name` made theta.svg
/// invalid) replaced by U+FFFD. `&`, `<` and `>` are escaped by the SVG
/// backend itself.
pub fn printable(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { '\u{fffd}' } else { c }).collect()
}

/// Writes `note` centred across `area`, a third of the way down (above a zero line in the middle).
pub fn note<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, note: &str) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let (w, h) = area.dim_in_pixel();
    let centre = (i32::try_from(w / 2).unwrap_or(0), i32::try_from(h / 3).unwrap_or(0));
    area.draw(&Text::new(
        printable(note),
        centre,
        text(size::NOTE, GREY).pos(Pos::new(HPos::Center, VPos::Center)),
    ))?;
    Ok(())
}

/// The chart of an x–y figure (the sweep's curves, a study's IDA and
/// fragility curves).
pub type XyChart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// An x–y chart on `panel` with the figures' margins; `plot_left` is the left
/// margin plus the label area (px), where the legend above starts.
pub fn xy_chart<'a, DB: DrawingBackend>(panel: &'a DrawingArea<DB, Shift>, plot_left: i32, x: (f64, f64), y: (f64, f64)) -> anyhow::Result<XyChart<'a, DB>>
where
    DB::ErrorType: 'static,
{
    Ok(ChartBuilder::on(panel)
        .margin_left(8)
        .margin_right(24)
        .margin_top(8)
        .margin_bottom(6)
        .y_label_area_size(plot_left - 8)
        .x_label_area_size(56)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)?)
}

/// The mesh of an x–y chart in the figures' look, with the axes' names; the
/// caller adds the label formatters and draws it.
pub fn xy_mesh<'a, 'b, DB: DrawingBackend>(
    chart: &'b mut XyChart<'a, DB>,
    x_desc: impl Into<String>,
    y_desc: impl Into<String>,
) -> MeshStyle<'a, 'b, RangedCoordf64, RangedCoordf64, DB> {
    let mut mesh = chart.configure_mesh();
    mesh.label_style(text(size::TICK, INK))
        .axis_desc_style(text(size::AXIS, INK))
        .bold_line_style(GREY.mix(0.25))
        .light_line_style(GREY.mix(0.08))
        .x_desc(x_desc)
        .y_desc(y_desc);
    mesh
}

/// The colour of a ζ_E on a scale from 0 to `top` that changes hue at 1:
/// below, where a check fails, reds from dark (0) to light (just below 1);
/// from 1 up, where it holds, blues from light (1) to dark (`top`) — the ends
/// and the middles of ColorBrewer's RdBu, so that 0.9 and 1.02, close in
/// value, are apart in hue (a sequential scale gave them one green).
pub fn fails_holds(z: f64, top: f64) -> RGBColor {
    const FAILS: [(f64, f64, f64); 3] = [(103.0, 0.0, 31.0), (214.0, 96.0, 77.0), (244.0, 165.0, 130.0)];
    const HOLDS: [(f64, f64, f64); 3] = [(146.0, 197.0, 222.0), (67.0, 147.0, 195.0), (5.0, 48.0, 97.0)];
    let (stops, x) = if !z.is_finite() || z < 1.0 {
        (FAILS, if z.is_finite() { z.max(0.0) } else { 0.0 })
    } else {
        (HOLDS, ((z - 1.0) / (top - 1.0).max(1e-9)).min(1.0))
    };
    let position = x * 2.0;
    let k = (position.floor() as usize).min(1);
    let f = position - k as f64;
    let (a, b) = (stops[k], stops[k + 1]);
    let mix = |p: f64, q: f64| (p + (q - p) * f).round().clamp(0.0, 255.0) as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// A vertical colour bar filling `area`: `colour` of each value from 0 to
/// `top`, its axis described by `desc`, and a white line across it at `mark`
/// if given (ζ_E = 1).
pub fn colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    top: f64,
    desc: &str,
    mark: Option<f64>,
    colour: &dyn Fn(f64) -> RGBColor,
) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let mut chart = ChartBuilder::on(area)
        .margin_top(8)
        .margin_bottom(62)
        .margin_right(50)
        .y_label_area_size(58)
        .build_cartesian_2d(0.0..1.0, 0.0..top)?;
    chart
        .configure_mesh()
        .disable_x_mesh()
        .disable_x_axis()
        .disable_y_mesh()
        .label_style(text(size::TICK, INK))
        .axis_desc_style(text(size::AXIS, INK))
        .y_desc(desc)
        .y_label_formatter(&|v| crate::format::sig(*v, 3))
        .set_all_tick_mark_size(4)
        .draw()?;
    let steps = 120;
    chart.draw_series((0..steps).map(|k| {
        let (a, b) = (k as f64 / steps as f64, (k + 1) as f64 / steps as f64);
        Rectangle::new([(0.0, a * top), (1.0, b * top)], colour((a + b) / 2.0 * top).filled())
    }))?;
    if let Some(m) = mark.filter(|m| (0.0..=top).contains(m)) {
        chart.draw_series(std::iter::once(PathElement::new(vec![(0.0, m), (1.0, m)], WHITE.stroke_width(3))))?;
        chart.draw_series(std::iter::once(PathElement::new(vec![(0.0, m), (1.0, m)], BLACK.stroke_width(1))))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viridis_ends_and_clamps() {
        assert_eq!(viridis(0.0), RGBColor(68, 1, 84));
        assert_eq!(viridis(1.0), RGBColor(253, 231, 37));
        assert_eq!(viridis(7.0), viridis(1.0));
        assert_eq!(viridis(f64::NAN), viridis(0.0));
    }

    #[test]
    fn the_town_scale_turns_from_red_to_blue_at_one() {
        // The stops as written: dark red at 0, light red below 1, light blue at 1, dark blue at the top.
        assert_eq!(fails_holds(0.0, 3.0), RGBColor(103, 0, 31));
        assert_eq!(fails_holds(0.999_999_999, 3.0), RGBColor(244, 165, 130));
        assert_eq!(fails_holds(1.0, 3.0), RGBColor(146, 197, 222));
        assert_eq!(fails_holds(3.0, 3.0), RGBColor(5, 48, 97));
        assert_eq!(fails_holds(7.0, 3.0), fails_holds(3.0, 3.0));
        // The example's 0.885 and a 1.02: red against blue (red channel above blue, then below).
        let (fails, holds) = (fails_holds(0.885, 2.2), fails_holds(1.02, 2.2));
        assert!(fails.0 > fails.2 && holds.0 < holds.2, "{fails:?} {holds:?}");
        // Halfway up the reds, the middle stop.
        assert_eq!(fails_holds(0.5, 3.0), RGBColor(214, 96, 77));
        assert_eq!(fails_holds(2.0, 3.0), RGBColor(67, 147, 195));
    }

    #[test]
    fn readable_text_colour() {
        assert_eq!(text_on(viridis(0.0)), WHITE);
        assert_eq!(text_on(viridis(1.0)), BLACK);
    }
}
