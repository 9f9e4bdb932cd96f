//! Certified completeness (`routh::certify`, docs/method.md §9): the interval enclosures contain
//! the derivatives of the hand-written num-dual twins, and the certificate never claims a wrong
//! count — on closed-form cases it proves the right count, and on the hard cases of
//! `routh-core/tests/trust.rs` (degenerate points, circles, huge terms constant on the sphere) it leaves regions
//! undecided instead.

use derived_models::{Gyrostat, LagrangeTop};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::certify::{steady_motions_certified, Certificate, CertifyOptions, Interval};
use routh::{Lagrangian, Routhian, Vector3};
use test_models::roots::bracketed_roots;

/// A body with identity inertia and the potential `exp(a γ₃)`.
#[derive(Lagrangian)]
#[lagrangian(kinetic = 0.5 * omega.dot(omega), potential = (a * gamma.z).exp())]
struct ExpBody {
    a: f64,
}

/// Identity inertia and `γ₁⁴ + γ₂⁴`: ten critical points, two of them degenerate (the poles).
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(omega),
    potential = gamma.x.powi(4) + gamma.y.powi(4),
)]
struct QuarticBody {}

/// A heavy top with principal moments and `U = mgl γ₃ + k|γ|²` (`k|γ|²` is constant on the
/// sphere).
#[derive(Lagrangian, Clone, Copy)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = mgl * gamma.z + k * gamma.norm_squared(),
)]
struct Top {
    inertia: Vector3<f64>,
    mgl: f64,
    k: f64,
}

/// The tangential gradient of `U_r = mgl γ₃ + k|γ|² + p²/(2γᵀJγ)` (34), (40) for [`Top`],
/// written by hand.
fn top_tangential(top: &Top, gamma: &Vector3<f64>, p: f64) -> Vector3<f64> {
    let j = top.inertia;
    let d = gamma.dot(&j.component_mul(gamma));
    let grad = Vector3::new(0.0, 0.0, top.mgl) + 2.0 * top.k * gamma
        - p * p / (d * d) * j.component_mul(gamma);
    grad - grad.dot(gamma) * gamma
}

/// Every certified motion's enclosure contains a point where the hand-written tangential
/// gradient vanishes to `tol`, and the motions are distinct.
fn assert_motions_are_real(cert: &Certificate, residual: impl Fn(&Vector3<f64>) -> f64, tol: f64) {
    for m in &cert.motions {
        let g = m.steady.gamma;
        for k in 0..3 {
            assert!(
                m.enclosure[k].contains(g[k]) || m.enclosure[k].width() < 1e-12,
                "centre outside its enclosure: {m:?}"
            );
        }
        assert!(
            residual(&g) < tol,
            "certified motion is not critical: {g:?}"
        );
    }
    for (i, a) in cert.motions.iter().enumerate() {
        for b in &cert.motions[i + 1..] {
            assert!(
                (a.steady.gamma - b.steady.gamma).norm() > 1e-9,
                "duplicate motion"
            );
        }
    }
}

/// The critical points of `U_r` of an asymmetric [`Top`] (`k = 0`, distinct moments) by an
/// independent 1-D search: by the Lagrange conditions every critical point has `γ₁ = 0` or
/// `γ₂ = 0` (otherwise `J₁ = J₂`), so it is a critical point of `θ ↦ U_r` on one of the two
/// principal great circles through `e₃`.
fn asymmetric_top_critical_points(top: &Top, p: f64) -> Vec<Vector3<f64>> {
    let mut out: Vec<Vector3<f64>> = Vec::new();
    for axis in [0usize, 1] {
        let point = |t: f64| {
            let mut g = Vector3::new(0.0, 0.0, t.cos());
            g[axis] = t.sin();
            g
        };
        let tangent = |t: f64| {
            let mut d = Vector3::new(0.0, 0.0, -t.sin());
            d[axis] = t.cos();
            d
        };
        let du = |t: f64| top_tangential(top, &point(t), p).dot(&tangent(t));
        let grid: Vec<f64> = (0..=4000)
            .map(|k| -0.001 + (2.0 * std::f64::consts::PI) * f64::from(k) / 4000.0)
            .collect();
        for t in bracketed_roots(du, &grid, 1e-9) {
            let g = point(t);
            if out.iter().all(|q| (q - g).norm() > 1e-7) {
                out.push(g);
            }
        }
    }
    out
}

