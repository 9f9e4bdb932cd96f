//! [`stability_atlas`]: the verdict of one steady motion over a grid of two parameters, with
//! boundary curves traced by continuation.
//!
//! # The grid
//!
//! The steady motion is found once, at [`AtlasOptions::start`] (default: the middle of the
//! rectangle), by [`steady_motion_near`] from the guess; if it lies farther than
//! [`AtlasOptions::max_guess_angle`] from the guess the atlas is refused (the motion asked for is
//! not there). It is followed to the nearest node, then from node to node: up and down the
//! column of that node, then along every row both ways from its node in that column. Each move
//! from a node to its neighbour is a small continuation along the
//! segment between them (the two-parameter family restricted to the segment is a one-parameter
//! family, so [`chart_eval`] applies): a tangent predictor `dξ/ds = −F_ξ⁻¹F_s`, then Newton's
//! method on the sphere at the new parameters in the chart around the old γ. A step is accepted
//! only if Newton converges, lands within `0.3·|Δξ_pred| + 10⁻⁴` rad of the prediction (no jump
//! to another branch) and the eigenvalues of the restricted second variation `K` move by less
//! than `0.3` of the local scale; otherwise the step is halved. Below `10⁻⁶` of the segment the
//! motion is gone: at a fold (an eigenvalue of `K` below `10⁻³` of the size of the derivatives
//! where it stalled) it does not exist beyond; elsewhere it is *lost*
//! ([`StabilityAtlas::lost`]): a step would land on another motion. That node and the rest of
//! its row (or column, away from the start) are `None` — continuing further along the same line
//! would cross the same fold, and a motion found again there could be another sheet.
//!
//! Rows are independent once the first column is known, so they run in parallel on a pool of
//! [`AtlasOptions::threads`] threads by [`stability_atlas_parallel`]; the traversal inside a row
//! is fixed, so the result does not depend on the number of threads (bit for bit).
//!
//! # The boundary curves
//!
//! Where the verdicts of two neighbouring nodes differ, the edge between them is searched for a
//! zero of a test function:
//! - an eigenvalue of `K` relative to the local scale (its sign changes on the edge):
//!   [`EventKind::Fold`] or [`EventKind::BranchPoint`]; the eigenvalue is picked by continuity of
//!   its eigenvector, so a double zero (the secular bound of a sleeping Lagrange top, `K = hE`)
//!   is followed like a simple one;
//! - [`relative_discriminant`] of `f₂`, where both nodes have degree of instability 2:
//!   [`EventKind::HamiltonianHopf`];
//! - next to a node where the motion is lost: the eigenvalue of `K` nearest zero at the last point
//!   the continuation reached (a fold).
//!
//! The crossing is located by the crate's event locator (Illinois) along the edge, γ following by the same
//! continuation, then projected onto the curve by Gauss–Newton with minimum-norm steps on the
//! three equations `P_bᵀt(γ(ξ); x, y) = 0` (relative to the local scale) and `τ(γ(ξ); x, y) = 0`
//! in the four unknowns `(ξ, x, y)` (`x`, `y` scaled to the unit square). The curve is then
//! followed both ways by pseudo-arclength continuation: tangent = the null vector of the 3×4
//! Jacobian nearest the previous tangent (minimum-norm steps and this choice keep symmetric
//! cases, where the Jacobian loses rank — a branch point of a symmetric body — on the curve),
//! corrector = Gauss–Newton on the three equations plus the arclength hyperplane. Derivatives in
//! ξ of `t` are exact ([`chart_eval`]), in `x`, `y` and of `τ` central differences. A step is
//! accepted when the residual is within [`AtlasOptions::curve_tol`], the correction stays
//! within half a step of the prediction, and the tangent turns by less than 37°; otherwise it is
//! halved, and below `10⁻⁴` of [`AtlasOptions::curve_step`] the curve ends (a cusp, a crossing,
//! or the end of the motion). A curve also ends where it leaves the rectangle (the exit point is
//! solved on the edge) or when it closes. A located start within `2·10⁻³` of the unit square of a
//! curve of the same class already traced is skipped.
//!
//! A zero-eigenvalue curve is a [`EventKind::Fold`] where the motion ceases to exist on one side:
//! with `ℓ` the null vector of `∂F/∂ξ`, the parameters move the equations out of its range,
//! `ℓᵀ∂F/∂(x, y) ≠ 0` (relative to the local scale, above `10⁻⁶` in unit-square units). Where
//! `ℓᵀ∂F/∂(x, y) = 0` other branches cross the motion instead (a pitchfork of a symmetric body,
//! where the motion exists on both sides): [`EventKind::BranchPoint`]. The kind of a curve is
//! that of the majority of its points.
//!
//! [`chart_eval`]: super::equations::chart_eval
//! [`relative_discriminant`]: super::equations::relative_discriminant
//! [`EventKind::Fold`]: super::EventKind::Fold
//! [`EventKind::BranchPoint`]: super::EventKind::BranchPoint
//! [`EventKind::HamiltonianHopf`]: super::EventKind::HamiltonianHopf
//!
//! # Layout
//!
//! - this module: the entry points, the options check and the context shared by the rest;
//! - `grid`: the motion followed from node to node, the verdicts at the nodes;
//! - `curve`: the defining equations of a boundary curve and their Gauss–Newton corrector;
//! - `edge`: the start of a curve bracketed on a grid edge;
//! - `trace`: the curves followed by continuation from their starts.

