//! Families that never fail where a researcher looks: seeds on branch points,
//! pitchfork tips, near-spherical circles, budgets that end with a partial result. Checked
//! against closed forms (the Kovalevskaya top, the asymmetric prolate top) and the global search.

use routh_core::steady::{steady_motion_search, SearchOptions};
use routh_core::{
    bifurcation_diagram, steady_motions, BifurcationDiagram, ContinuationOptions, EventKind,
    Matrix3, Vector3,
};
use test_models::HeavyTop;

fn top(a: f64, b: f64, c: f64, mgr: Vector3<f64>) -> HeavyTop {
    HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(a, b, c)),
        mgr,
    }
}

fn events(d: &BifurcationDiagram, kind: EventKind) -> Vec<f64> {
    d.events
        .iter()
        .filter(|e| e.kind == kind)
        .map(|e| e.s)
        .collect()
}

/// Whether some branch other than `not` has a point at `(s, gamma)` (to 1e−9 in s, 1e−6 in γ).
fn passes_through(d: &BifurcationDiagram, not: usize, s: f64, gamma: &Vector3<f64>) -> bool {
    d.branches.iter().enumerate().any(|(i, b)| {
        i != not
            && b.points.iter().any(|q| {
                (q.s - s).abs() <= 1e-9 * s.abs().max(1.0) && (q.steady.gamma - gamma).norm() < 1e-6
            })
    })
}

/// The Kovalevskaya top J = diag(2, 2, 1), U = γ₁ over p ∈ [0, 4], default options (seeds at
/// p = 0, 1, 2, 3, 4: p = 2 is exactly its pitchfork). U_r = ½p²/(2 − γ₃²) + γ₁ on the sphere:
/// its critical points have γ₂ = 0 (the γ₂ component of ∇U_r = λγ forces λ = 0, impossible, or
/// γ₂ = 0); they are γ = ±e₁ and the tilted motions x = γ₁ ∈ (0, 1) with (1 + x²)²/x = p², two
/// per root (γ₃ = ±√(1 − x²)). The function (1 + x²)²/x has its minimum 16√3/9 at x = 1/√3 (a
/// fold) and is 4 at x = 1 (the pitchfork on γ = e₁ at p = 2). Counts: 2 below the fold, 6
/// between the fold and p = 2, 4 above.
#[test]
fn kovalevskaya_top_closed_forms() {
    let k = top(2.0, 2.0, 1.0, Vector3::x());
    let d = bifurcation_diagram(|p| (k.clone(), p), (0.0, 4.0), &Default::default()).unwrap();
    assert_eq!(d.stop, None);
    let fold = (16.0 * 3f64.sqrt() / 9.0).sqrt();
    let folds = events(&d, EventKind::Fold);
    assert!(!folds.is_empty());
    for s in &folds {
        assert!(
            (s - fold).abs() <= 2e-10 * fold,
            "fold at {s}, closed form {fold}"
        );
    }
    let bps = events(&d, EventKind::BranchPoint);
    assert_eq!(bps.len(), 1, "{bps:?}");
    assert!((bps[0] - 2.0).abs() <= 4e-10, "{}", bps[0]);
    // Every point of every branch is a steady motion of the closed form.
    for b in &d.branches {
        assert!(b.isolated);
        for q in &b.points {
            let (g, p) = (q.steady.gamma, q.s);
            assert!(g.y.abs() < 1e-9, "γ₂ = {} at p = {p}", g.y);
            if (g.x.abs() - 1.0).abs() > 1e-9 {
                let x = g.x;
                assert!(x > 0.0);
                let r = (1.0 + x * x).powi(2) / x - p * p;
                assert!(
                    r.abs() < 1e-8 * (1.0 + p * p),
                    "(1 + x²)²/x − p² = {r} at p = {p}"
                );
            }
        }
    }
    // The tilted branch passes through the pitchfork point (p, γ) = (2, e₁).
    let e = d
        .events
        .iter()
        .find(|e| e.kind == EventKind::BranchPoint)
        .unwrap();
    assert!((e.gamma - Vector3::x()).norm() < 1e-9);
    assert!(passes_through(&d, e.branch, e.s, &e.gamma));
    // Counts from the polylines: at the closed-form values and next to the events.
    for (s, n) in [
        (0.5, 2),
        (fold - 1e-5, 2),
        (fold + 1e-5, 6),
        (1.9, 6),
        (2.0 - 1e-5, 6),
        (2.0 + 1e-5, 4),
        (3.5, 4),
    ] {
        assert_eq!(d.count_at(s), n, "count_at({s})");
    }
    for s in [0.5, 1.9, 3.5] {
        assert_eq!(
            d.count_at(s),
            steady_motions(&k, s).unwrap().len(),
            "at {s}"
        );
    }
}

