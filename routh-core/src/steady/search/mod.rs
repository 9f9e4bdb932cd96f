//! The global search behind [`steady_motions`](super::steady_motions): safeguarded Newton on the
//! sphere from a grid of starts, de-duplication, tracing of curves of critical points and the
//! Morse (Euler characteristic) self-check.
//!
//! Every test here is local: it compares tangential quantities at γ (the Riemannian gradient `g`
//! and the restricted form `K`, see [`Tangential`]) with each other, never with a scale taken over
//! the whole sphere, and never with the raw `∂R/∂γ`, `∂²R/∂γ²` except as a round-off floor.

use std::convert::Infallible;

use nalgebra::{Vector2, Vector3, Vector4};

use super::SearchOptions;
use crate::error::RouthError;
use crate::model::Routhian;
use crate::solve::locate::{locate, End};
use crate::solve::newton::{Jacobian, Linearised, Newton, Why};
use crate::sphere::local::Local;
use crate::sphere::{fibonacci_grid, tangent_basis, Tangential, NOISE, ROUND};
use crate::validate::check_kinetic;

mod curves;
use curves::{curve_axis, Curve};

/// Two values of `U_r` are equal when they differ by at most this much relative to the larger of
/// `|U_r|` and the raw scale (round-off in `U_r` is a few `ε` of the terms that form it).
const LEVEL_TOL: f64 = 1e-10;
/// Trial points of [`Search::polish_degenerate`]'s locator (bisection would take 80 to reach
/// adjacent floats from a bracket of `1e−2`).
const POLISH_BUDGET: usize = 80;
/// First step of the continuation along a curve of non-isolated critical points, in radians.
const TRACE_STEP: f64 = 0.05;
/// Number of continuation step lengths tried, each a quarter of the previous one (down to
/// `0.05 / 4⁸ ≈ 7.6e−7` rad, for circles next to a bifurcation).
const TRACE_LEVELS: usize = 9;
/// Largest number of continuation steps along one curve of critical points.
const MAX_TRACE_STEPS: usize = 1000;
/// Fewest vertices for a traced closed curve before the trace is redone with a shorter step.
const MIN_CLOSED_VERTICES: usize = 12;
/// Fewest vertices (besides the start) of a curve that does not close: fewer is a degenerate
/// isolated point.
const MIN_OPEN_VERTICES: usize = 4;
/// Two converged points are the same when they are closer than this multiple of the sum of their
/// estimated distances to the exact critical point (the Newton step, or the round-off radius).
/// Newton converges linearly with ratio `(n−2)/(n−1)` to a critical point of order `n`, whose
/// distance is then `(n−1)` times the last step: 8 covers `n ≤ 9`.
const MERGE_FACTOR: f64 = 8.0;
/// Degenerate points on one level within this distance (radians) are one critical point: about
/// 64√ε, beyond the round-off plateau of a higher-order point (see `same_point`). (1e−4 merged
/// the points of a circle of radius 2.4e−4 round a pole: tests/trust.rs.)
const FLAT_RADIUS: f64 = 1e-6;
/// An iterate of a grid start joins a known non-degenerate critical point `p` within this distance
/// (radians) when its Newton step lands within [`GRID_CAPTURE`] of its distance to `p`
/// (quadratic convergence towards `p` is under way).
const CAPTURE_RADIUS: f64 = 0.5;
/// Contraction ratio for the early capture of a grid start.
const GRID_CAPTURE: f64 = 0.25;
/// Contraction ratio for the early capture of a probe start (probes look for critical points
/// next to known ones, so they are captured only on much stronger evidence).
const PROBE_CAPTURE: f64 = 1e-3;
/// Distance (radians) of the neighbours tested to tell a two-dimensional critical set from a
/// higher-order isolated critical point.
const PLANAR_PROBE: f64 = 1e-2;
/// Largest number of points (critical points and curve vertices) probed around by
/// [`Found::probes`].
const MAX_PROBE_CENTRES: usize = 64;
/// Samples on the small circle around a degenerate isolated critical point for its index.
const INDEX_SAMPLES: usize = 48;
/// Largest radius of that circle (radians).
const INDEX_RADIUS: f64 = 1e-2;

/// What the global search found.
pub(super) struct Outcome {
    /// Every critical point found, with whether it is isolated (curves and planar sets by one
    /// representative).
    pub points: Vec<(Vector3<f64>, bool)>,
    /// The sum of the indices of the critical points (curves count 0), when it could be computed.
    pub euler: Option<i64>,
    /// Whether the count is reconciled with χ(S²) = 2 (or the whole sphere is critical).
    pub consistent: bool,
}

