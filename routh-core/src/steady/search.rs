//! The global search behind [`steady_motions`](super::steady_motions): safeguarded Newton on the
//! sphere from a grid of starts, de-duplication, tracing of curves of critical points and the
//! Morse (Euler characteristic) self-check.

use nalgebra::{Matrix2, Matrix3, Matrix3x2, SymmetricEigen, Vector2, Vector3};

use super::SearchOptions;
use crate::error::RouthError;
use crate::model::Routhian;
use crate::sphere::{fibonacci_sphere, local_scale, restricted_hessian, sym2_eigen, tangent_basis};
use crate::validate::check_kinetic;

const LEVEL_TOL: f64 = 1e-9;
/// Distance (in radians, on the unit sphere) under which two non-degenerate critical points are
/// the same.
const DUPLICATE_DISTANCE: f64 = 1e-6;
/// Distance under which two degenerate isolated critical points with the same `U_r` are the same
/// (Newton converges only linearly to them).
const DEGENERATE_DUPLICATE_DISTANCE: f64 = 2e-2;
/// Longest step of the Newton iteration on the sphere, in radians.
const MAX_STEP: f64 = 0.5;
/// Step of the continuation along a curve of non-isolated critical points, in radians.
const TRACE_STEP: f64 = 0.05;

/// Largest number of continuation steps along one curve of critical points.
const MAX_TRACE_STEPS: usize = 1000;
/// Fewest vertices for a traced closed curve before the trace is redone with a shorter step.
const MIN_CLOSED_VERTICES: usize = 12;
/// Largest number of Levenberg–Marquardt retries (growing λ) within one iteration.
const MAX_LM_RETRIES: usize = 14;
/// Gradient level (relative) at which the iteration stops improving.
const STOP_TOL: f64 = 1e-15;

/// The global search of [`steady_motions_with`](super::steady_motions_with): every critical
/// point found, with whether it is isolated (curves and planar sets by one representative).
pub(super) fn global<M: Routhian>(
    model: &M,
    p_psi: f64,
    opts: &SearchOptions,
) -> Result<Vec<(Vector3<f64>, bool)>, RouthError> {
    let grid = fibonacci_sphere(opts.starts);
    let mut scale = 0.0f64;
    for g in &grid {
        check_kinetic(model, g)?;
        if let Some(loc) = Local::at(model, g, p_psi, opts.zero_eigenvalue_tol) {
            scale = scale.max(loc.scale);
        }
    }
    let search = Search {
        model,
        p_psi,
        scale,
        max_iterations: opts.max_iterations,
        gradient_tol: opts.gradient_tol,
        zero_rel: opts.zero_eigenvalue_tol,
    };

    let mut found = Found::default();
    for start in &grid {
        found.add(&search, start);
    }
    // Critical points closer together than the grid spacing (next to a bifurcation, e.g. the
    // sleeping top inside a small circle of tilted precessions) share one start: probe around
    // every point found.
    let spacing = (4.0 * std::f64::consts::PI / opts.starts as f64).sqrt();
    for start in found.probes(spacing) {
        found.add(&search, &start);
    }
    // Morse check: non-degenerate isolated critical points alone must sum their indices to the
    // Euler characteristic of the sphere, χ = 2 (curves contribute 0). Otherwise something was
    // missed: search again on a grid four times finer.
    if found.euler_characteristic() != Some(2) && !found.is_empty() {
        let fine = fibonacci_sphere(4 * opts.starts);
        for start in &fine {
            found.add(&search, start);
        }
        for start in found.probes(0.5 * spacing) {
            found.add(&search, &start);
        }
    }
    let Found {
        isolated,
        curves,
        planar,
        best_residual,
    } = found;
    if isolated.is_empty() && curves.is_empty() && planar.is_empty() {
        return Err(RouthError::NoConvergence {
            what: "steady_motions (Newton on the sphere from every start)",
            iterations: opts.max_iterations,
            residual: best_residual,
        });
    }
    let mut out: Vec<(Vector3<f64>, bool)> = isolated.iter().map(|l| (l.gamma, true)).collect();
    out.extend(
        curves
            .iter()
            .map(|c| &c.start)
            .chain(planar.iter())
            .map(|l| (l.gamma, false)),
    );
    Ok(out)
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
    let start = Local::at(model, g0, p_psi, opts.zero_eigenvalue_tol).ok_or_else(non_finite)?;
    let search = Search {
        model,
        p_psi,
        scale: start.scale,
        max_iterations: 2 * opts.max_iterations,
        gradient_tol: opts.gradient_tol,
        zero_rel: opts.zero_eigenvalue_tol,
    };
    let (loc, converged) = search.refine(g0).ok_or_else(non_finite)?;
    if !converged {
        return Err(RouthError::NoConvergence {
            what: "steady_motion_near (Newton on the sphere)",
            iterations: search.max_iterations,
            residual: loc.grad.norm() / search.tol_scale(&loc),
        });
    }
    let eigs = sym2_eigen(&loc.hess);
    let zero = |k: f64| k.abs() <= loc.zero_rel * loc.scale;
    let isolated = if zero(eigs.values[0]) && zero(eigs.values[1]) {
        false
    } else if zero(eigs.values[0]) || zero(eigs.values[1]) {
        search.trace(&loc).is_none()
    } else {
        true
    };
    Ok((loc.gamma, isolated))
}

