//! Models declared with the derive, mirroring the hand-written num-dual references of the
//! `test-models` crate field for field.
#![allow(dead_code)]

use routh::{Lagrangian, Matrix3, Vector3};

/// Heavy rigid body about a fixed point carrying a rotor (Kelvin gyrostat), with a(γ) = K + Bγ.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega),
    linear = (rotor + coupling * gamma).dot(omega),
    potential = mass * g * com.dot(gamma),
)]
pub struct Gyrostat {
    pub inertia: Matrix3<f64>,
    pub rotor: Vector3<f64>,
    pub coupling: Matrix3<f64>,
    pub com: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
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

/// Heavy ellipsoid on a frictionless plane (paper Example 2; ERRATA E1, E2, E6): the height of
/// the centre of mass is the support function C₃(γ) = sqrt(γᵀDγ) − c₀·γ.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]
pub struct Ellipsoid {
    pub inertia: Matrix3<f64>,
    pub semi_axes: Vector3<f64>,
    pub offset: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}

impl From<&test_models::Ellipsoid> for Ellipsoid {
    fn from(m: &test_models::Ellipsoid) -> Self {
        Ellipsoid {
            inertia: m.inertia,
            semi_axes: m.semi_axes,
            offset: m.offset,
            mass: m.mass,
            g: m.g,
        }
    }
}

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
