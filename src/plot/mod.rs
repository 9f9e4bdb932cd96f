//! SVG figures of families of steady motions (feature `plot`, on by default): bifurcation
//! diagrams, Smale's energy–momentum diagram and stability atlases, drawn with `plotters`; of
//! periodic orbits: the stability diagram and the periods of a family ([`orbit_family_svg`],
//! [`orbit_periods_svg`]), orbits on the sphere of γ ([`orbits_on_sphere_svg`]), Poincaré
//! sections ([`poincare_section_svg`]) and orbit charts over a parameter and the energy
//! ([`orbit_chart_svg`]); and of single motions ([`apex_locus_svg`],
//! [`time_histories_svg`]).
//!
//! Every figure reads without colour:
//!
//! - along a branch, runs of equal verdict are drawn as **thick solid** lines where
//!   [`Stability::SecularlyStable`], **thin solid** where [`Stability::GyroscopicallyStabilized`],
//!   **dashed** where [`Stability::Unstable`] and **dotted** where [`Stability::Degenerate`];
//!   branches of circles of steady motions (`isolated == false`) carry open rings along them;
//! - events are marked by shape: ▲ [`EventKind::Fold`], ● [`EventKind::BranchPoint`],
//!   ■ [`EventKind::HamiltonianHopf`], and the nonlinear events (when
//!   [`ContinuationOptions::nonlinear`](crate::ContinuationOptions::nonlinear) asked for them)
//!   ○ [`EventKind::ArnoldDegenerate`] and ✕ [`EventKind::Resonance`], each with its name beside
//!   it (`D = 0`, `1:2`, `1:3`);
//! - in an atlas, each verdict has its own grey level *and* pattern (plain, dots, diagonal
//!   hatching, cross-hatching), nodes where the steady motion does not exist are white with a
//!   small ×, and the boundary curves are drawn on top, solid, dashed or dotted by kind; the
//!   nonlinear curves ([`StabilityAtlas::nonlinear`](crate::StabilityAtlas::nonlinear)) are thin,
//!   dotted (D = 0), medium-dashed (1:2) or long-dashed (1:3), each labelled with its name.
//!
//! - along a family of periodic orbits, the same strokes by stability: **thick solid** where
//!   [`OrbitStability::Elliptic`], **dashed** where [`OrbitStability::Hyperbolic`], **long
//!   dashes, wider** where [`OrbitStability::InverseHyperbolic`] (so that a run near k = −1
//!   does not merge with the dotted line k = −1 of the Python figures), medium solid where
//!   [`OrbitStability::Parabolic`]; its events are marked ▲ [`OrbitEventKind::Fold`],
//!   ● [`OrbitEventKind::BranchPoint`] and ◆ [`OrbitEventKind::PeriodDoubling`], each named
//!   beside its marker.
//!
//! A legend to the right of the axes names every line style, marker and shading that is drawn
//! (a verdict seen only under an event's marker is neither drawn nor listed). Colour is added on
//! top (switch it off with [`PlotOptions::monochrome`]): the Okabe–Ito colours of the one style
//! of routh's figures, [`crate::style`] (the table [`crate::style::STYLE`], which the Python package's
//! matplotlib figures read too). Curves are drawn smooth at print resolution (a cubic Hermite
//! curve through the samples, in fractional pixels, dashes laid along the whole curve); event
//! names are placed clear of one another, of the markers and where possible of the curves, on
//! leader lines when they must stand away, with their values on request
//! ([`PlotOptions::event_values`]); the regions of an atlas are clipped to its traced boundaries;
//! [`with_circle_verdicts`] draws circles of steady motions with the verdict of
//! [`classify_circle`](crate::classify_circle). Every figure is written whole or not at all:
//! into a temporary file beside `path`, then renamed onto it.
//!
//! ```
//! use routh::plot::{bifurcation_diagram_svg, stability_atlas_svg, DiagramAxis, PlotOptions};
//! use routh::{bifurcation_diagram, stability_atlas, AtlasOptions, ContinuationOptions};
//! use routh::{Lagrangian, Vector3};
//!
//! /// A heavy symmetric (Lagrange) top.
//! #[derive(Lagrangian, Clone)]
//! #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
//! struct Top { inertia: Vector3<f64>, mgl: f64 }
//!
//! let top = Top { inertia: Vector3::new(1.0, 1.0, 1.25), mgl: 1.0 };
//! let coarse = ContinuationOptions { seeds: 2, verify_counts: false, max_step: 0.1, ..Default::default() };
//! // Its steady motions over the cyclic momentum p_ψ, drawn with the tilt up.
//! let diagram = bifurcation_diagram(|p| (top.clone(), p), (0.0, 4.0), &coarse)?;
//! let opts = PlotOptions {
//!     title: "Lagrange top".into(),
//!     x_label: "p_ψ".into(),
//!     y: DiagramAxis::Tilt,
//!     ..PlotOptions::default()
//! };
//! let path = std::env::temp_dir().join("routh-doc-plot-diagram.svg");
//! bifurcation_diagram_svg(&diagram, &path, &opts)?;
//!
//! // The verdict of the sleeping top over the plane (mgl, p_ψ).
//! let atlas = stability_atlas(
//!     |mgl, p| (Top { mgl, ..top.clone() }, p),
//!     Vector3::z(),
//!     (0.5, 1.5),
//!     (0.0, 4.0),
//!     &AtlasOptions { nx: 9, ny: 9, ..Default::default() },
//! )?;
//! let opts = PlotOptions { x_label: "mgl".into(), y_label: "p_ψ".into(), ..PlotOptions::default() };
//! let path = std::env::temp_dir().join("routh-doc-plot-atlas.svg");
//! stability_atlas_svg(&atlas, &path, &opts)?;
//! assert!(std::fs::read_to_string(&path)?.contains("Hamiltonian–Hopf boundary"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fmt;
use std::path::Path;

