//! A heavy ellipsoid on a frictionless horizontal plane, paper Example 2 ((43)–(51)) with
//! errata E1, E2, E6.

use nalgebra::{Matrix3, Vector3};
use num_dual::DualNum;
use rand::Rng;

use crate::random::{random_spd, random_vector};
use crate::vec3::{cross, dot, dot_const, lift, mat_vec, quad_form, scale, sub, V3};
use crate::GenericModel;

/// A convex body bounded by an ellipsoid, sliding without friction on the plane `X₃ = 0`.
///
/// The height of the centre of mass above the plane is the support function (errata E6)
/// `C₃(γ) = sqrt(γᵀDγ) − c₀·γ`, `D = diag(a₁², a₂², a₃²)`, with gradient
/// `n = ∂C₃/∂γ = Dγ/sqrt(γᵀDγ) − c₀`. The Lagrangian is (49) minus the potential of errata E2:
///
/// `L(ω, γ) = ½(ωᵀIω + m (n·(γ×ω))²) − m g C₃(γ)`,
///
/// and the Routh function is (51) with the ½ of errata E1 (`γᵀJγ = γᵀIγ`, E6):
///
/// `R = ½(ΩᵀIΩ + m (n·(γ×Ω))²) − ½(p_ψ − (IΩ)·γ)²/(γᵀIγ) − m g C₃(γ)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Ellipsoid {
    /// Central inertia tensor `I` (symmetric positive definite).
    pub inertia: Matrix3<f64>,
    /// Semi-axes `(a₁, a₂, a₃)` along the body axes.
    pub semi_axes: Vector3<f64>,
    /// Position `c₀` of the ellipsoid's centre relative to the centre of mass (body frame).
    pub offset: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravitational acceleration `g` (gravity acts along −γ).
    pub g: f64,
}

impl Ellipsoid {
    /// An ellipsoid from all its parameters.
    pub fn new(
        inertia: Matrix3<f64>,
        semi_axes: Vector3<f64>,
        offset: Vector3<f64>,
        mass: f64,
        g: f64,
    ) -> Self {
        Ellipsoid {
            inertia,
            semi_axes,
            offset,
            mass,
            g,
        }
    }

    /// A homogeneous solid ellipsoid: `I = m/5 · diag(a₂² + a₃², a₁² + a₃², a₁² + a₂²)`,
    /// `c₀ = 0`.
    pub fn homogeneous(semi_axes: Vector3<f64>, mass: f64, g: f64) -> Self {
        let s = semi_axes.component_mul(&semi_axes);
        let inertia =
            Matrix3::from_diagonal(&Vector3::new(s.y + s.z, s.x + s.z, s.x + s.y)) * (mass / 5.0);
        Ellipsoid {
            inertia,
            semi_axes,
            offset: Vector3::zeros(),
            mass,
            g,
        }
    }

    /// A generic model: random SPD inertia (eigenvalues in `[1, 3]`), semi-axes in
    /// `[0.5, 1.5]`, offset in `[−0.2, 0.2]³`, `m ∈ [0.5, 2]`, `g = 9.81`.
    pub fn random<R: Rng + ?Sized>(rng: &mut R) -> Self {
        Ellipsoid {
            inertia: random_spd(rng),
            semi_axes: Vector3::from_fn(|_, _| rng.gen_range(0.5..1.5)),
            offset: random_vector(rng, 0.2),
            mass: rng.gen_range(0.5..2.0),
            g: 9.81,
        }
    }

    /// `D = diag(a₁², a₂², a₃²)`.
    pub fn shape_matrix(&self) -> Matrix3<f64> {
        Matrix3::from_diagonal(&self.semi_axes.component_mul(&self.semi_axes))
    }

    /// The height `C₃(γ)` of the centre of mass above the plane (46), errata E6.
    pub fn height(&self, gamma: &Vector3<f64>) -> f64 {
        self.height_generic(&lift::<f64>(gamma))
    }

    /// `n = ∂C₃/∂γ = Dγ/sqrt(γᵀDγ) − c₀`.
    pub fn height_gradient(&self, gamma: &Vector3<f64>) -> Vector3<f64> {
        crate::vec3::re(&self.height_gradient_generic(&lift::<f64>(gamma)))
    }

    fn height_generic<D: DualNum<f64> + Copy>(&self, gamma: &V3<D>) -> D {
        quad_form(&self.shape_matrix(), gamma).sqrt() - dot_const(&self.offset, gamma)
    }

    fn height_gradient_generic<D: DualNum<f64> + Copy>(&self, gamma: &V3<D>) -> V3<D> {
        let dmat = self.shape_matrix();
        let d_gamma = mat_vec(&dmat, gamma);
        let s = dot(gamma, &d_gamma).sqrt();
        sub(&scale(&d_gamma, s.recip()), &lift(&self.offset))
    }

    /// `½(xᵀIx + m (n·(γ×x))²)`: the kinetic energy (49) as a function of ω or Ω.
    fn kinetic_generic<D: DualNum<f64> + Copy>(&self, x: &V3<D>, gamma: &V3<D>) -> D {
        let n = self.height_gradient_generic(gamma);
        let v = dot(&n, &cross(gamma, x));
        (quad_form(&self.inertia, x) + v * v * self.mass) * 0.5
    }
}

impl GenericModel for Ellipsoid {
    fn lagrangian_generic<D: DualNum<f64> + Copy>(&self, omega: &V3<D>, gamma: &V3<D>) -> D {
        self.kinetic_generic(omega, gamma) - self.height_generic(gamma) * (self.mass * self.g)
    }

    fn routhian_generic<D: DualNum<f64> + Copy>(
        &self,
        big_omega: &V3<D>,
        gamma: &V3<D>,
        p_psi: D,
    ) -> D {
        // (51) with errata E1 (the ½), E2 (sign of U) and E6 (γᵀJγ = γᵀIγ).
        let d = p_psi - dot(&mat_vec(&self.inertia, big_omega), gamma);
        let c = quad_form(&self.inertia, gamma);
        self.kinetic_generic(big_omega, gamma)
            - d * d / c * 0.5
            - self.height_generic(gamma) * (self.mass * self.g)
    }

    fn psi_dot_closed_form(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> f64 {
        // (38) with a = 0 and, by errata E6, (JΩ)·γ = (IΩ)·γ, γᵀJγ = γᵀIγ.
        let q = (self.inertia * big_omega).dot(gamma);
        (p_psi - q) / gamma.dot(&(self.inertia * gamma))
    }
}

crate::impl_numdual_traits!(Ellipsoid);
