//! The reduced Hamiltonian at fixed `p_ψ` in local canonical coordinates of `T*S²` around a
//! steady motion, as a Taylor jet of order four (docs/method.md §10.1).
//!
//! **Chart.** With `(u, v, γ₀)` a right-handed orthonormal frame at the steady motion's `γ₀`,
//! `γ(x) = √(1 − x₁² − x₂²) γ₀ + x₁u + x₂v`: an orthogonal projection chart of the upper
//! hemisphere about `γ₀`, `γ(0) = γ₀`, exactly unit.
//!
//! **Gauge (errata E4).** The reduced velocity is `Ω = γ̇ × γ` (the gauge `Ω·γ = 0` of
//! `reduced_vector_field`), `γ̇ = Σ ∂γ/∂x_k ẋ_k`. A section of `SO(3) → S²` adds to it `α(ẋ) γ`,
//! with `dα` the area form `dA(X, Y) = (X × Y)·γ` of the sphere (in Euler angles `α = cos θ dφ`);
//! since `R(Ω + tγ) = R(Ω) + t p_ψ` (17), the Routhian in the chart is
//! `ℒ(x, ẋ) = R(Ω(x, ẋ), γ(x), p_ψ) + p_ψ α(ẋ)`: the monopole term of Routh reduction. Any `α`
//! with `dα = dA` gives the same equations; we take `α = F dx₂`, `∂F/∂x₁ = (∂₁γ × ∂₂γ)·γ`.
//!
//! **Hamiltonian.** `R` is quadratic in Ω, so `ℒ = ½ẋᵀm(x)ẋ + β(x)·ẋ + R₀(x)` with
//! `m = WᵀAW`, `β = Wᵀ∂R/∂Ω + p_ψ(0, F)`, `R₀ = R(0, γ(x), p_ψ) = −U_r` (34), `W = −[γ]×∂γ/∂x`.
//! The momenta are `p = mẋ + β` and `H = ½(p − β)ᵀm⁻¹(p − β) − R₀`, the reduced energy. We
//! expand in `x` and `y = p − β(0)` (the steady motion is `x = 0, y = 0`). `m`, `β`, `R₀` are
//! the parts of degree 2, 1, 0 in ẋ of one evaluation of `R(W(x)ẋ, γ(x), p_ψ)` at jets in
//! `(x, ẋ)`; the truncation at order four leaves `m` to degree 2 in `x`, `β` to degree 3 and
//! `R₀` to degree 4, exactly what `H` to order four needs (`p − β` vanishes at the steady
//! motion).

use nalgebra::Vector3;

use super::jet::{lower_index, monomials, Jet};

/// `R(Ω, γ, p_ψ)` evaluated at Taylor jets: what the nonlinear test needs of a model. A derived
/// model gets it from its expression tape; a hand-written generic `R` can implement it directly
/// (any closure `Fn(&[Jet; 3], &[Jet; 3], f64) -> Jet` does).
pub trait RouthianJet {
    /// `R(Ω, γ, p_ψ)` with Ω and γ jets.
    fn routhian_jet(&self, big_omega: &[Jet; 3], gamma: &[Jet; 3], p_psi: f64) -> Jet;
}

impl<F: Fn(&[Jet; 3], &[Jet; 3], f64) -> Jet> RouthianJet for F {
    fn routhian_jet(&self, big_omega: &[Jet; 3], gamma: &[Jet; 3], p_psi: f64) -> Jet {
        self(big_omega, gamma, p_psi)
    }
}

type V = [Jet; 3];

