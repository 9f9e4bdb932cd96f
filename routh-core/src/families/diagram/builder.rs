//! The bookkeeping of a diagram: the branches and events recorded so far, seeding by global
//! searches, following a branch both ways, the coverage test and the count checks.

use nalgebra::Vector3;

use super::CountCheck;
use crate::error::RouthError;
use crate::families::continuation::{Ctx, Node};
use crate::families::equations::{at, member};
use crate::families::{
    BifurcationDiagram, Branch, BranchEvent, ContinuationOptions, EventKind, StopReason,
};
use crate::model::Routhian;
use crate::solve::path::row::LinearRow;
use crate::sphere::local::Local;
use crate::stability::Stability;
use crate::steady::steady_motion_search;

/// A branch point found on a branch, where new branches may start.
#[derive(Debug, Clone)]
pub(super) struct Switch {
    pub(super) node: Node,
    pub(super) isolated: bool,
}

/// One direction of a branch, as [`Builder::trace`] followed it.
pub(super) struct Traced {
    pub(super) nodes: Vec<Node>,
    pub(super) events: Vec<(EventKind, Node, Stability, Stability)>,
    pub(super) switches: Vec<Switch>,
    /// Continuation steps spent (out of [`ContinuationOptions::max_steps`]).
    pub(super) steps: usize,
    /// Set when the budget of steps ran out before the branch ended.
    pub(super) stop: Option<StopReason>,
}

/// Why [`Builder::start_branch`] started no branch at a steady motion.
#[derive(Debug, Clone, Copy)]
pub(super) enum NotStarted {
    /// The corrector at fixed `s` did not converge; the smallest relative residual it reached.
    Corrector(f64),
    /// The Jacobian `[K | F_s]` has rank below 2 there: a bifurcation point, with no tangent.
    Singular,
    /// `K` has a zero eigenvalue at an isolated steady motion (a fold or a branch point), or
    /// none at a point of a circle.
    Degenerate,
}

/// `(γ₁, γ₂, γ₃)` for messages.
pub(super) fn show(g: &Vector3<f64>) -> String {
    format!("({:+.9}, {:+.9}, {:+.9})", g.x, g.y, g.z)
}

pub(super) struct Builder<'a, M, F> {
    pub(super) family: &'a F,
    pub(super) range: (f64, f64),
    pub(super) opts: &'a ContinuationOptions,
    pub(super) branches: Vec<(Vec<Node>, bool)>,
    pub(super) events: Vec<BranchEvent>,
    pub(super) pending: Vec<Switch>,
    pub(super) done_switches: Vec<(f64, Vector3<f64>)>,
    /// The first budget that ran out, if any.
    pub(super) stop: Option<StopReason>,
    pub(super) _model: std::marker::PhantomData<fn() -> M>,
}

impl<'a, M: Routhian, F: Fn(f64) -> (M, f64)> Builder<'a, M, F> {
    pub(super) fn new(family: &'a F, range: (f64, f64), opts: &'a ContinuationOptions) -> Self {
        Builder {
            family,
            range,
            opts,
            branches: Vec::new(),
            events: Vec::new(),
            pending: Vec::new(),
            done_switches: Vec::new(),
            stop: None,
            _model: std::marker::PhantomData,
        }
    }

