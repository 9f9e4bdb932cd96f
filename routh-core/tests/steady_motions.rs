//! Validation of `steady_motions` against things it did not produce: one-dimensional closed forms
//! of the amended potential of symmetric bodies (circles of steady motions), the six steady
//! rotations of a free asymmetric body, the Euler characteristic of the sphere for generic models,
//! and Theorem 2 (the energy of a steady motion equals the amended potential).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_core::{
    classify, steady::steady_motion_search, steady_motion_near, steady_motions, Lagrangian,
    Matrix3, RouthError, Routhian, SearchOptions, Stability, SteadyMotion, Vector3,
};
use test_models::{Ellipsoid, Gyrostat};

use crate::common;
use common::HeavyTop;

// ---------------------------------------------------------------------------------------------
// Helpers.

/// The interior roots in (−1, 1) of a function of γ₃, by sign changes on a fine grid (uniform in
/// θ = arccos γ₃, so that roots near the poles are resolved) and bisection.
fn roots_in_z(f: impl Fn(f64) -> f64) -> Vec<f64> {
    let n = 20_000;
    let zs: Vec<f64> = (1..n)
        .rev()
        .map(|i| (std::f64::consts::PI * i as f64 / n as f64).cos())
        .collect();
    test_models::roots::bracketed_roots(f, &zs, 1e-9)
}

/// Checks the general properties of every steady motion against computations that `record`
/// does not make: unit γ, critical point of U_r (33); ψ̇ = −∂R/∂p_ψ (15) by a central difference
/// of R itself; U_r by (40) generalised, ½(p_ψ − a·γ)²/(γᵀJγ) + U, from the Lagrangian alone
/// (a·γ = (∂L/∂ω(0, γ), γ), U = −L(0, γ), J = ∂²L/∂ω²); μ by (19) from the Lagrangian at
/// ω = ψ̇γ: ∂R/∂γ = ∂L/∂γ + ψ̇ ∂L/∂ω; Theorem 2 (E = U_r); the cyclic momentum (9) of the full
/// system at ω = ψ̇γ; sorted by U_r.
fn check_records<M: Routhian>(model: &M, p: f64, motions: &[SteadyMotion]) {
    let zero = Vector3::zeros();
    for s in motions {
        let g = s.gamma;
        assert!((g.norm() - 1.0).abs() < 1e-14, "{s}");
        let dr = model.dr_dgamma(&zero, &g, p);
        let scale = dr.norm().max(model.d2r_dgamma2(&zero, &g, p).norm());
        let tangential = dr - dr.dot(&g) * g;
        assert!(
            tangential.norm() <= 1e-10 * scale,
            "not critical: {s}, |grad| = {:e}",
            tangential.norm()
        );
        // (15) against R: R is quadratic in p_ψ ((39): it enters only through −½(p_ψ − q)²/D),
        // so the central difference is exact for any step but for the round-off of R, a few
        // ε·|R|/h.
        let h = 0.5 * p.abs().max(1.0);
        let (r_plus, r_minus) = (
            model.routhian(&zero, &g, p + h),
            model.routhian(&zero, &g, p - h),
        );
        let psi_dot_fd = -(r_plus - r_minus) / (2.0 * h);
        let fd_round_off = 64.0 * f64::EPSILON * (r_plus.abs() + r_minus.abs()) / (2.0 * h);
        assert!(
            (s.psi_dot - psi_dot_fd).abs() <= fd_round_off.max(1e-14 * psi_dot_fd.abs()),
            "ψ̇ = {} vs −∂R/∂p by central difference {psi_dot_fd}: {s}",
            s.psi_dot
        );
        // (40) generalised, from L only.
        let a_gamma = model.dl_domega(&zero, &g).dot(&g);
        let d = g.dot(&(model.d2l_domega2(&g) * g));
        let u = -model.lagrangian(&zero, &g);
        let centrifugal = 0.5 * (p - a_gamma).powi(2) / d;
        let u_r = centrifugal + u;
        assert!(
            (s.amended_potential - u_r).abs() <= 1e-12 * centrifugal.abs().max(u.abs()),
            "U_r = {} vs (40) {u_r}: {s}",
            s.amended_potential
        );
        // (19) at Ω = 0, ω = ψ̇γ, with ψ̇ = (p_ψ − a·γ)/(γᵀJγ) (38) from L.
        let psi_dot = (p - a_gamma) / d;
        let w = psi_dot * g;
        let dl_dw = model.dl_domega(&w, &g);
        let dl_dg = model.dl_dgamma(&w, &g);
        let mu = (dl_dg + psi_dot * dl_dw).dot(&g);
        let mu_scale = scale.max(dl_dg.norm()).max((psi_dot * dl_dw).norm());
        assert!(
            (s.mu - mu).abs() <= 1e-12 * mu_scale,
            "μ = {} vs (19) {mu}: {s}",
            s.mu
        );
        let e_scale = s.amended_potential.abs().max(scale);
        assert!(
            (s.energy - s.amended_potential).abs() <= 1e-12 * e_scale,
            "Theorem 2: E = {} vs U_r = {}",
            s.energy,
            s.amended_potential
        );
        // The full system's cyclic momentum (9) at ω = ψ̇γ is p_ψ.
        let pm = model.cyclic_momentum(&(s.psi_dot * s.gamma), &s.gamma);
        assert!((pm - p).abs() <= 1e-12 * p.abs().max(1.0));
    }
    for w in motions.windows(2) {
        assert!(w[0].amended_potential <= w[1].amended_potential);
    }
}

