//! Rigid bodies about a fixed point written by hand in closed form (no automatic
//! differentiation): `L = ½ωᵀJω − U(γ)` with J constant, and its Routh function (39)
//! `R = ½ΩᵀJΩ − U − ½q²/n`, `q = p_ψ − (JΩ)·γ`, `n = γᵀJγ`, with every derivative written out. A
//! second, independent reference next to the num-dual [`Gyrostat`](crate::Gyrostat), used by
//! routh-core's tests.
//!
//! - [`HeavyTop`]: `U = m g r·γ`.
//! - [`PotentialBody`]: any `U` given with its gradient and Hessian in ℝ³ (γ is a free vector).

use nalgebra::{Matrix3, Vector3};
use routh_core::{Lagrangian, Routhian};

/// `U(γ)` with its gradient and Hessian in ℝ³.
pub type PotentialTerms = (f64, Vector3<f64>, Matrix3<f64>);

/// A potential `γ ↦ (U, ∂U/∂γ, ∂²U/∂γ²)`.
pub type Potential = Box<dyn Fn(&Vector3<f64>) -> PotentialTerms>;

/// The kinetic part of the closed forms: everything of `L` and `R` but the potential.
#[derive(Debug, Clone, Copy)]
struct Kinetic<'a> {
    j: &'a Matrix3<f64>,
}

impl Kinetic<'_> {
    fn n(&self, g: &Vector3<f64>) -> f64 {
        g.dot(&(self.j * g))
    }
    fn q(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
        p - (self.j * w).dot(g)
    }
    /// ∂(q/n)/∂γ.
    fn dqn(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        let (n, q) = (self.n(g), self.q(w, g, p));
        -(self.j * w) / n - (2.0 * q / (n * n)) * (self.j * g)
    }
    fn lagrangian(&self, w: &Vector3<f64>) -> f64 {
        0.5 * w.dot(&(self.j * w))
    }
    fn routhian(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
        let (n, q) = (self.n(g), self.q(w, g, p));
        0.5 * w.dot(&(self.j * w)) - 0.5 * q * q / n
    }
    fn dr_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        let (n, q) = (self.n(g), self.q(w, g, p));
        self.j * w + (q / n) * (self.j * g)
    }
    fn dr_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        let (n, q) = (self.n(g), self.q(w, g, p));
        (q / n) * (self.j * w) + (q * q / (n * n)) * (self.j * g)
    }
    fn d2r_domega2(&self, g: &Vector3<f64>) -> Matrix3<f64> {
        let jg = self.j * g;
        self.j - jg * jg.transpose() / self.n(g)
    }
    fn d2r_domega_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
        let (n, q) = (self.n(g), self.q(w, g, p));
        (self.j * g) * self.dqn(w, g, p).transpose() + (q / n) * self.j
    }
    fn d2r_dgamma2(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
        let (n, q) = (self.n(g), self.q(w, g, p));
        let dqn = self.dqn(w, g, p);
        (self.j * w) * dqn.transpose()
            + (q * q / (n * n)) * self.j
            + (2.0 * q / n) * (self.j * g) * dqn.transpose()
    }
}