/// The global search of [`steady_motion_search`](super::steady_motion_search).
pub(super) fn global<M: Routhian>(
    model: &M,
    p_psi: f64,
    opts: &SearchOptions,
) -> Result<Outcome, RouthError> {
    let grid = fibonacci_grid(opts.starts);
    for g in grid.iter() {
        check_kinetic(model, g)?;
    }
    let search = Search {
        model,
        p_psi,
        max_iterations: opts.max_iterations,
        gradient_tol: opts.gradient_tol,
        zero_rel: opts.zero_eigenvalue_tol,
    };

    let mut found = Found::default();
    for start in grid.iter() {
        found.add(&search, start, GRID_CAPTURE);
    }
    // Critical points closer together than the grid spacing (next to a bifurcation, e.g. the
    // sleeping top inside a small circle of tilted precessions) share one start: probe around
    // every point found.
    let spacing = (4.0 * std::f64::consts::PI / opts.starts as f64).sqrt();
    for start in found.probes(spacing) {
        found.add(&search, &start, PROBE_CAPTURE);
    }
    // Morse check: the indices of the isolated critical points must sum to the Euler
    // characteristic of the sphere, χ = 2 (closed curves contribute 0). Otherwise something was
    // missed: search again on a grid four times finer.
    let mut euler = found.euler_characteristic(&search);
    if euler != Some(2) && !found.is_empty() && !found.planar_only() {
        let fine = fibonacci_grid(4 * opts.starts);
        for start in fine.iter() {
            found.add(&search, start, GRID_CAPTURE);
        }
        for start in found.probes(0.5 * spacing) {
            found.add(&search, &start, PROBE_CAPTURE);
        }
        euler = found.euler_characteristic(&search);
    }
    let consistent = euler == Some(2) || found.planar_only();
    let Found {
        isolated,
        curves,
        planar,
        best_residual,
        ..
    } = found;
    if isolated.is_empty() && curves.is_empty() && planar.is_empty() {
        return Err(RouthError::NoConvergence {
            what: "steady_motions (Newton on the sphere from every start)",
            iterations: opts.max_iterations,
            residual: best_residual,
        });
    }
    let mut points: Vec<(Vector3<f64>, bool)> = isolated.iter().map(|l| (l.gamma, true)).collect();
    points.extend(
        curves
            .iter()
            .map(|c| &c.start)
            .chain(planar.iter())
            .map(|l| (l.gamma, false)),
    );
    Ok(Outcome {
        points,
        euler,
        consistent,
    })
}

/// The critical point reached by Newton on the sphere from the unit vector `g0`, with whether it
/// is isolated, for [`steady_motion_near`](super::steady_motion_near).
pub(super) fn near<M: Routhian>(
    model: &M,
    g0: &Vector3<f64>,
    p_psi: f64,
    opts: &SearchOptions,
) -> Result<(Vector3<f64>, bool), RouthError> {
    let non_finite = || RouthError::NonFiniteModel {
        what: "amended potential or its derivatives",
        gamma: [g0.x, g0.y, g0.z],
    };
    let search = Search {
        model,
        p_psi,
        max_iterations: 2 * opts.max_iterations,
        gradient_tol: opts.gradient_tol,
        zero_rel: opts.zero_eigenvalue_tol,
    };
    let loc = match search.refine(g0, None).ok_or_else(non_finite)? {
        Refined::Converged(loc) => loc,
        Refined::Stalled(loc) => {
            return Err(RouthError::NoConvergence {
                what: "steady_motion_near (Newton on the sphere)",
                iterations: search.max_iterations,
                residual: loc.residual(),
            })
        }
        // Without a list of known points the iteration never reports a capture.
        Refined::Captured => {
            return Err(RouthError::NoConvergence {
                what: "steady_motion_near (Newton on the sphere)",
                iterations: 0,
                residual: f64::NAN,
            })
        }
    };
    let isolated = match loc.zeros() {
        0 => true,
        1 => search.trace(&loc).is_none(),
        _ => !search.is_planar(&loc),
    };
    Ok((loc.gamma, isolated))
}

