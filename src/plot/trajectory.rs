//! Figures of one motion: the apex locus (the path of a body axis on the unit sphere in space,
//! seen from above) and the time histories of γ, ω and the drifts of the first integrals.
//! Readable without colour: every curve has its own line style.

use std::path::Path;

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::curve::PxF;
use super::frame::{clip_polyline, float_px, tick_format, write_svg, Frame};
use super::marks::{stroke_curve, stroke_path};
use super::style::{asked_size, Sizes, Stroke};
use super::{drawing_error, PlotError, PlotOptions};
use crate::nalgebra::UnitQuaternion;
use crate::{Trajectory, Vector3};

/// The points `R(t) a` (space coordinates) of the body axis `a` along the attitudes.
pub fn apex_path(attitude: &[UnitQuaternion<f64>], body_axis: &Vector3<f64>) -> Vec<Vector3<f64>> {
    let a = body_axis.normalize();
    attitude.iter().map(|q| q * a).collect()
}

/// Draws the apex locus: the path on the unit sphere in space of the body axis `body_axis`
/// (the symmetry axis `e₃` of a top: `Vector3::z()`), in orthographic projection seen from above
/// (x to the right, y up), as an SVG file.
///
/// The part of the path on the upper hemisphere (z ≥ 0) is a solid line, the part below a
/// dotted line; the start is a ring, the end a filled dot (the axis caption says so); the
/// horizon (the equator, |x| = 1) is dashed when it falls in the frame. The frame is the locus's extent, square, padded, so the
/// loops, cusps or waves of a top show at any tilt. `opts.title` is the caption.
///
/// `attitude` is [`Trajectory::attitude`] or
/// [`ReducedTrajectory::attitude`](crate::ReducedTrajectory::attitude) of a run with
/// [`SimOptions::attitude`](crate::SimOptions::attitude).
///
/// # Errors
///
/// [`PlotError::EmptyData`] without attitude (the run did not integrate it),
/// [`PlotError::InvalidData`] for a non-finite attitude or a zero axis, [`PlotError::Io`] and
/// [`PlotError::Drawing`] from writing.
pub fn apex_locus_svg<P: AsRef<Path>>(
    attitude: &[UnitQuaternion<f64>],
    body_axis: Vector3<f64>,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    if attitude.is_empty() {
        return Err(PlotError::EmptyData(
            "no attitude: simulate with SimOptions::attitude = true",
        ));
    }
    if !(body_axis.norm() > 0.0 && body_axis.iter().all(|x| x.is_finite())) {
        return Err(PlotError::InvalidData(format!(
            "body axis {body_axis:?} is not a finite non-zero vector"
        )));
    }
    let pts = apex_path(attitude, &body_axis);
    if pts.iter().any(|p| !p.iter().all(|x| x.is_finite())) {
        return Err(PlotError::InvalidData("non-finite attitude".into()));
    }
    check_size(opts)?;
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &pts {
        x0 = x0.min(p.x);
        x1 = x1.max(p.x);
        y0 = y0.min(p.y);
        y1 = y1.max(p.y);
    }
    let half = (0.5 * (x1 - x0).max(y1 - y0)).max(1e-3) * 1.1;
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (xr, yr) = ((cx - half)..(cx + half), (cy - half)..(cy + half));
    let (w, h) = opts.pixels();
    let side = w.min(h);
    let sizes = Sizes::of(opts);
    write_svg(path.as_ref(), opts, (side, side), |root| {
        let mut b = ChartBuilder::on(root);
        if !opts.title.is_empty() {
            b.caption(&opts.title, ("sans-serif", asked_size(sizes.title)));
        }
        let (fx, fy) = (tick_format(xr.start, xr.end), tick_format(yr.start, yr.end));
        let y_tick_w = [yr.start, yr.end, cy]
            .iter()
            .map(|v| fy(v).chars().count())
            .max()
            .unwrap_or(4) as f64
            * 0.66
            * sizes.tick;
        let mut chart = b
            .margin(15)
            .x_label_area_size((8.0 + 1.3 * sizes.tick + 1.5 * sizes.label).ceil() as u32)
            .y_label_area_size((y_tick_w + 12.0 + 1.5 * sizes.label + 6.0).ceil() as u32)
            .build_cartesian_2d(xr.clone(), yr.clone())
            .map_err(drawing_error)?;
        let below = pts.iter().any(|p| p.z < 0.0);
        // The key in the axis name where it fits; at a narrow width, the start and end only.
        let wide = f64::from(side) > 60.0 * sizes.label;
        let key = match (below, wide) {
            (true, true) => "x (space, horizontal);  ○ start, ● end, dotted: below the horizon",
            (false, true) => "x (space, horizontal);  ○ start, ● end",
            (true, false) => "x;  ○ start, ● end, dotted: below",
            (false, false) => "x;  ○ start, ● end",
        };
        let n = ((f64::from(side) - 150.0) / (6.0 * sizes.tick)).clamp(2.0, 10.0) as usize;
        chart
            .configure_mesh()
            .x_desc(key)
            .y_desc(if wide { "y (space, horizontal)" } else { "y" })
            .x_labels(n)
            .y_labels(n)
            .x_label_formatter(&fx)
            .y_label_formatter(&fy)
            .label_style(("sans-serif", asked_size(sizes.tick)))
            .axis_desc_style(("sans-serif", asked_size(sizes.label)))
            .light_line_style(RGBColor(238, 238, 238))
            .bold_line_style(RGBColor(215, 215, 215))
            .draw()
            .map_err(drawing_error)?;
        let frame = Frame {
            x: (xr.start, xr.end),
            y: (yr.start, yr.end),
            x_label: "",
            y_label: "",
            mesh: true,
            y_ticks: None,
        };
        let fpx = float_px(&chart, &frame);
        let clip = |part: &[(f64, f64)]| clip_polyline(part, frame.x, frame.y);
        // The horizon |(x, y)| = 1, where it falls in the frame.
        let horizon: Vec<(f64, f64)> = (0..=720)
            .map(|k| {
                let a = k as f64 / 720.0 * std::f64::consts::TAU;
                (a.cos(), a.sin())
            })
            .collect();
        for part in clip(&horizon) {
            let fine: Vec<PxF> = part.iter().map(&fpx).collect();
            stroke_curve(
                root,
                &fine,
                RGBColor(120, 120, 120),
                Stroke::Dashed(1, 6, 6),
            )?;
        }
        // The locus, split where it crosses the horizon: solid above, dotted below.
        let mut runs: Vec<(bool, Vec<(f64, f64)>)> = Vec::new();
        for p in &pts {
            let upper = p.z >= 0.0;
            match runs.last_mut() {
                Some((u, run)) if *u == upper => run.push((p.x, p.y)),
                _ => runs.push((upper, vec![(p.x, p.y)])),
            }
        }
        for (upper, run) in runs {
            let fine: Vec<PxF> = run.iter().map(&fpx).collect();
            let stroke = if upper {
                Stroke::Solid(2)
            } else {
                Stroke::Dashed(2, 1, 5)
            };
            stroke_curve(root, &fine, BLACK, stroke)?;
        }
        let (s, e) = (pts[0], pts[pts.len() - 1]);
        chart
            .draw_series([
                Circle::new((s.x, s.y), 6, ShapeStyle::from(&BLACK).stroke_width(2)),
                Circle::new((e.x, e.y), 4, BLACK.filled()),
            ])
            .map_err(drawing_error)?;
        Ok(())
    })
}

