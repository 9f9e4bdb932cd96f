//! The event locator: the zero of a test function along a one-parameter path, bracketed by two
//! solved points, found by regula falsi with the Illinois modification (docs/method.md §11).
//! The one locator of the crate: the events of the bifurcation diagrams (`families::continuation`)
//! and of the orbit families (`periodic`), the starts of the atlas's boundary curves
//! (`families::atlas::edge`), the nonlinear events and curves (`families::nonlinear`), Poincaré
//! crossings and returns, and the degenerate critical points of the global search
//! (`steady::search`).
//!
//! The caller gives the bracket `[a, b]` in its own path parameter with the test values at both
//! ends (opposite signs), a `solve` callback that re-solves its equations at an interior
//! parameter (starting from the points at the current bracket's ends) and returns the test
//! value there with whatever the caller keeps of the point, a budget of solves and a stop rule
//! on the current bracket, in the event's own scale (`|Δs| ≤ 1e−10·max(1, |s|)` for the events
//! of a diagram, `|ΔE| ≤ 1e−9·max(1, |E|)` for orbit events). The locator returns the end of the
//! final bracket with the smaller test value and why it stopped ([`Stop`]). Each step: the
//! secant point, kept at least `1e−3` of the bracket from either end, and the retained end's
//! value halved when the same end moves twice (Illinois), which makes the convergence
//! superlinear where plain regula falsi would stall at one end (and bisection would take one
//! solve per bit).

/// One end of a bracket: the path parameter, the test value there and the caller's point.
#[derive(Debug, Clone)]
pub(crate) struct End<P> {
    pub at: f64,
    pub value: f64,
    pub point: P,
}

impl<P> End<P> {
    /// The end at `at` where the function is `value`, with its `point`.
    pub(crate) fn new(at: f64, value: f64, point: P) -> Self {
        End { at, value, point }
    }
}

/// The distance from the better end of a bracket to the zero, estimated by the secant through
/// both ends (in the path parameter): `|v_best|·|Δt|/|Δv|`. A stop rule on it ends the search once
/// one end is at the zero to the wanted accuracy; a rule on the bracket's width would wait for
/// the far end too, which regula falsi moves only by bisection once the near end has converged.
pub(crate) fn estimated_distance<P>(lo: &End<P>, hi: &End<P>) -> f64 {
    let best = lo.value.abs().min(hi.value.abs());
    best * (hi.at - lo.at).abs() / (hi.value - lo.value).abs()
}

/// Why [`locate`] stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Stop {
    /// The stop rule held on the final bracket.
    Converged,
    /// The test function was exactly zero at an end or at a solved point.
    Zero,
    /// The bracket is down to adjacent floating-point numbers.
    Floats,
    /// A re-solve failed (`Ok(None)`): the better end so far.
    SolveFailed,
    /// The budget of solves ran out before the stop rule held.
    Budget,
}

/// What [`locate`] found: the end of the final bracket with the smaller test value, the number
/// of solves made and why it stopped.
#[derive(Debug, Clone)]
pub(crate) struct Located<P> {
    pub best: End<P>,
    /// The final bracket's other end (the same as `best` after [`Stop::Zero`] at an end).
    #[allow(dead_code)]
    pub other: End<P>,
    /// Read by the tests (the count is the locator's cost).
    #[cfg_attr(not(test), allow(dead_code))]
    pub solves: usize,
    pub stop: Stop,
}

/// The stop rule "within `tol` of the zero in the path parameter": the bracket is at most `tol`
/// wide or its better end is estimated ([`estimated_distance`]) within `tol` of the zero. The
/// estimate is that of a simple zero; at a zero of higher order (a cubic) it is too small, and
/// a rule on the bracket's width alone is the safe one.
pub(crate) fn within<P>(lo: &End<P>, hi: &End<P>, tol: f64) -> bool {
    (hi.at - lo.at).abs() <= tol || estimated_distance(lo, hi) <= tol
}

