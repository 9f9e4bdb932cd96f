//! The predictor–corrector on curves with closed forms: the unit circle (the angle advanced by a
//! pseudo-arclength step `h` is `asin h`) and the fold `x = y²` (natural-parameter stepping in `x`
//! must stall at the fold, pseudo-arclength must pass it).

use super::*;
use nalgebra::{Matrix2, Vector2};
use std::convert::Infallible;

/// Newton on `[f(w), a·(w − w_pred)]` (or `w_k` fixed) in ℝ², `f` with gradient `df`.
fn newton2(
    p: &Prediction<2>,
    f: impl Fn(&Vector2<f64>) -> f64,
    df: impl Fn(&Vector2<f64>) -> Vector2<f64>,
) -> Option<Corrected<2, ()>> {
    let a = p.row?.normal;
    let mut w = p.point;
    for it in 0..30 {
        let r = Vector2::new(f(&w), a.dot(&(w - p.point)));
        if r.norm() <= 1e-14 {
            return Some(Corrected {
                point: w,
                iterations: it,
                value: (),
            });
        }
        let g = df(&w);
        let j = Matrix2::new(g.x, g.y, a.x, a.y);
        w -= j.try_inverse()? * r;
        if !w.iter().all(|v| v.is_finite()) {
            return None;
        }
    }
    None
}

fn circle(p: &Prediction<2>) -> Result<Option<Corrected<2, ()>>, Infallible> {
    Ok(newton2(p, |w| w.norm_squared() - 1.0, |w| 2.0 * w))
}

fn fold(p: &Prediction<2>) -> Result<Option<Corrected<2, ()>>, Infallible> {
    Ok(newton2(
        p,
        |w| w.x - w.y * w.y,
        |w| Vector2::new(1.0, -2.0 * w.y),
    ))
}

/// The unit tangent of `x = y²` at `w`, along `prev`.
fn fold_tangent(w: &Vector2<f64>, prev: &Vector2<f64>) -> Vector2<f64> {
    let t = Vector2::new(2.0 * w.y, 1.0).normalize();
    if t.dot(prev) < 0.0 {
        -t
    } else {
        t
    }
}

fn run<T>(r: Result<T, Infallible>) -> T {
    match r {
        Ok(v) => v,
        Err(e) => match e {},
    }
}

/// One step from `(w, t)` without a step limit, the point taken as corrected (no tangent) and
/// every step accepted.
fn plain_step(
    path: &mut Path<2>,
    w: &Vector2<f64>,
    t: &Vector2<f64>,
    correct: impl FnMut(&Prediction<2>) -> Result<Option<Corrected<2, ()>>, Infallible>,
) -> Outcome<2, ()> {
    run(path.step(
        w,
        t,
        f64::INFINITY,
        correct,
        |c| Ok(Some(c.bare())),
        |_, _| Check::Accept,
    ))
}

#[test]
fn circle_steps_advance_by_asin_h_and_close() {
    let mut path = Path::<2>::new(PathOptions::diagram(1e-7, 0.2), 0.01);
    let (mut w, mut t) = (Vector2::new(1.0, 0.0), Vector2::new(0.0, 1.0));
    let mut angle = 0.0;
    let mut steps = 0;
    while angle < 2.0 * std::f64::consts::PI {
        let tangent = |c: Corrected<2, ()>| {
            let tn = Vector2::new(-c.point.y, c.point.x);
            Ok(Some(Point {
                tangent: Some(tn),
                ..c.bare()
            }))
        };
        let out = run(path.step(&w, &t, f64::INFINITY, circle, tangent, |_, _| Check::Accept));
        let Outcome::Accepted { point, h } = out else {
            panic!("the circle is smooth: {out:?}");
        };
        assert!((point.point.norm() - 1.0).abs() < 1e-13);
        // Independent of the engine: the angle between the points, against the closed form.
        let turned = w.perp(&point.point).atan2(w.dot(&point.point));
        assert!((turned - h.asin()).abs() < 1e-12, "{turned} vs asin {h}");
        angle += turned;
        (w, t) = (point.point, point.tangent.unwrap());
        steps += 1;
        assert!(path.h() <= 0.2 && steps < 1000);
    }
    // Closed: back at the start after a full turn.
    assert!(
        (w - Vector2::new(1.0, 0.0)).norm() <= 0.2,
        "{w} after {steps} steps"
    );
}

#[test]
fn natural_parameter_stalls_at_the_fold() {
    let mut path = Path::<2>::new(PathOptions::grid_segment(0), 0.1);
    let mut w = Vector2::new(1.0, 1.0);
    let mut t = -fold_tangent(&w, &Vector2::new(1.0, 0.0));
    let failure = loop {
        let out = plain_step(&mut path, &w, &t, fold);
        match out {
            Outcome::Accepted { point, .. } => {
                assert!((point.point.x - point.point.y.powi(2)).abs() < 1e-13);
                t = fold_tangent(&point.point, &t);
                w = point.point;
            }
            Outcome::Stalled(f) => break f,
            o => panic!("{o:?}"),
        }
    };
    // Stalled on the upper half, within a few minimum steps of the fold x = 0.
    assert_eq!(failure, Failure::Corrector);
    assert!(w.y > 0.0 && w.x >= -1e-15 && w.x < 1e-4, "{w}");
}

