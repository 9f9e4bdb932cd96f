//! The stability atlas: the cells of its grid shaded by verdict, its boundary curves on top.

use std::path::Path;

use plotters::prelude::*;

use super::curve::PxF;
use super::frame::{
    clip_polyline, draw_figure, float_px, plot_rect, Chart, Frame, Overlays, Polyline,
};
use super::labels::{text_width, Rect};
use super::legend::{Entry, Swatch};
use super::marks::{draw_cross, stroke_boundary, stroke_path, Px, Root};
use super::regions::Regions;
use super::style::{asked_size, boundary_color, nonlinear_stroke, Sizes, FONT, KINDS, VERDICTS};
use super::{drawing_error, label_or, x_label_or, PlotError, PlotOptions};
use crate::{BoundaryCurve, NonlinearCurve, StabilityAtlas};

/// Cell edges around grid nodes: midpoints between nodes, the end nodes themselves at the ends.
fn edges(nodes: &[f64]) -> Vec<f64> {
    let n = nodes.len();
    if n == 1 {
        let h = 0.5 * nodes[0].abs().max(1.0);
        return vec![nodes[0] - h, nodes[0] + h];
    }
    let mut e = Vec::with_capacity(n + 1);
    e.push(nodes[0]);
    e.extend(nodes.windows(2).map(|w| 0.5 * (w[0] + w[1])));
    e.push(nodes[n - 1]);
    e
}

/// Checks that the verdicts are `y.len()` rows of `x.len()` over a finite ascending grid.
fn check_grid(atlas: &StabilityAtlas) -> Result<(), PlotError> {
    let (nx, ny) = (atlas.x.len(), atlas.y.len());
    if nx == 0 || ny == 0 {
        return Err(PlotError::EmptyData("the atlas has no grid node"));
    }
    if atlas.verdicts.len() != ny || atlas.verdicts.iter().any(|row| row.len() != nx) {
        return Err(PlotError::InvalidData(format!(
            "the verdicts must be {ny} rows of {nx} (one per y, then per x)"
        )));
    }
    for (name, v) in [("x", &atlas.x), ("y", &atlas.y)] {
        if v.iter().any(|t| !t.is_finite()) || v.windows(2).any(|w| w[1] <= w[0]) {
            return Err(PlotError::InvalidData(format!(
                "the grid {name} must be finite and strictly ascending"
            )));
        }
    }
    Ok(())
}

