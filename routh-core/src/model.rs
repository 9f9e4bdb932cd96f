//! The model traits (docs/method.md §8). Generated code implements every method; a hand-written
//! model needs only the required ones, the rest have defaults built from them.

use nalgebra::{Matrix3, Vector3};

use crate::formulas::LatexFormulas;

/// A Lagrangian `L(ω, γ) = ½ ωᵀJ(γ)ω + a(γ)·ω − U(γ)` of a rigid body with a symmetry about the
/// vertical: ω is the body-frame angular velocity, γ the body-frame coordinates of the upward unit
/// vertical. γ is treated as an unconstrained vector of ℝ³ when differentiating (paper (18)–(19)).
///
/// Second-derivative matrices are indexed `(i, j) = ∂²/∂x_i∂y_j`.
pub trait Lagrangian {
    /// `L(ω, γ)`.
    fn lagrangian(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> f64;
    /// `∂L/∂ω`.
    fn dl_domega(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Vector3<f64>;
    /// `∂L/∂γ`.
    fn dl_dgamma(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Vector3<f64>;
    /// `J(γ) = ∂²L/∂ω²` (independent of ω because L is quadratic in ω).
    fn d2l_domega2(&self, gamma: &Vector3<f64>) -> Matrix3<f64>;
    /// `∂²L/∂ω_i∂γ_j`.
    fn d2l_domega_dgamma(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Matrix3<f64>;
    /// The Painlevé–Jacobi energy (3): `E = (∂L/∂ω, ω) − L`.
    fn energy(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> f64 {
        self.dl_domega(omega, gamma).dot(omega) - self.lagrangian(omega, gamma)
    }
    /// The cyclic momentum (9): `p_ψ = (∂L/∂ω, γ)`.
    fn cyclic_momentum(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> f64 {
        self.dl_domega(omega, gamma).dot(gamma)
    }
    /// `J₀` when the kinetic matrix has the form `J(γ) = J₀ + c(γ) v(γ) v(γ)ᵀ` with `J₀`
    /// constant (docs/method.md §2a): a body on a smooth plane, whose kinetic energy is
    /// `½ωᵀIω` plus `½m ż²` of its centre's height. The equations then carry `c` and `v`
    /// ([`FullEquations::rank_one`], [`ReducedEquations::rank_one`]), and the simulations solve
    /// with `J` by Sherman–Morrison from one factorisation of `J₀`.
    ///
    /// `#[derive(Lagrangian)]` emits it when it finds the kinetic energy written as a sum of
    /// terms free of γ and one square `f(γ)·w(ω, γ)²` with `w` linear in ω. The default, `None`,
    /// is always correct: the solvers then factorise `J` itself.
    fn constant_inertia(&self) -> Option<Matrix3<f64>> {
        None
    }
    /// The terms of the full equations (8) solved for ω̇ at one state (see [`FullEquations`]):
    /// what [`simulate_full`](crate::simulate_full) evaluates at every stage.
    ///
    /// The default combines the methods above; `#[derive(Lagrangian)]` emits one straight-line
    /// body for all of it, so that the subexpressions the derivatives share are computed once.
    fn full_equations(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> FullEquations {
        let gamma_dot = gamma.cross(omega);
        FullEquations {
            inertia: self.d2l_domega2(gamma),
            right_side: self.dl_domega(omega, gamma).cross(omega)
                + self.dl_dgamma(omega, gamma).cross(gamma)
                - self.d2l_domega_dgamma(omega, gamma) * gamma_dot,
            rank_one: None,
        }
    }
    /// The full equations (8) at one state with their first derivatives in `(ω, γ)` (see
    /// [`FullJacobian`]): what the variational equations of a periodic orbit (the monodromy,
    /// [`periodic_orbit`](crate::periodic_orbit)) evaluate at every stage.
    ///
    /// `#[derive(Lagrangian)]` and `routh::Model` differentiate the right side of (8) and `J`
    /// symbolically on the generator's DAG (exact, one straight-line body). The default, for
    /// hand-written models, takes central differences of [`Lagrangian::full_equations`] (step
    /// `ε^{1/3}·max(1, |x|)`, about 8 significant digits): correct, but a hand-written model
    /// that needs exact multipliers should implement it.
    fn full_jacobian(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> FullJacobian {
        // The whole J, also where the equations carry J₀ + c v vᵀ as its rank-one part.
        let constant = self.constant_inertia();
        let full_j = |e: &FullEquations| match (&e.rank_one, &constant) {
            (Some(r), Some(j0)) => r.complete(j0),
            _ => e.inertia,
        };
        let eq = self.full_equations(omega, gamma);
        let mut jac = FullJacobian {
            inertia: full_j(&eq),
            right_side: eq.right_side,
            dright_domega: Matrix3::zeros(),
            dright_dgamma: Matrix3::zeros(),
            dinertia_dgamma: [Matrix3::zeros(); 3],
        };
        let cbrt_eps = f64::EPSILON.cbrt();
        for k in 0..3 {
            let h = cbrt_eps * omega[k].abs().max(1.0);
            let (mut wp, mut wm) = (*omega, *omega);
            wp[k] += h;
            wm[k] -= h;
            let d = (self.full_equations(&wp, gamma).right_side
                - self.full_equations(&wm, gamma).right_side)
                / (2.0 * h);
            jac.dright_domega.set_column(k, &d);
            let h = cbrt_eps * gamma[k].abs().max(1.0);
            let (mut gp, mut gm) = (*gamma, *gamma);
            gp[k] += h;
            gm[k] -= h;
            let (ep, em) = (
                self.full_equations(omega, &gp),
                self.full_equations(omega, &gm),
            );
            jac.dright_dgamma
                .set_column(k, &((ep.right_side - em.right_side) / (2.0 * h)));
            jac.dinertia_dgamma[k] = (full_j(&ep) - full_j(&em)) / (2.0 * h);
        }
        jac
    }
    /// `L(ω, γ)` with `∂L/∂ω`, `∂L/∂γ`, `J = ∂²L/∂ω²` and `∂²L/∂ω∂γ` as one tape with the
    /// model's parameter values bound ([`routh_tape::FLOW_OUTPUTS`]): the full equations (8)
    /// evaluated at Taylor jets, for the jets of the flow that
    /// [`orbit_nonlinear_stability`](crate::orbit_nonlinear_stability) takes and for the Taylor
    /// integrator ([`Method::Taylor`](crate::Method::Taylor)) of [`simulate_full`](crate::simulate_full). Its `f64` values
    /// are the generated methods' up to rounding (the same expression DAG).
    /// `#[derive(Lagrangian)]` and `routh::Model` provide it; a hand-written model has none
    /// (`None`, the default).
    fn flow_tape(&self) -> Option<routh_tape::FlowTape> {
        None
    }
}

/// The full equations (8) at one state and their first derivatives, for the variational
/// equations `δẋ = DF(x) δx` of the flow of (8) in `x = (ω, γ)` (docs/method.md §11).
///
/// With `J ω̇ = f(ω, γ)` (the right side of (8)) and `γ̇ = γ × ω`:
/// `∂ω̇/∂ω = J⁻¹ ∂f/∂ω`, `∂ω̇/∂γ_k = J⁻¹(∂f/∂γ_k − (∂J/∂γ_k) ω̇)`, `∂γ̇/∂ω = [γ]×`,
/// `∂γ̇/∂γ = −[ω]×`. Matrices are indexed `(i, j) = ∂f_i/∂x_j`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FullJacobian {
    /// `J(γ) = ∂²L/∂ω²` (the whole matrix, also for a model with a rank-one inertia).
    pub inertia: Matrix3<f64>,
    /// `f = ∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)`, the right side of (8).
    pub right_side: Vector3<f64>,
    /// `∂f_i/∂ω_j`.
    pub dright_domega: Matrix3<f64>,
    /// `∂f_i/∂γ_j` (γ an unconstrained vector of ℝ³).
    pub dright_dgamma: Matrix3<f64>,
    /// `∂J/∂γ_k`, `k = 0, 1, 2`.
    pub dinertia_dgamma: [Matrix3<f64>; 3],
}

/// The full equations (8) at one state `(ω, γ)`, solved for ω̇ (docs/method.md §2):
/// `J ω̇ = ∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)` and `γ̇ = γ × ω`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FullEquations {
    /// `J(γ) = ∂²L/∂ω²`, symmetric positive definite for a physical body.
    pub inertia: Matrix3<f64>,
    /// The right side `∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)`.
    pub right_side: Vector3<f64>,
    /// `J − J₀ = c v vᵀ` when the model has a [`Lagrangian::constant_inertia`] `J₀`; `None`
    /// otherwise (and always correct: the solvers then use `inertia`).
    pub rank_one: Option<RankOneInertia>,
}

/// The part `c v vᵀ` of a kinetic matrix `J(γ) = J₀ + c(γ) v(γ) v(γ)ᵀ` at one state, `J₀` being
/// the model's [`Lagrangian::constant_inertia`] (docs/method.md §2a). For a body on a smooth
/// plane, `c = m` and `v = n × γ`, with `n` the gradient of the centre's height.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RankOneInertia {
    /// `c(γ)`.
    pub weight: f64,
    /// `v(γ)`.
    pub vector: Vector3<f64>,
}

impl RankOneInertia {
    /// `J₀ + c v vᵀ`, the kinetic matrix it completes.
    pub fn complete(&self, constant: &Matrix3<f64>) -> Matrix3<f64> {
        constant + self.vector * self.vector.transpose() * self.weight
    }
}

/// The reduced equations (13) at one state `(Ω, γ, p_ψ)` (docs/method.md §3, errata E4):
/// `A Ω̇ = ∂R/∂Ω × Ω + ∂R/∂γ × γ − M(γ × Ω)` with `A = ∂²R/∂Ω²` and `M = ∂²R/∂Ω∂γ`,
/// `γ̇ = γ × Ω`, and the cyclic angle's rate `ψ̇ = −∂R/∂p_ψ` (15).
///
/// `A` is singular along γ and is not needed: with `J = ∂²L/∂ω²`, `A = J − (Jγ)(Jγ)ᵀ/(γᵀJγ)`,
/// and the solution with `Ω̇·γ = 0` (the gauge) is `J⁻¹b` projected on γ^⊥ (see
/// [`reduced_vector_field`](crate::sim::reduced_vector_field)), so the equations carry `J`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ReducedEquations {
    /// `J(γ) = ∂²L/∂ω²`, symmetric positive definite for a physical body.
    pub inertia: Matrix3<f64>,
    /// The right side `∂R/∂Ω × Ω + ∂R/∂γ × γ − M(γ × Ω)`.
    pub right_side: Vector3<f64>,
    /// `ψ̇ = −∂R/∂p_ψ` (15), (38).
    pub psi_dot: f64,
    /// `J − J₀ = c v vᵀ`, as [`FullEquations::rank_one`].
    pub rank_one: Option<RankOneInertia>,
}

/// Every output of the Routh function at one point `(Ω, γ, p_ψ)`, from one evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RouthBundle {
    /// `R(Ω, γ, p_ψ)` of (14).
    pub routhian: f64,
    /// `ψ̇(Ω, γ, p_ψ)` of (12)/(38).
    pub psi_dot: f64,
    /// `∂R/∂Ω`.
    pub dr_domega: Vector3<f64>,
    /// `∂R/∂γ`.
    pub dr_dgamma: Vector3<f64>,
    /// `∂R/∂p_ψ = −ψ̇` (15).
    pub dr_dp: f64,
    /// `∂²R/∂Ω²` (singular along γ, errata E4).
    pub d2r_domega2: Matrix3<f64>,
    /// `∂²R/∂Ω_i∂γ_j`.
    pub d2r_domega_dgamma: Matrix3<f64>,
    /// `∂²R/∂γ²`.
    pub d2r_dgamma2: Matrix3<f64>,
}

/// The matrices `A`, `G`, `C` of (64) at `Ω = 0` (section 5, errata E5–E6).
///
/// `A = ∂²R/∂Ω²`, `2G = M[γ]× + [γ]×Mᵀ − [∂R/∂Ω]×` with `M = ∂²R/∂Ω∂γ`, and
/// `C = [γ]×ᵀ(μE − ∂²R/∂γ²)[γ]×` with `μ = (∂R/∂γ, γ)`. All three annihilate γ, so
/// `det(Aλ² + 2Gλ + C) ≡ 0` (errata E5); the characteristic polynomial is the 2×2 one on γ^⊥.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GyroscopicSystem {
    /// Kinetic matrix `A = ∂²R/∂Ω²` at Ω = 0.
    pub a: Matrix3<f64>,
    /// Skew-symmetric gyroscopic matrix `G`.
    pub g: Matrix3<f64>,
    /// Symmetric stiffness matrix `C` (the second variation of the amended potential).
    pub c: Matrix3<f64>,
}

impl GyroscopicSystem {
    /// Forms `A`, `G`, `C` from a bundle evaluated at `Ω = 0` (section 5 in the matrix form of
    /// errata E6), entry by entry:
    /// - `M[γ]× + [γ]×Mᵀ = [(tr M)γ − Mᵀγ]×` for every 3×3 `M` (expand both sides), and
    ///   differentiating Theorem 2's identity (17), `(∂R/∂Ω, γ) ≡ p_ψ`, by γ gives
    ///   `Mᵀγ = −∂R/∂Ω` for every Routh function, so `2G = (tr M)[γ]×` — no matrix product
    ///   (docs/method.md §4; the same closed form as the generated `gyroscopic_system`). A
    ///   bundle that violates (17) is not the derivatives of a Routh function;
    /// - `C = [γ]×ᵀ(μE − ∂²R/∂γ²)[γ]× = [γ]× N [γ]×` with `N = ∂²R/∂γ² − μE` (the two signs
    ///   cancel, `[γ]×ᵀ = −[γ]×`), as `Y = N[γ]×` and `C = [γ]×Y` with the zeros of `[γ]×`
    ///   skipped, every entry one difference of two products and only the upper triangle of the
    ///   symmetric `C` formed: the form the derive writes (`stiffness_sandwich` in
    ///   routh-codegen), so that both give the same C. `∂²R/∂γ²` is taken as symmetric (it is a
    ///   Hessian); its entries are read as they are.
    ///
    /// `#[inline]`: a caller in another crate (the default [`Routhian::bundle_and_system`], a
    /// bench) would otherwise call it out of line and reload the bundle from memory.
    #[inline]
    pub fn from_bundle(bundle: &RouthBundle, gamma: &Vector3<f64>) -> Self {
        let (g0, g1, g2) = (gamma.x, gamma.y, gamma.z);
        let m = &bundle.d2r_domega_dgamma;
        let half_tr = 0.5 * (m[(0, 0)] + m[(1, 1)] + m[(2, 2)]);
        let g = (half_tr * gamma).cross_matrix();
        let h = &bundle.d2r_dgamma2;
        let mu = bundle.dr_dgamma.dot(gamma);
        // N = H − μE: the off-diagonal entries are H's own (H is symmetric).
        let (n00, n11, n22) = (h[(0, 0)] - mu, h[(1, 1)] - mu, h[(2, 2)] - mu);
        let (n01, n02, n10) = (h[(0, 1)], h[(0, 2)], h[(1, 0)]);
        let (n12, n20, n21) = (h[(1, 2)], h[(2, 0)], h[(2, 1)]);
        // Y = N[γ]×, rows of [γ]×: (0, −g2, g1), (g2, 0, −g0), (−g1, g0, 0); Y₀₀ is not read.
        let y01 = n02 * g0 - n00 * g2;
        let y02 = n00 * g1 - n01 * g0;
        let y10 = n11 * g2 - n12 * g1;
        let y11 = n12 * g0 - n10 * g2;
        let y12 = n10 * g1 - n11 * g0;
        let y20 = n21 * g2 - n22 * g1;
        let y21 = n22 * g0 - n20 * g2;
        let y22 = n20 * g1 - n21 * g0;
        // C = [γ]×Y, upper triangle.
        let c00 = g1 * y20 - g2 * y10;
        let c01 = g1 * y21 - g2 * y11;
        let c02 = g1 * y22 - g2 * y12;
        let c11 = g2 * y01 - g0 * y21;
        let c12 = g2 * y02 - g0 * y22;
        let c22 = g0 * y12 - g1 * y02;
        #[rustfmt::skip]
        let c = Matrix3::new(
            c00, c01, c02,
            c01, c11, c12,
            c02, c12, c22,
        );
        GyroscopicSystem {
            a: bundle.d2r_domega2,
            g,
            c,
        }
    }
}

/// The Routh function of Theorem 1 and its derivatives, with arguments `(Ω, γ, p_ψ)`: Ω is the
/// angular velocity relative to the frame rotating about the vertical, `ω = Ω + ψ̇γ` (7).
///
/// A model written by hand implements the required methods of both traits; the example of
/// [`steady_motions`](crate::steady_motions) does so for the Lagrange top.
pub trait Routhian: Lagrangian {
    /// `ψ̇(Ω, γ, p_ψ)` solving (12); for `L` of the form above this is (38) with `J(γ)`:
    /// `ψ̇ = (p_ψ − (∂L/∂ω(Ω, γ), γ)) / (γᵀJγ)`.
    fn psi_dot(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64) -> f64 {
        let q = self.dl_domega(big_omega, gamma).dot(gamma);
        (p_psi - q) / gamma.dot(&(self.d2l_domega2(gamma) * gamma))
    }
    /// `R(Ω, γ, p_ψ)` of (14) ((39) generalised).
    fn routhian(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64) -> f64;
    /// `∂R/∂Ω`.
    fn dr_domega(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64)
        -> Vector3<f64>;
    /// `∂R/∂γ`.
    fn dr_dgamma(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64)
        -> Vector3<f64>;
    /// `∂R/∂p_ψ = −ψ̇` (15).
    fn dr_dp(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64) -> f64 {
        -self.psi_dot(big_omega, gamma, p_psi)
    }
    /// `∂²R/∂Ω²`.
    fn d2r_domega2(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> Matrix3<f64>;
    /// `∂²R/∂Ω_i∂γ_j`.
    fn d2r_domega_dgamma(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> Matrix3<f64>;
    /// `∂²R/∂γ²`.
    fn d2r_dgamma2(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> Matrix3<f64>;
    /// All of the above from one evaluation.
    fn bundle(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64) -> RouthBundle {
        RouthBundle {
            routhian: self.routhian(big_omega, gamma, p_psi),
            psi_dot: self.psi_dot(big_omega, gamma, p_psi),
            dr_domega: self.dr_domega(big_omega, gamma, p_psi),
            dr_dgamma: self.dr_dgamma(big_omega, gamma, p_psi),
            dr_dp: self.dr_dp(big_omega, gamma, p_psi),
            d2r_domega2: self.d2r_domega2(big_omega, gamma, p_psi),
            d2r_domega_dgamma: self.d2r_domega_dgamma(big_omega, gamma, p_psi),
            d2r_dgamma2: self.d2r_dgamma2(big_omega, gamma, p_psi),
        }
    }
    /// [`Routhian::bundle`] and the matrices `A`, `G`, `C` of (64) formed from it, from one
    /// evaluation: what [`classify`](crate::classify) needs at a steady motion (call it with
    /// `Ω = 0`, where (64) is the linearisation, errata E5–E6).
    ///
    /// The system is [`GyroscopicSystem::from_bundle`] of the bundle at the same point:
    /// `A = ∂²R/∂Ω²`, `2G = (tr M)[γ]×` with `M = ∂²R/∂Ω∂γ` (by Theorem 2's identity (17),
    /// `(∂R/∂Ω, γ) ≡ p_ψ`, differentiated by γ: `Mᵀγ = −∂R/∂Ω`), and
    /// `C = [γ]×ᵀ(μE − ∂²R/∂γ²)[γ]×` with `μ = (∂R/∂γ, γ)`. At `Ω ≠ 0` the same formulas are
    /// applied to the bundle there.
    ///
    /// The default is exactly `bundle` then `from_bundle`, so a hand-written model (or
    /// `routh::Model`) gets it for free; `#[derive(Lagrangian)]` emits one straight-line body
    /// for all 62 outputs, with `A`, `G`, `C` formed from the values the bundle already holds
    /// in registers.
    ///
    /// ```
    /// # use routh_core::{GyroscopicSystem, Routhian, Vector3};
    /// # use test_models::HeavyTop;
    /// // A free symmetric body J = diag(2, 2, 1) (a top without weight, its Routh function written
    /// // by hand in closed form) spinning about its axis, p_ψ = 1.
    /// let free = HeavyTop::lagrange(2.0, 1.0, 0.0);
    /// let gamma = Vector3::z();
    /// let (bundle, system) = free.bundle_and_system(&Vector3::zeros(), &gamma, 1.0);
    /// assert_eq!(system, GyroscopicSystem::from_bundle(&bundle, &gamma));
    /// // ψ̇ = p_ψ/(γᵀJγ) = 1 (38); M = ψ̇J − 2ψ̇ (Jγ)(Jγ)ᵀ/(γᵀJγ) has trace 5 − 2 = 3, and
    /// // 2G = (tr M)[γ]×, so G₂₁ = 3/2.
    /// assert_eq!(bundle.psi_dot, 1.0);
    /// assert!((system.g[(1, 0)] - 1.5).abs() < 1e-15);
    /// ```
    fn bundle_and_system(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> (RouthBundle, GyroscopicSystem) {
        let bundle = self.bundle(big_omega, gamma, p_psi);
        let system = GyroscopicSystem::from_bundle(&bundle, gamma);
        (bundle, system)
    }
    /// The amended potential (34): `U_r(γ, p_ψ) = −R(0, γ, p_ψ)`.
    fn amended_potential(&self, gamma: &Vector3<f64>, p_psi: f64) -> f64 {
        -self.routhian(&Vector3::zeros(), gamma, p_psi)
    }
    /// `A`, `G`, `C` of (64) at `Ω = 0` (see [`GyroscopicSystem`]).
    fn gyroscopic_system(&self, gamma: &Vector3<f64>, p_psi: f64) -> GyroscopicSystem {
        GyroscopicSystem::from_bundle(&self.bundle(&Vector3::zeros(), gamma, p_psi), gamma)
    }
    /// The terms of the reduced equations (13) at one state (see [`ReducedEquations`]): what
    /// [`simulate_reduced`](crate::simulate_reduced) evaluates at every stage.
    ///
    /// The default combines the methods above; `#[derive(Lagrangian)]` emits one straight-line
    /// body for all of it, so that the subexpressions the derivatives share are computed once.
    fn reduced_equations(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> ReducedEquations {
        let (w, g, p) = (big_omega, gamma, p_psi);
        let gamma_dot = gamma.cross(big_omega);
        ReducedEquations {
            inertia: self.d2l_domega2(gamma),
            right_side: self.dr_domega(w, g, p).cross(big_omega)
                + self.dr_dgamma(w, g, p).cross(gamma)
                - self.d2r_domega_dgamma(w, g, p) * gamma_dot,
            psi_dot: -self.dr_dp(w, g, p),
            rank_one: None,
        }
    }
    /// `∂R/∂γ` and `∂²R/∂γ²` at `Ω = 0` as an expression tape that can be evaluated with
    /// intervals, for [`steady_motions_certified`](crate::certify::steady_motions_certified).
    /// `#[derive(Lagrangian)]` emits it; a hand-written model has none (`None`, the default)
    /// and cannot be certified.
    fn certification_tape(&self) -> Option<routh_tape::CertificationTape> {
        None
    }
    /// The Routh function `R(Ω, γ, p_ψ)` of (14) as a tape with the model's parameter values
    /// bound, to be evaluated with any [`TapeScalar`](routh_tape::TapeScalar): for analyses
    /// that need derivatives beyond the Hessian (evaluate it with a Taylor-jet scalar), or
    /// enclosures of `R` (intervals).
    ///
    /// All of `Ω`, `γ` (an unconstrained vector of ℝ³, as when the derive differentiates) and
    /// `p_ψ` are inputs; nothing in the tape assumes `Ω = 0` or `|γ| = 1`. Its `f64` value is the
    /// generated [`Routhian::routhian`] up to rounding (the same expression DAG).
    /// `#[derive(Lagrangian)]` and `routh::Model` provide it; a hand-written model has none
    /// (`None`, the default).
    fn routh_tape(&self) -> Option<routh_tape::RouthianTape> {
        None
    }
}

/// Formulas that `#[derive(Lagrangian)]` derived for a model, as plain text, for reports. The
/// variables are the DSL's names: the fields (a vector field `v` as `v[0]`, a matrix `m` as
/// `m[(i,j)]`), `ω₁ ω₂ ω₃`, `γ₁ γ₂ γ₃` and `p_ψ`. Hand-written models need not implement it.
pub trait DerivedFormulas {
    /// `L(ω, γ)` after simplification.
    const LAGRANGIAN: &'static str;
    /// The amended potential (34) `U_r(γ, p_ψ) = −R(0, γ, p_ψ)`, i.e. (40) for the model.
    const AMENDED_POTENTIAL: &'static str;
    /// `ψ̇(0, γ, p_ψ)` of (38): the rate of rotation about the vertical of a steady motion at γ.
    const PSI_DOT_AT_REST: &'static str;
    /// [`LatexFormulas::lagrangian`] (empty by default). These consts are what the default
    /// [`DerivedFormulas::latex`] returns, for a hand-written model; the derive leaves them
    /// empty and implements `latex` itself, printing the formulas on its first call.
    const LATEX_LAGRANGIAN: &'static str = "";
    /// [`LatexFormulas::psi_dot`].
    const LATEX_PSI_DOT: &'static str = "";
    /// [`LatexFormulas::routhian`].
    const LATEX_ROUTHIAN: &'static str = "";
    /// [`LatexFormulas::amended_potential`].
    const LATEX_AMENDED_POTENTIAL: &'static str = "";
    /// [`LatexFormulas::a`].
    const LATEX_A: &'static str = "";
    /// [`LatexFormulas::g`].
    const LATEX_G: &'static str = "";
    /// [`LatexFormulas::c`].
    const LATEX_C: &'static str = "";

    /// The derived formulas in LaTeX: L, ψ̇ (38), R (14), U_r (34) and A, G, C (64) as
    /// matrices (see [`LatexFormulas`] for the symbols and the `|γ|² = 1` rule). A derived
    /// model prints them on the first call (the derive's analysis runs again, a few ms in an
    /// optimised build) and returns the kept text afterwards.
    fn latex(&self) -> LatexFormulas {
        LatexFormulas {
            lagrangian: Self::LATEX_LAGRANGIAN.to_string(),
            psi_dot: Self::LATEX_PSI_DOT.to_string(),
            routhian: Self::LATEX_ROUTHIAN.to_string(),
            amended_potential: Self::LATEX_AMENDED_POTENTIAL.to_string(),
            a: Self::LATEX_A.to_string(),
            g: Self::LATEX_G.to_string(),
            c: Self::LATEX_C.to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The entry-by-entry `from_bundle` equals the matrix products of errata E6 for arbitrary
    /// matrices satisfying (17) differentiated, `Mᵀγ = −∂R/∂Ω` (the test imposes it on a random
    /// `M` and a random `∂R/∂Ω`); the rest of the identity is algebra.
    #[test]
    fn from_bundle_is_the_matrix_form() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for _ in 0..200 {
            let mut m3 = || Matrix3::from_fn(|_, _| next());
            let (m, a, h0) = (m3(), m3(), m3());
            let h = h0 + h0.transpose();
            let gamma = Vector3::new(next(), next(), next());
            // Impose Mᵀγ = −∂R/∂Ω by a rank-one correction of M.
            let d = Vector3::new(next(), next(), next());
            let m = m - gamma * (m.tr_mul(&gamma) + d).transpose() / gamma.norm_squared();
            let b = RouthBundle {
                routhian: 0.0,
                psi_dot: 0.0,
                dr_domega: d,
                dr_dgamma: Vector3::new(next(), next(), next()),
                dr_dp: 0.0,
                d2r_domega2: a,
                d2r_domega_dgamma: m,
                d2r_dgamma2: h,
            };
            let gx = gamma.cross_matrix();
            let g = 0.5 * (m * gx + gx * m.transpose() - b.dr_domega.cross_matrix());
            let mu = b.dr_dgamma.dot(&gamma);
            let c = gx.transpose() * (Matrix3::from_diagonal_element(mu) - h) * gx;
            let got = GyroscopicSystem::from_bundle(&b, &gamma);
            assert!((got.g - g).amax() < 1e-14, "{}", (got.g - g).amax());
            assert!((got.c - c).amax() < 1e-14, "{}", (got.c - c).amax());
            assert_eq!(got.a, a);
        }
    }
}
