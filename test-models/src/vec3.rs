//! Generic 3-vector helpers over any [`DualNum<f64>`] scalar, used to write the models' `L` and
//! `R` once for `f64` and for dual numbers alike. Vectors are plain arrays `[D; 3]`; constant
//! model data stays `f64` (`Vector3<f64>`, `Matrix3<f64>`).

use nalgebra::{Matrix3, Vector3};
use num_dual::DualNum;

/// A 3-vector of (dual) scalars.
pub type V3<D> = [D; 3];

/// Lifts an `f64` vector to constant dual numbers.
pub fn lift<D: DualNum<f64>>(v: &Vector3<f64>) -> V3<D> {
    [D::from(v.x), D::from(v.y), D::from(v.z)]
}

/// `a·b`.
pub fn dot<D: DualNum<f64> + Copy>(a: &V3<D>, b: &V3<D>) -> D {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `c·v` with a constant `c`.
pub fn dot_const<D: DualNum<f64> + Copy>(c: &Vector3<f64>, v: &V3<D>) -> D {
    v[0] * c.x + v[1] * c.y + v[2] * c.z
}

/// `a × b`.
pub fn cross<D: DualNum<f64> + Copy>(a: &V3<D>, b: &V3<D>) -> V3<D> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `M v` with a constant matrix `M`.
pub fn mat_vec<D: DualNum<f64> + Copy>(m: &Matrix3<f64>, v: &V3<D>) -> V3<D> {
    std::array::from_fn(|i| v[0] * m[(i, 0)] + v[1] * m[(i, 1)] + v[2] * m[(i, 2)])
}

/// `vᵀ M v` with a constant matrix `M`.
pub fn quad_form<D: DualNum<f64> + Copy>(m: &Matrix3<f64>, v: &V3<D>) -> D {
    dot(v, &mat_vec(m, v))
}

/// `a + b`.
pub fn add<D: DualNum<f64> + Copy>(a: &V3<D>, b: &V3<D>) -> V3<D> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a − b`.
pub fn sub<D: DualNum<f64> + Copy>(a: &V3<D>, b: &V3<D>) -> V3<D> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `s v`.
pub fn scale<D: DualNum<f64> + Copy>(v: &V3<D>, s: D) -> V3<D> {
    [v[0] * s, v[1] * s, v[2] * s]
}

/// The real parts of a dual vector.
pub fn re<D: DualNum<f64>>(v: &V3<D>) -> Vector3<f64> {
    Vector3::new(v[0].re(), v[1].re(), v[2].re())
}