use crate::{
    BifurcationDiagram, OrbitChart, OrbitFamily, PoincareSection, StabilityAtlas, Trajectory,
    Vector3,
};
#[cfg(doc)]
use crate::{EventKind, OrbitEventKind, OrbitStability, Stability};

// This file holds the public API; the drawing is split by responsibility: `style` (strokes,
// colours and fills by verdict and event, from `crate::style`), `curve` (smoothing and dashing),
// `labels` (placement of event names), `regions` (atlas regions clipped to the boundaries),
// `circles` (`with_circle_verdicts`), `marks` (what is drawn in pixels), `legend`, `frame`
// (ranges, clipping, axes, overlays, the SVG file), `diagram` (branches and events), `atlas`
// (cells and boundaries), `orbits` (families of periodic orbits, the sphere of γ, Poincaré
// sections) and `axis` (`DiagramAxis`).
mod atlas;
mod axis;
mod chart;
mod circles;
mod curve;
mod diagram;
mod frame;
mod labels;
mod legend;
mod marks;
mod orbits;
#[cfg(feature = "png")]
mod png;
mod regions;
mod style;
mod trajectory;

pub use axis::DiagramAxis;
pub use circles::with_circle_verdicts;
#[doc(hidden)]
pub use frame::rendered;
pub use orbits::stability_index_axis;
#[cfg(feature = "png")]
pub use png::png_from_svg;
pub use trajectory::{apex_locus_svg, apex_path, time_histories_svg};

/// The errors of the plotting functions.
///
/// ```
/// use routh::plot::{bifurcation_diagram_svg, stability_atlas_svg, PlotError, PlotOptions};
/// use routh::{bifurcation_diagram, ContinuationOptions, StabilityAtlas};
/// use routh::{Lagrangian, Vector3};
///
/// #[derive(Lagrangian, Clone)]
/// #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
/// struct Top { inertia: Vector3<f64>, mgl: f64 }
///
/// let top = Top { inertia: Vector3::new(1.0, 1.0, 1.25), mgl: 1.0 };
/// let coarse = ContinuationOptions { seeds: 2, verify_counts: false, max_step: 0.1, ..Default::default() };
/// let diagram = bifurcation_diagram(|p| (top.clone(), p), (0.0, 3.0), &coarse)?;
/// let path = std::env::temp_dir().join("routh-doc-plot-error.svg");
///
/// // Too small for axes and legend.
/// let tiny = PlotOptions { width: 300, ..PlotOptions::default() };
/// let err = bifurcation_diagram_svg(&diagram, &path, &tiny).unwrap_err();
/// assert!(matches!(err, PlotError::InvalidOptions(_)), "{err}");
///
/// // Nothing to draw.
/// let err = stability_atlas_svg(&StabilityAtlas::default(), &path, &PlotOptions::default());
/// assert!(matches!(err, Err(PlotError::EmptyData(_))));
///
/// // A file cannot be written below a file.
/// bifurcation_diagram_svg(&diagram, &path, &PlotOptions::default())?;
/// let err = bifurcation_diagram_svg(&diagram, path.join("below.svg"), &PlotOptions::default());
/// assert!(matches!(err, Err(PlotError::Io(_))));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
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

