//! Marks drawn in pixels: stroked paths, rings along a branch, event markers, shaded cells and
//! the × of a missing steady motion.

use std::cell::RefCell;

use plotters::coord::Shift;
use plotters::element::{DashedPathElement, DottedPathElement};
use plotters::prelude::*;

use super::curve::{dashes, smooth, PxF};
use super::labels::{place, Placed, Rect};
use super::style::BOUNDARY_UNDERLAY;
use super::style::{asked_size, Sizes, FONT, HATCH_INK, HATCH_SPACING};
use super::style::{boundary_color, boundary_stroke, cell_fill, Pattern, Stroke};
use super::{drawing_error, PlotError};
use crate::{EventKind, OrbitEventKind, Stability};

/// The whole figure, in backend pixels.
pub(super) type Root<'a> = DrawingArea<SVGBackend<'a>, Shift>;
// A point in backend pixels (defined beside the fractional one).
pub(super) use super::curve::Px;

/// Strokes the polyline `pts` (nothing for fewer than two points).
pub(super) fn stroke_path(
    root: &Root,
    pts: &[Px],
    color: RGBColor,
    stroke: Stroke,
) -> Result<(), PlotError> {
    if pts.len() < 2 {
        return Ok(());
    }
    match stroke {
        Stroke::Solid(w) => root
            .draw(&PathElement::new(pts.to_vec(), color.stroke_width(w)))
            .map_err(drawing_error),
        Stroke::Dashed(w, dash, gap) => root
            .draw(&DashedPathElement::new(
                pts.to_vec(),
                dash,
                gap,
                color.stroke_width(w),
            ))
            .map_err(drawing_error),
    }
}

/// Strokes the parts of a boundary curve of kind `kind`: first all of them on a white underlay,
/// then each in its own style.
pub(super) fn stroke_boundary(
    root: &Root,
    parts: &[Vec<PxF>],
    kind: EventKind,
    mono: bool,
) -> Result<(), PlotError> {
    for part in parts {
        stroke_curve(root, part, WHITE, BOUNDARY_UNDERLAY)?;
    }
    for part in parts {
        stroke_curve(
            root,
            part,
            boundary_color(kind, mono),
            boundary_stroke(kind),
        )?;
    }
    Ok(())
}

/// Open rings along the polyline `pts`: a branch of circles of steady motions.
pub(super) fn draw_rings(root: &Root, pts: &[Px], color: RGBColor) -> Result<(), PlotError> {
    if pts.len() < 2 {
        return Ok(());
    }
    let style = color.stroke_width(1);
    let white = WHITE.filled();
    root.draw(&DottedPathElement::new(pts.to_vec(), 10, 26, move |c| {
        Circle::new(c, 4, white)
    }))
    .map_err(drawing_error)?;
    root.draw(&DottedPathElement::new(pts.to_vec(), 10, 26, move |c| {
        Circle::new(c, 4, style)
    }))
    .map_err(drawing_error)
}

/// The marker of an event at `c`, black on a white halo: ▲ fold, ● branch point, ■
/// Hamiltonian–Hopf, ○ Arnold-degenerate (D = 0), ✕ resonance.
pub(super) fn draw_event_marker(root: &Root, c: Px, kind: EventKind) -> Result<(), PlotError> {
    let halo = WHITE.filled();
    let ink = BLACK.filled();
    let r = match kind {
        EventKind::Fold => root
            .draw(&TriangleMarker::new(c, 11, halo))
            .and_then(|_| root.draw(&TriangleMarker::new(c, 7, ink))),
        EventKind::BranchPoint => root
            .draw(&Circle::new(c, 7, halo))
            .and_then(|_| root.draw(&Circle::new(c, 5, ink))),
        EventKind::HamiltonianHopf => root
            .draw(&Rectangle::new(
                [(c.0 - 7, c.1 - 7), (c.0 + 7, c.1 + 7)],
                halo,
            ))
            .and_then(|_| {
                root.draw(&Rectangle::new(
                    [(c.0 - 5, c.1 - 5), (c.0 + 5, c.1 + 5)],
                    ink,
                ))
            }),
        // Nonlinear events (the post-pass of routh_core::nonlinear): ○ D = 0, ◆-ish ✕ resonance.
        EventKind::ArnoldDegenerate => root
            .draw(&Circle::new(c, 7, halo))
            .and_then(|_| root.draw(&Circle::new(c, 5, BLACK.stroke_width(2)))),
        EventKind::Resonance => root
            .draw(&Circle::new(c, 7, halo))
            .and_then(|_| root.draw(&Cross::new(c, 5, BLACK.stroke_width(2)))),
    };
    r.map_err(drawing_error)
}

