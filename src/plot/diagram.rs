//! The figures of branches: the bifurcation diagram and the energy–momentum diagram, each a map
//! of the points of a [`BifurcationDiagram`] into the plane.

use std::collections::HashSet;
use std::path::Path;

use plotters::prelude::*;

use super::curve::PxF;
use super::frame::{draw_figure, extent, float_px, padded, plot_rect, Frame, Overlays};
use super::labels::{value, Rect};
use super::legend::{Entry, Swatch};
use super::marks::{along, draw_event_marker, draw_names, draw_rings, stroke_curve, Px};
use super::style::{verdict_color, verdict_stroke, Sizes, KINDS, VERDICTS};
use super::{drawing_error, PlotError, PlotOptions};
use crate::{BifurcationDiagram, BranchEvent, BranchSample, EventKind, Stability};

/// A run of equal verdict along a branch, in data coordinates.
struct Run {
    verdict: Stability,
    isolated: bool,
    points: Vec<(f64, f64)>,
    /// The run is its whole branch (one verdict all along).
    whole: bool,
}

/// Splits each branch into runs of equal verdict (a change of verdict between two points is put
/// at their midpoint), breaking at non-finite values.
fn runs(diagram: &BifurcationDiagram, map: &impl Fn(&BranchSample) -> (f64, f64)) -> Vec<Run> {
    let mut out = Vec::new();
    for branch in &diagram.branches {
        let run = |verdict: Stability, points: Vec<(f64, f64)>| Run {
            verdict,
            isolated: branch.isolated,
            points,
            whole: false,
        };
        let first = out.len();
        let mut cur: Option<Run> = None;
        let mut prev: Option<((f64, f64), Stability)> = None;
        for p in &branch.points {
            let q = map(p);
            let v = p.report.verdict;
            if !(q.0.is_finite() && q.1.is_finite()) {
                out.extend(cur.take());
                prev = None;
                continue;
            }
            match (&mut cur, prev) {
                (Some(r), Some((_, pv))) if pv == v => r.points.push(q),
                (Some(r), Some((pq, _))) => {
                    let m = (0.5 * (pq.0 + q.0), 0.5 * (pq.1 + q.1));
                    r.points.push(m);
                    out.extend(cur.replace(run(v, vec![m, q])));
                }
                _ => out.extend(cur.replace(run(v, vec![q]))),
            }
            prev = Some((q, v));
        }
        out.extend(cur);
        if out.len() == first + 1 {
            out[first].whole = true;
        }
    }
    out
}

/// The position of an event in the figure: on the segment of its branch (or of any branch, if
/// its index is out of range) nearest to `(s, γ)`, interpolated linearly.
fn event_position(
    diagram: &BifurcationDiagram,
    e: &BranchEvent,
    s_scale: f64,
    map: &impl Fn(&BranchSample) -> (f64, f64),
) -> Option<(f64, f64)> {
    let candidates: Vec<&crate::Branch> = match diagram.branches.get(e.branch) {
        Some(b) if !b.points.is_empty() => vec![b],
        _ => diagram.branches.iter().collect(),
    };
    let key = |p: &BranchSample| -> [f64; 4] {
        [
            p.s / s_scale,
            p.steady.gamma.x,
            p.steady.gamma.y,
            p.steady.gamma.z,
        ]
    };
    let target = [e.s / s_scale, e.gamma.x, e.gamma.y, e.gamma.z];
    let mut best: Option<(f64, (f64, f64))> = None;
    for b in candidates {
        let pts = &b.points;
        let segs: Vec<(usize, usize)> = if pts.len() == 1 {
            vec![(0, 0)]
        } else {
            (1..pts.len()).map(|i| (i - 1, i)).collect()
        };
        for (i, j) in segs {
            let (a, c) = (key(&pts[i]), key(&pts[j]));
            let d: Vec<f64> = (0..4).map(|k| c[k] - a[k]).collect();
            let dd: f64 = d.iter().map(|v| v * v).sum();
            let t = if dd > 0.0 {
                ((0..4).map(|k| (target[k] - a[k]) * d[k]).sum::<f64>() / dd).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let dist: f64 = (0..4).map(|k| (a[k] + t * d[k] - target[k]).powi(2)).sum();
            if !dist.is_finite() {
                continue;
            }
            let (qa, qc) = (map(&pts[i]), map(&pts[j]));
            let q = (qa.0 + t * (qc.0 - qa.0), qa.1 + t * (qc.1 - qa.1));
            if q.0.is_finite() && q.1.is_finite() && best.is_none_or(|(bd, _)| dist < bd) {
                best = Some((dist, q));
            }
        }
    }
    best.map(|(_, q)| q)
}

/// The name written beside a nonlinear event: `1:2`, `1:3` or `D = 0`.
fn event_name(e: &BranchEvent) -> Option<String> {
    match e.kind {
        EventKind::Resonance => Some(
            e.nonlinear
                .and_then(|n| n.resonance)
                .map_or_else(|| "resonance".to_string(), |r| r.to_string()),
        ),
        EventKind::ArnoldDegenerate => Some("D = 0".into()),
        _ => None,
    }
}

/// Whether [`branch_figure`] writes each event's name next to its marker (the energy–momentum
/// diagram, where branches cross at cusps and the markers alone are hard to read).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum EventNames {
    /// Markers only (the legend names them).
    Legend,
    /// Markers with their names beside them, too.
    Beside,
}