#[test]
fn enclosures_contain_the_num_dual_twin() {
    // The tape evaluated at random points (degenerate intervals) and over small boxes contains
    // ∂R/∂γ and ∂²R/∂γ² at Ω = 0 of the hand-written num-dual twin.
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for _ in 0..40 {
        let twin = test_models::Gyrostat::random(&mut rng);
        let model = Gyrostat::from(&twin);
        let tape = model
            .certification_tape()
            .expect("derived models have a tape");
        let mut scratch = Vec::new();
        for _ in 0..10 {
            let gamma = test_models::random_unit_vector(&mut rng);
            let p: f64 = rng.gen_range(-3.0..3.0);
            let want_g = twin.dr_dgamma(&Vector3::zeros(), &gamma, p);
            let want_h = twin.d2r_dgamma2(&Vector3::zeros(), &gamma, p);
            let scale = want_h.norm().max(want_g.norm()).max(1.0);
            // A box of half-width 1e-3 around γ, and γ itself.
            for half in [0.0, 1e-3] {
                let b = gamma.map(|x| Interval::new(x - half, x + half));
                let (g, h) = tape.eval([b[0], b[1], b[2]], Interval::point(p), &mut scratch);
                for i in 0..3 {
                    // The twin's own rounding error is ~1e-14·scale: compare with that slack.
                    let slack = 1e-12 * scale;
                    let gi = Interval::new(g[i].lo - slack, g[i].hi + slack);
                    assert!(
                        gi.contains(want_g[i]),
                        "∂R/∂γ_{i}: {:?} ∌ {}",
                        g[i],
                        want_g[i]
                    );
                    for j in 0..3 {
                        let hij = Interval::new(h[i][j].lo - slack, h[i][j].hi + slack);
                        assert!(hij.contains(want_h[(i, j)]), "H_{i}{j}");
                    }
                    if half == 0.0 {
                        // At a point the enclosure is tight.
                        assert!(g[i].width() < 1e-10 * scale, "{:?}", g[i]);
                    }
                }
            }
        }
    }
}

#[test]
fn asymmetric_tops_certified_against_an_independent_count() {
    // (Away from the branch points p² = mglC²/(C − A), mglC²/(C − B) of the sleeping top, where
    // it is degenerate: 4.5 and 9 for the first top, 4.5 for the last.)
    for (inertia, p) in [
        (Vector3::new(1.0, 2.0, 3.0), 0.5),
        (Vector3::new(1.0, 2.0, 3.0), 2.5),
        (Vector3::new(1.0, 2.0, 3.0), 3.5),
        // (The hanging top of this one is degenerate where p²(B − C) = mgl C², p = 1.)
        (Vector3::new(3.0, 2.0, 1.0), 1.3),
        (Vector3::new(2.0, 1.0, 1.5), 4.0),
    ] {
        let top = Top {
            inertia,
            mgl: 1.0,
            k: 0.0,
        };
        let cert = steady_motions_certified(&top, p, &CertifyOptions::default()).unwrap();
        let expected = asymmetric_top_critical_points(&top, p);
        assert!(cert.complete, "{inertia:?} p = {p}: {cert}");
        assert_eq!(
            cert.motions.len(),
            expected.len(),
            "{inertia:?} p = {p}: {cert}"
        );
        for g in &expected {
            let hit = cert
                .motions
                .iter()
                .filter(|m| {
                    (0..3).all(|k| {
                        m.enclosure[k].contains(g[k]) || (m.steady.gamma - g).norm() < 1e-9
                    })
                })
                .count();
            assert_eq!(hit, 1, "critical point {g:?} not certified once");
        }
        assert_motions_are_real(&cert, |g| top_tangential(&top, g, p).norm(), 1e-9);
    }
}