/// The marker of an event of a family of periodic orbits at `c`, black on a white halo: ▲ fold
/// and ● branch point (as for steady motions), ◆ period doubling.
pub(super) fn draw_orbit_event_marker(
    root: &Root,
    c: Px,
    kind: OrbitEventKind,
) -> Result<(), PlotError> {
    match kind {
        OrbitEventKind::Fold => draw_event_marker(root, c, EventKind::Fold),
        OrbitEventKind::BranchPoint => draw_event_marker(root, c, EventKind::BranchPoint),
        OrbitEventKind::PeriodDoubling => {
            let diamond = |r: i32| {
                vec![
                    (c.0, c.1 - r),
                    (c.0 + r, c.1),
                    (c.0, c.1 + r),
                    (c.0 - r, c.1),
                ]
            };
            root.draw(&Polygon::new(diamond(10), WHITE.filled()))
                .and_then(|_| root.draw(&Polygon::new(diamond(7), BLACK.filled())))
                .map_err(drawing_error)
        }
        // ■ a vanishing twist; ○ a resonance of order three, ◎ of order four.
        OrbitEventKind::TwistDegenerate => {
            let square =
                |r: i32| Rectangle::new([(c.0 - r, c.1 - r), (c.0 + r, c.1 + r)], WHITE.filled());
            root.draw(&square(9))
                .and_then(|_| {
                    root.draw(&Rectangle::new(
                        [(c.0 - 6, c.1 - 6), (c.0 + 6, c.1 + 6)],
                        BLACK.filled(),
                    ))
                })
                .map_err(drawing_error)
        }
        OrbitEventKind::ThirdOrderResonance | OrbitEventKind::FourthOrderResonance => {
            let r = root
                .draw(&Circle::new(c, 9, WHITE.filled()))
                .and_then(|_| root.draw(&Circle::new(c, 6, BLACK.stroke_width(2))));
            let r = if kind == OrbitEventKind::FourthOrderResonance {
                r.and_then(|_| root.draw(&Circle::new(c, 2, BLACK.filled())))
            } else {
                r
            };
            r.map_err(drawing_error)
        }
    }
}

/// The mark of a fixed point of a Poincaré section (a periodic orbit's crossing) at `c`: a black
/// ring with a dot in it, on a white halo, so that it stands out of the cloud of crossings.
pub(super) fn draw_fixed_point(root: &Root, c: Px) -> Result<(), PlotError> {
    root.draw(&Circle::new(c, 8, WHITE.filled()))
        .and_then(|_| root.draw(&Circle::new(c, 6, BLACK.stroke_width(2))))
        .and_then(|_| root.draw(&Circle::new(c, 2, BLACK.filled())))
        .map_err(drawing_error)
}

/// Writes each name beside its marker at `c`, placed by [`place`] clear of one another, of the
/// `markers` and inside `area`; a name put away from its marker gets a thin grey leader line.
/// Returns where each went.
pub(super) fn draw_names(
    root: &Root,
    names: &[(Px, String)],
    markers: &[Rect],
    curves: &[Px],
    area: Rect,
    sizes: &Sizes,
) -> Result<Vec<Placed>, PlotError> {
    // Written at the annotation size (plotters is asked for 1.24 times more), and placed at the
    // size written.
    let size = sizes.annotation;
    let asked = asked_size(size);
    let placed = place(names, markers, curves, area, size);
    let font = (FONT.family, asked).into_font().color(&BLACK);
    for p in &placed {
        let r = p.rect;
        if p.leader {
            // From the marker's edge to the nearest point of the box.
            let q = (p.anchor.0.clamp(r.x0, r.x1), p.anchor.1.clamp(r.y0, r.y1));
            let (dx, dy) = ((q.0 - p.anchor.0) as f64, (q.1 - p.anchor.1) as f64);
            let d = dx.hypot(dy).max(1.0);
            let from = (
                p.anchor.0 + (9.0 * dx / d).round() as i32,
                p.anchor.1 + (9.0 * dy / d).round() as i32,
            );
            stroke_path(root, &[from, q], RGBColor(110, 110, 110), Stroke::Solid(1))?;
        }
        // A light ground under the text itself (narrower than the box kept clear for it).
        let ground = (0.56 * size * p.text.chars().count() as f64).ceil() as i32;
        root.draw(&Rectangle::new(
            [(r.x0 - 1, r.y0 + 1), (r.x0 + ground + 1, r.y1 - 1)],
            WHITE.mix(0.8).filled(),
        ))
        .map_err(drawing_error)?;
        root.draw(&Text::new(p.text.clone(), (r.x0, r.y0 + 1), font.clone()))
            .map_err(drawing_error)?;
    }
    Ok(placed)
}

