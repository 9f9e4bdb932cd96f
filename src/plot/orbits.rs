//! The figures of periodic orbits: the stability diagram and the periods of a family, orbits on
//! the sphere of γ, and Poincaré sections.

use std::collections::HashSet;
use std::f64::consts::TAU;
use std::path::Path;

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::curve::PxF;
use super::frame::{draw_figure, extent, float_px, padded, plot_rect, write_svg, Frame, Overlays};
use super::labels::{value, Rect};
use super::legend::{draw_legend, Entry, Layout, Swatch};
use super::marks::{
    along, draw_fixed_point, draw_names, draw_orbit_event_marker, stroke_curve, stroke_path, Px,
};
use super::style::{
    asked_size, orbit_color, orbit_event_name, orbit_stroke, orbit_verdict_name, palette, ramp,
    Sizes, Stroke, FONT, ORBIT_KINDS, ORBIT_VERDICTS, PARABOLIC_LINE,
};
use super::{drawing_error, x_label_or, PlotError, PlotOptions};
use crate::{OrbitFamily, OrbitStability, PeriodicOrbit, PoincareSection, Trajectory, Vector3};

/// The vertical coordinate of the stability index `k` in [`orbit_family_svg`](super::orbit_family_svg):
/// `k` itself on `[−1, 1]`, and one unit a decade beyond, `±(1 + log₁₀|k|)` (so `k = ±10` is
/// drawn at `±2`, `k = ±100` at `±3`); continuous and increasing, `NaN` for `NaN`.
pub fn stability_index_axis(k: f64) -> f64 {
    if k.abs() <= 1.0 {
        k
    } else {
        k.signum() * (1.0 + k.abs().log10())
    }
}

/// The label of `±10ⁿ` ([`crate::style::decade_label`]).
fn decade_label(n: i32, negative: bool) -> String {
    crate::style::decade_label(i64::from(n), negative)
}

/// The ticks of the index axis over `[lo, hi]` (axis coordinates): `0`, `±1` (and `±0.5` on a
/// short axis), the decades `±10ⁿ` beyond (every second or more on a tall axis), and `±2`, `±5`
/// (and `±20`, `±50`) when at most one decade shows.
fn index_ticks(lo: f64, hi: f64) -> Vec<(f64, String)> {
    let span = hi - lo;
    let mut ticks: Vec<(f64, String)> =
        vec![(-1.0, "−1".into()), (0.0, "0".into()), (1.0, "1".into())];
    if span <= 6.0 {
        ticks.push((-0.5, "−0.5".into()));
        ticks.push((0.5, "0.5".into()));
    }
    let top = hi.max(-lo);
    let decades = (top - 1.0).floor().max(0.0) as i32;
    let step = ((decades as f64 / 7.0).ceil() as i32).max(1);
    for n in (step..=decades).step_by(step as usize) {
        let y = 1.0 + n as f64;
        ticks.push((y, decade_label(n, false)));
        ticks.push((-y, decade_label(n, true)));
    }
    if decades <= 1 {
        for k in [2.0f64, 5.0, 20.0, 50.0] {
            if k < 10f64.powi(decades + 1) {
                let y = stability_index_axis(k);
                let label = format!("{k}");
                ticks.push((y, label.clone()));
                ticks.push((-y, format!("−{label}")));
            }
        }
    }
    ticks.retain(|(y, _)| *y >= lo && *y <= hi);
    ticks
}

/// The scalars of an orbit that the figures of a family map into the plane.
#[derive(Debug, Clone, Copy)]
struct Sample {
    energy: f64,
    index: f64,
    period: f64,
}

impl Sample {
    fn of(o: &PeriodicOrbit) -> Self {
        Sample {
            energy: o.energy,
            index: o.stability_index,
            period: o.period,
        }
    }

    fn lerp(&self, b: &Sample, s: f64) -> Sample {
        let l = |x: f64, y: f64| x + s * (y - x);
        Sample {
            energy: l(self.energy, b.energy),
            index: l(self.index, b.index),
            period: l(self.period, b.period),
        }
    }

