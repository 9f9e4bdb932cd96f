//! `classify_circle` against what it did not compute: the doubly amended potential of a
//! symmetric body written in Euler angles by hand (both cyclic momenta fixed),
//!
//! `V(θ) = (p_ψ − p_φ cos θ)² / (2A₁ sin²θ) + p_φ² / (2C) + U(cos θ)`,
//!
//! differentiated by central differences, and full simulations on either side of its verdict.

use derived_models::LagrangeTop;
use routh::{
    classify_circle, simulate_full, steady_motions, CircleStability, Lagrangian, RouthError,
    SimOptions, Stability, SteadyMotion, Vector3,
};

/// A symmetric body `J = diag(A, A, C)` in a quadrupole field, `U = ½ k γ₃²`.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * (a * (omega.x * omega.x + omega.y * omega.y) + c * omega.z * omega.z),
    potential = 0.5 * k * gamma.z * gamma.z,
)]
struct Quadrupole {
    a: f64,
    c: f64,
    k: f64,
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

/// `(V'(θ₀), V''(θ₀))` of the doubly amended potential above, by central differences, for the
/// circle `γ₃ = cos θ₀` of steady motions at `p_ψ` (where `ψ̇ = p_ψ / (A sin²θ₀ + C cos²θ₀)` and
/// `p_φ = C ψ̇ cos θ₀`), and `p_φ`.
fn closed_form(a: f64, c: f64, p: f64, z: f64, u: impl Fn(f64) -> f64) -> (f64, f64, f64) {
    let th0 = z.acos();
    let psi_dot = p / (a * th0.sin().powi(2) + c * z * z);
    let p_phi = c * psi_dot * z;
    let v = |th: f64| {
        (p - p_phi * th.cos()).powi(2) / (2.0 * a * th.sin().powi(2))
            + p_phi * p_phi / (2.0 * c)
            + u(th.cos())
    };
    // V' with a small step (its truncation h²V'''/6 is large near the poles); V'' with
    // Richardson's extrapolation of two steps (truncation O(h⁴), round-off ε/h²).
    let h1 = 1e-6;
    let d1 = (v(th0 + h1) - v(th0 - h1)) / (2.0 * h1);
    let second = |h: f64| (v(th0 + h) - 2.0 * v(th0) + v(th0 - h)) / (h * h);
    let d2 = (4.0 * second(5e-4) - second(1e-3)) / 3.0;
    (d1, d2, p_phi)
}

#[test]
fn lagrange_top_circles_are_minima_of_the_doubly_amended_potential() {
    let oblate = LagrangeTop::example();
    let prolate = LagrangeTop::with_mgl(1.0, 0.5, 1.0);
    for (top, zs) in [(oblate, [0.2, 0.5, 0.8]), (prolate, [-0.3, -0.6, -0.9])] {
        for z in zs {
            let p = top.tilted_family_p(z).unwrap();
            let gamma = Vector3::new((1.0 - z * z).sqrt(), 0.0, z);
            let motion = SteadyMotion::at(&top, gamma, p, false).unwrap();
            let circle = classify_circle(&top, &motion, &Vector3::z()).unwrap();
            let mgl = top.mgl();
            let (d1, d2, p_phi) = closed_form(top.a1, top.c, p, z, |x| mgl * x);
            assert!(d1.abs() < 1e-6 * d2.abs(), "z = {z}: V'(θ₀) = {d1}");
            assert!(
                rel(circle.curvature, d2) < 1e-5,
                "z = {z}: V'' = {} against {d2}",
                circle.curvature
            );
            assert!(rel(circle.axis_momentum, p_phi) < 1e-12);
            assert_eq!(circle.verdict, CircleStability::Stable, "z = {z}");
            // The plain test cannot decide a circle: its tangent is a null vector of K.
            assert_eq!(circle.report.verdict, Stability::Degenerate);
        }
    }
}

#[test]
fn quadrupole_body_circles_match_the_closed_form_on_both_sides() {
    // The equator γ₃ = 0 is a circle of steady motions for every p_ψ, with V'' = p²/A + k
    // (from the closed form by hand: sin²θ ≈ 1 − s², cos²θ ≈ s² at θ = π/2 + s, p_φ = 0).
    let (a, c, p) = (2.0, 1.0, 1.0);
    for (k, verdict) in [
        (-2.0, CircleStability::Unstable),
        (-0.25, CircleStability::Stable),
        (-0.5, CircleStability::Degenerate),
    ] {
        let body = Quadrupole { a, c, k };
        let motion = SteadyMotion::at(&body, Vector3::x(), p, false).unwrap();
        let circle = classify_circle(&body, &motion, &Vector3::z()).unwrap();
        assert!(
            (circle.curvature - (p * p / a + k)).abs() < 1e-12,
            "k = {k}: V'' = {}",
            circle.curvature
        );
        assert_eq!(circle.verdict, verdict, "k = {k}");
    }
    // Every circle that `steady_motions` finds off the equator, against the closed form.
    let mut seen = 0;
    for (k, p) in [
        (-2.0, 1.5),
        (-2.0, 2.5),
        (-3.0, 3.0),
        (-1.0, 1.5),
        (-6.0, 2.5),
    ] {
        let body = Quadrupole { a, c, k };
        for m in steady_motions(&body, p).unwrap() {
            let z = m.gamma.z;
            if m.isolated || z.abs() < 1e-6 || z.abs() > 1.0 - 1e-6 {
                continue;
            }
            let circle = classify_circle(&body, &m, &Vector3::z()).unwrap();
            let (d1, d2, _) = closed_form(a, c, p, z, |x| 0.5 * k * x * x);
            assert!(
                d1.abs() < 1e-6 * (1.0 + d2.abs()),
                "k = {k}, z = {z}: V' = {d1}"
            );
            assert!(
                (circle.curvature - d2).abs() < 1e-5 * (1.0 + d2.abs()),
                "k = {k}, p = {p}, z = {z}: V'' = {} against {d2}",
                circle.curvature
            );
            assert_eq!(circle.verdict, CircleStability::Stable);
            seen += 1;
        }
    }
    // Two circles ±z each (found by scanning the closed form beforehand): all minima of V.
    assert_eq!(seen, 10, "tilted circles found");
}

#[test]
fn simulations_leave_an_unstable_circle_and_stay_near_a_stable_one() {
    // The equator of the quadrupole body at p_ψ = 1: V'' = −1.5 (k = −2), +0.25 (k = −0.25).
    // Start on the circle, γ tilted towards e₃ by ε, with the steady ω = ψ̇γ of the equator.
    let max_height = |k: f64, eps: f64| {
        let body = Quadrupole { a: 2.0, c: 1.0, k };
        let motion = SteadyMotion::at(&body, Vector3::x(), 1.0, false).unwrap();
        let omega0 = motion.psi_dot * Vector3::x();
        let gamma0 = Vector3::new(eps.cos(), 0.0, eps.sin());
        let opts = SimOptions::with_tolerances(1e-10, 1e-12);
        let traj = simulate_full(&body, omega0, gamma0, 40.0, &opts).unwrap();
        traj.gamma.iter().map(|g| g.z.abs()).fold(0.0f64, f64::max)
    };
    let unstable = max_height(-2.0, 1e-6);
    let stable = max_height(-0.25, 1e-6);
    assert!(unstable > 0.1, "k = −2: γ₃ stayed below {unstable}");
    assert!(stable < 1e-4, "k = −0.25: γ₃ reached {stable}");
}

#[test]
fn an_axis_that_is_not_a_symmetry_is_an_error() {
    let top = LagrangeTop::example();
    let z: f64 = 0.5;
    let p = top.tilted_family_p(z).unwrap();
    let gamma = Vector3::new((1.0 - z * z).sqrt(), 0.0, z);
    let motion = SteadyMotion::at(&top, gamma, p, false).unwrap();
    // e₂ is not an axis of symmetry of the Lagrange top.
    let err = classify_circle(&top, &motion, &Vector3::y()).unwrap_err();
    assert!(matches!(err, RouthError::InvalidModel { .. }), "{err}");
    // The axis through γ itself, and a zero axis.
    for axis in [gamma, Vector3::zeros()] {
        let err = classify_circle(&top, &motion, &axis).unwrap_err();
        assert!(matches!(err, RouthError::InvalidOption { .. }), "{err}");
    }
}