/// Options of the figures.
///
/// ```
/// use routh::plot::{energy_momentum_svg, DiagramAxis, PlotOptions};
/// use routh::{bifurcation_diagram, ContinuationOptions};
/// use routh::{Lagrangian, Vector3};
///
/// #[derive(Lagrangian, Clone)]
/// #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
/// struct Top { inertia: Vector3<f64>, mgl: f64 }
///
/// let top = Top { inertia: Vector3::new(1.0, 1.0, 1.25), mgl: 1.0 };
/// let coarse = ContinuationOptions { seeds: 2, verify_counts: false, max_step: 0.1, ..Default::default() };
/// let diagram = bifurcation_diagram(|p| (top.clone(), p), (0.0, 3.0), &coarse)?;
/// // A small black-and-white figure for print.
/// let opts = PlotOptions {
///     title: "Lagrange top, A₁ = 1, C = 1.25, mgl = 1".into(),
///     y_label: "total energy".into(),
///     width: 600,
///     height: 400,
///     monochrome: true,
///     ..PlotOptions::default()
/// };
/// let path = std::env::temp_dir().join("routh-doc-plot-options.svg");
/// energy_momentum_svg(&diagram, &path, &opts)?;
/// let svg = std::fs::read_to_string(&path)?;
/// assert!(svg.contains("width=\"600\"") && svg.contains("total energy"));
/// assert!(svg.contains("p_ψ")); // the default x_label "s" says p_ψ here
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PlotOptions {
    /// Caption above the axes (default empty: none; a figure for a journal has its caption
    /// below it, in the text).
    pub title: String,
    /// Label of the horizontal axis: the parameter's name (default `"s"`, the parameter of a
    /// bifurcation diagram). The figures whose horizontal axis is something else say what it is
    /// when this is `"s"` or empty: `"p_ψ"` (energy–momentum diagram), `"x"` (atlas: name its
    /// parameters), `"E"` (families of periodic orbits), `"θ"` (Poincaré sections).
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
    /// Write each event's parameter value beside its marker (`branch point at 2.5`), in the
    /// diagrams of branches and of families of periodic orbits (default `false`: names only
    /// where the figure writes them, the legend tells the markers apart).
    pub event_values: bool,
    /// The printed width in inches (default `None`: [`Self::width`] × [`Self::height`] pixels, as
    /// an SVG without units). With `Some(w)` the SVG says its size in inches (`width="3.4in"`),
    /// is laid out at [`PX_PER_PT`](crate::style::PX_PER_PT) pixels a point (`w × 144` pixels
    /// wide, the height in the proportion of [`Self::height`] to [`Self::width`]), and its texts
    /// are printed at their sizes in points: [`COLUMN_WIDTH_IN`](crate::style::COLUMN_WIDTH_IN)
    /// (3.4 in) and [`PAGE_WIDTH_IN`](crate::style::PAGE_WIDTH_IN) (7 in) are a journal's
    /// column and page ([`Self::column`], [`Self::page`]). At least 2.8 in, at most 40 in.
    pub width_in: Option<f64>,
    /// The size of the tick labels in points (default [`FONT`](crate::style::FONT)`.tick_pt`,
    /// 8 pt; 5 to 24); the axis labels, legend and event names keep their proportions to it.
    /// Every text is written at its size: at 2 pixels a point, 8 pt is `font-size="16"`.
    pub font_pt: f64,
}

impl PlotOptions {
    /// The options of a figure one journal column wide (3.4 in), texts at their sizes in points
    /// (ticks 8 pt, nothing under 7 pt).
    ///
    /// ```
    /// use routh::plot::PlotOptions;
    ///
    /// let opts = PlotOptions::column();
    /// assert_eq!(opts.width_in, Some(3.4));
    /// assert_eq!(opts.pixels(), (490, 327));
    /// ```
    pub fn column() -> Self {
        PlotOptions {
            width_in: Some(crate::style::COLUMN_WIDTH_IN),
            ..PlotOptions::default()
        }
    }

