//! The zero test (docs/method.md §5) is relative to the local tangential scale, so neither the
//! units of the model nor a constant added to the potential on the sphere changes a verdict, a
//! count or an event of the search and of the bifurcation diagram.
//!
//! The two transformations, derived from `L = ½ωᵀJω + a(γ)·ω − U(γ)` and the amended potential
//! `U_r(γ) = ½(p_ψ − a·γ)²/(γᵀJγ) + U(γ)` (34), (40):
//!
//! - **Units of the Lagrangian.** `J → cJ`, `a → c·a`, `U → cU` multiplies `L` by `c`; the
//!   cyclic momentum (9) `p_ψ = (Jω + a, γ)` becomes `c·p_ψ` for the same motion. Then
//!   `U_r → ½c²(p_ψ − a·γ)²/(c γᵀJγ) + cU = c·U_r`, `R(0, γ, c p_ψ) → c·R`: the same critical
//!   points, their restricted second variations `K` (62)–(63) multiplied by `c`, the same
//!   verdicts. A family `s ↦ (model, p_ψ)` becomes `s ↦ (c·model, c·p_ψ)` with the same events at
//!   the same `s`. Checked for `c = 1e−3` and `1e3`.
//! - **A constant on the sphere.** `U → U + k|γ|²` changes nothing on `|γ| = 1`; it adds `2kγ`
//!   (radial) to `∂U/∂γ` and `2kE` to `∂²U/∂γ²`, which cancel exactly in the tangential gradient
//!   and in `K = Pᵀ(μE − ∂²R/∂γ²)P`. Checked for `k` a million times the size of the model: a
//!   zero test relative to the raw derivatives `max(|∇U_r|, ‖∂²U_r/∂γ²‖)` (the diagram's former
//!   `|eig| ≤ 1e−6` on `K` divided by that) took every steady motion for a degenerate one there.

use routh_core::steady::{steady_motion_search, SearchOptions};
use routh_core::{
    bifurcation_diagram, classify, BifurcationDiagram, ContinuationOptions, EventKind, Matrix3,
    Stability, Vector3,
};
use test_models::{Gyrostat, Potential, PotentialBody};

/// `(kind, s, before, after)` of every event, sorted by `s`.
fn event_list(d: &BifurcationDiagram) -> Vec<(EventKind, f64, Stability, Stability)> {
    let mut v: Vec<_> = d
        .events
        .iter()
        .map(|e| (e.kind, e.s, e.before, e.after))
        .collect();
    v.sort_by(|a, b| a.1.total_cmp(&b.1));
    v
}

/// The same events (kinds, verdicts, `s` to `1e−8` relative to the range) and the same number of
/// branches of each kind.
fn assert_same_diagram(what: &str, base: &BifurcationDiagram, other: &BifurcationDiagram) {
    let (a, b) = (event_list(base), event_list(other));
    assert_eq!(
        a.len(),
        b.len(),
        "{what}: events\n{:#?}\nvs\n{:#?}",
        base.events,
        other.events
    );
    // Matched one to one (mirror images share their `s`, in either order).
    let mut free: Vec<_> = b.clone();
    for x in &a {
        let hit = free.iter().position(|y| {
            (x.0, x.2, x.3) == (y.0, y.2, y.3) && (x.1 - y.1).abs() <= 1e-8 * x.1.abs().max(1.0)
        });
        let Some(i) = hit else {
            panic!("{what}: no match for {x:?} in {b:#?}");
        };
        free.swap_remove(i);
    }
    let kinds = |d: &BifurcationDiagram| {
        let circles = d.branches.iter().filter(|b| !b.isolated).count();
        (d.branches.len() - circles, circles)
    };
    assert_eq!(kinds(base), kinds(other), "{what}: branches");
    assert_eq!(base.consistent(), other.consistent(), "{what}");
}