/// The zero of the test function between `lo` and `hi` (values of opposite signs, or one zero).
///
/// `solve(t, lo, hi)` re-solves at the parameter `t` strictly inside the current bracket
/// `[lo, hi]` (whose points are there to start from): `Ok(None)` when it cannot (the locator
/// then returns the better end so far). `done(lo, hi)` is the stop rule on the bracket (the
/// caller's own scale: e.g. `|Δs| ≤ tol·max(1, |s|)` in the quantity the event is reported in,
/// which need not be the path parameter); at most `budget` solves are made.
pub(crate) fn locate<P: Clone, E>(
    lo: End<P>,
    hi: End<P>,
    budget: usize,
    mut solve: impl FnMut(f64, &End<P>, &End<P>) -> Result<Option<(f64, P)>, E>,
    done: impl Fn(&End<P>, &End<P>) -> bool,
) -> Result<Located<P>, E> {
    let (mut lo, mut hi) = if lo.at <= hi.at { (lo, hi) } else { (hi, lo) };
    let finish = |lo: End<P>, hi: End<P>, solves: usize, stop: Stop| {
        let (best, other) = if lo.value.abs() <= hi.value.abs() {
            (lo, hi)
        } else {
            (hi, lo)
        };
        Located {
            best,
            other,
            solves,
            stop,
        }
    };
    if lo.value == 0.0 || hi.value == 0.0 {
        return Ok(finish(lo, hi, 0, Stop::Zero));
    }
    let mut lo_value = lo.value;
    let mut hi_value = hi.value;
    let mut side = 0i32;
    let mut solves = 0;
    let stop = loop {
        if done(&lo, &hi) {
            break Stop::Converged;
        }
        if solves >= budget {
            break Stop::Budget;
        }
        let w = hi.at - lo.at;
        let mid = 0.5 * (lo.at + hi.at);
        if mid <= lo.at || mid >= hi.at {
            break Stop::Floats;
        }
        let t = if hi_value != lo_value {
            lo.at - lo_value * w / (hi_value - lo_value)
        } else {
            mid
        };
        // Kept 1e−3 of the bracket inside it: once one end has converged the secant point
        // crowds it, and the clamped point then lands just past the zero, cutting the bracket a
        // thousandfold (a midpoint would only halve it).
        let t = if t.is_nan() {
            mid
        } else {
            t.clamp(lo.at + 1e-3 * w, hi.at - 1e-3 * w)
        };
        // Strictly inside, also where the bracket is a few floats wide.
        let t = if t > lo.at && t < hi.at { t } else { mid };
        solves += 1;
        let Some((v, point)) = solve(t, &lo, &hi)? else {
            break Stop::SolveFailed;
        };
        let end = End {
            at: t,
            value: v,
            point,
        };
        if v == 0.0 {
            return Ok(Located {
                other: end.clone(),
                best: end,
                solves,
                stop: Stop::Zero,
            });
        }
        if (v < 0.0) == (lo.value < 0.0) {
            lo = end;
            lo_value = v;
            if side == -1 {
                hi_value *= 0.5;
            }
            side = -1;
        } else {
            hi = end;
            hi_value = v;
            if side == 1 {
                lo_value *= 0.5;
            }
            side = 1;
        }
    };
    Ok(finish(lo, hi, solves, stop))
}

/// [`locate`] with a re-solve that needs only the parameter, returning the better end.
pub(crate) fn illinois<P: Clone, E>(
    lo: End<P>,
    hi: End<P>,
    max_iter: usize,
    mut solve: impl FnMut(f64) -> Result<Option<(f64, P)>, E>,
    done: impl Fn(&End<P>, &End<P>) -> bool,
) -> Result<End<P>, E> {
    Ok(locate(lo, hi, max_iter, |t, _, _| solve(t), done)?.best)
}

#[cfg(test)]
mod tests {
    use super::*;

    type F<'a> = &'a dyn Fn(f64) -> f64;

    fn end(at: f64, f: F<'_>) -> End<()> {
        End {
            at,
            value: f(at),
            point: (),
        }
    }

