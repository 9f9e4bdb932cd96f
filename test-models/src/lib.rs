//! Reference models shared by `routh`'s tests and benches.
//!
//! Every model here is written twice by hand, as a generic Lagrangian `L(ω, γ)` and as a generic
//! closed-form Routh function `R(Ω, γ, p_ψ)` (paper (39) and its Example 2 form (51) with the
//! corrections of errata E1, E2, E6), and all derivatives are computed by forward-mode automatic
//! differentiation with [`num_dual`] (second-order dual numbers). The models are therefore
//! independent of `routh`'s symbolic code generator, and the two hand-written forms check each
//! other through the identities (14), (18), (19) and Theorem 2 (see the unit tests).
//!
//! - [`Gyrostat`]: `L = ½ωᵀIω + (K + Bγ)·ω − m g r·γ` (paper (35) with `A(γ) = K + Bγ`); the
//!   heavy (Lagrange or asymmetric) top is `K = B = 0`.
//! - [`Ellipsoid`]: a heavy ellipsoid on a frictionless horizontal plane (paper Example 2).
//! - [`HeavyTop`]: a heavy top with its Routh function and every derivative in closed form (no
//!   automatic differentiation), a second reference for the analysis tests.
//!
//! [`jacobian`] linearises the full equations (8) by finite differences and matches the roots of
//! f₂ to the eigenvalues (errata E5). The models declared with `#[derive(Lagrangian)]`, each
//! beside its twin here, are in the companion crate `derived-models` (`test-models/derived`):
//! they need the facade `routh`, which this crate must not depend on, because routh-core's own
//! tests use this crate.
//!
//! [`numdual_bundle`] evaluates every output of the Routh function with one num-dual Hessian over
//! `(Ω, γ)` (plus a first-order dual in `p_ψ`): it is the "num-dual Hessians of the same R"
//! baseline that the benches compare generated code against.
//!
//! [`runtime_properties`] is the runtime property test's harness (random and extreme inputs to
//! every public function of routh-core): routh-core's test runs its cases on the models here, the
//! facade's test its cases on the derived gyrostat.
#![forbid(unsafe_code)]

mod ellipsoid;
mod gyrostat;
mod hand;
pub use hand::{hand_gyrostat_bundle, hand_gyrostat_bundle_and_system, hand_gyrostat_system};
pub mod birkhoff;
pub mod compare;
mod heavy_top;
pub mod identities;
pub mod jacobian;
mod numdual;
mod random;
pub mod roots;
pub mod runtime_properties;
pub mod vec3;

pub use ellipsoid::Ellipsoid;
pub use gyrostat::Gyrostat;
pub use heavy_top::{HeavyTop, Potential, PotentialBody, PotentialTerms};
pub use numdual::{
    numdual_bundle, numdual_dr_dp, numdual_lagrangian_gradient, numdual_lagrangian_hessian,
    numdual_routhian_gradient, numdual_routhian_hessian, GenericModel,
};
pub use random::{
    random_gamma, random_matrix, random_spd, random_tangent, random_unit_vector, random_vector,
};

/// Paths used by [`impl_numdual_traits!`]; not part of the API.
#[doc(hidden)]
pub mod __private {
    pub use nalgebra::{Matrix3, Vector3};
    pub use routh_core::{Lagrangian, RouthBundle, Routhian};
}

#[cfg(test)]
mod tests;