/// Points every few pixels along the polyline (fractional pixels), for labels to keep off.
pub(super) fn along(pts: &[PxF]) -> Vec<Px> {
    let mut out = Vec::new();
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let n = ((b.0 - a.0).hypot(b.1 - a.1) / 4.0).ceil().max(1.0) as usize;
        for k in 0..n {
            let t = k as f64 / n as f64;
            out.push((
                (a.0 + t * (b.0 - a.0)).round() as i32,
                (a.1 + t * (b.1 - a.1)).round() as i32,
            ));
        }
    }
    if let Some(p) = pts.last() {
        out.push((p.0.round() as i32, p.1.round() as i32));
    }
    out
}

thread_local! {
    /// The polylines in fractional pixels of the figure being drawn on this thread (plotters'
    /// SVG backend writes whole pixels only), each put in place of its placeholder by
    /// [`fractional_polylines`] once the figure is drawn.
    static FINE: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
}

/// The text of the placeholder of the `k`-th fine polyline.
fn fine_tag(k: usize) -> String {
    format!("routh-fine-polyline-{k}.")
}

/// Empties the store of fine polylines (before a figure is drawn).
pub(super) fn reset_fine() {
    FINE.with(|f| f.borrow_mut().clear());
}

/// Strokes the polyline `pts` in fractional pixels, solid: a placeholder now, the polyline
/// itself (coordinates to 1/100 pixel, round joins) in the SVG written.
fn stroke_fine(root: &Root, pts: &[PxF], color: RGBColor, width: u32) -> Result<(), PlotError> {
    if pts.len() < 2 {
        return Ok(());
    }
    // To 1/100 pixel, each point once: a point that rounds to the one before it is left out
    // (a dense run repeats points many times over).
    let mut points = String::new();
    let mut last = String::new();
    let mut n = 0;
    for p in pts {
        let q = format!("{:.2},{:.2}", p.0, p.1);
        if q != last {
            points.push_str(&q);
            points.push(' ');
            n += 1;
            last = q;
        }
    }
    if n < 2 {
        return Ok(());
    }
    let RGBColor(r, g, b) = color;
    let line = format!(
        "<polyline fill=\"none\" opacity=\"1\" stroke=\"#{r:02X}{g:02X}{b:02X}\" \
         stroke-width=\"{width}\" stroke-linejoin=\"round\" stroke-linecap=\"butt\" \
         points=\"{points}\"/>"
    );
    let k = FINE.with(|f| {
        let mut f = f.borrow_mut();
        f.push(line);
        f.len() - 1
    });
    root.draw(&Text::new(
        fine_tag(k),
        (0, 0),
        ("sans-serif", 1).into_font(),
    ))
    .map_err(drawing_error)
}

/// The SVG with each placeholder of [`stroke_fine`] (a `<text>` element) replaced by its
/// polyline, in the order drawn; empties the store.
pub(super) fn fractional_polylines(svg: &str) -> String {
    let lines = FINE.with(|f| std::mem::take(&mut *f.borrow_mut()));
    if lines.is_empty() {
        return svg.to_string();
    }
    let mut out = String::with_capacity(svg.len() + 64 * lines.len());
    let mut rest = svg;
    for (k, line) in lines.iter().enumerate() {
        let tag = fine_tag(k);
        let Some(at) = rest.find(&tag) else { continue };
        let (Some(start), Some(end)) = (rest[..at].rfind("<text"), rest[at..].find("</text>"))
        else {
            continue;
        };
        out.push_str(&rest[..start]);
        out.push_str(line);
        rest = &rest[at + end + "</text>".len()..];
    }
    out.push_str(rest);
    out
}