/// Implements `Lagrangian` and `Routhian` for a type with a field `j: Matrix3<f64>` and a method
/// `terms(&self, g) -> PotentialTerms`.
macro_rules! closed_form_body {
    ($ty:ty) => {
        impl Lagrangian for $ty {
            fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
                Kinetic { j: &self.j }.lagrangian(w) - self.terms(g).0
            }
            fn dl_domega(&self, w: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
                self.j * w
            }
            fn dl_dgamma(&self, _: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
                -self.terms(g).1
            }
            fn d2l_domega2(&self, _: &Vector3<f64>) -> Matrix3<f64> {
                self.j
            }
            fn d2l_domega_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Matrix3<f64> {
                Matrix3::zeros()
            }
            /// In closed form: `f = (Jω) × ω − ∇U × γ`, so `∂f/∂ω = [Jω]× − [ω]×J`,
            /// `∂f/∂γ = [γ]×H − [∇U]×` (`H` the Hessian of `U`), and `J` is constant.
            fn full_jacobian(
                &self,
                w: &Vector3<f64>,
                g: &Vector3<f64>,
            ) -> routh_core::FullJacobian {
                let (_, grad, hess) = self.terms(g);
                let jw = self.j * w;
                routh_core::FullJacobian {
                    inertia: self.j,
                    right_side: jw.cross(w) - grad.cross(g),
                    dright_domega: jw.cross_matrix() - w.cross_matrix() * self.j,
                    dright_dgamma: g.cross_matrix() * hess - grad.cross_matrix(),
                    dinertia_dgamma: [Matrix3::zeros(); 3],
                }
            }
        }

        impl Routhian for $ty {
            fn routhian(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
                Kinetic { j: &self.j }.routhian(w, g, p) - self.terms(g).0
            }
            fn dr_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
                Kinetic { j: &self.j }.dr_domega(w, g, p)
            }
            fn dr_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
                Kinetic { j: &self.j }.dr_dgamma(w, g, p) - self.terms(g).1
            }
            fn d2r_domega2(&self, _: &Vector3<f64>, g: &Vector3<f64>, _: f64) -> Matrix3<f64> {
                Kinetic { j: &self.j }.d2r_domega2(g)
            }
            fn d2r_domega_dgamma(
                &self,
                w: &Vector3<f64>,
                g: &Vector3<f64>,
                p: f64,
            ) -> Matrix3<f64> {
                Kinetic { j: &self.j }.d2r_domega_dgamma(w, g, p)
            }
            fn d2r_dgamma2(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
                Kinetic { j: &self.j }.d2r_dgamma2(w, g, p) - self.terms(g).2
            }
        }
    };
}

/// `L = ½ωᵀJω − m g r·γ` (J constant, symmetric positive definite), with its Routh function (39)
/// and every derivative in closed form. Independent of routh-core's analysis code and of the code
/// generator.
#[derive(Debug, Clone)]
pub struct HeavyTop {
    /// The inertia tensor J about the fixed point.
    pub j: Matrix3<f64>,
    /// m g r: the weight times the body-frame position of the centre of mass.
    pub mgr: Vector3<f64>,
}

impl HeavyTop {
    /// The Lagrange top J = diag(A₁, A₁, C), U = m g l γ₃.
    pub fn lagrange(a1: f64, c: f64, mgl: f64) -> Self {
        HeavyTop {
            j: Matrix3::from_diagonal(&Vector3::new(a1, a1, c)),
            mgr: Vector3::new(0.0, 0.0, mgl),
        }
    }
    /// ∂(q/n)/∂γ with `q = p_ψ − (JΩ)·γ`, `n = γᵀJγ`.
    pub fn dqn(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        Kinetic { j: &self.j }.dqn(w, g, p)
    }
    fn terms(&self, g: &Vector3<f64>) -> PotentialTerms {
        (self.mgr.dot(g), self.mgr, Matrix3::zeros())
    }
}

closed_form_body!(HeavyTop);

/// `L = ½ωᵀJω − U(γ)` with any potential given with its gradient and Hessian.
pub struct PotentialBody {
    /// The inertia tensor J about the fixed point.
    pub j: Matrix3<f64>,
    /// The potential.
    pub u: Potential,
}

impl PotentialBody {
    /// The body with inertia `j` and potential `u`.
    pub fn new(j: Matrix3<f64>, u: Potential) -> Self {
        PotentialBody { j, u }
    }
    /// The body with principal moments `(a, b, c)` and potential `u`.
    pub fn diag(a: f64, b: f64, c: f64, u: Potential) -> Self {
        PotentialBody::new(Matrix3::from_diagonal(&Vector3::new(a, b, c)), u)
    }
    fn terms(&self, g: &Vector3<f64>) -> PotentialTerms {
        (self.u)(g)
    }
}

closed_form_body!(PotentialBody);
