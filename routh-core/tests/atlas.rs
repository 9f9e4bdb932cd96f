//! `stability_atlas` against closed forms that the code does not produce: Maievskii's bound and
//! the secular bound of the sleeping Lagrange top, the discriminant of `f₂` of the sleeping
//! asymmetric top derived by hand from the linearised Euler–Poisson equations, `classify` at
//! random nodes, and the eigenvalues of a finite-difference Jacobian of the full equations (8).

use crate::common;

use common::HeavyTop;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_core::{
    classify, stability_atlas, stability_atlas_parallel, AtlasOptions, Complex, EventKind, Matrix3,
    RouthError, Stability, StabilityAtlas, SteadyMotion, StopReason, Vector3,
};
use test_models::jacobian::{fd_jacobian, match_roots, steady_state};
use test_models::roots::bracketed_roots;

const A1: f64 = 1.0;
const C_LAGRANGE: f64 = 1.2;

/// The sleeping Lagrange top J = diag(1, 1, 1.2) over (mgl, p_ψ) ∈ [0.5, 2] × [0.5, 5].
fn lagrange_atlas(n: usize, threads: usize) -> StabilityAtlas {
    let opts = AtlasOptions {
        nx: n,
        ny: n,
        threads,
        ..AtlasOptions::default()
    };
    stability_atlas_parallel(
        |mgl: f64, p: f64| (HeavyTop::lagrange(A1, C_LAGRANGE, mgl), p),
        Vector3::z(),
        (0.5, 2.0),
        (0.5, 5.0),
        &opts,
    )
    .expect("atlas")
}

/// The sleeping asymmetric top J = diag(A, B, C), com on e₃ at mgl = 1.
const A: f64 = 1.0;
const C: f64 = 1.5;
const MGL: f64 = 1.0;

fn asymmetric(b: f64) -> HeavyTop {
    HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(A, b, C)),
        mgr: Vector3::new(0.0, 0.0, MGL),
    }
}

/// `f₂(λ) = c₄λ⁴ + c₂λ² + c₀` of the sleeping asymmetric top, by hand: linearising the
/// Euler–Poisson equations at ω = Ω e₃, γ = e₃ (Ω = p/C) in (w₁, w₂, g₁, g₂):
/// `A ẇ₁ = (B − C)Ω w₂ + mgl g₂`, `B ẇ₂ = (C − A)Ω w₁ − mgl g₁`, `ġ₁ = −w₂ + Ω g₂`,
/// `ġ₂ = w₁ − Ω g₁`, whose characteristic polynomial times AB is
/// `AB λ⁴ + [Ω²(2AB − AC − BC + C²) − mgl(A + B)] λ² + (mgl − (C − A)Ω²)(mgl − (C − B)Ω²)`.
fn hand_f2(b: f64, p: f64) -> [f64; 3] {
    let w2 = (p / C) * (p / C);
    [
        A * b,
        w2 * (2.0 * A * b - A * C - b * C + C * C) - MGL * (A + b),
        (MGL - (C - A) * w2) * (MGL - (C - b) * w2),
    ]
}

fn asymmetric_atlas(threads: usize) -> StabilityAtlas {
    let opts = AtlasOptions {
        nx: 41,
        ny: 61,
        threads,
        ..AtlasOptions::default()
    };
    stability_atlas_parallel(
        |b: f64, p: f64| (asymmetric(b), p),
        Vector3::z(),
        (1.05, 1.45),
        (1.5, 3.0),
        &opts,
    )
    .expect("atlas")
}

/// The verdict of the sleeping Lagrange top from Maievskii's and the secular bound.
fn lagrange_closed_form(mgl: f64, p: f64) -> Option<Stability> {
    let p2 = p * p;
    let maievskii = 4.0 * A1 * mgl;
    let secular = mgl * C_LAGRANGE * C_LAGRANGE / (C_LAGRANGE - A1);
    let margin = 1e-6;
    if p2 < maievskii * (1.0 - margin) {
        Some(Stability::Unstable)
    } else if p2 > maievskii * (1.0 + margin) && p2 < secular * (1.0 - margin) {
        Some(Stability::GyroscopicallyStabilized)
    } else if p2 > secular * (1.0 + margin) {
        Some(Stability::SecularlyStable)
    } else {
        None
    }
}

