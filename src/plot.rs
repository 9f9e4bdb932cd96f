//! SVG figures of families of steady motions (feature `plot`, on by default): bifurcation
//! diagrams, Smale's energy–momentum diagram and stability atlases, drawn with `plotters`.
//!
//! Every figure reads without colour:
//!
//! - along a branch, runs of equal verdict are drawn as **thick solid** lines where
//!   [`Stability::SecularlyStable`], **thin solid** where [`Stability::GyroscopicallyStabilized`],
//!   **dashed** where [`Stability::Unstable`] and **dotted** where [`Stability::Degenerate`];
//!   branches of circles of steady motions (`isolated == false`) carry open rings along them;
//! - events are marked by shape: ▲ [`EventKind::Fold`], ● [`EventKind::BranchPoint`],
//!   ■ [`EventKind::HamiltonianHopf`];
//! - in an atlas, each verdict has its own grey level *and* pattern (plain, dots, diagonal
//!   hatching, cross-hatching), nodes where the steady motion does not exist are white with a
//!   small ×, and the boundary curves are drawn on top, solid, dashed or dotted by kind.
//!
//! A legend to the right of the axes names every line style, marker and shading that occurs.
//! Colour is added on top (switch it off with [`PlotOptions::monochrome`]).
//!
//! ```
//! use routh::plot::{bifurcation_diagram_svg, DiagramAxis, PlotOptions};
//! # let diagram = routh::BifurcationDiagram::default();
//! let opts = PlotOptions {
//!     title: "Lagrange top".into(),
//!     x_label: "p_ψ".into(),
//!     y: DiagramAxis::Tilt,
//!     ..PlotOptions::default()
//! };
//! # let path = std::env::temp_dir().join("routh-plot-module-doc.svg");
//! // An empty diagram is an error; a diagram from `routh::bifurcation_diagram` is drawn.
//! assert!(bifurcation_diagram_svg(&diagram, &path, &opts).is_err());
//! ```

use std::fmt;
use std::path::Path;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::element::{DashedPathElement, DottedPathElement};
use plotters::prelude::*;
use routh_core::Vector3;

use crate::{BifurcationDiagram, BranchEvent, BranchPoint, EventKind, Stability, StabilityAtlas};
use crate::{BoundaryCurve, SteadyMotion};

/// The errors of the plotting functions.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PlotError {
    /// The SVG file could not be written.
    #[error("cannot write the figure: {0}")]
    Io(#[from] std::io::Error),
    /// `plotters` failed while drawing.
    #[error("drawing failed: {0}")]
    Drawing(String),
    /// Nothing to plot (no branch point, no grid node, or no finite value).
    #[error("nothing to plot: {0}")]
    EmptyData(&'static str),
    /// The data are inconsistent (e.g. the verdict grid of an atlas does not match its axes).
    #[error("inconsistent data: {0}")]
    InvalidData(String),
    /// The options cannot be honoured (e.g. a figure too small for its legend).
    #[error("invalid plot options: {0}")]
    InvalidOptions(String),
}

fn drawing_error<E: fmt::Display>(e: E) -> PlotError {
    PlotError::Drawing(e.to_string())
}

/// The scalar of a steady motion on the vertical axis of [`bifurcation_diagram_svg`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum DiagramAxis {
    /// `γ₃ = γ.z`, the cosine of the tilt of the body axis `e₃` from the vertical.
    #[default]
    GammaZ,
    /// `γ₁ = γ.x`.
    GammaX,
    /// `γ₂ = γ.y`.
    GammaY,
    /// The tilt, the angle between γ and `e₃`, in degrees.
    Tilt,
    /// The amended potential `U_r` (34).
    AmendedPotential,
    /// The energy `E` (3).
    Energy,
    /// The rate `ψ̇` of rotation about the vertical (38).
    PsiDot,
}

impl DiagramAxis {
    /// The value of this scalar at a steady motion.
    ///
    /// ```
    /// use routh::plot::DiagramAxis;
    /// use routh::{SteadyMotion, Vector3};
    ///
    /// let s = 0.5f64.sqrt();
    /// let m = SteadyMotion {
    ///     p_psi: 1.0, gamma: Vector3::new(s, 0.0, s), psi_dot: 2.0, mu: 0.0,
    ///     amended_potential: 3.0, energy: 3.0, isolated: true,
    /// };
    /// assert!((DiagramAxis::Tilt.value(&m) - 45.0).abs() < 1e-12);
    /// assert_eq!(DiagramAxis::PsiDot.value(&m), 2.0);
    /// ```
    pub fn value(self, steady: &SteadyMotion) -> f64 {
        match self {
            DiagramAxis::AmendedPotential => steady.amended_potential,
            DiagramAxis::Energy => steady.energy,
            DiagramAxis::PsiDot => steady.psi_dot,
            _ => self
                .of_gamma(&steady.gamma)
                .expect("the other axes are functions of γ"),
        }
    }