    /// The options of a figure a journal page wide (7 in).
    pub fn page() -> Self {
        PlotOptions {
            width_in: Some(crate::style::PAGE_WIDTH_IN),
            ..PlotOptions::default()
        }
    }

    /// The size of the figure in the SVG's pixels before any legend is put below its axes:
    /// [`Self::width`] × [`Self::height`], or, with [`Self::width_in`], 144 pixels an inch and
    /// the height in proportion.
    pub fn pixels(&self) -> (u32, u32) {
        match self.width_in {
            Some(w) if w.is_finite() && w > 0.0 && self.width > 0 => {
                let px = (w * 72.0 * crate::style::PX_PER_PT).round();
                let h = (px * f64::from(self.height) / f64::from(self.width)).round();
                (px as u32, h as u32)
            }
            _ => (self.width, self.height),
        }
    }
}

/// A named reference curve of [`PlotOptions::overlays`], drawn in black over the data (long
/// dashes, short dashes, a thin line, in turn).
///
/// ```
/// use routh::plot::{bifurcation_diagram_svg, Overlay, PlotOptions};
/// use routh::{bifurcation_diagram, ContinuationOptions};
/// use routh::{Lagrangian, Vector3};
///
/// #[derive(Lagrangian, Clone)]
/// #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
/// struct Top { inertia: Vector3<f64>, mgl: f64 }
///
/// let (a1, c, mgl) = (1.0, 1.25, 1.0);
/// let top = Top { inertia: Vector3::new(a1, a1, c), mgl };
/// let coarse = ContinuationOptions { seeds: 2, verify_counts: false, max_step: 0.1, ..Default::default() };
/// let diagram = bifurcation_diagram(|p| (top.clone(), p), (0.0, 4.0), &coarse)?;
/// // The tilted precessions in closed form, p_ψ² = mgl (A₁ + (C − A₁)γ₃²)² / ((C − A₁)γ₃),
/// // over the circles of steady motions that the continuation found.
/// let tilted = Overlay {
///     label: "tilted precessions, closed form".into(),
///     points: (30..=100)
///         .map(|k| {
///             let z = k as f64 / 100.0;
///             let p = (mgl * (a1 + (c - a1) * z * z).powi(2) / ((c - a1) * z)).sqrt();
///             (p, z)
///         })
///         .collect(),
/// };
/// let opts = PlotOptions { x_label: "p_ψ".into(), overlays: vec![tilted], ..PlotOptions::default() };
/// let path = std::env::temp_dir().join("routh-doc-plot-overlay.svg");
/// bifurcation_diagram_svg(&diagram, &path, &opts)?;
/// assert!(std::fs::read_to_string(&path)?.contains("tilted precessions, closed form"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
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
            event_values: false,
            width_in: None,
            font_pt: crate::style::FONT.tick_pt,
        }
    }
}

impl PlotOptions {
    fn check(&self) -> Result<(), PlotError> {
        if !(self.font_pt.is_finite() && (5.0..=24.0).contains(&self.font_pt)) {
            return Err(PlotError::InvalidOptions(format!(
                "a font of {} pt (5 to 24)",
                self.font_pt
            )));
        }
        if let Some(w) = self.width_in {
            let min = 400.0 / (72.0 * crate::style::PX_PER_PT);
            if !(w.is_finite() && (min..=40.0).contains(&w)) {
                return Err(PlotError::InvalidOptions(format!(
                    "a figure {w} in wide (at least {min:.1} in, at most 40 in)"
                )));
            }
        }
        let (w, h) = self.pixels();
        if w < 400 || h < 250 {
            return Err(PlotError::InvalidOptions(format!(
                "a figure of {w} × {h} pixels is too small (at least 400 × 250)"
            )));
        }
        Ok(())
    }
}

/// `label`, or `default` when it is empty.
fn label_or<'a>(label: &'a str, default: &'a str) -> &'a str {
    if label.is_empty() {
        default
    } else {
        label
    }
}

