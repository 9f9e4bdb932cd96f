//! The vector fields of the full equations (8) and of the reduced equations (13), apart from the
//! integrator drivers that use them.

use nalgebra::{Matrix3, Vector3};

use crate::model::{Lagrangian, Routhian};
use crate::validate::{gamma_array, min_eigenvalue};
use crate::RouthError;

/// The vector field of the full equations (8) solved for ω̇:
/// `J ω̇ = ∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)`, `γ̇ = γ × ω`, with `J = ∂²L/∂ω²`
/// (docs/method.md §2). Returns `(ω̇, γ̇)`.
///
/// Errors: [`RouthError::KineticNotPositiveDefinite`] when the Cholesky factorisation of a
/// finite `J(γ)` fails. Non-finite model outputs give non-finite rates (no error), so that an
/// integrator can shrink its step.
pub fn full_vector_field<M: Lagrangian + ?Sized>(
    model: &M,
    omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
) -> Result<(Vector3<f64>, Vector3<f64>), RouthError> {
    let gamma_dot = gamma.cross(omega);
    let j = model.d2l_domega2(gamma);
    let rhs = model.dl_domega(omega, gamma).cross(omega)
        + model.dl_dgamma(omega, gamma).cross(gamma)
        - model.d2l_domega_dgamma(omega, gamma) * gamma_dot;
    let omega_dot = solve_spd(&j, &rhs, gamma, |k, g| {
        RouthError::KineticNotPositiveDefinite {
            gamma: gamma_array(g),
            min_eigenvalue: min_eigenvalue(k),
        }
    })?;
    Ok((omega_dot, gamma_dot))
}

/// The vector field of the reduced equations (13) in the gauge of errata E4, with (15):
/// `(A + c γγᵀ) Ω̇ = ∂R/∂Ω × Ω + ∂R/∂γ × γ − M γ̇`, `γ̇ = γ × Ω`, `ψ̇ = −∂R/∂p_ψ`, where
/// `A = ∂²R/∂Ω²`, `M = ∂²R/∂Ω∂γ`, all from one [`Routhian::bundle`], and `c = tr(A)/2`.
/// Returns `(Ω̇, γ̇, ψ̇)`.
///
/// # The gauge
///
/// `A` annihilates γ (E4), so the γ-component of (13) is an identity and Ω̇ is fixed only up to a
/// multiple of γ; adding `c γγᵀ` for any `c > 0` picks the one with `Ω̇·γ = 0`. The gauge is
/// exact for every c: the right side is orthogonal to γ (by `Mᵀγ = −∂R/∂Ω`, E6), `A` maps γ^⊥
/// into γ^⊥, and `(A + cγγᵀ)γ = c|γ|²γ`, so the solution has no γ-component when `|γ| = 1`;
/// with `γ̇·Ω = 0` this keeps `Ω·γ` at its initial value.
///
/// The value of c matters only in floating point. It must carry the units of `A` (those of the
/// inertia J): with `c = 1` and J in units 1e9 times smaller (the same body in other units), the
/// round-off of the right side along γ, about `ε·|J||Ω|²`, is divided by 1 instead of by `|J|`
/// and pushes Ω off the gauge by `1e9·ε` per step, so that the error control fails ("too many
/// steps"); in units 1e9 times larger, Cholesky of `A + γγᵀ` mixes eigenvalues 1e−9 and 1 and
/// loses 9 digits of Ω̇. `c = tr(A)/2` is the mean of the two non-zero eigenvalues of A
/// (A is positive semi-definite with kernel γ), so `A + cγγᵀ` is exactly as well conditioned as
/// A on γ^⊥, and c scales with J and is invariant under rotations of the body frame. It is
/// computed as `A₁₁/2 + A₂₂/2 + A₃₃/2`, which overflows only if an entry of A does.
///
/// Errors: [`RouthError::SingularReducedKinetic`] (with the smallest eigenvalue of
/// `A + cγγᵀ`) when its Cholesky factorisation fails for finite entries.
pub fn reduced_vector_field<M: Routhian + ?Sized>(
    model: &M,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> Result<(Vector3<f64>, Vector3<f64>, f64), RouthError> {
    let b = model.bundle(big_omega, gamma, p_psi);
    let gamma_dot = gamma.cross(big_omega);
    let rhs =
        b.dr_domega.cross(big_omega) + b.dr_dgamma.cross(gamma) - b.d2r_domega_dgamma * gamma_dot;
    let a = &b.d2r_domega2;
    let gauge = 0.5 * a[(0, 0)] + 0.5 * a[(1, 1)] + 0.5 * a[(2, 2)];
    let k = a + gamma * gamma.transpose() * gauge;
    let big_omega_dot = solve_spd(&k, &rhs, gamma, |k, g| RouthError::SingularReducedKinetic {
        gamma: gamma_array(g),
        min_eigenvalue: min_eigenvalue(k),
    })?;
    Ok((big_omega_dot, gamma_dot, -b.dr_dp))
}

/// Solves `K x = rhs` by Cholesky; non-finite `K` or `rhs` give a NaN solution.
fn solve_spd(
    k: &Matrix3<f64>,
    rhs: &Vector3<f64>,
    gamma: &Vector3<f64>,
    error: impl Fn(&Matrix3<f64>, &Vector3<f64>) -> RouthError,
) -> Result<Vector3<f64>, RouthError> {
    if !(k.iter().all(|x| x.is_finite()) && rhs.iter().all(|x| x.is_finite())) {
        return Ok(Vector3::repeat(f64::NAN));
    }
    match k.cholesky() {
        Some(ch) => Ok(ch.solve(rhs)),
        None => Err(error(k, gamma)),
    }
}