/// Strokes a curve through the fractional-pixel samples `pts`, smoothed ([`smooth`]) and with
/// its dashes laid along its whole length ([`dashes`]).
pub(super) fn stroke_curve(
    root: &Root,
    pts: &[PxF],
    color: RGBColor,
    stroke: Stroke,
) -> Result<(), PlotError> {
    let smooth = smooth(pts);
    match stroke {
        Stroke::Solid(w) => stroke_fine(root, &smooth, color, w),
        Stroke::Dashed(w, dash, gap) => {
            for d in dashes(&smooth, dash as f64, gap as f64) {
                stroke_fine(root, &d, color, w)?;
            }
            Ok(())
        }
    }
}

/// Shades the pixel rectangle with corners `a` (top left) and `b` (bottom right) as a cell of
/// verdict `v`.
pub(super) fn shade_cell(
    root: &Root,
    a: Px,
    b: Px,
    v: Stability,
    mono: bool,
) -> Result<(), PlotError> {
    let (color, pattern) = cell_fill(v, mono);
    fill_cell(root, a, b, color, pattern)
}

/// Fills the pixel rectangle `[x0, x1] × [y0, y1]` with the background and pattern (dots on
/// `[x0, x1) × [y0, y1)`, so that abutting cells do not repeat them).
fn fill_cell(
    root: &Root,
    (x0, y0): Px,
    (x1, y1): Px,
    color: RGBColor,
    pattern: Pattern,
) -> Result<(), PlotError> {
    if x1 <= x0 || y1 <= y0 {
        return Ok(());
    }
    root.draw(&Rectangle::new([(x0, y0), (x1, y1)], color.filled()))
        .map_err(drawing_error)?;
    const SP: i32 = HATCH_SPACING;
    let ink = HATCH_INK;
    match pattern {
        Pattern::Plain => {}
        Pattern::Dots => {
            // A staggered lattice, global in pixels so that it runs on across cells.
            for py in (y0.div_euclid(SP) * SP..y1).step_by(SP as usize) {
                if py < y0 {
                    continue;
                }
                let off = if py.div_euclid(SP) % 2 == 0 {
                    0
                } else {
                    SP / 2
                };
                let start = (x0 - off).div_euclid(SP) * SP + off;
                for px in (start..x1).step_by(SP as usize) {
                    if px >= x0 {
                        root.draw(&Circle::new((px, py), 1, ink.filled()))
                            .map_err(drawing_error)?;
                    }
                }
            }
        }
        Pattern::Hatch | Pattern::CrossHatch => {
            let style = ink.stroke_width(1);
            // "/" lines: px + py = c.
            let c0 = (x0 + y0).div_euclid(SP) * SP;
            for c in (c0..=x1 + y1).step_by(SP as usize) {
                let a = (c - y1).max(x0);
                let b = (c - y0).min(x1);
                if a < b {
                    root.draw(&PathElement::new(vec![(a, c - a), (b, c - b)], style))
                        .map_err(drawing_error)?;
                }
            }
            if pattern == Pattern::CrossHatch {
                // "\" lines: px − py = c.
                let c0 = (x0 - y1).div_euclid(SP) * SP;
                for c in (c0..=x1 - y0).step_by(SP as usize) {
                    let a = (c + y0).max(x0);
                    let b = (c + y1).min(x1);
                    if a < b {
                        root.draw(&PathElement::new(vec![(a, a - c), (b, b - c)], style))
                            .map_err(drawing_error)?;
                    }
                }
            }
        }
    }
    Ok(())
}

/// A small grey × in the middle of the pixel rectangle: no steady motion there.
pub(super) fn draw_cross(root: &Root, (x0, y0): Px, (x1, y1): Px) -> Result<(), PlotError> {
    let (cx, cy) = ((x0 + x1) / 2, (y0 + y1) / 2);
    let h = ((x1 - x0).min(y1 - y0) / 4).clamp(2, 6);
    let style = RGBColor(120, 120, 120).stroke_width(1);
    root.draw(&PathElement::new(
        vec![(cx - h, cy - h), (cx + h, cy + h)],
        style,
    ))
    .and_then(|_| {
        root.draw(&PathElement::new(
            vec![(cx - h, cy + h), (cx + h, cy - h)],
            style,
        ))
    })
    .map_err(drawing_error)
}
