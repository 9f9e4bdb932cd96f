//! The events of a family of periodic orbits (docs/method.md §11, "The event correction"):
//! between two accepted orbits a sign change of the tangent's eighth component is a `Fold`, of
//! `k − 1` a `BranchPoint`, of `k + 1` a `PeriodDoubling` (and, with `OrbitOptions::nonlinear`,
//! of `k + 1/2`, `k` and the twist the resonances of order three and four and a
//! `TwistDegenerate`), each bracketed by the crate's one
//! event locator (`locate.rs`) on re-solves along the step and, at a branch point or a period
//! doubling, read off a secant through re-solves either side of it.

use super::family::Tracer;
use super::node::{same_family, Node};
use super::shoot::correct;
use super::{OrbitEvent, OrbitEventKind};
use crate::solve::locate::{estimated_distance, locate, End};
use crate::solve::path::row::LinearRow;
use crate::{RouthError, Routhian};

impl<M: Routhian> Tracer<'_, M> {
    /// Re-solves between two orbits `lo` (at arclength `s_lo`) and `hi` (at `s_hi`) of the family
    /// at the arclength `sigma` strictly between them: predicted on the cubic Hermite curve
    /// through both ends and their tangents (its error shrinks as the bracket's width to the
    /// fourth power), corrected in the hyperplane normal to the curve there (singular values
    /// below `cut` of the largest dropped), and kept only if it stayed by the prediction or lies
    /// on the same family as both ends ([`same_family`]): near a branch point the corrector may
    /// otherwise land on the family that crosses.
    fn resolve_between(
        &self,
        lo: (&Node, f64),
        hi: (&Node, f64),
        sigma: f64,
        cut: f64,
        twist: bool,
    ) -> Result<Option<Node>, RouthError> {
        let ((a, sa), (b, sb)) = (lo, hi);
        let span = sb - sa;
        let u = (sigma - sa) / span;
        let chord = (b.solved.w - a.solved.w).norm();
        let (ma, mb) = (a.tangent * chord, b.tangent * chord);
        let (u2, u3) = (u * u, u * u * u);
        let pred = a.solved.w * (2.0 * u3 - 3.0 * u2 + 1.0)
            + ma * (u3 - 2.0 * u2 + u)
            + b.solved.w * (-2.0 * u3 + 3.0 * u2)
            + mb * (u3 - u2);
        let slope = (a.solved.w * (6.0 * u2 - 6.0 * u)
            + ma * (3.0 * u2 - 4.0 * u + 1.0)
            + b.solved.w * (-6.0 * u2 + 6.0 * u)
            + mb * (3.0 * u2 - 2.0 * u))
            .normalize();
        let mut prob = self.problem_at(&a.solved.w)?;
        prob.cut = cut;
        let row = LinearRow::through(slope, &pred);
        let Ok(s) = correct(self.slot, &prob, &row, &pred, self.opts)? else {
            return Ok(None);
        };
        let near = (s.w - pred).norm() <= 1e-2 * chord;
        let n = self.node_with(s, Some(&slope), twist)?;
        Ok((near || (same_family(a, &n) && same_family(&n, b))).then_some(n))
    }

    /// The events on the step from `a` to `b` (arclength `h`).
    ///
    /// A sign change of `k ∓ 1` (or of `dE/dσ`) between the ends is bracketed by the crate's one
    /// locator on re-solves along the step. A fold is located in the arclength itself. A branch
    /// point or a period doubling is bracketed to `1e−4·h`, and its arclength and energy are then
    /// read off the secant through two re-solves `1e−4·h` either side of it: at a branch point the
    /// system is singular (the crossing family's direction), and a re-solve nearer than that
    /// would be displaced along the crossing family by the integration's round-off divided by
    /// the distance; `k` and `E` are smooth along the family, so the secant's error is of the
    /// order of that distance squared (1e−13 at the default steps). The event's orbit is then
    /// corrected at that arclength with the crossing direction dropped from the Gauss–Newton
    /// steps (singular values below `1e−8` of the largest; docs/method.md §11).
    /// Each event comes with its place along the family ([`Tracer::value`]).
    pub(super) fn events(
        &self,
        a: &Node,
        b: &Node,
        h: f64,
    ) -> Result<Vec<(OrbitEvent, f64)>, RouthError> {
        let mut out = Vec::new();
        let (ka, kb) = (a.orbit.stability_index, b.orbit.stability_index);
        let fold = a.tangent[7] * b.tangent[7] < 0.0;
        type Test = fn(&Node) -> f64;
        let mut tests: Vec<(OrbitEventKind, Test)> = Vec::new();
        if fold {
            tests.push((OrbitEventKind::Fold, |n: &Node| n.tangent[7]));
        } else if (ka - 1.0) * (kb - 1.0) < 0.0 {
            tests.push((OrbitEventKind::BranchPoint, |n: &Node| {
                n.orbit.stability_index - 1.0
            }));
        }
        if (ka + 1.0) * (kb + 1.0) < 0.0 {
            tests.push((OrbitEventKind::PeriodDoubling, |n: &Node| {
                n.orbit.stability_index + 1.0
            }));
        }
        if self.opts.nonlinear {
            let third = (ka + 0.5) * (kb + 0.5) < 0.0;
            if third {
                tests.push((OrbitEventKind::ThirdOrderResonance, |n: &Node| {
                    n.orbit.stability_index + 0.5
                }));
            }
            if ka * kb < 0.0 {
                tests.push((OrbitEventKind::FourthOrderResonance, |n: &Node| {
                    n.orbit.stability_index
                }));
            }
            // τ has a pole at k = −1/2 (the homological denominator of the term z̄²): a change
            // of sign across a resonance of order three is not a zero.
            if !third && a.twist * b.twist < 0.0 {
                tests.push((OrbitEventKind::TwistDegenerate, |n: &Node| n.twist));
            }
        }
        let near = 1e-4 * h;
        let cut = 1e-12;
        let solve =
            |sigma: f64, cut: f64| self.resolve_between((a, 0.0), (b, h), sigma, cut, false);
        for (kind, test) in tests {
            let lo = End::new(0.0, test(a), a.clone());
            let hi = End::new(h, test(b), b.clone());
            let found = locate(
                lo,
                hi,
                80,
                |sigma, lo, hi| {
                    Ok::<_, RouthError>(
                        self.resolve_between(
                            (&lo.point, lo.at),
                            (&hi.point, hi.at),
                            sigma,
                            cut,
                            kind == OrbitEventKind::TwistDegenerate,
                        )?
                        .map(|n| (test(&n), n)),
                    )
                },
                |lo, hi| match kind {
                    OrbitEventKind::Fold => estimated_distance(lo, hi) <= 1e-7 * h,
                    OrbitEventKind::BranchPoint | OrbitEventKind::PeriodDoubling => {
                        estimated_distance(lo, hi) <= near
                    }
                    // Regular zeros of a smooth function along the family: bracketed to the
                    // event tolerance in the family's own variable.
                    _ => {
                        let (u, v) = (self.value(&lo.point), self.value(&hi.point));
                        (u - v).abs() <= self.opts.event_tol * u.abs().max(1.0)
                            || estimated_distance(lo, hi) <= 1e-12 * h
                    }
                },
            )?;
            let node = match kind {
                OrbitEventKind::BranchPoint | OrbitEventKind::PeriodDoubling => {
                    self.polish(&found, test, kind, h, &solve)?
                }
                _ => found.best.point.clone(),
            };
            let at = self.value(&node);
            let orbit = node.orbit;
            out.push((
                OrbitEvent {
                    kind,
                    energy: orbit.energy,
                    orbit,
                    before: a.orbit.stability,
                    after: b.orbit.stability,
                },
                at,
            ));
        }
        Ok(out)
    }

    /// The orbit of a branch point or a period doubling from the locator's bracket (see
    /// [`Tracer::events`]): the secant zero through re-solves `1e−4·h` either side of the
    /// bracket's estimate, the orbit corrected there; the bracket's better end when a re-solve
    /// fails or the two do not straddle the zero.
    fn polish(
        &self,
        found: &crate::solve::locate::Located<Node>,
        test: fn(&Node) -> f64,
        kind: OrbitEventKind,
        h: f64,
        solve: &dyn Fn(f64, f64) -> Result<Option<Node>, RouthError>,
    ) -> Result<Node, RouthError> {
        let (b, o) = (&found.best, &found.other);
        let fallback = b.point.clone();
        let estimate = if o.value != b.value && o.at != b.at {
            b.at - b.value * (o.at - b.at) / (o.value - b.value)
        } else {
            b.at
        };
        let d = 1e-4 * h;
        let (s1, s2) = ((estimate - d).max(0.0), (estimate + d).min(h));
        let (Some(n1), Some(n2)) = (solve(s1, 1e-12)?, solve(s2, 1e-12)?) else {
            return Ok(fallback);
        };
        let (v1, v2) = (test(&n1), test(&n2));
        if v1 * v2 > 0.0 || v1 == v2 {
            return Ok(fallback);
        }
        let sigma = s1 - v1 * (s2 - s1) / (v2 - v1);
        // Predicted between the two re-solves (an error of order d⁴): the dropped direction
        // is not corrected.
        let cut = if kind == OrbitEventKind::BranchPoint {
            1e-8
        } else {
            1e-12
        };
        // One secant step more from the corrected orbit, along the pair's slope.
        let slope = (v2 - v1) / (s2 - s1);
        let mut best: Option<Node> = None;
        let mut sigma = sigma;
        for _ in 0..2 {
            let Some(n) = self.resolve_between((&n1, s1), (&n2, s2), sigma, cut, false)? else {
                break;
            };
            let v = test(&n);
            if best.as_ref().is_some_and(|m| test(m).abs() <= v.abs()) {
                break;
            }
            sigma -= v / slope;
            best = Some(n);
        }
        Ok(match best {
            Some(n) if test(&n).abs() <= b.value.abs() => n,
            _ => fallback,
        })
    }
}
