//! Families of steady motions: how steady motions move, appear, split and change stability as
//! the cyclic momentum `p_ψ` or a parameter of the body changes.
//!
//! A one-parameter family is a closure `s ↦ (model, p_ψ)`: `|p| (top.clone(), p)` follows the
//! cyclic momentum, `|mgl| (Top { mgl, ..top }, 3.0)` a field of the body at fixed `p_ψ`. A
//! two-parameter family is `(x, y) ↦ (model, p_ψ)`. Derivatives in the parameters are taken
//! numerically; derivatives in γ come from the model (the generated code).
//!
//! - [`bifurcation_diagram`]: every branch of steady motions over a range of `s`, followed by
//!   pseudo-arclength continuation through folds, with the events on them ([`EventKind`]).
//! - [`continue_branch`]: the same, restricted to the branch through one steady motion.
//! - [`stability_atlas`]: the verdict of one steady motion over a grid of two parameters, with
//!   the boundary curves of its stability region traced by continuation.
//!
//! Families of periodic orbits, through the energy or a parameter, are in [`crate::periodic`]
//! (`continue_orbit`, `continue_orbit_in`): both kinds of family are followed by the crate's one
//! predictor–corrector and locate their events with its one event locator (docs/architecture.md,
//! "Engines").
//!
//! # Events
//!
//! Along a branch the restricted second variation `K` (62)–(63) and the roots of `f₂` (errata E5)
//! change continuously. The verdict can change only where
//! - an eigenvalue of `K` passes through zero (`det K = 0`): a [`EventKind::Fold`] (the branch
//!   turns back in `s`) or a [`EventKind::BranchPoint`] (other branches meet it: a
//!   symmetry-breaking pitchfork, or the birth of a circle of tilted steady motions of a symmetric
//!   body);
//! - with degree of instability 2, two pairs of roots of `f₂` collide on the imaginary axis and
//!   leave it (or come back), which is a zero of the discriminant of `f₂` in `λ²`: a
//!   [`EventKind::HamiltonianHopf`] (Krein collision). Two pairs of equal Krein signature pass
//!   each other without leaving the axis; that is no event.

mod atlas;
mod continuation;
mod diagram;
mod equations;
mod nonlinear;

use std::fmt;

use nalgebra::Vector3;

use crate::nonlinear::NonlinearOptions;
use crate::stability::{ClassifyOptions, Stability, StabilityReport};
use crate::steady::{SearchOptions, SteadyMotion};

pub use atlas::{stability_atlas, stability_atlas_parallel};
pub use diagram::{bifurcation_diagram, continue_branch, CountCheck};
pub use nonlinear::{nonlinear_events, NonlinearCurve, NonlinearEvent, NonlinearEventVerdicts};