#[test]
fn lagrange_top_curves_are_maievskii_and_secular_bounds() {
    let atlas = lagrange_atlas(41, 0);
    // Every node against the closed forms (the motion γ = e₃ exists everywhere).
    for (j, row) in atlas.verdicts.iter().enumerate() {
        for (i, v) in row.iter().enumerate() {
            let (mgl, p) = (atlas.x[i], atlas.y[j]);
            assert!(v.is_some(), "lost at ({mgl}, {p})");
            if let Some(expected) = lagrange_closed_form(mgl, p) {
                assert_eq!(*v, Some(expected), "at mgl = {mgl}, p = {p}");
            }
        }
    }
    let hopf: Vec<_> = atlas
        .boundaries
        .iter()
        .filter(|b| b.kind == EventKind::HamiltonianHopf)
        .collect();
    let zero: Vec<_> = atlas
        .boundaries
        .iter()
        .filter(|b| b.kind != EventKind::HamiltonianHopf)
        .collect();
    assert_eq!(hopf.len(), 1, "{:?}", atlas.boundaries);
    assert_eq!(zero.len(), 1, "{:?}", atlas.boundaries);
    assert_eq!(zero[0].kind, EventKind::BranchPoint);

    let mut worst_hopf: f64 = 0.0;
    for &(mgl, p) in &hopf[0].points {
        worst_hopf = worst_hopf.max((p * p - 4.0 * A1 * mgl).abs() / (4.0 * A1 * mgl));
    }
    let mut worst_secular: f64 = 0.0;
    for &(mgl, p) in &zero[0].points {
        let h = p * p * (C_LAGRANGE - A1) / (C_LAGRANGE * C_LAGRANGE) - mgl;
        worst_secular = worst_secular.max(h.abs() / mgl);
    }
    println!(
        "Maievskii curve: {} points, max |p² − 4A₁mgl|/(4A₁mgl) = {worst_hopf:.3e}",
        hopf[0].points.len()
    );
    println!(
        "secular curve: {} points, max |p²(C − A₁)/C² − mgl|/mgl = {worst_secular:.3e}",
        zero[0].points.len()
    );
    // The points satisfy their equations to AtlasOptions::curve_tol = 1e−10 relative (the
    // contract); the corrector converges well past it. Measured: 2.4e−14 (Maievskii) and
    // 8.2e−15 (secular); the bounds are about ten times that.
    assert!(worst_hopf <= 3e-13, "{worst_hopf:e}");
    assert!(worst_secular <= 1e-13, "{worst_secular:e}");
    // Both curves cross the whole rectangle, from mgl = 0.5 to mgl = 2.
    for b in [hopf[0], zero[0]] {
        let xs: Vec<f64> = b.points.iter().map(|q| q.0).collect();
        let lo = xs.iter().cloned().fold(f64::INFINITY, f64::min);
        let hi = xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        assert!(
            (lo - 0.5).abs() < 1e-9 && (hi - 2.0).abs() < 1e-9,
            "{lo} {hi}"
        );
        assert!(b.points.len() > 50);
        // In order along the curve: consecutive points are close.
        for w in b.points.windows(2) {
            assert!((w[1].0 - w[0].0).hypot((w[1].1 - w[0].1) / 3.0) < 0.05);
        }
    }
}