/// The asymmetric prolate top J = diag(2, 2.2, 1), U = γ₃: the hanging top γ = −e₃ has its
/// pitchforks where the curvature of U_r = ½p²/(γᵀJγ) + γ₃ at −e₃ vanishes along e₁ and e₂,
/// p² = C²/(A − C) = 1 and p² = C²/(B − C) = 1/1.2; each starts a pair of tilted motions in the
/// plane of its axis. Counts: 2 below 1/√1.2, 4 up to 1, 6 above.
#[test]
fn prolate_top_pitchfork_tips() {
    let t = top(2.0, 2.2, 1.0, Vector3::z());
    let tips = [(1.0f64 / 1.2).sqrt(), 1.0];
    let d = bifurcation_diagram(
        |p| (t.clone(), p),
        (0.2, 5.0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    assert_eq!(d.stop, None);
    let bps = events(&d, EventKind::BranchPoint);
    assert_eq!(bps.len(), 2, "{bps:?}");
    for (s, exact) in bps.iter().zip(tips) {
        assert!((s - exact).abs() <= 2e-10, "{s} vs {exact}");
    }
    // Both arms of each pitchfork are joined at the located tip.
    for e in d.events.iter().filter(|e| e.kind == EventKind::BranchPoint) {
        assert!((e.gamma + Vector3::z()).norm() < 1e-9);
        assert!(passes_through(&d, e.branch, e.s, &e.gamma), "{e}");
    }
    let closed = |s: f64| 2 + tips.iter().filter(|t| s > **t).count() * 2;
    for s in [0.5, 0.9, 0.95, 1.2, 4.0] {
        assert_eq!(d.count_at(s), closed(s), "count_at({s})");
        assert_eq!(
            steady_motions(&t, s).unwrap().len(),
            closed(s),
            "search at {s}"
        );
    }
    for tip in tips {
        for ds in [-2e-6, 2e-6] {
            let s = tip + ds;
            assert_eq!(
                d.count_at(s),
                closed(s),
                "count_at({s}) next to the tip {tip}"
            );
        }
    }
    // A range with a seed on the tip p = 1.
    let d = bifurcation_diagram(
        |p| (t.clone(), p),
        (0.5, 1.5),
        &ContinuationOptions::default(),
    )
    .unwrap();
    assert_eq!(d.stop, None);
    for s in [0.6, 0.95, 1.3] {
        assert_eq!(d.count_at(s), closed(s), "count_at({s})");
    }
}

/// Symmetric bodies near a sphere over ranges around their secular bound (where a circle of
/// tilted steady motions is born at a pole): no failure for any number of seeds, and counts that
/// agree with the global search.
#[test]
fn near_spherical_symmetric_tops() {
    for (a, c, range) in [
        (2.1823, 2.1481, (11.53, 11.79)),
        (0.7509, 2.0895, (1.583, 1.969)),
        (1.0, 1.01, (9.0, 11.0)),
        (1.0, 0.99, (9.0, 11.0)),
    ] {
        let t = top(a, a, c, Vector3::z());
        for seeds in [2, 5, 6, 9] {
            let opts = ContinuationOptions {
                seeds,
                ..Default::default()
            };
            let d = bifurcation_diagram(|p| (t.clone(), p), range, &opts)
                .unwrap_or_else(|e| panic!("({a}, {c}) over {range:?}, {seeds} seeds: {e}"));
            assert_eq!(d.stop, None);
            for k in 1..4 {
                let s = range.0 + (range.1 - range.0) * (k as f64 / 4.0 + 0.013);
                assert_eq!(
                    d.count_at(s),
                    steady_motions(&t, s).unwrap().len(),
                    "({a}, {c}) at {s}, {seeds} seeds"
                );
            }
        }
    }
}

/// Symmetric tops on which the sweep (`tests/families_sweep.rs`) once found a runaway budget on a
/// branch of circles next to its axis, or a circle counted twice: every diagram is complete and
/// its counts agree with the global search.
#[test]
fn symmetric_tops_found_by_the_sweep() {
    for (a, c, mgl, range) in [
        (
            1.7896079667855886,
            0.9244872621694179,
            0.850263488186846,
            (0.5704683519035405, 1.0318632260119305),
        ),
        (
            1.259035798095694,
            1.8105563607740174,
            1.1113181513267394,
            (2.1706470674081837, 3.929929007332265),
        ),
        (
            0.5041867794522943,
            2.1308790236942428,
            1.6544642018095397,
            (2.0011613470990155, 2.296822502139793),
        ),
        (
            0.9088267332641699,
            2.0775525847747875,
            1.0713451908236011,
            (1.7845268202706923, 2.057314232611689),
        ),
        (
            1.419812344497365,
            1.417938475142442,
            0.7299629958083884,
            (16.633506387996693, 39.338148894777916),
        ),
    ] {
        let t = top(a, a, c, Vector3::new(0.0, 0.0, mgl));
        let d = bifurcation_diagram(|p| (t.clone(), p), range, &ContinuationOptions::default())
            .unwrap_or_else(|e| panic!("({a}, {c}, {mgl}) over {range:?}: {e}"));
        assert_eq!(d.stop, None, "({a}, {c}, {mgl}) over {range:?}");
        for k in 1..6 {
            let s = range.0 + (range.1 - range.0) * (k as f64 / 6.0 + 0.011);
            let found = steady_motion_search(&t, s, &SearchOptions::default()).unwrap();
            if found.consistent {
                assert_eq!(
                    d.count_at(s),
                    found.motions.len(),
                    "({a}, {c}, {mgl}) at {s}"
                );
            }
        }
    }
}

/// The pitchfork point of the Kovalevskaya top at p = 2, γ = e₁ (where (1 + x²)²/x = 4 has its
/// double root x = 1: U_r is quartic along e₃ there): the global search reports it once,
/// isolated, at its true place to the accuracy a cubic gradient allows (≈ ε^{1/3}; 1e−6 asked),
/// with the Morse self-check reconciled. The other motions: −e₁ and the tilted pair of the
/// simple root x ≈ 0.2956.
#[test]
fn kovalevskaya_pitchfork_point_is_isolated() {
    let k = top(2.0, 2.0, 1.0, Vector3::x());
    let found = steady_motion_search(&k, 2.0, &SearchOptions::default()).unwrap();
    for m in &found.motions {
        println!("{m}");
    }
    assert!(found.consistent, "χ = {:?}", found.euler_characteristic);
    assert_eq!(found.motions.len(), 4);
    assert!(found.motions.iter().all(|m| m.isolated));
    let e1 = found
        .motions
        .iter()
        .map(|m| (m.gamma - Vector3::x()).norm())
        .fold(f64::INFINITY, f64::min);
    println!("distance of the pitchfork point from e₁: {e1:.2e}");
    assert!(e1 < 1e-6);
    for m in found.motions.iter().filter(|m| m.gamma.z.abs() > 0.5) {
        let x = m.gamma.x;
        assert!(((1.0 + x * x).powi(2) / x - 4.0).abs() < 1e-8, "{m}");
    }
}
