//! Shared by the stability and steady-motion tests: the closed-form heavy top now lives in the
//! shared models crate (`test_models::HeavyTop`).
#![allow(unused_imports)]

pub use test_models::HeavyTop;

use routh_core::{simulate_full, Matrix3, PeriodicOrbit, SimOptions, Vector3};

/// A heavy body `J = diag(a, b, c)` with its centre of mass on the third axis (`U = mgl γ₃`).
pub fn heavy_body(a: f64, b: f64, c: f64, mgl: f64) -> HeavyTop {
    HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(a, b, c)),
        mgr: Vector3::new(0.0, 0.0, mgl),
    }
}

/// The complete elliptic integral `K(m) = π / (2 AGM(1, √(1 − m)))` (the pendulum's period is
/// `4K(sin²(θ₀/2))/ω₀`).
pub fn elliptic_k(m: f64) -> f64 {
    let (mut a, mut g) = (1.0f64, (1.0 - m).sqrt());
    for _ in 0..60 {
        let (an, gn) = (0.5 * (a + g), (a * g).sqrt());
        a = an;
        g = gn;
    }
    std::f64::consts::PI / (2.0 * a)
}

/// How far an orbit is from closing under `simulate_full` (another integrator than the
/// corrector's, no corrector): `|ω(T) − Rω₀| + |γ(T) − Rγ₀|` with `R = Rot(e₃, −Δφ)` the body
/// turn back (the identity on a body without the axial symmetry).
pub fn closure_gap(m: &HeavyTop, o: &PeriodicOrbit) -> f64 {
    let tr = simulate_full(
        m,
        o.omega0,
        o.gamma0,
        o.period,
        &SimOptions::with_tolerances(1e-12, 1e-13),
    )
    .unwrap();
    let n = tr.t.len() - 1;
    let r = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), -o.body_turn);
    (tr.omega[n] - r * o.omega0).norm() + (tr.gamma[n] - r * o.gamma0).norm()
}