/// [`stability_atlas_svg`](super::stability_atlas_svg).
pub(super) fn atlas_figure(
    atlas: &StabilityAtlas,
    path: &Path,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    opts.check()?;
    check_grid(atlas)?;
    let (ex, ey) = (edges(&atlas.x), edges(&atlas.y));
    let frame = Frame {
        x: (ex[0], ex[atlas.x.len()]),
        y: (ey[0], ey[atlas.y.len()]),
        x_label: x_label_or(&opts.x_label, "x"),
        y_label: label_or(&opts.y_label, "y"),
        mesh: false,
        y_ticks: None,
    };
    let mono = opts.monochrome;

    // The verdicts whose regions show (a node alone on a boundary is cut off on every side and
    // shows nowhere, or in a sliver under the curve): the regions at about the size of the axes (the legend, which takes its
    // room, comes first).
    let nominal = Rect {
        x0: 0,
        y0: 0,
        x1: (0.6 * f64::from(opts.width)) as i32,
        y1: (0.8 * f64::from(opts.height)) as i32,
    };
    let (nw, nh) = (f64::from(nominal.x1), f64::from(nominal.y1));
    let shown = Regions::new(atlas, nominal, |px, py| {
        (
            frame.x.0 + px / nw * (frame.x.1 - frame.x.0),
            frame.y.1 - py / nh * (frame.y.1 - frame.y.0),
        )
    })
    // A sliver along a boundary curve (a node just off it, under the curve's white band) is no
    // region a reader sees: at least 1/2000 of the axes, and 60 pixels.
    .shown(((nominal.x1 * nominal.y1) as usize / 2000).max(60));
    let mut legend: Vec<Entry> = VERDICTS
        .iter()
        .filter(|&&v| shown.contains(&v))
        .map(|&v| (Swatch::Cell(Some(v)), v.to_string()))
        .collect();
    // A missing verdict is either no steady motion (beyond a fold) or the motion lost along
    // the row (`StabilityAtlas::lost`).
    let is_lost = |i: usize, j: usize| atlas.lost.get(j).and_then(|r| r.get(i)) == Some(&true);
    let (mut absent, mut lost) = (false, false);
    for (j, row) in atlas.verdicts.iter().enumerate() {
        for (i, v) in row.iter().enumerate() {
            if v.is_none() {
                if is_lost(i, j) {
                    lost = true;
                } else {
                    absent = true;
                }
            }
        }
    }
    if absent {
        legend.push((Swatch::Cell(None), "no steady motion".into()));
    }
    if lost {
        legend.push((Swatch::Cell(None), "motion lost".into()));
    }
    let curves: Vec<(&BoundaryCurve, Vec<Polyline>)> = atlas
        .boundaries
        .iter()
        .map(|c| (c, clip_polyline(&c.points, frame.x, frame.y)))
        .filter(|(_, parts)| !parts.is_empty())
        .collect();
    legend.extend(
        KINDS
            .iter()
            .filter(|&&k| curves.iter().any(|c| c.0.kind == k))
            .map(|&k| (Swatch::Boundary(k), format!("{k} boundary"))),
    );
    // The nonlinear curves (D = 0, 1:2, 1:3), when the atlas was asked for them.
    let nonlinear: Vec<&NonlinearCurve> = atlas
        .nonlinear
        .iter()
        .filter(|c| !c.segments.is_empty())
        .collect();
    legend.extend(nonlinear.iter().map(|c| {
        (
            Swatch::Line(boundary_color(c.kind, mono), nonlinear_stroke(c.resonance)),
            match c.resonance {
                Some(r) => format!("{r} resonance"),
                None => "D = 0 (Arnold-degenerate)".to_string(),
            },
        )
    }));
    let overlays = Overlays::clip(opts, &frame);
    legend.extend(overlays.legend());

    draw_figure(path, opts, &frame, &legend, |root, chart| {
        let px = |pts: &[(f64, f64)]| -> Vec<Px> {
            pts.iter().map(|p| chart.backend_coord(p)).collect()
        };
        let rect = plot_rect(chart, &frame);
        let (w, h) = (
            f64::from((rect.x1 - rect.x0).max(1)),
            f64::from((rect.y1 - rect.y0).max(1)),
        );
        let to_data = |px: f64, py: f64| {
            (
                frame.x.0 + (px - f64::from(rect.x0)) / w * (frame.x.1 - frame.x.0),
                frame.y.1 - (py - f64::from(rect.y0)) / h * (frame.y.1 - frame.y.0),
            )
        };
        Regions::new(atlas, rect, to_data).paint(root, mono)?;
        draw_crosses(root, chart, atlas, (&ex, &ey))?;
        let fpx = float_px(chart, &frame);
        for (curve, parts) in &curves {
            let parts: Vec<Vec<PxF>> = parts.iter().map(|p| p.iter().map(&fpx).collect()).collect();
            stroke_boundary(root, &parts, curve.kind, mono)?;
        }
        draw_nonlinear(root, chart, &nonlinear, mono, &Sizes::of(opts))?;
        overlays.draw(root, px)?;
        let (a, b) = (
            chart.backend_coord(&(frame.x.0, frame.y.1)),
            chart.backend_coord(&(frame.x.1, frame.y.0)),
        );
        root.draw(&Rectangle::new([a, b], BLACK.stroke_width(1)))
            .map_err(drawing_error)
    })
}

/// Strokes the nonlinear curves segment by segment, each with its name (`D = 0`, `1:2`, `1:3`)
/// on a white ground beside its middle segment.
fn draw_nonlinear(
    root: &Root,
    chart: &Chart,
    curves: &[&NonlinearCurve],
    mono: bool,
    sizes: &Sizes,
) -> Result<(), PlotError> {
    let size = sizes.annotation;
    let font = (FONT.family, asked_size(size)).into_font().color(&BLACK);
    for c in curves {
        let color = boundary_color(c.kind, mono);
        let stroke = nonlinear_stroke(c.resonance);
        for s in &c.segments {
            let pts = [chart.backend_coord(&s[0]), chart.backend_coord(&s[1])];
            stroke_path(root, &pts, color, stroke)?;
        }
        let mid = &c.segments[c.segments.len() / 2];
        let (a, b) = (chart.backend_coord(&mid[0]), chart.backend_coord(&mid[1]));
        let at = ((a.0 + b.0) / 2 + 6, (a.1 + b.1) / 2 - (0.6 * size) as i32);
        let label = c.label();
        let w = text_width(&label, size);
        root.draw(&Rectangle::new(
            [
                (at.0 - 2, at.1 - 1),
                (at.0 + w, at.1 + size.ceil() as i32 + 2),
            ],
            WHITE.mix(0.85).filled(),
        ))
        .map_err(drawing_error)?;
        root.draw(&Text::new(label, at, font.clone()))
            .map_err(drawing_error)?;
    }
    Ok(())
}

/// A small × in each cell of the grid (edges `ex × ey`) without a steady motion.
fn draw_crosses(
    root: &Root,
    chart: &Chart,
    atlas: &StabilityAtlas,
    (ex, ey): (&[f64], &[f64]),
) -> Result<(), PlotError> {
    for (j, row) in atlas.verdicts.iter().enumerate() {
        for (i, v) in row.iter().enumerate() {
            if v.is_none() {
                let a = chart.backend_coord(&(ex[i], ey[j + 1]));
                let b = chart.backend_coord(&(ex[i + 1], ey[j]));
                draw_cross(root, a, b)?;
            }
        }
    }
    Ok(())
}