/// What the search keeps of one evaluation of the model ([`Local`]) at a unit γ: the amended
/// potential and its Riemannian derivatives there ([`Tangential`]). The families' equations keep
/// the derivatives in ℝ³ instead (their chart is not `tangent_basis(γ)`).
#[derive(Debug, Clone, Copy)]
struct Riemannian {
    gamma: Vector3<f64>,
    t: Tangential,
    u_r: f64,
}

impl Riemannian {
    /// `None` when the model returns non-finite values at γ.
    #[inline(always)]
    fn at<M: Routhian>(
        model: &M,
        gamma: &Vector3<f64>,
        p_psi: f64,
        zero_rel: f64,
    ) -> Option<Riemannian> {
        // The basis depends on γ alone: formed first, it is ready when the model returns.
        let basis = tangent_basis(gamma);
        let l = Local::evaluate(model, gamma, p_psi);
        if !l.is_finite() {
            return None;
        }
        let t = l.tangential_quantities(basis, zero_rel);
        if !(t.knorm.is_finite() && t.raw.is_finite()) {
            return None;
        }
        Some(Riemannian {
            gamma: *gamma,
            t,
            u_r: l.u_r,
        })
    }

    /// The equations of the search for the corrector: the Riemannian gradient `g` with its
    /// Jacobian `K` (62)–(63) by its eigen-decomposition, the residual being the Newton step as a
    /// distance on the sphere (`|K⁻¹g|`, see [`Tangential::step_len`]).
    #[inline(always)]
    fn linearised(&self) -> Linearised {
        Linearised {
            rows: Vector4::new(self.t.grad.x, self.t.grad.y, 0.0, 0.0),
            jac: Jacobian::Symmetric2 {
                values: self.t.values,
                vectors: self.t.vectors,
            },
            noise: self.t.grad_floor(),
            zero: self.t.zero_tol,
            residual: self.step_len(),
            floor: 0.0,
        }
    }

    /// Number of zero eigenvalues of `K` (relative to `‖K‖` with a round-off floor).
    fn zeros(&self) -> usize {
        self.t.zero_count()
    }

    fn degenerate(&self) -> bool {
        self.zeros() > 0
    }

    /// The Newton step, as a distance on the sphere; 0 when `g` is within round-off.
    fn residual(&self) -> f64 {
        self.t.residual
    }

    /// The length of the Newton step itself, also when `g` is within round-off (the distance to
    /// the critical point if `g` is accurate).
    fn step_len(&self) -> f64 {
        self.t.step_len
    }

    /// The estimated distance to the exact critical point: the Newton step, or the round-off in
    /// `g` divided by the curvature, whichever is larger.
    fn radius(&self) -> f64 {
        let curvature = if self.degenerate() {
            self.t.knorm.max(ROUND * self.t.raw)
        } else {
            self.t.values[0].abs().min(self.t.values[1].abs())
        };
        let noise = NOISE * self.t.raw_grad;
        let r = if noise > 0.0 { noise / curvature } else { 0.0 };
        self.step_len().max(r)
    }

    /// The unit tangent vector (in ℝ³) along the eigenvector of the eigenvalue of smaller
    /// magnitude.
    fn null_direction(&self) -> Vector3<f64> {
        let i = if self.t.values[0].abs() <= self.t.values[1].abs() {
            0
        } else {
            1
        };
        self.t.basis * self.t.vectors[i]
    }

    /// The Riemannian gradient of `U_r` as a tangent vector of ℝ³.
    fn grad3(&self) -> Vector3<f64> {
        self.t.basis * self.t.grad
    }
}

fn same_level(a: &Riemannian, b: &Riemannian) -> bool {
    let s = a.u_r.abs().max(b.u_r.abs()).max(a.t.raw).max(b.t.raw);
    (a.u_r - b.u_r).abs() <= LEVEL_TOL * s
}

/// Whether two converged points are the same critical point: closer than [`MERGE_FACTOR`] times
/// the sum of their estimated distances to it.
///
/// Two degenerate points on the same level closer than [`FLAT_RADIUS`] are also one: near a
/// higher-order point the model is flat to round-off on a cap of about `√ε` (U = (1 + γ₃)² at
/// −e₃: `1 + γ₃ = θ²/2` is 0 in floating point for θ below 1e−8), every point of it is a zero of
/// the computed gradient with a Newton step of 0, and copies landing anywhere on the cap would
/// otherwise each count as a critical point.
fn same_point(a: &Riemannian, b: &Riemannian) -> bool {
    let d = (a.gamma - b.gamma).norm();
    d <= MERGE_FACTOR * (a.radius() + b.radius()) + 8.0 * f64::EPSILON
        || (d <= FLAT_RADIUS && a.degenerate() && b.degenerate() && same_level(a, b))
}

