//! Paper Example 3: a rigid body in an ideal fluid, through [`routh::fluid::kirchhoff_lagrangian`]
//! (errata E3, E7).

use routh::fluid::{kirchhoff_lagrangian, FluidParameters};
use routh::RouthError;
use routh::{Lagrangian, Matrix3, Vector3};

/// `L(ω, γ) = ½(Aω, ω) + (Λγ, ω) − ½(Πγ, γ)` with the matrices of
/// [`kirchhoff_lagrangian`]: γ is the body-frame unit vector along the impulse.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(a_kin * omega),
    linear = (lin * gamma).dot(omega),
    potential = 0.5 * gamma.dot(pot * gamma),
)]
pub struct FluidBody {
    /// `A = a − bᵀc⁻¹b`.
    pub a_kin: Matrix3<f64>,
    /// `Λ = k bᵀc⁻¹`.
    pub lin: Matrix3<f64>,
    /// `Π = k²c⁻¹`.
    pub pot: Matrix3<f64>,
}

impl From<&FluidParameters> for FluidBody {
    fn from(f: &FluidParameters) -> Self {
        FluidBody {
            a_kin: f.kinetic,
            lin: f.linear,
            pot: f.potential,
        }
    }
}

/// The matrices `a`, `b`, `c` of Kirchhoff's kinetic energy (53) of a body (with its added
/// masses).
#[derive(Debug, Clone, Copy)]
pub struct Kirchhoff {
    /// Rotational block `a`.
    pub a: Matrix3<f64>,
    /// Coupling block `b` (`(bω, v)`).
    pub b: Matrix3<f64>,
    /// Translational block `c`.
    pub c: Matrix3<f64>,
}

impl Kirchhoff {
    /// An elongated body of revolution about `e₃` with three planes of symmetry (`b = 0`):
    /// `a = diag(1, 1, 0.4)`, `c = diag(3, 3, 1.5)` — less added mass along the axis than
    /// across it.
    pub fn body_of_revolution() -> Self {
        Kirchhoff {
            a: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.4)),
            b: Matrix3::zeros(),
            c: Matrix3::from_diagonal(&Vector3::new(3.0, 3.0, 1.5)),
        }
    }

    /// A body without symmetry (a screw-like body, `b ≠ 0` and not symmetric).
    pub fn chiral() -> Self {
        Kirchhoff {
            a: Matrix3::new(1.2, 0.05, 0.0, 0.05, 1.0, 0.02, 0.0, 0.02, 0.5),
            b: Matrix3::new(0.2, 0.05, 0.0, 0.0, 0.1, 0.03, 0.02, 0.0, 0.3),
            c: Matrix3::new(3.0, 0.1, 0.0, 0.1, 2.5, 0.0, 0.0, 0.0, 1.5),
        }
    }

    /// The reduced Lagrangian's matrices at impulse magnitude `k`.
    pub fn parameters(&self, k: f64) -> Result<FluidParameters, RouthError> {
        kirchhoff_lagrangian(self.a, self.b, self.c, k)
    }

    /// `T(ω, v)` of (53).
    pub fn energy(&self, omega: &Vector3<f64>, v: &Vector3<f64>) -> f64 {
        0.5 * (omega.dot(&(self.a * omega)) + 2.0 * v.dot(&(self.b * omega)) + v.dot(&(self.c * v)))
    }

    /// Kirchhoff's stability bound for the spinning body of revolution moving along its axis
    /// (`b = 0`, `a = diag(A₁, A₁, A₃)`, `c = diag(c₁, c₁, c₃)`). On the sphere the potential
    /// `½k²(c⁻¹γ, γ)` is `const + ½k²(1/c₃ − 1/c₁)γ₃²`, whose second variation at `γ = e₃` is
    /// `−k²(1/c₃ − 1/c₁)`: the same as the Lagrange top's `−m g l`. The top's analysis then
    /// carries over (see `ellipsoid.rs` for the quartic): the motion along the axis is stable iff
    /// `p_ψ² > 4A₁k²(1/c₃ − 1/c₁)`, Maievskii's bound with `m g l → k²(1/c₃ − 1/c₁)`.
    pub fn axial_threshold(&self, k: f64) -> f64 {
        let (a1, c1, c3) = (self.a[(0, 0)], self.c[(0, 0)], self.c[(2, 2)]);
        (4.0 * a1 * k * k * (1.0 / c3 - 1.0 / c1)).sqrt()
    }
}

/// The state `(ω₀, γ₀)` of the body moving along its axis `e₃`, its axis tilted by `tilt` radians
/// away from the impulse, spinning so that the cyclic momentum (9) is `p_psi`
/// (`b = 0`, diagonal `A`).
pub fn perturbed_axial(f: &FluidParameters, p_psi: f64, tilt: f64) -> (Vector3<f64>, Vector3<f64>) {
    let gamma0 = Vector3::new(tilt.sin(), 0.0, tilt.cos());
    let omega0 = Vector3::new(0.0, 0.0, p_psi / (f.kinetic[(2, 2)] * tilt.cos()));
    (omega0, gamma0)
}
