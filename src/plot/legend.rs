//! The legend panel to the right of the axes: one row per line style, marker, shading or curve
//! that occurs in the figure.

use plotters::prelude::*;

use super::marks::{draw_cross, draw_event_marker, draw_rings, shade_cell, stroke_boundary};
use super::marks::{draw_fixed_point, draw_orbit_event_marker};
use super::marks::{stroke_path, Px, Root};
use super::style::{asked_size, Sizes, Stroke};
use super::{drawing_error, PlotError};
use crate::{EventKind, OrbitEventKind, Stability};
use plotters::style::text_anchor::{HPos, Pos, VPos};

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
    /// A rectangle filled with this colour: a region of an orbit chart.
    Fill(RGBColor),
    /// Nothing: a row of text only.
    Text,
}

/// A legend row.
pub(super) type Entry = (Swatch, String);

/// The width of one legend entry in pixels: the swatch (44), a gap, its text ([`text_ems`] at
/// the legend's size) and a margin.
fn entry_width(entry: &Entry, sizes: &Sizes) -> u32 {
    44 + 10 + (text_ems(&entry.1) * sizes.legend).ceil() as u32 + 16
}

/// The height of a legend row in pixels.
pub(super) fn row_height(sizes: &Sizes) -> i32 {
    (1.6 * sizes.legend).ceil().max(18.0) as i32
}

/// Width of the legend panel to the right of the axes: a gap and the widest entry, at least 120
/// pixels (not clamped: a panel wider than the figure allows goes below the axes instead, see
/// [`Layout`]).
pub(super) fn legend_width(entries: &[Entry], sizes: &Sizes) -> u32 {
    (10 + entries
        .iter()
        .map(|e| entry_width(e, sizes))
        .max()
        .unwrap_or(0))
    .max(120)
}

/// Where the legend goes: in a panel to the right of the axes when it takes at most 40 % of
/// the figure's width, else below the axes, its entries side by side in rows as wide as the
/// figure (as words in lines of text).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Layout {
    /// A panel this many pixels wide to the right.
    Right(u32),
    /// Below the axes: rows at most `wrap` pixels wide, `height` pixels in all.
    Below { wrap: u32, height: u32 },
}

impl Layout {
    pub(super) fn of(entries: &[Entry], sizes: &Sizes, width: u32) -> Layout {
        let right = legend_width(entries, sizes);
        if entries.is_empty() || f64::from(right) <= 0.4 * f64::from(width) {
            return Layout::Right(right.min(width / 2));
        }
        let wrap = width.saturating_sub(30);
        let rows = positions(entries, sizes, Some(wrap))
            .last()
            .map_or(0, |p| p.1 + 1) as i32;
        Layout::Below {
            wrap,
            height: (rows * row_height(sizes) + 12) as u32,
        }
    }
}

/// Where each entry goes: its offset across and its row. Without `wrap`, one entry a row;
/// with it, entries side by side, a new row where the next would pass `wrap` pixels.
fn positions(entries: &[Entry], sizes: &Sizes, wrap: Option<u32>) -> Vec<(i32, usize)> {
    let mut out = Vec::with_capacity(entries.len());
    let (mut x, mut row) = (0u32, 0usize);
    for e in entries {
        let w = entry_width(e, sizes);
        match wrap {
            None => {
                out.push((0, row));
                row += 1;
            }
            Some(max) => {
                if x > 0 && x + w > max {
                    x = 0;
                    row += 1;
                }
                out.push((x as i32, row));
                x += w;
            }
        }
    }
    out
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

/// Draws the legend entries from the top-left corner `(x, y)` (backend pixels), at the
/// legend's size of `sizes`: one a row, or with `wrap` side by side in rows of at most `wrap`
/// pixels.
pub(super) fn draw_legend(
    root: &Root,
    (x, y): Px,
    entries: &[Entry],
    mono: bool,
    sizes: &Sizes,
    wrap: Option<u32>,
) -> Result<(), PlotError> {
    let row = row_height(sizes);
    let at = positions(entries, sizes, wrap);
    let font = ("sans-serif", asked_size(sizes.legend))
        .into_font()
        .color(&BLACK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    for ((swatch, text), &(dx, r)) in entries.iter().zip(&at) {
        let cy = y + row * r as i32 + row / 2;
        let x = x + dx;
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
            Swatch::Fill(color) => {
                let (a, b) = ((sx0, cy - 9), (sx1, cy + 9));
                root.draw(&Rectangle::new([a, b], color.filled()))
                    .and_then(|_| {
                        root.draw(&Rectangle::new(
                            [a, b],
                            RGBColor(90, 90, 90).stroke_width(1),
                        ))
                    })
                    .map_err(drawing_error)?;
            }
            Swatch::Text => {}
        }
        root.draw(&Text::new(text.clone(), (sx1 + 10, cy), font.clone()))
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
        let sizes = Sizes::of(&super::super::PlotOptions::default());
        let panel = f64::from(legend_width(&entries, &sizes));
        let text = 9.9775 * sizes.legend;
        // The text starts 10 + 44 + 10 pixels into the panel; at least 10 pixels are left over.
        assert!(
            64.0 + text + 10.0 <= panel,
            "{text} pixels of text in a panel of {panel}"
        );
        // At a column's width it goes below the axes, in rows that fit across.
        let column = super::super::PlotOptions::column();
        match Layout::of(&entries, &sizes, column.pixels().0) {
            Layout::Below { wrap, height } => {
                let at = positions(&entries, &sizes, Some(wrap));
                for (e, p) in entries.iter().zip(&at) {
                    let end = p.0 as u32 + entry_width(e, &sizes);
                    assert!(end <= wrap, "{:?} ends at {end} of {wrap}", e.1);
                }
                let rows = at.last().unwrap().1 as i32 + 1;
                assert_eq!(height as i32, rows * row_height(&sizes) + 12);
            }
            other => panic!("{other:?}"),
        }
    }
}