mod curve;
mod edge;
mod grid;
mod trace;

use std::marker::PhantomData;

use nalgebra::Vector3;
use rayon::prelude::*;

use super::nonlinear::GridNode;
use super::{AtlasOptions, StabilityAtlas, StopReason};
use crate::error::RouthError;
use crate::model::Routhian;
use crate::nonlinear::NonlinearOptions;
use crate::steady::steady_motion_near;
use grid::{Line, Node};

/// The largest grid `nx · ny` an atlas accepts.
pub const MAX_ATLAS_NODES: usize = 100_000_000;

/// Singular values below this fraction of the largest (or of the local scale) are zero.
const PINV_CUT: f64 = 1e-10;
/// Central-difference steps: parameters (relative to the range) and chart coordinates (rad).
const PARAM_FD: f64 = 1e-6;

/// The stability atlas of the steady motion nearest `gamma_guess` at [`AtlasOptions::start`]
/// (default: the middle of the rectangle): its verdict
/// ([`classify_with`] with [`AtlasOptions::classify`]) at every node of an `nx × ny` grid of the
/// rectangle `[x.0, x.1] × [y.0, y.1]` (ends included), following the motion by continuation from
/// node to node, and the boundary curves of its stability regions traced by continuation of their
/// defining equations (the algorithm in full is in the docs of the source module, `families/atlas/mod.rs`):
///
/// - `verdicts[j][i]` is the verdict at `(x[i], y[j])`, `None` where the followed motion no longer
///   exists (beyond a fold) or was lost (`lost[j][i]`: its continuation would have jumped to
///   another steady motion, which is never done). The column of the start node is followed both
///   ways from it, then every row both ways from its node in that column; once gone, the rest of
///   a line stays `None`.
/// - `boundaries`: curves where an eigenvalue of the restricted second variation `K` vanishes
///   ([`EventKind::Fold`] if the motion is lost on one side, else [`EventKind::BranchPoint`]) or,
///   with degree of instability 2, the discriminant of `f₂` in `λ²` vanishes
///   ([`EventKind::HamiltonianHopf`]). Every point satisfies `t(γ; x, y) = 0` (33) and its test
///   function to [`AtlasOptions::curve_tol`] relative to the local scale (the discriminant
///   relative to `c₂² + 4|c₄c₀|`). Curves end at the edges of the rectangle, where they close,
///   or at cusps and crossings.
/// - The rows run one after the other; [`stability_atlas_parallel`] runs them on all cores (or
///   [`AtlasOptions::threads`]) for a family that can be shared between threads, with the same
///   result bit for bit.
///
/// A boundary curve longer than [`AtlasOptions::max_curve_points`] ends there, and the atlas
/// comes back with [`StabilityAtlas::stop`] saying where.
///
/// Errors: [`RouthError::InvalidOption`] for `nx < 2`, `ny < 2`, an empty or non-finite range,
/// or options out of range (a start outside the rectangle); [`RouthError::InvalidOption`] naming
/// `gamma_guess` when the motion found from it at the start is farther than
/// [`AtlasOptions::max_guess_angle`] from it, or naming `start` when that motion cannot be
/// followed from a start between nodes to the nearest node; the errors of
/// [`steady_motion_near`] at the start; a non-finite `p_ψ` from the family, or a failure of
/// [`classify_with`] at a node where the motion was found — these are wrapped as
/// `AtParameter { s: x, source: AtParameter { s: y, source } }`.
///
/// ```
/// # use routh_core::Vector3;
/// # use test_models::HeavyTop;
/// use routh_core::{stability_atlas, AtlasOptions, EventKind, Stability};
/// // The sleeping top γ = e₃ over (mgl, p_ψ) ∈ [0.5, 2] × [0.5, 5], A₁ = 1, C = 1.2: the Lagrange
/// // top J = diag(A₁, A₁, C), U = mgl·γ₃, with its Routh function written by hand.
/// let family = |mgl: f64, p: f64| (HeavyTop::lagrange(1.0, 1.2, mgl), p);
/// let opts = AtlasOptions { nx: 21, ny: 21, ..AtlasOptions::default() };
/// let atlas = stability_atlas(family, Vector3::z(), (0.5, 2.0), (0.5, 5.0), &opts)?;
/// // Slow: unstable; fast: secularly stable; in between gyroscopically stabilised.
/// assert_eq!(atlas.verdicts[0][0], Some(Stability::Unstable));
/// assert_eq!(atlas.verdicts[20][0], Some(Stability::SecularlyStable));
/// assert_eq!(atlas.verdicts[9][10], Some(Stability::GyroscopicallyStabilized)); // mgl = 1.25, p = 2.525
/// // Maievskii's bound p² = 4A₁·mgl is the Hamiltonian–Hopf curve.
/// let hopf = atlas.boundaries.iter().find(|b| b.kind == EventKind::HamiltonianHopf).unwrap();
/// for &(mgl, p) in &hopf.points {
///     assert!((p * p / (4.0 * mgl) - 1.0).abs() < 1e-8);
/// }
/// # Ok::<(), routh_core::RouthError>(())
/// ```
///
/// [`classify_with`]: crate::stability::classify_with
/// [`EventKind::Fold`]: super::EventKind::Fold
/// [`EventKind::BranchPoint`]: super::EventKind::BranchPoint
/// [`EventKind::HamiltonianHopf`]: super::EventKind::HamiltonianHopf
pub fn stability_atlas<M: Routhian, F: Fn(f64, f64) -> (M, f64)>(
    family: F,
    gamma_guess: Vector3<f64>,
    x: (f64, f64),
    y: (f64, f64),
    opts: &AtlasOptions,
) -> Result<StabilityAtlas, RouthError> {
    atlas_with(
        &family,
        gamma_guess,
        x,
        y,
        opts,
        |ctx, xs, ys, i0, column| {
            (0..ys.len())
                .map(|j| ctx.row(xs, ys[j], i0, column[j].0, column[j].1))
                .collect()
        },
        |xs, ys, nodes, nl| super::nonlinear::atlas_curves(&family, xs, ys, nodes, nl),
    )
}

