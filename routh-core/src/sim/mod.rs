//! Simulation of the full equations (8) and of the reduced equations (13) (docs/method.md §2–3).
//!
//! - [`simulate_full`] integrates (8) for `(ω, γ)` and records the energy (3), the cyclic
//!   momentum (9) and `|γ|²` along the way.
//! - [`simulate_reduced`] integrates (13) for `(Ω, γ)` in the gauge of errata E4, reconstructs
//!   the rotation angle ψ of the rotating frame by (15), and records E' (16), `(∂R/∂Ω, γ)` (17)
//!   and `|γ|²`.
//!
//! Two integrators are offered ([`Method`]): DOP853, an adaptive Runge–Kutta method of order 8
//! with error control and a dense output of order 7 (the default), and RKMK4, a fixed-step
//! Lie-group Runge–Kutta method of order 4 that moves γ by exact rotations and so keeps
//! `|γ| = 1` to round-off over arbitrarily long runs. (The crate `ode_solvers` was considered:
//! it depends on another major version of nalgebra and has no fallible right-hand side, so a
//! compact DOP853 is implemented here instead, following Hairer's `dop853.f`.)
//!
//! Layout: this module holds the options, the trajectory types and the two drivers; `drive` the
//! integration loop over both methods, `field` the vector fields, `dop853` (with `tableau`) and
//! `lie` the two steppers.

pub mod attitude;
pub(crate) mod dop853;
mod drive;
mod field;
mod lie;
mod tableau;

pub use field::{full_vector_field, reduced_vector_field};

use drive::{drive, split3, Field};
use field::{FullField, ReducedField};

use nalgebra::{SVector, UnitQuaternion, Vector3};

use crate::norm::stable_norm;
use crate::validate::{check_finite, unit_gamma};
use crate::{Lagrangian, RouthError, Routhian};

/// The integration method.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Method {
    /// Dormand–Prince 8(5,3) with Hairer's step-size control, initial-step heuristic and
    /// 7th-order dense output. Uses [`SimOptions::rtol`], [`SimOptions::atol`],
    /// [`SimOptions::h_max`], [`SimOptions::h_init`] and [`SimOptions::max_steps`].
    Dop853,
    /// The fixed-step Lie-group (Munthe-Kaas) Runge–Kutta method of order 4 on `ℝᵐ × S²`: the
    /// velocities (and ψ) are advanced by classical RK4 stages, γ only by exact rotations
    /// (Rodrigues), so `|γ|² − 1` stays at round-off level. `step` is the largest step; every
    /// interval between two outputs (or `[0, t_end]`) is cut into equal steps no longer than it.
    LieRk4 {
        /// The (largest) step size, finite and positive.
        step: f64,
    },
}

/// Which points the trajectory records.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Output {
    /// `t = 0` and the end of every accepted step (the last one is `t_end`).
    Steps,
    /// Exactly these times, which must be finite, non-decreasing and in `[0, t_end]`. With
    /// [`Method::Dop853`] they are filled in by the dense output (3 more evaluations of the
    /// vector field a step); with [`Method::LieRk4`] the steps are cut to land on them.
    Times(Vec<f64>),
}

