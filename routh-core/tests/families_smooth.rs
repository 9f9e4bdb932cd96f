//! Smooth energy–momentum curves: after continuation the
//! branches get corrected points wherever their curve `(s, E)` turns by more than
//! [`ContinuationOptions::em_turn_degrees`] in plot-normalised coordinates. Checked on the
//! Lagrange top against the closed forms of its energy along the sleeping, hanging and tilted
//! branches, between the samples of the polylines.

use routh_core::{bifurcation_diagram, BifurcationDiagram, ContinuationOptions};
use test_models::Gyrostat;

const A: f64 = 1.0;
const C: f64 = 1.25;
const MGL: f64 = 1.0;

/// The energy `E = p²/(2n) + mgl·z`, `n = A + (C − A)z²`, of the steady motion with `γ₃ = z`.
fn energy(p: f64, z: f64) -> f64 {
    p * p / (2.0 * (A + (C - A) * z * z)) + MGL * z
}

/// `γ₃` on the circles of tilted precessions at `p`: the root in `(0, 1]` of
/// `p² = mgl·n²/((C − A)z)`, decreasing in `z` for these values (bisection).
fn tilted_z(p: f64) -> f64 {
    let p2 = |z: f64| MGL * (A + (C - A) * z * z).powi(2) / ((C - A) * z);
    let (mut lo, mut hi) = (1e-9, 1.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if p2(mid) > p * p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The closed-form energy along a branch of the Lagrange top: sleeping (`z = 1`), hanging
/// (`z = −1`) or tilted.
fn closed_form(kind: &str, p: f64) -> f64 {
    match kind {
        "sleeping" => energy(p, 1.0),
        "hanging" => energy(p, -1.0),
        _ => energy(p, tilted_z(p)),
    }
}

fn branch_kind(b: &routh_core::Branch) -> &'static str {
    if !b.isolated {
        "tilted"
    } else if b.points[0].steady.gamma.z > 0.0 {
        "sleeping"
    } else {
        "hanging"
    }
}

/// Largest turning angle (degrees) between successive chords of the branches' `(s, E)` curves,
/// `s` over the range and `E` over its extent, at nodes that are not turning points in `s` and
/// whose chords are longer than `min_chord`.
fn max_turn(d: &BifurcationDiagram, range: (f64, f64), min_chord: f64) -> f64 {
    let es = d
        .branches
        .iter()
        .flat_map(|b| b.points.iter().map(|q| q.steady.energy));
    let (lo, hi) = es.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| {
        (l.min(e), h.max(e))
    });
    let (xs, ys) = (range.1 - range.0, hi - lo);
    let mut worst: f64 = 0.0;
    for b in &d.branches {
        let q: Vec<(f64, f64)> = b
            .points
            .iter()
            .map(|p| (p.s / xs, p.steady.energy / ys))
            .collect();
        for k in 1..q.len().saturating_sub(1) {
            let u = (q[k].0 - q[k - 1].0, q[k].1 - q[k - 1].1);
            let v = (q[k + 1].0 - q[k].0, q[k + 1].1 - q[k].1);
            if u.0 * v.0 <= 0.0 || u.0.hypot(u.1) <= min_chord || v.0.hypot(v.1) <= min_chord {
                continue;
            }
            let a = (u.0 * v.1 - u.1 * v.0).abs().atan2(u.0 * v.0 + u.1 * v.1);
            worst = worst.max(a.to_degrees());
        }
    }
    worst
}

/// Largest error of the polylines' linear interpolation of `E` against the closed form, at a
/// quarter, half and three quarters of every segment, relative to the extent of `E` on the
/// diagram (the height of the figure: `1e−3` is half a pixel of a 600-pixel figure); and the
/// largest error of the points themselves, relative to `max(1, |E|)`.
fn interpolation_error(d: &BifurcationDiagram) -> (f64, f64) {
    let es = d
        .branches
        .iter()
        .flat_map(|b| b.points.iter().map(|q| q.steady.energy));
    let (lo, hi) = es.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| {
        (l.min(e), h.max(e))
    });
    let (mut between, mut at): (f64, f64) = (0.0, 0.0);
    for b in &d.branches {
        let kind = branch_kind(b);
        for q in &b.points {
            let e = closed_form(kind, q.s);
            at = at.max((q.steady.energy - e).abs() / e.abs().max(1.0));
        }
        for w in b.points.windows(2) {
            for t in [0.25, 0.5, 0.75] {
                let s = w[0].s + t * (w[1].s - w[0].s);
                let e_line = w[0].steady.energy + t * (w[1].steady.energy - w[0].steady.energy);
                let e = closed_form(kind, s);
                between = between.max((e_line - e).abs() / (hi - lo));
            }
        }
    }
    (between, at)
}

