//! One evaluation of the model at a point γ of the sphere: the amended potential and its first
//! and second derivatives there, shared by the search of steady motions (`steady/search`) and the
//! equations of their families (`families/equations.rs`).

use nalgebra::{Matrix2, Matrix3, Matrix3x2, Vector3};

use super::{restricted_hessian, tangent_basis, Tangential};
use crate::error::RouthError;
use crate::model::Routhian;
use crate::solve::zero::tangential_scale;
use crate::validate::{check_kinetic, check_model_finite};

/// The amended potential `U_r = −R(0, γ, p_ψ)` and its derivatives at one γ, from one
/// evaluation of the model at `Ω = 0` (γ differentiated as a free vector of ℝ³, errata).
///
/// The derivatives are kept as the model returns them (the Riemannian quantities of the search,
/// [`Local::tangential_quantities`], are formed from exactly these); the families' equations read
/// them as `∇U_r` ([`Local::grad`]) and `H` ([`Local::hess`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Local {
    pub gamma: Vector3<f64>,
    /// `U_r = −R(0, γ, p_ψ)`.
    pub u_r: f64,
    /// `∂R/∂γ` at `Ω = 0`.
    pub dr_dgamma: Vector3<f64>,
    /// `∂²R/∂γ²` at `Ω = 0`.
    pub d2r_dgamma2: Matrix3<f64>,
}

impl Local {
    /// The model at `(Ω = 0, γ, p_ψ)`, unchecked (see [`Local::is_finite`]).
    #[inline(always)]
    pub fn evaluate<M: Routhian>(model: &M, gamma: &Vector3<f64>, p_psi: f64) -> Self {
        let b = model.bundle(&Vector3::zeros(), gamma, p_psi);
        Local {
            gamma: *gamma,
            u_r: -b.routhian,
            dr_dgamma: b.dr_dgamma,
            d2r_dgamma2: b.d2r_dgamma2,
        }
    }

    /// [`Local::evaluate`] where the kinetic form is positive definite, with the derivatives
    /// checked finite (errors name the model's function and γ).
    pub fn at<M: Routhian>(model: &M, gamma: &Vector3<f64>, p: f64) -> Result<Self, RouthError> {
        check_kinetic(model, gamma)?;
        let l = Self::evaluate(model, gamma, p);
        check_model_finite("dr_dgamma", l.dr_dgamma.as_slice(), gamma)?;
        check_model_finite("d2r_dgamma2", l.d2r_dgamma2.as_slice(), gamma)?;
        Ok(l)
    }

    /// Whether `U_r` and its derivatives are all finite.
    #[inline(always)]
    pub fn is_finite(&self) -> bool {
        self.u_r.is_finite()
            && self.dr_dgamma.iter().all(|v| v.is_finite())
            && self.d2r_dgamma2.iter().all(|v| v.is_finite())
    }

    /// The Riemannian quantities at γ ([`Tangential`]: the gradient `g`, the restricted second
    /// variation `K` (62)–(63), their scales) in the basis `tangent_basis(γ)`, given; `rel` the
    /// relative zero-eigenvalue tolerance.
    #[inline(always)]
    pub fn tangential_quantities(&self, basis: Matrix3x2<f64>, rel: f64) -> Tangential {
        Tangential::with_basis(&self.gamma, basis, &self.dr_dgamma, &self.d2r_dgamma2, rel)
    }

    /// `∇U_r = −∂R/∂γ`.
    pub fn grad(&self) -> Vector3<f64> {
        -self.dr_dgamma
    }

    /// `H = −∂²R/∂γ²`, symmetrised.
    pub fn hess(&self) -> Matrix3<f64> {
        let h = -self.d2r_dgamma2;
        0.5 * (h + h.transpose())
    }

    /// The tangential gradient `t = (E − γγᵀ)∇U_r`, zero at a steady motion (33).
    pub fn tangential(&self) -> Vector3<f64> {
        let grad = self.grad();
        grad - self.gamma * self.gamma.dot(&grad)
    }

    /// `∂t/∂γ = (E − γγᵀ)H − (γ·∇U_r)E − γ∇U_rᵀ` as a 3×3 map on tangent vectors (the derivative
    /// of [`Local::tangential`], γ a free vector).
    pub fn dt_dgamma(&self) -> Matrix3<f64> {
        let (grad, hess) = (self.grad(), self.hess());
        let g = self.gamma;
        let proj = Matrix3::identity() - g * g.transpose();
        proj * hess - Matrix3::from_diagonal_element(g.dot(&grad)) - g * grad.transpose()
    }

    /// The restricted second variation `K` (62)–(63) in the basis `tangent_basis(γ)`.
    pub fn restricted(&self) -> Matrix2<f64> {
        let p = tangent_basis(&self.gamma);
        // K = Pᵀ(μE − ∂²R/∂γ²)P with μ = (∂R/∂γ, γ) = −(∇U_r, γ).
        restricted_hessian(&p, -self.grad().dot(&self.gamma), &(-self.hess()))
    }

    /// The local tangential scale [`tangential_scale`] at this point: linear in the units of the
    /// Lagrangian and unchanged by adding `k|γ|²` to `U` (docs/method.md §5). The residual of the
    /// continuation's corrector and the test functions of the atlas are relative to it.
    pub fn scale(&self) -> f64 {
        tangential_scale(&self.gamma, &self.grad(), &self.hess())
    }
}
