//! The frame of a figure: the data ranges, clipping to them, the axes with their ticks, the
//! reference curves of [`PlotOptions::overlays`], and the SVG file with the axes on the left and
//! the legend on the right.

use std::path::Path;

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::curve::PxF;
use super::labels::Rect;
use super::legend::{draw_legend, Entry, Layout, Swatch};
use super::marks::{fractional_polylines, reset_fine, stroke_path, Px, Root};
use super::style::{asked_size, overlay_stroke, Sizes, Stroke};
use super::{drawing_error, PlotError, PlotOptions};

/// The axes, in data coordinates.
pub(super) type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;
/// A polyline in data coordinates.
pub(super) type Polyline = Vec<(f64, f64)>;

/// The axes of a figure: their ranges and labels, and whether a grid is drawn.
pub(super) struct Frame<'l> {
    pub(super) x: (f64, f64),
    pub(super) y: (f64, f64),
    pub(super) x_label: &'l str,
    pub(super) y_label: &'l str,
    pub(super) mesh: bool,
    /// The vertical axis's ticks `(y, label)` in place of plotters' own (an axis whose labels are
    /// not its coordinate, e.g. the stability index on a log-like scale); `None`: plotters'.
    pub(super) y_ticks: Option<Vec<(f64, String)>>,
}

/// Writes the figure to `path`: the axes of `frame`, `draw` in them, and the legend to their
/// right, level with their top, or below them when it would take too much of the width
/// ([`Layout`]; a figure of [`PlotOptions::width_in`] grows by the legend's height).
pub(super) fn draw_figure(
    path: &Path,
    opts: &PlotOptions,
    frame: &Frame,
    legend: &[Entry],
    draw: impl FnOnce(&Root, &Chart) -> Result<(), PlotError>,
) -> Result<(), PlotError> {
    let sizes = Sizes::of(opts);
    let (width, base) = opts.pixels();
    let layout = Layout::of(legend, &sizes, width);
    let height = match layout {
        Layout::Below { height, .. } if opts.width_in.is_some() => base + height,
        _ => base,
    };
    write_svg(path, opts, (width, height), |root| {
        let (area, _) = match layout {
            Layout::Right(w) => root.split_horizontally(width - w),
            Layout::Below { height: h, .. } => root.split_vertically(height - h),
        };
        let chart = axes(&area, opts, frame, &sizes)?;
        if let Some(ticks) = &frame.y_ticks {
            draw_y_ticks(root, &chart, frame, ticks, &sizes)?;
        }
        draw(root, &chart)?;
        match layout {
            Layout::Right(w) => {
                let top = chart.backend_coord(&(frame.x.0, frame.y.1)).1;
                draw_legend(
                    root,
                    ((width - w) as i32 + 10, top),
                    legend,
                    opts.monochrome,
                    &sizes,
                    None,
                )
            }
            Layout::Below { wrap, height: h } => draw_legend(
                root,
                (15, (height - h) as i32 + 2),
                legend,
                opts.monochrome,
                &sizes,
                Some(wrap),
            ),
        }
    })
}

/// Renders `draw` into an SVG string of `size` pixels and writes it to `path` ([`write_whole`]),
/// its curves in fractional pixels ([`fractional_polylines`]); with [`PlotOptions::width_in`]
/// the SVG's width and height are in inches (its view box in pixels, 144 an inch).
pub(super) fn write_svg(
    path: &Path,
    opts: &PlotOptions,
    size: (u32, u32),
    draw: impl FnOnce(&Root) -> Result<(), PlotError>,
) -> Result<(), PlotError> {
    let mut svg = String::new();
    reset_fine();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(drawing_error)?;
        draw(&root)?;
        root.present().map_err(drawing_error)?;
    }
    let mut svg = fractional_polylines(&svg);
    if let Some(width_in) = opts.width_in {
        // The width as asked, the height in the proportion of the pixels (about 144 an inch).
        let per_in = f64::from(size.0) / width_in;
        let inches = |px: u32| {
            let s = format!("{:.3}", f64::from(px) / per_in);
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        };
        let old = format!("width=\"{}\" height=\"{}\"", size.0, size.1);
        let new = format!(
            "width=\"{}in\" height=\"{}in\"",
            inches(size.0),
            inches(size.1)
        );
        svg = svg.replacen(&old, &new, 1);
    }
    write_whole(path, svg.as_bytes())
}