    /// The value of this scalar at the vertical γ, if it depends on γ alone.
    pub fn of_gamma(self, gamma: &Vector3<f64>) -> Option<f64> {
        match self {
            DiagramAxis::GammaZ => Some(gamma.z),
            DiagramAxis::GammaX => Some(gamma.x),
            DiagramAxis::GammaY => Some(gamma.y),
            DiagramAxis::Tilt => {
                let n = gamma.norm();
                Some((gamma.z / n).clamp(-1.0, 1.0).acos().to_degrees())
            }
            DiagramAxis::AmendedPotential | DiagramAxis::Energy | DiagramAxis::PsiDot => None,
        }
    }

    /// The default label of the axis.
    pub fn label(self) -> &'static str {
        match self {
            DiagramAxis::GammaZ => "γ₃ (cosine of the tilt)",
            DiagramAxis::GammaX => "γ₁",
            DiagramAxis::GammaY => "γ₂",
            DiagramAxis::Tilt => "tilt of e₃ from the vertical (degrees)",
            DiagramAxis::AmendedPotential => "amended potential U_r",
            DiagramAxis::Energy => "energy E",
            DiagramAxis::PsiDot => "ψ̇",
        }
    }
}

/// Options of the figures.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotOptions {
    /// Caption above the axes (empty: none; default empty).
    pub title: String,
    /// Label of the horizontal axis: the parameter's name (default `"s"`). The energy–momentum
    /// diagram, whose horizontal axis is always `p_ψ`, says `"p_ψ"` when this is `"s"` or empty.
    pub x_label: String,
    /// Label of the vertical axis (empty, the default: [`DiagramAxis::label`] of [`Self::y`] for
    /// a bifurcation diagram, `"energy E"` for an energy–momentum diagram, `"y"` for an atlas).
    pub y_label: String,
    /// Width of the figure in pixels, legend included (default `900`, at least `400`).
    pub width: u32,
    /// Height of the figure in pixels (default `600`, at least `250`).
    pub height: u32,
    /// The scalar of the steady motion on the vertical axis of a bifurcation diagram (default
    /// [`DiagramAxis::GammaZ`]).
    pub y: DiagramAxis,
    /// Black, white and greys only (default `false`: the line styles, markers and patterns are
    /// the same, colour is added on top).
    pub monochrome: bool,
    /// Reference curves drawn on top of a bifurcation diagram or an atlas, in the data's
    /// coordinates, each named in the legend — e.g. a closed form to compare with (default none).
    pub overlays: Vec<Overlay>,
}

/// A named reference curve of [`PlotOptions::overlays`], drawn in black over the data (long
/// dashes, short dashes, a thin line, in turn).
#[derive(Debug, Clone, PartialEq)]
pub struct Overlay {
    /// The legend text.
    pub label: String,
    /// The points `(x, y)` in order; non-finite points break the line.
    pub points: Vec<(f64, f64)>,
}

impl Default for PlotOptions {
    fn default() -> Self {
        PlotOptions {
            title: String::new(),
            x_label: "s".into(),
            y_label: String::new(),
            width: 900,
            height: 600,
            y: DiagramAxis::GammaZ,
            monochrome: false,
            overlays: Vec::new(),
        }
    }
}

impl PlotOptions {
    fn check(&self) -> Result<(), PlotError> {
        if self.width < 400 || self.height < 250 {
            return Err(PlotError::InvalidOptions(format!(
                "a figure of {} × {} pixels is too small (at least 400 × 250)",
                self.width, self.height
            )));
        }
        Ok(())
    }
}

// --- styles ------------------------------------------------------------------------------------

/// The strokes of [`Overlay`] curves, in turn: long dashes, short dashes, a thin line.
const OVERLAY_STROKES: [Stroke; 3] = [
    Stroke::Dashed(2, 12, 4),
    Stroke::Dashed(2, 4, 6),
    Stroke::Solid(1),
];

/// The stroke of the `k`-th overlay.
fn overlay_stroke(k: usize) -> Stroke {
    OVERLAY_STROKES[k % OVERLAY_STROKES.len()]
}