/// Options of [`simulate_full`] and [`simulate_reduced`].
///
/// Build with struct-update syntax, e.g. `SimOptions { rtol: 1e-12, ..SimOptions::default() }`.
///
/// # Error control and units
///
/// [`Method::Dop853`] accepts a step when the RMS over the state of `eᵢ/skᵢ` is at most 1, where
/// `eᵢ` is the local error estimate. The weights are taken per 3-vector, by Euclidean length, so
/// that rotating the body frame changes nothing:
///
/// - angular velocity ω (full) or Ω (reduced): `sk = rate_atol + rtol·|ω|`;
/// - γ: `sk = atol + rtol·|γ|`;
/// - ψ (reduced): `sk = atol + rtol·|ψ|`.
///
/// `rtol` has no units. γ and ψ have none either, so neither has `atol`. The angular velocity
/// has the units 1/time, and so does `rate_atol`: the same motion in a unit of time s times
/// smaller (ω s times larger, output times s times larger, `t_end` too) takes the same steps
/// and gives the same γ at the same physical times when `rate_atol` is multiplied by s and the
/// rest is kept. Scaling the inertia, the gyroscopic term, the potential and p_ψ by one factor
/// (the same Lagrangian in other units of energy) changes no state variable and needs no change
/// of the options.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SimOptions {
    /// Relative tolerance of [`Method::Dop853`]. Must be finite and at least
    /// `10·ε ≈ 2.2e-15`. Default `1e-10`.
    pub rtol: f64,
    /// Absolute tolerance of [`Method::Dop853`] for γ and ψ (dimensionless), and for the angular
    /// velocity unless [`rate_atol`](Self::rate_atol) is given. Finite and positive. Default
    /// `1e-12`.
    pub atol: f64,
    /// Absolute tolerance of [`Method::Dop853`] for the angular velocity (ω or Ω), in the units
    /// of the angular velocity (1/time). `None`: [`atol`](Self::atol). Finite and positive if
    /// given. Default `None`.
    pub rate_atol: Option<f64>,
    /// The integrator. Default [`Method::Dop853`].
    pub method: Method,
    /// Largest step of [`Method::Dop853`] (`None`: unbounded). Must be positive if given.
    pub h_max: Option<f64>,
    /// Initial step of [`Method::Dop853`] (`None`: Hairer's heuristic). Positive if given.
    pub h_init: Option<f64>,
    /// Budget of attempted steps (accepted and rejected); at least 1. Default `100_000`.
    pub max_steps: usize,
    /// Which points are recorded. Default [`Output::Steps`].
    pub output: Output,
    /// Also integrate the attitude of the body, the rotation `R` body → space, as a unit
    /// quaternion (`Ṙ = R[ω]×`, module [`attitude`]), recorded in [`Trajectory::attitude`] /
    /// [`ReducedTrajectory::attitude`]. Default `false` (no cost when off).
    ///
    /// With [`Method::LieRk4`] the attitude moves by the same exact rotations as γ, so it stays
    /// a unit quaternion and `γ = Rᵀe₃` holds to round-off. With [`Method::Dop853`] the
    /// quaternion is four more components of the state under the same error control; each
    /// recorded attitude is normalised and turned by the (tolerance-sized) smallest rotation
    /// that makes `Rᵀe₃` equal the direction of the integrated γ, so `γ/|γ| = Rᵀe₃` holds to
    /// round-off there too (|γ| itself drifts at the tolerance, see
    /// [`Trajectory::gamma_norm_error`]).
    pub attitude: bool,
}

impl Default for SimOptions {
    fn default() -> Self {
        SimOptions {
            rtol: 1e-10,
            atol: 1e-12,
            rate_atol: None,
            method: Method::Dop853,
            h_max: None,
            h_init: None,
            max_steps: 100_000,
            output: Output::Steps,
            attitude: false,
        }
    }
}

impl SimOptions {
    /// The adaptive method with the given tolerances, other options at their defaults.
    pub fn with_tolerances(rtol: f64, atol: f64) -> Self {
        SimOptions {
            rtol,
            atol,
            ..SimOptions::default()
        }
    }

    /// The Lie-group RK4 method with the given step, other options at their defaults.
    pub fn lie_rk4(step: f64) -> Self {
        SimOptions {
            method: Method::LieRk4 { step },
            ..SimOptions::default()
        }
    }

    /// The same options, also integrating the attitude (see [`SimOptions::attitude`]).
    pub fn with_attitude(mut self) -> Self {
        self.attitude = true;
        self
    }

    /// The same options, recording exactly at `times` (see [`Output::Times`]).
    pub fn at_times(mut self, times: Vec<f64>) -> Self {
        self.output = Output::Times(times);
        self
    }
}

/// Work done by one simulation.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SimStats {
    /// Accepted steps.
    pub accepted_steps: usize,
    /// Rejected steps (error too large, or non-finite trial values).
    pub rejected_steps: usize,
    /// Evaluations of the vector field (each one is one evaluation of the model's derivatives
    /// `∂L/∂ω`, `∂L/∂γ`, `J`, `∂²L/∂ω∂γ`, or for the reduced equations of `∂R/∂Ω`, `∂R/∂γ`,
    /// `∂²R/∂Ω²`, `∂²R/∂Ω∂γ` and `∂R/∂p_ψ`).
    pub rhs_evaluations: usize,
}

