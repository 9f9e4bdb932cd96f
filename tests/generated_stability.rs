//! Steady motions and stability of models declared with the derive: the roots of f₂ built from
//! the generated `gyroscopic_system` against a finite-difference Jacobian of the full system (8)
//! built from the generated `Lagrangian` (errata E5), the verdicts against those of the num-dual
//! twin models, and Maievskii's criterion for a derived Lagrange top.

use derived_models::{Ellipsoid, Gyrostat, LagrangeTop};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::{classify, steady_motions, Stability, SteadyMotion, Vector3};
use test_models::jacobian::assert_f2_roots_are_jacobian_eigenvalues;

#[test]
fn f2_roots_of_generated_models_match_the_full_jacobian() {
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    let mut worst = 0.0f64;
    let mut checked = 0;
    for _ in 0..3 {
        let twin = test_models::Gyrostat::random(&mut rng);
        let model = Gyrostat::from(&twin);
        let p = rng.gen_range(1.0..6.0);
        let found = steady_motions(&model, p).expect("steady motions");
        let reference = steady_motions(&twin, p).expect("steady motions of the twin");
        assert_eq!(
            found.len(),
            reference.len(),
            "same number of steady motions as the twin"
        );
        for s in found.iter().filter(|s| s.isolated) {
            worst = worst.max(assert_f2_roots_are_jacobian_eigenvalues(
                &model, s, "gyrostat",
            ));
            // The verdict equals the num-dual twin's at the same steady motion.
            let ours = classify(&model, s).expect("classify").verdict;
            let theirs = classify(&twin, s).expect("classify twin").verdict;
            assert_eq!(ours, theirs);
            checked += 1;
        }
        let twin = test_models::Ellipsoid::random(&mut rng);
        let model = Ellipsoid::from(&twin);
        for s in steady_motions(&model, p)
            .expect("steady motions")
            .iter()
            .filter(|s| s.isolated)
        {
            worst = worst.max(assert_f2_roots_are_jacobian_eigenvalues(
                &model,
                s,
                "ellipsoid",
            ));
            checked += 1;
        }
    }
    eprintln!("{checked} steady motions; worst relative f₂-root mismatch {worst:.1e}");
    assert!(checked >= 12);
}

/// Maievskii's bound p² = 4A₁mgl. Just above it the restricted second variation of the sleeping
/// top, h = p²(C − A₁)/C² − mgl (twice), is still negative for these tops (checked below), so
/// the only right verdict there is `GyroscopicallyStabilized`; just below, `Unstable`.
#[test]
fn derived_lagrange_top_obeys_maievskii() {
    for (a1, c, mgl) in [(2.0, 1.0, 1.0), (1.0, 1.5, 0.7), (1.0, 3.0, 2.0)] {
        let top = LagrangeTop::with_mgl(a1, c, mgl);
        let sleeping = |p2: f64| {
            SteadyMotion::at(&top, Vector3::z(), p2.sqrt(), true).expect("a steady motion")
        };
        let maievskii = 4.0 * a1 * mgl;
        let below = maievskii * (1.0 - 0.001);
        let above = maievskii * (1.0 + 0.001);
        let h_above = above * (c - a1) / (c * c) - mgl;
        assert!(h_above < 0.0, "degree 2 above the bound: h = {h_above}");
        assert_eq!(
            classify(&top, &sleeping(below)).unwrap().verdict,
            Stability::Unstable
        );
        assert_eq!(
            classify(&top, &sleeping(above)).unwrap().verdict,
            Stability::GyroscopicallyStabilized,
            "A₁ = {a1}, C = {c}, mgl = {mgl}"
        );
    }
}