/// [`stability_atlas`] with the rows of the grid on [`AtlasOptions::threads`] threads (`0`: all
/// cores), for a family that can be shared between threads (`Sync`: any closure over plain
/// data). The result is the same, bit for bit, for any number of threads and equal to that of
/// [`stability_atlas`].
///
/// Errors: as [`stability_atlas`], plus [`RouthError::InvalidOption`] when the thread pool cannot
/// be built.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let family = |mgl: f64, p: f64| (Gyrostat::lagrange_top(1.0, 1.25, mgl), p);
/// let opts = AtlasOptions { nx: 11, ny: 11, threads: 2, ..Default::default() };
/// let parallel = stability_atlas_parallel(family, Vector3::z(), (0.5, 1.5), (1.0, 4.0), &opts)?;
/// let sequential = stability_atlas(family, Vector3::z(), (0.5, 1.5), (1.0, 4.0), &opts)?;
/// assert_eq!(parallel, sequential);
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn stability_atlas_parallel<M: Routhian, F: Fn(f64, f64) -> (M, f64) + Sync>(
    family: F,
    gamma_guess: Vector3<f64>,
    x: (f64, f64),
    y: (f64, f64),
    opts: &AtlasOptions,
) -> Result<StabilityAtlas, RouthError> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(opts.threads)
        .build()
        .map_err(|e| RouthError::InvalidOption {
            what: "threads",
            reason: e.to_string(),
        })?;
    atlas_with(
        &family,
        gamma_guess,
        x,
        y,
        opts,
        |ctx, xs, ys, i0, column| {
            pool.install(|| {
                (0..ys.len())
                    .into_par_iter()
                    .map(|j| ctx.row(xs, ys[j], i0, column[j].0, column[j].1))
                    .collect()
            })
        },
        |xs, ys, nodes, nl| {
            pool.install(|| super::nonlinear::atlas_curves_parallel(&family, xs, ys, nodes, nl))
        },
    )
}

