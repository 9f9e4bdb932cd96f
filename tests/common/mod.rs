//! Comparison helpers shared by the tests. The models are in the `derived-models` crate
//! (`test-models/derived`), each beside its num-dual twin of `test-models`.
#![allow(dead_code)]

use routh::{Matrix3, Vector3};

/// The shared comparisons (test-models): `close` for lists, `close_to` for scalars.
pub use test_models::compare::{close, close_to};

pub fn s(x: f64) -> Vec<f64> {
    vec![x]
}

pub fn v(x: Vector3<f64>) -> Vec<f64> {
    x.iter().copied().collect()
}

pub fn m(x: Matrix3<f64>) -> Vec<f64> {
    x.iter().copied().collect()
}
