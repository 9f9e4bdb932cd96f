//! [`stability_atlas`]: the verdict of one steady motion over a grid of two parameters, with
//! boundary curves traced by continuation.
//!
//! # The grid
//!
//! The steady motion is found once, at the corner `(x₀, y₀)`, by
//! [`steady_motion_near`](crate::steady_motion_near). It is then followed from node to node:
//! up the first column (`x = x₀`, `y` ascending), then along every row from its first node
//! (`x` ascending). Each move from a node to its neighbour is a small continuation along the
//! segment between them (the two-parameter family restricted to the segment is a one-parameter
//! family, so [`chart_eval`] applies): a tangent predictor `dξ/ds = −F_ξ⁻¹F_s`, then Newton's
//! method on the sphere at the new parameters in the chart around the old γ. A step is accepted
//! only if Newton converges, lands within `0.3·|Δξ_pred| + 10⁻⁴` rad of the prediction (no jump
//! to another branch) and the eigenvalues of the restricted second variation `K` move by less
//! than `0.3` of the local scale; otherwise the step is halved. Below `10⁻⁶` of the segment the
//! motion is lost (it ended at a fold): that node and the rest of its row (or column) are
//! `None` — continuing further along the same line would cross the same fold.
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
//! The crossing is bracketed by regula falsi (Illinois) along the edge, γ following by the same
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

use std::marker::PhantomData;

use nalgebra::{Matrix2, Matrix3x2, Matrix3x4, Matrix4, Vector2, Vector3, Vector4};
use rayon::prelude::*;

use super::equations::{chart, chart_eval, relative_discriminant, restricted_eigen, Local};
use super::{AtlasOptions, BoundaryCurve, EventKind, StabilityAtlas};
use crate::error::RouthError;
use crate::model::Routhian;
use crate::sphere::{sym2_eigen, tangent_basis};
use crate::stability::{classify_with, StabilityReport};
use crate::steady::{steady_motion_near, SteadyMotion};

/// Newton on the sphere: converged when `|P_bᵀt| ≤ NEWTON_TOL ·` local scale.
const NEWTON_TOL: f64 = 1e-11;
/// … and polished until this (or one more step after `NEWTON_TOL`).
const NEWTON_POLISH: f64 = 1e-14;
const NEWTON_MAX_ITER: usize = 12;
/// Largest Newton step on the sphere (rad).
const NEWTON_MAX_STEP: f64 = 0.5;
/// Singular values below this fraction of the largest (or of the local scale) are zero.
const PINV_CUT: f64 = 1e-10;
/// Central-difference step in the segment parameter of the grid continuation.
const SEGMENT_DS: f64 = 1e-6;
/// Smallest step (fraction of a segment) of the grid continuation.
const SEGMENT_MIN_STEP: f64 = 1e-6;
/// Jump detection: `|ξ − ξ_pred| ≤ JUMP_RATIO·|ξ_pred| + JUMP_FLOOR`.
const JUMP_RATIO: f64 = 0.3;
const JUMP_FLOOR: f64 = 1e-4;
/// Jump detection: eigenvalues of `K` move by at most this fraction of the local scale per step.
const EIGEN_JUMP: f64 = 0.3;
/// Central-difference steps: parameters (relative to the range) and chart coordinates (rad).
const PARAM_FD: f64 = 1e-6;
const XI_FD: f64 = 1e-6;
/// Singular values of the curve Jacobian below this fraction of the largest span its null space.
const NULL_CUT: f64 = 1e-8;
/// Smallest curve step, relative to `curve_step`.
const CURVE_MIN_STEP: f64 = 1e-4;
const CURVE_MAX_ITER: usize = 10;
/// Largest Gauss–Newton step on a curve (unit-square units and rad).
const CURVE_MAX_CORRECTION: f64 = 0.25;
/// A zero-eigenvalue curve is a fold where [`fold_indicator`] exceeds this.
const FOLD_INDICATOR: f64 = 1e-6;
/// Smallest cosine between consecutive tangents of a curve.
const CURVE_MIN_COS: f64 = 0.8;
/// Starts closer than this (unit square) to a traced curve of the same class are skipped.
const DEDUP: f64 = 2e-3;
const LOCATE_MAX_ITER: usize = 80;