/// Rows of nodes of the grid (with their lost flags), or an error.
type Rows = Result<Vec<Line>, RouthError>;

/// The first column: at each ordinate γ at the start column, if reached, and whether it was lost.
type Column = [(Option<Vector3<f64>>, bool)];

/// The nonlinear curves from the grid's nodes, or an error.
type Curves = Result<Vec<super::NonlinearCurve>, RouthError>;

/// The atlas, with the rows computed by `rows` (sequentially or in parallel) from the start
/// column, and the nonlinear curves (if asked for) by `curves` (likewise).
fn atlas_with<'a, M: Routhian, F: Fn(f64, f64) -> (M, f64)>(
    family: &'a F,
    gamma_guess: Vector3<f64>,
    x: (f64, f64),
    y: (f64, f64),
    opts: &'a AtlasOptions,
    rows: impl FnOnce(&Ctx<'a, M, F>, &[f64], &[f64], usize, &Column) -> Rows,
    curves: impl FnOnce(&[f64], &[f64], &[Vec<GridNode>], &NonlinearOptions) -> Curves,
) -> Result<StabilityAtlas, RouthError> {
    validate(x, y, opts)?;
    let ctx = Ctx::new(family, x, y, opts);
    let xs = linspace(x, opts.nx);
    let ys = linspace(y, opts.ny);

    // The start: the motion nearest the guess at the start point, followed to its nearest node.
    let (sx, sy) = opts.start.unwrap_or((0.5 * (x.0 + x.1), 0.5 * (y.0 + y.1)));
    let nearest = |v: &[f64], t: f64| {
        (0..v.len())
            .min_by(|&a, &b| (v[a] - t).abs().total_cmp(&(v[b] - t).abs()))
            .unwrap_or(0)
    };
    let (i0, j0) = (nearest(&xs, sx), nearest(&ys, sy));
    let (m0, p0) = ctx.member(sx, sy)?;
    let found = steady_motion_near(&m0, gamma_guess, p0).map_err(|e| at_xy(sx, sy, e))?;
    let guess = gamma_guess.normalize();
    let angle = guess.dot(&found.gamma).clamp(-1.0, 1.0).acos();
    if angle.is_nan() || angle > opts.max_guess_angle {
        return Err(RouthError::InvalidOption {
            what: "gamma_guess",
            reason: format!(
                "the steady motion found from it at the start (x, y) = ({sx}, {sy}), γ = \
                 ({:+.9}, {:+.9}, {:+.9}), is {angle:.4} rad from the guess, more than \
                 max_guess_angle = {} rad: the motion asked for is probably not there; give \
                 another start or a better guess",
                found.gamma.x, found.gamma.y, found.gamma.z, opts.max_guess_angle
            ),
        });
    }
    let start = if (sx, sy) == (xs[i0], ys[j0]) {
        found.gamma
    } else {
        ctx.follow((sx, sy), &found.gamma, (xs[i0], ys[j0]))
            .reached
            .ok_or_else(|| RouthError::InvalidOption {
                what: "start",
                reason: format!(
                    "the steady motion found at the start (x, y) = ({sx}, {sy}) cannot be \
                     followed to the nearest node ({}, {}); give a start on a node",
                    xs[i0], ys[j0]
                ),
            })?
    };

    // The start column, both ways from the start node, sequentially.
    let mut column: Vec<(Option<Vector3<f64>>, bool)> = vec![(None, false); opts.ny];
    column[j0] = (Some(start), false);
    let order: [Vec<usize>; 2] = [(j0 + 1..opts.ny).collect(), (0..j0).rev().collect()];
    for dir in order {
        let mut gone: Option<bool> = None;
        for j in dir {
            if let Some(l) = gone {
                column[j] = (None, l);
                continue;
            }
            let k = if j > j0 { j - 1 } else { j + 1 };
            let Some(g) = column[k].0 else { continue };
            ctx.member(xs[i0], ys[j])?;
            let f = ctx.follow((xs[i0], ys[k]), &g, (xs[i0], ys[j]));
            match f.reached {
                Some(g) => column[j] = (Some(g), false),
                None => {
                    let l = ctx.lost_at((xs[i0], ys[k]), (xs[i0], ys[j]), f.last);
                    column[j] = (None, l);
                    gone = Some(l);
                }
            }
        }
    }

    // The rows, each from its node in the start column in a fixed order.
    let lines = rows(&ctx, &xs, &ys, i0, &column)?;
    opts.control.check()?;
    let (rows, lost): (Vec<Vec<Option<Node>>>, Vec<Vec<bool>>) = lines.into_iter().unzip();

    let boundaries = ctx.boundaries(&xs, &ys, &rows)?;
    let nonlinear = match &opts.nonlinear {
        Some(nl) => {
            let nodes: Vec<Vec<GridNode>> = rows
                .iter()
                .map(|r| {
                    r.iter()
                        .map(|n| n.as_ref().map(|n| (n.gamma, n.report.verdict)))
                        .collect()
                })
                .collect();
            curves(&xs, &ys, &nodes, nl)?
        }
        None => Vec::new(),
    };
    let verdicts = rows
        .iter()
        .map(|r| {
            r.iter()
                .map(|n| n.as_ref().map(|n| n.report.verdict))
                .collect()
        })
        .collect();
    let lost = lost
        .into_iter()
        .zip(&rows)
        .map(|(l, r)| {
            l.into_iter()
                .zip(r)
                .map(|(l, n)| l && n.is_none())
                .collect()
        })
        .collect();
    let stop = ctx.stop.lock().map(|s| s.clone()).unwrap_or(None);
    Ok(StabilityAtlas {
        x: xs,
        y: ys,
        verdicts,
        boundaries,
        lost,
        stop,
        nonlinear,
    })
}

