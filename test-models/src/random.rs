//! Random test data.

use nalgebra::{Matrix3, Vector3};
use rand::Rng;

/// A vector with components uniform in `[−scale, scale]`.
pub fn random_vector<R: Rng + ?Sized>(rng: &mut R, scale: f64) -> Vector3<f64> {
    Vector3::from_fn(|_, _| rng.gen_range(-scale..=scale))
}

/// A matrix with entries uniform in `[−scale, scale]`.
pub fn random_matrix<R: Rng + ?Sized>(rng: &mut R, scale: f64) -> Matrix3<f64> {
    Matrix3::from_fn(|_, _| rng.gen_range(-scale..=scale))
}

/// A unit vector uniformly distributed on the sphere (rejection sampling in the unit ball).
pub fn random_unit_vector<R: Rng + ?Sized>(rng: &mut R) -> Vector3<f64> {
    loop {
        let v = random_vector(rng, 1.0);
        let n = v.norm();
        if (0.1..=1.0).contains(&n) {
            return v / n;
        }
    }
}

/// A vector of uniformly random direction and length uniform in `[0.5, 1.5]`: a γ off the sphere
/// (the paper differentiates in ℝ³, so the functions of γ are defined there too).
pub fn random_gamma<R: Rng + ?Sized>(rng: &mut R) -> Vector3<f64> {
    random_unit_vector(rng) * rng.gen_range(0.5..1.5)
}

/// A random unit vector orthogonal to `gamma` (which need not be unit, but must be non-zero).
pub fn random_tangent<R: Rng + ?Sized>(rng: &mut R, gamma: &Vector3<f64>) -> Vector3<f64> {
    let g = gamma.normalize();
    loop {
        let v = random_unit_vector(rng);
        let t = v - g * v.dot(&g);
        let n = t.norm();
        if n > 0.1 {
            return t / n;
        }
    }
}

/// A random symmetric positive definite matrix `Q diag(λ) Qᵀ` with a uniformly random rotation
/// `Q` and eigenvalues `λ` uniform in `[1, 3]` (a generic, well-conditioned inertia tensor).
pub fn random_spd<R: Rng + ?Sized>(rng: &mut R) -> Matrix3<f64> {
    // Uniform random rotation from a uniform unit quaternion (rejection in the 4-ball).
    let q = loop {
        let q: [f64; 4] = std::array::from_fn(|_| rng.gen_range(-1.0..=1.0));
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        if (0.1..=1.0).contains(&n) {
            break q.map(|x| x / n);
        }
    };
    let [w, x, y, z] = q;
    let rot = Matrix3::new(
        1.0 - 2.0 * (y * y + z * z),
        2.0 * (x * y - w * z),
        2.0 * (x * z + w * y),
        2.0 * (x * y + w * z),
        1.0 - 2.0 * (x * x + z * z),
        2.0 * (y * z - w * x),
        2.0 * (x * z - w * y),
        2.0 * (y * z + w * x),
        1.0 - 2.0 * (x * x + y * y),
    );
    let lambda = Vector3::from_fn(|_, _| rng.gen_range(1.0..3.0));
    let m = rot * Matrix3::from_diagonal(&lambda) * rot.transpose();
    // Exact symmetry.
    (m + m.transpose()) * 0.5
}