#[test]
fn no_hopf_curve_when_c_is_twice_a1() {
    // C = 2A₁: the discriminant of f₂ vanishes identically on γ = e₃ (no Krein collision), and
    // Maievskii's bound coincides with the secular one.
    let opts = AtlasOptions {
        nx: 15,
        ny: 15,
        ..AtlasOptions::default()
    };
    let atlas = stability_atlas(
        |mgl: f64, p: f64| (HeavyTop::lagrange(1.0, 2.0, mgl), p),
        Vector3::z(),
        (0.5, 2.0),
        (0.5, 5.0),
        &opts,
    )
    .unwrap();
    assert!(atlas
        .boundaries
        .iter()
        .all(|b| b.kind != EventKind::HamiltonianHopf));
    let zero: Vec<_> = atlas.boundaries.iter().collect();
    assert_eq!(zero.len(), 1);
    let worst = zero[0]
        .points
        .iter()
        .map(|&(mgl, p)| (p * p / (4.0 * mgl) - 1.0).abs())
        .fold(0.0, f64::max);
    println!("C = 2A₁ curve: max |p²/(4mgl) − 1| = {worst:.3e}");
    // Measured 1.3e−12 (the contract is curve_tol = 1e−10): ten times that.
    assert!(worst <= 1.5e-11, "{worst:e}");
}

#[test]
fn asymmetric_top_hopf_curve_satisfies_the_hand_discriminant() {
    let atlas = asymmetric_atlas(0);
    let hopf: Vec<_> = atlas
        .boundaries
        .iter()
        .filter(|b| b.kind == EventKind::HamiltonianHopf)
        .collect();
    assert_eq!(hopf.len(), 1, "{:?}", atlas.boundaries);
    let mut worst: f64 = 0.0;
    for &(b, p) in &hopf[0].points {
        let [c4, c2, c0] = hand_f2(b, p);
        worst = worst.max((c2 * c2 - 4.0 * c4 * c0).abs() / (c2 * c2 + 4.0 * (c4 * c0).abs()));
        // Degree 2 and c₂ > 0: the collision is on the imaginary axis.
        assert!(c0 > 0.0 && c2 > 0.0);
    }
    println!(
        "asymmetric Hamiltonian–Hopf curve: {} points, max relative |c₂² − 4c₄c₀| = {worst:.3e}",
        hopf[0].points.len()
    );
    // Measured 1.9e−14 (the contract is curve_tol = 1e−10): ten times that.
    assert!(worst <= 2e-13, "{worst:e}");
    // The branch points: κ_A = 0 (p² = mgl C²/(C − A)) and κ_B = 0 (p² = mgl C²/(C − B)).
    let zero: Vec<_> = atlas
        .boundaries
        .iter()
        .filter(|b| b.kind != EventKind::HamiltonianHopf)
        .collect();
    assert!(zero.len() >= 2, "{:?}", atlas.boundaries);
    let mut worst_zero: f64 = 0.0;
    for z in &zero {
        assert_eq!(z.kind, EventKind::BranchPoint);
        for &(b, p) in &z.points {
            let ka = p * p * (C - A) / (C * C) - MGL;
            let kb = p * p * (C - b) / (C * C) - MGL;
            worst_zero = worst_zero.max(ka.abs().min(kb.abs()) / MGL);
        }
    }
    println!("asymmetric branch-point curves: max |κ|/mgl = {worst_zero:.3e}");
    // Measured 5.4e−13: ten times that.
    assert!(worst_zero <= 5e-12, "{worst_zero:e}");
}

/// Whether the node is far enough from every boundary for a finite-difference check: every
/// root of f₂ (as `classify` finds it) is far from zero and either on the imaginary axis or
/// clearly off it.
fn well_separated(model: &HeavyTop, p: f64) -> bool {
    let steady = SteadyMotion::at(model, Vector3::z(), p, true).unwrap();
    let roots = classify(model, &steady).unwrap().f2_roots;
    let big = roots.iter().map(|l| l.norm()).fold(0.0, f64::max);
    roots
        .iter()
        .all(|l| l.norm() >= 1e-2 * big && (l.re == 0.0 || l.re.abs() >= 1e-3 * big))
}