/// `label`, or `default` when it is empty or the default `"s"` of [`PlotOptions::x_label`].
fn x_label_or<'a>(label: &'a str, default: &'a str) -> &'a str {
    if label == "s" {
        default
    } else {
        label_or(label, default)
    }
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
///     BifurcationDiagram, Branch, BranchSample, Complex, Stability, StabilityReport,
///     SteadyMotion, Vector3,
/// };
///
/// // The sleeping top: stable for p_ψ > 2, unstable below.
/// let point = |p: f64| BranchSample {
///     s: p,
///     steady: SteadyMotion {
///         // C = 1: ψ̇ = p/C (38), U_r = ½p²/C + mgl with mgl = 1.
///         p_psi: p, gamma: Vector3::z(), psi_dot: p, mu: 0.0,
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
///     ..Default::default()
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
    diagram::branch_figure(
        diagram,
        path.as_ref(),
        opts,
        |p| (p.s, axis.value(&p.steady)),
        |e| (Some(e.s), axis.of_gamma(&e.gamma)),
        &opts.x_label,
        label_or(&opts.y_label, axis.label()),
        diagram::EventNames::Legend,
    )
}

/// Writes Smale's energy–momentum diagram as an SVG: the energy `E` of each steady motion of the
/// diagram up, against its cyclic momentum `p_ψ` across.
///
/// For a diagram over `p_ψ` this is the diagram's own curves seen in the `(p_ψ, E)` plane; for a
/// diagram over a parameter of the body at fixed `p_ψ`, the branches stand on one vertical line.
/// Line styles, markers and legend are those of [`bifurcation_diagram_svg`] (events are placed
/// by interpolation along their branch), and each event's name is written beside its marker.
/// The curves are the branches' polylines: smooth when the diagram was computed with
/// [`ContinuationOptions::em_turn_degrees`](crate::ContinuationOptions::em_turn_degrees) on (the
/// default: the curve `(s, E)` turns by at most 3° between successive chords, but at its cusps).
/// The horizontal axis is labelled [`PlotOptions::x_label`], or `"p_ψ"` when that is the default
/// `"s"` or empty.
///
/// # Errors
///
/// As [`bifurcation_diagram_svg`].
///
/// ```
/// use routh::plot::{energy_momentum_svg, PlotOptions};
/// use routh::{
///     BifurcationDiagram, Branch, BranchSample, Complex, Stability, StabilityReport,
///     SteadyMotion, Vector3,
/// };
///
/// let point = |p: f64| BranchSample {
///     s: p,
///     steady: SteadyMotion {
///         // C = 1: ψ̇ = p/C (38), U_r = ½p²/C + mgl with mgl = 1.
///         p_psi: p, gamma: Vector3::z(), psi_dot: p, mu: 0.0,
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
///     ..Default::default()
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
    let x_label = x_label_or(&opts.x_label, "p_ψ");
    diagram::branch_figure(
        diagram,
        path.as_ref(),
        opts,
        |p| (p.steady.p_psi, p.steady.energy),
        |_| (None, None),
        x_label,
        label_or(&opts.y_label, DiagramAxis::Energy.label()),
        diagram::EventNames::Beside,
    )
}

/// Writes the stability atlas as an SVG: the parameter plane shaded by verdict and the boundary
/// curves on top. The regions are clipped to the traced boundaries: each pixel takes the verdict
/// of the nearest grid node it reaches without crossing a boundary curve, so that the shading
/// meets the curves instead of stepping across them cell by cell.
///
/// Each verdict has a tint (a grey level in monochrome) and a light pattern: secularly stable
/// plain, gyroscopically stabilised dotted, unstable hatched `/`, degenerate cross-hatched; where
/// the steady motion does not exist (`None`) the cell is white with a small ×. Boundary curves are solid (fold), dashed
/// (branch point) or dotted (Hamiltonian–Hopf), on a white underlay. The legend names each shading
/// and curve that occurs. The axes are labelled [`PlotOptions::x_label`] (`"x"` when it is the
/// default `"s"` or empty) and [`PlotOptions::y_label`] (`"y"` when empty); [`PlotOptions::y`] is
/// not used.
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
/// let atlas = StabilityAtlas { x, y, verdicts, boundaries, ..Default::default() };
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
    atlas::atlas_figure(atlas, path.as_ref(), opts)
}