/// The critical points found so far by [`global`].
struct Found {
    isolated: Vec<Riemannian>,
    /// The non-degenerate points of `isolated` (their γ): the targets of early capture.
    anchors: Vec<Vector3<f64>>,
    curves: Vec<Curve>,
    planar: Vec<Riemannian>,
    best_residual: f64,
}

impl Default for Found {
    fn default() -> Self {
        Found {
            isolated: Vec::new(),
            anchors: Vec::new(),
            curves: Vec::new(),
            planar: Vec::new(),
            best_residual: f64::INFINITY,
        }
    }
}

impl Found {
    fn is_empty(&self) -> bool {
        self.isolated.is_empty() && self.curves.is_empty() && self.planar.is_empty()
    }

    /// Only two-dimensional critical sets (`U_r` constant on the sphere).
    fn planar_only(&self) -> bool {
        !self.planar.is_empty() && self.isolated.is_empty() && self.curves.is_empty()
    }

    /// Runs the Newton iteration from `start` and records a new critical point, if any.
    fn add<M: Routhian>(&mut self, search: &Search<'_, M>, start: &Vector3<f64>, capture: f64) {
        let loc = match search.refine(start, Some((&self.anchors, capture))) {
            Some(Refined::Converged(loc)) => loc,
            Some(Refined::Stalled(loc)) => {
                self.best_residual = self.best_residual.min(loc.residual());
                return;
            }
            Some(Refined::Captured) | None => return,
        };
        self.best_residual = self.best_residual.min(loc.residual());
        if self.curves.iter().any(|c| c.contains(&loc)) {
            return;
        }
        let loc = if loc.zeros() == 1 {
            search.polish_degenerate(loc)
        } else {
            loc
        };
        if self.isolated.iter().any(|q| same_point(q, &loc))
            || self.curves.iter().any(|c| c.contains(&loc))
        {
            return;
        }
        match loc.zeros() {
            0 => {
                self.anchors.push(loc.gamma);
                self.isolated.push(loc);
            }
            1 => match search.trace(&loc) {
                Some(curve) => self.curves.push(curve),
                None => self.isolated.push(loc),
            },
            _ => {
                // Only a point proven to lie in a two-dimensional critical set joins one: being
                // on the level of a known set is not enough (a higher-order isolated point, or a
                // point of the boundary of a flat region, can share its level).
                if search.is_planar(&loc) {
                    // The whole neighbourhood is critical (e.g. U_r constant): one representative
                    // per level.
                    if !self.planar.iter().any(|q| same_level(q, &loc)) {
                        self.planar.push(loc);
                    }
                } else {
                    // A higher-order isolated critical point (e.g. x⁴ + y⁴ at its minimum).
                    self.isolated.push(loc);
                }
            }
        }
    }

    /// Starting points on rings of radii `{1/2, 1/5, 1/20} · spacing` around every isolated
    /// point and around up to 16 vertices of every curve, and the axes of closed curves.
    fn probes(&self, spacing: f64) -> Vec<Vector3<f64>> {
        let mut centres: Vec<Vector3<f64>> = self.isolated.iter().map(|l| l.gamma).collect();
        let mut out = Vec::new();
        for c in &self.curves {
            let stride = c.vertices.len().div_ceil(16).max(1);
            centres.extend(c.vertices.iter().step_by(stride).copied());
            // The axis of a closed curve: for a circle of latitude of a symmetric body it is the
            // pole, a critical point by symmetry that a small circle around it hides from the
            // grid. The normal of the plane of the vertices is exact for a circle however
            // unevenly its vertices are spread.
            if c.closed {
                out.extend(curve_axis(&c.vertices).into_iter().flat_map(|n| [n, -n]));
            }
        }
        // At most MAX_PROBE_CENTRES centres. Probes resolve a few critical points hidden next to
        // known ones; far more points than that means a degenerate landscape (e.g. a curve of
        // critical points not recognised as one, every start landing on a different point of it),
        // where probing every point multiplied the points by 19 and the quadratic de-duplication
        // took seconds to minutes (found by tests/runtime_properties.rs).
        centres.truncate(MAX_PROBE_CENTRES);
        for c in centres {
            let basis = tangent_basis(&c);
            for (ring, r) in [0.5, 0.2, 0.05].into_iter().enumerate() {
                for k in 0..6 {
                    let angle = std::f64::consts::PI * (k as f64 / 3.0 + ring as f64 / 9.0);
                    let t = basis * Vector2::new(angle.cos(), angle.sin());
                    out.push((c * (r * spacing).cos() + t * (r * spacing).sin()).normalize());
                }
            }
        }
        out
    }