/// A body symmetric about e₃: its isolated steady motions are the poles ±e₃ and its other steady
/// motions are circles γ₃ = z*, one per interior root z* of dU_r/dγ₃; the search must report
/// exactly those (one representative per circle, `isolated: false`), all Degenerate.
fn check_symmetric<M: Routhian>(
    model: &M,
    p: f64,
    du_dz: impl Fn(f64) -> f64,
    what: &str,
) -> usize {
    let motions = steady_motions(model, p).unwrap();
    check_records(model, p, &motions);
    let poles: Vec<_> = motions.iter().filter(|s| s.isolated).collect();
    assert_eq!(poles.len(), 2, "{what}, p = {p}: {motions:#?}");
    assert!(poles.iter().any(|s| (s.gamma - Vector3::z()).norm() < 1e-9));
    assert!(poles.iter().any(|s| (s.gamma + Vector3::z()).norm() < 1e-9));
    let mut expected = roots_in_z(du_dz);
    let mut circles: Vec<f64> = motions
        .iter()
        .filter(|s| !s.isolated)
        .map(|s| s.gamma.z)
        .collect();
    expected.sort_by(f64::total_cmp);
    circles.sort_by(f64::total_cmp);
    assert_eq!(
        circles.len(),
        expected.len(),
        "{what}, p = {p}: circles {circles:?} vs γ₃ = {expected:?}"
    );
    for (c, e) in circles.iter().zip(&expected) {
        assert!(
            (c - e).abs() < 1e-7,
            "{what}, p = {p}: circle at γ₃ = {c}, expected {e}"
        );
    }
    for s in motions.iter().filter(|s| !s.isolated) {
        assert_eq!(classify(model, s).unwrap().verdict, Stability::Degenerate);
    }
    eprintln!("{what}, p = {p}: poles ±e₃ and circles at γ₃ = {circles:?}");
    circles.len()
}

/// #minima − #saddles + #maxima over the isolated critical points (they must all be
/// non-degenerate); returns (χ, #critical points).
fn euler_characteristic<M: Routhian>(model: &M, p: f64, what: &str) -> (i64, usize) {
    let motions = steady_motions(model, p).unwrap();
    check_records(model, p, &motions);
    let mut chi = 0;
    for s in &motions {
        assert!(
            s.isolated,
            "{what}, p = {p}: a generic model has no circles: {s}"
        );
        let r = classify(model, s).unwrap();
        assert_ne!(
            r.verdict,
            Stability::Degenerate,
            "{what}, p = {p}: {s}: {r}"
        );
        chi += match r.degree_of_instability {
            0 | 2 => 1,
            _ => -1,
        };
    }
    let kinds: Vec<_> = motions
        .iter()
        .map(|s| classify(model, s).unwrap().degree_of_instability)
        .collect();
    eprintln!(
        "{what}, p = {p}: χ = {chi} from {} points, degrees {kinds:?}",
        motions.len()
    );
    (chi, motions.len())
}