/// Writes the stability diagram of a family of periodic orbits as an SVG: the stability index
/// `k = (μ + 1/μ)/2` up against the energy `E` across, the lines `k = ±1` between which the
/// orbits are elliptic (linearly stable), the runs of the family styled by
/// [`PeriodicOrbit::stability`](crate::PeriodicOrbit::stability) (thick solid elliptic, dashed
/// hyperbolic, long-dashed inverse hyperbolic; the style changes where `k` crosses ±1, interpolated
/// between orbits), and its events ([`OrbitFamily::events`]) marked ▲ fold, ● branch point,
/// ◆ period doubling, each named beside its marker.
///
/// **The vertical axis.** Near a separatrix `k` grows like `e^{cT}` and spans many orders of
/// magnitude, so the axis is linear in `k` on `[−1, 1]` and logarithmic beyond, one unit a
/// decade ([`stability_index_axis`]: `y = ±(1 + log₁₀|k|)`), its ticks labelled in `k` (`10`,
/// `100`, `10³`, …). Nothing is clipped, and the elliptic band keeps its room.
///
/// The axes are labelled [`PlotOptions::x_label`] (`"E"` when it is the default `"s"` or empty)
/// and [`PlotOptions::y_label`] (`"k"` when empty); [`PlotOptions::overlays`] are drawn in the
/// figure's coordinates (the index through [`stability_index_axis`]).
///
/// # Errors
///
/// [`PlotError::EmptyData`] for a family without an orbit with finite `E`, `T` and `k`,
/// [`PlotError::InvalidOptions`] for a figure smaller than 400 × 250 pixels, [`PlotError::Io`]
/// if the file cannot be written.
///
/// ```
/// use routh::plot::{orbit_family_svg, orbit_periods_svg, PlotOptions};
/// use routh::{
///     OrbitEvent, OrbitEventKind, OrbitFamily, OrbitStability, PeriodicOrbit, Vector3,
/// };
///
/// // A family by hand: k falls through −1 at E = 0.5 and rises through 1 at E = 1.5.
/// let orbit = |e: f64| {
///     let k = if e < 1.0 { 0.9 - 3.8 * e } else { 10f64.powf(2.7 * (e - 1.5)) };
///     PeriodicOrbit {
///         omega0: Vector3::zeros(),
///         gamma0: -Vector3::z(),
///         period: 6.0 + e,
///         energy: e,
///         p_psi: 0.0,
///         precession: 0.0,
///         body_turn: 0.0,
///         multipliers: PeriodicOrbit::multipliers_from_index(k),
///         stability_index: k,
///         stability: OrbitStability::from_index(k, 1e-9),
///         degenerate: false,
///         amplitude: e,
///     }
/// };
/// let event = |kind, e: f64, before, after| OrbitEvent {
///     kind, energy: e, orbit: orbit(e), before, after,
/// };
/// let family = OrbitFamily {
///     orbits: (0..=50).map(|i| orbit(0.05 * i as f64)).collect(),
///     events: vec![
///         event(OrbitEventKind::PeriodDoubling, 0.5, OrbitStability::Elliptic, OrbitStability::InverseHyperbolic),
///         event(OrbitEventKind::BranchPoint, 1.5, OrbitStability::Elliptic, OrbitStability::Hyperbolic),
///     ],
///     stop: None,
/// };
/// let path = std::env::temp_dir().join("routh-doc-orbit-family.svg");
/// orbit_family_svg(&family, &path, &PlotOptions::default())?;
/// let svg = std::fs::read_to_string(&path)?;
/// assert!(svg.contains("period doubling") && svg.contains("k = ±1 (log scale beyond)"));
///
/// let path = std::env::temp_dir().join("routh-doc-orbit-periods.svg");
/// orbit_periods_svg(&family, &path, &PlotOptions::default())?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn orbit_family_svg<P: AsRef<Path>>(
    family: &OrbitFamily,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    orbits::family_figure(family, path.as_ref(), opts, orbits::FamilyAxis::Index)
}

/// Writes the periods of a family of periodic orbits as an SVG: the period `T` up against the
/// energy `E` across, with the strokes, markers and names of [`orbit_family_svg`] (the runs
/// styled by stability, the events marked and named). The axes are labelled
/// [`PlotOptions::x_label`] (`"E"` when it is the default `"s"` or empty) and
/// [`PlotOptions::y_label`] (`"T"` when empty); [`PlotOptions::overlays`] (e.g. a period in
/// closed form) are drawn on top.
///
/// # Errors
///
/// As [`orbit_family_svg`]. An example is there.
pub fn orbit_periods_svg<P: AsRef<Path>>(
    family: &OrbitFamily,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    orbits::family_figure(family, path.as_ref(), opts, orbits::FamilyAxis::Period)
}