    /// The sum of the indices of the isolated critical points (`+1` at a minimum or maximum,
    /// `−1` at a saddle; for a degenerate point the winding number of the gradient on a small
    /// circle around it), closed curves counting 0 (Morse–Bott). `None` when a two-dimensional
    /// critical set was found, a curve is not closed, or an index could not be computed.
    fn euler_characteristic<M: Routhian>(&self, search: &Search<'_, M>) -> Option<i64> {
        if !self.planar.is_empty() || self.curves.iter().any(|c| !c.closed) {
            return None;
        }
        let mut chi = 0;
        for (i, loc) in self.isolated.iter().enumerate() {
            chi += match loc.zeros() {
                0 => {
                    if (loc.t.values[0] < 0.0) != (loc.t.values[1] < 0.0) {
                        -1
                    } else {
                        1
                    }
                }
                _ => {
                    // The circle must enclose no other critical point.
                    let mut nearest = INDEX_RADIUS * 4.0;
                    for (j, q) in self.isolated.iter().enumerate() {
                        if j != i {
                            nearest = nearest.min((q.gamma - loc.gamma).norm());
                        }
                    }
                    for c in &self.curves {
                        for v in &c.vertices {
                            nearest = nearest.min((v - loc.gamma).norm());
                        }
                    }
                    search.index(loc, 0.25 * nearest)?
                }
            };
        }
        Some(chi)
    }
}

/// The end of one Newton iteration.
enum Refined {
    /// A critical point.
    Converged(Riemannian),
    /// The iteration joined a known critical point (early de-duplication of a basin).
    Captured,
    /// The iteration stopped at a point that is not critical (budget spent, or a local minimum
    /// of `|g|`).
    Stalled(Riemannian),
}

struct Search<'a, M> {
    model: &'a M,
    p_psi: f64,
    max_iterations: usize,
    gradient_tol: f64,
    zero_rel: f64,
}