/// A solution of the full equations (8), from [`simulate_full`].
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Trajectory {
    /// Times: `t = 0` first, then every accepted step (or the requested [`Output::Times`]).
    pub t: Vec<f64>,
    /// Body angular velocity ω.
    pub omega: Vec<Vector3<f64>>,
    /// Body coordinates γ of the upward vertical.
    pub gamma: Vec<Vector3<f64>>,
    /// The Painlevé–Jacobi energy (3) `E = (∂L/∂ω, ω) − L` ([`Lagrangian::energy`]).
    pub energy: Vec<f64>,
    /// The cyclic momentum (9) `p_ψ = (∂L/∂ω, γ)` ([`Lagrangian::cyclic_momentum`]).
    pub p_psi: Vec<f64>,
    /// `|γ|²` (the geometric integral (4) is `|γ|² − 1 = 0`).
    pub gamma_norm_sq: Vec<f64>,
    /// The attitude `R` (body → space) at each point when [`SimOptions::attitude`] is set,
    /// empty otherwise: `γ = Rᵀe₃`, `Ṙ = R[ω]×`, and `R(0)` the attitude with Euler angle
    /// `ψ(0) = 0`: `R(0) = R_x(θ₀) R_z(φ₀)` with `γ₀ = (sin θ₀ sin φ₀, sin θ₀ cos φ₀, cos θ₀)`.
    pub attitude: Vec<UnitQuaternion<f64>>,
    /// Work counters.
    pub stats: SimStats,
}

/// A solution of the reduced equations (13) with the reconstruction (15), from
/// [`simulate_reduced`].
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ReducedTrajectory {
    /// Times: `t = 0` first, then every accepted step (or the requested [`Output::Times`]).
    pub t: Vec<f64>,
    /// Angular velocity Ω relative to the frame rotating about the vertical (7).
    pub big_omega: Vec<Vector3<f64>>,
    /// Body coordinates γ of the upward vertical.
    pub gamma: Vec<Vector3<f64>>,
    /// Rotation angle ψ of the rotating frame about the vertical, integrated from
    /// `ψ̇ = −∂R/∂p_ψ` (15) with `ψ(0) = 0`.
    pub psi: Vec<f64>,
    /// `ψ̇(Ω, γ, p_ψ)` of (12)/(38) ([`Routhian::psi_dot`]).
    pub psi_dot: Vec<f64>,
    /// The reconstructed body angular velocity `ω = Ω + ψ̇γ` (7).
    pub omega: Vec<Vector3<f64>>,
    /// The reduced energy (16) `E' = (∂R/∂Ω, Ω) − R`, equal to E of (3) (Theorem 2).
    pub energy: Vec<f64>,
    /// `(∂R/∂Ω, γ)` of (17), identically `p_ψ` (Theorem 2).
    pub p_psi: Vec<f64>,
    /// `|γ|²`.
    pub gamma_norm_sq: Vec<f64>,
    /// The attitude `R` (body → space) at each point when [`SimOptions::attitude`] is set,
    /// empty otherwise, reconstructed by (15): `R = R_z(ψ) R_Ω` with `R_Ω` the attitude of the
    /// body relative to the frame rotating about the vertical (`Ṙ_Ω = R_Ω[Ω]×`,
    /// `R_Ω(0)` the attitude with Euler angle ψ = 0 whose `Rᵀe₃` is `γ₀`) and ψ the angle of [`psi`](Self::psi);
    /// then `Ṙ = R[Ω + ψ̇γ]× = R[ω]×` and `γ = Rᵀe₃`.
    ///
    /// The gauge angle ψ (errata E4) is not the Euler angle ψ of [`euler_angles`](Self::euler_angles):
    /// the Euler ψ of `R` is the gauge ψ plus the Euler ψ of `R_Ω`, which moves unless Ω = 0.
    /// On a steady motion (Ω = 0) the two differ by a constant, so their rates agree.
    pub attitude: Vec<UnitQuaternion<f64>>,
    /// Work counters.
    pub stats: SimStats,
}

/// `max |x_i − x_0|` (0 for fewer than two points).
fn max_deviation(x: &[f64]) -> f64 {
    match x.first() {
        Some(&x0) => x.iter().fold(0.0, |m, &v| m.max((v - x0).abs())),
        None => 0.0,
    }
}

/// `max | |γ|² − 1 |`.
fn max_unit_error(x: &[f64]) -> f64 {
    x.iter().fold(0.0, |m, &v| m.max((v - 1.0).abs()))
}

impl Trajectory {
    /// Number of recorded points.
    pub fn len(&self) -> usize {
        self.t.len()
    }
    /// Whether no point was recorded.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }
    /// `max |E(t) − E(t₀)|` of the energy (3) over the recorded points.
    pub fn energy_drift(&self) -> f64 {
        max_deviation(&self.energy)
    }
    /// `max |p_ψ(t) − p_ψ(t₀)|` of the cyclic momentum (9).
    pub fn p_psi_drift(&self) -> f64 {
        max_deviation(&self.p_psi)
    }
    /// `max | |γ(t)|² − 1 |`.
    pub fn gamma_norm_error(&self) -> f64 {
        max_unit_error(&self.gamma_norm_sq)
    }
    /// The z-x-z Euler angles `(ψ, θ, φ)` of [`attitude`](Self::attitude),
    /// `R = R_z(ψ) R_x(θ) R_z(φ)`, ψ and φ unwrapped ([`attitude::euler_angles`]); empty when
    /// the attitude was not integrated.
    pub fn euler_angles(&self) -> Vec<[f64; 3]> {
        attitude::euler_angles(&self.attitude)
    }
}