/// A diagram of branches and events with `map` giving the position of each point, and
/// `exact_event` the coordinates of an event known without interpolation (if any).
#[allow(clippy::too_many_arguments)]
pub(super) fn branch_figure(
    diagram: &BifurcationDiagram,
    path: &Path,
    opts: &PlotOptions,
    map: impl Fn(&BranchSample) -> (f64, f64),
    exact_event: impl Fn(&BranchEvent) -> (Option<f64>, Option<f64>),
    x_label: &str,
    y_label: &str,
    names: EventNames,
) -> Result<(), PlotError> {
    opts.check()?;
    if diagram.branches.iter().all(|b| b.points.is_empty()) {
        return Err(PlotError::EmptyData("the diagram has no branch point"));
    }
    let runs = runs(diagram, &map);
    if runs.is_empty() {
        return Err(PlotError::EmptyData(
            "no branch point has finite coordinates",
        ));
    }
    let s_scale = extent(
        diagram
            .branches
            .iter()
            .flat_map(|b| b.points.iter().map(|p| p.s)),
    )
    .map(|(lo, hi)| (hi - lo).max(1e-12 * lo.abs().max(1.0)))
    .unwrap_or(1.0);
    let values = opts.event_values;
    let events: Vec<(EventKind, (f64, f64), Option<String>)> = diagram
        .events
        .iter()
        .filter_map(|e| {
            let (ex, ey) = exact_event(e);
            let q = event_position(diagram, e, s_scale, &map);
            let x = ex.or(q.map(|q| q.0))?;
            let y = ey.or(q.map(|q| q.1))?;
            // The name beside the marker: a nonlinear event's always (`1:2`, `D = 0`), every
            // event's when the figure asks for names or values; with its value on request.
            let name = event_name(e)
                .or_else(|| (names == EventNames::Beside || values).then(|| e.kind.to_string()));
            let name = name.map(|n| {
                if values {
                    format!("{n} at {}", value(x))
                } else {
                    n
                }
            });
            (x.is_finite() && y.is_finite()).then_some((e.kind, (x, y), name))
        })
        .collect();
    let all = || {
        runs.iter()
            .flat_map(|r| r.points.iter().copied())
            .chain(events.iter().map(|e| e.1))
    };
    let xr = extent(all().map(|p| p.0)).expect("runs are non-empty and finite");
    let yr = extent(all().map(|p| p.1)).expect("runs are non-empty and finite");
    let frame = Frame {
        x: padded(xr.0, xr.1),
        y: padded(yr.0, yr.1),
        x_label,
        y_label,
        mesh: true,
        y_ticks: None,
    };
    let mono = opts.monochrome;

    // The runs as they will be drawn: too short a run (a sample or two at an event, under its
    // marker) is left out, and so from the legend, which lists only what is drawn.
    let at: Vec<(f64, f64)> = events.iter().map(|e| e.1).collect();
    let runs: Vec<Run> = drawn_runs(runs, &at, &frame, opts);
    let mut legend: Vec<Entry> = VERDICTS
        .iter()
        .filter(|&&v| runs.iter().any(|r| r.verdict == v))
        .map(|&v| {
            (
                Swatch::Line(verdict_color(v, mono), verdict_stroke(v)),
                v.to_string(),
            )
        })
        .collect();
    if runs.iter().any(|r| !r.isolated) {
        legend.push((Swatch::Rings, "circle of steady motions".into()));
    }
    legend.extend(
        KINDS
            .iter()
            .filter(|&&k| events.iter().any(|e| e.0 == k))
            .map(|&k| (Swatch::Event(k), k.to_string())),
    );
    let overlays = Overlays::clip(opts, &frame);
    legend.extend(overlays.legend());

    draw_figure(path, opts, &frame, &legend, |root, chart| {
        // In pixels, without repeats (a dense branch has many points per pixel).
        let px = |pts: &[(f64, f64)]| -> Vec<Px> {
            let mut v: Vec<Px> = pts.iter().map(|p| chart.backend_coord(p)).collect();
            v.dedup();
            v
        };
        let fpx = float_px(chart, &frame);
        let mut curves = Vec::new();
        // Stable runs last, so that they stay on top where branches cross.
        for &v in VERDICTS.iter().rev() {
            // The pixels covered by the runs of this verdict drawn so far: where a run lies on
            // one of them (the mirror image of a branch, which the map sends onto the same
            // curve) it is drawn once, so that two dash patterns do not fill each other's gaps
            // into a solid line.
            let mut covered: HashSet<Px> = HashSet::new();
            for run in runs.iter().filter(|r| r.verdict == v) {
                let pts: Vec<PxF> = run.points.iter().map(&fpx).collect();
                let color = verdict_color(v, mono);
                if px(&run.points).len() == 1 {
                    root.draw(&Circle::new(px(&run.points)[0], 3, color.filled()))
                        .map_err(drawing_error)?;
                    continue;
                }
                let parts = uncovered_parts(&pts, &covered);
                covered.extend(pixels_along(&pts));
                for part in &parts {
                    stroke_curve(root, part, color, verdict_stroke(v))?;
                    if !run.isolated {
                        let whole: Vec<Px> = part
                            .iter()
                            .map(|p| (p.0.round() as i32, p.1.round() as i32))
                            .collect();
                        draw_rings(root, &whole, color)?;
                    }
                }
                curves.extend(along(&pts));
            }
        }
        overlays.draw(root, px)?;
        // The markers, then the names placed clear of them and of one another.
        let mut labels = Vec::new();
        let mut markers = Vec::new();
        for (kind, q, name) in &events {
            let c = chart.backend_coord(q);
            draw_event_marker(root, c, *kind)?;
            markers.push(Rect::around(c, 8));
            if let Some(name) = name {
                labels.push((c, name.clone()));
            }
        }
        draw_names(
            root,
            &labels,
            &markers,
            &curves,
            plot_rect(chart, &frame),
            &Sizes::of(opts),
        )?;
        Ok(())
    })
}