/// A Lagrange gyrostat (rotor along the axis), every part multiplied by `c`.
fn lagrange_gyrostat(c: f64) -> Gyrostat {
    let mut g = Gyrostat::lagrange_top(1.0, 1.5, 0.7);
    g.inertia *= c;
    g.rotor = Vector3::new(0.0, 0.0, 0.3 * c);
    g.g *= c;
    g
}

#[test]
fn scaling_the_lagrangian_changes_no_event() {
    let opts = ContinuationOptions::default();
    let base = bifurcation_diagram(|p| (lagrange_gyrostat(1.0), p), (0.0, 4.0), &opts).unwrap();
    assert!(base.consistent(), "{:#?}", base.checks);
    let kinds: Vec<_> = base.events.iter().map(|e| e.kind).collect();
    for k in [
        EventKind::HamiltonianHopf,
        EventKind::BranchPoint,
        EventKind::Fold,
    ] {
        assert!(
            kinds.contains(&k),
            "the base diagram has a {k:?}: {kinds:?}"
        );
    }
    for c in [1e-3, 1e3] {
        let d = bifurcation_diagram(|p| (lagrange_gyrostat(c), c * p), (0.0, 4.0), &opts).unwrap();
        assert_same_diagram(&format!("c = {c}"), &base, &d);
    }
}

/// `U = mgl·γ₃ + k|γ|²` (asymmetric body).
fn shifted(k: f64) -> Potential {
    Box::new(move |g: &Vector3<f64>| {
        (
            0.8 * g.z + k * g.norm_squared(),
            Vector3::new(0.0, 0.0, 0.8) + 2.0 * k * g,
            Matrix3::from_diagonal_element(2.0 * k),
        )
    })
}

fn shifted_top(k: f64) -> PotentialBody {
    PotentialBody::diag(1.0, 1.2, 1.5, shifted(k))
}

#[test]
fn a_constant_on_the_sphere_changes_no_event() {
    let opts = ContinuationOptions::default();
    let base = bifurcation_diagram(|p| (shifted_top(0.0), p), (0.0, 4.0), &opts).unwrap();
    assert!(base.consistent(), "{:#?}", base.checks);
    let bp = base
        .events
        .iter()
        .filter(|e| e.kind == EventKind::BranchPoint)
        .count();
    assert_eq!(bp, 2, "{:#?}", base.events);
    for k in [1e6, -1e6] {
        let d = bifurcation_diagram(|p| (shifted_top(k), p), (0.0, 4.0), &opts).unwrap();
        assert_same_diagram(&format!("k = {k}"), &base, &d);
    }
}

#[test]
fn scaling_the_lagrangian_changes_no_count_or_verdict() {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(21);
    let mut seen = 0;
    for _ in 0..3 {
        let body = Gyrostat::random(&mut rng);
        for p in [0.5, 4.0, 12.0] {
            let base = steady_motion_search(&body, p, &SearchOptions::default()).unwrap();
            let verdicts = |m: &Gyrostat, r: &routh_core::steady::SearchResult| {
                let mut v: Vec<_> = r
                    .motions
                    .iter()
                    .map(|s| format!("{:?}", classify(m, s).unwrap().verdict))
                    .collect();
                v.sort();
                v
            };
            let want = verdicts(&body, &base);
            for c in [1e-3, 1e3] {
                let scaled = Gyrostat {
                    inertia: c * body.inertia,
                    rotor: c * body.rotor,
                    coupling: c * body.coupling,
                    g: c * body.g,
                    ..body.clone()
                };
                let r = steady_motion_search(&scaled, c * p, &SearchOptions::default()).unwrap();
                let what = format!("p = {p}, c = {c}");
                assert_eq!(r.motions.len(), base.motions.len(), "{what}");
                assert_eq!(r.consistent, base.consistent, "{what}");
                assert_eq!(r.euler_characteristic, base.euler_characteristic, "{what}");
                assert_eq!(verdicts(&scaled, &r), want, "{what}");
                seen += r.motions.len();
            }
        }
    }
    assert!(seen >= 12, "{seen}");
}
