//! The legend panel to the right of the axes: one row per line style, marker, shading or curve
//! that occurs in the figure.

use plotters::prelude::*;

use super::marks::{draw_cross, draw_event_marker, draw_rings, shade_cell, stroke_boundary};
use super::marks::{draw_fixed_point, draw_orbit_event_marker};
use super::marks::{stroke_path, Px, Root};
use super::style::Stroke;
use super::{drawing_error, PlotError};
use crate::{EventKind, OrbitEventKind, Stability};

/// What a legend row shows left of its text.
pub(super) enum Swatch {
    /// A line of this colour and stroke.
    Line(RGBColor, Stroke),
    /// A thin line with open rings: circles of steady motions.
    Rings,
    /// The marker of an event.
    Event(EventKind),
    /// An atlas cell of this verdict, or of no steady motion.
    Cell(Option<Stability>),
    /// A boundary curve of an atlas.
    Boundary(EventKind),
    /// The marker of an event of a family of periodic orbits.
    OrbitEvent(OrbitEventKind),
    /// Three dots of this colour: the crossings of a Poincaré section.
    Dots(RGBColor),
    /// The mark of a fixed point of a Poincaré section.
    FixedPoint,
    /// Nothing: a row of text only.
    Text,
}

/// A legend row.
pub(super) type Entry = (Swatch, String);

/// Width of the legend panel: its longest text at about 7.5 pixels a character, after the swatch,
/// at most half the figure.
pub(super) fn legend_width(entries: &[Entry], width: u32) -> u32 {
    let chars = entries
        .iter()
        .map(|e| e.1.chars().count())
        .max()
        .unwrap_or(0) as u32;
    (74 + 15 * chars / 2 + 12).clamp(120, width / 2)
}

/// Draws the legend entries top-down in the panel whose top-left corner is `(x, y)` (backend
/// pixels).
pub(super) fn draw_legend(
    root: &Root,
    (x, y): Px,
    entries: &[Entry],
    mono: bool,
) -> Result<(), PlotError> {
    const ROW: i32 = 26;
    let font = ("sans-serif", 17).into_font().color(&BLACK);
    for (k, (swatch, text)) in entries.iter().enumerate() {
        let cy = y + ROW * k as i32 + ROW / 2;
        let (sx0, sx1) = (x, x + 44);
        let line = [(sx0, cy), (sx1, cy)];
        match swatch {
            Swatch::Line(color, stroke) => stroke_path(root, &line, *color, *stroke)?,
            Swatch::Rings => {
                stroke_path(root, &line, BLACK, Stroke::Solid(1))?;
                draw_rings(root, &line, BLACK)?;
            }
            Swatch::Event(kind) => draw_event_marker(root, ((sx0 + sx1) / 2, cy), *kind)?,
            Swatch::Cell(v) => {
                let (a, b) = ((sx0, cy - 9), (sx1, cy + 9));
                match v {
                    Some(v) => shade_cell(root, a, b, *v, mono)?,
                    None => {
                        root.draw(&Rectangle::new([a, b], WHITE.filled()))
                            .map_err(drawing_error)?;
                        draw_cross(root, a, b)?;
                    }
                }
                root.draw(&Rectangle::new(
                    [a, b],
                    RGBColor(90, 90, 90).stroke_width(1),
                ))
                .map_err(drawing_error)?;
            }
            Swatch::Boundary(kind) => {
                let line: Vec<(f64, f64)> = line
                    .iter()
                    .map(|&(x, y)| (f64::from(x), f64::from(y)))
                    .collect();
                stroke_boundary(root, &[line], *kind, mono)?
            }
            Swatch::OrbitEvent(kind) => {
                draw_orbit_event_marker(root, ((sx0 + sx1) / 2, cy), *kind)?
            }
            Swatch::Dots(color) => {
                for dx in [8, 22, 36] {
                    root.draw(&Circle::new((sx0 + dx, cy), 2, color.filled()))
                        .map_err(drawing_error)?;
                }
            }
            Swatch::FixedPoint => draw_fixed_point(root, ((sx0 + sx1) / 2, cy))?,
            Swatch::Text => {}
        }
        root.draw(&Text::new(text.clone(), (sx1 + 10, cy - 8), font.clone()))
            .map_err(drawing_error)?;
    }
    Ok(())
}
