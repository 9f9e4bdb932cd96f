//! Heavy tops: the symmetric (Lagrange) top `J = diag(A₁, A₁, C)`, `U = m g l γ₃`, and a heavy
//! asymmetric top with principal moments. Their twins are `test_models::Gyrostat::lagrange_top`
//! and `test_models::Gyrostat::heavy_top` (`K = B = 0`).

use routh::{Lagrangian, Vector3};

/// The Lagrange top about its fixed point: `L = ½(A₁(ω₁² + ω₂²) + Cω₃²) − m g l γ₃`, the centre
/// of mass at distance `l` from the fixed point on the symmetry axis `e₃`.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * (a1 * (omega.x * omega.x + omega.y * omega.y) + c * omega.z * omega.z),
    potential = mass * g * l * gamma.z,
)]
pub struct LagrangeTop {
    /// Transverse moment of inertia about the fixed point, `A₁`.
    #[lagrangian(latex = "A_1")]
    pub a1: f64,
    /// Axial moment of inertia, `C`.
    #[lagrangian(latex = "C")]
    pub c: f64,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
    /// Distance `l` from the fixed point to the centre of mass.
    pub l: f64,
}

impl LagrangeTop {
    /// The top of the example, in units where `A₁ = m = g = l = 1`: `C = 1.25`, an oblate top
    /// (`C > A₁`, still `C ≤ 2A₁`), chosen so that the sleeping top passes through all three
    /// verdicts: unstable, gyroscopically stabilised, secularly stable.
    pub fn example() -> Self {
        LagrangeTop {
            a1: 1.0,
            c: 1.25,
            mass: 1.0,
            g: 1.0,
            l: 1.0,
        }
    }

    /// The Lagrange top `(A₁, C, m g l)` in units where `m = g = 1`.
    pub fn with_mgl(a1: f64, c: f64, mgl: f64) -> Self {
        LagrangeTop {
            a1,
            c,
            mass: 1.0,
            g: 1.0,
            l: mgl,
        }
    }

    /// The num-dual twin.
    pub fn twin(&self) -> test_models::Gyrostat {
        test_models::Gyrostat::lagrange_top(self.a1, self.c, self.mgl())
    }

    /// `m g l`.
    pub fn mgl(&self) -> f64 {
        self.mass * self.g * self.l
    }

    /// Maievskii's bound: the sleeping top is stable iff `p_ψ² > 4 A₁ m g l`.
    pub fn maievskii_p(&self) -> f64 {
        (4.0 * self.a1 * self.mgl()).sqrt()
    }

    /// The `p_ψ` above which the sleeping top is a minimum of the amended potential (secular
    /// stability), for an oblate top (`C > A₁`): the restricted second variation at `γ = e₃` is
    /// `p²(C − A₁)/C² − m g l` (twice), positive iff `p² > m g l C²/(C − A₁)`. `None` for
    /// `C ≤ A₁` (never secularly stable).
    pub fn secular_p(&self) -> Option<f64> {
        (self.c > self.a1).then(|| (self.mgl() * self.c * self.c / (self.c - self.a1)).sqrt())
    }

    /// The family of tilted steady motions: on the sphere with `z = γ₃`,
    /// `U_r = p²/(2(A₁ + (C − A₁)z²)) + m g l z`, and `dU_r/dz = 0` at
    /// `m g l (A₁ + (C − A₁)z²)² = p² (C − A₁) z`. Returns the `p_ψ ≥ 0` of the member at height
    /// `z` (`None` where there is none, i.e. `(C − A₁)z ≤ 0`).
    pub fn tilted_family_p(&self, z: f64) -> Option<f64> {
        let d = self.c - self.a1;
        let n = self.a1 + d * z * z;
        (d * z > 0.0).then(|| (self.mgl() * n * n / (d * z)).sqrt())
    }

    /// The initial state of a sleeping top tilted by `tilt` radians about `e₂` with the spin
    /// chosen so that the cyclic momentum (9) is exactly `p_psi`: `γ₀ = (sin ε, 0, cos ε)`,
    /// `ω₀ = (0, 0, p_ψ/(C cos ε))`. Returns `(ω₀, γ₀)`.
    pub fn perturbed_sleeping(&self, p_psi: f64, tilt: f64) -> (Vector3<f64>, Vector3<f64>) {
        let gamma0 = Vector3::new(tilt.sin(), 0.0, tilt.cos());
        let omega0 = Vector3::new(0.0, 0.0, p_psi / (self.c * tilt.cos()));
        (omega0, gamma0)
    }
}

/// A heavy rigid body about a fixed point with principal moments `inertia` and centre of mass
/// `com` (off the axes: an asymmetric heavy top), as in the simulation bench.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = mass * g * com.dot(gamma),
)]
pub struct AsymmetricTop {
    /// Principal moments of inertia about the fixed point.
    pub inertia: Vector3<f64>,
    /// Centre of mass in the body frame.
    pub com: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
}

impl AsymmetricTop {
    /// The num-dual twin.
    pub fn twin(&self) -> test_models::Gyrostat {
        test_models::Gyrostat::heavy_top(self.inertia, self.com, self.mass, self.g)
    }
}