/// Writes orbits drawn on the sphere of γ (the body coordinates of the upward vertical) as an
/// SVG: an orthographic projection of the unit sphere seen from the body direction `view` (the
/// viewer on the ray through `view`; up on the page is `e₃`, or `e₂` when `view` is within about
/// 25° of `±e₃`). Each trajectory's `γ` is a curve, solid on the near side (`γ·view ≥ 0`) and thin
/// dotted on the far side; the trajectories are coloured in their order from blue to orange
/// (from black to grey with [`PlotOptions::monochrome`]). The limb, the principal planes
/// `γᵢ = 0` (grey) and the body axes `±eᵢ` on the near side (dots, named) give the orientation;
/// the legend names the first and last trajectory and the view. Sample periodic orbits with
/// [`orbit_path`](crate::orbit_path).
///
/// # Errors
///
/// [`PlotError::EmptyData`] when no trajectory has a point, [`PlotError::InvalidData`] for a
/// zero or non-finite `view` or a non-finite `γ`, [`PlotError::InvalidOptions`] for a figure
/// smaller than 400 × 250 pixels, [`PlotError::Io`] if the file cannot be written.
///
/// ```
/// use routh::plot::{orbits_on_sphere_svg, PlotOptions};
/// use routh::{Trajectory, Vector3};
///
/// // Two swings about e₁ near the hanging position γ = −e₃, drawn as simulate_full would.
/// let swing = |a: f64| Trajectory {
///     gamma: (0..=100)
///         .map(|i| {
///             let th = a * (i as f64 / 100.0 * std::f64::consts::TAU).sin();
///             Vector3::new(0.0, th.sin(), -th.cos())
///         })
///         .collect(),
///     ..Trajectory::default()
/// };
/// let path = std::env::temp_dir().join("routh-doc-orbits-sphere.svg");
/// let opts = PlotOptions { width: 700, height: 500, ..PlotOptions::default() };
/// orbits_on_sphere_svg(&[swing(0.3), swing(0.9)], Vector3::new(1.0, 0.0, -1.0), &path, &opts)?;
/// assert!(std::fs::read_to_string(&path)?.contains("last orbit (2 in all)"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn orbits_on_sphere_svg<P: AsRef<Path>>(
    orbits: &[Trajectory],
    view: Vector3<f64>,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    orbits::sphere_figure(orbits, view, path.as_ref(), opts)
}

/// Writes a Poincaré section as an SVG: every crossing `(θ, M_n)` of every orbit of the section
/// as a small dot, one colour per orbit (in turn; all black with [`PlotOptions::monochrome`]),
/// and `fixed_points` — the crossings of periodic orbits, from
/// [`orbit_crossings`](crate::orbit_crossings) with the section's options — as large marks (a
/// ring with a dot, on a white halo). Islands of regular motion show as closed curves around
/// elliptic fixed points, chaos as scattered dots. The angle `θ ∈ (−π, π]` is drawn on the window
/// of width 2π that keeps the crossings together: where they leave a wider gap elsewhere than
/// across ±π, the angles below the gap are drawn at `θ + 2π` (a region of motion straddling
/// θ = ±π shows in one piece, its ticks beyond π). The axes are labelled [`PlotOptions::x_label`]
/// (`"θ"` when it is the default `"s"` or empty) and [`PlotOptions::y_label`] (`"M_n"` when
/// empty); the legend gives the number of crossings and orbits, `(p_ψ, E)` and the plane.
///
/// # Errors
///
/// [`PlotError::EmptyData`] for a section without a finite crossing, [`PlotError::InvalidData`]
/// for a non-finite fixed point, [`PlotError::InvalidOptions`] for a figure smaller than
/// 400 × 250 pixels, [`PlotError::Io`] if the file cannot be written.
///
/// ```
/// use routh::plot::{poincare_section_svg, PlotOptions};
/// use routh::periodic::SectionOrbit;
/// use routh::{PoincareSection, Vector3};
///
/// // Rings around a fixed point at (0, 0), as a harmonic oscillator's section.
/// let ring = |r: f64| SectionOrbit {
///     omega0: Vector3::zeros(),
///     gamma0: Vector3::y(),
///     points: (0..200).map(|i| {
///         let a = 0.7 * i as f64;
///         [r * a.cos(), r * a.sin()]
///     }).collect(),
///     stop: None,
/// };
/// let section = PoincareSection {
///     p_psi: 0.0,
///     energy: 1.0,
///     normal: Vector3::x(),
///     orbits: vec![ring(0.5), ring(1.0), ring(1.5)],
/// };
/// let path = std::env::temp_dir().join("routh-doc-section.svg");
/// poincare_section_svg(&section, &[[0.0, 0.0]], &path, &PlotOptions::default())?;
/// assert!(std::fs::read_to_string(&path)?.contains("600 crossings of 3 orbits"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn poincare_section_svg<P: AsRef<Path>>(
    section: &PoincareSection,
    fixed_points: &[[f64; 2]],
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    orbits::section_figure(section, fixed_points, path.as_ref(), opts)
}