/// The overlays of `opts` clipped to the rectangle `xr × yr`, by label.
fn overlay_parts(
    opts: &PlotOptions,
    xr: (f64, f64),
    yr: (f64, f64),
) -> Vec<(String, Vec<Polyline>)> {
    opts.overlays
        .iter()
        .map(|o| (o.label.clone(), clip_polyline(&o.points, xr, yr)))
        .filter(|(_, parts)| !parts.is_empty())
        .collect()
}

const VERDICTS: [Stability; 4] = [
    Stability::SecularlyStable,
    Stability::GyroscopicallyStabilized,
    Stability::Unstable,
    Stability::Degenerate,
];

const KINDS: [EventKind; 3] = [
    EventKind::Fold,
    EventKind::BranchPoint,
    EventKind::HamiltonianHopf,
];

/// How a polyline is stroked.
#[derive(Debug, Clone, Copy)]
enum Stroke {
    Solid(u32),
    /// Width, dash, gap (pixels).
    Dashed(u32, u32, u32),
}

fn verdict_stroke(v: Stability) -> Stroke {
    match v {
        Stability::SecularlyStable => Stroke::Solid(4),
        Stability::GyroscopicallyStabilized => Stroke::Solid(1),
        Stability::Unstable => Stroke::Dashed(2, 9, 6),
        Stability::Degenerate => Stroke::Dashed(2, 2, 4),
    }
}

fn verdict_color(v: Stability, mono: bool) -> RGBColor {
    if mono {
        return BLACK;
    }
    match v {
        Stability::SecularlyStable => RGBColor(0, 130, 55),
        Stability::GyroscopicallyStabilized => RGBColor(25, 80, 210),
        Stability::Unstable => RGBColor(205, 30, 30),
        Stability::Degenerate => RGBColor(110, 110, 110),
    }
}

fn boundary_stroke(k: EventKind) -> Stroke {
    match k {
        EventKind::Fold => Stroke::Solid(3),
        EventKind::BranchPoint => Stroke::Dashed(3, 12, 5),
        EventKind::HamiltonianHopf => Stroke::Dashed(3, 3, 4),
    }
}

fn boundary_color(k: EventKind, mono: bool) -> RGBColor {
    if mono {
        return BLACK;
    }
    match k {
        EventKind::Fold => BLACK,
        EventKind::BranchPoint => RGBColor(90, 0, 130),
        EventKind::HamiltonianHopf => RGBColor(150, 50, 0),
    }
}

/// Fill of an atlas cell: background colour and pattern.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Pattern {
    Plain,
    Dots,
    Hatch,
    CrossHatch,
}

fn cell_fill(v: Stability, mono: bool) -> (RGBColor, Pattern) {
    let (grey, tint, pattern) = match v {
        Stability::SecularlyStable => (240, RGBColor(228, 244, 228), Pattern::Plain),
        Stability::GyroscopicallyStabilized => (212, RGBColor(200, 214, 240), Pattern::Dots),
        Stability::Unstable => (180, RGBColor(238, 178, 172), Pattern::Hatch),
        Stability::Degenerate => (150, RGBColor(160, 160, 160), Pattern::CrossHatch),
    };
    (
        if mono {
            RGBColor(grey, grey, grey)
        } else {
            tint
        },
        pattern,
    )
}

type Root<'a> = DrawingArea<SVGBackend<'a>, Shift>;
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;
type Px = (i32, i32);
/// A polyline in data coordinates.
type Polyline = Vec<(f64, f64)>;