fn validate(x: (f64, f64), y: (f64, f64), opts: &AtlasOptions) -> Result<(), RouthError> {
    let invalid =
        |what: &'static str, reason: String| Err(RouthError::InvalidOption { what, reason });
    for (what, r) in [("x", x), ("y", y)] {
        if !(r.0.is_finite() && r.1.is_finite() && r.0 < r.1) {
            return invalid(
                what,
                format!("the range must be finite and ascending (got {r:?})"),
            );
        }
    }
    if opts.nx < 2 {
        return invalid(
            "nx",
            format!("at least 2 nodes are needed (got {})", opts.nx),
        );
    }
    if opts.ny < 2 {
        return invalid(
            "ny",
            format!("at least 2 nodes are needed (got {})", opts.ny),
        );
    }
    // The grid is allocated up front: a grid that cannot be allocated is bad input, not a crash
    // (2^32 × 2^32 nodes overflowed the allocation; 10^8 nodes are hours of work at best).
    if opts
        .nx
        .checked_mul(opts.ny)
        .is_none_or(|n| n > MAX_ATLAS_NODES)
    {
        return invalid(
            "nx",
            format!(
                "the grid of {} × {} nodes exceeds {MAX_ATLAS_NODES} nodes",
                opts.nx, opts.ny
            ),
        );
    }
    if !(opts.curve_tol > 0.0 && opts.curve_tol < 1.0) {
        return invalid(
            "curve_tol",
            format!("must be in (0, 1) (got {:e})", opts.curve_tol),
        );
    }
    if !(opts.curve_step > 0.0 && opts.curve_step <= 1.0) {
        return invalid(
            "curve_step",
            format!("must be in (0, 1] (got {:e})", opts.curve_step),
        );
    }
    if !(opts.max_guess_angle > 0.0 && opts.max_guess_angle <= std::f64::consts::PI) {
        return invalid(
            "max_guess_angle",
            format!("must be in (0, π] (got {:e})", opts.max_guess_angle),
        );
    }
    if let Some((sx, sy)) = opts.start {
        if !(sx >= x.0 && sx <= x.1 && sy >= y.0 && sy <= y.1) {
            return invalid(
                "start",
                format!("must lie in the rectangle (got ({sx}, {sy}))"),
            );
        }
    }
    if opts.max_curve_points < 2 {
        return invalid(
            "max_curve_points",
            format!(
                "at least 2 points are needed (got {})",
                opts.max_curve_points
            ),
        );
    }
    Ok(())
}