/// The runs that show: not those lying wholly under an event's marker (within about 14 pixels
/// of it: the sample or two where a test is inconclusive exactly at the event), nor fragments
/// under 4 pixels long. Pixels are estimated from the figure's size (the axes take about 65 % of
/// its width and 85 % of its height).
fn drawn_runs(
    runs: Vec<Run>,
    events: &[(f64, f64)],
    frame: &Frame,
    opts: &PlotOptions,
) -> Vec<Run> {
    let (sx, sy) = (
        0.65 * f64::from(opts.width) / (frame.x.1 - frame.x.0),
        0.85 * f64::from(opts.height) / (frame.y.1 - frame.y.0),
    );
    let dist = |a: (f64, f64), b: (f64, f64)| ((a.0 - b.0) * sx).hypot((a.1 - b.1) * sy);
    let length = |pts: &[(f64, f64)]| -> f64 { pts.windows(2).map(|w| dist(w[0], w[1])).sum() };
    let under_marker = |pts: &[(f64, f64)]| {
        events
            .iter()
            .any(|&e| pts.iter().all(|&p| dist(p, e) <= 14.0))
    };
    runs.into_iter()
        .filter(|r| r.whole || (length(&r.points) >= 4.0 && !under_marker(&r.points)))
        .collect()
}

/// The whole pixels a polyline in fractional pixels passes through, a pixel apart.
fn pixels_along(pts: &[PxF]) -> Vec<Px> {
    let mut out: Vec<Px> = Vec::new();
    let mut push = |q: PxF| {
        let p = (q.0.round() as i32, q.1.round() as i32);
        if out.last() != Some(&p) {
            out.push(p);
        }
    };
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let n = (b.0 - a.0).hypot(b.1 - a.1).ceil().max(1.0) as usize;
        for k in 0..n {
            let t = k as f64 / n as f64;
            push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
        }
    }
    if let Some(&q) = pts.last() {
        push(q);
    }
    out
}

/// The parts of the polyline `pts` not lying on the pixels `covered` (within a pixel): its
/// segments that leave them, joined where they follow one another.
fn uncovered_parts(pts: &[PxF], covered: &HashSet<Px>) -> Vec<Vec<PxF>> {
    let near =
        |p: &Px| (-1..=1).any(|dx| (-1..=1).any(|dy| covered.contains(&(p.0 + dx, p.1 + dy))));
    let mut parts: Vec<Vec<PxF>> = Vec::new();
    let mut cur: Vec<PxF> = Vec::new();
    for w in pts.windows(2) {
        let on = !covered.is_empty() && pixels_along(w).iter().all(near);
        if on {
            if cur.len() >= 2 {
                parts.push(std::mem::take(&mut cur));
            }
            cur.clear();
        } else {
            if cur.is_empty() {
                cur.push(w[0]);
            }
            cur.push(w[1]);
        }
    }
    if cur.len() >= 2 {
        parts.push(cur);
    }
    parts
}
