//! Steady motions (31)–(34): the critical points of the amended potential on the unit sphere.
//!
//! A steady motion of (8) is a uniform rotation about the vertical with the body at rest in the
//! rotating frame: `Ω = 0` (31) (in the gauge `Ω·γ = 0` of ERRATA E4) and the tangential part of
//! `∂R(0, γ, p_ψ)/∂γ` vanishes (33). Equivalently γ is a critical point of the amended potential
//! `U_r(γ) = −R(0, γ, p_ψ)` (34) restricted to the sphere `|γ| = 1`.
//!
//! The method and its tolerances are documented on [`steady_motions`].

use std::fmt;

use nalgebra::{Matrix2, Matrix3, Matrix3x2, SymmetricEigen, Vector2, Vector3};

use crate::error::{check_finite, RouthError};
use crate::model::Routhian;

/// Relative tolerance on the Riemannian gradient for a point to count as critical (see
/// [`steady_motions`] for the scale it multiplies).
pub const GRADIENT_TOL: f64 = 1e-10;
/// Relative tolerance under which an eigenvalue of the restricted second variation (62)–(63)
/// counts as zero (ERRATA E8). Round-off in the eigenvalues is about `1e−15` of the scale and a
/// converged point is located to about `1e−13`, so `1e−8` leaves a wide margin on both sides.
pub const ZERO_EIGENVALUE_TOL: f64 = 1e-8;
/// Relative tolerance for two values of the amended potential to be equal.
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

/// One steady motion (31)–(34): the body at rest in the frame that turns uniformly about the
/// vertical at the rate `psi_dot`, with body-frame vertical `gamma`.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadyMotion {
    /// The body-frame upward vertical γ, a unit vector; a critical point of `U_r` on the sphere
    /// (33).
    pub gamma: Vector3<f64>,
    /// The rotation rate about the vertical, `ψ̇ = −∂R/∂p_ψ` at `Ω = 0` (15), (38); the full
    /// angular velocity is `ω = ψ̇γ` (7).
    pub psi_dot: f64,
    /// The Lagrange multiplier `μ = (∂R/∂γ, γ)` at `Ω = 0` (32)–(33).
    pub mu: f64,
    /// The amended potential `U_r(γ, p_ψ) = −R(0, γ, p_ψ)` (34).
    pub amended_potential: f64,
    /// The energy (3) of the full system at `ω = ψ̇γ`, computed from the Lagrangian. By Theorem 2
    /// (E' = E) it equals `amended_potential` up to round-off.
    pub energy: f64,
    /// `false` when γ lies on a curve of steady motions (a circle for a body with a symmetry); one
    /// representative per curve is reported. A degenerate isolated point keeps `true`.
    pub isolated: bool,
}

impl fmt::Display for SteadyMotion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "γ = ({:+.9}, {:+.9}, {:+.9}), ψ̇ = {:+.9e}, μ = {:+.9e}, U_r = {:+.9e}, E = {:+.9e}{}",
            self.gamma.x,
            self.gamma.y,
            self.gamma.z,
            self.psi_dot,
            self.mu,
            self.amended_potential,
            self.energy,
            if self.isolated {
                ""
            } else {
                " (one of a curve of steady motions)"
            }
        )
    }
}

impl SteadyMotion {
    /// The record of the steady motion at the unit vector `gamma`, without any search: `ψ̇` by
    /// (15), `μ` by (32)–(33), `U_r` by (34), the energy (3) of the full system at `ω = ψ̇γ`, and
    /// `isolated` as given. The caller is responsible for `gamma` being a critical point of `U_r`
    /// (for example the sleeping top `γ = e₃`); [`steady_motion_near`] finds one from a guess.
    ///
    /// Errors: non-finite input, `|γ| ≠ 1` beyond [`UNIT_GAMMA_TOL`](crate::UNIT_GAMMA_TOL), and a
    /// kinetic form `J(γ)` that is not positive definite.
    pub fn at<M: Routhian>(
        model: &M,
        gamma: Vector3<f64>,
        p_psi: f64,
        isolated: bool,
    ) -> Result<Self, RouthError> {
        check_finite("p_psi", &[p_psi])?;
        let gamma = unit_gamma(&gamma)?;
        check_kinetic(model, &gamma)?;
        record(model, &gamma, p_psi, isolated)
    }
}