// ---------------------------------------------------------------------------------------------
// Symmetric bodies: circles of steady motions.

/// ψ̇, μ and U_r of every steady motion of the Lagrange top in closed form: with γ₃ = z and
/// n = A₁(1 − z²) + Cz² = γᵀJγ, ψ̇ = p/n (38), U_r = ½p²/n + mgl z (40), and from
/// ∂R/∂γ = −mgl e₃ + (p²/n²)Jγ at Ω = 0 (39), μ = p²/n − mgl z (32)–(33). The sleeping top
/// (z = 1) has ψ̇ = p/C, U_r = ½p²/C + mgl, μ = p²/C − mgl.
fn check_lagrange_closed_forms(a1: f64, c: f64, mgl: f64, p: f64) {
    let top = HeavyTop::lagrange(a1, c, mgl);
    for s in steady_motions(&top, p).unwrap() {
        let z = s.gamma.z;
        let n = a1 * (1.0 - z * z) + c * z * z;
        let tol = 1e-12 * (p * p / n + mgl);
        assert!((s.psi_dot - p / n).abs() <= 1e-12 * p / n, "{s}");
        assert!(
            (s.amended_potential - (0.5 * p * p / n + mgl * z)).abs() <= tol,
            "{s}"
        );
        assert!((s.mu - (p * p / n - mgl * z)).abs() <= tol, "{s}");
    }
}

#[test]
fn lagrange_top_poles_and_circles_of_tilted_precessions() {
    let mut total = 0;
    for (a1, c, mgl) in [(2.0, 1.0, 1.0), (1.0, 1.5, 2.0)] {
        let top = HeavyTop::lagrange(a1, c, mgl);
        for p in [0.5, 2.0, 3.5, 8.0] {
            // U_r = ½p²/n + mgl γ₃ with n = C + (A₁ − C)(1 − γ₃²).
            let du = |z: f64| {
                let n = c + (a1 - c) * (1.0 - z * z);
                p * p * (a1 - c) * z / (n * n) + mgl
            };
            total += check_symmetric(&top, p, du, "Lagrange top");
            check_lagrange_closed_forms(a1, c, mgl, p);
        }
    }
    assert!(total >= 3, "too few circles exercised: {total}");
}

#[test]
fn lagrange_top_from_test_models_matches_the_hand_written_one() {
    let (a1, c, mgl, p) = (2.0, 1.0, 1.0, 3.5);
    let a = steady_motions(&Gyrostat::lagrange_top(a1, c, mgl), p).unwrap();
    let b = steady_motions(&HeavyTop::lagrange(a1, c, mgl), p).unwrap();
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.isolated, y.isolated);
        assert!((x.amended_potential - y.amended_potential).abs() < 1e-10);
        assert!((x.gamma.z - y.gamma.z).abs() < 1e-8);
    }
}

#[test]
fn ellipsoid_of_revolution_has_symmetric_circles_on_one_level() {
    // An ellipsoid of revolution (semi-axes a, a, c) with inertia diag(A, A, C) and its centre at
    // the centre of mass: U_r = ½p²/(A(1 − z²) + Cz²) + mg√(a²(1 − z²) + c²z²) is even in z = γ₃,
    // so besides the equator z = 0 any tilted circles come in pairs ±z* with the same U_r: they
    // must be reported as two circles, not merged. Tilted circles need sign(C − A) =
    // sign(c² − a²), hence a prolate shape with an oblate mass distribution here (a homogeneous
    // body has none).
    let mut total = 0;
    let (a, c, ia, ic) = (1.0, 1.5, 1.0, 2.0);
    let body = Ellipsoid::new(
        Matrix3::from_diagonal(&Vector3::new(ia, ia, ic)),
        Vector3::new(a, a, c),
        Vector3::zeros(),
        1.0,
        9.81,
    );
    let mg = body.mass * body.g;
    for p in [0.5, 4.0, 5.0, 8.0] {
        let du = |z: f64| {
            let n = ia * (1.0 - z * z) + ic * z * z;
            let s = a * a * (1.0 - z * z) + c * c * z * z;
            -0.5 * p * p * 2.0 * (ic - ia) * z / (n * n) + mg * (c * c - a * a) * z / s.sqrt()
        };
        total += check_symmetric(&body, p, du, "ellipsoid of revolution");
    }
    // p = 4 and 5 have the equator and a pair of tilted circles each.
    assert!(total >= 8, "too few circles exercised: {total}");
}