#[test]
fn pseudo_arclength_passes_the_fold() {
    let mut path = Path::<2>::new(PathOptions::diagram(1e-7, 0.05), 0.01);
    let mut w = Vector2::new(1.0, 1.0);
    let mut t = -fold_tangent(&w, &Vector2::new(1.0, 0.0));
    let mut min_x = f64::INFINITY;
    while w.y > -1.0 {
        let tangent = |c: Corrected<2, ()>| {
            let tn = fold_tangent(&c.point, &t);
            Ok(Some(Point {
                tangent: Some(tn),
                ..c.bare()
            }))
        };
        let out = run(path.step(&w, &t, f64::INFINITY, fold, tangent, |_, _| Check::Accept));
        let Outcome::Accepted { point, .. } = out else {
            panic!("the fold is a regular point of the curve: {out:?}");
        };
        assert!((point.point.x - point.point.y.powi(2)).abs() < 1e-13);
        assert!(
            point.point.y < w.y,
            "y decreases monotonically along the curve"
        );
        min_x = min_x.min(point.point.x);
        (w, t) = (point.point, point.tangent.unwrap());
        assert!(path.attempts() < 1000);
    }
    // Through the fold (x = 0 at y = 0) to the lower half.
    assert!(min_x < 1e-3 && w.y <= -1.0);
}

#[test]
fn jumps_turns_checks_and_budget() {
    let (w, t) = (Vector2::new(1.0, 0.0), Vector2::new(0.0, 1.0));
    let opts = PathOptions::diagram(1e-3, 0.2);
    // A corrector that jumps to the antipode: rejected by distance down to h_min.
    let mut path = Path::<2>::new(opts, 0.1);
    let jump = |_: &Prediction<2>| {
        Ok::<_, Infallible>(Some(Corrected {
            point: -w,
            iterations: 1,
            value: (),
        }))
    };
    let out = plain_step(&mut path, &w, &t, jump);
    assert!(matches!(out, Outcome::Stalled(Failure::Moved)));
    // 0.1, 0.05, …, 0.0015625 ≥ 1e−3: seven attempts.
    assert_eq!(path.attempts(), 7);
    // A tangent that reverses: rejected until the step is below 4·h_min, where it is waived.
    let mut path = Path::<2>::new(opts, 0.1);
    let reverse = |c: Corrected<2, ()>| {
        Ok(Some(Point {
            tangent: Some(-t),
            ..c.bare()
        }))
    };
    let out = run(path.step(&w, &t, f64::INFINITY, circle, reverse, |_, _| Check::Accept));
    let Outcome::Accepted { h, .. } = out else {
        panic!("{out:?}");
    };
    assert!(h <= 4e-3 && h > 2e-3, "{h}");
    // The caller's check: shorten twice, then stop.
    let opts = PathOptions {
        min_cos: f64::NEG_INFINITY,
        ..opts
    };
    let mut path = Path::<2>::new(opts, 0.1);
    let mut calls = 0;
    let out = run(path.step(
        &w,
        &t,
        f64::INFINITY,
        circle,
        |c| Ok(Some(c.bare())),
        |_, h| {
            calls += 1;
            if calls < 3 {
                Check::Shorten
            } else {
                assert_eq!(h, 0.025);
                Check::Stop
            }
        },
    ));
    assert!(matches!(out, Outcome::Stopped(_)));
    // The budget counts every attempt; the limit cuts the step.
    let mut path = Path::<2>::new(opts, 0.1).with_budget(1);
    let out = run(path.step(
        &w,
        &t,
        0.03,
        circle,
        |c| Ok(Some(c.bare())),
        |_, h| {
            assert_eq!(h, 0.03);
            Check::Accept
        },
    ));
    assert!(matches!(out, Outcome::Accepted { .. }));
    let out = plain_step(&mut path, &w, &t, circle);
    assert!(matches!(out, Outcome::Exhausted));
    // Easy convergences grow the step by 1.5 up to the cap.
    let mut path = Path::<2>::new(opts, 0.1);
    let easy = |p: &Prediction<2>| {
        Ok::<_, Infallible>(Some(Corrected {
            point: p.point.normalize(),
            iterations: 0,
            value: (),
        }))
    };
    for expected in [0.15, 0.2, 0.2] {
        let out = plain_step(&mut path, &w, &t, easy);
        assert!(matches!(out, Outcome::Accepted { .. }));
        assert!((path.h() - expected).abs() < 1e-15, "{}", path.h());
    }
}

#[test]
fn sphere_retraction_normalises_gamma_only() {
    let w = sphere_head(nalgebra::Vector4::new(0.0, 3.0, 4.0, 7.0));
    assert_eq!(w, nalgebra::Vector4::new(0.0, 0.6, 0.8, 7.0));
}
