//! Steady motions (31)–(34): the critical points of the amended potential on the unit sphere.
//!
//! A steady motion of (8) is a uniform rotation about the vertical with the body at rest in the
//! rotating frame: `Ω = 0` (31) (in the gauge `Ω·γ = 0` of errata E4) and the tangential part of
//! `∂R(0, γ, p_ψ)/∂γ` vanishes (33). Equivalently γ is a critical point of the amended potential
//! `U_r(γ) = −R(0, γ, p_ψ)` (34) restricted to the sphere `|γ| = 1`.
//!
//! The method and its tolerances are documented on [`steady_motions`].

use std::fmt;

mod search;

use nalgebra::Vector3;

use crate::error::RouthError;
use crate::model::Routhian;
use crate::solve::norm::stable_norm;
use crate::validate::{check_finite, check_kinetic, check_model_finite, unit_gamma};

/// One steady motion (31)–(34): the body at rest in the frame that turns uniformly about the
/// vertical at the rate `psi_dot`, with body-frame vertical `gamma`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SteadyMotion {
    /// The cyclic momentum `p_ψ` (9) at which this is a steady motion.
    pub p_psi: f64,
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
    /// Errors: non-finite input, `|γ| ≠ 1` beyond [`UNIT_GAMMA_TOL`](crate::validate::UNIT_GAMMA_TOL), and a
    /// kinetic form `J(γ)` that is not positive definite.
    pub fn at<M: Routhian>(
        model: &M,
        gamma: Vector3<f64>,
        p_psi: f64,
        isolated: bool,
    ) -> Result<Self, RouthError> {
        check_finite("p_psi", &[p_psi])?;
        let gamma = unit_gamma("gamma", &gamma)?;
        check_kinetic(model, &gamma)?;
        record(model, &gamma, p_psi, isolated)
    }
}

/// The default number of starts of the search ([`SearchOptions::starts`]); defined with the
/// grids it sizes, below this module.
pub(crate) use crate::sphere::DEFAULT_STARTS;

/// Options of the global search of [`steady_motion_search`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SearchOptions {
    /// Number of starting points of the Fibonacci grid on the sphere (default 400).
    pub starts: usize,
    /// Largest number of Newton iterations from one start (default 100).
    pub max_iterations: usize,
    /// Tolerance on the Newton step `|K⁻¹g|` (radians, the estimated distance to the critical
    /// point) for a point to count as critical (default `1e−10`; see [`steady_motions`]).
    pub gradient_tol: f64,
    /// Tolerance, relative to `‖K‖_F` with a round-off floor, under which an eigenvalue of the
    /// restricted second variation `K` (62)–(63) counts as zero (errata E8; default `1e−8`, the
    /// same as [`ClassifyOptions::zero_eigenvalue_tol`](crate::stability::ClassifyOptions)).
    pub zero_eigenvalue_tol: f64,
}

impl Default for SearchOptions {
    fn default() -> Self {
        SearchOptions {
            starts: DEFAULT_STARTS,
            max_iterations: 100,
            gradient_tol: 1e-10,
            zero_eigenvalue_tol: 1e-8,
        }
    }
}

impl SearchOptions {
    fn validate(&self) -> Result<(), RouthError> {
        let invalid = |what, reason: &str| {
            Err(RouthError::InvalidOption {
                what,
                reason: reason.into(),
            })
        };
        if self.starts == 0 {
            return invalid("starts", "at least one starting point is needed");
        }
        if self.max_iterations == 0 {
            return invalid("max_iterations", "at least one iteration is needed");
        }
        if !(self.gradient_tol > 0.0 && self.gradient_tol < 1.0) {
            return invalid("gradient_tol", "must be in (0, 1)");
        }
        if !(self.zero_eigenvalue_tol > 0.0 && self.zero_eigenvalue_tol < 1.0) {
            return invalid("zero_eigenvalue_tol", "must be in (0, 1)");
        }
        Ok(())
    }
}

/// All steady motions (31)–(34) at the cyclic momentum `p_psi`: the critical points of the
/// amended potential `U_r = −R(0, γ, p_ψ)` (34) on the unit sphere, sorted by increasing `U_r`,
/// found by a global search at the default [`SearchOptions`] — a safeguarded Newton iteration on
/// the sphere from every point of a Fibonacci grid, every tolerance local and tangential (so
/// invariant under scaling the model and under adding `c|γ|²` to `U`), degenerate points placed
/// along the kernel of `K` and curves of steady motions (bodies with a symmetry) traced and
/// reported once, with `isolated: false` (errata E8). The method, its tolerances and its
/// self-check are in docs/method.md §5, "The search".
///
/// **The list is the result of a search, and its completeness is self-checked, but this
/// function does not return the check**: [`steady_motion_search`] returns the same motions with
/// the index sum of the Morse relation ([`SearchResult::euler_characteristic`], χ(S²) = 2) and
/// whether it is reconciled ([`SearchResult::consistent`]); use it whenever the number of steady
/// motions matters. A pair of critical points born together in a fold, closer than the grid
/// spacing to each other and to any other critical point, leaves χ unchanged and can be missed:
/// give [`steady_motion_search`] more starts near bifurcations.
///
/// Errors: [`RouthError::NonFinite`] for a non-finite `p_psi`;
/// [`RouthError::DegenerateVerticalInertia`] / [`RouthError::KineticNotPositiveDefinite`] when
/// `J(γ) = ∂²L/∂ω²` fails to be positive definite at a point of the search grid;
/// [`RouthError::NoConvergence`] when no start converges.
///
/// The example writes its model by hand, both traits in closed form: it is the one example of
/// the crate that shows how (the others take the same top ready-made, and `routh`'s derive
/// writes all of this from the Lagrangian alone).
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
/// let report = classify(&top, upright)?;
/// assert_eq!(report.verdict, Stability::GyroscopicallyStabilized);
/// assert!(motions.iter().any(|s| !s.isolated));
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn steady_motions<M: Routhian>(model: &M, p_psi: f64) -> Result<Vec<SteadyMotion>, RouthError> {
    Ok(steady_motion_search(model, p_psi, &SearchOptions::default())?.motions)
}