/// Options of the global search of [`steady_motions_with`].
#[derive(Debug, Clone, PartialEq)]
pub struct SearchOptions {
    /// Number of starting points of the Fibonacci grid on the sphere (default 400).
    pub starts: usize,
    /// Largest number of Newton iterations from one start (default 100).
    pub max_iterations: usize,
}

impl Default for SearchOptions {
    fn default() -> Self {
        SearchOptions {
            starts: 400,
            max_iterations: 100,
        }
    }
}

/// All steady motions (31)–(34) at the cyclic momentum `p_psi`: the critical points of the
/// amended potential `U_r = −R(0, γ, p_ψ)` (34) on the unit sphere, found by a global search with
/// the default [`SearchOptions`] (method and tolerances below). Sorted by increasing `U_r`.
/// Curves of steady motions (bodies with a symmetry) are reported once, with `isolated: false`
/// (ERRATA E8).
///
/// # Geometry on the sphere
///
/// γ is an unconstrained vector of ℝ³ when the model differentiates (ERRATA, convention), so the
/// Euclidean gradient and Hessian of `U_r` are `−∂R/∂γ` and `−∂²R/∂γ²`. On the sphere, with `P` a
/// 3×2 orthonormal basis of the tangent plane γ^⊥ and `μ = (∂R/∂γ, γ)`:
/// - Riemannian gradient: `g = Pᵀ(−∂R/∂γ)`; it vanishes exactly when (33) holds;
/// - Riemannian Hessian: `K = Pᵀ(μE − ∂²R/∂γ²)P`, the restricted second variation (62)–(63); it
///   equals `PᵀCP` with `C` of section 5 up to a rotation of the plane (ERRATA E5, E6).
///
/// # Search
///
/// A safeguarded Riemannian Newton iteration starts from every point of a Fibonacci grid on the
/// sphere ([`SearchOptions::starts`], 400 by default: neighbouring starts are about
/// `√(4π/400) ≈ 0.18` rad apart). Each iteration solves the 2×2 Levenberg–Marquardt system
/// `(K² + λE) ξ = −K g`, steps along the retraction `γ ← (γ + Pξ)/|γ + Pξ|` (at most
/// 0.5 radians), and accepts a step only when `|g|` decreases (otherwise λ grows, turning
/// the step into steepest descent of `½|g|²`). With `λ → 0` this is Newton's method on the
/// sphere (quadratic convergence at a non-degenerate critical point); the safeguard makes every
/// start converge to a critical point or stall at a local minimum of `|g|` that is not one (such
/// starts are discarded).
///
/// Critical points closer together than the grid spacing (next to a bifurcation, e.g. the sleeping
/// top inside a small circle of tilted precessions) can share one basin, so the search then starts
/// again from rings of radii `{1/2, 1/5, 1/20}` of the spacing around every point found (and around
/// up to 16 vertices of every curve), and from the axis `±n` of every closed curve (the normal of
/// the plane of its vertices: for a circle of latitude of a symmetric body, the pole, a critical
/// point by symmetry). Finally the Morse relation is checked: the non-degenerate isolated critical
/// points must satisfy `#minima − #saddles + #maxima = χ(S²) = 2` (curves contribute 0). If they
/// do not, the whole search is repeated on a grid four times finer. (A pair of critical points
/// born together in a fold and both missed leaves χ unchanged: such a pair, closer than the grid
/// spacing to each other and to any other critical point, can be missed; use
/// [`steady_motions_with`] with more starts near bifurcations.)
///
/// # Tolerances (all relative to the model scale)
///
/// The *local scale* at γ is `s(γ) = max(|∂R/∂γ|, ‖∂²R/∂γ²‖_F)` at `Ω = 0`: it has units of energy
/// (γ is dimensionless) and bounds the terms whose difference forms `g` and `K`, so round-off in
/// those is a small multiple of `ε·s`. The *search scale* `S` is the largest local scale over the
/// grid of starts.
/// - A point is critical when `|g| ≤` [`GRADIENT_TOL`]` · max(S, s(γ))` (`1e−10`; the iteration
///   goes on to round-off, about `1e−15`, when it can).
/// - Two critical points are the same when they are closer than `1e−6`
///   (non-degenerate points converge to about `1e−13`) or, when one is degenerate (which Newton
///   approaches only linearly), closer than `2e−2` with the same `U_r`.
/// - An eigenvalue of `K` is zero when `|κ| ≤` [`ZERO_EIGENVALUE_TOL`]` · s(γ)`: the same test as
///   [`classify`](crate::classify), so `isolated: false` always comes with
///   [`Stability::Degenerate`](crate::Stability).
/// - Two values of `U_r` are equal when they differ by at most
///   `1e−9 · max(s(γ), |U_r|)`.
///
/// # Non-isolated critical points
///
/// A body with a symmetry has whole circles of steady motions (the tilted precessions of a
/// symmetric top). At a critical point whose `K` has a zero eigenvalue, the search moves by `h`
/// along the null direction, re-converges, and calls the point non-isolated if it lands on a
/// *different* critical point (at least `h/4` away) with the same `U_r`; `h` is 0.05 rad, then
/// `h/4`, `h/16`, `h/64` for small curves. It then traces the curve by predictor–corrector
/// continuation with step `h` (again with a shorter step when a closed curve gets fewer than 12
/// vertices) and reports one representative per curve (`isolated: false`); a later degenerate
/// critical point with the same `U_r` within `h/2` of the traced polyline belongs to that curve.
/// Two circles on the same level (e.g. `γ₃ = ±z` for a body symmetric under `γ₃ → −γ₃`) are
/// therefore two curves. A zero eigenvalue without such a continuation is a degenerate isolated
/// critical point (a bifurcation point): `isolated: true`, and
/// [`classify`](crate::classify) reports it as [`Stability::Degenerate`](crate::Stability).
/// A whole neighbourhood of critical points (both eigenvalues zero, e.g. `U_r` constant) is
/// reported once per level of `U_r`, with `isolated: false`.
///
/// Errors: [`RouthError::NonFinite`] for a non-finite `p_psi`;
/// [`RouthError::DegenerateVerticalInertia`] / [`RouthError::KineticNotPositiveDefinite`] when
/// `J(γ) = ∂²L/∂ω²` fails to be positive definite at a point of the search grid;
/// [`RouthError::NoConvergence`] when no start converges.
///
/// ```
/// # use routh_core::{Lagrangian, Routhian, Matrix3, Vector3};
/// # use routh_core::{steady_motions, classify, Stability};
/// /// The Lagrange top: J = diag(A, A, C), U = m g l γ₃, with its Routh function by hand (39).
/// struct Top { a: f64, c: f64, mgl: f64 }
/// impl Top {
///     fn j(&self) -> Matrix3<f64> {
///         Matrix3::from_diagonal(&Vector3::new(self.a, self.a, self.c))
///     }
/// }
/// impl Lagrangian for Top {
///     fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
///         0.5 * w.dot(&(self.j() * w)) - self.mgl * g.z
///     }
///     fn dl_domega(&self, w: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> { self.j() * w }
///     fn dl_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
///         Vector3::new(0.0, 0.0, -self.mgl)
///     }
///     fn d2l_domega2(&self, _: &Vector3<f64>) -> Matrix3<f64> { self.j() }
///     fn d2l_domega_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Matrix3<f64> {
///         Matrix3::zeros()
///     }
/// }
/// // R = ½ΩᵀJΩ − mglγ₃ − ½q²/n with q = p − (JΩ)·γ, n = γᵀJγ.
/// impl Routhian for Top {
///     fn routhian(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
///         let (j, n) = (self.j(), g.dot(&(self.j() * g)));
///         let q = p - (j * w).dot(g);
///         0.5 * w.dot(&(j * w)) - self.mgl * g.z - 0.5 * q * q / n
///     }
///     fn dr_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
///         let (j, n) = (self.j(), g.dot(&(self.j() * g)));
///         let q = p - (j * w).dot(g);
///         j * w + (q / n) * (j * g)
///     }
///     fn dr_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
///         let (j, n) = (self.j(), g.dot(&(self.j() * g)));
///         let q = p - (j * w).dot(g);
///         Vector3::new(0.0, 0.0, -self.mgl) + (q / n) * (j * w) + (q * q / (n * n)) * (j * g)
///     }
///     fn d2r_domega2(&self, _: &Vector3<f64>, g: &Vector3<f64>, _: f64) -> Matrix3<f64> {
///         let (j, n) = (self.j(), g.dot(&(self.j() * g)));
///         j - (j * g) * (j * g).transpose() / n
///     }
///     fn d2r_domega_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
///         let (j, n) = (self.j(), g.dot(&(self.j() * g)));
///         let q = p - (j * w).dot(g);
///         let dqn = -(j * w) / n - (2.0 * q / (n * n)) * (j * g); // ∂(q/n)/∂γ
///         (j * g) * dqn.transpose() + (q / n) * j
///     }
///     fn d2r_dgamma2(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
///         let (j, n) = (self.j(), g.dot(&(self.j() * g)));
///         let q = p - (j * w).dot(g);
///         let dqn = -(j * w) / n - (2.0 * q / (n * n)) * (j * g);
///         (j * w) * dqn.transpose()
///             + (q * q / (n * n)) * j
///             + (2.0 * q / n) * (j * g) * dqn.transpose()
///     }
/// }
///
/// // A prolate top spinning fast enough: p² > 4 A m g l (Maievskii).
/// let top = Top { a: 2.0, c: 1.0, mgl: 1.0 };
/// let p = 1.1 * (4.0f64 * 2.0 * 1.0).sqrt();
/// let motions = steady_motions(&top, p)?;
/// // The sleeping top upright and upside down, plus one circle of tilted precessions.
/// let upright = motions.iter().find(|s| s.isolated && s.gamma.z > 0.999).unwrap();
/// assert!((upright.energy - upright.amended_potential).abs() < 1e-9);
/// let report = classify(&top, upright, p)?;
/// assert_eq!(report.verdict, Stability::GyroscopicallyStabilized);
/// assert!(motions.iter().any(|s| !s.isolated));
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn steady_motions<M: Routhian>(model: &M, p_psi: f64) -> Result<Vec<SteadyMotion>, RouthError> {
    steady_motions_with(model, p_psi, &SearchOptions::default())
}

