//! A heavy top written by hand in closed form (no automatic differentiation): a second,
//! independent reference next to the num-dual [`Gyrostat`](crate::Gyrostat).

use nalgebra::{Matrix3, Vector3};
use routh_core::{Lagrangian, Routhian};

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
    fn n(&self, g: &Vector3<f64>) -> f64 {
        g.dot(&(self.j * g))
    }
    fn q(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
        p - (self.j * w).dot(g)
    }
    /// ∂(q/n)/∂γ.
    pub fn dqn(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        let (n, q) = (self.n(g), self.q(w, g, p));
        -(self.j * w) / n - (2.0 * q / (n * n)) * (self.j * g)
    }
}

impl Lagrangian for HeavyTop {
    fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
        0.5 * w.dot(&(self.j * w)) - self.mgr.dot(g)
    }
    fn dl_domega(&self, w: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
        self.j * w
    }
    fn dl_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
        -self.mgr
    }
    fn d2l_domega2(&self, _: &Vector3<f64>) -> Matrix3<f64> {
        self.j
    }
    fn d2l_domega_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Matrix3<f64> {
        Matrix3::zeros()
    }
}

impl Routhian for HeavyTop {
    fn routhian(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
        let (n, q) = (self.n(g), self.q(w, g, p));
        0.5 * w.dot(&(self.j * w)) - self.mgr.dot(g) - 0.5 * q * q / n
    }
    fn dr_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        let (n, q) = (self.n(g), self.q(w, g, p));
        self.j * w + (q / n) * (self.j * g)
    }
    fn dr_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        let (n, q) = (self.n(g), self.q(w, g, p));
        -self.mgr + (q / n) * (self.j * w) + (q * q / (n * n)) * (self.j * g)
    }
    fn d2r_domega2(&self, _: &Vector3<f64>, g: &Vector3<f64>, _: f64) -> Matrix3<f64> {
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
