//! Families of steady motions (bifurcation diagrams) against closed forms and independent
//! computations: Maievskii's and the secular bound of Lagrange tops, the branch points and the
//! fold of the asymmetric top, the Hamiltonian–Hopf point of a prolate asymmetric top from a
//! hand-derived f₂, no event where two roots of f₂ of equal Krein signature cross (a hand-derived
//! quartic of a gyrostat), counts of steady motions between events against the global search and
//! the closed form, finite-difference Jacobian eigenvalues on each side of every event, and the
//! budgets, which end with a partial diagram and say where, and unreachable branches,
//! which are errors.

use crate::common;

use common::HeavyTop;

use routh_core::nalgebra::{Matrix4, Vector6};
use routh_core::stability::krein_report;
use routh_core::{
    bifurcation_diagram, continue_branch, steady_motions, BifurcationDiagram, ClassifyOptions,
    ContinuationOptions, EventKind, Matrix3, RouthError, Stability, StopReason, Vector3,
};
use test_models::jacobian::fd_jacobian;
use test_models::roots::bracketed_roots;
use test_models::Gyrostat;

fn asymmetric(a: f64, b: f64, c: f64, mgl: f64) -> HeavyTop {
    HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(a, b, c)),
        mgr: Vector3::new(0.0, 0.0, mgl),
    }
}

fn events(d: &BifurcationDiagram, kind: EventKind) -> Vec<f64> {
    d.events
        .iter()
        .filter(|e| e.kind == kind)
        .map(|e| e.s)
        .collect()
}

/// An event located at `found` against its closed form `exact`: within `2·event_tol` (the
/// bracket of the located zero, `event_tol·max(1, |s|)` wide, plus the error of the test function
/// itself; `event_tol = 1e−10` by default). Measured over this file: at most 1.7e−11·max(1, |s|)
/// (6.7e−11 at s = 4.03); each call prints its error.
fn assert_located(found: f64, exact: f64, what: &str) {
    let err = (found - exact).abs();
    println!("{what}: |Δs| = {err:.3e}");
    assert!(
        err <= 2e-10 * exact.abs().max(1.0),
        "{what}: found {found:.15}, closed form {exact:.15}, |Δs| = {err:e}"
    );
}

/// The fold of tilted steady motions in the plane γ = (sin θ, 0, cos θ) of a top
/// J = diag(A, ·, C), U = mgl·γ₃: with c = cos θ, U_r = ½p²/(A + (C − A)c²) + mgl·c; critical
/// where ∂U_r/∂c = 0 and folded where also ∂²U_r/∂c² = 0, which gives A = 3(C − A)c² and
/// p² = mgl(A + (C − A)c²)²/((C − A)c).
fn plane_fold(a: f64, c: f64, mgl: f64) -> (f64, f64) {
    let z = (a / (3.0 * (c - a))).sqrt();
    let p2 = mgl * (a + (c - a) * z * z).powi(2) / ((c - a) * z);
    (p2.sqrt(), z)
}

#[test]
fn lagrange_tops_have_exactly_the_closed_form_events() {
    // (A₁, C, mgl): prolate-ish, C > 4A₁/3 (subcritical: a fold of circles below the secular
    // bound), C > 2A₁.
    for (a1, c, mgl) in [
        (1.0, 1.25, 1.0),
        (1.0, 1.5, 0.7),
        (1.0, 3.0, 2.0),
        (2.0, 2.5, 1.3),
    ] {
        let top = HeavyTop::lagrange(a1, c, mgl);
        let maievskii = (4.0 * a1 * mgl).sqrt();
        let secular = (mgl * c * c / (c - a1)).sqrt();
        let hi = (1.4 * secular).max(5.0);
        let checked = bifurcation_diagram(
            |p| (top.clone(), p),
            (0.0, hi),
            &ContinuationOptions::default(),
        )
        .unwrap();
        let d = &checked;
        let what = format!("A₁ = {a1}, C = {c}, mgl = {mgl}");
        let hh = events(d, EventKind::HamiltonianHopf);
        assert_eq!(hh.len(), 1, "{what}: {:#?}", d.events);
        assert_located(hh[0], maievskii, &format!("{what}: Maievskii"));
        let bp = events(d, EventKind::BranchPoint);
        assert_eq!(bp.len(), 1, "{what}: {:#?}", d.events);
        assert_located(bp[0], secular, &format!("{what}: secular bound"));
        let folds = events(d, EventKind::Fold);
        if c > 4.0 * a1 / 3.0 {
            let (p, z) = plane_fold(a1, c, mgl);
            assert_eq!(folds.len(), 1, "{what}: {:#?}", d.events);
            assert_located(folds[0], p, &format!("{what}: fold of circles"));
            let e = d.events.iter().find(|e| e.kind == EventKind::Fold).unwrap();
            assert!(
                (e.gamma.z - z).abs() < 1e-6,
                "{what}: fold at γ₃ = {}",
                e.gamma.z
            );
            assert!(!d.branches[e.branch].isolated, "the fold is one of circles");
        } else {
            assert!(folds.is_empty(), "{what}: {:#?}", d.events);
        }
        // Verdicts on the sleeping top.
        let hh = d
            .events
            .iter()
            .find(|e| e.kind == EventKind::HamiltonianHopf)
            .unwrap();
        assert_eq!(
            (hh.before, hh.after),
            (Stability::Unstable, Stability::GyroscopicallyStabilized)
        );
        let bp = d
            .events
            .iter()
            .find(|e| e.kind == EventKind::BranchPoint)
            .unwrap();
        assert_eq!(
            (bp.before, bp.after),
            (
                Stability::GyroscopicallyStabilized,
                Stability::SecularlyStable
            ),
            "{what}"
        );
        assert!((bp.gamma - Vector3::z()).norm() < 1e-9);
        // The circles are born at the branch point.
        assert!(d.branches.iter().any(|b| !b.isolated));
        assert!(checked.consistent(), "{what}: {:#?}", checked.checks);
    }
}