/// Options of [`bifurcation_diagram`] and [`continue_branch`].
///
/// Steps are measured in the pseudo-arclength of the curve `(s, γ)`, with `s` scaled by the
/// length of the range (so a step of `0.01` is about 1 % of the range where the branch is flat).
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// // Smaller steps and no count checks, the rest by default.
/// let opts = ContinuationOptions { max_step: 0.02, verify_counts: false, ..Default::default() };
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let d = bifurcation_diagram(|p| (top.clone(), p), (1.5, 3.0), &opts)?;
/// assert_eq!(d.events.len(), 2);
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ContinuationOptions {
    /// First step, relative to the length of the range (default `0.01`).
    pub initial_step: f64,
    /// Largest step, relative to the length of the range (default `0.05`).
    pub max_step: f64,
    /// Smallest step, relative to the length of the range (default `1e−7`): where the corrector
    /// fails for every step down to it, the branch cannot be continued and the diagram is an
    /// error ([`RouthError::AtParameter`](crate::RouthError::AtParameter) at the last `s`
    /// reached, wrapping [`RouthError::NoConvergence`](crate::RouthError::NoConvergence)).
    pub min_step: f64,
    /// Budget of continuation steps per branch, both directions together (default `20_000`); a
    /// branch that needs more ends where the budget ran out, and the diagram comes back with
    /// [`BifurcationDiagram::stop`] = [`StopReason::MaxSteps`] (the `s` and γ where it ran out).
    pub max_steps: usize,
    /// Budget of branches (default `64`); when it is spent the diagram comes back with the
    /// branches so far and [`BifurcationDiagram::stop`] = [`StopReason::MaxBranches`] (the `s`
    /// and γ of the first branch over the budget).
    pub max_branches: usize,
    /// Relative tolerance of the Newton corrector on the Riemannian gradient (default `1e−12`).
    pub newton_tol: f64,
    /// Events are located to `|Δs| ≤ event_tol · max(1, |s|)` (default `1e−10`, inside the
    /// `1e−9` of the contract).
    pub event_tol: f64,
    /// Number of parameter values, evenly spread over the range ends included, at which
    /// [`bifurcation_diagram`] seeds branches with a global search (default `5`). A seed value
    /// that falls on an event is moved off it (by `1.3e−3`, then `7.1e−3` of the range).
    pub seeds: usize,
    /// Whether [`bifurcation_diagram`] checks, between consecutive events, that the number of
    /// steady motions equals what [`steady_motions`](crate::steady_motions) finds there, and seeds
    /// the missing branches if not (default `true`).
    pub verify_counts: bool,
    /// Largest turning angle, in degrees, between successive chords of each branch's energy
    /// curve `(s, E)` in plot-normalised coordinates (`s` over the range, `E` over its extent on
    /// the diagram) (default `3`; `0` turns it off). After continuation, points corrected onto
    /// the branch are inserted where the curve turns faster, down to chords of `2e−4`, so that
    /// the energy–momentum curves are drawn smooth whatever the continuation step; the turning
    /// points of the curve in `s` (its cusps at folds and pitchfork tips) are left as they are.
    /// Not done on a diagram that stopped early ([`BifurcationDiagram::stop`]).
    #[cfg_attr(feature = "serde", serde(default = "default_em_turn_degrees"))]
    pub em_turn_degrees: f64,
    /// Options of the global searches.
    pub search: SearchOptions,
    /// Tolerances of the verdicts at each point.
    pub classify: ClassifyOptions,
    /// When `Some`, the diagram also locates, on the gyroscopically stabilised stretches of its
    /// isolated branches, the zeros of Arnold's determinant ([`EventKind::ArnoldDegenerate`]) and
    /// the 1:2 and 1:3 resonances ([`EventKind::Resonance`]) with the nonlinear test
    /// ([`nonlinear_stability`](crate::nonlinear_stability)) and these options, each to
    /// `|Δs| ≤ event_tol·max(1, |s|)`, with the nonlinear verdicts around it in
    /// [`BranchEvent::nonlinear`] (docs/method.md §10.7). The branches are the same as without
    /// it, and the count checks ignore these events. Needs a model with a Routh-function tape
    /// (derived or run-time; for a hand-written one use
    /// [`nonlinear_events`]). Default `None`: no nonlinear
    /// test, the diagram of the linear verdicts alone.
    ///
    /// ```
    /// # use routh_core::*;
    /// let opts = ContinuationOptions {
    ///     nonlinear: Some(NonlinearOptions::default()),
    ///     ..Default::default()
    /// };
    /// assert_eq!(ContinuationOptions::default().nonlinear, None);
    /// # let _ = opts;
    /// ```
    #[cfg_attr(feature = "serde", serde(default))]
    pub nonlinear: Option<NonlinearOptions>,
    /// Cancellation and progress (seeds done of [`ContinuationOptions::seeds`]): a cancelled
    /// diagram ends with [`StopReason::Interrupted`] and the branches it has. Not a setting: not
    /// serialised, not compared.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub control: crate::RunControl,
}

/// The default of [`ContinuationOptions::em_turn_degrees`] (also for options serialised before
/// it existed).
#[cfg(feature = "serde")]
fn default_em_turn_degrees() -> f64 {
    ContinuationOptions::default().em_turn_degrees
}

impl Default for ContinuationOptions {
    fn default() -> Self {
        ContinuationOptions {
            initial_step: 0.01,
            max_step: 0.05,
            min_step: 1e-7,
            max_steps: 20_000,
            max_branches: 64,
            newton_tol: 1e-12,
            event_tol: 1e-10,
            seeds: 5,
            verify_counts: true,
            em_turn_degrees: 3.0,
            search: SearchOptions::default(),
            classify: ClassifyOptions::default(),
            nonlinear: None,
            control: crate::RunControl::default(),
        }
    }
}