#[test]
fn paper_gyrostat_is_certified_and_agrees_with_the_search() {
    let model = Gyrostat::kelvin();
    for p in [0.0, 1.0, 3.0] {
        let cert = steady_motions_certified(&model, p, &CertifyOptions::default()).unwrap();
        assert!(cert.complete, "{cert}");
        let searched = routh::steady_motions(&model, p).unwrap();
        assert_eq!(cert.motions.len(), searched.len(), "p = {p}: {cert}");
        for m in &cert.motions {
            assert!(searched
                .iter()
                .any(|s| (s.gamma - m.steady.gamma).norm() < 1e-7));
        }
    }
}

#[test]
fn exponential_potential_has_exactly_two_motions() {
    // U = exp(aγ₃) with J = E and p_ψ = 0: U_r = U on the sphere, whose only critical points
    // are the poles (∇U ∥ e₃).
    for a in [1.0, 10.0, 15.0] {
        let body = ExpBody { a };
        let cert = steady_motions_certified(&body, 0.0, &CertifyOptions::default()).unwrap();
        assert!(cert.complete, "a = {a}: {cert}");
        assert_eq!(cert.motions.len(), 2, "a = {a}: {cert}");
        for m in &cert.motions {
            assert!((m.steady.gamma.z.abs() - 1.0).abs() < 1e-12);
        }
    }
}

#[test]
fn degenerate_poles_are_left_undecided_not_miscounted() {
    // γ₁⁴ + γ₂⁴ on the sphere: ±e₁, ±e₂ (maxima), (±1, ±1, 0)/√2 (saddles) and the poles ±e₃,
    // where the Hessian vanishes (a quartic minimum), so no interval Newton can prove them
    // unique. The 8 non-degenerate points are certified; the poles are undecided regions.
    let body = QuarticBody {};
    let opts = CertifyOptions {
        max_boxes: 100_000,
        ..CertifyOptions::default()
    };
    let cert = steady_motions_certified(&body, 0.0, &opts).unwrap();
    assert!(!cert.complete, "{cert}");
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let mut expected = vec![Vector3::x(), -Vector3::x(), Vector3::y(), -Vector3::y()];
    for (a, b) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
        expected.push(Vector3::new(a * s, b * s, 0.0));
    }
    assert_eq!(cert.motions.len(), 8, "{cert}");
    for g in &expected {
        assert!(cert
            .motions
            .iter()
            .any(|m| (m.steady.gamma - g).norm() < 1e-9));
    }
    // Both poles are inside undecided regions, and nothing else is undecided.
    for pole in [Vector3::z(), -Vector3::z()] {
        assert!(cert
            .undecided
            .iter()
            .any(|r| (0..3).all(|k| r.hull[k].contains(pole[k]))));
    }
    assert_eq!(cert.undecided.len(), 2, "{:?}", cert.undecided);
}

#[test]
fn heavy_top_at_tiny_momentum() {
    // p_ψ = 1e−100: U_r = mgl γ₃ to all digits; the sleeping and the hanging top.
    let top = Top {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        mgl: 1.0,
        k: 0.0,
    };
    let cert = steady_motions_certified(&top, 1e-100, &CertifyOptions::default()).unwrap();
    assert!(cert.complete, "{cert}");
    assert_eq!(cert.motions.len(), 2);
}

