//! Legends drawn in a strip above a panel rather than inside it: a harmonic
//! response fills its whole panel, and a legend box there would hide the curve.

use super::style::{size, text, INK};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// How an entry of a legend looks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Swatch {
    /// A solid line.
    Line(RGBColor),
    /// A dashed line.
    Dashed(RGBColor),
    /// A light band (`opacity` of the colour).
    Band(RGBColor, f64),
    /// A short vertical tick.
    Tick(RGBColor),
    /// A cross (×).
    Cross(RGBColor),
    /// A filled square.
    Square(RGBColor),
    /// A line with round markers.
    LineDots(RGBColor),
    /// A point of a chart, as drawn on it.
    Point(Shape, RGBColor),
}

/// The shape of a point of a chart (and of its legend's swatch).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A filled disc.
    Circle,
    /// A filled square.
    Square,
    /// A filled triangle pointing up.
    Triangle,
    /// A cross (×): a failure.
    Cross,
}

/// Draws a point of `shape` at `at` (in `area`'s coordinates), the same size
/// on a chart as in its legend.
pub fn point<DB: DrawingBackend, CT: CoordTranslate>(area: &DrawingArea<DB, CT>, at: CT::From, shape: Shape, color: RGBColor) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let anchor = EmptyElement::<CT::From, DB>::at(at);
    match shape {
        Shape::Circle => area.draw(&(anchor + Circle::new((0, 0), 6, color.filled())))?,
        Shape::Square => area.draw(&(anchor + Rectangle::new([(-6, -6), (6, 6)], color.filled())))?,
        Shape::Triangle => area.draw(&(anchor + Polygon::new(vec![(0, -8), (7, 5), (-7, 5)], color.filled())))?,
        Shape::Cross => area.draw(&(anchor + Cross::new((0, 0), 7, color.stroke_width(3))))?,
    }
    Ok(())
}

/// One entry: its swatch and its text.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// How it looks.
    pub swatch: Swatch,
    /// What it is.
    pub label: String,
}

impl Entry {
    /// An entry.
    pub fn new(swatch: Swatch, label: impl Into<String>) -> Self {
        Self { swatch, label: label.into() }
    }
}

const SWATCH: i32 = 30;
const GAP: i32 = 8;
const SPACING: i32 = 26;
const ROW: i32 = 24;

/// The rows of `entries` in a strip `width` px wide starting at `left`, each
/// entry with its x position, measured on `area`.
fn layout<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, left: i32, width: i32, entries: &[Entry]) -> anyhow::Result<Vec<Vec<(i32, usize)>>>
where
    DB::ErrorType: 'static,
{
    let style = text(size::LEGEND, INK);
    let mut rows: Vec<Vec<(i32, usize)>> = vec![Vec::new()];
    let mut x = left;
    for (k, entry) in entries.iter().enumerate() {
        let (w, _) = area.estimate_text_size(&entry.label, &style)?;
        let w = SWATCH + GAP + i32::try_from(w).unwrap_or(0);
        let row_is_empty = rows.last().is_none_or(Vec::is_empty);
        if x + w > left + width && !row_is_empty {
            rows.push(Vec::new());
            x = left;
        }
        if let Some(row) = rows.last_mut() {
            row.push((x, k));
        }
        x += w + SPACING;
    }
    Ok(rows)
}

/// The height (px) a strip of `entries` needs on `area` between `left` and the right edge.
fn height<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, left: i32, entries: &[Entry]) -> anyhow::Result<u32>
where
    DB::ErrorType: 'static,
{
    if entries.is_empty() {
        return Ok(0);
    }
    let (w, _) = area.dim_in_pixel();
    let rows = layout(area, left, i32::try_from(w).unwrap_or(0) - left - 16, entries)?.len();
    Ok(u32::try_from(rows).unwrap_or(1) * ROW as u32 + 8)
}

/// Draws `entries` in `area` (a strip as high as [`height`] says), from `left`.
fn draw<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, left: i32, entries: &[Entry]) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let (w, _) = area.dim_in_pixel();
    let rows = layout(area, left, i32::try_from(w).unwrap_or(0) - left - 16, entries)?;
    let style = text(size::LEGEND, INK).pos(Pos::new(HPos::Left, VPos::Center));
    for (r, row) in rows.iter().enumerate() {
        let y = 4 + ROW / 2 + ROW * i32::try_from(r).unwrap_or(0);
        for &(x, k) in row {
            let entry = &entries[k];
            swatch(area, (x, y), entry.swatch)?;
            area.draw(&Text::new(super::style::printable(&entry.label), (x + SWATCH + GAP, y), style.clone()))?;
        }
    }
    Ok(())
}

/// Draws `entries` in a strip at the top of `area`, from `left`, and returns
/// the rest of `area` below it: the panel the legend describes.
pub fn above<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, left: i32, entries: &[Entry]) -> anyhow::Result<DrawingArea<DB, Shift>>
where
    DB::ErrorType: 'static,
{
    let (strip, panel) = area.split_vertically(height(area, left, entries)?);
    draw(&strip, left, entries)?;
    Ok(panel)
}

fn swatch<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, (x, y): (i32, i32), swatch: Swatch) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let line = |color: RGBColor| PathElement::new(vec![(x, y), (x + SWATCH, y)], color.stroke_width(3));
    match swatch {
        Swatch::Line(c) => area.draw(&line(c))?,
        Swatch::Dashed(c) => {
            for k in 0..3 {
                let x0 = x + k * 11;
                area.draw(&PathElement::new(vec![(x0, y), (x0 + 7, y)], c.stroke_width(2)))?;
            }
        }
        Swatch::Band(c, opacity) => area.draw(&Rectangle::new([(x, y - 8), (x + SWATCH, y + 8)], c.mix(opacity).filled()))?,
        Swatch::Tick(c) => area.draw(&PathElement::new(vec![(x + SWATCH / 2, y - 8), (x + SWATCH / 2, y + 8)], c.stroke_width(2)))?,
        Swatch::Cross(c) => area.draw(&Cross::new((x + SWATCH / 2, y), 6, c.stroke_width(3)))?,
        Swatch::Square(c) => area.draw(&Rectangle::new([(x + 6, y - 9), (x + SWATCH - 6, y + 9)], c.filled()))?,
        Swatch::LineDots(c) => {
            area.draw(&line(c))?;
            area.draw(&Circle::new((x + SWATCH / 2, y), 4, c.filled()))?;
        }
        Swatch::Point(shape, c) => point(area, (x + SWATCH / 2, y), shape, c)?,
    }
    Ok(())
}