/// Writes an orbit chart ([`orbit_chart`](crate::orbit_chart)) as an SVG: the parameter `x`
/// across, the energy `h = E − Eₛ` above the steady motion up; the regions of the families'
/// orbits filled by linear stability (a light tint of the verdict's colour, or a grey level with
/// [`PlotOptions::monochrome`], lighter the more stable: elliptic, parabolic, hyperbolic, inverse
/// hyperbolic), each family a strip half-way to its neighbours, cut where `k` crosses `±1`; on
/// top, on a white halo, the chart's curves in the look of their kind (the table
/// [`crate::style::STYLE`]'s `orbit_curve`, as the Python figure): solid folds, dashed
/// `k = 1`, dotted `k = −1`, blue dashes for the resonances of order three and four, the twist's
/// zero; a curve met at one `x` only is its event's marker. The legend names what is drawn.
///
/// The axes are labelled [`PlotOptions::x_label`] (`"x"` when it is the default `"s"` or empty)
/// and [`PlotOptions::y_label`] (`"h = E − Eₛ"` when empty).
///
/// # Errors
///
/// [`PlotError::EmptyData`] for a chart with neither a family nor a curve,
/// [`PlotError::InvalidOptions`] for a figure smaller than 400 × 250 pixels, [`PlotError::Io`]
/// if the file cannot be written.
///
/// ```
/// use routh::plot::{orbit_chart_svg, PlotOptions};
/// use routh::{OrbitChart, OrbitChartCurve, OrbitEventKind, OrbitFamily, OrbitStability};
/// use routh::{PeriodicOrbit, Vector3};
///
/// // Families at x = 0, 0.5, 1 whose orbits turn hyperbolic (k = 1) at h = 1 + x.
/// let orbit = |x: f64, h: f64| {
///     let k = 0.5 + 0.5 * h / (1.0 + x);
///     PeriodicOrbit {
///         omega0: Vector3::zeros(), gamma0: -Vector3::z(), period: 6.0, energy: h - 1.0,
///         p_psi: 0.0, precession: 0.0, body_turn: 0.0,
///         multipliers: PeriodicOrbit::multipliers_from_index(k), stability_index: k,
///         stability: OrbitStability::from_index(k, 1e-9), degenerate: false, amplitude: h,
///     }
/// };
/// let x = vec![0.0, 0.5, 1.0];
/// let families = x
///     .iter()
///     .map(|&x| Some(OrbitFamily {
///         orbits: (0..=30).map(|i| orbit(x, 0.1 * i as f64)).collect(),
///         events: vec![],
///         stop: None,
///     }))
///     .collect();
/// let chart = OrbitChart {
///     steady_energy: vec![-1.0; 3],
///     failures: vec![None; 3],
///     curves: vec![OrbitChartCurve {
///         kind: OrbitEventKind::BranchPoint,
///         points: x.iter().map(|&x| [x, 1.0 + x]).collect(),
///     }],
///     families,
///     x,
///     stop: None,
/// };
/// let path = std::env::temp_dir().join("routh-doc-orbit-chart.svg");
/// orbit_chart_svg(&chart, &path, &PlotOptions::column())?;
/// let svg = std::fs::read_to_string(&path)?;
/// assert!(svg.contains("k = 1 (branch point)") && svg.contains("hyperbolic"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn orbit_chart_svg<P: AsRef<Path>>(
    chart: &OrbitChart,
    path: P,
    opts: &PlotOptions,
) -> Result<(), PlotError> {
    chart::chart_figure(chart, path.as_ref(), opts)
}