/// Step of the finite-difference Jacobian (Richardson-extrapolated central differences: error
/// O(h⁴) ≈ 1e−16 against a round-off of ε/h ≈ 1e−12, relative).
const FD_STEP: f64 = 1e-4;

/// Checks the verdict at node (i, j) against `classify` and (if `fd`) against the FD Jacobian;
/// returns the FD check's worst mismatches `(root of f₂ to its eigenvalue, leftover eigenvalue to
/// zero)`, relative to the largest eigenvalue (zero when there was none).
fn check_node(
    atlas: &StabilityAtlas,
    model: &HeavyTop,
    p: f64,
    i: usize,
    j: usize,
    fd: bool,
) -> (f64, f64) {
    let steady = SteadyMotion::at(model, Vector3::z(), p, true).unwrap();
    let report = classify(model, &steady).unwrap();
    let verdict = atlas.verdicts[j][i].expect("the sleeping top exists");
    assert_eq!(verdict, report.verdict, "node ({i}, {j})");
    if !fd || !well_separated(model, p) {
        return (0.0, 0.0);
    }
    // The full equations (8) linearised by finite differences (test-models, from the Lagrangian
    // alone): the four roots of f₂ are eigenvalues, the other two are zeros (the integrals).
    let eig: Vec<Complex<f64>> = fd_jacobian(model, &steady_state(&steady), FD_STEP)
        .complex_eigenvalues()
        .iter()
        .copied()
        .collect();
    let big = eig.iter().map(|l| l.norm()).fold(0.0, f64::max);
    let matched = match_roots(&report.f2_roots, &eig);
    // Richardson-extrapolated central differences: truncation O(h⁴) ≈ 1e−16, round-off about
    // ε/h ≈ 2e−12 relative; measured 6e−14 (the test prints it).
    assert!(
        matched.worst <= 1e-9 * big,
        "roots {:?} of f₂ are not eigenvalues: {eig:?}",
        report.f2_roots
    );
    let leftover = matched
        .leftover
        .iter()
        .map(|l| l.norm())
        .fold(0.0, f64::max);
    assert!(leftover <= 1e-9 * big, "{eig:?}");
    let stable = eig.iter().all(|l| l.re.abs() <= 1e-6 * big);
    match verdict {
        Stability::SecularlyStable | Stability::GyroscopicallyStabilized => {
            assert!(stable, "{verdict} but {eig:?}")
        }
        Stability::Unstable => assert!(!stable, "unstable but {eig:?}"),
        Stability::Degenerate => {}
    }
    (matched.worst / big, leftover / big)
}

#[test]
fn grid_verdicts_agree_with_classify_and_the_full_jacobian() {
    let mut rng = ChaCha8Rng::seed_from_u64(0xA71A5);
    let (mut worst_root, mut worst_zero, mut checked): (f64, f64, usize) = (0.0, 0.0, 0);
    let mut record = |(root, zero): (f64, f64)| {
        worst_root = worst_root.max(root);
        worst_zero = worst_zero.max(zero);
        checked += usize::from(root > 0.0 || zero > 0.0);
    };
    let atlas = lagrange_atlas(41, 0);
    for k in 0..60 {
        let (i, j) = (rng.gen_range(0..41), rng.gen_range(0..41));
        let model = HeavyTop::lagrange(A1, C_LAGRANGE, atlas.x[i]);
        record(check_node(&atlas, &model, atlas.y[j], i, j, k < 12));
    }
    let atlas = asymmetric_atlas(0);
    for k in 0..60 {
        let (i, j) = (rng.gen_range(0..41), rng.gen_range(0..61));
        record(check_node(
            &atlas,
            &asymmetric(atlas.x[i]),
            atlas.y[j],
            i,
            j,
            k < 12,
        ));
    }
    // One node in each region of the asymmetric top, checked against the FD Jacobian.
    let mut seen = std::collections::HashSet::new();
    for j in 0..61 {
        for i in 0..41 {
            if let Some(v) = atlas.verdicts[j][i] {
                if !seen.contains(&v) && well_separated(&asymmetric(atlas.x[i]), atlas.y[j]) {
                    seen.insert(v);
                    record(check_node(
                        &atlas,
                        &asymmetric(atlas.x[i]),
                        atlas.y[j],
                        i,
                        j,
                        true,
                    ));
                }
            }
        }
    }
    assert!(seen.contains(&Stability::GyroscopicallyStabilized));
    assert!(seen.contains(&Stability::SecularlyStable));
    assert!(seen.contains(&Stability::Unstable));
    println!(
        "FD Jacobian at {checked} nodes: roots of f₂ to eigenvalues {worst_root:.3e}, leftover \
         eigenvalues to zero {worst_zero:.3e} (relative to |λ|max)"
    );
    assert!(
        checked >= 10,
        "only {checked} nodes checked against the FD Jacobian"
    );
}