/// The amended potential and its Riemannian derivatives at one unit γ.
#[derive(Debug, Clone)]
struct Local {
    gamma: Vector3<f64>,
    basis: Matrix3x2<f64>,
    /// Riemannian gradient of `U_r` in the basis.
    grad: Vector2<f64>,
    /// Riemannian Hessian of `U_r` in the basis (62)–(63).
    hess: Matrix2<f64>,
    u_r: f64,
    scale: f64,
    /// Relative tolerance for a zero eigenvalue ([`SearchOptions::zero_eigenvalue_tol`]).
    zero_rel: f64,
}

impl Local {
    /// `None` when the model returns non-finite values at γ.
    fn at<M: Routhian>(
        model: &M,
        gamma: &Vector3<f64>,
        p_psi: f64,
        zero_rel: f64,
    ) -> Option<Local> {
        let b = model.bundle(&Vector3::zeros(), gamma, p_psi);
        let finite = b.routhian.is_finite()
            && b.dr_dgamma.iter().all(|v| v.is_finite())
            && b.d2r_dgamma2.iter().all(|v| v.is_finite());
        if !finite {
            return None;
        }
        let basis = tangent_basis(gamma);
        let mu = b.dr_dgamma.dot(gamma);
        Some(Local {
            gamma: *gamma,
            basis,
            grad: -(basis.transpose() * b.dr_dgamma),
            hess: restricted_hessian(&basis, mu, &b.d2r_dgamma2),
            u_r: -b.routhian,
            scale: local_scale(&b.dr_dgamma, &b.d2r_dgamma2),
            zero_rel,
        })
    }

    /// The unit tangent vector (in ℝ³) along the eigenvector of the eigenvalue of smaller
    /// magnitude.
    fn null_direction(&self) -> Vector3<f64> {
        let e = sym2_eigen(&self.hess);
        let i = if e.values[0].abs() <= e.values[1].abs() {
            0
        } else {
            1
        };
        self.basis * e.vectors[i]
    }
}

fn same_level(a: &Local, b: &Local) -> bool {
    let s = a.scale.max(b.scale).max(a.u_r.abs()).max(b.u_r.abs());
    (a.u_r - b.u_r).abs() <= LEVEL_TOL * s
}

fn is_degenerate(loc: &Local) -> bool {
    let e = sym2_eigen(&loc.hess);
    e.values.iter().any(|k| k.abs() <= loc.zero_rel * loc.scale)
}

fn same_point(a: &Local, b: &Local) -> bool {
    let d = (a.gamma - b.gamma).norm();
    d <= DUPLICATE_DISTANCE
        || (d <= DEGENERATE_DUPLICATE_DISTANCE
            && (is_degenerate(a) || is_degenerate(b))
            && same_level(a, b))
}

/// The critical points found so far by [`steady_motions_with`].
struct Found {
    isolated: Vec<Local>,
    curves: Vec<Curve>,
    planar: Vec<Local>,
    best_residual: f64,
}