#[test]
fn free_asymmetric_body_has_six_steady_rotations() {
    // No potential: U_r = ½p²/(γᵀJγ); critical points are the principal axes ±eᵢ: minima on the
    // axis of largest inertia, maxima on the smallest, saddles on the middle one.
    let top = HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
        mgr: Vector3::zeros(),
    };
    let p = 2.0;
    let motions = steady_motions(&top, p).unwrap();
    check_records(&top, p, &motions);
    assert_eq!(motions.len(), 6, "{motions:#?}");
    for (k, s) in motions.iter().enumerate() {
        // Sorted by U_r: largest inertia (e₃) first.
        let axis = 2 - k / 2;
        assert!((s.gamma[axis].abs() - 1.0).abs() < 1e-12, "{s}");
        assert!((s.amended_potential - 0.5 * p * p / top.j[(axis, axis)]).abs() < 1e-12);
        assert!((s.psi_dot - p / top.j[(axis, axis)]).abs() < 1e-12);
        let r = classify(&top, s).unwrap();
        assert_eq!(r.degree_of_instability, [0, 1, 2][k / 2]);
        // Euler's classical result: rotation about the middle axis is unstable, about the others
        // stable (the smallest axis by gyroscopic stabilisation).
        let expected = [
            Stability::SecularlyStable,
            Stability::Unstable,
            Stability::GyroscopicallyStabilized,
        ][k / 2];
        assert_eq!(r.verdict, expected, "{s}: {r}");
    }
}

#[test]
fn free_body_at_rest_is_one_two_dimensional_critical_set() {
    // p_ψ = 0 and no potential: U_r ≡ 0, every γ is a steady motion (rest). One representative.
    let top = HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
        mgr: Vector3::zeros(),
    };
    let motions = steady_motions(&top, 0.0).unwrap();
    assert_eq!(motions.len(), 1, "{motions:#?}");
    assert!(!motions[0].isolated);
    assert_eq!(motions[0].amended_potential, 0.0);
    let r = classify(&top, &motions[0]).unwrap();
    assert_eq!(r.verdict, Stability::Degenerate);
}

// ---------------------------------------------------------------------------------------------
// b. Generic models: the isolated critical points satisfy the Morse relation χ(S²) = 2.

#[test]
fn euler_characteristic_asymmetric_heavy_tops() {
    let mut rng = ChaCha8Rng::seed_from_u64(2024);
    for _ in 0..3 {
        let j = {
            let b = Matrix3::from_fn(|_, _| rng.gen_range(-1.0..1.0));
            b * b.transpose() + Matrix3::from_diagonal_element(0.5)
        };
        let top = HeavyTop {
            j,
            mgr: Vector3::from_fn(|_, _| rng.gen_range(-1.0..1.0)),
        };
        for p in [0.0, 0.4, 1.5, 5.0] {
            let (chi, n) = euler_characteristic(&top, p, "heavy top");
            assert_eq!(chi, 2, "heavy top, p = {p}: χ = {chi} over {n} points");
        }
    }
}

#[test]
fn euler_characteristic_gyrostats() {
    let mut rng = ChaCha8Rng::seed_from_u64(99);
    let mut counts = Vec::new();
    for _ in 0..3 {
        let body = Gyrostat::random(&mut rng);
        for p in [0.5, 4.0, 12.0, 30.0] {
            let (chi, n) = euler_characteristic(&body, p, "gyrostat");
            assert_eq!(
                chi, 2,
                "gyrostat {body:?}, p = {p}: χ = {chi} over {n} points"
            );
            counts.push(n);
        }
    }
    // Not only the trivial two-point case.
    assert!(counts.iter().any(|&n| n >= 4), "{counts:?}");
}

