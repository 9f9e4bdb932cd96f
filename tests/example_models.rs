//! The TOML models of examples/models load and find their steady motions, checked against
//! closed forms and the derived twins.

use derived_models::{Ellipsoid, Gyrostat, LagrangeTop};
use routh::{classify, steady_motions, Lagrangian, Model, Routhian, Stability, Vector3};

fn load(name: &str) -> Model {
    let path = format!("{}/examples/models/{name}", env!("CARGO_MANIFEST_DIR"));
    Model::from_file(&path).unwrap_or_else(|e| panic!("{path}:\n{e}"))
}

#[test]
fn heavy_top_is_the_lagrange_top_of_the_example() {
    let m = load("heavy_top.toml");
    let d = LagrangeTop::example();
    assert_eq!(m.latex_symbols().get("a1").map(String::as_str), Some("A_1"));
    // The sleeping top at p_ψ = 3 > Maievskii's bound 2√(A₁ m g l) = 2 is stable: steady
    // motions at both poles, the upright one stable.
    let p = 3.0;
    let motions = steady_motions(&m, p).unwrap();
    let derived = steady_motions(&d, p).unwrap();
    assert_eq!(motions.len(), derived.len());
    let up = motions
        .iter()
        .find(|s| (s.gamma - Vector3::z()).norm() < 1e-8)
        .expect("the sleeping top");
    // U_r at the pole: p²/(2C) + m g l.
    assert!((up.amended_potential - (p * p / 2.5 + 1.0)).abs() < 1e-12);
    assert_ne!(classify(&m, up).unwrap().verdict, Stability::Unstable);
}

#[test]
fn gyrostat_is_the_kelvin_gyrostat() {
    let m = load("gyrostat.toml");
    let d = Gyrostat::kelvin();
    for p in [0.5, 3.5] {
        let (a, b) = (
            steady_motions(&m, p).unwrap(),
            steady_motions(&d, p).unwrap(),
        );
        assert!(!a.is_empty());
        assert_eq!(a.len(), b.len(), "p = {p}");
    }
    let g = Vector3::new(0.0, 0.6, 0.8);
    assert!((m.amended_potential(&g, 2.0) - d.amended_potential(&g, 2.0)).abs() < 1e-13);
}

#[test]
fn ellipsoid_is_the_spheroid() {
    let m = load("ellipsoid.toml");
    let d = Ellipsoid::spheroid();
    let p = 5.0;
    let (a, b) = (
        steady_motions(&m, p).unwrap(),
        steady_motions(&d, p).unwrap(),
    );
    assert!(!a.is_empty());
    assert_eq!(a.len(), b.len());
    assert!(
        m.constant_inertia().is_some(),
        "the rank-one split is found at run time too"
    );
}

#[test]
fn kovalevskaya_top_has_its_steady_motions() {
    let m = load("kovalevskaya.toml");
    // At p_ψ = 0 the steady motions are the equilibria: the critical points of U = γ₁ on the
    // sphere, γ = ±e₁ (U_r = p²/(2γᵀIγ) + γ₁ has no other critical point when p = 0).
    let motions = steady_motions(&m, 0.0).unwrap();
    assert_eq!(motions.len(), 2, "{motions:?}");
    for s in &motions {
        assert!((s.gamma.x.abs() - 1.0).abs() < 1e-8, "{:?}", s.gamma);
    }
    // With momentum: every motion found is a critical point of U_r on the sphere.
    for s in steady_motions(&m, 1.5).unwrap() {
        let grad = m.dr_dgamma(&Vector3::zeros(), &s.gamma, 1.5);
        let tangential = grad - grad.dot(&s.gamma) * s.gamma;
        assert!(tangential.norm() < 1e-9);
    }
}