/// Every branch of steady motions over a range of the parameter, with its events.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// // The hanging top, the sleeping top and the circles of tilted precessions.
/// assert_eq!(d.branches.len(), 3);
/// for e in &d.events {
///     let branch: &Branch = &d.branches[e.branch];
///     assert!(branch.points.first().unwrap().s <= e.s);
/// }
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BifurcationDiagram {
    /// The branches; [`BranchEvent::branch`] indexes this list.
    pub branches: Vec<Branch>,
    /// The events, sorted by `s`.
    pub events: Vec<BranchEvent>,
    /// `None` when the diagram is complete; otherwise why it stopped early (a budget of
    /// [`ContinuationOptions`] ran out): the branches and events are those computed so far.
    pub stop: Option<StopReason>,
    /// The diagram's self-check: between consecutive events, the number of steady motions on the
    /// branches against a global search ([`CountCheck`]; empty when
    /// [`ContinuationOptions::verify_counts`] is off). See [`BifurcationDiagram::consistent`].
    #[cfg_attr(feature = "serde", serde(default))]
    pub checks: Vec<CountCheck>,
}

impl BifurcationDiagram {
    /// Whether every count check agreed (`true` when none was made).
    ///
    /// ```
    /// # use routh_core::*;
    /// # use test_models::Gyrostat;
    /// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
    /// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
    /// assert!(d.consistent());
    /// assert_eq!(d.checks.len(), d.events.len() + 1);
    /// # Ok::<(), routh_core::RouthError>(())
    /// ```
    pub fn consistent(&self) -> bool {
        self.checks.iter().all(|c| c.on_branches == c.searched)
    }

    /// The number of steady motions at `s` according to the branches: the number of segments of
    /// the branches' polylines that cross `s` (a circle of steady motions counts once, as it is
    /// one point of its branch).
    ///
    /// Branches contain their events (folds, branch points, the tips of pitchforks) as points,
    /// so the count is right at any `s` inside the range farther than about `1e−6·max(1, |s|)`
    /// from an event; exactly at an event or at a point of a branch it is not meaningful.
    ///
    /// ```
    /// # use routh_core::*;
    /// # use test_models::Gyrostat;
    /// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
    /// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
    /// // Below the fold of the circles: the hanging and the sleeping top; above the secular
    /// // bound p = 2.5: those two and one circle of tilted precessions.
    /// assert_eq!(d.count_at(1.0), 2);
    /// assert_eq!(d.count_at(4.0), 3);
    /// # Ok::<(), routh_core::RouthError>(())
    /// ```
    pub fn count_at(&self, s: f64) -> usize {
        self.branches
            .iter()
            .map(|b| {
                b.points
                    .windows(2)
                    .filter(|w| (w[0].s < s) != (w[1].s < s))
                    .count()
            })
            .sum()
    }
}

/// Why a family computation stopped before it was complete: a budget ran out. The result it
/// comes with holds everything computed so far. (Errors, [`RouthError`](crate::RouthError), are
/// kept for bad input: invalid options, a family that is not smooth or not finite.)
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let opts = ContinuationOptions { max_branches: 2, ..Default::default() };
/// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &opts)?;
/// assert_eq!(d.branches.len(), 2);
/// assert!(matches!(d.stop, Some(StopReason::MaxBranches { .. })));
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum StopReason {
    /// [`ContinuationOptions::max_steps`] ran out on a branch at `(s, gamma)`; that branch ends
    /// there, the others are complete.
    MaxSteps {
        /// The parameter where the branch ends.
        s: f64,
        /// The steady motion where it ends.
        gamma: Vector3<f64>,
    },
    /// [`ContinuationOptions::max_branches`] was spent; a further branch would start at
    /// `(s, gamma)`, and it and any later branch are missing.
    MaxBranches {
        /// The parameter of the first missing branch.
        s: f64,
        /// A steady motion of it.
        gamma: Vector3<f64>,
    },
    /// [`AtlasOptions::max_curve_points`] ran out on a boundary curve at `(x, y)`; that curve
    /// ends there.
    MaxCurvePoints {
        /// The first parameter where the curve ends.
        x: f64,
        /// The second parameter where the curve ends.
        y: f64,
        /// The steady motion there.
        gamma: Vector3<f64>,
    },
    /// The caller stopped the diagram ([`ContinuationOptions::control`]'s cancel flag: Ctrl-C);
    /// the branches traced before are kept, the branch being traced ends where it was.
    Interrupted,
}