    /// The zero of `cos` on [1, 2] is π/2, and of `x³ − 2` on [0, 3] is ∛2: closed forms the
    /// locator does not know, found to the bracket width asked for.
    #[test]
    fn finds_closed_form_zeros() {
        let cases: [(F<'_>, f64, f64, f64); 3] = [
            (&|x: f64| x.cos(), 1.0, 2.0, std::f64::consts::FRAC_PI_2),
            (&|x: f64| x * x * x - 2.0, 0.0, 3.0, 2f64.cbrt()),
            // Flat on one side: plain regula falsi would crawl from the right end.
            (
                &|x: f64| (x - 0.3).powi(3) + 1e-3 * (x - 0.3),
                0.0,
                5.0,
                0.3,
            ),
        ];
        for (f, a, b, root) in cases {
            let mut solves = 0;
            let got = illinois(
                end(a, f),
                end(b, f),
                100,
                |t| {
                    solves += 1;
                    Ok::<_, ()>(Some((f(t), ())))
                },
                |lo, hi| estimated_distance(lo, hi) <= 1e-14 || hi.at - lo.at <= 1e-14,
            )
            .unwrap();
            assert!((got.at - root).abs() < 1e-12, "{} vs {root}", got.at);
            // Bisection would need log₂(5/1e−14) ≈ 49 solves on the widest bracket.
            assert!(solves < 25, "{root}: {solves} solves");
        }
    }

    /// A zero of order three (`x³`, a pitchfork's gradient along its kernel) by the bracket's
    /// width alone, and the stop reasons: converged, out of budget, down to adjacent floats.
    #[test]
    fn cubic_zero_budget_and_stop_reasons() {
        let f = |x: f64| (x - 0.1).powi(3);
        let run = |budget: usize, tol: f64| {
            let mut solves = 0;
            let got = locate(
                end(-0.3, &f),
                end(0.7, &f),
                budget,
                |t, lo, hi| {
                    assert!(lo.at < t && t < hi.at);
                    solves += 1;
                    Ok::<_, ()>(Some((f(t), ())))
                },
                |lo, hi| hi.at - lo.at <= tol,
            )
            .unwrap();
            assert_eq!(got.solves, solves);
            got
        };
        let got = run(200, 1e-12);
        assert_eq!(got.stop, Stop::Converged);
        assert!((got.best.at - 0.1).abs() <= 1e-12, "{}", got.best.at);
        // Bisection: log₂(1/1e−12) ≈ 40 solves.
        assert!(got.solves <= 80, "{} solves", got.solves);
        let short = run(3, 1e-12);
        assert_eq!((short.stop, short.solves), (Stop::Budget, 3));
        let floats = run(10_000, 0.0);
        assert!(
            matches!(floats.stop, Stop::Floats | Stop::Zero),
            "{:?}",
            floats.stop
        );
        assert!((floats.best.at - 0.1).abs() <= 1e-15, "{}", floats.best.at);
        // The secant estimate of the distance to a cubic zero is far too small: `within` on a
        // simple zero only.
        let lo = end(0.1 - 1e-3, &f);
        let hi = end(0.7, &f);
        assert!(estimated_distance(&lo, &hi) < 1e-7);
    }

    /// The tolerance of `within` on the path parameter, on a simple zero: `eᵗ − 2` on [0, 3]
    /// (zero ln 2), asked to 1e−11.
    #[test]
    fn within_a_tolerance_on_a_simple_zero() {
        let f = |x: f64| x.exp() - 2.0;
        let got = locate(
            end(0.0, &f),
            end(3.0, &f),
            100,
            |t, _, _| Ok::<_, ()>(Some((f(t), ()))),
            |lo, hi| within(lo, hi, 1e-11),
        )
        .unwrap();
        assert!(matches!(got.stop, Stop::Converged | Stop::Zero));
        assert!((got.best.at - 2f64.ln()).abs() <= 1e-11, "{}", got.best.at);
        assert!(got.solves < 15, "{} solves", got.solves);
    }

    /// A solve that fails ends the search with the better end so far.
    #[test]
    fn stops_when_a_solve_fails() {
        let f = |x: f64| x - 0.25;
        let got = illinois(
            end(0.0, &f),
            end(1.0, &f),
            100,
            |_| Ok::<_, ()>(None),
            |_, _| false,
        )
        .unwrap();
        assert_eq!(got.at, 0.0);
        let got = locate(
            end(0.0, &f),
            end(1.0, &f),
            100,
            |_, _, _| Ok::<_, ()>(None),
            |_, _| false,
        )
        .unwrap();
        assert_eq!((got.stop, got.solves), (Stop::SolveFailed, 1));
    }
}