/// [`steady_motions`] with explicit [`SearchOptions`], and with the search's self-check: the
/// motions together with the index sum of the Morse relation and whether it is reconciled with
/// χ(S²) = 2 ([`SearchResult`]). Use it whenever completeness of the list matters (check
/// [`SearchResult::consistent`]); [`steady_motions`] returns the same motions without the flag.
///
/// Errors: as [`steady_motions`], plus [`RouthError::InvalidOption`] for zero starts or zero
/// iterations.
///
/// ```
/// use routh_core::steady::{steady_motion_search, SearchOptions};
/// use routh_core::Vector3;
/// # use test_models::Gyrostat;
/// // A heavy asymmetric top, centre of mass on its third axis: the Morse relation closes.
/// let top = Gyrostat::heavy_top(Vector3::new(1.0, 2.0, 3.0), Vector3::z(), 1.0, 1.0);
/// let found = steady_motion_search(&top, 0.5, &SearchOptions::default())?;
/// assert!(found.consistent);
/// assert_eq!(found.euler_characteristic, Some(2));
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn steady_motion_search<M: Routhian>(
    model: &M,
    p_psi: f64,
    opts: &SearchOptions,
) -> Result<SearchResult, RouthError> {
    check_finite("p_psi", &[p_psi])?;
    opts.validate()?;
    let outcome = search::global(model, p_psi, opts)?;
    let mut motions = Vec::with_capacity(outcome.points.len());
    for (gamma, isolated) in outcome.points {
        check_kinetic(model, &gamma)?;
        motions.push(record(model, &gamma, p_psi, isolated)?);
    }
    motions.sort_by(|a, b| a.amended_potential.total_cmp(&b.amended_potential));
    Ok(SearchResult {
        motions,
        euler_characteristic: outcome.euler,
        consistent: outcome.consistent,
    })
}

/// The steady motions of [`steady_motions`] with the outcome of its Morse self-check.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SearchResult {
    /// The steady motions, as returned by [`steady_motions`].
    pub motions: Vec<SteadyMotion>,
    /// The sum of the indices of the isolated steady motions (`+1` at a minimum or a maximum of
    /// `U_r`, `−1` at a saddle; at a degenerate isolated point, the winding number of the gradient
    /// of `U_r` on a small circle around it), closed curves counting 0. By Poincaré–Hopf it is
    /// χ(S²) = 2 when every critical point was found. `None` when it could not be computed: a
    /// two-dimensional set of critical points, a curve that did not close, or a degenerate point
    /// whose index could not be resolved.
    pub euler_characteristic: Option<i64>,
    /// `true` when the count is reconciled: `euler_characteristic == Some(2)`, or `U_r` is
    /// constant on the sphere (every γ is a steady motion, reported once). `false` means that
    /// critical points were probably missed or mis-merged even after the refined second search:
    /// do not trust the list as complete.
    pub consistent: bool,
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
    steady_motion_near_with(model, gamma_guess, p_psi, &SearchOptions::default())
}

/// [`steady_motion_near`] with the search's tolerances and budgets (what `continue_branch` uses
/// with its `ContinuationOptions::search`).
pub(crate) fn steady_motion_near_with<M: Routhian>(
    model: &M,
    gamma_guess: Vector3<f64>,
    p_psi: f64,
    opts: &SearchOptions,
) -> Result<SteadyMotion, RouthError> {
    check_finite("p_psi", &[p_psi])?;
    check_finite("gamma_guess", gamma_guess.as_slice())?;
    let norm = stable_norm(gamma_guess.as_slice());
    if norm == 0.0 {
        return Err(RouthError::NonUnitGamma {
            what: "gamma_guess",
            norm,
            tol: crate::validate::UNIT_GAMMA_TOL,
        });
    }
    let g0 = gamma_guess / norm;
    check_kinetic(model, &g0)?;
    let (gamma, isolated) = search::near(model, &g0, p_psi, opts)?;
    check_kinetic(model, &gamma)?;
    record(model, &gamma, p_psi, isolated)
}

/// The [`SteadyMotion`] record at a unit γ.
pub(crate) fn record<M: Routhian>(
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
    check_model_finite(
        "steady motion (psi_dot, mu, U_r, E)",
        &[psi_dot, mu, amended_potential, energy],
        gamma,
    )?;
    Ok(SteadyMotion {
        p_psi,
        gamma: *gamma,
        psi_dot,
        mu,
        amended_potential,
        energy,
        isolated,
    })
}