    fn finite(&self) -> bool {
        self.energy.is_finite() && self.index.is_finite() && self.period.is_finite()
    }
}

/// Where between `a` and `b` the verdict changes: where `k` crosses `1` or `−1` if it does
/// (linearly interpolated), else half-way.
fn change_at(a: &Sample, b: &Sample) -> f64 {
    for bound in [1.0, -1.0] {
        let (da, db) = (a.index - bound, b.index - bound);
        if da * db < 0.0 {
            return da / (da - db);
        }
    }
    0.5
}

/// A run of equal verdict along a family, in the figure's coordinates.
struct Run {
    verdict: OrbitStability,
    points: Vec<(f64, f64)>,
}

/// Splits the family into runs of equal verdict (the change put where `k` crosses ±1), breaking
/// at orbits with non-finite values.
fn runs(orbits: &[PeriodicOrbit], map: &impl Fn(&Sample) -> (f64, f64)) -> Vec<Run> {
    let mut out = Vec::new();
    let mut cur: Option<Run> = None;
    let mut prev: Option<(Sample, OrbitStability)> = None;
    for o in orbits {
        let s = Sample::of(o);
        let q = map(&s);
        if !(s.finite() && q.0.is_finite() && q.1.is_finite()) {
            out.extend(cur.take());
            prev = None;
            continue;
        }
        let v = o.stability;
        match (&mut cur, prev) {
            (Some(r), Some((_, pv))) if pv == v => r.points.push(q),
            (Some(r), Some((ps, _))) => {
                let m = map(&ps.lerp(&s, change_at(&ps, &s)));
                r.points.push(m);
                out.extend(cur.replace(Run {
                    verdict: v,
                    points: vec![m, q],
                }));
            }
            _ => out.extend(cur.replace(Run {
                verdict: v,
                points: vec![q],
            })),
        }
        prev = Some((s, v));
    }
    out.extend(cur);
    out
}

/// What the vertical axis of a family's figure shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum FamilyAxis {
    /// The stability index on [`stability_index_axis`], with the lines `k = ±1`.
    Index,
    /// The period.
    Period,
}