#[test]
fn circles_are_reported_as_undecided_tubes() {
    // The Lagrange top A₁ = 1, C = 1.5, mgl = 1. With c = cos θ and D = A₁ + (C − A₁)c², a
    // tilted steady motion (a circle, by the symmetry) solves p²(C − A₁)c = mgl D² (dU_r/dθ = 0
    // with sin θ ≠ 0), counted here by an independent 1-D root search. Just below the secular
    // bound p² = mglC²/(C − A₁) = 4.5 a tiny circle surrounds the sleeping top: the certificate
    // must be incomplete there; at p² = 3 there is no circle and it must prove exactly the
    // sleeping and the hanging top.
    let top = Top {
        inertia: Vector3::new(1.0, 1.0, 1.5),
        mgl: 1.0,
        k: 0.0,
    };
    let (a1, c) = (1.0, 1.5);
    for p2 in [4.5 * (1.0 - 1e-8), 4.4, 3.0, 6.0] {
        let f = |x: f64| p2 * (c - a1) * x - (a1 + (c - a1) * x * x).powi(2);
        let grid: Vec<f64> = (0..=20000)
            .map(|k| -1.0 + 2.0 * f64::from(k) / 20000.0)
            .collect();
        let circles = bracketed_roots(f, &grid[1..grid.len() - 1], 1e-12).len();
        let p = f64::sqrt(p2);
        let cert = steady_motions_certified(&top, p, &CertifyOptions::default()).unwrap();
        assert_motions_are_real(&cert, |g| top_tangential(&top, g, p).norm(), 1e-9);
        // The hanging top is isolated and far from any circle: it is certified.
        assert!(cert
            .motions
            .iter()
            .any(|m| (m.steady.gamma + Vector3::z()).norm() < 1e-9));
        if circles > 0 {
            assert!(!cert.complete, "p² = {p2}: {circles} circle(s), but {cert}");
            assert!(!cert.undecided.is_empty());
        } else {
            assert!(cert.complete, "p² = {p2}: {cert}");
            assert_eq!(cert.motions.len(), 2, "p² = {p2}: {cert}");
        }
    }
}

#[test]
fn huge_terms_constant_on_the_sphere_never_give_a_wrong_count() {
    // A fast spherical top (J = E, p_ψ = 1e4) and a top with 1e8|γ|² added to its potential:
    // the amended potential has a radial part 1e8 times its tangential one. Intervals cannot
    // cancel it on boxes much wider than 1e−8, so the certificate may stay incomplete within
    // its budget — but it must not certify anything false.
    let spherical = Top {
        inertia: Vector3::new(1.0, 1.0, 1.0),
        mgl: 1.0,
        k: 0.0,
    };
    let shifted = Top {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        mgl: 1.0,
        k: 1e8,
    };
    let opts = CertifyOptions {
        max_boxes: 20_000,
        ..CertifyOptions::default()
    };
    for (top, p) in [(&spherical, 1e4), (&shifted, 0.5)] {
        let cert = steady_motions_certified(top, p, &opts).unwrap();
        assert_motions_are_real(
            &cert,
            |g| top_tangential(top, g, p).norm() / (1.0 + 2.0 * top.k),
            1e-9,
        );
        if cert.complete {
            let unshifted = Top { k: 0.0, ..*top };
            assert_eq!(
                cert.motions.len(),
                asymmetric_top_critical_points(&unshifted, p).len()
            );
        }
    }
}

#[test]
fn hand_written_models_and_bad_options_are_errors() {
    let twin = LagrangeTop::example().twin();
    let err = steady_motions_certified(&twin, 1.0, &CertifyOptions::default()).unwrap_err();
    assert!(
        matches!(err, routh::RouthError::InvalidModel { .. }),
        "{err}"
    );
    let top = LagrangeTop::example();
    for (opts, what) in [
        (
            CertifyOptions {
                min_width: 0.0,
                ..Default::default()
            },
            "min_width",
        ),
        (
            CertifyOptions {
                initial_split: 0,
                ..Default::default()
            },
            "initial_split",
        ),
    ] {
        let err = steady_motions_certified(&top, 1.0, &opts).unwrap_err();
        assert!(err.to_string().contains(what), "{err}");
    }
    let err = steady_motions_certified(&top, f64::NAN, &CertifyOptions::default()).unwrap_err();
    assert!(matches!(err, routh::RouthError::NonFinite { .. }), "{err}");
}