/// The stability atlas of the steady motion nearest `gamma_guess` at `(x.0, y.0)`: its verdict
/// ([`classify_with`] with [`AtlasOptions::classify`]) at every node of an `nx × ny` grid of the
/// rectangle `[x.0, x.1] × [y.0, y.1]` (ends included), following the motion by continuation from
/// node to node, and the boundary curves of its stability regions traced by continuation of their
/// defining equations (the algorithm in full is in the docs of the source module, `atlas.rs`):
///
/// - `verdicts[j][i]` is the verdict at `(x[i], y[j])`, `None` where the followed motion no longer
///   exists (beyond a fold) or could not be followed. The first column is followed upwards from
///   the corner, then every row from its first node; once lost, a row (or the first column) stays
///   lost.
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
/// Errors: [`RouthError::InvalidOption`] for `nx < 2`, `ny < 2`, an empty or non-finite range,
/// or options out of range; the errors of [`steady_motion_near`](crate::steady_motion_near) at the
/// corner; a non-finite `p_ψ` from the family, or a failure of [`classify_with`] at a node where
/// the motion was found — these are wrapped as
/// `AtParameter { s: x, source: AtParameter { s: y, source } }`.
///
/// ```
/// # use routh_core::{Lagrangian, Routhian, Matrix3, Vector3};
/// use routh_core::{stability_atlas, AtlasOptions, EventKind, Stability};
/// /// The Lagrange top J = diag(A₁, A₁, C), U = mgl·γ₃, written with its Routh function.
/// struct Top { a1: f64, c: f64, mgl: f64 }
/// # impl Top {
/// #     fn j(&self) -> Matrix3<f64> { Matrix3::from_diagonal(&Vector3::new(self.a1, self.a1, self.c)) }
/// #     fn nq(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> (f64, f64) {
/// #         (g.dot(&(self.j() * g)), p - (self.j() * w).dot(g))
/// #     }
/// #     fn dqn(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
/// #         let (n, q) = self.nq(w, g, p);
/// #         -(self.j() * w) / n - (2.0 * q / (n * n)) * (self.j() * g)
/// #     }
/// # }
/// # impl Lagrangian for Top {
/// #     fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
/// #         0.5 * w.dot(&(self.j() * w)) - self.mgl * g.z
/// #     }
/// #     fn dl_domega(&self, w: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> { self.j() * w }
/// #     fn dl_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
/// #         Vector3::new(0.0, 0.0, -self.mgl)
/// #     }
/// #     fn d2l_domega2(&self, _: &Vector3<f64>) -> Matrix3<f64> { self.j() }
/// #     fn d2l_domega_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Matrix3<f64> {
/// #         Matrix3::zeros()
/// #     }
/// # }
/// # impl Routhian for Top {
/// #     fn routhian(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
/// #         let (n, q) = self.nq(w, g, p);
/// #         0.5 * w.dot(&(self.j() * w)) - self.mgl * g.z - 0.5 * q * q / n
/// #     }
/// #     fn dr_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
/// #         let (n, q) = self.nq(w, g, p);
/// #         self.j() * w + (q / n) * (self.j() * g)
/// #     }
/// #     fn dr_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
/// #         let (n, q) = self.nq(w, g, p);
/// #         Vector3::new(0.0, 0.0, -self.mgl) + (q / n) * (self.j() * w)
/// #             + (q * q / (n * n)) * (self.j() * g)
/// #     }
/// #     fn d2r_domega2(&self, _: &Vector3<f64>, g: &Vector3<f64>, _: f64) -> Matrix3<f64> {
/// #         let jg = self.j() * g;
/// #         self.j() - jg * jg.transpose() / g.dot(&jg)
/// #     }
/// #     fn d2r_domega_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
/// #         let (n, q) = self.nq(w, g, p);
/// #         (self.j() * g) * self.dqn(w, g, p).transpose() + (q / n) * self.j()
/// #     }
/// #     fn d2r_dgamma2(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
/// #         let (n, q) = self.nq(w, g, p);
/// #         let dqn = self.dqn(w, g, p);
/// #         (self.j() * w) * dqn.transpose() + (q * q / (n * n)) * self.j()
/// #             + (2.0 * q / n) * (self.j() * g) * dqn.transpose()
/// #     }
/// # }
/// // The sleeping top γ = e₃ over (mgl, p_ψ) ∈ [0.5, 2] × [0.5, 5], A₁ = 1, C = 1.2.
/// let family = |mgl: f64, p: f64| (Top { a1: 1.0, c: 1.2, mgl }, p);
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
pub fn stability_atlas<M: Routhian, F: Fn(f64, f64) -> (M, f64)>(
    family: F,
    gamma_guess: Vector3<f64>,
    x: (f64, f64),
    y: (f64, f64),
    opts: &AtlasOptions,
) -> Result<StabilityAtlas, RouthError> {
    atlas_with(&family, gamma_guess, x, y, opts, |ctx, xs, ys, column| {
        (0..ys.len())
            .map(|j| ctx.row(xs, ys[j], column[j]))
            .collect()
    })
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
    atlas_with(&family, gamma_guess, x, y, opts, |ctx, xs, ys, column| {
        pool.install(|| {
            (0..ys.len())
                .into_par_iter()
                .map(|j| ctx.row(xs, ys[j], column[j]))
                .collect()
        })
    })
}

/// Rows of nodes of the grid, or an error.
type Rows = Result<Vec<Vec<Option<Node>>>, RouthError>;