impl fmt::Display for StopReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StopReason::MaxSteps { s, gamma } => write!(
                f,
                "the budget max_steps ran out on a branch at s = {s}, γ = ({:+.9}, {:+.9}, {:+.9})",
                gamma.x, gamma.y, gamma.z
            ),
            StopReason::MaxBranches { s, gamma } => write!(
                f,
                "the budget max_branches was spent; a further branch starts at s = {s}, \
                 γ = ({:+.9}, {:+.9}, {:+.9})",
                gamma.x, gamma.y, gamma.z
            ),
            StopReason::MaxCurvePoints { x, y, gamma } => write!(
                f,
                "the budget max_curve_points ran out on a boundary curve at (x, y) = ({x}, {y}), \
                 γ = ({:+.9}, {:+.9}, {:+.9})",
                gamma.x, gamma.y, gamma.z
            ),
            StopReason::Interrupted => f.write_str("interrupted by the caller"),
        }
    }
}

/// One branch: a curve of steady motions `s ↦ γ(s)`, possibly turning back in `s` at folds.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// let circles = d.branches.iter().find(|b| !b.isolated).unwrap();
/// // Every point of a branch of circles is degenerate (errata E8).
/// assert!(circles.points.iter().all(|q| q.report.verdict == Stability::Degenerate));
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Branch {
    /// The points, in arclength order along the branch.
    pub points: Vec<BranchSample>,
    /// `false` for a branch of circles of steady motions (a symmetric body's tilted precessions):
    /// each point is one representative of its circle.
    pub isolated: bool,
}

/// One sample of a branch: the steady motion at one value of the parameter, with its stability.
/// (Formerly `BranchPoint`, a name that clashed with the event [`EventKind::BranchPoint`]; the
/// old name remains as a deprecated alias.)
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// let q: &BranchSample = &d.branches[0].points[0];
/// assert_eq!(q.steady.p_psi, q.s); // the family follows p_ψ itself
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BranchSample {
    /// The parameter.
    pub s: f64,
    /// The steady motion (its `p_psi` is the family's at `s`).
    pub steady: SteadyMotion,
    /// Its stability.
    pub report: StabilityReport,
}

/// The former name of [`BranchSample`].
#[deprecated(note = "renamed `BranchSample` (`EventKind::BranchPoint` is the bifurcation)")]
pub type BranchPoint = BranchSample;

/// An event on a branch, located by solving its defining equation.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// let hh = d.events.iter().find(|e| e.kind == EventKind::HamiltonianHopf).unwrap();
/// assert_eq!((hh.before, hh.after), (Stability::Unstable, Stability::GyroscopicallyStabilized));
/// println!("{hh}");
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BranchEvent {
    /// What happens.
    pub kind: EventKind,
    /// Where, in the parameter.
    pub s: f64,
    /// The steady motion at the event (for a branch point, the meeting point of the branches).
    pub gamma: Vector3<f64>,
    /// The index of the branch in [`BifurcationDiagram::branches`] (for a branch point, the one
    /// that passes through it).
    pub branch: usize,
    /// The verdict on the branch just before the event (in `s`, or for a fold along the branch's
    /// point order).
    pub before: Stability,
    /// The verdict just after.
    pub after: Stability,
    /// For the nonlinear events ([`EventKind::ArnoldDegenerate`], [`EventKind::Resonance`],
    /// added when [`ContinuationOptions::nonlinear`] asks), the nonlinear verdicts around the
    /// event and which resonance; `None` for the others.
    #[cfg_attr(feature = "serde", serde(default))]
    pub nonlinear: Option<NonlinearEventVerdicts>,
}