impl Default for Found {
    fn default() -> Self {
        Found {
            isolated: Vec::new(),
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

    /// Runs the Newton iteration from `start` and records a new critical point, if any.
    fn add<M: Routhian>(&mut self, search: &Search<'_, M>, start: &Vector3<f64>) {
        let Some((loc, converged)) = search.refine(start) else {
            return;
        };
        self.best_residual = self
            .best_residual
            .min(loc.grad.norm() / search.tol_scale(&loc));
        if !converged
            || self.isolated.iter().any(|q| same_point(q, &loc))
            || self.curves.iter().any(|c| c.contains(&loc))
            || self.planar.iter().any(|q| same_level(q, &loc))
        {
            return;
        }
        let eigs = sym2_eigen(&loc.hess);
        let zero = |k: f64| k.abs() <= loc.zero_rel * loc.scale;
        if zero(eigs.values[0]) && zero(eigs.values[1]) {
            // The whole neighbourhood is critical (e.g. U_r constant): one representative per
            // level.
            self.planar.push(loc);
        } else if zero(eigs.values[0]) || zero(eigs.values[1]) {
            match search.trace(&loc) {
                Some(curve) => self.curves.push(curve),
                None => self.isolated.push(loc),
            }
        } else {
            self.isolated.push(loc);
        }
    }

    /// Starting points on rings of radii `{1/2, 1/5, 1/20} · spacing` around every isolated
    /// point and around up to 16 vertices of every curve.
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

    /// `#minima − #saddles + #maxima` over the isolated critical points, or `None` when one of
    /// them is degenerate or a two-dimensional critical set was found (indices unknown).
    fn euler_characteristic(&self) -> Option<i64> {
        if !self.planar.is_empty() {
            return None;
        }
        let mut chi = 0;
        for loc in &self.isolated {
            let e = sym2_eigen(&loc.hess).values;
            let tol = loc.zero_rel * loc.scale;
            if e.iter().any(|k| k.abs() <= tol) {
                return None;
            }
            chi += if (e[0] < 0.0) != (e[1] < 0.0) { -1 } else { 1 };
        }
        Some(chi)
    }
}

/// The unit normal of the least-squares plane through `vertices` (the axis of a circle on the
/// sphere), if there are at least three.
fn curve_axis(vertices: &[Vector3<f64>]) -> Option<Vector3<f64>> {
    if vertices.len() < 3 {
        return None;
    }
    let mean: Vector3<f64> = vertices.iter().sum::<Vector3<f64>>() / vertices.len() as f64;
    let cov: Matrix3<f64> = vertices
        .iter()
        .map(|v| (v - mean) * (v - mean).transpose())
        .sum();
    let eig = SymmetricEigen::try_new(cov, f64::EPSILON, 1000)?;
    let k = eig.eigenvalues.imin();
    let n = eig.eigenvectors.column(k).into_owned();
    (n.iter().all(|x| x.is_finite()) && n.norm() > 0.0).then(|| n.normalize())
}

/// A traced curve of non-isolated critical points.
struct Curve {
    start: Local,
    /// Vertices in order along the curve (the trace may have gone both ways from the start: the
    /// vertices of the second direction then follow those of the first, reversed at the seam).
    vertices: Vec<Vector3<f64>>,
    closed: bool,
    step: f64,
}

impl Curve {
    /// Whether `loc` lies on this curve: degenerate, same level of `U_r` and within `h/2` of the
    /// polyline through the traced vertices (closed when the trace came back to its start).
    fn contains(&self, loc: &Local) -> bool {
        // A point of a curve of critical points has a zero eigenvalue; a non-degenerate point
        // close to a small curve (the pole inside a small circle) is not on it.
        if !same_level(&self.start, loc) || !is_degenerate(loc) {
            return false;
        }
        let n = self.vertices.len();
        let segments = if self.closed { n } else { n.saturating_sub(1) };
        let near = |a: &Vector3<f64>, b: &Vector3<f64>| {
            let ab = b - a;
            let len2 = ab.norm_squared();
            let t = if len2 > 0.0 {
                ((loc.gamma - a).dot(&ab) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (a + t * ab - loc.gamma).norm() <= 0.5 * self.step
        };
        (n == 1 && near(&self.vertices[0], &self.vertices[0]))
            || (0..segments).any(|i| near(&self.vertices[i], &self.vertices[(i + 1) % n]))
    }
}

struct Search<'a, M> {
    model: &'a M,
    p_psi: f64,
    scale: f64,
    max_iterations: usize,
    gradient_tol: f64,
    zero_rel: f64,
}

impl<M: Routhian> Search<'_, M> {
    fn local(&self, gamma: &Vector3<f64>) -> Option<Local> {
        Local::at(self.model, gamma, self.p_psi, self.zero_rel)
    }

    fn tol_scale(&self, loc: &Local) -> f64 {
        self.scale.max(loc.scale)
    }

    /// Safeguarded Newton (Levenberg–Marquardt) on the sphere from `gamma0`. Returns the last
    /// point and whether it is critical; `None` if the model is not finite at `gamma0`.
    fn refine(&self, gamma0: &Vector3<f64>) -> Option<(Local, bool)> {
        let mut cur = self.local(gamma0)?;
        let mut lambda = 0.0f64;
        for _ in 0..self.max_iterations {
            let gn = cur.grad.norm();
            if gn <= STOP_TOL * self.tol_scale(&cur) {
                break;
            }
            let k = cur.hess;
            let k2 = k * k;
            let rhs = -(k * cur.grad);
            let kn2 = k2.norm();
            let lambda_min = (STOP_TOL * self.tol_scale(&cur)).powi(2);
            let mut accepted = None;
            for _ in 0..MAX_LM_RETRIES {
                let m = k2 + Matrix2::from_diagonal_element(lambda);
                let step = m.try_inverse().map(|mi| mi * rhs);
                match step {
                    Some(mut xi) if xi.iter().all(|v| v.is_finite()) => {
                        let len = xi.norm();
                        if len > MAX_STEP {
                            xi *= MAX_STEP / len;
                        }
                        let moved = cur.gamma + cur.basis * xi;
                        let next = moved.normalize();
                        if let Some(n) = self.local(&next) {
                            if n.grad.norm() < gn {
                                accepted = Some(n);
                                break;
                            }
                        }
                    }
                    _ => {}
                }
                lambda = if lambda == 0.0 {
                    (1e-6 * kn2).max(lambda_min)
                } else {
                    lambda * 10.0
                };
            }
            match accepted {
                Some(n) => {
                    cur = n;
                    lambda = if lambda <= 1e-6 * kn2 {
                        0.0
                    } else {
                        lambda / 10.0
                    };
                }
                None => break,
            }
        }
        let converged = cur.grad.norm() <= self.gradient_tol * self.tol_scale(&cur);
        Some((cur, converged))
    }

    /// A converged continuation point from `from` along the direction `dir` with step `h`:
    /// critical, on the level of `level`, and at a distance in `[h/4, 3h]` from `from`.
    fn continue_from(
        &self,
        from: &Local,
        dir: &Vector3<f64>,
        h: f64,
        level: &Local,
    ) -> Option<Local> {
        let guess = (from.gamma + h * dir).normalize();
        let (loc, converged) = self.refine(&guess)?;
        let d = (loc.gamma - from.gamma).norm();
        (converged && same_level(&loc, level) && d >= 0.25 * h && d <= 3.0 * h).then_some(loc)
    }

    /// Traces the curve of critical points through the degenerate critical point `start`;
    /// `None` when there is no such curve (a degenerate isolated point).
    fn trace(&self, start: &Local) -> Option<Curve> {
        let t0 = start.null_direction();
        let steps = [
            TRACE_STEP,
            TRACE_STEP / 4.0,
            TRACE_STEP / 16.0,
            TRACE_STEP / 64.0,
        ];
        for (level, h) in steps.into_iter().enumerate() {
            let mut branches: Vec<Vec<Vector3<f64>>> = Vec::new();
            let mut closed = false;
            for sign in [1.0, -1.0] {
                if closed {
                    break;
                }
                let Some(first) = self.continue_from(start, &(sign * t0), h, start) else {
                    continue;
                };
                let mut branch = vec![first.gamma];
                let mut prev = start.gamma;
                let mut cur = first;
                for step in 0..MAX_TRACE_STEPS {
                    let mut t = cur.null_direction();
                    if t.dot(&(cur.gamma - prev)) < 0.0 {
                        t = -t;
                    }
                    let Some(next) = self.continue_from(&cur, &t, h, start) else {
                        break;
                    };
                    branch.push(next.gamma);
                    if step >= 2 && (next.gamma - start.gamma).norm() < 1.5 * h {
                        closed = true;
                        break;
                    }
                    prev = cur.gamma;
                    cur = next;
                }
                branches.push(branch);
            }
            if branches.is_empty() {
                continue;
            }
            // A closed curve resolved by too few vertices (small compared with h): trace it again
            // with a shorter step.
            let count: usize = branches.iter().map(Vec::len).sum();
            if closed && count < MIN_CLOSED_VERTICES && level + 1 < steps.len() {
                continue;
            }
            // Order the vertices along the curve: second branch reversed, start, first branch.
            let mut vertices: Vec<Vector3<f64>> = Vec::new();
            if let Some(back) = branches.get(1) {
                vertices.extend(back.iter().rev().copied());
            }
            vertices.push(start.gamma);
            vertices.extend(branches[0].iter().copied());
            return Some(Curve {
                start: start.clone(),
                vertices,
                closed,
                step: h,
            });
        }
        None
    }
}