/// The figure of a family: the energy across, the index or the period up, runs styled by
/// verdict, events marked and named.
pub(super) fn family_figure(
    family: &OrbitFamily,
    path: &Path,
    opts: &PlotOptions,
    axis: FamilyAxis,
) -> Result<(), PlotError> {
    opts.check()?;
    if family.orbits.is_empty() {
        return Err(PlotError::EmptyData("the family has no orbit"));
    }
    let map = |s: &Sample| match axis {
        FamilyAxis::Index => (s.energy, stability_index_axis(s.index)),
        FamilyAxis::Period => (s.energy, s.period),
    };
    let runs = runs(&family.orbits, &map);
    if runs.is_empty() {
        return Err(PlotError::EmptyData(
            "no orbit has a finite energy, period and stability index",
        ));
    }
    let events: Vec<_> = family
        .events
        .iter()
        .filter_map(|e| {
            let q = map(&Sample {
                energy: e.energy,
                ..Sample::of(&e.orbit)
            });
            (q.0.is_finite() && q.1.is_finite()).then_some((e.kind, q))
        })
        .collect();
    let all = || {
        runs.iter()
            .flat_map(|r| r.points.iter().copied())
            .chain(events.iter().map(|e| e.1))
    };
    let xr = extent(all().map(|p| p.0)).expect("runs are non-empty and finite");
    let mut yr = extent(all().map(|p| p.1)).expect("runs are non-empty and finite");
    if axis == FamilyAxis::Index {
        // Both lines k = ±1 always show.
        yr = (yr.0.min(-1.0), yr.1.max(1.0));
    }
    let (x, y) = (padded(xr.0, xr.1), padded(yr.0, yr.1));
    let (default_y, y_ticks) = match axis {
        FamilyAxis::Index => ("k", Some(index_ticks(y.0, y.1))),
        FamilyAxis::Period => ("T", None),
    };
    let frame = Frame {
        x,
        y,
        x_label: x_label_or(&opts.x_label, "E"),
        y_label: if opts.y_label.is_empty() {
            default_y
        } else {
            &opts.y_label
        },
        mesh: true,
        y_ticks,
    };
    let mono = opts.monochrome;
    let mut legend: Vec<Entry> = ORBIT_VERDICTS
        .iter()
        .filter(|&&v| runs.iter().any(|r| r.verdict == v))
        .map(|&v| {
            (
                Swatch::Line(orbit_color(v, mono), orbit_stroke(v)),
                orbit_verdict_name(v).to_string(),
            )
        })
        .collect();
    if axis == FamilyAxis::Index {
        legend.push((
            Swatch::Line(PARABOLIC_LINE, Stroke::Solid(1)),
            "k = ±1 (log scale beyond)".into(),
        ));
    }
    legend.extend(
        ORBIT_KINDS
            .iter()
            .filter(|&&k| events.iter().any(|e| e.0 == k))
            .map(|&k| (Swatch::OrbitEvent(k), orbit_event_name(k).to_string())),
    );
    let overlays = Overlays::clip(opts, &frame);
    legend.extend(overlays.legend());

    draw_figure(path, opts, &frame, &legend, |root, chart| {
        let px = |pts: &[(f64, f64)]| -> Vec<Px> {
            let mut v: Vec<Px> = pts.iter().map(|p| chart.backend_coord(p)).collect();
            v.dedup();
            v
        };
        if axis == FamilyAxis::Index {
            let font = (FONT.family, asked_size(Sizes::of(opts).annotation))
                .into_font()
                .color(&PARABOLIC_LINE)
                .pos(Pos::new(HPos::Right, VPos::Bottom));
            for (k, name) in [(1.0, "k = 1"), (-1.0, "k = −1")] {
                let line = px(&[(frame.x.0, k), (frame.x.1, k)]);
                stroke_path(root, &line, PARABOLIC_LINE, Stroke::Solid(1))?;
                let end = line[line.len() - 1];
                root.draw(&Text::new(name, (end.0 - 4, end.1 - 3), font.clone()))
                    .map_err(drawing_error)?;
            }
        }
        let mut curves = Vec::new();
        // Elliptic runs last, so that they stay on top.
        for &v in ORBIT_VERDICTS.iter().rev() {
            for run in runs.iter().filter(|r| r.verdict == v) {
                let pts = px(&run.points);
                let color = orbit_color(v, mono);
                if pts.len() == 1 {
                    root.draw(&Circle::new(pts[0], 3, color.filled()))
                        .map_err(drawing_error)?;
                    continue;
                }
                let fpx = float_px(chart, &frame);
                let fine: Vec<PxF> = run.points.iter().map(fpx).collect();
                stroke_curve(root, &fine, color, orbit_stroke(v))?;
                curves.extend(along(&fine));
            }
        }
        overlays.draw(root, px)?;
        let (mut names, mut markers) = (Vec::new(), Vec::new());
        for (kind, q) in &events {
            let c = chart.backend_coord(q);
            draw_orbit_event_marker(root, c, *kind)?;
            markers.push(Rect::around(c, 9));
            let name = orbit_event_name(*kind);
            names.push((
                c,
                if opts.event_values {
                    format!("{name} at E = {}", value(q.0))
                } else {
                    name.to_string()
                },
            ));
        }
        draw_names(
            root,
            &names,
            &markers,
            &curves,
            plot_rect(chart, &frame),
            &Sizes::of(opts),
        )
        .map(|_| ())
    })
}

