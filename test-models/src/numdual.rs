//! Derivatives of hand-written generic `L` and `R` by num-dual, and the trait implementations
//! built from them ([`impl_numdual_traits!`](crate::impl_numdual_traits)).

use nalgebra::{Matrix3, SMatrix, SVector, Vector3};
use num_dual::{first_derivative, gradient, hessian, Dual2SVec64, Dual64, DualNum, DualSVec64};
use routh_core::RouthBundle;

use crate::vec3::{lift, V3};

/// A model written by hand as a generic Lagrangian and a generic closed-form Routh function.
///
/// Both functions must hold for every `γ ∈ ℝ³` (γ is an unconstrained vector when
/// differentiating, paper (18)–(19)), and `routhian_generic` must equal (14):
/// `R(Ω, γ, p_ψ) = L(Ω + ψ̇γ, γ) − ψ̇ p_ψ` with `ψ̇` from (12).
pub trait GenericModel {
    /// `L(ω, γ)`.
    fn lagrangian_generic<D: DualNum<f64> + Copy>(&self, omega: &V3<D>, gamma: &V3<D>) -> D;
    /// `R(Ω, γ, p_ψ)` in closed form ((39) generalised).
    fn routhian_generic<D: DualNum<f64> + Copy>(
        &self,
        big_omega: &V3<D>,
        gamma: &V3<D>,
        p_psi: D,
    ) -> D;
    /// `ψ̇(Ω, γ, p_ψ)` in closed form ((38) generalised to `J(γ)`).
    fn psi_dot_closed_form(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> f64;
}

fn stack(a: &Vector3<f64>, b: &Vector3<f64>) -> SVector<f64, 6> {
    SVector::<f64, 6>::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

fn split<T: Copy>(x: &SVector<T, 6>) -> (V3<T>, V3<T>) {
    ([x[0], x[1], x[2]], [x[3], x[4], x[5]])
}

/// The 3×3 block of a 6×6 matrix starting at `(row, col)`.
pub(crate) fn block(m: &SMatrix<f64, 6, 6>, row: usize, col: usize) -> Matrix3<f64> {
    m.fixed_view::<3, 3>(row, col).into_owned()
}

/// `(L, ∂L/∂ω, ∂L/∂γ)` by one first-order num-dual pass over the six variables `(ω, γ)`.
pub fn numdual_lagrangian_gradient<M: GenericModel + ?Sized>(
    model: &M,
    omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
) -> (f64, Vector3<f64>, Vector3<f64>) {
    let (l, g) = gradient(
        |x: SVector<DualSVec64<6>, 6>| {
            let (w, c) = split(&x);
            model.lagrangian_generic(&w, &c)
        },
        stack(omega, gamma),
    );
    (
        l,
        g.fixed_rows::<3>(0).into_owned(),
        g.fixed_rows::<3>(3).into_owned(),
    )
}

/// `(L, ∇L, ∇²L)` over `(ω, γ)` (in this order) by one second-order num-dual pass.
pub fn numdual_lagrangian_hessian<M: GenericModel + ?Sized>(
    model: &M,
    omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
) -> (f64, SVector<f64, 6>, SMatrix<f64, 6, 6>) {
    hessian(
        |x: SVector<Dual2SVec64<6>, 6>| {
            let (w, c) = split(&x);
            model.lagrangian_generic(&w, &c)
        },
        stack(omega, gamma),
    )
}

/// `(R, ∂R/∂Ω, ∂R/∂γ)` by one first-order num-dual pass over `(Ω, γ)` at fixed `p_ψ`.
pub fn numdual_routhian_gradient<M: GenericModel + ?Sized>(
    model: &M,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> (f64, Vector3<f64>, Vector3<f64>) {
    let (r, g) = gradient(
        |x: SVector<DualSVec64<6>, 6>| {
            let (w, c) = split(&x);
            model.routhian_generic(&w, &c, DualSVec64::<6>::from(p_psi))
        },
        stack(big_omega, gamma),
    );
    (
        r,
        g.fixed_rows::<3>(0).into_owned(),
        g.fixed_rows::<3>(3).into_owned(),
    )
}

/// `(R, ∇R, ∇²R)` over `(Ω, γ)` (in this order) at fixed `p_ψ`, by one second-order pass.
pub fn numdual_routhian_hessian<M: GenericModel + ?Sized>(
    model: &M,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> (f64, SVector<f64, 6>, SMatrix<f64, 6, 6>) {
    hessian(
        |x: SVector<Dual2SVec64<6>, 6>| {
            let (w, c) = split(&x);
            model.routhian_generic(&w, &c, Dual2SVec64::<6>::from(p_psi))
        },
        stack(big_omega, gamma),
    )
}

/// `∂R/∂p_ψ` by a first-order dual number in `p_ψ` (it must equal `−ψ̇`, (15)).
pub fn numdual_dr_dp<M: GenericModel + ?Sized>(
    model: &M,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> f64 {
    let w: V3<Dual64> = lift(big_omega);
    let c: V3<Dual64> = lift(gamma);
    first_derivative(|p| model.routhian_generic(&w, &c, p), p_psi).1
}

/// Every output of the Routh function from ONE num-dual Hessian over `(Ω, γ)`, one first-order
/// dual in `p_ψ` (for `∂R/∂p_ψ`) and the closed form of `ψ̇`.
pub fn numdual_bundle<M: GenericModel + ?Sized>(
    model: &M,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> RouthBundle {
    let (r, g, h) = numdual_routhian_hessian(model, big_omega, gamma, p_psi);
    RouthBundle {
        routhian: r,
        psi_dot: model.psi_dot_closed_form(big_omega, gamma, p_psi),
        dr_domega: g.fixed_rows::<3>(0).into_owned(),
        dr_dgamma: g.fixed_rows::<3>(3).into_owned(),
        dr_dp: numdual_dr_dp(model, big_omega, gamma, p_psi),
        d2r_domega2: block(&h, 0, 0),
        d2r_domega_dgamma: block(&h, 0, 3),
        d2r_dgamma2: block(&h, 3, 3),
    }
}

/// Implements `routh_core::{Lagrangian, Routhian}` for a type that implements
/// [`GenericModel`](crate::GenericModel): values from the generic functions at `f64`, gradients
/// and Hessians by num-dual, `psi_dot` from the closed form, `dr_dp` by num-dual and `bundle`
/// by [`numdual_bundle`](crate::numdual_bundle). `energy`, `cyclic_momentum`,
/// `amended_potential` and `gyroscopic_system` keep the trait defaults.
#[macro_export]
macro_rules! impl_numdual_traits {
    ($t:ty) => {
        impl $crate::__private::Lagrangian for $t {
            fn lagrangian(
                &self,
                omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
            ) -> f64 {
                $crate::GenericModel::lagrangian_generic::<f64>(
                    self,
                    &[omega.x, omega.y, omega.z],
                    &[gamma.x, gamma.y, gamma.z],
                )
            }
            fn dl_domega(
                &self,
                omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
            ) -> $crate::__private::Vector3<f64> {
                $crate::numdual_lagrangian_gradient(self, omega, gamma).1
            }
            fn dl_dgamma(
                &self,
                omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
            ) -> $crate::__private::Vector3<f64> {
                $crate::numdual_lagrangian_gradient(self, omega, gamma).2
            }
            fn d2l_domega2(
                &self,
                gamma: &$crate::__private::Vector3<f64>,
            ) -> $crate::__private::Matrix3<f64> {
                let h = $crate::numdual_lagrangian_hessian(
                    self,
                    &$crate::__private::Vector3::zeros(),
                    gamma,
                )
                .2;
                h.fixed_view::<3, 3>(0, 0).into_owned()
            }
            fn d2l_domega_dgamma(
                &self,
                omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
            ) -> $crate::__private::Matrix3<f64> {
                let h = $crate::numdual_lagrangian_hessian(self, omega, gamma).2;
                h.fixed_view::<3, 3>(0, 3).into_owned()
            }
        }

        impl $crate::__private::Routhian for $t {
            fn psi_dot(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> f64 {
                $crate::GenericModel::psi_dot_closed_form(self, big_omega, gamma, p_psi)
            }
            fn routhian(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> f64 {
                $crate::GenericModel::routhian_generic::<f64>(
                    self,
                    &[big_omega.x, big_omega.y, big_omega.z],
                    &[gamma.x, gamma.y, gamma.z],
                    p_psi,
                )
            }
            fn dr_domega(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> $crate::__private::Vector3<f64> {
                $crate::numdual_routhian_gradient(self, big_omega, gamma, p_psi).1
            }
            fn dr_dgamma(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> $crate::__private::Vector3<f64> {
                $crate::numdual_routhian_gradient(self, big_omega, gamma, p_psi).2
            }
            fn dr_dp(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> f64 {
                $crate::numdual_dr_dp(self, big_omega, gamma, p_psi)
            }
            fn d2r_domega2(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> $crate::__private::Matrix3<f64> {
                let h = $crate::numdual_routhian_hessian(self, big_omega, gamma, p_psi).2;
                h.fixed_view::<3, 3>(0, 0).into_owned()
            }
            fn d2r_domega_dgamma(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> $crate::__private::Matrix3<f64> {
                let h = $crate::numdual_routhian_hessian(self, big_omega, gamma, p_psi).2;
                h.fixed_view::<3, 3>(0, 3).into_owned()
            }
            fn d2r_dgamma2(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> $crate::__private::Matrix3<f64> {
                let h = $crate::numdual_routhian_hessian(self, big_omega, gamma, p_psi).2;
                h.fixed_view::<3, 3>(3, 3).into_owned()
            }
            fn bundle(
                &self,
                big_omega: &$crate::__private::Vector3<f64>,
                gamma: &$crate::__private::Vector3<f64>,
                p_psi: f64,
            ) -> $crate::__private::RouthBundle {
                $crate::numdual_bundle(self, big_omega, gamma, p_psi)
            }
        }
    };
}
