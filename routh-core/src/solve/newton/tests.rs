//! Tests of the Newton corrector against closed forms.

use super::*;
use std::convert::Infallible;

/// A point of a fixed-chart test problem: the unknowns and the equations there.
type At = (Vector4<f64>, Linearised);

// A test helper: the iterate is returned by value, as `solve` returns it.
#[allow(clippy::result_large_err)]
fn run(
    newton: &Newton,
    w0: Vector4<f64>,
    rows: &[LinearRow<4>],
    f: impl Fn(&Vector4<f64>) -> Linearised,
) -> Result<Solved<At>, Stop<At>> {
    let start = (w0, f(&w0));
    let r: Result<_, Infallible> = newton.solve(
        w0,
        rows,
        start,
        |p: &At| p.1,
        |_, w, _| Ok(Some((*w, f(w)))),
        |_| false,
    );
    match r {
        Ok(x) => x,
        Err(e) => match e {},
    }
}

/// The unit circle `x² + y² = 1` cut by the line `x − y = 0.2` (a linear row), Newton with
/// a 1×2 residual: the closed-form intersection `x = (0.2 + √1.96)/2`.
#[test]
fn circle_and_line_meet_at_the_closed_form_point() {
    let f = |w: &Vector4<f64>| {
        let mut j = Matrix4::zeros();
        j[(0, 0)] = 2.0 * w[0];
        j[(0, 1)] = 2.0 * w[1];
        Linearised::new(
            Vector4::new(w[0] * w[0] + w[1] * w[1] - 1.0, 0.0, 0.0, 0.0),
            j,
            0.0,
        )
    };
    let row = LinearRow::new(Vector4::new(1.0, -1.0, 0.0, 0.0), 0.2);
    let s = run(
        &Newton::continuation(1e-14),
        Vector4::new(1.0, 0.5, 0.0, 0.0),
        &[row],
        f,
    )
    .expect("converges");
    let x = 0.5 * (0.2 + 1.96f64.sqrt());
    assert!(
        (s.w[0] - x).abs() < 1e-13 && (s.w[1] - (x - 0.2)).abs() < 1e-13,
        "{}",
        s.w
    );
    assert!(s.iterations <= 6, "{}", s.iterations);
}

/// One equation in two unknowns (`x + 2y = −0.2`, linear): the minimum-norm step lands on the
/// point of the line nearest the start, the projection `w0 + (−0.2 − a·w0) a/|a|²`.
#[test]
fn underdetermined_step_is_the_minimum_norm_one() {
    let a = Vector4::new(1.0, 2.0, 0.0, 0.0);
    let f = |w: &Vector4<f64>| {
        let mut j = Matrix4::zeros();
        j.set_row(0, &a.transpose());
        Linearised::new(Vector4::new(a.dot(w) + 0.2, 0.0, 0.0, 0.0), j, 0.0)
    };
    let w0 = Vector4::new(0.3, -0.4, 0.0, 0.0);
    let s = run(&Newton::grid(), w0, &[], f).expect("converges");
    let want = w0 + a * ((-0.2 - a.dot(&w0)) / a.norm_squared());
    assert!((s.w - want).norm() < 1e-14, "{} vs {}", s.w, want);
    assert_eq!(s.iterations, 1);
}

/// Damped Newton on the gradient of `U = x⁴/4 + y²/2 − x` (symmetric Jacobian, closed-form
/// path) from far away reaches the minimum `(1, 0)`, each accepted step decreasing `|∇U|`.
#[test]
fn damped_newton_reaches_the_minimum_of_a_quartic() {
    let f = |w: &Vector4<f64>| {
        let (x, y) = (w[0], w[1]);
        let rows = Vector4::new(x * x * x - 1.0, y, 0.0, 0.0);
        // K = diag(3x², 1), its eigenvalues in ascending order with their unit vectors.
        let (d, e1, e2) = (3.0 * x * x, Vector2::x(), Vector2::y());
        let (values, vectors) = if d <= 1.0 {
            ([d, 1.0], [e1, e2])
        } else {
            ([1.0, d], [e2, e1])
        };
        Linearised {
            rows,
            jac: Jacobian::Symmetric2 { values, vectors },
            noise: 0.0,
            zero: 0.0,
            residual: norm4(&rows),
            floor: 0.0,
        }
    };
    let s = run(
        &Newton::search(100, 1e-12),
        Vector4::new(-3.0, 2.0, 0.0, 0.0),
        &[],
        f,
    )
    .expect("converges");
    assert!(
        (s.w[0] - 1.0).abs() < 1e-12 && s.w[1].abs() < 1e-12,
        "{}",
        s.w
    );
}

/// The stops say why: a far root with a step cap (StepTooLong), no root (`x² + 1`, damped:
/// NoDecrease at the minimum of `|F|`, with that residual reported), the hook (Interrupted).
#[test]
fn stops_say_why() {
    let lin = |v: f64, d: f64| {
        let mut j = Matrix4::zeros();
        j[(0, 0)] = d;
        Linearised::new(Vector4::new(v, 0.0, 0.0, 0.0), j, 0.0)
    };
    let far = |w: &Vector4<f64>| lin(w[0] - 10.0, 1.0);
    let e = run(&Newton::grid(), Vector4::zeros(), &[], far).expect_err("capped");
    assert_eq!(e.why, Why::StepTooLong);
    let none = |w: &Vector4<f64>| lin(w[0] * w[0] + 1.0, 2.0 * w[0]);
    let e = run(
        &Newton::search(50, 1e-10),
        Vector4::new(0.7, 0.0, 0.0, 0.0),
        &[],
        none,
    )
    .expect_err("no root");
    assert!(
        matches!(e.why, Why::NoDecrease | Why::Singular | Why::MaxIterations),
        "{:?}",
        e.why
    );
    assert!((e.best_residual - 1.0).abs() < 1e-3, "{}", e.best_residual);
    let start = (Vector4::zeros(), far(&Vector4::zeros()));
    let r: Result<_, Infallible> = Newton::grid().solve(
        Vector4::zeros(),
        &[],
        start,
        |p: &At| p.1,
        |_, w, _| Ok(Some((*w, far(w)))),
        |_| true,
    );
    assert!(matches!(
        r,
        Ok(Err(Stop {
            why: Why::Interrupted,
            ..
        }))
    ));
}