impl ReducedTrajectory {
    /// Number of recorded points.
    pub fn len(&self) -> usize {
        self.t.len()
    }
    /// Whether no point was recorded.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }
    /// `max |E'(t) − E'(t₀)|` of the reduced energy (16).
    pub fn energy_drift(&self) -> f64 {
        max_deviation(&self.energy)
    }
    /// `max |(∂R/∂Ω, γ)(t) − p_ψ|` (17), with `p_ψ` the constant the run was started with.
    pub fn p_psi_error(&self, p_psi: f64) -> f64 {
        self.p_psi
            .iter()
            .fold(0.0, |m, &v| m.max((v - p_psi).abs()))
    }
    /// `max | |γ(t)|² − 1 |`.
    pub fn gamma_norm_error(&self) -> f64 {
        max_unit_error(&self.gamma_norm_sq)
    }
    /// The z-x-z Euler angles `(ψ, θ, φ)` of [`attitude`](Self::attitude) (see
    /// [`Trajectory::euler_angles`]); empty when the attitude was not integrated.
    pub fn euler_angles(&self) -> Vec<[f64; 3]> {
        attitude::euler_angles(&self.attitude)
    }
}

fn check_unit_gamma(gamma: &Vector3<f64>) -> Result<(), RouthError> {
    unit_gamma("gamma0", gamma).map(|_| ())
}

fn invalid(what: &'static str, reason: impl Into<String>) -> RouthError {
    RouthError::InvalidOption {
        what,
        reason: reason.into(),
    }
}

/// Checks `t_end` and every option.
fn validate(opts: &SimOptions, t_end: f64) -> Result<(), RouthError> {
    check_finite("t_end", &[t_end])?;
    if t_end < 0.0 {
        return Err(invalid("t_end", format!("must be ≥ 0 (got {t_end})")));
    }
    check_finite("rtol", &[opts.rtol])?;
    check_finite("atol", &[opts.atol])?;
    if opts.rtol < 10.0 * f64::EPSILON {
        return Err(invalid(
            "rtol",
            format!("must be ≥ 10ε ≈ 2.2e-15 (got {:e})", opts.rtol),
        ));
    }
    if opts.atol <= 0.0 {
        return Err(invalid(
            "atol",
            format!("must be > 0 (got {:e})", opts.atol),
        ));
    }
    if let Some(a) = opts.rate_atol {
        check_finite("rate_atol", &[a])?;
        if a <= 0.0 {
            return Err(invalid("rate_atol", format!("must be > 0 (got {a:e})")));
        }
    }
    if let Method::LieRk4 { step } = opts.method {
        check_finite("step", &[step])?;
        if step <= 0.0 {
            return Err(invalid("step", format!("must be > 0 (got {step:e})")));
        }
    }
    if let Some(h) = opts.h_max {
        if h.is_nan() {
            return Err(RouthError::NonFinite {
                what: "h_max",
                value: h,
            });
        }
        if h <= 0.0 {
            return Err(invalid("h_max", format!("must be > 0 (got {h:e})")));
        }
    }
    if let Some(h) = opts.h_init {
        check_finite("h_init", &[h])?;
        if h <= 0.0 {
            return Err(invalid("h_init", format!("must be > 0 (got {h:e})")));
        }
    }
    if opts.max_steps == 0 {
        return Err(invalid("max_steps", "must be ≥ 1"));
    }
    if let Output::Times(ts) = &opts.output {
        check_finite("output time", ts)?;
        if let Some(&t) = ts.iter().find(|&&t| !(0.0..=t_end).contains(&t)) {
            return Err(invalid(
                "output",
                format!("time {t} outside [0, t_end = {t_end}]"),
            ));
        }
        if ts.windows(2).any(|w| w[1] < w[0]) {
            return Err(invalid("output", "times must be non-decreasing"));
        }
    }
    Ok(())
}

fn all_finite(v: &Vector3<f64>) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// A finite input so large that the vector field overflows at the initial state.
fn too_large(what: &'static str, size: f64, equations: &str) -> RouthError {
    invalid(
        what,
        format!(
            "|{what}| = {size:e} is too large for this model: the vector field of {equations} \
             overflows f64 at the initial state"
        ),
    )
}