#[test]
fn energy_curves_of_the_lagrange_top_are_smooth_and_match_the_closed_forms() {
    let top = Gyrostat::lagrange_top(A, C, MGL);
    let range = (0.0, 5.0);
    let family = |p: f64| (top.clone(), p);
    let smooth = bifurcation_diagram(family, range, &ContinuationOptions::default()).unwrap();
    let raw_opts = ContinuationOptions {
        em_turn_degrees: 0.0,
        ..Default::default()
    };
    let raw = bifurcation_diagram(family, range, &raw_opts).unwrap();
    assert_eq!(smooth.branches.len(), 3);
    let kinds: Vec<&str> = smooth.branches.iter().map(branch_kind).collect();
    for k in ["sleeping", "hanging", "tilted"] {
        assert!(kinds.contains(&k), "{kinds:?}");
    }
    let (between, at) = interpolation_error(&smooth);
    let (raw_between, _) = interpolation_error(&raw);
    let (turn, raw_turn) = (max_turn(&smooth, range, 2e-4), max_turn(&raw, range, 2e-4));
    let count = |d: &BifurcationDiagram| d.branches.iter().map(|b| b.points.len()).sum::<usize>();
    println!(
        "smooth: {} points, max turn {turn:.2}°, interpolation error {between:.2e} (points \
         {at:.1e}); raw: {} points, max turn {raw_turn:.2}°, interpolation error {raw_between:.2e}",
        count(&smooth),
        count(&raw)
    );
    assert!(at <= 1e-9, "points off the closed form by {at:e}");
    assert!(between <= 1e-3, "interpolation error {between:e}");
    // The bound of the option (3°), with a margin for the normalisation: the refinement scales E
    // by its extent before the points it adds.
    assert!(turn <= 3.2, "turning angle {turn}°");
    // Without the refinement the curves are visibly polygonal: the test can tell.
    assert!(raw_turn > 3.2, "raw turning angle {raw_turn}°");
    // Refinement adds points but no event, and the counts are unchanged.
    assert_eq!(smooth.events, raw.events);
    for s in [0.5, 1.7, 2.2, 3.0, 4.5] {
        assert_eq!(smooth.count_at(s), raw.count_at(s), "at s = {s}");
    }
}

#[test]
fn refinement_is_refused_with_a_negative_angle() {
    let top = Gyrostat::lagrange_top(A, C, MGL);
    let opts = ContinuationOptions {
        em_turn_degrees: -1.0,
        ..Default::default()
    };
    let err = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &opts).unwrap_err();
    assert!(err.to_string().contains("em_turn_degrees"), "{err}");
}

/// The cost of the refinement: the best of 5 diagrams of the Lagrange top over `[0, 5]` (default
/// options) with and without it, and of a heavy asymmetric top with pitchforks over `[1, 4]`.
#[test]
#[ignore = "timing: run with -- --ignored --nocapture"]
fn cost_of_the_refinement() {
    use routh_core::{Matrix3, Vector3};
    use test_models::HeavyTop;
    let lagrange = Gyrostat::lagrange_top(A, C, MGL);
    let asym = HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(2.0, 2.3, 1.2)),
        mgr: Vector3::new(0.0, 0.0, 1.0),
    };
    let best = |f: &dyn Fn() -> usize| {
        let mut t = f64::INFINITY;
        let mut n = 0;
        for _ in 0..5 {
            let t0 = std::time::Instant::now();
            n = f();
            t = t.min(t0.elapsed().as_secs_f64());
        }
        (t * 1e3, n)
    };
    let points = |d: BifurcationDiagram| d.branches.iter().map(|b| b.points.len()).sum::<usize>();
    for deg in [0.0, 3.0] {
        let opts = ContinuationOptions {
            em_turn_degrees: deg,
            ..Default::default()
        };
        let (t1, n1) = best(&|| {
            points(bifurcation_diagram(|p| (lagrange.clone(), p), (0.0, 5.0), &opts).unwrap())
        });
        let (t2, n2) = best(&|| {
            points(bifurcation_diagram(|p| (asym.clone(), p), (1.0, 4.0), &opts).unwrap())
        });
        println!(
            "em_turn_degrees = {deg}: Lagrange top {t1:.1} ms ({n1} points), asymmetric top \
             {t2:.1} ms ({n2} points)"
        );
    }
}