type Panel<'a> = (&'a str, Vec<(&'a str, Vec<f64>)>);

fn check_size(opts: &PlotOptions) -> Result<(), PlotError> {
    if !(opts.font_pt.is_finite() && (5.0..=24.0).contains(&opts.font_pt)) {
        return Err(PlotError::InvalidOptions(format!(
            "a font of {} pt (5 to 24)",
            opts.font_pt
        )));
    }
    if let Some(w) = opts.width_in {
        if !(w.is_finite() && (2.0..=40.0).contains(&w)) {
            return Err(PlotError::InvalidOptions(format!(
                "a figure {w} in wide (2 to 40 in)"
            )));
        }
    }
    let (w, h) = opts.pixels();
    if w < 250 || h < 250 {
        return Err(PlotError::InvalidOptions(format!(
            "a figure of {w}×{h} pixels is too small (at least 250×250)"
        )));
    }
    Ok(())
}

/// Draws the time histories of a full simulation in three panels, one above the other: γ₁, γ₂,
/// γ₃; ω₁, ω₂, ω₃ (solid, dashed, dotted in that order); and `log₁₀` of the largest drifts so
/// far, `max_{s ≤ t} |E(s) − E(0)|` (solid) and `max_{s ≤ t} |p_ψ(s) − p_ψ(0)|` (dashed), of the
/// energy (3) and the cyclic momentum (9), floored at 1e−18 (the drift itself oscillates at
/// round-off and would hide one curve behind the other). Each panel's legend is in a column to
/// its right, clear of the curves.
///
/// # Errors
///
/// [`PlotError::EmptyData`] for an empty trajectory, [`PlotError::InvalidOptions`] for a figure
/// smaller than 250×250, [`PlotError::Io`] and [`PlotError::Drawing`] from writing.
pub fn time_histories_svg<P: AsRef<Path>>(
    traj: &Trajectory,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    if traj.is_empty() {
        return Err(PlotError::EmptyData("empty trajectory"));
    }
    check_size(opts)?;
    let t = &traj.t;
    let comp = |v: &[Vector3<f64>], i: usize| -> Vec<f64> { v.iter().map(|x| x[i]).collect() };
    let drift = |x: &[f64]| -> Vec<f64> {
        let mut worst = 1e-18_f64;
        x.iter()
            .map(|v| {
                worst = worst.max((v - x[0]).abs());
                worst.log10()
            })
            .collect()
    };
    let panels: [Panel; 3] = [
        (
            "γ (body frame)",
            vec![
                ("γ₁", comp(&traj.gamma, 0)),
                ("γ₂", comp(&traj.gamma, 1)),
                ("γ₃", comp(&traj.gamma, 2)),
            ],
        ),
        (
            "ω (body frame)",
            vec![
                ("ω₁", comp(&traj.omega, 0)),
                ("ω₂", comp(&traj.omega, 1)),
                ("ω₃", comp(&traj.omega, 2)),
            ],
        ),
        (
            "log₁₀ max drift",
            vec![
                ("|E − E₀|", drift(&traj.energy)),
                ("|p_ψ − p_ψ₀|", drift(&traj.p_psi)),
            ],
        ),
    ];
    let sizes = Sizes::of(opts);
    write_svg(path.as_ref(), opts, opts.pixels(), |root| {
        let root = if opts.title.is_empty() {
            root.clone()
        } else {
            root.titled(&opts.title, ("sans-serif", asked_size(sizes.title)))
                .map_err(drawing_error)?
        };
        let areas = root.split_evenly((3, 1));
        let (t0, t1) = (t[0], t[t.len() - 1].max(t[0] + 1e-12));
        for (panel, (label, curves)) in areas.iter().zip(panels) {
            // The legend's column, to the right of the axes.
            // The widest name, |p_ψ − p_ψ₀|, is under 7 em.
            let legend_width = ((7.0 * sizes.legend) as u32 + 52).min(panel.dim_in_pixel().0 / 3);
            let (area, key) =
                panel.split_horizontally(panel.dim_in_pixel().0.saturating_sub(legend_width));
            let finite = curves
                .iter()
                .flat_map(|(_, v)| v.iter())
                .filter(|v| v.is_finite());
            let (lo, hi) = finite.fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
            let (lo, hi) = if lo <= hi { (lo, hi) } else { (-1.0, 1.0) };
            let pad = ((hi - lo) * 0.05).max(1e-9);
            let (ft, fy) = (tick_format(t0, t1), tick_format(lo - pad, hi + pad));
            let y_tick_w = [lo, hi, 0.5 * (lo + hi)]
                .iter()
                .map(|v| fy(v).chars().count())
                .max()
                .unwrap_or(4) as f64
                * 0.66
                * sizes.tick;
            let panel_h = f64::from(area.dim_in_pixel().1);
            let mut chart = ChartBuilder::on(&area)
                .margin(8)
                .x_label_area_size((6.0 + 1.3 * sizes.tick + 1.4 * sizes.label).ceil() as u32)
                .y_label_area_size((y_tick_w + 12.0 + 1.5 * sizes.label + 4.0).ceil() as u32)
                .build_cartesian_2d(t0..t1, (lo - pad)..(hi + pad))
                .map_err(drawing_error)?;
            let ny = ((panel_h - 60.0) / (1.8 * sizes.tick)).clamp(2.0, 6.0) as usize;
            chart
                .configure_mesh()
                .x_desc("t")
                .y_desc(label)
                .y_labels(ny)
                .label_style(("sans-serif", asked_size(sizes.tick)))
                .axis_desc_style(("sans-serif", asked_size(sizes.label)))
                .x_label_formatter(&ft)
                .y_label_formatter(&fy)
                .light_line_style(RGBColor(238, 238, 238))
                .bold_line_style(RGBColor(215, 215, 215))
                .draw()
                .map_err(drawing_error)?;
            let frame = Frame {
                x: (t0, t1),
                y: (lo - pad, hi + pad),
                x_label: "",
                y_label: "",
                mesh: true,
                y_ticks: None,
            };
            let fpx = float_px(&chart, &frame);
            let row = (1.6 * sizes.legend).ceil() as i32;
            let font = ("sans-serif", asked_size(sizes.legend))
                .into_font()
                .color(&BLACK)
                .pos(Pos::new(HPos::Left, VPos::Center));
            for (k, (name, ys)) in curves.into_iter().enumerate() {
                let pts: Vec<(f64, f64)> = t.iter().copied().zip(ys).collect();
                let stroke = match k {
                    0 => Stroke::Solid(2),
                    1 => Stroke::Dashed(1, 8, 5),
                    _ => Stroke::Dashed(1, 2, 4),
                };
                for part in clip_polyline(&pts, frame.x, frame.y) {
                    let fine: Vec<PxF> = part.iter().map(&fpx).collect();
                    stroke_curve(&root, &fine, BLACK, stroke)?;
                }
                // The legend entry: the line's sample and the name, one row per curve.
                let (kx, ky) = key.get_base_pixel();
                let y = ky + 12 + row * k as i32 + row / 2;
                stroke_path(&root, &[(kx + 6, y), (kx + 36, y)], BLACK, stroke)?;
                root.draw(&Text::new(name, (kx + 42, y), font.clone()))
                    .map_err(drawing_error)?;
            }
        }
        Ok(())
    })
}
