//! Steady motions and stability of models declared with the derive: the roots of f₂ built from
//! the generated `gyroscopic_system` against a finite-difference Jacobian of the full system (8)
//! built from the generated `Lagrangian` (ERRATA E5), the verdicts against those of the num-dual
//! twin models, and Maievskii's criterion for a derived Lagrange top.

mod common;

use common::{Ellipsoid, Gyrostat};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::nalgebra::{Matrix6, Vector6};
use routh::{
    classify, sim::full_vector_field, steady_motions, Complex, Lagrangian, Routhian, Stability,
};
use routh::{SteadyMotion, Vector3};

fn field<M: Lagrangian>(m: &M, x: &Vector6<f64>) -> Vector6<f64> {
    let w = Vector3::new(x[0], x[1], x[2]);
    let g = Vector3::new(x[3], x[4], x[5]);
    let (wd, gd) = full_vector_field(m, &w, &g).expect("J positive definite");
    Vector6::new(wd.x, wd.y, wd.z, gd.x, gd.y, gd.z)
}

/// Central differences with one Richardson extrapolation (error O(h⁴)).
fn fd_jacobian<M: Lagrangian>(m: &M, x: &Vector6<f64>, h: f64) -> Matrix6<f64> {
    let mut jac = Matrix6::zeros();
    for k in 0..6 {
        let d = |h: f64| {
            let (mut xp, mut xm) = (*x, *x);
            xp[k] += h;
            xm[k] -= h;
            (field(m, &xp) - field(m, &xm)) / (2.0 * h)
        };
        jac.set_column(k, &((4.0 * d(h / 2.0) - d(h)) / 3.0));
    }
    jac
}

/// Checks the f₂ roots against the Jacobian's eigenvalues (f₂ roots ∪ {0, 0}); returns the worst
/// relative mismatch.
fn check_roots<M: Routhian>(model: &M, s: &SteadyMotion) -> f64 {
    let report = classify(model, s).expect("classify");
    let w = s.psi_dot * s.gamma;
    let x = Vector6::new(w.x, w.y, w.z, s.gamma.x, s.gamma.y, s.gamma.z);
    let eig: Vec<Complex<f64>> = fd_jacobian(model, &x, 1e-3)
        .complex_eigenvalues()
        .iter()
        .copied()
        .collect();
    let scale = report
        .f2_roots
        .iter()
        .map(|r| r.norm())
        .fold(1e-300, f64::max);
    let mut rest = eig.clone();
    let mut worst = 0.0f64;
    for r in &report.f2_roots {
        let k = (0..rest.len())
            .min_by(|&a, &b| (rest[a] - r).norm().total_cmp(&(rest[b] - r).norm()))
            .expect("six eigenvalues");
        worst = worst.max((rest[k] - r).norm() / scale);
        rest.remove(k);
    }
    assert!(
        worst <= 1e-6,
        "f₂ roots {:?} vs Jacobian eigenvalues {eig:?}",
        report.f2_roots
    );
    for z in rest {
        assert!(
            z.norm() <= 1e-4 * scale,
            "leftover eigenvalue {z} is not zero"
        );
    }
    worst
}

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
            worst = worst.max(check_roots(&model, s));
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
            worst = worst.max(check_roots(&model, s));
            checked += 1;
        }
    }
    eprintln!("{checked} steady motions; worst relative f₂-root mismatch {worst:.1e}");
    assert!(checked >= 12);
}

#[derive(routh::Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * (a1 * (omega.x * omega.x + omega.y * omega.y) + c * omega.z * omega.z),
    potential = mgl * gamma.z,
)]
struct LagrangeTop {
    a1: f64,
    c: f64,
    mgl: f64,
}

#[test]
fn derived_lagrange_top_obeys_maievskii() {
    for (a1, c, mgl) in [(2.0, 1.0, 1.0), (1.0, 1.5, 0.7), (1.0, 3.0, 2.0)] {
        let top = LagrangeTop { a1, c, mgl };
        let threshold = (4.0 * a1 * mgl).sqrt();
        let sleeping = |p: f64| SteadyMotion {
            p_psi: p,
            gamma: Vector3::z(),
            psi_dot: top.psi_dot(&Vector3::zeros(), &Vector3::z(), p),
            mu: top.dr_dgamma(&Vector3::zeros(), &Vector3::z(), p).z,
            amended_potential: top.amended_potential(&Vector3::z(), p),
            energy: top.amended_potential(&Vector3::z(), p),
            isolated: true,
        };
        let below = threshold * (1.0 - 0.001f64).sqrt();
        let above = threshold * (1.0 + 0.001f64).sqrt();
        assert_eq!(
            classify(&top, &sleeping(below)).unwrap().verdict,
            Stability::Unstable
        );
        let v = classify(&top, &sleeping(above)).unwrap().verdict;
        assert!(
            matches!(
                v,
                Stability::GyroscopicallyStabilized | Stability::SecularlyStable
            ),
            "above Maievskii's bound: {v:?}"
        );
    }
}
