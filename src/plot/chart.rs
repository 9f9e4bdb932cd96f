//! The figure of an orbit chart ([`orbit_chart_svg`](super::orbit_chart_svg)): the regions of
//! the families' orbits by linear stability, the chart's curves on top.

use std::path::Path;

use super::curve::PxF;
use super::frame::{draw_figure, extent, float_px, padded, Frame};
use super::legend::{Entry, Swatch};
use super::marks::{draw_orbit_event_marker, stroke_curve};
use super::style::{
    orbit_curve_look, orbit_region_fill, orbit_verdict_name, Stroke, ORBIT_VERDICTS,
};
use super::{drawing_error, PlotError, PlotOptions};
use crate::{OrbitChart, OrbitEventKind, OrbitStability, PeriodicOrbit};
use plotters::prelude::*;

/// A filled rectangle of the regions: `x` from `x0` to `x1`, `h` from `h0` to `h1`.
struct Cell {
    x: (f64, f64),
    h: (f64, f64),
    verdict: OrbitStability,
}

/// The cells of the regions: at each `x`, a strip half-way to its neighbours; along the family
/// between two neighbouring orbits, the strip is cut where `k` crosses `±1` (linearly
/// interpolated), each part in its verdict.
fn cells(chart: &OrbitChart) -> Vec<Cell> {
    let n = chart.x.len();
    let mut out = Vec::new();
    for i in 0..n {
        let Some(fam) = &chart.families[i] else {
            continue;
        };
        let es = chart.steady_energy[i];
        let left = if i > 0 {
            0.5 * (chart.x[i - 1] + chart.x[i])
        } else {
            chart.x[i]
        };
        let right = if i + 1 < n {
            0.5 * (chart.x[i] + chart.x[i + 1])
        } else {
            chart.x[i]
        };
        let h = |o: &PeriodicOrbit| o.energy - es;
        for pair in fam.orbits.windows(2) {
            let (a, b) = (&pair[0], &pair[1]);
            if !(h(a).is_finite() && h(b).is_finite()) {
                continue;
            }
            // Cut where k crosses ±1; each part takes the verdict of k at its middle (the
            // ends' own where they agree, so that a parabolic run stays parabolic).
            let (ka, kb) = (a.stability_index, b.stability_index);
            let mut cuts = vec![0.0, 1.0];
            for bound in [1.0, -1.0] {
                let (da, db) = (ka - bound, kb - bound);
                if da * db < 0.0 {
                    cuts.push(da / (da - db));
                }
            }
            cuts.sort_by(f64::total_cmp);
            let at = |s: f64| h(a) + s * (h(b) - h(a));
            for w in cuts.windows(2) {
                let verdict = if a.stability == b.stability {
                    a.stability
                } else {
                    OrbitStability::from_index(ka + 0.5 * (w[0] + w[1]) * (kb - ka), 0.0)
                };
                out.push(Cell {
                    x: (left, right),
                    h: (at(w[0]), at(w[1])),
                    verdict,
                });
            }
        }
    }
    out
}

pub(super) fn chart_figure(
    chart: &OrbitChart,
    path: &Path,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    opts.check()?;
    let cells = cells(chart);
    let finite = |p: &&[f64; 2]| p[0].is_finite() && p[1].is_finite();
    let curve_points = || {
        chart
            .curves
            .iter()
            .flat_map(|c| c.points.iter())
            .filter(finite)
    };
    if cells.is_empty() && curve_points().next().is_none() {
        return Err(PlotError::EmptyData("the chart has no family and no curve"));
    }
    let xr = extent(chart.x.iter().copied()).ok_or(PlotError::EmptyData("the chart has no x"))?;
    let yr = extent(
        cells
            .iter()
            .flat_map(|c| [c.h.0, c.h.1])
            .chain(curve_points().map(|p| p[1])),
    )
    .ok_or(PlotError::EmptyData("the chart has no finite h"))?;
    let frame = Frame {
        x: if xr.0 < xr.1 { xr } else { padded(xr.0, xr.1) },
        y: (yr.0.min(0.0), padded(yr.0, yr.1).1),
        x_label: super::x_label_or(&opts.x_label, "x"),
        y_label: if opts.y_label.is_empty() {
            "h = E − Eₛ"
        } else {
            &opts.y_label
        },
        mesh: false,
        y_ticks: None,
    };
    let mono = opts.monochrome;
    let mut legend: Vec<Entry> = ORBIT_VERDICTS
        .iter()
        .filter(|&&v| cells.iter().any(|c| c.verdict == v))
        .map(|&v| {
            (
                Swatch::Fill(orbit_region_fill(v, mono)),
                orbit_verdict_name(v).to_string(),
            )
        })
        .collect();
    // The kinds in the order of the chart's curves.
    let mut kinds: Vec<OrbitEventKind> = Vec::new();
    for c in &chart.curves {
        if !kinds.contains(&c.kind) {
            kinds.push(c.kind);
        }
    }
    for kind in kinds {
        let drawn: Vec<_> = chart.curves.iter().filter(|c| c.kind == kind).collect();
        if drawn.is_empty() {
            continue;
        }
        let (stroke, color, label) = orbit_curve_look(kind, mono);
        if drawn.iter().any(|c| c.points.len() > 1) {
            legend.push((Swatch::Line(color, stroke), label.to_string()));
        }
        if drawn.iter().any(|c| c.points.len() == 1) {
            legend.push((Swatch::OrbitEvent(kind), format!("{label}, at one x")));
        }
    }
    draw_figure(path, opts, &frame, &legend, |root, plot| {
        // The regions, then the curves on a white halo, then the curves met at one point.
        for c in &cells {
            let a = plot.backend_coord(&(c.x.0, c.h.0.max(c.h.1)));
            let b = plot.backend_coord(&(c.x.1, c.h.0.min(c.h.1)));
            // One pixel over the neighbours (no seam of the background between cells), but
            // not over the axes' lines.
            let bottom_left = plot.backend_coord(&(frame.x.0, frame.y.0));
            let a = (a.0.max(bottom_left.0 + 1), a.1);
            let b = (b.0.max(a.0) + 1, (b.1.max(a.1) + 1).min(bottom_left.1 - 1));
            root.draw(&Rectangle::new(
                [a, b],
                orbit_region_fill(c.verdict, mono).filled(),
            ))
            .map_err(drawing_error)?;
        }
        let fpx = float_px(plot, &frame);
        for c in &chart.curves {
            let fine: Vec<PxF> = c
                .points
                .iter()
                .filter(|p| p[0].is_finite() && p[1].is_finite())
                .map(|p| fpx(&(p[0], p[1])))
                .collect();
            if fine.len() < 2 {
                continue;
            }
            let (stroke, color, _) = orbit_curve_look(c.kind, mono);
            let width = match stroke {
                Stroke::Solid(w) | Stroke::Dashed(w, _, _) => w,
            };
            stroke_curve(root, &fine, WHITE, Stroke::Solid(width + 3))?;
            stroke_curve(root, &fine, color, stroke)?;
        }
        for c in chart.curves.iter().filter(|c| c.points.len() == 1) {
            let p = c.points[0];
            if p[0].is_finite() && p[1].is_finite() {
                draw_orbit_event_marker(root, plot.backend_coord(&(p[0], p[1])), c.kind)?;
            }
        }
        Ok(())
    })
}