#[test]
fn atlas_does_not_depend_on_the_number_of_threads() {
    let one = lagrange_atlas(31, 1);
    let four = lagrange_atlas(31, 4);
    assert_eq!(one, four);
    // The sequential entry point gives the same atlas.
    let sequential = stability_atlas(
        |mgl: f64, p: f64| (HeavyTop::lagrange(A1, C_LAGRANGE, mgl), p),
        Vector3::z(),
        (0.5, 2.0),
        (0.5, 5.0),
        &AtlasOptions {
            nx: 31,
            ny: 31,
            ..AtlasOptions::default()
        },
    )
    .unwrap();
    assert_eq!(one, sequential);
    let one = asymmetric_atlas(1);
    let four = asymmetric_atlas(4);
    assert_eq!(one, four);
}

#[test]
fn invalid_options_are_errors() {
    let family = |mgl: f64, p: f64| (HeavyTop::lagrange(A1, C_LAGRANGE, mgl), p);
    for opts in [
        AtlasOptions {
            nx: 1,
            ..AtlasOptions::default()
        },
        AtlasOptions {
            curve_tol: 0.0,
            ..AtlasOptions::default()
        },
    ] {
        assert!(stability_atlas(family, Vector3::z(), (0.5, 2.0), (0.5, 5.0), &opts).is_err());
    }
    let opts = AtlasOptions::default();
    assert!(stability_atlas(family, Vector3::z(), (2.0, 0.5), (0.5, 5.0), &opts).is_err());
    assert!(stability_atlas(family, Vector3::z(), (0.5, 2.0), (0.5, f64::NAN), &opts).is_err());
}

/// A top J = diag(1, 1.2, 1.6) with its centre of mass off the axis, r = (ε, 0, 1) (mgl = 1),
/// over (p_ψ, ε): the pitchfork of the sleeping top unfolds and the near-upright motion, followed
/// from slow spin, ends at a fold.
fn imperfect(p: f64, eps: f64) -> (HeavyTop, f64) {
    (
        HeavyTop {
            j: Matrix3::from_diagonal(&Vector3::new(1.0, 1.2, 1.6)),
            mgr: Vector3::new(eps, 0.0, 1.0),
        },
        p,
    )
}

/// The folds of the motions in the plane γ = (sin θ, 0, cos θ), by hand: with
/// U_r(θ) = ½p²/n + ε sin θ + cos θ, n = A sin²θ + C cos²θ, U_r′ = p²a − sin θ + ε cos θ and
/// U_r″ = p²a′ − cos θ − ε sin θ with a = (C − A) sin θ cos θ / n². Both vanish — linear in
/// (p², ε) — at p² = 1/(a sin θ + a′ cos θ), ε = (a′ sin θ − a cos θ)/(a sin θ + a′ cos θ).
fn in_plane_fold(theta: f64) -> (f64, f64) {
    let (a_, c_) = (1.0, 1.6);
    let (s, c) = theta.sin_cos();
    let n = a_ * s * s + c_ * c * c;
    let dn = 2.0 * (a_ - c_) * s * c;
    let a = (c_ - a_) * s * c / (n * n);
    let da = (c_ - a_) * ((c * c - s * s) / (n * n) - 2.0 * s * c * dn / (n * n * n));
    let d = a * s + da * c;
    (1.0 / d, (da * s - a * c) / d)
}

