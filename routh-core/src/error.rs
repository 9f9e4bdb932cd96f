//! The error type of the runtime: every failure is a value, no function of `routh-core` panics on
//! bad input.

use thiserror::Error;

/// Everything that can go wrong at run time. Each variant says which input or which computation
/// failed, with the offending value where there is one.
///
/// With the feature `serde` (default on) an error is a value like any result, for a batch of
/// runs that records its failures next to its results: JSON
/// `{"kind": "NonFinite", "what": "p_psi", "value": "NaN", "message": "non-finite input: p_psi = NaN"}`
/// (the variant, its fields, non-finite numbers as strings, and the `Display` message, which is
/// ignored when read back).
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum RouthError {
    /// An input (initial state, parameter, tolerance, time) is NaN or infinite.
    #[error("non-finite input: {what} = {value}")]
    NonFinite {
        /// The name of the input, as in the function's signature (e.g. `"p_psi"`, `"omega0"`).
        what: &'static str,
        /// The first non-finite value found in it.
        value: f64,
    },
    /// The model returned a non-finite value (NaN or ±∞) for one of its derivatives at this γ.
    #[error("the model's {what} is not finite at γ = {gamma:?}")]
    NonFiniteModel {
        /// Which output of the model (e.g. `"d2r_dgamma2"`).
        what: &'static str,
        /// Where it was evaluated.
        gamma: [f64; 3],
    },
    /// A unit vertical γ was required (|γ| = 1 within `tol`, the geometric integral (4)).
    #[error("{what} must be a unit vector: |{what}| = {norm} (tolerance {tol:e})")]
    NonUnitGamma {
        /// The name of the input, as in the function's signature (e.g. `"gamma0"`,
        /// `"steady.gamma"`).
        what: &'static str,
        /// The norm of the γ given.
        norm: f64,
        /// The tolerance on `| |γ| − 1 |` ([`UNIT_GAMMA_TOL`](crate::validate::UNIT_GAMMA_TOL)).
        tol: f64,
    },
    /// The kinetic form J(γ) = ∂²L/∂ω² is not positive definite at this γ.
    #[error("the kinetic form J(γ) is not positive definite at γ = {gamma:?} (smallest eigenvalue {min_eigenvalue:e})")]
    KineticNotPositiveDefinite {
        /// Where J was evaluated.
        gamma: [f64; 3],
        /// The smallest eigenvalue of the symmetric part of J (NaN if it could not be computed).
        min_eigenvalue: f64,
    },
    /// γᵀJ(γ)γ ≤ 0, so ψ̇ of (38) is undefined.
    #[error("γᵀJ(γ)γ = {value:e} ≤ 0 at γ = {gamma:?}: the reduction (12) is undefined")]
    DegenerateVerticalInertia {
        /// Where J was evaluated.
        gamma: [f64; 3],
        /// The value of γᵀJγ.
        value: f64,
    },
    /// The gauge-fixed reduced kinetic form `∂²R/∂Ω² + c·γγᵀ` (errata E4) is singular or not
    /// positive definite, so the reduced equations (13) cannot be solved for Ω̇; or, from
    /// [`classify`](crate::classify), its restriction `PᵀAP` to the tangent plane (63) (`A` of
    /// (64); the same eigenvalues on γ^⊥, since `A` annihilates γ) is not positive definite, so
    /// `f₂` (errata E5) is not a quartic.
    #[error("the reduced kinetic form ∂²R/∂Ω² + cγγᵀ is singular at γ = {gamma:?} (smallest eigenvalue {min_eigenvalue:e})")]
    SingularReducedKinetic {
        /// Where it was evaluated.
        gamma: [f64; 3],
        /// Its smallest eigenvalue (NaN if it could not be computed).
        min_eigenvalue: f64,
    },
    /// The γ given to [`classify`](crate::classify) is not a steady motion: the tangential part of
    /// `∂R/∂γ` (33) does not vanish there within the tolerance.
    #[error("γ = {gamma:?} is not a steady motion: |tangential ∂R/∂γ| = {residual:e} > {tol:e} (relative to the local scale)")]
    NotASteadyMotion {
        /// The γ given.
        gamma: [f64; 3],
        /// The norm of the tangential gradient of the amended potential, relative to the local
        /// scale of the restricted form.
        residual: f64,
        /// The relative tolerance it was compared with.
        tol: f64,
    },
    /// The model itself is invalid (e.g. a fluid body with a non-symmetric added-mass tensor).
    #[error("invalid model: {what}: {reason}")]
    InvalidModel {
        /// Which parameter of the model.
        what: &'static str,
        /// Why it is invalid.
        reason: String,
    },
    /// A failure while evaluating a family of models at the parameter value `s` (see
    /// [`families`](crate::families)): the family returned an invalid model or `p_ψ` there.
    #[error("at the family parameter s = {s}: {source}")]
    AtParameter {
        /// The parameter value.
        s: f64,
        /// What went wrong there.
        source: Box<RouthError>,
    },
    /// An invalid option (e.g. a negative tolerance) or argument (e.g. an empty range).
    #[error("invalid option {what}: {reason}")]
    InvalidOption {
        /// The option or argument.
        what: &'static str,
        /// Why it is invalid.
        reason: String,
    },
    /// The adaptive integrator's step size fell below what the floating-point time can resolve.
    #[error("step size underflow at t = {t}: h = {h:e}")]
    StepSizeUnderflow {
        /// The time reached.
        t: f64,
        /// The step size proposed.
        h: f64,
    },
    /// The integrator exceeded its step budget.
    #[error("too many steps ({steps}) before t = {t}")]
    TooManySteps {
        /// The time reached.
        t: f64,
        /// The budget ([`SimOptions::max_steps`](crate::SimOptions)).
        steps: usize,
    },
    /// The state became non-finite during integration.
    #[error("the solution became non-finite at t = {t}")]
    NonFiniteState {
        /// The time reached.
        t: f64,
    },
    /// The caller stopped the analysis (its [`RunControl`](crate::RunControl)'s cancel flag:
    /// Ctrl-C) before it had a result.
    #[error("interrupted: the analysis was cancelled by its caller")]
    Interrupted,
    /// An iterative method did not converge.
    #[error("no convergence in {what} after {iterations} iterations (residual {residual:e})")]
    NoConvergence {
        /// Which method.
        what: &'static str,
        /// The iterations (or steps) spent.
        iterations: usize,
        /// The best residual reached, relative to the method's scale.
        residual: f64,
    },
}