thread_local! {
    /// Set by [`rendered`]: the bytes of the figure being made go here, not to a file.
    static CAPTURE: std::cell::RefCell<Option<Vec<u8>>> = const { std::cell::RefCell::new(None) };
}

/// Writes `bytes` to `path` whole or not at all, through the one writer of routh
/// ([`routh_core::files::write_file`]: a temporary beside the file, renamed; links written
/// through, pipes and devices in place; errors name the path). Within [`rendered`], keeps them
/// instead.
pub(super) fn write_whole(path: &Path, bytes: &[u8]) -> Result<(), PlotError> {
    let kept = CAPTURE.with(|c| match c.borrow_mut().as_mut() {
        Some(buf) => {
            buf.clear();
            buf.extend_from_slice(bytes);
            true
        }
        None => false,
    });
    if !kept {
        routh_core::files::write_file(path, bytes)?;
    }
    Ok(())
}

/// The bytes of the figure that `draw` (a figure function of this module, given a placeholder
/// path) makes, not written anywhere: for the command line, which writes the files of a run all
/// or none through [`routh_core::files::Staged`].
#[doc(hidden)]
pub fn rendered(draw: impl FnOnce(&Path) -> Result<(), PlotError>) -> Result<Vec<u8>, PlotError> {
    let outer = CAPTURE.with(|c| c.borrow_mut().replace(Vec::new()));
    let drawn = draw(Path::new("figure"));
    let bytes = CAPTURE.with(|c| std::mem::replace(&mut *c.borrow_mut(), outer));
    drawn.map(|()| bytes.unwrap_or_default())
}

/// The ticks of [`Frame::y_ticks`]: a short tick, a light grid line across the axes and the
/// label to the left of the axis, for each tick within the vertical range.
fn draw_y_ticks(
    root: &Root,
    chart: &Chart,
    frame: &Frame,
    ticks: &[(f64, String)],
    sizes: &Sizes,
) -> Result<(), PlotError> {
    let font = ("sans-serif", asked_size(sizes.tick))
        .into_font()
        .color(&BLACK)
        .pos(Pos::new(HPos::Right, VPos::Center));
    let (lo, hi) = (frame.y.0.min(frame.y.1), frame.y.0.max(frame.y.1));
    for (y, label) in ticks.iter().filter(|(y, _)| (lo..=hi).contains(y)) {
        let (x0, py) = chart.backend_coord(&(frame.x.0, *y));
        let (x1, _) = chart.backend_coord(&(frame.x.1, *y));
        if frame.mesh {
            stroke_path(
                root,
                &[(x0 + 1, py), (x1, py)],
                RGBColor(225, 225, 225),
                Stroke::Solid(1),
            )?;
        }
        stroke_path(root, &[(x0 - 5, py), (x0, py)], BLACK, Stroke::Solid(1))?;
        root.draw(&Text::new(label.clone(), (x0 - 8, py), font.clone()))
            .map_err(drawing_error)?;
    }
    Ok(())
}

/// The width in pixels of the widest of the tick labels at a font of `size` pixels (0.62 em a
/// character, DejaVu Sans's digits are 0.64 em and the minus 0.84 em).
fn ticks_width<'a>(labels: impl Iterator<Item = &'a str>, size: f64) -> f64 {
    labels
        .map(|l| {
            l.chars()
                .map(|c| if c == '−' { 0.84 } else { 0.64 })
                .sum::<f64>()
        })
        .fold(0.0, f64::max)
        * size
}