impl<M: Routhian> Search<'_, M> {
    fn local(&self, gamma: &Vector3<f64>) -> Option<Riemannian> {
        Riemannian::at(self.model, gamma, self.p_psi, self.zero_rel)
    }

    /// Safeguarded Newton (Levenberg–Marquardt, [`Newton::search`]) on the sphere from `gamma0`;
    /// `None` if the model is not finite at `gamma0`. With `capture = Some((known, ratio))`
    /// (`known` the γ of the known non-degenerate critical points) the iteration stops as soon as
    /// its Newton step heads into one of them (lands within `ratio` times its distance to it). No
    /// allocation.
    fn refine(
        &self,
        gamma0: &Vector3<f64>,
        capture: Option<(&[Vector3<f64>], f64)>,
    ) -> Option<Refined> {
        let start = self.local(gamma0)?;
        // Each step is taken in the tangent plane at the current point, then retracted onto the
        // sphere: the chart moves with the iterate.
        let next = |cur: &Riemannian, _: &Vector4<f64>, d: &Vector4<f64>| {
            let gamma = (cur.gamma + cur.t.basis * Vector2::new(d[0], d[1])).normalize();
            Ok::<_, Infallible>(self.local(&gamma))
        };
        let joined = |cur: &Riemannian| {
            capture.is_some_and(|(known, ratio)| {
                let target = cur.gamma + cur.t.basis * cur.t.step;
                known.iter().any(|p| {
                    let dp = (cur.gamma - p).norm();
                    dp <= CAPTURE_RADIUS && (target - p).norm() <= ratio * dp
                })
            })
        };
        let newton = Newton::search(self.max_iterations, self.gradient_tol);
        let out = match newton.solve(
            Vector4::zeros(),
            &[],
            start,
            Riemannian::linearised,
            next,
            joined,
        ) {
            Ok(out) => out,
            Err(never) => match never {},
        };
        let cur = match out {
            Ok(solved) => solved.point,
            Err(stop) if stop.why == Why::Interrupted => return Some(Refined::Captured),
            Err(stop) => stop.last,
        };
        Some(if cur.residual() <= self.gradient_tol {
            Refined::Converged(cur)
        } else {
            Refined::Stalled(cur)
        })
    }

    /// A critical point with one zero eigenvalue of `K`, placed where the gradient along the
    /// kernel changes sign. Newton's method converges only linearly there and stops at the
    /// tolerance on its step, which at a point of order `n` (a pitchfork point: `n = 3`, the
    /// gradient cubic along the kernel) is `n − 1` times farther from the point than the step
    /// (6e−5 rad at the Kovalevskaya top's pitchfork). Here: the sign change of `φ(t) = g·v` along
    /// the kernel direction `v` is bracketed within `±r` (`r` from `1e−8` doubling to `1e−2`),
    /// each trial point corrected across the kernel by Newton steps along the other eigenvector,
    /// and located by the crate's event locator ([`crate::solve::locate`]) to round-off in `t`, which
    /// leaves it at round-off in `φ`: to about `(ε·s_raw/|φ⁽ⁿ⁾|)^{1/n}` (`~1e−5` rad for a
    /// cubic gradient). Unchanged when no sign change is bracketed (a curve of critical points,
    /// where `φ ≡ 0`, or an even order).
    fn polish_degenerate(&self, loc: Riemannian) -> Riemannian {
        let v = loc.null_direction();
        let i_w = if loc.t.values[0].abs() <= loc.t.values[1].abs() {
            1
        } else {
            0
        };
        let w = loc.t.basis * loc.t.vectors[i_w];
        let kappa = loc.t.values[i_w];
        if kappa == 0.0 || !kappa.is_finite() {
            return loc;
        }
        // The point at offset t along v, corrected across it, and φ there.
        let at = |t: f64| -> Option<(Riemannian, f64)> {
            let mut g = (loc.gamma + t * v).normalize();
            let mut l = self.local(&g)?;
            for _ in 0..4 {
                let gw = l.grad3().dot(&w);
                g = (g - (gw / kappa) * w).normalize();
                l = self.local(&g)?;
            }
            let phi = l.grad3().dot(&v);
            Some((l, phi))
        };
        let Some((_, phi0)) = at(0.0) else {
            return loc;
        };
        if phi0 == 0.0 {
            return loc;
        }
        let mut r = 1e-8;
        let mut bracket = None;
        while r <= 1e-2 {
            let (Some((la, pa)), Some((lb, pb))) = (at(-r), at(r)) else {
                return loc;
            };
            // Signs of φ within round-off (a curve of critical points, φ ≡ 0) are no bracket.
            let noise = 4.0 * la.t.grad_floor().max(lb.t.grad_floor());
            if pa.abs() <= noise || pb.abs() <= noise {
                r *= 2.0;
                continue;
            }
            if pa * pb < 0.0 {
                bracket = Some(((-r, pa, la), (r, pb, lb)));
                break;
            }
            r *= 2.0;
        }
        let Some(((a, pa, la), (b, pb, lb))) = bracket else {
            return loc;
        };
        // Located to round-off in `t` by the bracket's width alone: at a zero of order `n > 1`
        // the secant's estimate of the distance is far too small.
        let end = End::new;
        let found = locate(
            end(a, pa, la),
            end(b, pb, lb),
            POLISH_BUDGET,
            |t, _, _| Ok::<_, ()>(at(t).map(|(l, p)| (p, l))),
            |lo, hi| hi.at - lo.at <= 4.0 * f64::EPSILON * lo.at.abs().max(hi.at.abs()),
        );
        match found {
            Ok(f) => {
                let l = f.best.point;
                if l.degenerate() && l.residual() <= self.gradient_tol.max(loc.residual()) {
                    l
                } else {
                    loc
                }
            }
            Err(()) => loc,
        }
    }

    /// Whether the degenerate critical point `loc` (both eigenvalues of `K` zero) lies in a
    /// two-dimensional set of critical points: the gradient vanishes within round-off at four
    /// neighbours at [`PLANAR_PROBE`]. At a higher-order isolated point (x⁴ + y⁴) it does not.
    fn is_planar(&self, loc: &Riemannian) -> bool {
        (0..4).all(|k| {
            let a = std::f64::consts::FRAC_PI_2 * k as f64 + 0.3;
            let t = loc.t.basis * Vector2::new(a.cos(), a.sin());
            let g = (loc.gamma * PLANAR_PROBE.cos() + t * PLANAR_PROBE.sin()).normalize();
            self.local(&g)
                .is_some_and(|n| n.t.grad_norm <= n.t.grad_floor() && same_level(&n, loc))
        })
    }
}
