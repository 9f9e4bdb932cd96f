//! Paper Example 2: a heavy ellipsoid on a smooth horizontal plane (twin:
//! [`test_models::Ellipsoid`]), with the corrections of
//! errata E1 (the ½ in (51)), E2 (`U = +m g C₃`) and E6 (the support function).
//!
//! # The spin threshold about a vertical principal axis, by hand
//!
//! Let the body spin about the principal axis `e₃` held vertical, `γ = σe₃` (`σ = ±1`: standing on
//! the end `−σa₃e₃`), the semi-axes `a₁, a₂, a₃` along the principal axes of `I = diag(I₁, I₂, I₃)`
//! and the ellipsoid's centre at `c₀ = h e₃` from the centre of mass. At `Ω = 0`, by E6,
//! `γᵀJγ = γᵀIγ`, so the amended potential (34) is
//!
//! ```text
//! U_r(γ) = ½ p² / (γᵀIγ) + m g C₃(γ),    C₃(γ) = √(γᵀDγ) − h γ₃,   D = diag(a₁², a₂², a₃²).
//! ```
//!
//! Near the pole take `γ = (ε₁, ε₂, σ√(1 − ε₁² − ε₂²))`; the chart is orthonormal at `ε = 0`,
//! so the second-order terms give the restricted second variation (62)–(63) directly:
//! - `γᵀIγ = I₃ + (I₁ − I₃)ε₁² + (I₂ − I₃)ε₂²` exactly, so
//!   `½p²/(γᵀIγ) = p²/(2I₃) − ½ Σ p²(Iᵢ − I₃)/I₃² εᵢ² + O(ε⁴)`;
//! - `√(γᵀDγ) = √(a₃² + Σ (aᵢ² − a₃²)εᵢ²) = a₃ + ½ Σ (aᵢ² − a₃²)/a₃ εᵢ² + O(ε⁴)`;
//! - `−hγ₃ = −σh + ½ σh Σ εᵢ² + O(ε⁴)`.
//!
//! Hence `U_r = const + ½ Σ kᵢ εᵢ²` with
//!
//! ```text
//! kᵢ = −m g ℓᵢ − p² (Iᵢ − I₃)/I₃²,     ℓᵢ = a₃ − σh − aᵢ²/a₃   (i = 1, 2),
//! ```
//!
//! `ℓᵢ` being the height of the centre of mass above the centre of curvature of the contact
//! point's normal section in the plane `(eᵢ, e₃)`. (The vertical-motion term of the kinetic energy
//! (49) is quadratic in `(∂C₃/∂γ, γ × ω)`, which vanishes at the pole, so it adds nothing to the
//! linearisation.) The gyroscopic matrix of section 5 at the pole is, by E6,
//! `2G₁₂ = p(I₃ − I₁ − I₂)/I₃`, and the kinetic matrix on the tangent plane is `diag(I₁, I₂)`.
//! In the coordinates `δγ = (ε₁, ε₂)` (moved by rotations about `e₂` and `e₁` respectively),
//! `f₂(λ) = c₄λ⁴ + c₂λ² + c₀` with
//!
//! ```text
//! c₄ = I₁I₂,   c₂ = I₁k₁ + I₂k₂ + p²(I₁ + I₂ − I₃)²/I₃²,   c₀ = k₁k₂.
//! ```
//!
//! (Check: for a free body, `ℓᵢ = 0`, this gives `λ² = −Ω²` and Euler's
//! `λ² = (I₂ − I₃)(I₃ − I₁)Ω²/(I₁I₂)` with `p = I₃Ω`.)
//!
//! Standing on the end of its longest axis with `ℓᵢ > 0` and `Iᵢ > I₃`, both `kᵢ < 0`: degree 2, so
//! the spin is gyroscopically stabilised iff `c₂ > 0` and `c₂² − 4c₄c₀ > 0`. Write `P = p²`,
//! `αᵢ = m g ℓᵢ`, `βᵢ = (Iᵢ − I₃)/I₃²`, so `kᵢ = −αᵢ − βᵢP` and `c₂ = uP − v` with
//! `u = (I₁ + I₂ − I₃)²/I₃² − I₁β₁ − I₂β₂`, `v = I₁α₁ + I₂α₂`. The discriminant is the quadratic
//!
//! ```text
//! Δ(P) = (u² − 4I₁I₂β₁β₂) P² − (2uv + 4I₁I₂(α₁β₂ + α₂β₁)) P + (I₁α₁ − I₂α₂)²,
//! ```
//!
//! and the threshold is its largest root `P*` (where also `c₂ > 0`): [`Ellipsoid::spin_threshold`].
//!
//! For a spheroid (`a₁ = a₂ = a`, `I₁ = I₂ = I`) this factorises:
//! `u² − 4I²β² = (2I − I₃)²/I₃²`, `2uv + 8I²αβ = 4Iα(2I − I₃)²/I₃²`, constant `0`, so
//! `Δ = P (2I − I₃)²/I₃² (P − 4Iα)`, and the spin about the axis is stable iff
//!
//! ```text
//! p_ψ² > 4 I m g ℓ,   ℓ = a₃ − σh − a²/a₃,
//! ```
//!
//! the analogue of Maievskii's `p² > 4A₁mgl` with the centre of curvature of the contact point in
//! place of the fixed point: [`Ellipsoid::spheroid_threshold`].