fn stroke_path(root: &Root, pts: &[Px], color: RGBColor, stroke: Stroke) -> Result<(), PlotError> {
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

fn draw_rings(root: &Root, pts: &[Px], color: RGBColor) -> Result<(), PlotError> {
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

fn draw_event_marker(root: &Root, c: Px, kind: EventKind) -> Result<(), PlotError> {
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
    };
    r.map_err(drawing_error)
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
    const SP: i32 = 9;
    let ink = RGBColor(40, 40, 40);
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

fn draw_cross(root: &Root, (x0, y0): Px, (x1, y1): Px) -> Result<(), PlotError> {
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

// --- legend ------------------------------------------------------------------------------------

enum Swatch {
    Line(RGBColor, Stroke),
    Rings,
    Event(EventKind),
    Cell(Option<Stability>),
    Boundary(EventKind),
}

/// Draws the legend entries top-down in the panel whose top-left corner is `(x, y)` (backend
/// pixels).
fn draw_legend(
    root: &Root,
    (x, y): Px,
    entries: &[(Swatch, String)],
    mono: bool,
) -> Result<(), PlotError> {
    const ROW: i32 = 26;
    let font = ("sans-serif", 17).into_font().color(&BLACK);
    for (k, (swatch, text)) in entries.iter().enumerate() {
        let cy = y + ROW * k as i32 + ROW / 2;
        let (sx0, sx1) = (x, x + 44);
        match swatch {
            Swatch::Line(color, stroke) => {
                stroke_path(root, &[(sx0, cy), (sx1, cy)], *color, *stroke)?
            }
            Swatch::Rings => {
                stroke_path(root, &[(sx0, cy), (sx1, cy)], BLACK, Stroke::Solid(1))?;
                draw_rings(root, &[(sx0, cy), (sx1, cy)], BLACK)?;
            }
            Swatch::Event(kind) => draw_event_marker(root, ((sx0 + sx1) / 2, cy), *kind)?,
            Swatch::Cell(v) => {
                let (a, b) = ((sx0, cy - 9), (sx1, cy + 9));
                match v {
                    Some(v) => {
                        let (color, pattern) = cell_fill(*v, mono);
                        fill_cell(root, a, b, color, pattern)?;
                    }
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
                stroke_path(root, &[(sx0, cy), (sx1, cy)], WHITE, Stroke::Solid(7))?;
                stroke_path(
                    root,
                    &[(sx0, cy), (sx1, cy)],
                    boundary_color(*kind, mono),
                    boundary_stroke(*kind),
                )?;
            }
        }
        root.draw(&Text::new(text.clone(), (sx1 + 10, cy - 8), font.clone()))
            .map_err(drawing_error)?;
    }
    Ok(())
}

// --- axes --------------------------------------------------------------------------------------

/// Width of the legend panel: its longest text at about 7.5 pixels a character, after the swatch,
/// at most half the figure.
fn legend_width(entries: &[(Swatch, String)], width: u32) -> u32 {
    let chars = entries
        .iter()
        .map(|e| e.1.chars().count())
        .max()
        .unwrap_or(0) as u32;
    (74 + 15 * chars / 2 + 12).clamp(120, width / 2)
}

/// Tick labels as plain decimals, with as many digits as the tick spacing needs.
fn tick_format(lo: f64, hi: f64) -> impl Fn(&f64) -> String {
    let step = ((hi - lo) / 10.0).abs().max(f64::MIN_POSITIVE);
    let digits = ((-step.log10()).ceil().max(0.0) as usize + 1).min(12);
    move |v: &f64| {
        if v.abs() < step * 1e-6 {
            return "0".into();
        }
        let s = format!("{:.*}", digits, v);
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    }
}

fn padded(lo: f64, hi: f64) -> (f64, f64) {
    if hi > lo {
        let pad = 0.05 * (hi - lo);
        (lo - pad, hi + pad)
    } else {
        let pad = 0.5 * lo.abs().max(1e-3);
        (lo - pad, hi + pad)
    }
}

fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// The axes, on the left part of `root` (the legend panel is to their right).
#[allow(clippy::too_many_arguments)]
fn axes<'a, 'b>(
    area: &'a Root<'b>,
    opts: &PlotOptions,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    x_label: &str,
    y_label: &str,
    mesh: bool,
) -> Result<Chart<'a, 'b>, PlotError> {
    let mut builder = ChartBuilder::on(area);
    if !opts.title.is_empty() {
        // Centred over the axes: shrink a long title so that it fits their width (about 0.55 em
        // a character).
        let width = area.dim_in_pixel().0 as f64;
        let chars = opts.title.chars().count().max(1) as f64;
        let size = (width / (0.55 * chars)).clamp(10.0, 24.0);
        builder.caption(&opts.title, ("sans-serif", size));
    }
    let mut chart = builder
        .margin(15)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(drawing_error)?;
    let fx = tick_format(x0, x1);
    let fy = tick_format(y0, y1);
    let mut mesh_style = chart.configure_mesh();
    mesh_style
        .x_desc(x_label)
        .y_desc(y_label)
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .label_style(("sans-serif", 16))
        .axis_desc_style(("sans-serif", 19))
        .light_line_style(RGBColor(238, 238, 238))
        .bold_line_style(RGBColor(215, 215, 215));
    if !mesh {
        mesh_style.disable_mesh();
    }
    mesh_style.draw().map_err(drawing_error)?;
    Ok(chart)
}

/// Renders `draw` into an SVG string and writes it to `path`.
fn write_svg(
    path: &Path,
    opts: &PlotOptions,
    draw: impl FnOnce(&Root) -> Result<(), PlotError>,
) -> Result<(), PlotError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (opts.width, opts.height)).into_drawing_area();
        root.fill(&WHITE).map_err(drawing_error)?;
        draw(&root)?;
        root.present().map_err(drawing_error)?;
    }
    std::fs::write(path, svg)?;
    Ok(())
}

// --- branches ----------------------------------------------------------------------------------

/// A run of equal verdict along a branch, in data coordinates.
struct Run {
    verdict: Stability,
    isolated: bool,
    points: Vec<(f64, f64)>,
}

/// Splits each branch into runs of equal verdict (a change of verdict between two points is put
/// at their midpoint), breaking at non-finite values.
fn runs(diagram: &BifurcationDiagram, map: &impl Fn(&BranchPoint) -> (f64, f64)) -> Vec<Run> {
    let mut out = Vec::new();
    for branch in &diagram.branches {
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
                (Some(run), Some((pq, pv))) => {
                    if pv == v {
                        run.points.push(q);
                    } else {
                        let m = (0.5 * (pq.0 + q.0), 0.5 * (pq.1 + q.1));
                        run.points.push(m);
                        out.extend(cur.take());
                        cur = Some(Run {
                            verdict: v,
                            isolated: branch.isolated,
                            points: vec![m, q],
                        });
                    }
                }
                _ => {
                    out.extend(cur.take());
                    cur = Some(Run {
                        verdict: v,
                        isolated: branch.isolated,
                        points: vec![q],
                    });
                }
            }
            prev = Some((q, v));
        }
        out.extend(cur);
    }
    out
}