#[test]
fn asymmetric_top_branch_points_and_fold() {
    // J = diag(A, B, C), C largest, centre of mass on e₃: on the sleeping top
    // K = diag(p²(C − A)/C² − mgl, p²(C − B)/C² − mgl), zero at p² = mglC²/(C − A), mglC²/(C − B).
    let (a, b, c, mgl) = (1.0, 1.2, 1.5, 1.0);
    let top = asymmetric(a, b, c, mgl);
    let checked = bifurcation_diagram(
        |p| (top.clone(), p),
        (0.0, 4.0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    let d = &checked;
    let bp = events(d, EventKind::BranchPoint);
    assert_eq!(bp.len(), 2, "{:#?}", d.events);
    assert_located(bp[0], (mgl * c * c / (c - a)).sqrt(), "first branch point");
    assert_located(bp[1], (mgl * c * c / (c - b)).sqrt(), "second branch point");
    // The branch leaving the first branch point lies in the plane γ₂ = 0 and folds where the
    // plane's own {∂U_r/∂θ = 0, ∂²U_r/∂θ² = 0} holds (two mirror images).
    let (p_fold, z_fold) = plane_fold(a, c, mgl);
    let folds: Vec<_> = d
        .events
        .iter()
        .filter(|e| e.kind == EventKind::Fold)
        .collect();
    assert_eq!(folds.len(), 2, "{:#?}", d.events);
    for f in folds {
        assert_located(f.s, p_fold, "fold");
        assert!(
            f.gamma.y.abs() < 1e-9 && (f.gamma.z - z_fold).abs() < 1e-7,
            "{f}"
        );
    }
    assert!(checked.consistent(), "{:#?}", checked.checks);
}

/// f₂ = c₄λ⁴ + c₂λ² + c₀ of a sleeping gyrostat by hand: a body J = diag(A, B, C) with a rotor of
/// momentum κe₃ and its centre of mass on e₃ (U = mgl·γ₃), at γ = e₃, ω = (0, 0, r), so
/// p_ψ = Cr + κ. Linearising Euler's (Jω + κe₃)˙ = (Jω + κe₃) × ω + ∂L/∂γ × γ and Poisson's
/// γ̇ = γ × ω in (ω₁, ω₂, γ₁, γ₂):
/// Aω̇₁ = (Br − p)ω₂ + mgl γ₂, Bω̇₂ = (p − Ar)ω₁ − mgl γ₁, γ̇₁ = rγ₂ − ω₂, γ̇₂ = ω₁ − rγ₁
/// (κ = 0 is the heavy top: Br − p = (B − C)r, p − Ar = (C − A)r). The characteristic polynomial
/// (rows scaled by A and B) is an even quartic; its coefficients come from evaluating the
/// determinant at λ = 0, 1, 2 (even: c₀ + c₂λ² + c₄λ⁴).
fn sleeping_f2(a: f64, b: f64, c: f64, kappa: f64, mgl: f64, p: f64) -> [f64; 3] {
    let r = (p - kappa) / c;
    let det = |l: f64| {
        Matrix4::new(
            a * l,
            -(b * r - p),
            0.0,
            -mgl, //
            -(p - a * r),
            b * l,
            mgl,
            0.0, //
            0.0,
            1.0,
            l,
            -r, //
            -1.0,
            0.0,
            r,
            l,
        )
        .determinant()
    };
    let c0 = det(0.0);
    let c4 = (det(2.0) - 4.0 * det(1.0) + 3.0 * c0) / 12.0;
    let c2 = det(1.0) - c0 - c4;
    [c4, c2, c0]
}

/// The discriminant c₂² − 4c₄c₀ of f₂ of the sleeping asymmetric top (no rotor).
fn sleeping_discriminant(a: f64, b: f64, c: f64, mgl: f64, p: f64) -> f64 {
    let [c4, c2, c0] = sleeping_f2(a, b, c, 0.0, mgl, p);
    c2 * c2 - 4.0 * c4 * c0
}

#[test]
fn hamiltonian_hopf_of_a_prolate_asymmetric_top_matches_the_hand_written_discriminant() {
    let (a, b, c, mgl) = (2.0, 2.3, 1.0, 1.0);
    let top = asymmetric(a, b, c, mgl);
    let d = bifurcation_diagram(
        |p| (top.clone(), p),
        (0.5, 6.0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    let hh: Vec<_> = d
        .events
        .iter()
        .filter(|e| e.kind == EventKind::HamiltonianHopf && (e.gamma - Vector3::z()).norm() < 1e-9)
        .collect();
    assert_eq!(hh.len(), 1, "{:#?}", d.events);
    // The zero of the hand-written discriminant, bisected within ±0.05 of the event.
    let zeros = bracketed_roots(
        |p| sleeping_discriminant(a, b, c, mgl, p),
        &[hh[0].s - 0.05, hh[0].s + 0.05],
        0.0,
    );
    assert_eq!(
        zeros.len(),
        1,
        "the discriminant changes sign once near the event"
    );
    assert_located(hh[0].s, zeros[0], "Hamiltonian–Hopf");
    assert_eq!(hh[0].before, Stability::Unstable);
    assert_eq!(hh[0].after, Stability::GyroscopicallyStabilized);
}

#[test]
fn jacobian_eigenvalues_agree_with_verdicts_on_each_side_of_every_event() {
    let mut checked = 0;
    for (top, hi) in [
        (HeavyTop::lagrange(1.0, 1.25, 1.0), 3.5),
        (asymmetric(1.0, 1.2, 1.5, 1.0), 3.5),
        (asymmetric(2.0, 2.3, 1.0, 1.0), 6.0),
    ] {
        let d = bifurcation_diagram(
            |p| (top.clone(), p),
            (0.5, hi),
            &ContinuationOptions::default(),
        )
        .unwrap();
        for e in &d.events {
            let branch = &d.branches[e.branch];
            // The points of the branch nearest the event on either side.
            let i = branch
                .points
                .iter()
                .enumerate()
                .min_by(|x, y| (x.1.s - e.s).abs().total_cmp(&(y.1.s - e.s).abs()))
                .unwrap()
                .0;
            for q in [i.saturating_sub(1), (i + 1).min(branch.points.len() - 1)] {
                let pt = &branch.points[q];
                let verdict = pt.report.verdict;
                if verdict == Stability::Degenerate {
                    continue;
                }
                let w = pt.steady.psi_dot * pt.steady.gamma;
                let g = pt.steady.gamma;
                let x = Vector6::new(w.x, w.y, w.z, g.x, g.y, g.z);
                let eig = fd_jacobian(&top, &x, 1e-4).complex_eigenvalues();
                let max_re = eig.iter().map(|l| l.re).fold(f64::MIN, f64::max);
                let size = eig.iter().map(|l| l.norm()).fold(0.0, f64::max);
                if verdict == Stability::Unstable {
                    assert!(
                        max_re > 1e-4 * size,
                        "{e}: at s = {} unstable but {eig}",
                        pt.s
                    );
                } else {
                    assert!(
                        max_re < 1e-5 * size.max(1.0),
                        "{e}: at s = {} {verdict} but {eig}",
                        pt.s
                    );
                }
                checked += 1;
            }
        }
    }
    assert!(checked >= 10, "only {checked} points checked");
}

#[test]
fn continue_branch_follows_one_branch_over_a_body_parameter() {
    // The sleeping top over mgl at p = 3: secular stability lost at mgl = p²(C − A₁)/C²,
    // gyroscopic stabilisation lost at Maievskii's mgl = p²/(4A₁).
    let (a1, c, p) = (1.0, 1.25, 3.0);
    let d = continue_branch(
        |mgl| (HeavyTop::lagrange(a1, c, mgl), p),
        Vector3::new(0.01, 0.0, 1.0),
        1.0,
        (0.5, 3.0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    let on_sleeping: Vec<_> = d
        .events
        .iter()
        .filter(|e| (e.gamma - Vector3::z()).norm() < 1e-9)
        .collect();
    let bp = on_sleeping
        .iter()
        .find(|e| e.kind == EventKind::BranchPoint)
        .unwrap();
    assert_located(bp.s, p * p * (c - a1) / (c * c), "secular bound in mgl");
    assert_eq!(
        (bp.before, bp.after),
        (
            Stability::SecularlyStable,
            Stability::GyroscopicallyStabilized
        )
    );
    let hh = on_sleeping
        .iter()
        .find(|e| e.kind == EventKind::HamiltonianHopf)
        .unwrap();
    assert_located(hh.s, p * p / (4.0 * a1), "Maievskii in mgl");
    assert_eq!(
        (hh.before, hh.after),
        (Stability::GyroscopicallyStabilized, Stability::Unstable)
    );
}

#[test]
fn errors_are_values() {
    let top = HeavyTop::lagrange(1.0, 1.25, 1.0);
    let opts = ContinuationOptions::default();
    assert!(matches!(
        bifurcation_diagram(|p| (top.clone(), p), (1.0, 1.0), &opts),
        Err(RouthError::InvalidOption { what: "range", .. })
    ));
    assert!(matches!(
        bifurcation_diagram(|p| (top.clone(), p), (0.0, f64::NAN), &opts),
        Err(RouthError::NonFinite { what: "range", .. })
    ));
    // A family whose kinetic form stops being positive definite inside the range.
    let bad = |s: f64| (HeavyTop::lagrange(1.0 - s, 1.25, 1.0), 1.0);
    match bifurcation_diagram(bad, (0.0, 2.0), &opts) {
        Err(RouthError::AtParameter { s, source }) => {
            assert!(s >= 1.0, "{s}");
            assert!(matches!(
                *source,
                RouthError::KineticNotPositiveDefinite { .. }
                    | RouthError::DegenerateVerticalInertia { .. }
            ));
        }
        other => panic!("{other:?}"),
    }
    // A non-finite p_ψ from the family.
    assert!(matches!(
        bifurcation_diagram(|_| (top.clone(), f64::NAN), (0.0, 1.0), &opts),
        Err(RouthError::AtParameter { .. })
    ));
    assert!(matches!(
        continue_branch(|p| (top.clone(), p), Vector3::z(), 9.0, (0.0, 5.0), &opts),
        Err(RouthError::InvalidOption { what: "s0", .. })
    ));
}

/// Whether γ is a steady motion of the Lagrange top (A₁, C, mgl) at p, to the 9 digits of an
/// error message: γ = ±e₃, or a point of a circle γ₃ = c with p²(C − A₁)c = mgl(A₁ + (C − A₁)c²)²
/// (the critical points of U_r(c) = ½p²/(A₁ + (C − A₁)c²) + mgl·c in c = γ₃ ∈ (−1, 1)).
fn lagrange_steady(a1: f64, c: f64, mgl: f64, p: f64, g: &Vector3<f64>) -> bool {
    let z = g.z;
    let pole = (z.abs() - 1.0).abs() < 1e-8;
    let circle = (p * p * (c - a1) * z - mgl * (a1 + (c - a1) * z * z).powi(2)).abs()
        < 1e-7 * (p * p).max(mgl);
    (g.norm() - 1.0).abs() < 1e-8 && (pole || circle)
}

#[test]
fn budgets_end_with_a_partial_diagram_and_unreachable_branches_are_errors() {
    let (a1, c, mgl) = (1.0, 1.25, 1.0);
    let top = HeavyTop::lagrange(a1, c, mgl);
    let family = |p: f64| (top.clone(), p);
    let default = ContinuationOptions::default();
    // The budget of steps per branch: no branch of [0, 5] fits in 3 steps. The diagram comes
    // back with what was traced and the reason it stopped, at a steady motion.
    let tiny = ContinuationOptions {
        max_steps: 3,
        ..ContinuationOptions::default()
    };
    let d = bifurcation_diagram(family, (0.0, 5.0), &tiny).unwrap();
    match d.stop {
        Some(StopReason::MaxSteps { s, gamma }) => {
            assert!(s > 0.0 && s < 5.0, "{s}");
            assert!(lagrange_steady(a1, c, mgl, s, &gamma), "{s} {gamma}");
        }
        ref other => panic!("{other:?}"),
    }
    assert!(!d.branches.is_empty());
    for b in &d.branches {
        assert!(b.points.len() <= 4);
        for q in &b.points {
            assert!(lagrange_steady(a1, c, mgl, q.s, &q.steady.gamma));
        }
    }
    // The budget of branches: the diagram over [0, 5] has three.
    for (max_branches, ok) in [(2, false), (3, true)] {
        let opts = ContinuationOptions {
            max_branches,
            ..ContinuationOptions::default()
        };
        let d = bifurcation_diagram(family, (0.0, 5.0), &opts).unwrap();
        assert_eq!(d.branches.len(), max_branches);
        match d.stop {
            None if ok => {}
            Some(StopReason::MaxBranches { s, gamma }) if !ok => {
                assert!((0.0..=5.0).contains(&s), "{s}");
                assert!(lagrange_steady(a1, c, mgl, s, &gamma), "{s} {gamma}");
            }
            other => panic!("max_branches = {max_branches}: {other:?}"),
        }
    }
    // An unreachable branch: the weight jumps from mgl = 1 to 1/2 at p = 3, so the circles of
    // tilted steady motions (γ₃ from p²(C − A₁)γ₃ = mgl(A₁ + (C − A₁)γ₃²)²) jump there and
    // cannot be continued through it; the poles γ = ±e₃ are steady motions on both sides.
    let jump = |p: f64| {
        let mgl = if p < 3.0 { 1.0 } else { 0.5 };
        (HeavyTop::lagrange(a1, c, mgl), p)
    };
    match bifurcation_diagram(jump, (0.0, 5.0), &default) {
        Err(RouthError::AtParameter { s, source }) => {
            assert!((s - 3.0).abs() < 1e-3, "{s}: {source}");
            assert!(
                matches!(*source, RouthError::NoConvergence { what, .. } if what.contains("min_step")),
                "{source}"
            );
        }
        other => panic!("{other:?}"),
    }
    // continue_branch from a point that is not a regular point of a branch: the sleeping top at
    // its secular bound p² = mglC²/(C − A₁) = 6.25, where K = 0.
    match continue_branch(family, Vector3::z(), 2.5, (0.0, 5.0), &default) {
        Err(RouthError::InvalidOption { what: "s0", reason }) => {
            assert!(reason.contains("s0 = 2.5"), "{reason}")
        }
        other => panic!("{other:?}"),
    }
    // … from a guess where Newton's method cannot start (γ = 0), or where the model is not finite.
    match continue_branch(family, Vector3::zeros(), 1.0, (0.0, 5.0), &default) {
        Err(RouthError::AtParameter { s, source }) => {
            assert_eq!(s, 1.0);
            assert!(
                matches!(*source, RouthError::NonUnitGamma { .. }),
                "{source}"
            );
        }
        other => panic!("{other:?}"),
    }
    let nan_at_one = |p: f64| {
        let mgl = if p == 1.0 { f64::NAN } else { 1.0 };
        (HeavyTop::lagrange(a1, c, mgl), p)
    };
    match continue_branch(nan_at_one, Vector3::z(), 1.0, (0.0, 5.0), &default) {
        Err(RouthError::AtParameter { s, .. }) => assert_eq!(s, 1.0),
        other => panic!("{other:?}"),
    }
}

#[test]
fn roots_of_equal_krein_signature_cross_without_an_event() {
    // A symmetric gyrostat A = B = 1, C = 3/2 with a rotor κ = 1/2 on its axis, hanging (centre
    // of mass on −e₃: mgl = −1), over p_ψ ∈ [1, 3]. At γ = e₃, ω = re₃ (r = (p − κ)/C) the
    // linearisation of `sleeping_f2` in z = ω₁ + iω₂, ζ = γ₁ + iγ₂ is Aż = i(p − Ar)z − i·mgl·ζ,
    // ζ̇ = −irζ + iz; with z, ζ ∝ e^{iωt}, z = (ω + r)ζ and ν = ω + r solves Aν² − pν + mgl = 0.
    // The roots of f₂ are ±iω_a, ±iω_b with ω_a = ν₊ − r, ω_b = r − ν₋ (both positive here), and
    // ω_a − ω_b = p/A − 2r is linear in p: the frequencies cross at p* = 2Aκ/(2A − C) = 2.
    // U_r(c) = ½(p − κc)²/(A + (C − A)c²) + mgl·c in c = γ₃ has at the pole
    // K = −U_r′(1)·E = [κ(p − κ)/C + (p − κ)²(C − A)/C² − mgl]·E > 0: degree of instability 0, so
    // every mode carries positive energy (one Krein signature), and the crossing is harmless.
    let (a, c, kappa, mgl) = (1.0, 1.5, 0.5, -1.0);
    let body = Gyrostat::new(
        Matrix3::from_diagonal(&Vector3::new(a, a, c)),
        Vector3::new(0.0, 0.0, kappa),
        Matrix3::zeros(),
        Vector3::new(0.0, 0.0, mgl),
        1.0,
        1.0,
    );
    let p_star = 2.0 * a * kappa / (2.0 * a - c);
    let closed = |p: f64| {
        let r = (p - kappa) / c;
        let root = (p * p - 4.0 * a * mgl).sqrt();
        ((p + root) / (2.0 * a) - r, r - (p - root) / (2.0 * a))
    };
    // The frequencies from the hand-written quartic, (slow, fast).
    let quartic = |p: f64| {
        let [c4, c2, c0] = sleeping_f2(a, a, c, kappa, mgl, p);
        assert!(c4 > 0.0 && c2 > 0.0 && c0 > 0.0, "p = {p}: {c4} {c2} {c0}");
        let d = c2 * c2 - 4.0 * c4 * c0;
        assert!(d >= -1e-12 * c2 * c2, "p = {p}: a complex pair");
        let sq = d.max(0.0).sqrt();
        (
            ((c2 - sq) / (2.0 * c4)).sqrt(),
            ((c2 + sq) / (2.0 * c4)).sqrt(),
        )
    };
    // Independently of routh: the closed form is the quartic's, and its branches cross at p*
    // (ω_a − ω_b changes sign there once), where the quartic has a double pair.
    for k in 0..=20 {
        let p = 1.0 + 0.1 * k as f64;
        let (slow, fast) = quartic(p);
        let (wa, wb) = closed(p);
        assert!(
            (slow - wa.min(wb)).abs() <= 1e-12 * fast && (fast - wa.max(wb)).abs() <= 1e-12 * fast,
            "p = {p}: quartic ({slow}, {fast}), closed form ({wa}, {wb})"
        );
    }
    let grid: Vec<f64> = (0..=20).map(|k| 1.0 + 0.1 * k as f64 + 0.013).collect();
    let crossings = bracketed_roots(|p| closed(p).0 - closed(p).1, &grid, 0.0);
    assert_eq!(crossings.len(), 1);
    assert!((crossings[0] - p_star).abs() <= 1e-12, "{crossings:?}");
    let [c4, c2, c0] = sleeping_f2(a, a, c, kappa, mgl, p_star);
    assert!((c2 * c2 - 4.0 * c4 * c0).abs() <= 1e-12 * c2 * c2);

    let d = bifurcation_diagram(
        |p| (body.clone(), p),
        (1.0, 3.0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    let hanging = d
        .branches
        .iter()
        .position(|b| {
            b.isolated
                && b.points
                    .iter()
                    .all(|q| (q.steady.gamma - Vector3::z()).norm() < 1e-9)
        })
        .expect("the hanging gyrostat is a branch");
    let branch = &d.branches[hanging];
    let s: Vec<f64> = branch.points.iter().map(|q| q.s).collect();
    assert!(s.contains(&1.0) && s.contains(&3.0), "{s:?}");
    // No event on it, in particular no Hamiltonian–Hopf point at p*.
    assert!(
        d.events
            .iter()
            .all(|e| e.branch != hanging && (e.gamma - Vector3::z()).norm() > 1e-6),
        "{:#?}",
        d.events
    );
    for q in &branch.points {
        assert_eq!(q.report.verdict, Stability::SecularlyStable, "p = {}", q.s);
        let k = kappa * (q.s - kappa) / c + (q.s - kappa).powi(2) * (c - a) / (c * c) - mgl;
        for e in q.report.restricted_hessian_eigenvalues {
            assert!(
                (e - k).abs() <= 1e-9 * k,
                "p = {}: K = {e}, closed form {k}",
                q.s
            );
        }
    }
    // The points next to p* on either side: the frequencies are the hand-written ones, in the
    // opposite order of the branches ω_a, ω_b, and all four roots have one Krein signature.
    let below = branch
        .points
        .iter()
        .filter(|q| q.s < p_star)
        .max_by(|x, y| x.s.total_cmp(&y.s))
        .unwrap();
    let above = branch
        .points
        .iter()
        .filter(|q| q.s > p_star)
        .min_by(|x, y| x.s.total_cmp(&y.s))
        .unwrap();
    let gap = |p: f64| closed(p).0 - closed(p).1;
    assert!(gap(below.s) * gap(above.s) < 0.0);
    for q in [below, above] {
        let kr = krein_report(&body, &q.steady, &ClassifyOptions::default()).unwrap();
        let (slow, fast) = quartic(q.s);
        let mut w: Vec<f64> = kr.report.f2_roots.iter().map(|r| r.im.abs()).collect();
        w.sort_by(f64::total_cmp);
        for (x, y) in w.iter().zip([slow, slow, fast, fast]) {
            assert!(
                (x - y).abs() <= 1e-9 * fast,
                "p = {}: {w:?} vs ({slow}, {fast})",
                q.s
            );
        }
        assert!(kr.report.f2_roots.iter().all(|r| r.re == 0.0), "{kr}");
        assert!(kr.krein_signatures.iter().all(|&k| k == 1), "{kr}");
    }
}

/// The number of tilted steady motions in the plane spanned by e₁ and e₃ of a top J = diag(A, ·, C)
/// with U = mgl·γ₃ (C > A, mgl > 0), at p: the c = γ₃ ∈ (−1, 1) with
/// p²(C − A)c = mgl(A + (C − A)c²)² (`plane_fold`). With D = C − A only c > 0 can solve it, where
/// it reads φ(c) = p²D/mgl for φ(c) = (A + Dc²)²/c. φ → ∞ as c → 0, φ(1) = C², and
/// φ′(c) = (A + Dc²)(3Dc² − A)/c², so φ decreases to its minimum at c_m² = A/(3D) if c_m < 1 (then
/// two solutions for φ(c_m) < p²D/mgl < C², one above C², none below φ(c_m)); else φ decreases
/// on (0, 1] (one solution above C², none below).
fn plane_solutions(a: f64, c: f64, mgl: f64, p: f64) -> usize {
    assert!(c > a && mgl > 0.0);
    let d = c - a;
    let level = p * p * d / mgl;
    let phi = |z: f64| (a + d * z * z).powi(2) / z;
    let cm = (a / (3.0 * d)).sqrt();
    if level > c * c {
        1
    } else if cm < 1.0 && level > phi(cm) {
        2
    } else {
        0
    }
}

#[test]
fn counts_between_events_match_the_search_and_the_closed_form() {
    // The steady motions of a top J = diag(A, B, C), centre of mass on e₃, at p_ψ = p: the
    // critical points of U_r = ½p²/(γᵀJγ) + mgl·γ₃ on the sphere, ∇U_r = −p²Jγ/(γᵀJγ)² + mgl·e₃
    // parallel to γ. The components 1 and 2 give (−p²A/(γᵀJγ)² − μ)γ₁ = 0 and
    // (−p²B/(γᵀJγ)² − μ)γ₂ = 0: for A ≠ B, γ₁ = 0 or γ₂ = 0 — the poles ±e₃, and the tilted
    // motions in the planes (e₁, e₃) and (e₂, e₃), two mirror images per solution of
    // `plane_solutions`. For A = B (the Lagrange top) each solution is a circle, which the
    // diagram and the search count once: 2 + N(A) motions, and 2 + 2N(A) + 2N(B) for A ≠ B.
    let opts = ContinuationOptions {
        verify_counts: false, // the diagram is not repaired by its own count check
        ..ContinuationOptions::default()
    };
    for (what, (a, b, c, mgl), hi) in [
        ("Lagrange top", (1.0, 1.0, 1.25, 1.0), 5.0),
        ("asymmetric top", (1.0, 1.2, 1.5, 1.0), 4.0),
    ] {
        let top = asymmetric(a, b, c, mgl);
        let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, hi), &opts).unwrap();
        let mut cuts: Vec<f64> = d.events.iter().map(|e| e.s).chain([0.0, hi]).collect();
        cuts.sort_by(f64::total_cmp);
        cuts.dedup_by(|x, y| (*x - *y).abs() <= 1e-9);
        assert!(cuts.len() >= 4, "{what}: {:#?}", d.events);
        for w in cuts.windows(2) {
            let s = 0.5 * (w[0] + w[1]);
            let on_diagram: usize = d
                .branches
                .iter()
                .map(|br| {
                    br.points
                        .windows(2)
                        .filter(|q| (q[0].s < s) != (q[1].s < s))
                        .count()
                })
                .sum();
            let searched = steady_motions(&top, s).unwrap();
            let circles = searched.iter().filter(|m| !m.isolated).count();
            let closed = if a == b {
                2 + plane_solutions(a, c, mgl, s)
            } else {
                2 + 2 * plane_solutions(a, c, mgl, s) + 2 * plane_solutions(b, c, mgl, s)
            };
            println!(
                "{what}, p = {s:.6}: {on_diagram} on the diagram, {} found ({circles} circles), \
                 {closed} by the closed form",
                searched.len()
            );
            assert_eq!(
                (on_diagram, searched.len()),
                (closed, closed),
                "{what} at p = {s}: {:#?}",
                d.events
            );
        }
    }
}

#[test]
fn continue_branch_uses_the_search_options_for_its_first_point() {
    // The first point comes from Newton on the sphere from the guess, with the budget of
    // `opts.search`: one iteration (two in `near`) cannot reach the sleeping top from a guess
    // 0.6 rad away, the default budget does.
    let top = HeavyTop::lagrange(1.0, 1.25, 1.0);
    let guess = Vector3::new(0.5, 0.3, 0.8);
    let family = |p: f64| (top.clone(), p);
    let d = continue_branch(
        family,
        guess,
        3.0,
        (2.8, 3.2),
        &ContinuationOptions::default(),
    );
    assert!(d.is_ok(), "{d:?}");
    let mut opts = ContinuationOptions::default();
    opts.search.max_iterations = 1;
    let e = continue_branch(family, guess, 3.0, (2.8, 3.2), &opts);
    let Err(RouthError::AtParameter { s, source }) = e else {
        panic!("{e:?}");
    };
    assert_eq!(s, 3.0);
    assert!(
        matches!(*source, RouthError::NoConvergence { .. }),
        "{source:?}"
    );
}

/// Events are located in their own scale, not the range's: over p ∈ [0, 1000] the Routh
/// function at the far end (where branches are seeded) is ~10⁵ times larger than at the folds
/// near p ≈ 2, and a residual relative to it placed the folds ~1e−8 (up to 1.6e−7) off. The body
/// J = diag(1, 1.2, 2), mgl = 1 folds in both principal planes through e₃ (the closed form
/// [`plane_fold`] with A = 1 and with A = 1.2: p ≈ 1.7548 and 2.1273), each fold twice (mirror
/// images); every one within `2·event_tol·max(1, |s|)` on every range.
#[test]
fn folds_are_located_to_their_own_scale_on_wide_ranges() {
    let (a, b, c, mgl) = (1.0, 1.2, 2.0, 1.0);
    let top = asymmetric(a, b, c, mgl);
    let exact = [plane_fold(a, c, mgl).0, plane_fold(b, c, mgl).0];
    for hi in [5.0, 100.0, 1000.0] {
        let d = bifurcation_diagram(
            |p| (top.clone(), p),
            (0.0, hi),
            &ContinuationOptions::default(),
        )
        .unwrap();
        let folds = events(&d, EventKind::Fold);
        assert_eq!(folds.len(), 4, "[0, {hi}]: {:#?}", d.events);
        for f in folds {
            let near = if (f - exact[0]).abs() < (f - exact[1]).abs() {
                exact[0]
            } else {
                exact[1]
            };
            assert_located(f, near, &format!("[0, {hi}]: fold"));
        }
    }
}

/// Nothing is lost on a wide range: the events of a Lagrange top (A₁, C, mgl) over
/// p_ψ ∈ [0, 5], [0, 100] and [0, 1000] are the same, each at its closed form (Maievskii's
/// Hamiltonian–Hopf point p² = 4A₁mgl, the secular branch point p² = mglC²/(C − A₁), the fold of
/// circles [`plane_fold`] when C > 4A₁/3) within `2·event_tol·max(1, |s|)`, no other, and the
/// count checks agree. Before steps were bounded in the local scale of s, the first step from
/// p = 0 on [0, 1000] reached p = 10, past the Hamiltonian–Hopf point and the branch point
/// (0.1 apart for (1, 1.5, 0.7)), where the discriminant of f₂ starts at zero (its double root
/// at p = 0): every Hamiltonian–Hopf point on [0, 1000] was lost. A branch of circles seeded at
/// p = 250, whose eigenvalues were relative to the scale there, was taken to reach its axis
/// before its fold ((1, 3, 2)), or was traced twice ((1, 1.5, 0.7) on [0, 100]: the fold twice);
/// a step from p = 1 to exactly 2.5, the secular bound of (1, 1.25, 1), hid both of its events
/// on [0, 100]. Ten of the eighteen diagrams were wrong.
#[test]
fn wide_ranges_find_the_events_of_narrow_ones() {
    let mut wrong = Vec::new();
    for (a1, c, mgl) in [
        (1.0, 1.5, 0.7),
        (1.0, 3.0, 2.0),
        (1.0, 1.25, 1.0),
        (2.0, 2.5, 1.3),
        (1.0, 1.2, 1.0),
        (1.5, 4.0, 0.3),
    ] {
        let top = HeavyTop::lagrange(a1, c, mgl);
        let mut exact = vec![
            (EventKind::HamiltonianHopf, (4.0 * a1 * mgl).sqrt()),
            (EventKind::BranchPoint, (mgl * c * c / (c - a1)).sqrt()),
        ];
        if c > 4.0 * a1 / 3.0 {
            exact.push((EventKind::Fold, plane_fold(a1, c, mgl).0));
        }
        exact.sort_by(|x, y| x.1.total_cmp(&y.1));
        for hi in [5.0, 100.0, 1000.0] {
            let what = format!("A₁ = {a1}, C = {c}, mgl = {mgl} on [0, {hi}]");
            let d = bifurcation_diagram(
                |p| (top.clone(), p),
                (0.0, hi),
                &ContinuationOptions::default(),
            )
            .unwrap();
            let found: Vec<(EventKind, f64)> = d.events.iter().map(|e| (e.kind, e.s)).collect();
            let kinds = |v: &[(EventKind, f64)]| v.iter().map(|e| e.0).collect::<Vec<_>>();
            let located = found.len() == exact.len()
                && found
                    .iter()
                    .zip(&exact)
                    .all(|(f, e)| f.0 == e.0 && (f.1 - e.1).abs() <= 2e-10 * e.1.abs().max(1.0));
            println!("{what}: {found:?}");
            if !located || kinds(&found) != kinds(&exact) || !d.consistent() {
                wrong.push(format!(
                    "{what}: found {found:?}, closed forms {exact:?}, counts {}",
                    d.consistent()
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{wrong:#?}");
}