use rand::Rng;
use routh::{Lagrangian, Matrix3, Vector3};

/// A heavy ellipsoid on a smooth horizontal plane (paper Example 2). The height of the centre of
/// mass is the support function `C₃(γ) = √(γᵀDγ) − c₀·γ` (errata E6), the potential is
/// `U = +m g C₃` (errata E2) and the kinetic energy is (49).
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]
pub struct Ellipsoid {
    /// Central inertia tensor `I` (principal axes along the semi-axes).
    pub inertia: Matrix3<f64>,
    /// Semi-axes `(a₁, a₂, a₃)`.
    pub semi_axes: Vector3<f64>,
    /// Position `c₀` of the ellipsoid's centre relative to the centre of mass.
    pub offset: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
}

impl From<&test_models::Ellipsoid> for Ellipsoid {
    fn from(m: &test_models::Ellipsoid) -> Self {
        Ellipsoid {
            inertia: m.inertia,
            semi_axes: m.semi_axes,
            offset: m.offset,
            mass: m.mass,
            g: m.g,
        }
    }
}

model! { DIAGONAL_ELLIPSOID_SRC:
    /// Bench model M2: [`Ellipsoid`] with a diagonal inertia tensor, written with `diag(v)`.
    #[derive(Lagrangian, Debug, Clone)]
    #[lagrangian(
        let d = diag(semi_axes.component_mul(semi_axes)),
        let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
        let n = grad(c3, gamma),
        kinetic = 0.5 * (omega.dot(diag(inertia) * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
        potential = mass * g * c3,
    )]
    pub struct DiagonalEllipsoid {
        /// Principal moments of inertia `(I₁, I₂, I₃)`.
        pub inertia: Vector3<f64>,
        /// Semi-axes `(a₁, a₂, a₃)`.
        pub semi_axes: Vector3<f64>,
        /// Position `c₀` of the ellipsoid's centre relative to the centre of mass.
        pub offset: Vector3<f64>,
        /// Mass `m`.
        pub mass: f64,
        /// Gravity `g`.
        pub g: f64,
    }
}

impl DiagonalEllipsoid {
    /// A generic body: moments in [1, 3], semi-axes in [0.5, 1.5], offset in [−0.2, 0.2]³,
    /// `m ∈ [0.5, 2]`, `g = 9.81`.
    pub fn random<R: Rng + ?Sized>(rng: &mut R) -> Self {
        DiagonalEllipsoid {
            inertia: Vector3::from_fn(|_, _| rng.gen_range(1.0..3.0)),
            semi_axes: Vector3::from_fn(|_, _| rng.gen_range(0.5..1.5)),
            offset: test_models::random_vector(rng, 0.2),
            mass: rng.gen_range(0.5..2.0),
            g: 9.81,
        }
    }

    /// The num-dual twin: `test_models::Ellipsoid` with `I = diag(inertia)`.
    pub fn twin(&self) -> test_models::Ellipsoid {
        test_models::Ellipsoid {
            inertia: Matrix3::from_diagonal(&self.inertia),
            semi_axes: self.semi_axes,
            offset: self.offset,
            mass: self.mass,
            g: self.g,
        }
    }
}

/// Central inertia of a uniform solid ellipsoid of mass `m` and semi-axes `a`.
pub fn uniform_inertia(m: f64, a: &Vector3<f64>) -> Matrix3<f64> {
    let (a1, a2, a3) = (a.x * a.x, a.y * a.y, a.z * a.z);
    Matrix3::from_diagonal(&(m / 5.0 * Vector3::new(a2 + a3, a1 + a3, a1 + a2)))
}