/// The position of an event in the figure: on the segment of its branch (or of any branch, if
/// its index is out of range) nearest to `(s, γ)`, interpolated linearly.
fn event_position(
    diagram: &BifurcationDiagram,
    e: &BranchEvent,
    s_scale: f64,
    map: &impl Fn(&BranchPoint) -> (f64, f64),
) -> Option<(f64, f64)> {
    let candidates: Vec<&crate::Branch> = match diagram.branches.get(e.branch) {
        Some(b) if !b.points.is_empty() => vec![b],
        _ => diagram.branches.iter().collect(),
    };
    let key = |p: &BranchPoint| -> [f64; 4] {
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

/// A diagram of branches and events with `map` giving the position of each point.
fn branch_figure(
    diagram: &BifurcationDiagram,
    path: &Path,
    opts: &PlotOptions,
    map: impl Fn(&BranchPoint) -> (f64, f64),
    exact_event: impl Fn(&BranchEvent) -> (Option<f64>, Option<f64>),
    x_label: &str,
    y_label: &str,
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
    let events: Vec<(EventKind, (f64, f64))> = diagram
        .events
        .iter()
        .filter_map(|e| {
            let (ex, ey) = exact_event(e);
            let q = event_position(diagram, e, s_scale, &map);
            let x = ex.or(q.map(|q| q.0))?;
            let y = ey.or(q.map(|q| q.1))?;
            (x.is_finite() && y.is_finite()).then_some((e.kind, (x, y)))
        })
        .collect();
    let all = || {
        runs.iter()
            .flat_map(|r| r.points.iter().copied())
            .chain(events.iter().map(|e| e.1))
    };
    let xr = extent(all().map(|p| p.0)).expect("runs are non-empty and finite");
    let yr = extent(all().map(|p| p.1)).expect("runs are non-empty and finite");
    let (xr, yr) = (padded(xr.0, xr.1), padded(yr.0, yr.1));
    let mono = opts.monochrome;

    let mut legend: Vec<(Swatch, String)> = VERDICTS
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
    let overlays = overlay_parts(opts, xr, yr);
    legend.extend(
        overlays
            .iter()
            .enumerate()
            .map(|(k, (label, _))| (Swatch::Line(BLACK, overlay_stroke(k)), label.clone())),
    );

    let legend_w = legend_width(&legend, opts.width);
    write_svg(path, opts, |root| {
        let (left, _) = root.split_horizontally(opts.width - legend_w);
        let chart = axes(&left, opts, xr, yr, x_label, y_label, true)?;
        // In pixels, without repeats (a dense branch has many points per pixel).
        let px = |pts: &[(f64, f64)]| -> Vec<Px> {
            let mut v: Vec<Px> = pts.iter().map(|p| chart.backend_coord(p)).collect();
            v.dedup();
            v
        };
        // Stable runs last, so that they stay on top where branches cross.
        for &v in VERDICTS.iter().rev() {
            for run in runs.iter().filter(|r| r.verdict == v) {
                let pts = px(&run.points);
                let color = verdict_color(v, mono);
                if pts.len() == 1 {
                    root.draw(&Circle::new(pts[0], 3, color.filled()))
                        .map_err(drawing_error)?;
                    continue;
                }
                stroke_path(root, &pts, color, verdict_stroke(v))?;
                if !run.isolated {
                    draw_rings(root, &pts, color)?;
                }
            }
        }
        for (k, (_, parts)) in overlays.iter().enumerate() {
            for part in parts {
                stroke_path(root, &px(part), BLACK, overlay_stroke(k))?;
            }
        }
        for &(kind, q) in &events {
            draw_event_marker(root, chart.backend_coord(&q), kind)?;
        }
        let top = chart.backend_coord(&(xr.0, yr.1)).1;
        draw_legend(
            root,
            ((opts.width - legend_w) as i32 + 10, top),
            &legend,
            mono,
        )
    })
}

/// Writes the bifurcation diagram as an SVG: the parameter `s` across, the scalar
/// [`PlotOptions::y`] of each steady motion up.
///
/// Each branch is drawn as a line, split into runs of equal verdict: thick solid where
/// secularly stable, thin solid where gyroscopically stabilised, dashed where unstable, dotted
/// where degenerate; branches of circles of steady motions carry open rings. Events are marked
/// ▲ (fold), ● (branch point) and ■ (Hamiltonian–Hopf). The legend names each style and marker
/// that occurs.
///
/// # Errors
///
/// [`PlotError::EmptyData`] if no branch has a point with finite coordinates,
/// [`PlotError::InvalidOptions`] for a figure smaller than 400 × 250 pixels, [`PlotError::Io`]
/// if the file cannot be written.
///
/// ```
/// use routh::plot::{bifurcation_diagram_svg, PlotOptions};
/// use routh::{
///     BifurcationDiagram, Branch, BranchPoint, Complex, Stability, StabilityReport,
///     SteadyMotion, Vector3,
/// };
///
/// // The sleeping top: stable for p_ψ > 2, unstable below.
/// let point = |p: f64| BranchPoint {
///     s: p,
///     steady: SteadyMotion {
///         p_psi: p, gamma: Vector3::z(), psi_dot: -p, mu: 0.0,
///         amended_potential: 1.0 + 0.5 * p * p, energy: 1.0 + 0.5 * p * p, isolated: true,
///     },
///     report: StabilityReport {
///         restricted_hessian_eigenvalues: [p * p / 4.0 - 1.0; 2],
///         degree_of_instability: if p > 2.0 { 0 } else { 2 },
///         f2_roots: [Complex::new(0.0, 0.0); 4],
///         verdict: if p > 2.0 { Stability::SecularlyStable } else { Stability::Unstable },
///     },
/// };
/// let diagram = BifurcationDiagram {
///     branches: vec![Branch { points: (0..=40).map(|i| point(0.1 * i as f64)).collect(), isolated: true }],
///     events: vec![],
/// };
/// let path = std::env::temp_dir().join("routh-doc-bifurcation.svg");
/// let opts = PlotOptions { x_label: "p_ψ".into(), ..PlotOptions::default() };
/// bifurcation_diagram_svg(&diagram, &path, &opts)?;
/// assert!(std::fs::read_to_string(&path)?.contains("secularly stable"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn bifurcation_diagram_svg<P: AsRef<Path>>(
    diagram: &BifurcationDiagram,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    let axis = opts.y;
    let y_label = if opts.y_label.is_empty() {
        axis.label()
    } else {
        opts.y_label.as_str()
    };
    branch_figure(
        diagram,
        path.as_ref(),
        opts,
        |p| (p.s, axis.value(&p.steady)),
        |e| (Some(e.s), axis.of_gamma(&e.gamma)),
        &opts.x_label,
        y_label,
    )
}

/// Writes Smale's energy–momentum diagram as an SVG: the energy `E` of each steady motion of the
/// diagram up, against its cyclic momentum `p_ψ` across.
///
/// For a diagram over `p_ψ` this is the diagram's own curves seen in the `(p_ψ, E)` plane; for a
/// diagram over a parameter of the body at fixed `p_ψ`, the branches stand on one vertical line.
/// Line styles, markers and legend are those of [`bifurcation_diagram_svg`] (events are placed
/// by interpolation along their branch). The horizontal axis is labelled
/// [`PlotOptions::x_label`], or `"p_ψ"` when that is the default `"s"` or empty.
///
/// # Errors
///
/// As [`bifurcation_diagram_svg`].
///
/// ```
/// use routh::plot::{energy_momentum_svg, PlotOptions};
/// use routh::{
///     BifurcationDiagram, Branch, BranchPoint, Complex, Stability, StabilityReport,
///     SteadyMotion, Vector3,
/// };
///
/// let point = |p: f64| BranchPoint {
///     s: p,
///     steady: SteadyMotion {
///         p_psi: p, gamma: Vector3::z(), psi_dot: -p, mu: 0.0,
///         amended_potential: 1.0 + 0.5 * p * p, energy: 1.0 + 0.5 * p * p, isolated: true,
///     },
///     report: StabilityReport {
///         restricted_hessian_eigenvalues: [1.0; 2],
///         degree_of_instability: 0,
///         f2_roots: [Complex::new(0.0, 0.0); 4],
///         verdict: Stability::SecularlyStable,
///     },
/// };
/// let diagram = BifurcationDiagram {
///     branches: vec![Branch { points: (0..=20).map(|i| point(0.2 * i as f64)).collect(), isolated: true }],
///     events: vec![],
/// };
/// let path = std::env::temp_dir().join("routh-doc-energy-momentum.svg");
/// energy_momentum_svg(&diagram, &path, &PlotOptions::default())?;
/// assert!(std::fs::read_to_string(&path)?.contains("p_ψ"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn energy_momentum_svg<P: AsRef<Path>>(
    diagram: &BifurcationDiagram,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    let x_label = if opts.x_label.is_empty() || opts.x_label == "s" {
        "p_ψ"
    } else {
        opts.x_label.as_str()
    };
    let y_label = if opts.y_label.is_empty() {
        DiagramAxis::Energy.label()
    } else {
        opts.y_label.as_str()
    };
    branch_figure(
        diagram,
        path.as_ref(),
        opts,
        |p| (p.steady.p_psi, p.steady.energy),
        |_| (None, None),
        x_label,
        y_label,
    )
}