/// The kinds of [`BranchEvent`] and [`BoundaryCurve`].
///
/// ```
/// use routh_core::EventKind;
/// assert_eq!(EventKind::HamiltonianHopf.to_string(), "Hamiltonian–Hopf");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum EventKind {
    /// A zero eigenvalue of the restricted second variation where the branch turns back in the
    /// parameter: two steady motions meet and vanish.
    Fold,
    /// A zero eigenvalue of the restricted second variation where other branches meet this one
    /// (a pitchfork, or the birth of a circle of steady motions).
    BranchPoint,
    /// A zero of the discriminant of `f₂` in `λ²` with degree of instability 2: two pairs of
    /// roots of `f₂` collide on the imaginary axis and leave it (gyroscopic stabilisation is lost
    /// or gained).
    HamiltonianHopf,
    /// A zero of Arnold's determinant `D` on a gyroscopically stabilised stretch: the
    /// Arnold–Moser test is inconclusive there (docs/method.md §10). Reported only when
    /// [`ContinuationOptions::nonlinear`] asks (or by the post-pass
    /// [`nonlinear_events`]).
    ArnoldDegenerate,
    /// A 1:2 or 1:3 resonance between the two frequencies on a gyroscopically stabilised
    /// stretch (docs/method.md §10); [`BranchEvent::nonlinear`] says which. Reported only when
    /// [`ContinuationOptions::nonlinear`] asks (or by the post-pass).
    Resonance,
}

impl fmt::Display for EventKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            EventKind::Fold => "fold",
            EventKind::BranchPoint => "branch point",
            EventKind::HamiltonianHopf => "Hamiltonian–Hopf",
            EventKind::ArnoldDegenerate => "Arnold-degenerate (D = 0)",
            EventKind::Resonance => "resonance",
        })
    }
}

impl fmt::Display for BranchEvent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} at s = {:.12} on branch {}, γ = ({:+.6}, {:+.6}, {:+.6}): {} → {}",
            self.kind,
            self.s,
            self.branch,
            self.gamma.x,
            self.gamma.y,
            self.gamma.z,
            self.before,
            self.after
        )?;
        if let Some(n) = &self.nonlinear {
            write!(f, "; nonlinear: {n}")?;
        }
        Ok(())
    }
}

/// Options of [`stability_atlas`].
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let opts = AtlasOptions { nx: 11, ny: 11, ..Default::default() };
/// let atlas = stability_atlas(
///     |mgl, p| (Gyrostat::lagrange_top(1.0, 1.25, mgl), p),
///     Vector3::z(), (0.5, 1.5), (1.0, 4.0), &opts)?;
/// assert_eq!((atlas.x.len(), atlas.y.len()), (11, 11));
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct AtlasOptions {
    /// Number of grid nodes along x (default `41`), at least 2.
    pub nx: usize,
    /// Number of grid nodes along y (default `41`), at least 2.
    pub ny: usize,
    /// Points on the boundary curves satisfy their defining equation to this relative tolerance
    /// (default `1e−10`, inside the `1e−8` of the contract).
    pub curve_tol: f64,
    /// Step of the boundary-curve continuation, relative to the diagonal of the rectangle
    /// (default `0.005`).
    pub curve_step: f64,
    /// Budget of points per boundary curve (default `20_000`); a curve that needs more ends
    /// where it ran out, and the atlas comes back with [`StabilityAtlas::stop`] =
    /// [`StopReason::MaxCurvePoints`] (the `(x, y)` and γ there).
    pub max_curve_points: usize,
    /// Where the motion is first found from `gamma_guess` (by Newton's method on the sphere),
    /// then followed to the nearest node, from which the grid is followed: up and down its
    /// column, then along every row both ways. `None` (the default): the middle of the
    /// rectangle.
    pub start: Option<(f64, f64)>,
    /// Largest angle (radians) between `gamma_guess` and the steady motion found from it at the
    /// start (default `0.35`, about 20°). Farther, the motion asked for is probably not there
    /// and Newton's method landed on another one: [`stability_atlas`] refuses
    /// ([`RouthError::InvalidOption`](crate::RouthError::InvalidOption) naming `gamma_guess`).
    pub max_guess_angle: f64,
    /// Number of worker threads for the grid of
    /// [`stability_atlas_parallel`] (`0`: all cores; default
    /// `0`). The result does not depend on it.
    pub threads: usize,
    /// Tolerances of the verdicts at each node.
    pub classify: ClassifyOptions,
    /// When `Some`, the atlas also marks, on its gyroscopically stabilised cells, the curves
    /// where Arnold's determinant vanishes and the 1:2 and 1:3 resonances
    /// ([`StabilityAtlas::nonlinear`]), with the nonlinear test and these options. Needs a model
    /// with a Routh-function tape (derived or run-time). Default `None`.
    #[cfg_attr(feature = "serde", serde(default))]
    pub nonlinear: Option<NonlinearOptions>,
    /// Cancellation and progress (rows of the grid done of `ny`): a cancelled atlas returns
    /// [`RouthError::Interrupted`](crate::RouthError::Interrupted). Not a setting: not
    /// serialised, not compared.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub control: crate::RunControl,
}