#[test]
fn euler_characteristic_triaxial_ellipsoids() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut counts = Vec::new();
    for _ in 0..3 {
        let body = Ellipsoid::random(&mut rng);
        for p in [0.0, 3.0, 8.0, 20.0] {
            let (chi, n) = euler_characteristic(&body, p, "ellipsoid");
            assert_eq!(
                chi, 2,
                "ellipsoid {body:?}, p = {p}: χ = {chi} over {n} points"
            );
            counts.push(n);
        }
    }
    assert!(counts.iter().any(|&n| n >= 6), "{counts:?}");
}

// ---------------------------------------------------------------------------------------------
// Following a branch, options and errors.

#[test]
fn steady_motion_near_refines_a_guess() {
    let top = HeavyTop::lagrange(2.0, 1.0, 1.0);
    let s = steady_motion_near(&top, Vector3::new(0.01, -0.02, 1.0), 3.0).unwrap();
    assert!(s.isolated);
    assert!((s.gamma - Vector3::z()).norm() < 1e-12);
    // A point of a circle is reported as non-isolated.
    let all = steady_motions(&top, 3.0).unwrap();
    let circle = all.iter().find(|s| !s.isolated).unwrap();
    let guess = circle.gamma + Vector3::new(0.01, 0.0, 0.0);
    let t = steady_motion_near(&top, guess, 3.0).unwrap();
    assert!(!t.isolated);
    assert!((t.gamma.z - circle.gamma.z).abs() < 1e-9);
    assert!(matches!(
        steady_motion_near(&top, Vector3::zeros(), 3.0),
        Err(RouthError::NonUnitGamma {
            what: "gamma_guess",
            norm: 0.0,
            ..
        })
    ));
}

#[test]
fn search_options_and_errors() {
    let top = HeavyTop::lagrange(2.0, 1.0, 1.0);
    assert!(matches!(
        steady_motions(&top, f64::NAN),
        Err(RouthError::NonFinite { .. })
    ));
    let no_starts = SearchOptions {
        starts: 0,
        ..SearchOptions::default()
    };
    assert!(matches!(
        steady_motion_search(&top, 1.0, &no_starts),
        Err(RouthError::InvalidOption { .. })
    ));
    // Few starts still find the two poles of a slow top (U_r has only those critical points).
    let few = SearchOptions {
        starts: 20,
        ..SearchOptions::default()
    };
    let poles = steady_motion_search(&top, 0.1, &few).unwrap().motions;
    assert!(
        poles.iter().filter(|s| s.isolated).count() == 2,
        "{poles:#?}"
    );

    // J indefinite: γᵀJγ ≤ 0 somewhere on the sphere.
    let bad = HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0)),
        mgr: Vector3::z(),
    };
    assert!(matches!(
        steady_motions(&bad, 1.0),
        Err(RouthError::DegenerateVerticalInertia { .. }
            | RouthError::KineticNotPositiveDefinite { .. })
    ));

    /// A model whose Routh function is not finite anywhere: nothing can converge.
    struct Broken(HeavyTop);
    impl Lagrangian for Broken {
        fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
            self.0.lagrangian(w, g)
        }
        fn dl_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
            self.0.dl_domega(w, g)
        }
        fn dl_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
            self.0.dl_dgamma(w, g)
        }
        fn d2l_domega2(&self, g: &Vector3<f64>) -> Matrix3<f64> {
            self.0.d2l_domega2(g)
        }
        fn d2l_domega_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> Matrix3<f64> {
            self.0.d2l_domega_dgamma(w, g)
        }
    }
    impl Routhian for Broken {
        fn routhian(&self, _: &Vector3<f64>, _: &Vector3<f64>, _: f64) -> f64 {
            f64::NAN
        }
        fn dr_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
            self.0.dr_domega(w, g, p)
        }
        fn dr_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>, _: f64) -> Vector3<f64> {
            Vector3::repeat(f64::NAN)
        }
        fn d2r_domega2(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
            self.0.d2r_domega2(w, g, p)
        }
        fn d2r_domega_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
            self.0.d2r_domega_dgamma(w, g, p)
        }
        fn d2r_dgamma2(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
            self.0.d2r_dgamma2(w, g, p)
        }
    }
    let broken = Broken(top.clone());
    assert!(matches!(
        steady_motions(&broken, 1.0),
        Err(RouthError::NoConvergence { .. })
    ));
    assert!(steady_motion_near(&broken, Vector3::z(), 1.0).is_err());
}