    pub(super) fn ctx(&self, isolated: bool, scale: f64) -> Ctx<'a, M, F> {
        let mut c = Ctx::new(self.family, self.range, self.opts);
        c.isolated = isolated;
        c.scale = scale;
        c
    }

    pub(super) fn len(&self) -> f64 {
        self.range.1 - self.range.0
    }

    /// Seeds every steady motion at `s` that no branch covers yet. A seed value that falls on
    /// an event (a steady motion there is degenerate, or the corrector or the classification
    /// fails at it) is never fatal: the seed is moved by `±1.3e−3` and then `±7.1e−3` of the
    /// range (inside it) and the search repeated there; when every move fails too the seed is
    /// dropped (the branches through an event are found from their regular points by the other
    /// seeds, the branch switching and the count checks).
    ///
    /// Errors: those of the family and the model (bad input), and of [`Builder::follow`] (a
    /// branch that cannot be continued from the seed nor from any moved seed).
    pub(super) fn seed_all(&mut self, s: f64) -> Result<(), RouthError> {
        let len = self.len();
        let mut first_failure = None;
        for shift in [0.0, 1.3e-3, -1.3e-3, 7.1e-3, -7.1e-3] {
            let t = s + shift * len;
            if t < self.range.0 || t > self.range.1 {
                continue;
            }
            match self.seed_at(t) {
                Ok(true) => return Ok(()),
                Ok(false) => {}
                // A branch started from a seed on an event can fail to continue (a degenerate
                // point taken for a point of a circle); a branch that fails from every moved
                // seed as well is a family that is not smooth: that is an error.
                Err(e @ RouthError::AtParameter { .. })
                    if matches!(
                        &e,
                        RouthError::AtParameter { source, .. }
                            if matches!(**source, RouthError::NoConvergence { .. })
                    ) =>
                {
                    first_failure.get_or_insert(e);
                }
                Err(e) => return Err(e),
            }
        }
        first_failure.map_or(Ok(()), Err)
    }

    /// [`Builder::seed_all`] at exactly `s`: `Ok(false)` when some steady motion there started no
    /// branch (or the search failed to converge).
    fn seed_at(&mut self, s: f64) -> Result<bool, RouthError> {
        let (m, p) = member(self.family, s)?;
        let motions = match steady_motion_search(&m, p, &self.opts.search).map(|r| r.motions) {
            Ok(v) => v,
            Err(RouthError::NoConvergence { .. }) => return Ok(false),
            Err(e) => return Err(at(s, e)),
        };
        let mut all = true;
        for sm in motions {
            if self.stop.is_some() {
                break;
            }
            if !self.covered(s, &sm.gamma, sm.isolated)?
                && self.start_branch(sm.gamma, s, sm.isolated)?.is_some()
            {
                all = false;
            }
        }
        Ok(all)
    }

    pub(super) fn scale_at(&self, gamma: &Vector3<f64>, s: f64) -> Result<f64, RouthError> {
        let (m, p) = member(self.family, s)?;
        let l = Local::at(&m, gamma, p).map_err(|e| at(s, e))?;
        let sc = l.scale();
        Ok(if sc > 0.0 && sc.is_finite() { sc } else { 1.0 })
    }

    /// Starts a branch at the steady motion `(gamma, s)` and follows it both ways; `Ok(Some(_))`
    /// (and nothing recorded) when the point is not a regular point of a branch.
    pub(super) fn start_branch(
        &mut self,
        gamma: Vector3<f64>,
        s: f64,
        isolated: bool,
    ) -> Result<Option<NotStarted>, RouthError> {
        let ctx = self.ctx(isolated, self.scale_at(&gamma, s)?);
        // σ fixed at the seed's.
        let row = LinearRow::fixed(3, 0.0);
        let Some((g, s1, _)) = ctx.correct(&gamma, s / ctx.len, &row, None)? else {
            return Ok(Some(NotStarted::Corrector(ctx.failed_residual.get())));
        };
        let Some(start) = ctx.node(&g, s1, None)? else {
            return Ok(Some(NotStarted::Singular));
        };
        // A degenerate point is not a regular point of an isolated branch, and a circle needs
        // its zero eigenvalue.
        let zero = start.eig_zeros() > 0;
        if isolated == zero {
            return Ok(Some(NotStarted::Degenerate));
        }
        // A point of a circle keeps its zero eigenvalue along the branch; a degenerate isolated
        // point that the search took for a point of a curve (the tip of a pitchfork, where the
        // amended potential is quartic along the kernel of K) loses it one step away.
        // A seed that cannot show this (no step along the branch succeeds) is moved.
        if !isolated {
            let mut circle = false;
            for h in [1e-2, 1e-3] {
                if let Some(next) = ctx.advance(&start, h)? {
                    circle = next.eig_zeros() > 0;
                    break;
                }
            }
            if !circle {
                return Ok(Some(NotStarted::Degenerate));
            }
        }
        self.follow(&ctx, start)?;
        Ok(None)
    }

    /// Records the first budget that ran out.
    pub(super) fn stopped(&mut self, why: StopReason) {
        if self.stop.is_none() {
            self.stop = Some(why);
        }
    }

    /// Follows the branch through `start` both ways and records it. When the budget of
    /// branches is spent, records [`StopReason::MaxBranches`] instead.
    ///
    /// Errors: those of [`Builder::trace`] (a branch that cannot be continued).
    pub(super) fn follow(&mut self, ctx: &Ctx<'a, M, F>, start: Node) -> Result<(), RouthError> {
        if self.branches.len() >= self.opts.max_branches {
            self.stopped(StopReason::MaxBranches {
                s: start.s,
                gamma: start.gamma,
            });
            return Ok(());
        }
        let fwd = self.trace(ctx, start.clone(), self.opts.max_steps)?;
        let mut back_start = start.clone();
        back_start.tau_g = -back_start.tau_g;
        back_start.tau_s = -back_start.tau_s;
        let closed = fwd.nodes.len() > 3
            && dist(fwd.nodes.last().unwrap(), &start, ctx.len) < 1e-9
            && fwd.nodes.last().unwrap().s == start.s;
        let back = if closed {
            Traced {
                nodes: vec![back_start],
                events: Vec::new(),
                switches: Vec::new(),
                steps: 0,
                stop: None,
            }
        } else {
            self.trace(ctx, back_start, self.opts.max_steps - fwd.steps)?
        };
        let index = self.branches.len();
        let mut nodes: Vec<Node> = back.nodes.into_iter().skip(1).rev().collect();
        nodes.extend(fwd.nodes);
        for (traced, reversed) in [(back.events, true), (fwd.events, false)] {
            for (kind, n, mut before, mut after) in traced {
                if reversed && kind == EventKind::Fold {
                    std::mem::swap(&mut before, &mut after);
                }
                self.push_event(kind, &n, index, before, after);
            }
        }
        self.pending.extend(back.switches);
        self.pending.extend(fwd.switches);
        for why in [fwd.stop, back.stop].into_iter().flatten() {
            self.stopped(why);
        }
        self.branches.push((nodes, ctx.isolated));
        Ok(())
    }

    pub(super) fn push_event(
        &mut self,
        kind: EventKind,
        n: &Node,
        branch: usize,
        before: Stability,
        after: Stability,
    ) {
        let dup = self.events.iter().any(|e| {
            e.kind == kind
                && (e.s - n.s).abs() <= 1e-7 * 1f64.max(n.s.abs())
                && (e.gamma - n.gamma).norm() < 1e-5
        });
        if !dup {
            self.events.push(BranchEvent {
                kind,
                s: n.s,
                gamma: n.gamma,
                branch,
                before,
                after,
                nonlinear: None,
            });
        }
    }

    /// Whether a recorded branch passes through the steady motion `(gamma, s)` (for circles:
    /// has the same amended potential and ψ̇ there).
    pub(super) fn covered(
        &self,
        s: f64,
        gamma: &Vector3<f64>,
        isolated: bool,
    ) -> Result<bool, RouthError> {
        let (m, p) = member(self.family, s)?;
        let u = m.amended_potential(gamma, p);
        let w = m.psi_dot(&Vector3::zeros(), gamma, p);
        for (nodes, iso) in &self.branches {
            if *iso != isolated {
                continue;
            }
            // A node of the branch at the point itself, on the point's own scale (not the
            // range's: over a range a few ulps wide a branch can be one node, or nodes at the
            // same s, which the segments below do not cover).
            let same_s = |n: f64| (n - s).abs() <= 1e-9 * s.abs().max(1.0);
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-7 * (1.0 + b.abs());
            if nodes.iter().any(|n| {
                same_s(n.s)
                    && if isolated {
                        (n.gamma - gamma).norm() <= 1e-6
                    } else {
                        close(n.point.steady.amended_potential, u)
                            && close(n.point.steady.psi_dot, w)
                    }
            }) {
                return Ok(true);
            }
            for pair in nodes.windows(2) {
                let (a, b) = (&pair[0], &pair[1]);
                if isolated {
                    // Distance in (γ, σ) from the point to the segment: robust at turning points
                    // in s, where the segments' s-ranges need not contain s.
                    let len = self.len();
                    let x = (gamma, s / len);
                    let (ag, asg) = (a.gamma, a.s / len);
                    let (dg, ds) = (b.gamma - a.gamma, (b.s - a.s) / len);
                    let seg2 = dg.norm_squared() + ds * ds;
                    let t = if seg2 > 0.0 {
                        (((x.0 - ag).dot(&dg) + (x.1 - asg) * ds) / seg2).clamp(0.0, 1.0)
                    } else {
                        0.0
                    };
                    let dist = ((x.0 - (ag + t * dg)).norm_squared()
                        + (x.1 - (asg + t * ds)).powi(2))
                    .sqrt();
                    if dist <= 0.3 * seg2.sqrt() + 1e-6 {
                        return Ok(true);
                    }
                    continue;
                }
                let (lo, hi) = (a.s.min(b.s), a.s.max(b.s));
                let pad = 1e-9 * self.len();
                if s < lo - pad || s > hi + pad {
                    continue;
                }
                let t = if hi > lo {
                    ((s - a.s) / (b.s - a.s)).clamp(0.0, 1.0)
                } else {
                    0.5
                };
                let (ua, ub) = (
                    a.point.steady.amended_potential,
                    b.point.steady.amended_potential,
                );
                let (wa, wb) = (a.point.steady.psi_dot, b.point.steady.psi_dot);
                let ui = ua + t * (ub - ua);
                let wi = wa + t * (wb - wa);
                let tol_u = 0.3 * (ub - ua).abs() + 1e-7 * (1.0 + u.abs());
                let tol_w = 0.3 * (wb - wa).abs() + 1e-7 * (1.0 + w.abs());
                if (ui - u).abs() <= tol_u && (wi - w).abs() <= tol_w {
                    return Ok(true);
                }
            }
        }
        Ok(false)
    }

    /// The count of steady motions on the branches against a global search, in the middle of
    /// every interval between consecutive events.
    pub(super) fn count_checks(&self) -> Result<Vec<CountCheck>, RouthError> {
        let mut cuts: Vec<f64> = self.events.iter().map(|e| e.s).collect();
        cuts.push(self.range.0);
        cuts.push(self.range.1);
        cuts.sort_by(f64::total_cmp);
        cuts.dedup_by(|a, b| (*a - *b).abs() <= 1e-6 * (self.range.1 - self.range.0));
        let mut out = Vec::new();
        for w in cuts.windows(2) {
            let s = 0.5 * (w[0] + w[1]);
            let on = self
                .branches
                .iter()
                .map(|(nodes, _)| {
                    nodes
                        .windows(2)
                        .filter(|p| (p[0].s < s) != (p[1].s < s))
                        .count()
                })
                .sum();
            let (m, p) = member(self.family, s)?;
            let found = steady_motion_search(&m, p, &self.opts.search)
                .map_err(|e| at(s, e))?
                .motions
                .len();
            out.push(CountCheck {
                s,
                on_branches: on,
                searched: found,
            });
        }
        Ok(out)
    }

    pub(super) fn finish(mut self) -> BifurcationDiagram {
        self.join_at_branch_points();
        self.events.sort_by(|a, b| a.s.total_cmp(&b.s));
        BifurcationDiagram {
            branches: self
                .branches
                .into_iter()
                .map(|(nodes, isolated)| Branch {
                    points: nodes.into_iter().map(|n| n.point).collect(),
                    isolated,
                })
                .collect(),
            events: self.events,
            stop: self.stop,
            checks: Vec::new(),
        }
    }
}

/// Distance between two nodes in `(γ, σ)`.
pub(super) fn dist(a: &Node, b: &Node, len: f64) -> f64 {
    ((a.gamma - b.gamma).norm_squared() + ((a.s - b.s) / len).powi(2)).sqrt()
}