fn cross(a: &V, b: &V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: &V, b: &V) -> Jet {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn add(a: &V, b: &V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn times(a: &V, s: &Jet) -> V {
    [a[0] * *s, a[1] * *s, a[2] * *s]
}

/// The coefficient of `ẋ₁^k₀ ẋ₂^k₁` (jet variables 2, 3) in `l`, as a jet in `x` (variables 0,
/// 1): exact to the degree `4 − k₀ − k₁` the truncation leaves it.
fn velocity_part(l: &Jet, k: [u8; 2]) -> Jet {
    let mut out = Jet::constant(0.0);
    for (i, e) in monomials().iter().enumerate() {
        if e[2] == k[0] && e[3] == k[1] {
            // The monomial divided by ẋ₁^k₀ ẋ₂^k₁.
            let mut j = Some(i);
            for v in [2; 2]
                .iter()
                .take(k[0].into())
                .chain([3; 2].iter().take(k[1].into()))
            {
                j = j.and_then(|j| lower_index(*v, j));
            }
            if let Some(j) = j {
                out.c[j] = l.c[i];
            }
        }
    }
    out
}

/// A right-handed orthonormal frame `(u, v, γ₀)`.
pub fn tangent_frame(gamma0: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let g = gamma0.normalize();
    // The axis least aligned with γ₀.
    let i = g.iamin();
    let mut e = Vector3::zeros();
    e[i] = 1.0;
    let u = (e - g * g[i]).normalize();
    let v = g.cross(&u);
    (u, v)
}

/// The chart `γ(x)` as jets in the variables `x₁ = x₀`-slot 0 and `x₂` = slot 1.
pub fn chart(gamma0: &Vector3<f64>) -> V {
    let (u, v) = tangent_frame(gamma0);
    let x1 = Jet::variable(0.0, 0);
    let x2 = Jet::variable(0.0, 1);
    let s = (-(x1 * x1) - x2 * x2 + 1.0).sqrt();
    let g = gamma0.normalize();
    [
        s * g.x + x1 * u.x + x2 * v.x,
        s * g.y + x1 * u.y + x2 * v.y,
        s * g.z + x1 * u.z + x2 * v.z,
    ]
}

/// The reduced Hamiltonian `H(x₁, x₂, y₁, y₂)` (jet variables 0–3, canonical pairs `(x_k, y_k)`)
/// at fixed `p_ψ`, minus its value at the steady motion.
pub fn reduced_hamiltonian<R: RouthianJet + ?Sized>(
    r: &R,
    gamma0: &Vector3<f64>,
    p_psi: f64,
) -> Jet {
    let g = chart(gamma0);
    let d1 = [g[0].partial(0), g[1].partial(0), g[2].partial(0)];
    let d2 = [g[0].partial(1), g[1].partial(1), g[2].partial(1)];
    // Columns of W: Ω = Σ (∂_kγ × γ) ẋ_k.
    let w1 = cross(&d1, &g);
    let w2 = cross(&d2, &g);
    // The area form in the chart and α = F dx₂ with ∂F/∂x₁ = (∂₁γ × ∂₂γ)·γ.
    let f = dot(&cross(&d1, &d2), &g);
    let big_f = f.integrate(0);
    // ℒ without the monopole term in one evaluation: R at Ω = W(x)ẋ with the velocities ẋ₁, ẋ₂
    // as jet variables 2 and 3 (free until H is assembled).
    let (v1, v2) = (Jet::variable(0.0, 2), Jet::variable(0.0, 3));
    let omega = add(&times(&w1, &v1), &times(&w2, &v2));
    let lagrangian = r.routhian_jet(&omega, &g, p_psi);
    // Its parts of degree 0, 1, 2 in ẋ as jets in x: R₀, b, ½m.
    let part = |k: [u8; 2]| velocity_part(&lagrangian, k);
    let r0 = part([0, 0]);
    let (b1, b2) = (part([1, 0]), part([0, 1]));
    let m11 = part([2, 0]) * 2.0;
    let m22 = part([0, 2]) * 2.0;
    let m12 = part([1, 1]);
    let beta1 = b1;
    let beta2 = b2 + big_f * p_psi;
    let p1 = Jet::variable(0.0, 2) - (beta1 - beta1.value());
    let p2 = Jet::variable(0.0, 3) - (beta2 - beta2.value());
    let det = m11 * m22 - m12 * m12;
    let kinetic = (p1 * p1 * m22 - p1 * p2 * m12 * 2.0 + p2 * p2 * m11) * det.recip() * 0.5;
    kinetic - (r0 - r0.value())
}
