//! One direction of one branch: the steps of the crate's predictor–corrector ([`Ctx::path`]) with
//! the branch's own checks, the events on each step located by their defining equations, and the
//! ends of the branch.

use super::builder::{dist, Builder, Switch, Traced};
use crate::error::RouthError;
use crate::families::continuation::{changes, lands_on_a_zero, test_value, Change, Ctx, Node};
use crate::families::{EventKind, StopReason};
use crate::model::Routhian;
use crate::solve::path::{Check, Outcome, Point};
use crate::solve::zero::{ZeroTest, AXIS_REL, EIGEN_REL};

/// Whether a point of a branch of circles is next to the axis of its circles, where they shrink
/// to a pole: both eigenvalues of `K` below `1e−5` and the whole Jacobian `[K | F_s]` below
/// `1e−2`, relative to the scale at the point ([`Node::scale`]; at the pole both vanish by
/// symmetry; at a fold of circles `F_s` does not).
fn near_axis(n: &Node) -> bool {
    ZeroTest::relative(AXIS_REL, 1.0).count(&n.eig) == 2 && n.jac.norm() <= 1e-2 * n.scale
}

/// Whether a point of a branch of circles has the zero eigenvalue of `K` of a circle: below
/// `1e−6` relative to the scale at the point, or below `1e−3` of the other eigenvalue (a
/// near-spherical body, whose `K` is small altogether: the point of the pole next to the axis has
/// two nearly equal eigenvalues instead).
fn circle_point(n: &Node) -> bool {
    let (lo, hi) = (
        n.eig[0].abs().min(n.eig[1].abs()),
        n.eig[0].abs().max(n.eig[1].abs()),
    );
    ZeroTest::relative(EIGEN_REL, 1.0).is_zero(lo) || ZeroTest::relative(1e-3, hi).is_zero(lo)
}