/// The figure of Poincaré sections: the crossings as small dots, one colour per orbit, the fixed
/// points as large marks.
pub(super) fn section_figure(
    section: &PoincareSection,
    fixed_points: &[[f64; 2]],
    path: &Path,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    opts.check()?;
    if let Some(p) = fixed_points
        .iter()
        .find(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(PlotError::InvalidData(format!(
            "fixed point {p:?} is not finite"
        )));
    }
    let finite = |p: &&[f64; 2]| p[0].is_finite() && p[1].is_finite();
    let count = section.points().filter(finite).count();
    if count == 0 {
        return Err(PlotError::EmptyData("the section has no crossing"));
    }
    let cut = theta_cut(section.points().filter(finite).map(|p| p[0]));
    let place = |p: &[f64; 2]| -> (f64, f64) {
        match cut {
            Some(c) if p[0] <= c => (p[0] + TAU, p[1]),
            _ => (p[0], p[1]),
        }
    };
    let all = || {
        section
            .points()
            .filter(finite)
            .chain(fixed_points.iter())
            .map(place)
    };
    let xr = extent(all().map(|p| p.0)).expect("finite points");
    let yr = extent(all().map(|p| p.1)).expect("finite points");
    let frame = Frame {
        x: padded(xr.0, xr.1),
        y: padded(yr.0, yr.1),
        x_label: x_label_or(&opts.x_label, "θ"),
        y_label: if opts.y_label.is_empty() {
            "M_n"
        } else {
            &opts.y_label
        },
        mesh: true,
        y_ticks: None,
    };
    let mono = opts.monochrome;
    let orbits = section
        .orbits
        .iter()
        .filter(|o| !o.points.is_empty())
        .count();
    let mut legend: Vec<Entry> = vec![(
        Swatch::Dots(palette(0, mono)),
        format!("{count} crossings of {orbits} orbits"),
    )];
    if !fixed_points.is_empty() {
        legend.push((Swatch::FixedPoint, "periodic orbits (fixed points)".into()));
    }
    legend.push((
        Swatch::Text,
        format!(
            "p_ψ = {}, E = {}",
            short(section.p_psi),
            short(section.energy)
        ),
    ));
    let n = section.normal;
    legend.push((
        Swatch::Text,
        format!(
            "plane γ·n = 0, n = ({}, {}, {})",
            short(n.x),
            short(n.y),
            short(n.z)
        ),
    ));
    draw_figure(path, opts, &frame, &legend, |root, chart| {
        for (k, orbit) in section.orbits.iter().enumerate() {
            let color = palette(k, mono).filled();
            // One dot a pixel: dense orbits repeat pixels many times.
            let mut seen: HashSet<Px> = HashSet::new();
            for p in orbit.points.iter().filter(|p| finite(p)) {
                let c = chart.backend_coord(&place(p));
                if seen.insert(c) {
                    root.draw(&Circle::new(c, 1, color))
                        .map_err(drawing_error)?;
                }
            }
        }
        for p in fixed_points {
            draw_fixed_point(root, chart.backend_coord(&place(p)))?;
        }
        Ok(())
    })
}

/// Where to cut the circle of the angle θ so that the crossings stay together: `None` to draw
/// θ on `(−π, π]` as it is (the widest gap between the crossings' angles is across ±π already),
/// else the angle `c` after which the widest gap opens; angles `θ ≤ c` are then drawn at `θ + 2π`.
fn theta_cut(thetas: impl Iterator<Item = f64>) -> Option<f64> {
    let mut t: Vec<f64> = thetas.collect();
    if t.len() < 2 {
        return None;
    }
    t.sort_by(f64::total_cmp);
    let across = t[0] + TAU - t[t.len() - 1];
    let (i, gap) = t
        .windows(2)
        .enumerate()
        .map(|(i, w)| (i, w[1] - w[0]))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .expect("two angles or more");
    (gap > across).then_some(t[i])
}

/// A number in at most 4 significant decimals, for captions.
fn short(x: f64) -> String {
    let s = format!("{x:.4}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s.replacen('-', "−", 1)
    }
}