/// [`steady_motions`] with explicit [`SearchOptions`].
///
/// Errors: as [`steady_motions`], plus [`RouthError::InvalidOption`] for zero starts or zero
/// iterations.
pub fn steady_motions_with<M: Routhian>(
    model: &M,
    p_psi: f64,
    opts: &SearchOptions,
) -> Result<Vec<SteadyMotion>, RouthError> {
    check_finite("p_psi", &[p_psi])?;
    if opts.starts == 0 {
        return Err(RouthError::InvalidOption {
            what: "starts",
            reason: "at least one starting point is needed".into(),
        });
    }
    if opts.max_iterations == 0 {
        return Err(RouthError::InvalidOption {
            what: "max_iterations",
            reason: "at least one iteration is needed".into(),
        });
    }
    let grid = fibonacci_sphere(opts.starts);
    let mut scale = 0.0f64;
    for g in &grid {
        check_kinetic(model, g)?;
        if let Some(loc) = Local::at(model, g, p_psi) {
            scale = scale.max(loc.scale);
        }
    }
    let search = Search {
        model,
        p_psi,
        scale,
        max_iterations: opts.max_iterations,
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
    let mut out = Vec::with_capacity(isolated.len() + curves.len() + planar.len());
    for loc in &isolated {
        check_kinetic(model, &loc.gamma)?;
        out.push(record(model, &loc.gamma, p_psi, true)?);
    }
    for loc in curves.iter().map(|c| &c.start).chain(planar.iter()) {
        check_kinetic(model, &loc.gamma)?;
        out.push(record(model, &loc.gamma, p_psi, false)?);
    }
    out.sort_by(|a, b| a.amended_potential.total_cmp(&b.amended_potential));
    Ok(out)
}

/// The steady motion nearest (in the sense of Newton's method on the sphere) to the guess
/// `gamma_guess` (any non-zero vector; it is normalised), with `isolated` decided as in
/// [`steady_motions`]. Useful to follow a branch of steady motions as `p_ψ` varies.
///
/// Errors: non-finite input, a zero guess ([`RouthError::NonUnitGamma`] with `norm = 0`), a kinetic
/// form that is not positive definite, and [`RouthError::NoConvergence`] when the iteration stalls
/// before reaching a critical point.
pub fn steady_motion_near<M: Routhian>(
    model: &M,
    gamma_guess: Vector3<f64>,
    p_psi: f64,
) -> Result<SteadyMotion, RouthError> {
    check_finite("p_psi", &[p_psi])?;
    check_finite("gamma_guess", gamma_guess.as_slice())?;
    let norm = gamma_guess.norm();
    if norm == 0.0 || !norm.is_finite() {
        return Err(RouthError::NonUnitGamma {
            norm,
            tol: crate::stability::UNIT_GAMMA_TOL,
        });
    }
    let g0 = gamma_guess / norm;
    check_kinetic(model, &g0)?;
    let start = Local::at(model, &g0, p_psi).ok_or(RouthError::NonFinite {
        what: "amended potential or its derivatives at gamma_guess",
        value: f64::NAN,
    })?;
    let search = Search {
        model,
        p_psi,
        scale: start.scale,
        max_iterations: 200,
    };
    let (loc, converged) = search.refine(&g0).ok_or(RouthError::NonFinite {
        what: "amended potential or its derivatives at gamma_guess",
        value: f64::NAN,
    })?;
    if !converged {
        return Err(RouthError::NoConvergence {
            what: "steady_motion_near (Newton on the sphere)",
            iterations: search.max_iterations,
            residual: loc.grad.norm() / search.tol_scale(&loc),
        });
    }
    check_kinetic(model, &loc.gamma)?;
    let eigs = sym2_eigen(&loc.hess);
    let zero = |k: f64| k.abs() <= ZERO_EIGENVALUE_TOL * loc.scale;
    let isolated = if zero(eigs.values[0]) && zero(eigs.values[1]) {
        false
    } else if zero(eigs.values[0]) || zero(eigs.values[1]) {
        search.trace(&loc).is_none()
    } else {
        true
    };
    record(model, &loc.gamma, p_psi, isolated)
}

// ---------------------------------------------------------------------------------------------
// Crate-internal helpers shared with `stability`.

/// Checks `|γ| = 1` within [`UNIT_GAMMA_TOL`](crate::UNIT_GAMMA_TOL) and returns `γ/|γ|`.
pub(crate) fn unit_gamma(gamma: &Vector3<f64>) -> Result<Vector3<f64>, RouthError> {
    check_finite("gamma", gamma.as_slice())?;
    let norm = gamma.norm();
    let tol = crate::stability::UNIT_GAMMA_TOL;
    if (norm - 1.0).abs() > tol {
        return Err(RouthError::NonUnitGamma { norm, tol });
    }
    Ok(gamma / norm)
}

/// Checks that `J(γ) = ∂²L/∂ω²` is finite and positive definite and `γᵀJγ > 0`.
pub(crate) fn check_kinetic<M: Routhian>(
    model: &M,
    gamma: &Vector3<f64>,
) -> Result<(), RouthError> {
    let j = model.d2l_domega2(gamma);
    check_finite("J(gamma) = d2l_domega2", j.as_slice())?;
    let vertical = gamma.dot(&(j * gamma));
    if vertical <= 0.0 {
        return Err(RouthError::DegenerateVerticalInertia {
            gamma: [gamma.x, gamma.y, gamma.z],
            value: vertical,
        });
    }
    let sym = 0.5 * (j + j.transpose());
    let min_eigenvalue = SymmetricEigen::try_new(sym, f64::EPSILON, 1000)
        .map(|e| e.eigenvalues.min())
        .unwrap_or(f64::NAN);
    if min_eigenvalue.is_nan() || min_eigenvalue <= 0.0 {
        return Err(RouthError::KineticNotPositiveDefinite {
            gamma: [gamma.x, gamma.y, gamma.z],
            min_eigenvalue,
        });
    }
    Ok(())
}

/// A 3×2 orthonormal basis `P = [u v]` of γ^⊥ with `(u, v, γ)` right-handed; γ must be a unit
/// vector.
pub(crate) fn tangent_basis(gamma: &Vector3<f64>) -> Matrix3x2<f64> {
    let a = gamma.abs();
    let e = if a.x <= a.y && a.x <= a.z {
        Vector3::x()
    } else if a.y <= a.z {
        Vector3::y()
    } else {
        Vector3::z()
    };
    let u = (e - e.dot(gamma) * gamma).normalize();
    let v = gamma.cross(&u);
    Matrix3x2::from_columns(&[u, v])
}

/// The local scale `max(|∂R/∂γ|, ‖∂²R/∂γ²‖_F)` (see [`steady_motions`]).
pub(crate) fn local_scale(dr_dgamma: &Vector3<f64>, d2r_dgamma2: &Matrix3<f64>) -> f64 {
    dr_dgamma.norm().max(d2r_dgamma2.norm())
}

/// The restricted second variation `Pᵀ(μE − ∂²R/∂γ²)P` (62)–(63), symmetrised.
pub(crate) fn restricted_hessian(
    p: &Matrix3x2<f64>,
    mu: f64,
    d2r_dgamma2: &Matrix3<f64>,
) -> Matrix2<f64> {
    let k = p.transpose() * (Matrix3::from_diagonal_element(mu) - d2r_dgamma2) * p;
    0.5 * (k + k.transpose())
}

/// Eigen-decomposition of a symmetric 2×2 matrix, eigenvalues ascending.
pub(crate) struct Eigen2 {
    pub values: [f64; 2],
    pub vectors: [Vector2<f64>; 2],
}

/// Closed-form eigen-decomposition of the symmetric 2×2 matrix `k` (reads the upper triangle).
pub(crate) fn sym2_eigen(k: &Matrix2<f64>) -> Eigen2 {
    let (a, b, c) = (k[(0, 0)], k[(0, 1)], k[(1, 1)]);
    let m = 0.5 * (a + c);
    let d = (0.5 * (a - c)).hypot(b);
    // The eigenvalue of larger magnitude by the direct formula, the other from the determinant
    // when that avoids cancellation.
    let (lo, hi) = if d == 0.0 {
        (m, m)
    } else {
        let big = if m >= 0.0 { m + d } else { m - d };
        let det = a * c - b * b;
        let small = if big != 0.0 { det / big } else { m - d };
        if m >= 0.0 {
            (small, big)
        } else {
            (big, small)
        }
    };
    let vec_for = |lam: f64| {
        let v1 = Vector2::new(b, lam - a);
        let v2 = Vector2::new(lam - c, b);
        let v = if v1.norm() >= v2.norm() { v1 } else { v2 };
        let n = v.norm();
        if n > 0.0 {
            v / n
        } else {
            Vector2::new(1.0, 0.0)
        }
    };
    let v_lo = if d == 0.0 {
        Vector2::new(1.0, 0.0)
    } else {
        vec_for(lo)
    };
    let v_hi = Vector2::new(-v_lo.y, v_lo.x);
    Eigen2 {
        values: [lo, hi],
        vectors: [v_lo, v_hi],
    }
}

/// The [`SteadyMotion`] record at a unit γ.
fn record<M: Routhian>(
    model: &M,
    gamma: &Vector3<f64>,
    p_psi: f64,
    isolated: bool,
) -> Result<SteadyMotion, RouthError> {
    let zero = Vector3::zeros();
    let psi_dot = model.psi_dot(&zero, gamma, p_psi);
    let mu = model.dr_dgamma(&zero, gamma, p_psi).dot(gamma);
    let amended_potential = model.amended_potential(gamma, p_psi);
    let energy = model.energy(&(psi_dot * gamma), gamma);
    check_finite(
        "steady motion (psi_dot, mu, U_r, E)",
        &[psi_dot, mu, amended_potential, energy],
    )?;
    Ok(SteadyMotion {
        gamma: *gamma,
        psi_dot,
        mu,
        amended_potential,
        energy,
        isolated,
    })
}

/// `n` points of the Fibonacci (golden-angle) lattice on the unit sphere.
fn fibonacci_sphere(n: usize) -> Vec<Vector3<f64>> {
    let golden = std::f64::consts::PI * (3.0 - 5.0f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / n as f64;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let phi = golden * i as f64;
            Vector3::new(r * phi.cos(), r * phi.sin(), z)
        })
        .collect()
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
}