/// The atlas, with the rows computed by `rows` (sequentially or in parallel) from the first
/// column.
fn atlas_with<'a, M: Routhian, F: Fn(f64, f64) -> (M, f64)>(
    family: &'a F,
    gamma_guess: Vector3<f64>,
    x: (f64, f64),
    y: (f64, f64),
    opts: &'a AtlasOptions,
    rows: impl FnOnce(&Ctx<'a, M, F>, &[f64], &[f64], &[Option<Vector3<f64>>]) -> Rows,
) -> Result<StabilityAtlas, RouthError> {
    validate(x, y, opts)?;
    let ctx = Ctx::new(family, x, y, opts);
    let xs = linspace(x, opts.nx);
    let ys = linspace(y, opts.ny);

    // The corner, by a local search.
    let (m0, p0) = ctx.member(x.0, y.0)?;
    let start = steady_motion_near(&m0, gamma_guess, p0).map_err(|e| at_xy(x.0, y.0, e))?;

    // The first column, sequentially.
    let mut column: Vec<Option<Vector3<f64>>> = vec![None; opts.ny];
    column[0] = Some(start.gamma);
    for j in 1..opts.ny {
        let Some(g) = column[j - 1] else { break };
        ctx.member(xs[0], ys[j])?;
        column[j] = ctx.follow((xs[0], ys[j - 1]), &g, (xs[0], ys[j])).reached;
    }

    // The rows, each from its first node in a fixed order.
    let rows = rows(&ctx, &xs, &ys, &column)?;

    let boundaries = ctx.boundaries(&xs, &ys, &rows);
    let verdicts = rows
        .iter()
        .map(|r| {
            r.iter()
                .map(|n| n.as_ref().map(|n| n.report.verdict))
                .collect()
        })
        .collect();
    Ok(StabilityAtlas {
        x: xs,
        y: ys,
        verdicts,
        boundaries,
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

/// A grid node where the motion was found.
#[derive(Debug, Clone)]
struct Node {
    gamma: Vector3<f64>,
    report: StabilityReport,
    /// [`relative_discriminant`] of `f₂` there.
    disc: f64,
}

/// The result of following the motion along a segment.
struct Follow {
    /// γ at the end of the segment, if reached.
    reached: Option<Vector3<f64>>,
    /// The last point reached: the segment parameter and γ.
    last: (f64, Vector3<f64>),
}

/// A test function whose zeros are a boundary curve.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Test {
    /// The eigenvalue of `K` (relative to the local scale) whose eigenvector is nearest the
    /// reference (a tangent vector of ℝ³).
    Zero(Vector3<f64>),
    /// The relative discriminant of `f₂`.
    Hopf,
}

/// Which zero the search on an edge looks for.
#[derive(Debug, Clone, Copy)]
enum Seed {
    /// The motion is lost beyond this edge.
    Fold,
    /// The `k`-th eigenvalue (ascending) of `K` changes sign.
    Zero(usize),
    /// The discriminant of `f₂` changes sign with degree 2 on both ends.
    Hopf,
}

/// A point of a curve: γ (the centre of the chart, ξ = 0) and the scaled parameters.
#[derive(Debug, Clone, Copy)]
struct CurvePoint {
    gamma: Vector3<f64>,
    u: f64,
    v: f64,
}

/// The curve equations at one point, in the chart around `base`.
struct Ext {
    gamma: Vector3<f64>,
    /// `(P_bᵀt / scale, τ)`.
    g: Vector3<f64>,
    /// Its Jacobian in `(ξ₁, ξ₂, u, v)`.
    jac: Matrix3x4<f64>,
    /// The eigenvector picked by a [`Test::Zero`] (zero for [`Test::Hopf`]).
    pick: Vector3<f64>,
}

/// A traced curve: whether it is a Hamiltonian–Hopf curve, its points in the unit square, and
/// the number of them where the fold indicator is non-zero.
type Traced = (bool, Vec<(f64, f64)>, usize);

struct Ctx<'a, M, F> {
    family: &'a F,
    x: (f64, f64),
    y: (f64, f64),
    hx: f64,
    hy: f64,
    opts: &'a AtlasOptions,
    _model: PhantomData<fn() -> M>,
}

/// Minimum-norm solution of `j·d = b`, singular values `≤ cut` taken as zero.
fn pinv_solve2(j: &Matrix2<f64>, b: &Vector2<f64>, cut: f64) -> Option<Vector2<f64>> {
    if !j.iter().all(|v| v.is_finite()) || !b.iter().all(|v| v.is_finite()) {
        return None;
    }
    let svd = j.svd(true, true);
    svd.solve(b, cut)
        .ok()
        .filter(|d| d.iter().all(|v| v.is_finite()))
}

/// The null vector of the 3×4 `jac` nearest the reference `r` (normalised, oriented along `r`).
fn null_tangent(jac: &Matrix3x4<f64>, r: &Vector4<f64>) -> Option<Vector4<f64>> {
    if !jac.iter().all(|v| v.is_finite()) {
        return None;
    }
    let mut m = Matrix4::zeros();
    m.fixed_view_mut::<3, 4>(0, 0).copy_from(jac);
    let svd = m.svd(false, true);
    let vt = svd.v_t?;
    let smax = svd.singular_values[0];
    let mut t = Vector4::zeros();
    for i in 0..4 {
        if i == 3 || svd.singular_values[i] <= NULL_CUT * smax {
            let v = vt.row(i).transpose();
            t += v * v.dot(r);
        }
    }
    if t.norm() <= 1e-6 * r.norm() {
        // The reference is orthogonal to the null space: take the last singular vector.
        t = vt.row(3).transpose();
        if t.dot(r) < 0.0 {
            t = -t;
        }
    }
    let n = t.norm();
    (n > 0.0 && n.is_finite()).then(|| t / n)
}

/// The fold indicator of a zero-eigenvalue curve at a point: `|ℓᵀ ∂F/∂(u, v)|` with `ℓ` the left
/// null vector of `∂F/∂ξ` (both relative to the local scale). Non-zero at a fold (the parameters
/// push the motion out of the null direction: it ceases to exist on one side), zero at a branch
/// point (where `∂F/∂(u, v)` lies in the range of `∂F/∂ξ`).
fn fold_indicator(e: &Ext) -> f64 {
    let fxi = e.jac.fixed_view::<2, 2>(0, 0).into_owned();
    let fp = e.jac.fixed_view::<2, 2>(0, 2).into_owned();
    if !fxi.iter().chain(fp.iter()).all(|v| v.is_finite()) {
        return 0.0;
    }
    let svd = fxi.svd(true, false);
    let Some(u) = svd.u else { return 0.0 };
    let k = usize::from(svd.singular_values[1] < svd.singular_values[0]);
    (fp.transpose() * u.column(k)).norm()
}

/// Distance from `p` to the segment `[a, b]` of the plane.
fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
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
            _model: PhantomData,
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

    // ---------------------------------------------------------------- the grid

    /// Newton's method on the sphere for the member `(m, p)`, in the chart around `base`, from
    /// `xi0`. `None` if it does not converge.
    fn newton(
        m: &M,
        p: f64,
        base: &Vector3<f64>,
        basis: &Matrix3x2<f64>,
        xi0: Vector2<f64>,
    ) -> Option<(Vector2<f64>, Local)> {
        let mut xi = xi0;
        let mut polished = false;
        for _ in 0..NEWTON_MAX_ITER {
            let (g, dg) = chart(base, basis, &xi);
            let l = Local::at(m, &g, p).ok()?;
            let f = basis.transpose() * l.tangential();
            let scale = l.raw_scale();
            if !(scale > 0.0 && scale.is_finite()) {
                return None;
            }
            let r = f.norm() / scale;
            if r <= NEWTON_POLISH || (polished && r <= NEWTON_TOL) {
                return Some((xi, l));
            }
            polished = r <= NEWTON_TOL;
            let j = basis.transpose() * l.dt_dgamma() * dg;
            let d = pinv_solve2(&j, &(-f), PINV_CUT * scale)?;
            if d.norm() > NEWTON_MAX_STEP {
                return None;
            }
            xi += d;
        }
        None
    }

    /// Follows the motion from `γ_a` at `a` to `b` along the segment.
    fn follow(&self, a: (f64, f64), gamma_a: &Vector3<f64>, b: (f64, f64)) -> Follow {
        let seg = |s: f64| {
            if s == 1.0 {
                (self.family)(b.0, b.1)
            } else {
                (self.family)(a.0 + s * (b.0 - a.0), a.1 + s * (b.1 - a.1))
            }
        };
        let mut s = 0.0;
        let mut gamma = *gamma_a;
        let mut h: f64 = 1.0;
        let lost = |s: f64, gamma: Vector3<f64>| Follow {
            reached: None,
            last: (s, gamma),
        };
        while s < 1.0 {
            let basis = tangent_basis(&gamma);
            let Ok(ce) = chart_eval(&seg, &gamma, &basis, &Vector2::zeros(), s, SEGMENT_DS) else {
                return lost(s, gamma);
            };
            let scale = ce.local.raw_scale();
            let kappa0 = sym2_eigen(&ce.local.restricted()).values;
            let jxi = ce.jac.fixed_view::<2, 2>(0, 0).into_owned();
            let js = ce.jac.column(2).into_owned();
            let Some(dxi) = pinv_solve2(&jxi, &(-js), PINV_CUT * scale) else {
                return lost(s, gamma);
            };
            loop {
                let last = h >= 1.0 - s;
                let step = if last { 1.0 - s } else { h };
                let s1 = if last { 1.0 } else { s + step };
                let pred = dxi * step;
                let (m, p) = seg(s1);
                let ok = p.is_finite()
                    && match Self::newton(&m, p, &gamma, &basis, pred) {
                        Some((xi, l)) => {
                            let scale1 = l.raw_scale();
                            let kappa1 = sym2_eigen(&l.restricted()).values;
                            let near = (xi - pred).norm() <= JUMP_RATIO * pred.norm() + JUMP_FLOOR;
                            let smooth = (0..2).all(|i| {
                                (kappa1[i] - kappa0[i]).abs() <= EIGEN_JUMP * scale.max(scale1)
                            });
                            if near && smooth {
                                gamma = l.gamma;
                                true
                            } else {
                                false
                            }
                        }
                        None => false,
                    };
                if ok {
                    s = s1;
                    h = (2.0 * step).min(1.0);
                    break;
                }
                h = step / 2.0;
                if h < SEGMENT_MIN_STEP {
                    return lost(s, gamma);
                }
            }
        }
        Follow {
            reached: Some(gamma),
            last: (1.0, gamma),
        }
    }

    /// The record and verdict at a node where the motion is at `gamma`.
    fn node(&self, x: f64, y: f64, gamma: Vector3<f64>) -> Result<Node, RouthError> {
        let (m, p) = self.member(x, y)?;
        let steady = SteadyMotion::at(&m, gamma, p, true).map_err(|e| at_xy(x, y, e))?;
        let report = classify_with(&m, &steady, &self.opts.classify).map_err(|e| at_xy(x, y, e))?;
        let disc = relative_discriminant(&m, &steady.gamma, p).map_err(|e| at_xy(x, y, e))?;
        Ok(Node {
            gamma: steady.gamma,
            report,
            disc,
        })
    }

    /// One row at ordinate `y`, from its first node.
    fn row(
        &self,
        xs: &[f64],
        y: f64,
        first: Option<Vector3<f64>>,
    ) -> Result<Vec<Option<Node>>, RouthError> {
        let mut out: Vec<Option<Node>> = vec![None; xs.len()];
        let Some(g0) = first else { return Ok(out) };
        out[0] = Some(self.node(xs[0], y, g0)?);
        for i in 1..xs.len() {
            self.member(xs[i], y)?;
            let prev = out[i - 1].as_ref().map(|n| n.gamma);
            let Some(g) = prev else { break };
            match self.follow((xs[i - 1], y), &g, (xs[i], y)).reached {
                Some(g) => out[i] = Some(self.node(xs[i], y, g)?),
                None => break,
            }
        }
        Ok(out)
    }

    // ---------------------------------------------------------------- the curves

    /// The test function at γ and `(x, y)`, and the picked eigenvector.
    fn tau(
        &self,
        test: &Test,
        gamma: &Vector3<f64>,
        x: f64,
        y: f64,
    ) -> Result<(f64, Vector3<f64>), RouthError> {
        let (m, p) = self.member(x, y)?;
        match test {
            Test::Zero(r) => {
                let l = Local::at(&m, gamma, p)?;
                let e = sym2_eigen(&l.restricted());
                let pb = tangent_basis(gamma);
                let v = [pb * e.vectors[0], pb * e.vectors[1]];
                let i = usize::from(v[1].dot(r).abs() > v[0].dot(r).abs());
                let scale = l.raw_scale();
                Ok((e.values[i] / scale, v[i]))
            }
            Test::Hopf => Ok((relative_discriminant(&m, gamma, p)?, Vector3::zeros())),
        }
    }

    /// The curve equations and their Jacobian at `(ξ, u, v)` in the chart around `base`.
    fn ext(
        &self,
        test: &Test,
        base: &Vector3<f64>,
        basis: &Matrix3x2<f64>,
        w: &Vector4<f64>,
    ) -> Result<Ext, RouthError> {
        let xi = Vector2::new(w[0], w[1]);
        let (x, y) = self.unscale(w[2], w[3]);
        let ce = chart_eval(&|s| (self.family)(s, y), base, basis, &xi, x, self.hx)?;
        let scale = ce.local.raw_scale();
        if !(scale > 0.0 && scale.is_finite()) {
            return Err(RouthError::NoConvergence {
                what: "boundary curve (zero local scale)",
                iterations: 0,
                residual: f64::NAN,
            });
        }
        let ty = |yy: f64| -> Result<Vector2<f64>, RouthError> {
            let (m, p) = self.member(x, yy)?;
            Ok(basis.transpose() * Local::at(&m, &ce.gamma, p)?.tangential())
        };
        let fy = (ty(y + self.hy)? - ty(y - self.hy)?) / (2.0 * self.hy);
        let (t0, pick) = self.tau(test, &ce.gamma, x, y)?;
        let mut dtau = [0.0; 4];
        for (k, d) in dtau.iter_mut().enumerate().take(2) {
            let mut e = Vector2::zeros();
            e[k] = XI_FD;
            let gp = chart(base, basis, &(xi + e)).0;
            let gm = chart(base, basis, &(xi - e)).0;
            *d = (self.tau(test, &gp, x, y)?.0 - self.tau(test, &gm, x, y)?.0) / (2.0 * XI_FD);
        }
        dtau[2] = (self.tau(test, &ce.gamma, x + self.hx, y)?.0
            - self.tau(test, &ce.gamma, x - self.hx, y)?.0)
            / (2.0 * self.hx)
            * self.lx();
        dtau[3] = (self.tau(test, &ce.gamma, x, y + self.hy)?.0
            - self.tau(test, &ce.gamma, x, y - self.hy)?.0)
            / (2.0 * self.hy)
            * self.ly();
        let j = &ce.jac;
        let (lx, ly) = (self.lx(), self.ly());
        let jac = Matrix3x4::new(
            j[(0, 0)] / scale,
            j[(0, 1)] / scale,
            j[(0, 2)] * lx / scale,
            fy.x * ly / scale,
            j[(1, 0)] / scale,
            j[(1, 1)] / scale,
            j[(1, 2)] * lx / scale,
            fy.y * ly / scale,
            dtau[0],
            dtau[1],
            dtau[2],
            dtau[3],
        );
        Ok(Ext {
            gamma: ce.gamma,
            g: Vector3::new(ce.f.x / scale, ce.f.y / scale, t0),
            jac,
            pick,
        })
    }

    /// Gauss–Newton with minimum-norm steps on the curve equations, plus the linear equation
    /// `a·w = b` if given, from `w0` in the chart around `base`.
    fn correct(
        &self,
        test: &Test,
        base: &Vector3<f64>,
        basis: &Matrix3x2<f64>,
        w0: Vector4<f64>,
        extra: Option<(Vector4<f64>, f64)>,
    ) -> Option<(Vector4<f64>, Ext, usize)> {
        let tol = self.opts.curve_tol;
        let mut w = w0;
        let mut last_step = f64::INFINITY;
        for it in 0..=CURVE_MAX_ITER {
            let e = self.ext(test, base, basis, &w).ok()?;
            let res = e.g.amax();
            let extra_res = extra.map_or(0.0, |(a, b)| a.dot(&w) - b);
            let converged = extra_res.abs() <= 1e-13
                && (res <= 0.01 * tol || (last_step <= 1e-13 && res <= tol));
            if converged {
                return Some((w, e, it));
            }
            if it == CURVE_MAX_ITER || !e.g.iter().all(|v| v.is_finite()) {
                break;
            }
            let d = match extra {
                Some((a, _)) => {
                    let mut m = Matrix4::zeros();
                    m.fixed_view_mut::<3, 4>(0, 0).copy_from(&e.jac);
                    m.set_row(3, &a.transpose());
                    if !m.iter().all(|v| v.is_finite()) {
                        return None;
                    }
                    let rhs = Vector4::new(-e.g.x, -e.g.y, -e.g.z, -extra_res);
                    let svd = m.svd(true, true);
                    let cut = PINV_CUT * svd.singular_values[0];
                    svd.solve(&rhs, cut).ok()?
                }
                None => {
                    if !e.jac.iter().all(|v| v.is_finite()) {
                        return None;
                    }
                    let svd = e.jac.svd(true, true);
                    let cut = PINV_CUT * svd.singular_values[0];
                    svd.solve(&(-e.g), cut).ok()?
                }
            };
            last_step = d.norm();
            if last_step.is_nan() || last_step > CURVE_MAX_CORRECTION {
                return None;
            }
            w += d;
        }
        None
    }

    /// The start of a curve on the edge from node `a` to node `b`: the test function and the
    /// point, projected onto the curve.
    fn locate(
        &self,
        pa: (f64, f64),
        na: &Node,
        pb: (f64, f64),
        nb: Option<&Node>,
        seed: Seed,
    ) -> Option<(Test, CurvePoint)> {
        let point = |s: f64| {
            if s == 1.0 {
                pb
            } else {
                (pa.0 + s * (pb.0 - pa.0), pa.1 + s * (pb.1 - pa.1))
            }
        };
        let (test, s0, g0) = match seed {
            Seed::Fold => {
                let f = self.follow(pa, &na.gamma, pb);
                if f.reached.is_some() {
                    return None;
                }
                let (s, g) = f.last;
                let (x, y) = point(s);
                let (m, p) = self.member(x, y).ok()?;
                let l = Local::at(&m, &g, p).ok()?;
                (Test::Zero(restricted_eigen(&l).1), s, g)
            }
            Seed::Zero(_) | Seed::Hopf => {
                let nb = nb?;
                let test = match seed {
                    Seed::Zero(k) => {
                        let (m, p) = self.member(pa.0, pa.1).ok()?;
                        let l = Local::at(&m, &na.gamma, p).ok()?;
                        let e = sym2_eigen(&l.restricted());
                        Test::Zero(tangent_basis(&na.gamma) * e.vectors[k])
                    }
                    _ => Test::Hopf,
                };
                let tau = |s: f64, g: &Vector3<f64>| {
                    let (x, y) = point(s);
                    self.tau(&test, g, x, y).ok().map(|t| t.0)
                };
                let (mut sa, mut ga, mut fa): (f64, _, _) = (0.0, na.gamma, tau(0.0, &na.gamma)?);
                let (mut sb, mut gb, mut fb) = (1.0, nb.gamma, tau(1.0, &nb.gamma)?);
                if fa * fb > 0.0 || (fa == 0.0 && fb == 0.0) {
                    return None;
                }
                // Illinois on τ(s) along the edge, γ(s) by continuation from the bracket.
                let (mut sc, mut gc) = if fa.abs() <= fb.abs() {
                    (sa, ga)
                } else {
                    (sb, gb)
                };
                for _ in 0..LOCATE_MAX_ITER {
                    if fa == 0.0 {
                        (sc, gc) = (sa, ga);
                        break;
                    }
                    if fb == 0.0 {
                        (sc, gc) = (sb, gb);
                        break;
                    }
                    if (sb - sa).abs() <= 1e-12 {
                        break;
                    }
                    let mut s = (sa * fb - sb * fa) / (fb - fa);
                    if !(s.is_finite() && s > sa.min(sb) && s < sa.max(sb)) {
                        s = 0.5 * (sa + sb);
                    }
                    let g = self
                        .follow(point(sb), &gb, point(s))
                        .reached
                        .or_else(|| self.follow(point(sa), &ga, point(s)).reached)?;
                    let f = tau(s, &g)?;
                    (sc, gc) = (s, g);
                    if f.abs() <= 1e-3 * self.opts.curve_tol {
                        break;
                    }
                    if f * fb < 0.0 {
                        (sa, ga, fa) = (sb, gb, fb);
                    } else {
                        fa /= 2.0;
                    }
                    (sb, gb, fb) = (s, g, f);
                }
                (test, sc, gc)
            }
        };
        let (x, y) = point(s0);
        let (u, v) = self.scale_xy(x, y);
        let basis = tangent_basis(&g0);
        let (w, e, _) = self.correct(&test, &g0, &basis, Vector4::new(0.0, 0.0, u, v), None)?;
        let test = match test {
            Test::Zero(_) => Test::Zero(e.pick),
            t => t,
        };
        Some((
            test,
            CurvePoint {
                gamma: e.gamma,
                u: w[2],
                v: w[3],
            },
        ))
    }

    /// Follows a curve from `start` along `t0` (in the chart around `start.gamma`): the points
    /// after the start, and whether it closed.
    fn trace(
        &self,
        test0: Test,
        start: CurvePoint,
        t0: Vector4<f64>,
        budget: usize,
    ) -> (Vec<(CurvePoint, f64)>, bool) {
        let h_max = self.opts.curve_step * std::f64::consts::SQRT_2;
        let h_min = CURVE_MIN_STEP * h_max;
        let mut test = test0;
        let mut pts = Vec::new();
        let mut cur = start;
        let mut t = t0;
        let mut h = h_max;
        let mut travelled = 0.0;
        let inside = |u: f64, v: f64| (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v);
        while pts.len() < budget {
            let basis = tangent_basis(&cur.gamma);
            let w = Vector4::new(0.0, 0.0, cur.u, cur.v);
            let pred = w + t * h;
            let accepted = self
                .correct(&test, &cur.gamma, &basis, pred, Some((t, t.dot(&pred))))
                .and_then(|(wc, e, it)| {
                    if (wc - pred).norm() > 0.5 * h {
                        return None;
                    }
                    let tn = null_tangent(&e.jac, &t)?;
                    if tn.dot(&t) < CURVE_MIN_COS {
                        return None;
                    }
                    Some((wc, e, it, tn))
                });
            let Some((wc, e, it, tn)) = accepted else {
                h /= 2.0;
                if h < h_min {
                    break;
                }
                continue;
            };
            if !inside(wc[2], wc[3]) {
                // Solve the exit point on the edge of the square crossed first.
                let mut best: Option<(f64, usize, f64)> = None;
                for (k, from, to) in [(2, w[2], wc[2]), (3, w[3], wc[3])] {
                    for bound in [0.0, 1.0] {
                        if (to - bound) * (from - bound) < 0.0 || (to != bound && from == bound) {
                            let lam = (bound - from) / (to - from);
                            if best.is_none_or(|b| lam < b.0) {
                                best = Some((lam, k, bound));
                            }
                        }
                    }
                }
                if let Some((lam, k, bound)) = best {
                    let guess = w + (wc - w) * lam;
                    let a = Vector4::ith(k, 1.0);
                    if let Some((we, ee, _)) =
                        self.correct(&test, &cur.gamma, &basis, guess, Some((a, bound)))
                    {
                        let (mut u, mut v) = (we[2], we[3]);
                        if k == 2 {
                            u = bound;
                        } else {
                            v = bound;
                        }
                        if inside(u, v) {
                            let point = CurvePoint {
                                gamma: ee.gamma,
                                u,
                                v,
                            };
                            pts.push((point, fold_indicator(&ee)));
                        }
                    }
                }
                return (pts, false);
            }
            // Accept; move the chart to the new point and carry the tangent over.
            let xi = Vector2::new(wc[0], wc[1]);
            let dg = chart(&cur.gamma, &basis, &xi).1;
            let nb = tangent_basis(&e.gamma);
            let txi = nb.transpose() * (dg * Vector2::new(tn[0], tn[1]));
            let tnew = Vector4::new(txi.x, txi.y, tn[2], tn[3]);
            t = tnew / tnew.norm();
            travelled += (wc - w).norm();
            cur = CurvePoint {
                gamma: e.gamma,
                u: wc[2],
                v: wc[3],
            };
            if let Test::Zero(_) = test {
                test = Test::Zero(e.pick);
            }
            pts.push((cur, fold_indicator(&e)));
            if it <= 3 {
                h = (1.5 * h).min(h_max);
            }
            let back = (cur.u - start.u).hypot(cur.v - start.v);
            if travelled > 4.0 * h_max && back < h && (cur.gamma - start.gamma).norm() < 0.1 {
                let beta = pts[0].1;
                pts.push((start, beta));
                return (pts, true);
            }
        }
        (pts, false)
    }

    /// All boundary curves from the grid.
    fn boundaries(&self, xs: &[f64], ys: &[f64], rows: &[Vec<Option<Node>>]) -> Vec<BoundaryCurve> {
        let (nx, ny) = (xs.len(), ys.len());
        let mut edges = Vec::new();
        for j in 0..ny {
            for i in 0..nx - 1 {
                edges.push(((i, j), (i + 1, j)));
            }
        }
        for i in 0..nx {
            for j in 0..ny - 1 {
                edges.push(((i, j), (i, j + 1)));
            }
        }
        // (kind is Hopf, scaled points, started at a fold).
        // (kind is Hopf, scaled points, number of points where the fold indicator is non-zero).
        let mut curves: Vec<Traced> = Vec::new();
        let budget = self.opts.max_curve_points;
        for (a, b) in edges {
            let na = rows[a.1][a.0].as_ref();
            let nb = rows[b.1][b.0].as_ref();
            let (pa, pb) = ((xs[a.0], ys[a.1]), (xs[b.0], ys[b.1]));
            let mut seeds: Vec<(f64, f64, &Node, Option<&Node>, Seed)> = Vec::new();
            match (na, nb) {
                (Some(n), None) => seeds.push((pa.0, pa.1, n, None, Seed::Fold)),
                (None, Some(n)) => seeds.push((pb.0, pb.1, n, None, Seed::Fold)),
                (Some(n1), Some(n2)) if n1.report.verdict != n2.report.verdict => {
                    let (k1, k2) = (
                        n1.report.restricted_hessian_eigenvalues,
                        n2.report.restricted_hessian_eigenvalues,
                    );
                    for k in 0..2 {
                        if k1[k] * k2[k] <= 0.0 && !(k1[k] == 0.0 && k2[k] == 0.0) {
                            seeds.push((pa.0, pa.1, n1, Some(n2), Seed::Zero(k)));
                        }
                    }
                    if k1[1] < 0.0 && k2[1] < 0.0 && n1.disc * n2.disc <= 0.0 {
                        seeds.push((pa.0, pa.1, n1, Some(n2), Seed::Hopf));
                    }
                }
                _ => {}
            }
            for (x0, y0, n1, n2, seed) in seeds {
                let to = if (x0, y0) == pa { pb } else { pa };
                let Some((test, start)) = self.locate((x0, y0), n1, to, n2, seed) else {
                    continue;
                };
                let hopf = test == Test::Hopf;
                let near = curves.iter().any(|(h, pts, _)| {
                    *h == hopf
                        && pts
                            .windows(2)
                            .any(|s| segment_distance((start.u, start.v), s[0], s[1]) <= DEDUP)
                        || *h == hopf
                            && pts.len() == 1
                            && (pts[0].0 - start.u).hypot(pts[0].1 - start.v) <= DEDUP
                });
                if near {
                    continue;
                }
                let basis = tangent_basis(&start.gamma);
                let w = Vector4::new(0.0, 0.0, start.u, start.v);
                let Ok(e) = self.ext(&test, &start.gamma, &basis, &w) else {
                    continue;
                };
                let r = Vector4::new(0.0, 0.0, -e.jac[(2, 3)], e.jac[(2, 2)]);
                let r = if r.norm() > 0.0 {
                    r
                } else {
                    Vector4::new(0.0, 0.0, 1.0, 0.0)
                };
                let Some(t0) = null_tangent(&e.jac, &r) else {
                    continue;
                };
                let (fwd, closed) = self.trace(test, start, t0, budget - 1);
                let back = if closed {
                    Vec::new()
                } else {
                    self.trace(test, start, -t0, budget - 1 - fwd.len()).0
                };
                let mut all: Vec<(CurvePoint, f64)> = back.into_iter().rev().collect();
                all.push((start, fold_indicator(&e)));
                all.extend(fwd);
                let folds = all.iter().filter(|p| p.1 > FOLD_INDICATOR).count();
                let pts = all.iter().map(|(p, _)| (p.u, p.v)).collect();
                curves.push((hopf, pts, folds));
            }
        }
        curves
            .into_iter()
            .map(|(hopf, pts, folds)| {
                let kind = if hopf {
                    EventKind::HamiltonianHopf
                } else if 2 * folds > pts.len() {
                    EventKind::Fold
                } else {
                    EventKind::BranchPoint
                };
                BoundaryCurve {
                    kind,
                    points: pts.iter().map(|&(u, v)| self.unscale(u, v)).collect(),
                }
            })
            .collect()
    }
}