/// The grey of the principal planes on the sphere.
const GRID: RGBColor = RGBColor(170, 170, 170);

/// Orbits on the sphere of γ, seen from `view`.
pub(super) fn sphere_figure(
    orbits: &[Trajectory],
    view: Vector3<f64>,
    path: &Path,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    opts.check()?;
    if !(view.iter().all(|v| v.is_finite()) && view.norm() > 0.0) {
        return Err(PlotError::InvalidData(format!(
            "view direction {view:?} is not a finite non-zero vector"
        )));
    }
    let paths: Vec<&Trajectory> = orbits.iter().filter(|t| !t.gamma.is_empty()).collect();
    if paths.is_empty() {
        return Err(PlotError::EmptyData("no orbit has a point"));
    }
    if paths
        .iter()
        .any(|t| t.gamma.iter().any(|g| !g.iter().all(|x| x.is_finite())))
    {
        return Err(PlotError::InvalidData("non-finite γ".into()));
    }
    // The viewer is at +w; up is e₃ (e₂ when looking nearly along e₃), right = up × w.
    let w = (view / view.amax()).normalize();
    let up = if w.z.abs() < 0.9 {
        Vector3::z()
    } else {
        Vector3::y()
    };
    let u = (up - w * w.dot(&up)).normalize();
    let r = u.cross(&w);
    let mono = opts.monochrome;
    let n = paths.len();
    let mut legend: Vec<Entry> = Vec::new();
    if n == 1 {
        legend.push((
            Swatch::Line(ramp(0, 1, mono), Stroke::Solid(2)),
            "orbit".into(),
        ));
    } else {
        legend.push((
            Swatch::Line(ramp(0, n, mono), Stroke::Solid(2)),
            "first orbit".into(),
        ));
        legend.push((
            Swatch::Line(ramp(n - 1, n, mono), Stroke::Solid(2)),
            format!("last orbit ({n} in all)"),
        ));
    }
    legend.push((
        Swatch::Line(BLACK, FAR_SIDE),
        "on the far side of the sphere".into(),
    ));
    legend.push((
        Swatch::Line(GRID, Stroke::Solid(1)),
        "principal planes γᵢ = 0".into(),
    ));
    legend.push((
        Swatch::Text,
        format!(
            "γ seen from ({}, {}, {})",
            short(w.x),
            short(w.y),
            short(w.z)
        ),
    ));
    let sizes = Sizes::of(opts);
    let (width, base) = opts.pixels();
    // The legend to the right of the sphere, or below it when the figure is narrow (a figure
    // of `width_in` then grows by the legend's height).
    let layout = Layout::of(&legend, &sizes, width);
    let (legend_w, below) = match layout {
        Layout::Right(w) => (w, 0),
        Layout::Below { height, .. } => (0, height),
    };
    let height = if opts.width_in.is_some() {
        base + below
    } else {
        base
    };
    write_svg(path, opts, (width, height), |root| {
        let left_w = (width - legend_w) as i32;
        let mut top = 15;
        if !opts.title.is_empty() {
            let chars = opts.title.chars().count().max(1) as f64;
            let size = (left_w as f64 / (0.55 * chars)).clamp(sizes.tick, sizes.title);
            let font = ("sans-serif", asked_size(size))
                .into_font()
                .color(&BLACK)
                .pos(Pos::new(HPos::Center, VPos::Top));
            root.draw(&Text::new(opts.title.clone(), (left_w / 2, 12), font))
                .map_err(drawing_error)?;
            top += size as i32 + 10;
        }
        let h = (height - below) as i32;
        let radius = ((left_w - 60).min(h - top - 30) / 2).max(20);
        let centre = (left_w / 2, top + (h - top) / 2);
        // In fractional pixels: the curves are smoothed before they are rounded.
        let to_fpx = |g: &Vector3<f64>| -> PxF {
            (
                f64::from(centre.0) + radius as f64 * g.dot(&r),
                f64::from(centre.1) - radius as f64 * g.dot(&u),
            )
        };
        let to_px = |g: &Vector3<f64>| -> Px {
            let (x, y) = to_fpx(g);
            (x.round() as i32, y.round() as i32)
        };
        // The principal planes, then the limb.
        for i in 0..3 {
            // The great circle γᵢ = 0, spanned by the other two axes.
            let a: Vector3<f64> = Vector3::ith((i + 1) % 3, 1.0);
            let c: Vector3<f64> = Vector3::ith((i + 2) % 3, 1.0);
            let circle: Vec<Vector3<f64>> = (0..=360)
                .map(|i| {
                    let t = (i as f64).to_radians();
                    a * t.cos() + c * t.sin()
                })
                .collect();
            draw_on_sphere(root, &circle, &w, &to_fpx, GRID, 1)?;
        }
        root.draw(&Circle::new(centre, radius as u32, BLACK.stroke_width(1)))
            .map_err(drawing_error)?;
        // The body axes on the near side.
        let font = (FONT.family, asked_size(sizes.annotation))
            .into_font()
            .color(&BLACK);
        for (i, name) in ["e₁", "e₂", "e₃"].iter().enumerate() {
            for sign in [1.0, -1.0] {
                let e = Vector3::ith(i, sign);
                if e.dot(&w) < -1e-9 {
                    continue;
                }
                let c = to_px(&e);
                root.draw(&Circle::new(c, 3, BLACK.filled()))
                    .map_err(drawing_error)?;
                let label = if sign > 0.0 {
                    name.to_string()
                } else {
                    format!("−{name}")
                };
                let lift = sizes.annotation.ceil() as i32 + 3;
                root.draw(&Text::new(label, (c.0 + 6, c.1 - lift), font.clone()))
                    .map_err(drawing_error)?;
            }
        }
        for (k, t) in paths.iter().enumerate() {
            let pts: Vec<Vector3<f64>> = t.gamma.iter().map(|g| g.normalize()).collect();
            draw_on_sphere(root, &pts, &w, &to_fpx, ramp(k, n, mono), 2)?;
        }
        match layout {
            Layout::Right(_) => draw_legend(root, (left_w + 10, top), &legend, mono, &sizes, None),
            Layout::Below { wrap, .. } => {
                draw_legend(root, (15, h + 2), &legend, mono, &sizes, Some(wrap))
            }
        }
    })
}