#[test]
fn imperfect_top_fold_curve_matches_the_in_plane_closed_form() {
    // The near-upright motion does not exist in the middle of the rectangle (beyond its fold):
    // start where it does, at slow spin and ε = 0.
    let opts = AtlasOptions {
        nx: 31,
        ny: 31,
        start: Some((1.0, 0.0)),
        ..AtlasOptions::default()
    };
    let atlas = stability_atlas(imperfect, Vector3::z(), (1.0, 3.0), (0.0, 0.2), &opts).unwrap();
    // From the middle, the motion asked for is not there: Newton's method from the guess does
    // not converge, or lands on another motion (refused), never a silent atlas of another one.
    let middle = AtlasOptions {
        start: None,
        ..opts.clone()
    };
    match stability_atlas(imperfect, Vector3::z(), (1.0, 3.0), (0.0, 0.2), &middle) {
        Err(RouthError::InvalidOption {
            what: "gamma_guess",
            reason,
        }) => println!("{reason}"),
        Err(RouthError::AtParameter { .. }) => {}
        other => panic!("{other:?}"),
    }
    // No node is "lost" on this grid: beyond the fold the motion does not exist.
    assert!(atlas.lost.iter().flatten().all(|l| !l));
    // The motion is lost beyond the fold for small ε > 0.
    assert!(atlas.verdicts[1].iter().any(|v| v.is_none()));
    assert!(atlas.verdicts[0].iter().all(|v| v.is_some()));
    let folds: Vec<_> = atlas
        .boundaries
        .iter()
        .filter(|b| b.kind == EventKind::Fold)
        .collect();
    assert_eq!(folds.len(), 1, "{:?}", atlas.boundaries);
    let grid: Vec<f64> = (0..=4000).map(|k| -1.2 + 2.4 * k as f64 / 4000.0).collect();
    let mut worst: f64 = 0.0;
    for &(p, eps) in &folds[0].points {
        // Every θ ∈ [−1.2, 1.2] with ε(θ) = ε (a scan and bisection); the fold is there if
        // p²(θ) = p² for one of them.
        let thetas = bracketed_roots(|t| in_plane_fold(t).1 - eps, &grid, 1e-12);
        assert!(!thetas.is_empty(), "no θ with ε(θ) = {eps}");
        let best = thetas
            .iter()
            .map(|&t| (in_plane_fold(t).0 - p * p).abs() / (p * p))
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(best);
    }
    println!(
        "fold curve: {} points, max |p² − p²_fold(θ)|/p² = {worst:.3e}",
        folds[0].points.len()
    );
    // Measured 3.6e−10 (the fold is a square-root point of the motion, so p² along the curve is
    // less well conditioned than the residual of its equations): ten times that.
    assert!(worst <= 4e-9, "{worst:e}");
    // The out-of-plane pitchfork (γ₂ → −γ₂ is still a symmetry) is a branch point.
    assert!(atlas
        .boundaries
        .iter()
        .any(|b| b.kind == EventKind::BranchPoint));
}