// --- atlas -------------------------------------------------------------------------------------

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

/// Clips the polyline to the rectangle, splitting it where it leaves (Liang–Barsky per segment)
/// and at non-finite points.
fn clip_polyline(pts: &[(f64, f64)], (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> Vec<Polyline> {
    let mut out: Vec<Polyline> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let finite = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite();
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if !(finite(&a) && finite(&b)) {
            if cur.len() >= 2 {
                out.push(std::mem::take(&mut cur));
            }
            cur.clear();
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
            if cur.len() >= 2 {
                out.push(std::mem::take(&mut cur));
            }
            cur.clear();
            continue;
        }
        let pa = (a.0 + t0 * dx, a.1 + t0 * dy);
        let pb = (a.0 + t1 * dx, a.1 + t1 * dy);
        if cur.last() != Some(&pa) {
            if cur.len() >= 2 {
                out.push(std::mem::take(&mut cur));
            }
            cur = vec![pa];
        }
        cur.push(pb);
        if t1 < 1.0 {
            out.push(std::mem::take(&mut cur));
        }
    }
    if cur.len() >= 2 {
        out.push(cur);
    }
    out
}

/// Writes the stability atlas as an SVG: the parameter plane with each grid node's cell shaded by
/// its verdict and the boundary curves on top.
///
/// Each verdict has a grey level and a pattern: secularly stable plain light, gyroscopically
/// stabilised dotted, unstable hatched `/`, degenerate cross-hatched; where the steady motion does
/// not exist (`None`) the cell is white with a small ×. Boundary curves are solid (fold), dashed
/// (branch point) or dotted (Hamiltonian–Hopf), on a white underlay. The legend names each shading
/// and curve that occurs. The axes are labelled [`PlotOptions::x_label`] and
/// [`PlotOptions::y_label`] (`"y"` when empty); [`PlotOptions::y`] is not used.
///
/// # Errors
///
/// [`PlotError::EmptyData`] for an empty grid, [`PlotError::InvalidData`] if `verdicts` is not
/// `y.len()` rows of `x.len()` or the grid is not finite and ascending,
/// [`PlotError::InvalidOptions`] for a figure smaller than 400 × 250 pixels, [`PlotError::Io`] if
/// the file cannot be written.
///
/// ```
/// use routh::plot::{stability_atlas_svg, PlotOptions};
/// use routh::{BoundaryCurve, EventKind, Stability, StabilityAtlas};
///
/// let x: Vec<f64> = (0..=10).map(|i| i as f64 / 10.0).collect();
/// let y = x.clone();
/// let verdicts = y
///     .iter()
///     .map(|&y| {
///         x.iter()
///             .map(|&x| Some(if y > x { Stability::SecularlyStable } else { Stability::Unstable }))
///             .collect()
///     })
///     .collect();
/// let boundaries = vec![BoundaryCurve { kind: EventKind::BranchPoint, points: vec![(0.0, 0.0), (1.0, 1.0)] }];
/// let atlas = StabilityAtlas { x, y, verdicts, boundaries };
/// let path = std::env::temp_dir().join("routh-doc-atlas.svg");
/// let opts = PlotOptions { x_label: "mgl".into(), y_label: "p_ψ".into(), ..PlotOptions::default() };
/// stability_atlas_svg(&atlas, &path, &opts)?;
/// assert!(std::fs::read_to_string(&path)?.contains("branch point"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn stability_atlas_svg<P: AsRef<Path>>(
    atlas: &StabilityAtlas,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    opts.check()?;
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
    let (ex, ey) = (edges(&atlas.x), edges(&atlas.y));
    let xr = (ex[0], ex[nx]);
    let yr = (ey[0], ey[ny]);
    let mono = opts.monochrome;
    let y_label = if opts.y_label.is_empty() {
        "y"
    } else {
        opts.y_label.as_str()
    };

    let occurs = |v: Option<Stability>| atlas.verdicts.iter().flatten().any(|&c| c == v);
    let mut legend: Vec<(Swatch, String)> = VERDICTS
        .iter()
        .filter(|&&v| occurs(Some(v)))
        .map(|&v| (Swatch::Cell(Some(v)), v.to_string()))
        .collect();
    if occurs(None) {
        legend.push((Swatch::Cell(None), "no steady motion".into()));
    }
    let curves: Vec<(&BoundaryCurve, Vec<Polyline>)> = atlas
        .boundaries
        .iter()
        .map(|c| (c, clip_polyline(&c.points, xr, yr)))
        .filter(|(_, parts)| !parts.is_empty())
        .collect();
    legend.extend(
        KINDS
            .iter()
            .filter(|&&k| curves.iter().any(|c| c.0.kind == k))
            .map(|&k| (Swatch::Boundary(k), format!("{k} boundary"))),
    );
    let overlays = overlay_parts(opts, xr, yr);
    legend.extend(
        overlays
            .iter()
            .enumerate()
            .map(|(k, (label, _))| (Swatch::Line(BLACK, overlay_stroke(k)), label.clone())),
    );

    let legend_w = legend_width(&legend, opts.width);
    write_svg(path.as_ref(), opts, |root| {
        let (left, _) = root.split_horizontally(opts.width - legend_w);
        let chart = axes(&left, opts, xr, yr, &opts.x_label, y_label, false)?;
        // Pixel corners of the cell rectangle [ex[i0], ex[i1]] × [ey[j], ey[j + 1]].
        let rect = |i0: usize, i1: usize, j: usize| -> (Px, Px) {
            let a = chart.backend_coord(&(ex[i0], ey[j + 1]));
            let b = chart.backend_coord(&(ex[i1], ey[j]));
            (a, b)
        };
        for (j, row) in atlas.verdicts.iter().enumerate() {
            // Runs of equal verdict along the row, drawn as one rectangle each.
            let mut i0 = 0;
            while i0 < nx {
                let v = row[i0];
                let mut i1 = i0 + 1;
                while i1 < nx && row[i1] == v {
                    i1 += 1;
                }
                let (a, b) = rect(i0, i1, j);
                match v {
                    Some(v) => {
                        let (color, pattern) = cell_fill(v, mono);
                        fill_cell(root, a, b, color, pattern)?;
                    }
                    None => {
                        for i in i0..i1 {
                            let (a, b) = rect(i, i + 1, j);
                            draw_cross(root, a, b)?;
                        }
                    }
                }
                i0 = i1;
            }
        }
        for (curve, parts) in &curves {
            for part in parts {
                let pts: Vec<Px> = part.iter().map(|p| chart.backend_coord(p)).collect();
                stroke_path(root, &pts, WHITE, Stroke::Solid(7))?;
            }
            for part in parts {
                let pts: Vec<Px> = part.iter().map(|p| chart.backend_coord(p)).collect();
                stroke_path(
                    root,
                    &pts,
                    boundary_color(curve.kind, mono),
                    boundary_stroke(curve.kind),
                )?;
            }
        }
        for (k, (_, parts)) in overlays.iter().enumerate() {
            for part in parts {
                let pts: Vec<Px> = part.iter().map(|p| chart.backend_coord(p)).collect();
                stroke_path(root, &pts, BLACK, overlay_stroke(k))?;
            }
        }
        let (a, b) = (
            chart.backend_coord(&(xr.0, yr.1)),
            chart.backend_coord(&(xr.1, yr.0)),
        );
        root.draw(&Rectangle::new([a, b], BLACK.stroke_width(1)))
            .map_err(drawing_error)?;
        draw_legend(
            root,
            ((opts.width - legend_w) as i32 + 10, a.1),
            &legend,
            mono,
        )
    })
}