/// Simulates the full equations of motion (8) from `(ω₀, γ₀)` at `t = 0` to `t_end`.
///
/// The state is `(ω, γ)`; ω̇ is solved from
/// `J ω̇ = ∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)` with `J = ∂²L/∂ω²` by a square-root-free
/// Cholesky factorisation (factorised once when `J` does not depend on γ; when
/// `J = J₀ + c(γ) v(γ) v(γ)ᵀ`, a body on a plane, `J₀` is factorised once and each solve is
/// Sherman–Morrison, docs/method.md §2a), and `γ̇ = γ × ω` (see [`full_vector_field`]). Along the trajectory the energy (3), the cyclic
/// momentum (9) and `|γ|²` are recorded; they are first integrals, so their drift measures the
/// integration error.
///
/// γ₀ must be a unit vector (`| |γ₀| − 1 | ≤ 1e−8`, [`UNIT_GAMMA_TOL`](crate::validate::UNIT_GAMMA_TOL)); it is used as given
/// (not normalised).
///
/// # Errors
///
/// [`RouthError::NonFinite`] for non-finite `ω₀`, `γ₀`, `t_end`, tolerances or options;
/// [`RouthError::InvalidOption`] for `t_end < 0`, invalid [`SimOptions`], or a finite `ω₀` so
/// large that the vector field overflows (`what: "omega0"`); [`RouthError::NonFiniteModel`]
/// when the vector field is not finite at `(0, γ₀)`;
/// [`RouthError::NonUnitGamma`]; [`RouthError::KineticNotPositiveDefinite`] when `J(γ)` has no
/// Cholesky factor (at γ₀ or later); [`RouthError::StepSizeUnderflow`],
/// [`RouthError::TooManySteps`] and [`RouthError::NonFiniteState`] from the integrator.
///
/// # Example
///
/// A heavy symmetric (Lagrange) top `L = ½(A(ω₁² + ω₂²) + Cω₃²) − m g l γ₃`, written by hand:
///
/// ```
/// use routh_core::{simulate_full, Lagrangian, Matrix3, SimOptions, Vector3};
///
/// struct Top { a: f64, c: f64, mgl: f64 }
///
/// impl Lagrangian for Top {
///     fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
///         0.5 * (self.a * (w.x * w.x + w.y * w.y) + self.c * w.z * w.z) - self.mgl * g.z
///     }
///     fn dl_domega(&self, w: &Vector3<f64>, _g: &Vector3<f64>) -> Vector3<f64> {
///         Vector3::new(self.a * w.x, self.a * w.y, self.c * w.z)
///     }
///     fn dl_dgamma(&self, _w: &Vector3<f64>, _g: &Vector3<f64>) -> Vector3<f64> {
///         Vector3::new(0.0, 0.0, -self.mgl)
///     }
///     fn d2l_domega2(&self, _g: &Vector3<f64>) -> Matrix3<f64> {
///         Matrix3::from_diagonal(&Vector3::new(self.a, self.a, self.c))
///     }
///     fn d2l_domega_dgamma(&self, _w: &Vector3<f64>, _g: &Vector3<f64>) -> Matrix3<f64> {
///         Matrix3::zeros()
///     }
/// }
///
/// let top = Top { a: 2.0, c: 1.0, mgl: 1.0 };
/// let gamma0 = Vector3::new(0.6, 0.0, 0.8); // tilted
/// let omega0 = Vector3::new(0.0, 0.3, 5.0); // spinning fast
/// let traj = simulate_full(&top, omega0, gamma0, 10.0, &SimOptions::default())?;
///
/// assert_eq!(traj.t[0], 0.0);
/// assert_eq!(*traj.t.last().unwrap(), 10.0);
/// // The spin ω₃ of a Lagrange top is constant (Euler's third equation).
/// assert!(traj.omega.iter().all(|w| (w.z - 5.0).abs() < 1e-9));
/// // Energy (3), cyclic momentum (9) and |γ|² are kept.
/// assert!(traj.energy_drift() < 1e-8);
/// assert!(traj.p_psi_drift() < 1e-8);
/// assert!(traj.gamma_norm_error() < 1e-9);
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn simulate_full<M: Lagrangian>(
    model: &M,
    omega0: Vector3<f64>,
    gamma0: Vector3<f64>,
    t_end: f64,
    opts: &SimOptions,
) -> Result<Trajectory, RouthError> {
    check_finite("omega0", omega0.as_slice())?;
    check_finite("gamma0", gamma0.as_slice())?;
    validate(opts, t_end)?;
    check_unit_gamma(&gamma0)?;
    // A finite input for which the vector field overflows: say which input is too large.
    // The recorded integrals count too: an ω₀ for which the energy (3) overflows (|ω₀| = 1e300)
    // is too large even where the field is finite (found by tests/runtime_properties.rs).
    let finite_at = |w: &Vector3<f64>| {
        full_vector_field(model, w, &gamma0).map(|(a, b)| {
            all_finite(&a)
                && all_finite(&b)
                && model.energy(w, &gamma0).is_finite()
                && model.cyclic_momentum(w, &gamma0).is_finite()
        })
    };
    if !finite_at(&omega0)? {
        return Err(if finite_at(&Vector3::zeros())? {
            too_large("omega0", stable_norm(omega0.as_slice()), "(8)")
        } else {
            RouthError::NonFiniteModel {
                what: "full vector field (8) at omega = 0",
                gamma: [gamma0.x, gamma0.y, gamma0.z],
            }
        });
    }
    let mut y0 = SVector::<f64, 6>::zeros();
    y0.fixed_rows_mut::<3>(0).copy_from(&omega0);
    y0.fixed_rows_mut::<3>(3).copy_from(&gamma0);

    let mut traj = Trajectory::default();
    let mut push = |t: f64, w: Vector3<f64>, g: Vector3<f64>, q: Option<UnitQuaternion<f64>>| {
        traj.t.push(t);
        traj.omega.push(w);
        traj.gamma.push(g);
        traj.energy.push(model.energy(&w, &g));
        traj.p_psi.push(model.cyclic_momentum(&w, &g));
        traj.gamma_norm_sq.push(g.norm_squared());
        if let Some(q) = q {
            traj.attitude.push(q);
        }
    };
    let q0 = opts.attitude.then(|| attitude::initial_attitude(&gamma0));
    let stats = match (q0, opts.method) {
        (Some(q0), Method::Dop853) => {
            let mut y0q = SVector::<f64, 10>::zeros();
            y0q.fixed_rows_mut::<6>(0).copy_from(&y0);
            attitude::write(&mut y0q, 6, q0.quaternion());
            let field = WithAttitude(FullRhs(FullField::new(model)));
            drive(field, y0q, t_end, opts, None, |t, y, _| {
                let g = split3(y, 3);
                let q = attitude::aligned(&attitude::read(y, 6), &g);
                push(t, split3(y, 0), g, Some(q))
            })?
        }
        (q0, _) => {
            let field = FullRhs(FullField::new(model));
            drive(field, y0, t_end, opts, q0, |t, y, q| {
                push(t, split3(y, 0), split3(y, 3), q.copied())
            })?
        }
    };
    // A finite state can still overflow the recorded integrals (a fixed-step run gone unstable).
    non_finite_record(&traj.t, &[&traj.energy, &traj.p_psi])?;
    traj.stats = stats;
    Ok(traj)
}