impl Local {
    /// `None` when the model returns non-finite values at γ.
    fn at<M: Routhian>(model: &M, gamma: &Vector3<f64>, p_psi: f64) -> Option<Local> {
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
    e.values
        .iter()
        .any(|k| k.abs() <= ZERO_EIGENVALUE_TOL * loc.scale)
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
        let zero = |k: f64| k.abs() <= ZERO_EIGENVALUE_TOL * loc.scale;
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
            let tol = ZERO_EIGENVALUE_TOL * loc.scale;
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
}

impl<M: Routhian> Search<'_, M> {
    fn local(&self, gamma: &Vector3<f64>) -> Option<Local> {
        Local::at(self.model, gamma, self.p_psi)
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
        let converged = cur.grad.norm() <= GRADIENT_TOL * self.tol_scale(&cur);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tangent_basis_is_orthonormal_and_right_handed() {
        for g in fibonacci_sphere(50) {
            let p = tangent_basis(&g);
            let (u, v) = (p.column(0).into_owned(), p.column(1).into_owned());
            assert!((u.norm() - 1.0).abs() < 1e-14 && (v.norm() - 1.0).abs() < 1e-14);
            assert!(u.dot(&v).abs() < 1e-14 && u.dot(&g).abs() < 1e-14);
            assert!((u.cross(&v) - g).norm() < 1e-14);
        }
    }

    #[test]
    fn sym2_eigen_matches_definition() {
        for (a, b, c) in [
            (1.0, 0.0, 1.0),
            (2.0, 1.0, -3.0),
            (1e8, 1.0, 1e8 + 1e-3),
            (0.0, 0.0, 5.0),
        ] {
            let k = Matrix2::new(a, b, b, c);
            let e = sym2_eigen(&k);
            assert!(e.values[0] <= e.values[1]);
            for i in 0..2 {
                let r = k * e.vectors[i] - e.values[i] * e.vectors[i];
                assert!(r.norm() <= 1e-9 * (1.0 + k.norm()), "{a} {b} {c}: {r}");
            }
        }
    }
}
