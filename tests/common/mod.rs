//! Comparison helpers shared by the tests. The models are in the `derived-models` crate
//! (`test-models/derived`), each beside its num-dual twin of `test-models`.
#![allow(dead_code)]

use routh::{Matrix3, Vector3};

/// Normwise relative agreement: `‖a − b‖∞ ≤ tol · max(‖b‖∞, floor)`, the floor guarding outputs
/// that are exactly zero in the reference.
/// Returns the relative error `‖a − b‖∞ / max(‖b‖∞, floor)` on success.
pub fn close(a: &[f64], b: &[f64], tol: f64, floor: f64) -> Result<f64, String> {
    let scale = b.iter().fold(floor, |m, x| m.max(x.abs()));
    let err = a
        .iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    if err <= tol * scale && a.iter().all(|x| x.is_finite()) {
        Ok(err / scale)
    } else {
        Err(format!(
            "error {err:e} > {tol:e} × {scale:e}\n  got      {a:?}\n  expected {b:?}"
        ))
    }
}

pub fn s(x: f64) -> Vec<f64> {
    vec![x]
}

pub fn v(x: Vector3<f64>) -> Vec<f64> {
    x.iter().copied().collect()
}

pub fn m(x: Matrix3<f64>) -> Vec<f64> {
    x.iter().copied().collect()
}
