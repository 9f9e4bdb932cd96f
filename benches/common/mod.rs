//! Inputs shared by the benches. The models are the derived ones of the `derived-models` crate
//! (M1 [`Gyrostat`], M2 [`DiagonalEllipsoid`]), each with its num-dual twin of `test-models`; their
//! source text (`derived_models::GYROSTAT_SRC`, `DIAGONAL_ELLIPSOID_SRC`) is what
//! `benches/expand.rs` expands.
#![allow(dead_code)]

use derived_models::{DiagonalEllipsoid, Gyrostat};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::Vector3;

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
pub fn m2(rng: &mut ChaCha8Rng) -> (DiagonalEllipsoid, test_models::Ellipsoid) {
    let model = DiagonalEllipsoid::random(rng);
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
