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

/// The legend's font size (plotters' units: the SVG says `font-size` 17/1.24 ≈ 13.7 px).
const FONT: f64 = 17.0;

/// Width of the legend panel: the gap, the swatch, its longest text ([`text_ems`] at the SVG's
/// font size) and a margin, at most half the figure.
pub(super) fn legend_width(entries: &[Entry], width: u32) -> u32 {
    let ems = entries.iter().map(|e| text_ems(&e.1)).fold(0.0, f64::max);
    let text = (ems * FONT / 1.24).ceil() as u32;
    (10 + 44 + 10 + text + 16).clamp(120, width / 2)
}

/// The width of `text` in ems, by the glyph widths of DejaVu Sans (a wide sans-serif: a viewer's
/// narrower face fits too) rounded up per class: narrow letters and punctuation, ordinary
/// letters and digits, capitals, the widest letters and operators, sub- and superscripts.
/// Plotters' SVG backend cannot measure text, and counting characters at an average width let
/// a legend of wide glyphs (`m`, `ω`) run past the figure's right edge.
fn text_ems(text: &str) -> f64 {
    text.chars()
        .map(|c| match c {
            'i' | 'j' | 'l' | 'f' | 't' | 'r' | 'I' | ' ' | '.' | ',' | ':' | ';' | '\'' | '!'
            | '|' | '/' | '(' | ')' | '[' | ']' => 0.42,
            'm' | 'w' | 'M' | 'W' | 'ω' | 'Ω' | '=' | '<' | '>' | '+' | '−' | '±' | '×' | '≤'
            | '≥' | '≈' | '—' | '%' | '@' | '&' | '#' | '^' | '~' => 1.0,
            '₀'..='₉' | '⁰'..='⁹' | '¹' | '²' | '³' => 0.5,
            c if c.is_uppercase() => 0.8,
            _ => 0.67,
        })
        .sum()
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
    let font = ("sans-serif", FONT).into_font().color(&BLACK);
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Legend texts of the figures with their advance widths in DejaVu Sans (ems: the sums of
    /// the glyphs' `hmtx` advances over 2048 units per em, read from DejaVuSans.ttf 2.37).
    const MEASURED: &[(&str, f64)] = &[
        ("pendulum 4K(m)/ω₀", 9.9775),
        ("elliptic, |k| < 1", 7.3018),
        ("hyperbolic, k > 1", 8.5635),
        ("inverse hyperbolic, k < −1", 13.3853),
        ("branch point", 6.3442),
        ("period doubling", 7.8428),
        ("gyroscopically stabilized", 12.2417),
        ("secularly stable", 7.8628),
        ("Hamiltonian–Hopf", 8.9072),
        ("tilted precessions, closed form", 15.3335),
        ("no steady motion", 8.7505),
        ("circle of steady motions", 11.9893),
        ("1:2 resonance", 7.1318),
        ("mMwW", 3.6436),
        ("ABCDEFGHJKLNOPQRSTUVXYZ", 15.3428),
        ("iljftrI .,:;'!|/()[]", 6.8213),
    ];

    #[test]
    fn text_widths_bound_the_fonts_without_wasting_room() {
        for &(text, font) in MEASURED {
            let ems = text_ems(text);
            assert!(
                ems >= font && ems <= 1.25 * font,
                "{text:?}: {ems} ems for {font}"
            );
        }
    }

    #[test]
    fn the_longest_text_fits_in_the_panel() {
        // The periods of a family with the pendulum's curve: the legend whose last row ran past
        // the right edge of a 900-pixel figure (docs/figures/periodic_swing_e1_periods.svg).
        let entries: Vec<Entry> = MEASURED[..3]
            .iter()
            .map(|&(text, _)| (Swatch::Text, text.to_string()))
            .collect();
        let panel = f64::from(legend_width(&entries, 900));
        let text = 9.9775 * FONT / 1.24;
        // The text starts 10 + 44 + 10 pixels into the panel; at least 10 pixels are left over.
        assert!(
            64.0 + text + 10.0 <= panel,
            "{text} pixels of text in a panel of {panel}"
        );
    }
}