/// The state `(ω, γ)` of (8) and its rates.
struct FullRhs<'a, M: ?Sized>(FullField<'a, M>);

impl<M: Lagrangian + ?Sized> Field<6> for FullRhs<'_, M> {
    #[inline(always)]
    fn eval(&mut self, y: &SVector<f64, 6>) -> Result<(SVector<f64, 6>, Vector3<f64>), RouthError> {
        let (w, g) = (split3(y, 0), split3(y, 3));
        let (w_dot, g_dot) = self.0.eval(&w, &g)?;
        let mut d = SVector::<f64, 6>::zeros();
        d.fixed_rows_mut::<3>(0).copy_from(&w_dot);
        d.fixed_rows_mut::<3>(3).copy_from(&g_dot);
        // γ̇ = γ × ω = (−ω) × γ.
        Ok((d, -w))
    }
}

/// A field of `N` components extended by the attitude quaternion `q` at `y[N..N + 4]`, moved by
/// the angular velocity `ω` (full) or Ω (reduced) of `y[0..3]`: `q̇ = ½ q ⊗ (0, ω)` (module
/// [`attitude`]). For [`Method::Dop853`] only (the Lie method moves the attitude exactly).
struct WithAttitude<F>(F);

impl<'a, M: Lagrangian + ?Sized> Field<10> for WithAttitude<FullRhs<'a, M>> {
    #[inline(always)]
    fn eval(
        &mut self,
        y: &SVector<f64, 10>,
    ) -> Result<(SVector<f64, 10>, Vector3<f64>), RouthError> {
        let (d6, w) = self.0.eval(&y.fixed_rows::<6>(0).into_owned())?;
        let mut d = SVector::<f64, 10>::zeros();
        d.fixed_rows_mut::<6>(0).copy_from(&d6);
        attitude::write(
            &mut d,
            6,
            &attitude::rate(&attitude::read(y, 6), &split3(y, 0)),
        );
        Ok((d, w))
    }
}

