//! What a simulation returns: the [`Trajectory`] of the full equations, the
//! [`ReducedTrajectory`] of the reduced ones, and the work counters [`SimStats`].

use nalgebra::{UnitQuaternion, Vector3};

use super::attitude;

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

/// A solution of the full equations (8), from [`simulate_full`](super::simulate_full).
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Trajectory {
    /// Times: `t = 0` first, then every accepted step (or the requested
    /// [`Output::Times`](super::Output::Times)).
    pub t: Vec<f64>,
    /// Body angular velocity ω.
    pub omega: Vec<Vector3<f64>>,
    /// Body coordinates γ of the upward vertical.
    pub gamma: Vec<Vector3<f64>>,
    /// The Painlevé–Jacobi energy (3) `E = (∂L/∂ω, ω) − L`
    /// ([`Lagrangian::energy`](crate::Lagrangian::energy)).
    pub energy: Vec<f64>,
    /// The cyclic momentum (9) `p_ψ = (∂L/∂ω, γ)`
    /// ([`Lagrangian::cyclic_momentum`](crate::Lagrangian::cyclic_momentum)).
    pub p_psi: Vec<f64>,
    /// `|γ|²` (the geometric integral (4) is `|γ|² − 1 = 0`).
    pub gamma_norm_sq: Vec<f64>,
    /// The attitude `R` (body → space) at each point when
    /// [`SimOptions::attitude`](super::SimOptions::attitude) is set,
    /// empty otherwise: `γ = Rᵀe₃`, `Ṙ = R[ω]×`, and `R(0)` the attitude with Euler angle
    /// `ψ(0) = 0`: `R(0) = R_x(θ₀) R_z(φ₀)` with `γ₀ = (sin θ₀ sin φ₀, sin θ₀ cos φ₀, cos θ₀)`.
    pub attitude: Vec<UnitQuaternion<f64>>,
    /// Work counters.
    pub stats: SimStats,
}

/// A solution of the reduced equations (13) with the reconstruction (15), from
/// [`simulate_reduced`](super::simulate_reduced).
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ReducedTrajectory {
    /// Times: `t = 0` first, then every accepted step (or the requested
    /// [`Output::Times`](super::Output::Times)).
    pub t: Vec<f64>,
    /// Angular velocity Ω relative to the frame rotating about the vertical (7).
    pub big_omega: Vec<Vector3<f64>>,
    /// Body coordinates γ of the upward vertical.
    pub gamma: Vec<Vector3<f64>>,
    /// Rotation angle ψ of the rotating frame about the vertical, integrated from
    /// `ψ̇ = −∂R/∂p_ψ` (15) with `ψ(0) = 0`.
    pub psi: Vec<f64>,
    /// `ψ̇(Ω, γ, p_ψ)` of (12)/(38) ([`Routhian::psi_dot`](crate::Routhian::psi_dot)).
    pub psi_dot: Vec<f64>,
    /// The reconstructed body angular velocity `ω = Ω + ψ̇γ` (7).
    pub omega: Vec<Vector3<f64>>,
    /// The reduced energy (16) `E' = (∂R/∂Ω, Ω) − R`, equal to E of (3) (Theorem 2).
    pub energy: Vec<f64>,
    /// `(∂R/∂Ω, γ)` of (17), identically `p_ψ` (Theorem 2).
    pub p_psi: Vec<f64>,
    /// `|γ|²`.
    pub gamma_norm_sq: Vec<f64>,
    /// The attitude `R` (body → space) at each point when
    /// [`SimOptions::attitude`](super::SimOptions::attitude) is set,
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
pub(super) fn max_deviation(x: &[f64]) -> f64 {
    match x.first() {
        Some(&x0) => x.iter().fold(0.0, |m, &v| m.max((v - x0).abs())),
        None => 0.0,
    }
}

/// `max | |γ|² − 1 |`.
pub(super) fn max_unit_error(x: &[f64]) -> f64 {
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