impl Default for AtlasOptions {
    fn default() -> Self {
        AtlasOptions {
            nx: 41,
            ny: 41,
            curve_tol: 1e-10,
            curve_step: 0.005,
            max_curve_points: 20_000,
            start: None,
            max_guess_angle: 0.35,
            threads: 0,
            classify: ClassifyOptions::default(),
            nonlinear: None,
            control: crate::RunControl::default(),
        }
    }
}

/// The verdict of one steady motion over a grid of two parameters, with the boundary curves of
/// its stability regions.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let opts = AtlasOptions { nx: 11, ny: 11, ..Default::default() };
/// let atlas: StabilityAtlas = stability_atlas(
///     |mgl, p| (Gyrostat::lagrange_top(1.0, 1.25, mgl), p),
///     Vector3::z(), (0.5, 1.5), (1.0, 4.0), &opts)?;
/// // At mgl = 0.5, p = 4 the sleeping top is secularly stable (p² > mglC²/(C − A₁) = 3.125).
/// assert_eq!(atlas.verdicts[10][0], Some(Stability::SecularlyStable));
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StabilityAtlas {
    /// The grid abscissae, ascending.
    pub x: Vec<f64>,
    /// The grid ordinates, ascending.
    pub y: Vec<f64>,
    /// `verdicts[j][i]` at `(x[i], y[j])`; `None` where the steady motion does not exist (beyond
    /// a fold) or could not be followed (see [`StabilityAtlas::lost`]).
    pub verdicts: Vec<Vec<Option<Stability>>>,
    /// The boundary curves, traced by continuation of their defining equations.
    pub boundaries: Vec<BoundaryCurve>,
    /// `lost[j][i]` is `true` where `verdicts[j][i]` is `None` because the motion was lost: its
    /// continuation towards the node stalled away from a fold (a step would land on another
    /// steady motion, which is refused: the atlas never jumps from one motion to another), so
    /// nothing is known there. `false` where the motion ends at a fold on the way (it does not
    /// exist beyond it) and at every node with a verdict.
    pub lost: Vec<Vec<bool>>,
    /// `None` when the atlas is complete; otherwise why it stopped early (a budget ran out).
    pub stop: Option<StopReason>,
    /// The curves D = 0 and the 1:2, 1:3 resonances on the gyroscopically stabilised cells,
    /// when [`AtlasOptions::nonlinear`] asks (empty otherwise).
    #[cfg_attr(feature = "serde", serde(default))]
    pub nonlinear: Vec<NonlinearCurve>,
}

/// A curve in the parameter plane where the verdict of the followed steady motion changes.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let opts = AtlasOptions { nx: 11, ny: 11, ..Default::default() };
/// let atlas = stability_atlas(
///     |mgl, p| (Gyrostat::lagrange_top(1.0, 1.25, mgl), p),
///     Vector3::z(), (0.5, 1.5), (1.0, 4.0), &opts)?;
/// let secular: &BoundaryCurve =
///     atlas.boundaries.iter().find(|b| b.kind == EventKind::BranchPoint).unwrap();
/// for &(mgl, p) in &secular.points {
///     assert!((p * p * 0.25 / 1.5625 - mgl).abs() < 1e-8 * mgl); // p² = mglC²/(C − A₁)
/// }
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BoundaryCurve {
    /// Which defining equation: a zero eigenvalue of the restricted second variation
    /// ([`EventKind::Fold`] or [`EventKind::BranchPoint`]) or a zero discriminant of `f₂`
    /// ([`EventKind::HamiltonianHopf`]).
    pub kind: EventKind,
    /// Points `(x, y)` along the curve, in order.
    pub points: Vec<(f64, f64)>,
}