impl<'a, M: Routhian + ?Sized> Field<11> for WithAttitude<ReducedRhs<'a, M>> {
    #[inline(always)]
    fn eval(
        &mut self,
        y: &SVector<f64, 11>,
    ) -> Result<(SVector<f64, 11>, Vector3<f64>), RouthError> {
        let (d7, w) = self.0.eval(&y.fixed_rows::<7>(0).into_owned())?;
        let mut d = SVector::<f64, 11>::zeros();
        d.fixed_rows_mut::<7>(0).copy_from(&d7);
        attitude::write(
            &mut d,
            7,
            &attitude::rate(&attitude::read(y, 7), &split3(y, 0)),
        );
        Ok((d, w))
    }
}

/// The state `(Ω, γ, ψ)` of (13), (15) on the level `p_psi`, and its rates.
struct ReducedRhs<'a, M: ?Sized>(ReducedField<'a, M>);

impl<M: Routhian + ?Sized> Field<7> for ReducedRhs<'_, M> {
    #[inline(always)]
    fn eval(&mut self, y: &SVector<f64, 7>) -> Result<(SVector<f64, 7>, Vector3<f64>), RouthError> {
        let (w, g) = (split3(y, 0), split3(y, 3));
        let (w_dot, g_dot, psi_dot) = self.0.eval(&w, &g)?;
        let mut d = SVector::<f64, 7>::zeros();
        d.fixed_rows_mut::<3>(0).copy_from(&w_dot);
        d.fixed_rows_mut::<3>(3).copy_from(&g_dot);
        d[6] = psi_dot;
        // γ̇ = γ × Ω = (−Ω) × γ.
        Ok((d, -w))
    }
}

/// `Err(NonFiniteState)` at the first recorded time where one of `columns` is not finite: the
/// integrators check the state, not the quantities recorded from it (energy, ψ̇, …), which can
/// overflow for a finite state (e.g. ω ≈ 1e200 after a fixed-step run went unstable). Found by
/// tests/runtime_properties.rs.
fn non_finite_record(t: &[f64], columns: &[&[f64]]) -> Result<(), RouthError> {
    let bad = (0..t.len()).find(|&i| columns.iter().any(|c| !c[i].is_finite()));
    match bad {
        Some(i) => Err(RouthError::NonFiniteState { t: t[i] }),
        None => Ok(()),
    }
}

