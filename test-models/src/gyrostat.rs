//! The Kelvin gyrostat with a linear gyroscopic term, paper Example 1 ((35)–(40)).

use nalgebra::{Matrix3, Vector3};
use num_dual::DualNum;
use rand::Rng;

use crate::random::{random_matrix, random_spd, random_vector};
use crate::vec3::{add, dot, dot_const, mat_vec, quad_form, V3};
use crate::GenericModel;

/// A heavy rigid body about a fixed point carrying a rotor, with a gyroscopic vector linear in
/// γ (paper (35) with `A(γ) = K + Bγ`, `U = m g r·γ`):
///
/// `L(ω, γ) = ½ωᵀIω + (K + Bγ)·ω − m g r·γ`.
///
/// Its Routh function is (39): with `a = K + Bγ`,
/// `R = ½ΩᵀIΩ + a·Ω − m g r·γ − ½(p_ψ − (IΩ)·γ − a·γ)²/(γᵀIγ)`, and `ψ̇` is (38).
/// `K = B = 0` is the heavy top (Lagrange top when `I = diag(A, A, C)` and `r ∥ e₃`).
#[derive(Debug, Clone, PartialEq)]
pub struct Gyrostat {
    /// Inertia tensor `I` about the fixed point (symmetric positive definite).
    pub inertia: Matrix3<f64>,
    /// Constant gyrostatic momentum `K` of the rotor.
    pub rotor: Vector3<f64>,
    /// Coupling matrix `B` of the linear gyroscopic term `Bγ`.
    pub coupling: Matrix3<f64>,
    /// Centre of mass `r` in the body frame (relative to the fixed point).
    pub com: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravitational acceleration `g` (gravity acts along −γ).
    pub g: f64,
}

impl Gyrostat {
    /// A gyrostat from all its parameters.
    pub fn new(
        inertia: Matrix3<f64>,
        rotor: Vector3<f64>,
        coupling: Matrix3<f64>,
        com: Vector3<f64>,
        mass: f64,
        g: f64,
    ) -> Self {
        Gyrostat {
            inertia,
            rotor,
            coupling,
            com,
            mass,
            g,
        }
    }

    /// A heavy top (`K = B = 0`) with principal moments `inertia_diag` and centre of mass `com`
    /// (any body vector: off-axis gives an asymmetric heavy top).
    pub fn heavy_top(inertia_diag: Vector3<f64>, com: Vector3<f64>, mass: f64, g: f64) -> Self {
        Gyrostat {
            inertia: Matrix3::from_diagonal(&inertia_diag),
            rotor: Vector3::zeros(),
            coupling: Matrix3::zeros(),
            com,
            mass,
            g,
        }
    }

    /// The Lagrange top: `I = diag(a1, a1, c)`, centre of mass on the symmetry axis with
    /// `m g l = mgl` (`U = mgl·γ₃`), realised as `mass = 1`, `g = mgl`, `com = e₃`.
    pub fn lagrange_top(a1: f64, c: f64, mgl: f64) -> Self {
        Self::heavy_top(Vector3::new(a1, a1, c), Vector3::z(), 1.0, mgl)
    }

    /// A generic asymmetric gyrostat: random SPD inertia with eigenvalues in `[1, 3]`, rotor
    /// and coupling entries in `[−0.5, 0.5]`, centre of mass in `[−1, 1]³`, `m ∈ [0.5, 2]`,
    /// `g = 9.81`.
    pub fn random<R: Rng + ?Sized>(rng: &mut R) -> Self {
        Gyrostat {
            inertia: random_spd(rng),
            rotor: random_vector(rng, 0.5),
            coupling: random_matrix(rng, 0.5),
            com: random_vector(rng, 1.0),
            mass: rng.gen_range(0.5..2.0),
            g: 9.81,
        }
    }

    /// The gyroscopic vector `a(γ) = K + Bγ` of (35).
    pub fn linear_term(&self, gamma: &Vector3<f64>) -> Vector3<f64> {
        self.rotor + self.coupling * gamma
    }

    fn linear_generic<D: DualNum<f64> + Copy>(&self, gamma: &V3<D>) -> V3<D> {
        let bg = mat_vec(&self.coupling, gamma);
        let k: V3<D> = crate::vec3::lift(&self.rotor);
        add(&k, &bg)
    }

    fn potential_generic<D: DualNum<f64> + Copy>(&self, gamma: &V3<D>) -> D {
        dot_const(&self.com, gamma) * (self.mass * self.g)
    }
}

impl GenericModel for Gyrostat {
    fn lagrangian_generic<D: DualNum<f64> + Copy>(&self, omega: &V3<D>, gamma: &V3<D>) -> D {
        let a = self.linear_generic(gamma);
        quad_form(&self.inertia, omega) * 0.5 + dot(&a, omega) - self.potential_generic(gamma)
    }

    fn routhian_generic<D: DualNum<f64> + Copy>(
        &self,
        big_omega: &V3<D>,
        gamma: &V3<D>,
        p_psi: D,
    ) -> D {
        // (39) with A(γ) = K + Bγ.
        let a = self.linear_generic(gamma);
        let i_omega = mat_vec(&self.inertia, big_omega);
        let q = dot(&i_omega, gamma) + dot(&a, gamma);
        let c = quad_form(&self.inertia, gamma);
        let d = p_psi - q;
        dot(&i_omega, big_omega) * 0.5 + dot(&a, big_omega)
            - self.potential_generic(gamma)
            - d * d / c * 0.5
    }

    fn psi_dot_closed_form(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> f64 {
        // (38).
        let q = (self.inertia * big_omega).dot(gamma) + self.linear_term(gamma).dot(gamma);
        (p_psi - q) / gamma.dot(&(self.inertia * gamma))
    }
}

crate::impl_numdual_traits!(Gyrostat);