impl Ellipsoid {
    /// A prolate spheroid `a = (1, 1, 2)`, `m = 1`, `g = 9.81`, with the inertia of the uniform
    /// body and its centre of mass `h = 0.2` below the geometric centre along `e₃`
    /// (`c₀ = 0.2 e₃`): an egg, heavier at the `−e₃` end.
    pub fn spheroid() -> Self {
        let a = Vector3::new(1.0, 1.0, 2.0);
        Ellipsoid {
            inertia: uniform_inertia(1.0, &a),
            semi_axes: a,
            offset: Vector3::new(0.0, 0.0, 0.2),
            mass: 1.0,
            g: 9.81,
        }
    }

    /// A uniform triaxial ellipsoid `a = (0.8, 1.2, 2)`, `m = 1`, `g = 9.81`.
    pub fn triaxial() -> Self {
        let a = Vector3::new(0.8, 1.2, 2.0);
        Ellipsoid {
            inertia: uniform_inertia(1.0, &a),
            semi_axes: a,
            offset: Vector3::zeros(),
            mass: 1.0,
            g: 9.81,
        }
    }

    /// `C₃(γ)`, the height of the centre of mass above the plane.
    pub fn height(&self, gamma: &Vector3<f64>) -> f64 {
        let d = Matrix3::from_diagonal(&self.semi_axes.component_mul(&self.semi_axes));
        gamma.dot(&(d * gamma)).sqrt() - self.offset.dot(gamma)
    }

    /// `ℓᵢ = a₃ − σh − aᵢ²/a₃` for the spin with `γ = σe₃` (see the module documentation).
    fn ell(&self, sigma: f64, i: usize) -> f64 {
        let a = &self.semi_axes;
        a.z - sigma * self.offset.z - a[i] * a[i] / a.z
    }

    /// The restricted second variation `(k₁, k₂)` at `γ = σe₃` by the hand formula.
    pub fn pole_hessian(&self, sigma: f64, p_psi: f64) -> (f64, f64) {
        let i3 = self.inertia[(2, 2)];
        let k = |i: usize| {
            -self.mass * self.g * self.ell(sigma, i)
                - p_psi * p_psi * (self.inertia[(i, i)] - i3) / (i3 * i3)
        };
        (k(0), k(1))
    }

    /// Hand formula for a spheroid (`a₁ = a₂`, `I₁ = I₂`): the spin with `γ = σe₃` is stable iff
    /// `p_ψ² > 4 I₁ m g ℓ`, `ℓ = a₃ − σh − a₁²/a₃`. Returns that `p_ψ` (`None` if `ℓ ≤ 0`).
    pub fn spheroid_threshold(&self, sigma: f64) -> Option<f64> {
        let l = self.ell(sigma, 0);
        (l > 0.0).then(|| (4.0 * self.inertia[(0, 0)] * self.mass * self.g * l).sqrt())
    }

    /// Hand formula for a triaxial body: the largest root `P*` of the discriminant `Δ(P)` of the
    /// module documentation, as `p_ψ = √P*` (`None` when the spin is not of degree 2 for large
    /// `p_ψ` or `Δ` has no positive root with `c₂ > 0`).
    pub fn spin_threshold(&self, sigma: f64) -> Option<f64> {
        let (i1, i2, i3) = (
            self.inertia[(0, 0)],
            self.inertia[(1, 1)],
            self.inertia[(2, 2)],
        );
        let mg = self.mass * self.g;
        let (al1, al2) = (mg * self.ell(sigma, 0), mg * self.ell(sigma, 1));
        let (be1, be2) = ((i1 - i3) / (i3 * i3), (i2 - i3) / (i3 * i3));
        if al1 <= 0.0 || al2 <= 0.0 || be1 <= 0.0 || be2 <= 0.0 {
            return None;
        }
        let s = i1 + i2 - i3;
        let u = s * s / (i3 * i3) - i1 * be1 - i2 * be2;
        let v = i1 * al1 + i2 * al2;
        let qa = u * u - 4.0 * i1 * i2 * be1 * be2;
        let qb = -(2.0 * u * v + 4.0 * i1 * i2 * (al1 * be2 + al2 * be1));
        let qc = (i1 * al1 - i2 * al2).powi(2);
        let disc = qb * qb - 4.0 * qa * qc;
        if qa <= 0.0 || disc < 0.0 {
            return None;
        }
        let big = (-qb + disc.sqrt()) / (2.0 * qa);
        (big > 0.0 && u * big > v).then(|| big.sqrt())
    }
}