/// The axes, on the given part of the figure, their texts at `sizes`: the areas for the tick
/// labels and axis names made to fit them, and no more ticks than fit side by side.
fn axes<'a, 'b>(
    area: &'a Root<'b>,
    opts: &PlotOptions,
    frame: &Frame,
    sizes: &Sizes,
) -> Result<Chart<'a, 'b>, PlotError> {
    let ((x0, x1), (y0, y1)) = (frame.x, frame.y);
    let (area_w, area_h) = area.dim_in_pixel();
    let mut builder = ChartBuilder::on(area);
    if !opts.title.is_empty() {
        // Centred over the axes: shrink a long title so that it fits their width (about 0.55 em
        // a character), down to the size of the tick labels.
        let chars = opts.title.chars().count().max(1) as f64;
        let size = (f64::from(area_w) / (0.55 * chars)).clamp(sizes.tick, sizes.title);
        builder.caption(&opts.title, ("sans-serif", asked_size(size)));
    }
    let fx = tick_format(x0, x1);
    let fy = tick_format(y0, y1);
    // Candidate labels: the ends and the middle of each range, with the digits of its ticks.
    let samples = |f: &dyn Fn(&f64) -> String, a: f64, b: f64| {
        [a, b, 0.5 * (a + b), a + 0.1 * (b - a), b - 0.1 * (b - a)].map(|v| f(&v))
    };
    let y_labels: Vec<String> = match &frame.y_ticks {
        Some(t) => t.iter().map(|(_, l)| l.clone()).collect(),
        None => samples(&fy, y0, y1).to_vec(),
    };
    let x_labels = samples(&fx, x0, x1);
    let y_tick_w = ticks_width(y_labels.iter().map(String::as_str), sizes.tick);
    let x_tick_w = ticks_width(x_labels.iter().map(String::as_str), sizes.tick);
    let y_area = (y_tick_w + 12.0 + 1.5 * sizes.label + 6.0).ceil() as u32;
    let x_area = (8.0 + 1.3 * sizes.tick + 1.5 * sizes.label).ceil() as u32;
    let margin = 15;
    let mut chart = builder
        .margin(margin)
        .margin_right(margin + (0.5 * x_tick_w).ceil() as u32)
        .x_label_area_size(x_area)
        .y_label_area_size(y_area)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(drawing_error)?;
    // As many ticks as fit: labels at least 1.5 em apart across, 1.8 lines apart up.
    let axis_w = f64::from(area_w.saturating_sub(y_area + 2 * margin));
    let axis_h = f64::from(area_h.saturating_sub(x_area + 2 * margin));
    let nx = (axis_w / (x_tick_w + 1.5 * sizes.tick))
        .floor()
        .clamp(2.0, 10.0) as usize;
    let ny = (axis_h / (1.8 * sizes.tick)).floor().clamp(2.0, 10.0) as usize;
    let mut mesh_style = chart.configure_mesh();
    mesh_style.x_labels(nx).y_labels(ny);
    if frame.y_ticks.is_some() {
        // Drawn by `draw_y_ticks`; plotters' own y grid lines and labels left out.
        mesh_style.y_labels(0);
    }
    mesh_style
        .x_desc(frame.x_label)
        .y_desc(frame.y_label)
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .label_style(("sans-serif", asked_size(sizes.tick)))
        .axis_desc_style(("sans-serif", asked_size(sizes.label)))
        .light_line_style(RGBColor(238, 238, 238))
        .bold_line_style(RGBColor(215, 215, 215));
    if !frame.mesh {
        mesh_style.disable_mesh();
    }
    mesh_style.draw().map_err(drawing_error)?;
    Ok(chart)
}

/// Tick labels: decimals with as many digits as the tick spacing needs and a true minus sign
/// (U+2212); [`crate::style::tick_label`] (the one format of both renderers).
pub(super) fn tick_format(lo: f64, hi: f64) -> impl Fn(&f64) -> String {
    let step = ((hi - lo) / 10.0).abs().max(f64::MIN_POSITIVE);
    let scale = lo.abs().max(hi.abs());
    move |v: &f64| crate::style::tick_label(*v, step, scale)
}

/// The range `[lo, hi]` widened by 5 % on each side (a point: by half its size, at least 1e−3).
pub(super) fn padded(lo: f64, hi: f64) -> (f64, f64) {
    if hi > lo {
        let pad = 0.05 * (hi - lo);
        (lo - pad, hi + pad)
    } else {
        let pad = 0.5 * lo.abs().max(1e-3);
        (lo - pad, hi + pad)
    }
}