#[test]
fn curve_budget_ends_the_atlas_with_a_stop_reason_that_says_where() {
    // Each boundary curve of the sleeping Lagrange top crosses the whole rectangle in about 150
    // points: a budget of 10 runs out on the first one traced. The atlas comes back with its
    // verdicts, the curves cut short, and where the budget ran out.
    let opts = AtlasOptions {
        nx: 11,
        ny: 11,
        max_curve_points: 10,
        ..AtlasOptions::default()
    };
    let family = |mgl: f64, p: f64| (HeavyTop::lagrange(A1, C_LAGRANGE, mgl), p);
    let atlas = stability_atlas(family, Vector3::z(), (0.5, 2.0), (0.5, 5.0), &opts).unwrap();
    assert!(atlas.verdicts.iter().flatten().all(|v| v.is_some()));
    assert!(atlas.boundaries.iter().all(|b| b.points.len() <= 10));
    match atlas.stop {
        Some(StopReason::MaxCurvePoints { x: mgl, y: p, .. }) => {
            // On Maievskii's or on the secular bound.
            let maievskii = (p * p - 4.0 * A1 * mgl).abs() / (4.0 * A1 * mgl);
            let secular = (p * p * (C_LAGRANGE - A1) / (C_LAGRANGE * C_LAGRANGE) - mgl).abs() / mgl;
            assert!(maievskii.min(secular) < 1e-9, "({mgl}, {p})");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_start_and_the_angle_from_the_guess() {
    let family = |mgl: f64, p: f64| (HeavyTop::lagrange(A1, C_LAGRANGE, mgl), p);
    let guess = Vector3::new(1e-3, 0.0, 1.0); // 1e−3 rad from the sleeping top e₃
    let base = AtlasOptions {
        nx: 5,
        ny: 5,
        ..AtlasOptions::default()
    };
    // Default: the middle of the rectangle; the sleeping top exists everywhere, so the start
    // does not change the verdicts.
    let middle = stability_atlas(family, guess, (0.5, 2.0), (0.5, 5.0), &base).unwrap();
    for start in [(0.5, 0.5), (2.0, 5.0), (1.1, 2.2)] {
        let opts = AtlasOptions {
            start: Some(start),
            ..base.clone()
        };
        let other = stability_atlas(family, guess, (0.5, 2.0), (0.5, 5.0), &opts).unwrap();
        assert_eq!(other.verdicts, middle.verdicts, "start {start:?}");
    }
    // The motion found is 1e−3 rad from the guess: refused below that angle.
    let strict = AtlasOptions {
        max_guess_angle: 1e-4,
        ..base.clone()
    };
    match stability_atlas(family, guess, (0.5, 2.0), (0.5, 5.0), &strict) {
        Err(RouthError::InvalidOption {
            what: "gamma_guess",
            reason,
        }) => assert!(reason.contains("rad from the guess"), "{reason}"),
        other => panic!("{other:?}"),
    }
    let outside = AtlasOptions {
        start: Some((3.0, 1.0)),
        ..base
    };
    assert!(matches!(
        stability_atlas(family, guess, (0.5, 2.0), (0.5, 5.0), &outside),
        Err(RouthError::InvalidOption { what: "start", .. })
    ));
}

/// Grids and seed counts too large to run are bad input (an `InvalidOption` naming the option),
/// not a crash on allocation or a computation that never ends (found from Python: 2³² × 2³²
/// nodes aborted the interpreter, 2⁴⁰ seeds hung).
#[test]
fn oversized_grids_and_seed_counts_are_refused() {
    use routh_core::{bifurcation_diagram, ContinuationOptions, RouthError, Vector3};
    let top = test_models::Gyrostat::lagrange_top(1.0, 1.25, 1.0);
    let family = |mgl: f64, p: f64| (test_models::Gyrostat::lagrange_top(1.0, 1.25, mgl), p);
    for (nx, ny) in [
        (1usize << 32, 1usize << 32),
        (usize::MAX, 2),
        (20_000, 20_000),
    ] {
        let opts = AtlasOptions {
            nx,
            ny,
            ..Default::default()
        };
        let r = stability_atlas(family, Vector3::z(), (0.5, 1.5), (1.0, 4.0), &opts);
        assert!(
            matches!(r, Err(RouthError::InvalidOption { what: "nx", .. })),
            "{nx} × {ny}: {r:?}"
        );
    }
    let opts = ContinuationOptions {
        seeds: 1 << 40,
        ..Default::default()
    };
    let r = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &opts);
    assert!(
        matches!(r, Err(RouthError::InvalidOption { what: "seeds", .. })),
        "{r:?}"
    );
}