impl<'a, M: Routhian, F: Fn(f64) -> (M, f64)> Builder<'a, M, F> {
    /// Follows one direction from `start`, with at most `budget` steps, until the branch leaves
    /// the range (it then ends exactly on the range's end), closes, or meets another branch (a
    /// branch of circles reaching its axis).
    ///
    /// When the budget is spent first the branch ends there, with [`StopReason::MaxSteps`].
    ///
    /// Errors:
    /// - [`RouthError::AtParameter`] at the last point reached, wrapping
    ///   [`RouthError::NoConvergence`], when the corrector fails for every step down to
    ///   [`ContinuationOptions::min_step`](crate::ContinuationOptions::min_step) (the branch
    ///   cannot be continued there: the family is not smooth, or the branch ends in a
    ///   singularity that is not an event of the module);
    /// - the errors of the family and the model along the way.
    pub(super) fn trace(
        &self,
        ctx: &Ctx<'a, M, F>,
        start: Node,
        budget: usize,
    ) -> Result<Traced, RouthError> {
        let opts = self.opts;
        let (lo, hi) = self.range;
        let mut out = Traced {
            nodes: vec![start.clone()],
            events: Vec::new(),
            switches: Vec::new(),
            steps: 0,
            stop: None,
        };
        let mut path = ctx.path(budget);
        // The largest eigenvalue of K met along the way (in modulus).
        let mut widest = start.eig[0].abs().max(start.eig[1].abs());
        // Below this step, events sharing a step or a verdict changing unexplained no longer
        // shorten it (nor a tangent turning fast: `PathOptions::diagram`).
        let short = 4.0 * opts.min_step;
        loop {
            if opts.control.is_cancelled() {
                out.stop = Some(StopReason::Interrupted);
                break;
            }
            let a = out.nodes.last().unwrap().clone();
            // A branch of circles has a zero eigenvalue of K all along it (the circle
            // direction). Where its circles shrink to their axis it crosses the branch of the
            // pole (where K is a multiple of the identity), and a step can slide onto that
            // branch: a point with no zero eigenvalue is not a circle. Shorter steps, and next to
            // the axis the end (`finish` appends the point on the axis).
            // Shorten the step also when two events share it, when the verdict changes with
            // no test function changing sign, or when the new point lies exactly on a zero of a
            // test function ([`lands_on_a_zero`]).
            let check = |p: &Point<4, Node>, h: f64| {
                let b = &p.value;
                if !ctx.isolated && !circle_point(b) {
                    return if h <= short {
                        Check::Stop
                    } else {
                        Check::Shorten
                    };
                }
                let ch = changes(&a, b, ctx.isolated);
                let eigen = ch.iter().filter(|c| matches!(c, Change::Eigen(_))).count();
                let unexplained = ch.is_empty() && a.verdict() != b.verdict();
                let shared = eigen > 0 && ch.contains(&Change::Discriminant);
                if (shared || eigen > 1 || unexplained || lands_on_a_zero(&a, b, ctx.isolated))
                    && h > short
                {
                    Check::Shorten
                } else {
                    Check::Accept
                }
            };
            let w = a.on_path(ctx.len);
            // Steps bounded in the local scale of s, not the range's alone
            // ([`Ctx::longest_step`]).
            let step = path.step(
                &w,
                &a.tangent(),
                ctx.longest_step(&a),
                ctx.corrector(&a),
                ctx.completer(&a),
                check,
            )?;
            out.steps = path.attempts();
            let (b, h) = match step {
                Outcome::Accepted { point, h } => (point.value, h),
                Outcome::Exhausted => {
                    out.stop = Some(StopReason::MaxSteps {
                        s: a.s,
                        gamma: a.gamma,
                    });
                    break;
                }
                Outcome::Stopped(_) => break,
                Outcome::Stalled(f) => {
                    ctx.failed(f);
                    // A branch of circles next to its axis (both eigenvalues of K nearly zero:
                    // the circle shrinks to the pole of the symmetry), where the circle direction
                    // is lost in round-off: the rest is the same circles again, down to the axis,
                    // which `finish` appends from the branch point on the axis.
                    if !ctx.isolated && near_axis(&a) {
                        break;
                    }
                    return Err(RouthError::AtParameter {
                        s: a.s,
                        source: Box::new(RouthError::NoConvergence {
                            what: "continuation of a branch: the corrector fails for every step \
                                   down to ContinuationOptions::min_step (the branch cannot be \
                                   continued from here)",
                            iterations: out.steps,
                            residual: ctx.failed_residual.get(),
                        }),
                    });
                }
            };
            let ch = changes(&a, &b, ctx.isolated);
            let eigen = ch.iter().any(|c| matches!(c, Change::Eigen(_)));
            let disc = ch.contains(&Change::Discriminant);
            // Leaving the range: end exactly on its boundary.
            if b.s < lo || b.s > hi {
                let bound = if b.s < lo { lo } else { hi };
                if let Some(e) = ctx.at_parameter(&a, &b, bound)? {
                    if (e.s - a.s).abs() > 0.0 {
                        out.nodes.push(e);
                    }
                }
                break;
            }
            let turn = ch.contains(&Change::Turn);
            let mut end = false;
            // The located events and turning points on this step: points of the branch, so that
            // its polyline passes through them (the tip of a pitchfork, a fold).
            let mut located: Vec<Node> = Vec::new();
            if eigen {
                let which = *ch.iter().find(|c| matches!(c, Change::Eigen(_))).unwrap();
                let e = ctx.locate(&a, &b, h, &|n| test_value(which, n))?;
                if ctx.is_branch_point(&e) {
                    if !ctx.isolated {
                        end = true;
                        out.nodes.push(e.clone());
                    } else {
                        located.push(e.clone());
                        if !turn {
                            out.events.push((
                                EventKind::BranchPoint,
                                e.clone(),
                                a.verdict(),
                                b.verdict(),
                            ));
                        }
                        out.switches.push(Switch {
                            node: e,
                            isolated: ctx.isolated,
                        });
                    }
                } else {
                    located.push(e.clone());
                    out.events
                        .push((EventKind::Fold, e, a.verdict(), b.verdict()));
                }
            } else if turn {
                // A turning point in s with no eigenvalue changing sign: the branch passes
                // through the tip of a pitchfork on another branch.
                let e = ctx.locate(&a, &b, h, &|n| n.tau_s)?;
                if ctx.isolated {
                    // Next to the tip the hyperplanes of the corrector also cut the other branch,
                    // and a located point can slide onto it (its tangent is then along s, not
                    // across): not a point of this branch. `finish` joins the tip to the branch
                    // point located on the other branch.
                    if e.tau_s.abs() <= 0.5 {
                        located.push(e.clone());
                    }
                    out.switches.push(Switch {
                        node: e,
                        isolated: true,
                    });
                } else {
                    // A branch of circles reaching its axis: the rest is the same circles again.
                    out.nodes.push(e);
                    end = true;
                }
            }
            if disc && !end && a.degree_two() && b.degree_two() {
                let e = ctx.locate(&a, &b, h, &|n| n.disc)?;
                if a.verdict() != b.verdict() {
                    located.push(e.clone());
                    out.events
                        .push((EventKind::HamiltonianHopf, e, a.verdict(), b.verdict()));
                }
            }
            if end {
                break;
            }
            let hi = b.eig[0].abs().max(b.eig[1].abs());
            widest = widest.max(hi);
            if !ctx.isolated && near_axis(&b) && hi <= 1e-3 * widest {
                // Next to the axis the steps would shrink without end (the circle direction is
                // lost in round-off): end here; `finish` appends the point on the axis. (The
                // eigenvalues of `K` must also have shrunk along the branch: a near-spherical
                // body has small ones all along.)
                out.nodes.push(b);
                break;
            }
            let ab = dist(&a, &b, ctx.len);
            located.sort_by(|x, y| dist(&a, x, ctx.len).total_cmp(&dist(&a, y, ctx.len)));
            for e in located {
                let (da, db) = (dist(&a, &e, ctx.len), dist(&e, &b, ctx.len));
                let last = out.nodes.last().map_or(0.0, |l| dist(l, &e, ctx.len));
                if da > 1e-9 * ab && db > 1e-9 * ab && last > 1e-9 * ab {
                    out.nodes.push(e);
                }
            }
            out.nodes.push(b);
            let first = &out.nodes[0];
            let last = out.nodes.last().unwrap();
            if out.nodes.len() > 4
                && dist(last, first, ctx.len) < 0.75 * h
                && last.dot_tangent(&first.tau_g, first.tau_s) > 0.0
            {
                // Closed loop: end on the start.
                let mut closing = first.clone();
                closing.tau_g = last.tau_g;
                closing.tau_s = last.tau_s;
                out.nodes.push(closing);
                break;
            }
        }
        if !ctx.isolated {
            // A located end that slid onto the branch of the pole is no point of a circle.
            while out.nodes.len() > 1 && out.nodes.last().is_some_and(|n| !circle_point(n)) {
                out.nodes.pop();
            }
        }
        Ok(out)
    }
}
