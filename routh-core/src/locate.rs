//! The event locator: the zero of a test function along a one-parameter path, bracketed by two
//! solved points, found by regula falsi with the Illinois modification (docs/method.md §7).
//!
//! The caller gives the bracket `[a, b]` in its own path parameter with the test values at both
//! ends (opposite signs), a `solve` callback that re-solves its equations at an interior
//! parameter and returns the test value there with whatever the caller keeps of the point, and a
//! stop rule on the current bracket (its own scale: `|ΔE| ≤ 1e−9·max(1, |E|)` for orbit events).
//! The locator returns the end of the final bracket with the smaller test value. The same steps
//! as the continuation's `Ctx::locate`: the secant point, kept at least `1e−3` of the bracket
//! from either end (else the midpoint), and the retained end's value halved when the same end
//! moves twice (Illinois), which makes the convergence superlinear where plain regula falsi
//! would stall at one end.

/// One end of a bracket: the path parameter, the test value there and the caller's point.
#[derive(Debug, Clone)]
pub(crate) struct End<P> {
    pub at: f64,
    pub value: f64,
    pub point: P,
}

/// The distance from the better end of a bracket to the zero, estimated by the secant through
/// both ends (in the path parameter): `|v_best|·|Δt|/|Δv|`. A stop rule on it ends the search once
/// one end is at the zero to the wanted accuracy; a rule on the bracket's width would wait for
/// the far end too, which regula falsi moves only by bisection once the near end has converged.
pub(crate) fn estimated_distance<P>(lo: &End<P>, hi: &End<P>) -> f64 {
    let best = lo.value.abs().min(hi.value.abs());
    best * (hi.at - lo.at).abs() / (hi.value - lo.value).abs()
}

/// The zero of the test function between `lo` and `hi` (values of opposite signs, or one zero).
///
/// `solve(t)` re-solves at the parameter `t` strictly inside the bracket: `Ok(None)` when it
/// cannot (the locator then returns the better end so far). `done(lo, hi)` is the stop rule on
/// the bracket; at most `max_iter` solves are made.
pub(crate) fn illinois<P: Clone, E>(
    lo: End<P>,
    hi: End<P>,
    max_iter: usize,
    mut solve: impl FnMut(f64) -> Result<Option<(f64, P)>, E>,
    done: impl Fn(&End<P>, &End<P>) -> bool,
) -> Result<End<P>, E> {
    let (mut lo, mut hi) = (lo, hi);
    if lo.value == 0.0 {
        return Ok(lo);
    }
    if hi.value == 0.0 {
        return Ok(hi);
    }
    let mut lo_value = lo.value;
    let mut hi_value = hi.value;
    let mut side = 0i32;
    for _ in 0..max_iter {
        if done(&lo, &hi) {
            break;
        }
        let w = hi.at - lo.at;
        let mut t = if hi_value != lo_value {
            lo.at - lo_value * w / (hi_value - lo_value)
        } else {
            0.5 * (lo.at + hi.at)
        };
        // Kept 1e−3 of the bracket inside it: once one end has converged the secant point
        // crowds it, and the clamped point then lands just past the zero, cutting the bracket a
        // thousandfold (a midpoint would only halve it).
        t = if t.is_nan() {
            0.5 * (lo.at + hi.at)
        } else {
            t.clamp(lo.at + 1e-3 * w, hi.at - 1e-3 * w)
        };
        let Some((v, point)) = solve(t)? else {
            break;
        };
        if v == 0.0 {
            return Ok(End {
                at: t,
                value: v,
                point,
            });
        }
        if (v < 0.0) == (lo.value < 0.0) {
            lo = End {
                at: t,
                value: v,
                point,
            };
            lo_value = v;
            if side == -1 {
                hi_value *= 0.5;
            }
            side = -1;
        } else {
            hi = End {
                at: t,
                value: v,
                point,
            };
            hi_value = v;
            if side == 1 {
                lo_value *= 0.5;
            }
            side = 1;
        }
    }
    Ok(if lo.value.abs() <= hi.value.abs() {
        lo
    } else {
        hi
    })
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
    }
}