#[test]
fn random_inputs_never_panic() {
    // Random gyrostats with parameters over 1e−6…1e6 (now and then indefinite, NaN or huge),
    // random p_ψ with NaN, ±∞, 0, subnormals and 1e300 mixed in, small budgets: every call returns
    // (no panic, no hang), an Ok certificate is internally consistent, an error names its input.
    let mut rng = ChaCha8Rng::seed_from_u64(1313);
    let specials = [
        f64::NAN,
        f64::INFINITY,
        -f64::INFINITY,
        0.0,
        5e-324,
        1e300,
        -1e300,
    ];
    let pick = |rng: &mut ChaCha8Rng| -> f64 {
        if rng.gen_bool(0.05) {
            specials[rng.gen_range(0..specials.len())]
        } else {
            let x = 10f64.powf(rng.gen_range(-6.0..6.0));
            if rng.gen_bool(0.2) {
                -x
            } else {
                x
            }
        }
    };
    let (mut ok, mut err) = (0, 0);
    for _ in 0..300 {
        let mut twin = test_models::Gyrostat::random(&mut rng);
        twin.inertia *= pick(&mut rng);
        twin.rotor *= pick(&mut rng);
        twin.mass = pick(&mut rng);
        let model = Gyrostat::from(&twin);
        let p = pick(&mut rng);
        let opts = CertifyOptions {
            max_boxes: rng.gen_range(1..3000),
            min_width: 10f64.powf(rng.gen_range(-6.0..-1.0)),
            initial_split: rng.gen_range(1..6),
            ..CertifyOptions::default()
        };
        match steady_motions_certified(&model, p, &opts) {
            Ok(cert) => {
                ok += 1;
                assert!(cert.boxes <= opts.max_boxes);
                assert!(cert.excluded <= cert.boxes);
                assert_eq!(
                    cert.complete,
                    cert.undecided.is_empty() && cert.ambiguous_pairs == 0
                );
                for m in &cert.motions {
                    assert!(m.steady.gamma.iter().all(|x| x.is_finite()));
                }
            }
            Err(e) => {
                err += 1;
                assert!(!e.to_string().is_empty());
            }
        }
    }
    assert!(ok > 0 && err > 0, "ok {ok}, err {err}");
}

/// An off-axis heavy top.
#[derive(Lagrangian, Clone, Copy)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = com.dot(gamma),
)]
struct OffAxisTop {
    inertia: Vector3<f64>,
    com: Vector3<f64>,
}

/// Every certified enclosure is at most 1e−10 wide, and its `steady` is a steady motion that
/// `classify` accepts and that the hand-written gradient of U_r = r·γ + p²/(2γᵀJγ) confirms: the
/// off-axis top J = diag(1, 2, 3), r = (0.3, 0.2, 1) over p = 1…6, where enclosures used to stay
/// 0.03–0.09 wide, 1e−4 rad from the motion.
#[test]
fn certified_enclosures_are_tight_and_their_motions_classify() {
    let top = OffAxisTop {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        com: Vector3::new(0.3, 0.2, 1.0),
    };
    let mut widest: f64 = 0.0;
    let mut count = 0;
    for k in 0..=20 {
        let p = 1.0 + 5.0 * k as f64 / 20.0;
        let cert = steady_motions_certified(&top, p, &CertifyOptions::default()).unwrap();
        for m in &cert.motions {
            for i in 0..3 {
                widest = widest.max(m.enclosure[i].width());
                assert!(m.enclosure[i].width() <= 1e-10, "p = {p}: {m:?}");
            }
            routh::classify(&top, &m.steady).unwrap_or_else(|e| panic!("p = {p}: {e}"));
            let g = m.steady.gamma;
            let j = top.inertia;
            let d = g.dot(&j.component_mul(&g));
            let grad = top.com - p * p / (d * d) * j.component_mul(&g);
            let t = grad - grad.dot(&g) * g;
            assert!(
                t.norm() < 1e-9 * (1.0 + p * p),
                "p = {p}: |t| = {}",
                t.norm()
            );
            count += 1;
        }
    }
    println!("{count} certified motions, widest enclosure {widest:.2e}");
}
