use thiserror::Error;

/// Everything that can go wrong at run time. Errors are values: no function of `routh-core`
/// panics on bad input.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum RouthError {
    /// An input (initial state, parameter, tolerance, time) is NaN or infinite.
    #[error("non-finite input: {what} = {value}")]
    NonFinite { what: &'static str, value: f64 },
    /// A unit vertical γ was required (|γ| = 1 within `tol`).
    #[error("γ must be a unit vector: |γ| = {norm} (tolerance {tol:e})")]
    NonUnitGamma { norm: f64, tol: f64 },
    /// The kinetic form J(γ) = ∂²L/∂ω² is not positive definite at this γ.
    #[error("the kinetic form J(γ) is not positive definite at γ = {gamma:?} (smallest eigenvalue {min_eigenvalue:e})")]
    KineticNotPositiveDefinite {
        gamma: [f64; 3],
        min_eigenvalue: f64,
    },
    /// γᵀJ(γ)γ ≤ 0, so ψ̇ of (38) is undefined.
    #[error("γᵀJ(γ)γ = {value:e} ≤ 0 at γ = {gamma:?}: the reduction (12) is undefined")]
    DegenerateVerticalInertia { gamma: [f64; 3], value: f64 },
    /// An invalid option (e.g. a negative tolerance).
    #[error("invalid option {what}: {reason}")]
    InvalidOption { what: &'static str, reason: String },
    /// The adaptive integrator's step size fell below what the floating-point time can resolve.
    #[error("step size underflow at t = {t}: h = {h:e}")]
    StepSizeUnderflow { t: f64, h: f64 },
    /// The integrator exceeded its step budget.
    #[error("too many steps ({steps}) before t = {t}")]
    TooManySteps { t: f64, steps: usize },
    /// The state became non-finite during integration.
    #[error("the solution became non-finite at t = {t}")]
    NonFiniteState { t: f64 },
    /// An iterative method did not converge.
    #[error("no convergence in {what} after {iterations} iterations (residual {residual:e})")]
    NoConvergence {
        what: &'static str,
        iterations: usize,
        residual: f64,
    },
}

/// Checks that every component of `v` is finite.
pub(crate) fn check_finite(what: &'static str, values: &[f64]) -> Result<(), RouthError> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(&value) => Err(RouthError::NonFinite { what, value }),
        None => Ok(()),
    }
}