/// The smallest and largest finite value, if any.
pub(super) fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// Clips the polyline to the rectangle, splitting it where it leaves (Liang–Barsky per segment)
/// and at non-finite points.
pub(super) fn clip_polyline(
    pts: &[(f64, f64)],
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Vec<Polyline> {
    /// Ends the current part: kept if it is a line, dropped if it is a lone point.
    fn end_part(out: &mut Vec<Polyline>, cur: &mut Polyline) {
        if cur.len() >= 2 {
            out.push(std::mem::take(cur));
        }
        cur.clear();
    }
    let mut out: Vec<Polyline> = Vec::new();
    let mut cur: Polyline = Vec::new();
    let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if !(finite(&a) && finite(&b)) {
            end_part(&mut out, &mut cur);
            continue;
        }
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let mut visible = true;
        for (p, q) in [
            (-dx, a.0 - x0),
            (dx, x1 - a.0),
            (-dy, a.1 - y0),
            (dy, y1 - a.1),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    visible = false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        if !visible || t0 > t1 {
            end_part(&mut out, &mut cur);
            continue;
        }
        let pa = (a.0 + t0 * dx, a.1 + t0 * dy);
        let pb = (a.0 + t1 * dx, a.1 + t1 * dy);
        if cur.last() != Some(&pa) {
            end_part(&mut out, &mut cur);
            cur.push(pa);
        }
        cur.push(pb);
        if t1 < 1.0 {
            out.push(std::mem::take(&mut cur));
        }
    }
    end_part(&mut out, &mut cur);
    out
}

/// The overlays of [`PlotOptions::overlays`] clipped to the axes, by label (those wholly outside
/// left out).
pub(super) struct Overlays(Vec<(String, Vec<Polyline>)>);

impl Overlays {
    pub(super) fn clip(opts: &PlotOptions, frame: &Frame) -> Self {
        Overlays(
            opts.overlays
                .iter()
                .map(|o| (o.label.clone(), clip_polyline(&o.points, frame.x, frame.y)))
                .filter(|(_, parts)| !parts.is_empty())
                .collect(),
        )
    }

    /// Their legend rows, in turn.
    pub(super) fn legend(&self) -> impl Iterator<Item = Entry> + '_ {
        self.0
            .iter()
            .enumerate()
            .map(|(k, (label, _))| (Swatch::Line(BLACK, overlay_stroke(k)), label.clone()))
    }

    /// Strokes them in black, each part mapped to pixels by `to_px`.
    pub(super) fn draw(
        &self,
        root: &Root,
        to_px: impl Fn(&[(f64, f64)]) -> Vec<Px>,
    ) -> Result<(), PlotError> {
        for (k, (_, parts)) in self.0.iter().enumerate() {
            for part in parts {
                stroke_path(root, &to_px(part), BLACK, overlay_stroke(k))?;
            }
        }
        Ok(())
    }
}

/// The rectangle of the axes in backend pixels.
pub(super) fn plot_rect(chart: &Chart, frame: &Frame) -> Rect {
    let a = chart.backend_coord(&(frame.x.0, frame.y.1));
    let b = chart.backend_coord(&(frame.x.1, frame.y.0));
    Rect {
        x0: a.0.min(b.0),
        y0: a.1.min(b.1),
        x1: a.0.max(b.0),
        y1: a.1.max(b.1),
    }
}

/// The map from data coordinates to fractional backend pixels (the linear map of the axes,
/// without plotters' rounding to whole pixels).
pub(super) fn float_px(chart: &Chart, frame: &Frame) -> impl Fn(&(f64, f64)) -> PxF {
    let a = chart.backend_coord(&(frame.x.0, frame.y.1));
    let b = chart.backend_coord(&(frame.x.1, frame.y.0));
    let ((x0, x1), (y0, y1)) = (frame.x, frame.y);
    let (ax, ay, bx, by) = (a.0 as f64, a.1 as f64, b.0 as f64, b.1 as f64);
    move |p: &(f64, f64)| {
        (
            ax + (p.0 - x0) / (x1 - x0) * (bx - ax),
            ay + (y1 - p.1) / (y1 - y0) * (by - ay),
        )
    }
}