/// The stroke of a curve's part on the far side of the sphere.
const FAR_SIDE: Stroke = Stroke::Dashed(1, 2, 4);

/// Draws the curve `pts` on the unit sphere seen from `w`: solid of width `width` on the near
/// side, thin dotted on the far side, split where it crosses the limb (the crossing
/// interpolated onto the limb, so that the parts join).
fn draw_on_sphere(
    root: &super::marks::Root,
    pts: &[Vector3<f64>],
    w: &Vector3<f64>,
    to_px: &impl Fn(&Vector3<f64>) -> PxF,
    color: RGBColor,
    width: u32,
) -> Result<(), PlotError> {
    let mut parts: Vec<(bool, Vec<PxF>)> = Vec::new();
    let mut prev: Option<(Vector3<f64>, f64)> = None;
    for p in pts {
        let d = p.dot(w);
        let near = d >= 0.0;
        match (parts.last_mut(), prev) {
            (Some((side, part)), Some(_)) if *side == near => part.push(to_px(p)),
            (Some((_, part)), Some((q, dq))) => {
                let s = dq / (dq - d);
                let limb = (q + (p - q) * s).normalize();
                part.push(to_px(&limb));
                parts.push((near, vec![to_px(&limb), to_px(p)]));
            }
            _ => parts.push((near, vec![to_px(p)])),
        }
        prev = Some((*p, d));
    }
    for (near, part) in parts {
        let stroke = if near { Stroke::Solid(width) } else { FAR_SIDE };
        stroke_curve(root, &part, color, stroke)?;
    }
    Ok(())
}