/// `n` evenly spaced values from `r.0` to `r.1`, both exact.
fn linspace(r: (f64, f64), n: usize) -> Vec<f64> {
    let d = (r.1 - r.0) / (n - 1) as f64;
    (0..n)
        .map(|i| if i + 1 == n { r.1 } else { r.0 + d * i as f64 })
        .collect()
}

/// An error at the parameters `(x, y)`.
fn at_xy(x: f64, y: f64, e: RouthError) -> RouthError {
    RouthError::AtParameter {
        s: x,
        source: Box::new(RouthError::AtParameter {
            s: y,
            source: Box::new(e),
        }),
    }
}

struct Ctx<'a, M, F> {
    family: &'a F,
    x: (f64, f64),
    y: (f64, f64),
    hx: f64,
    hy: f64,
    opts: &'a AtlasOptions,
    /// The first budget that ran out, if any (shared by the rows' threads).
    stop: std::sync::Mutex<Option<StopReason>>,
    /// Rows of the grid done (for [`AtlasOptions::control`]'s progress).
    rows_done: std::sync::atomic::AtomicUsize,
    _model: PhantomData<fn() -> M>,
}

impl<'a, M: Routhian, F: Fn(f64, f64) -> (M, f64)> Ctx<'a, M, F> {
    fn new(family: &'a F, x: (f64, f64), y: (f64, f64), opts: &'a AtlasOptions) -> Self {
        let step = |r: (f64, f64)| PARAM_FD * (r.1 - r.0).max(1e-8 * r.0.abs().max(r.1.abs()));
        Ctx {
            family,
            x,
            y,
            hx: step(x),
            hy: step(y),
            opts,
            stop: std::sync::Mutex::new(None),
            rows_done: std::sync::atomic::AtomicUsize::new(0),
            _model: PhantomData,
        }
    }

    /// Records the first budget that ran out.
    fn stopped(&self, why: StopReason) {
        if let Ok(mut s) = self.stop.lock() {
            if s.is_none() {
                *s = Some(why);
            }
        }
    }

    /// The member at `(x, y)`.
    fn member(&self, x: f64, y: f64) -> Result<(M, f64), RouthError> {
        let (m, p) = (self.family)(x, y);
        if !p.is_finite() {
            return Err(at_xy(
                x,
                y,
                RouthError::NonFinite {
                    what: "p_psi returned by the family",
                    value: p,
                },
            ));
        }
        Ok((m, p))
    }

    fn lx(&self) -> f64 {
        self.x.1 - self.x.0
    }
    fn ly(&self) -> f64 {
        self.y.1 - self.y.0
    }
    /// Scaled coordinates `(u, v) ∈ [0, 1]²` → parameters.
    fn unscale(&self, u: f64, v: f64) -> (f64, f64) {
        (self.x.0 + u * self.lx(), self.y.0 + v * self.ly())
    }
    fn scale_xy(&self, x: f64, y: f64) -> (f64, f64) {
        ((x - self.x.0) / self.lx(), (y - self.y.0) / self.ly())
    }
}