/// Simulates the reduced equations (13) from `(Ω₀, γ₀)` at `t = 0` to `t_end` on the level
/// `p_ψ` of the cyclic momentum (9), and reconstructs the rotation angle ψ of the rotating frame
/// by (15), `ψ̇ = −∂R/∂p_ψ`, with `ψ(0) = 0`.
///
/// The equations are solved in the gauge of errata E4 (see [`reduced_vector_field`]):
/// `∂²R/∂Ω²` is singular along γ, the component of Ω along γ is a gauge, and the integration
/// keeps `Ω·γ` at its initial value. Ω₀ is used as given: the usual choice is `Ω₀·γ₀ = 0`, for
/// which `ψ̇` is the whole rotation rate about the vertical. With `Ω₀·γ₀ = s ≠ 0` the body motion
/// `ω = Ω + ψ̇γ` is the same and ψ differs by `s·t` (since `ψ̇(Ω + sγ) = ψ̇(Ω) − s` by (38)).
///
/// The full state corresponding to `(Ω₀, γ₀, p_ψ)` is `ω₀ = Ω₀ + ψ̇(Ω₀, γ₀, p_ψ) γ₀` (7), (12).
/// Recorded along the way: E' (16) (equal to E of (3)), `(∂R/∂Ω, γ)` (17) (identically p_ψ),
/// `|γ|²`, ψ̇ and the reconstructed ω.
///
/// # Errors
///
/// As [`simulate_full`] (an overflowing input is named `"p_psi"` or `"big_omega0"`), plus
/// [`RouthError::DegenerateVerticalInertia`] when
/// `γ₀ᵀJ(γ₀)γ₀ ≤ 0` (ψ̇ of (38) undefined), and
/// [`RouthError::SingularReducedKinetic`] when `∂²R/∂Ω² + cγγᵀ` has no Cholesky factor.
pub fn simulate_reduced<M: Routhian>(
    model: &M,
    big_omega0: Vector3<f64>,
    gamma0: Vector3<f64>,
    p_psi: f64,
    t_end: f64,
    opts: &SimOptions,
) -> Result<ReducedTrajectory, RouthError> {
    check_finite("big_omega0", big_omega0.as_slice())?;
    check_finite("gamma0", gamma0.as_slice())?;
    check_finite("p_psi", &[p_psi])?;
    validate(opts, t_end)?;
    check_unit_gamma(&gamma0)?;
    let vertical_inertia = gamma0.dot(&(model.d2l_domega2(&gamma0) * gamma0));
    // Also rejects NaN.
    if vertical_inertia.is_nan() || vertical_inertia <= 0.0 {
        return Err(RouthError::DegenerateVerticalInertia {
            gamma: [gamma0.x, gamma0.y, gamma0.z],
            value: vertical_inertia,
        });
    }
    // As in `simulate_full`, the recorded E' (16) and (17) must be finite at the start too.
    let finite_at = |w: &Vector3<f64>, p: f64| {
        reduced_vector_field(model, w, &gamma0, p).map(|(a, b, c)| {
            let r = model.bundle(w, &gamma0, p);
            let recorded = [r.dr_domega.dot(w) - r.routhian, r.dr_domega.dot(&gamma0)];
            all_finite(&a)
                && all_finite(&b)
                && c.is_finite()
                && recorded.iter().all(|x| x.is_finite())
        })
    };
    if !finite_at(&big_omega0, p_psi)? {
        let zero = Vector3::zeros();
        return Err(if !finite_at(&zero, 0.0)? {
            RouthError::NonFiniteModel {
                what: "reduced vector field (13) at Omega = 0, p_psi = 0",
                gamma: [gamma0.x, gamma0.y, gamma0.z],
            }
        } else if !finite_at(&zero, p_psi)? {
            too_large("p_psi", p_psi.abs(), "(13)")
        } else {
            too_large("big_omega0", stable_norm(big_omega0.as_slice()), "(13)")
        });
    }
    let mut y0 = SVector::<f64, 7>::zeros();
    y0.fixed_rows_mut::<3>(0).copy_from(&big_omega0);
    y0.fixed_rows_mut::<3>(3).copy_from(&gamma0);

    let mut traj = ReducedTrajectory::default();
    let mut record = |t: f64, y: &SVector<f64, 7>, q: Option<UnitQuaternion<f64>>| {
        let (w, g) = (split3(y, 0), split3(y, 3));
        if let Some(q) = q {
            // (15): R = R_z(ψ) R_Ω.
            traj.attitude.push(attitude::about_vertical(y[6]) * q);
        }
        // Only R, ∂R/∂Ω and ψ̇ (not the whole bundle, see `reduced_vector_field`).
        let (psi_dot, dr_domega) = (model.psi_dot(&w, &g, p_psi), model.dr_domega(&w, &g, p_psi));
        traj.t.push(t);
        traj.big_omega.push(w);
        traj.gamma.push(g);
        traj.psi.push(y[6]);
        traj.psi_dot.push(psi_dot);
        traj.omega.push(w + g * psi_dot);
        traj.energy
            .push(dr_domega.dot(&w) - model.routhian(&w, &g, p_psi));
        traj.p_psi.push(dr_domega.dot(&g));
        traj.gamma_norm_sq.push(g.norm_squared());
    };
    let q0 = opts.attitude.then(|| attitude::initial_attitude(&gamma0));
    let stats = match (q0, opts.method) {
        (Some(q0), Method::Dop853) => {
            let mut y0q = SVector::<f64, 11>::zeros();
            y0q.fixed_rows_mut::<7>(0).copy_from(&y0);
            attitude::write(&mut y0q, 7, q0.quaternion());
            let field = WithAttitude(ReducedRhs(ReducedField::new(model, p_psi)));
            drive(field, y0q, t_end, opts, None, |t, y, _| {
                let q = attitude::aligned(&attitude::read(y, 7), &split3(y, 3));
                record(t, &y.fixed_rows::<7>(0).into_owned(), Some(q))
            })?
        }
        (q0, _) => {
            let field = ReducedRhs(ReducedField::new(model, p_psi));
            drive(field, y0, t_end, opts, q0, |t, y, q| {
                record(t, y, q.copied())
            })?
        }
    };
    let omega: Vec<f64> = (traj.omega.iter())
        .map(|w| if all_finite(w) { 0.0 } else { f64::NAN })
        .collect();
    let columns = [
        &traj.psi[..],
        &traj.psi_dot,
        &omega,
        &traj.energy,
        &traj.p_psi,
    ];
    non_finite_record(&traj.t, &columns)?;
    traj.stats = stats;
    Ok(traj)
}

#[cfg(test)]
mod tests;
