//! Models shared by the benches, declared with the derive. Each declaration is also kept as
//! source text (`*_SRC`), so that `benches/expand.rs` times the expansion of exactly the models
//! that `benches/bundle.rs` evaluates.
#![allow(dead_code)]

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::{Lagrangian, Matrix3, Vector3};

/// Declares the item and a `&str` constant holding its source tokens.
macro_rules! model {
    ($src:ident: $($item:tt)*) => {
        $($item)*
        /// The declaration above, as source text.
        pub const $src: &str = stringify!($($item)*);
    };
}

model! { GYROSTAT_SRC:
    /// M1. Heavy rigid body about a fixed point carrying a rotor (Kelvin gyrostat), with
    /// a(γ) = K + Bγ (as in `tests/common/mod.rs`). The inertia tensor is declared symmetric,
    /// as the hand-written bundle assumes it to be.
    #[derive(Lagrangian, Debug, Clone)]
    #[lagrangian(
        kinetic = 0.5 * omega.dot(inertia * omega),
        linear = (rotor + coupling * gamma).dot(omega),
        potential = mass * g * com.dot(gamma),
    )]
    pub struct Gyrostat {
        #[lagrangian(symmetric)]
        pub inertia: Matrix3<f64>,
        pub rotor: Vector3<f64>,
        pub coupling: Matrix3<f64>,
        pub com: Vector3<f64>,
        pub mass: f64,
        pub g: f64,
    }
}

model! { ELLIPSOID2_SRC:
    /// M2. Heavy ellipsoid on a frictionless plane (paper Example 2) with a diagonal inertia
    /// tensor and D written with `diag(v)`.
    #[derive(Lagrangian, Debug, Clone)]
    #[lagrangian(
        let d = diag(semi_axes.component_mul(semi_axes)),
        let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
        let n = grad(c3, gamma),
        kinetic = 0.5 * (omega.dot(diag(inertia) * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
        potential = mass * g * c3,
    )]
    pub struct Ellipsoid2 {
        pub inertia: Vector3<f64>,
        pub semi_axes: Vector3<f64>,
        pub offset: Vector3<f64>,
        pub mass: f64,
        pub g: f64,
    }
}

impl From<&test_models::Gyrostat> for Gyrostat {
    fn from(m: &test_models::Gyrostat) -> Self {
        Gyrostat {
            inertia: m.inertia,
            rotor: m.rotor,
            coupling: m.coupling,
            com: m.com,
            mass: m.mass,
            g: m.g,
        }
    }
}

impl Ellipsoid2 {
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

/// A deterministic generator for the benches.
pub fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

/// M1: a generic gyrostat (full SPD I, K, general B, r) and its num-dual twin.
pub fn m1(rng: &mut ChaCha8Rng) -> (Gyrostat, test_models::Gyrostat) {
    let twin = test_models::Gyrostat::random(rng);
    (Gyrostat::from(&twin), twin)
}

/// M2: a generic ellipsoid with diagonal inertia (moments in [1, 3]), semi-axes in [0.5, 1.5],
/// offset in [−0.2, 0.2]³, and its num-dual twin.
pub fn m2(rng: &mut ChaCha8Rng) -> (Ellipsoid2, test_models::Ellipsoid) {
    let model = Ellipsoid2 {
        inertia: Vector3::from_fn(|_, _| rng.gen_range(1.0..3.0)),
        semi_axes: Vector3::from_fn(|_, _| rng.gen_range(0.5..1.5)),
        offset: test_models::random_vector(rng, 0.2),
        mass: rng.gen_range(0.5..2.0),
        g: 9.81,
    };
    let twin = model.twin();
    (model, twin)
}

/// One input point `(Ω, γ, p_ψ)`.
#[derive(Debug, Clone, Copy)]
pub struct Point {
    pub big_omega: Vector3<f64>,
    pub gamma: Vector3<f64>,
    pub p_psi: f64,
}

/// `n` random points: Ω in [−2, 2]³, γ uniform on the unit sphere, p_ψ in [−3, 3].
pub fn points(rng: &mut ChaCha8Rng, n: usize) -> Vec<Point> {
    (0..n)
        .map(|_| Point {
            big_omega: test_models::random_vector(rng, 2.0),
            gamma: test_models::random_unit_vector(rng),
            p_psi: rng.gen_range(-3.0..3.0),
        })
        .collect()
}
