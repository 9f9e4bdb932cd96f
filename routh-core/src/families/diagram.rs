//! [`bifurcation_diagram`] and [`continue_branch`]: branches seeded by global searches, followed
//! by continuation, switched at branch points, with their events, and a count check.

use nalgebra::{Vector2, Vector3};

use super::continuation::{changes, test_value, Change, Constraint, Ctx, Node};
use super::equations::member;
use super::{BifurcationDiagram, Branch, BranchEvent, ContinuationOptions, EventKind};
use crate::error::RouthError;
use crate::model::Routhian;
use crate::sphere::tangent_basis;
use crate::stability::Stability;
use crate::steady::{steady_motion_near, steady_motions_with};
use crate::validate::check_finite;

/// One comparison of [`bifurcation_diagram_checked`]: the number of steady motions that the
/// branches give at `s` against the number that [`steady_motions`](crate::steady_motions) finds.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let c = families::bifurcation_diagram_checked(
///     |p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// let first: &families::CountCheck = &c.checks[0];
/// assert_eq!(first.on_branches, first.searched); // the hanging and the sleeping top
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CountCheck {
    /// The parameter value (the middle of an interval between consecutive events).
    pub s: f64,
    /// Steady motions on the branches at `s` (a circle counts once).
    pub on_branches: usize,
    /// Steady motions found by the global search at `s`.
    pub searched: usize,
}

/// A diagram with the count checks made while building it.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let c: families::CheckedDiagram = families::bifurcation_diagram_checked(
///     |p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// assert!(c.consistent());
/// assert_eq!(c.checks.len(), c.diagram.events.len() + 1);
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CheckedDiagram {
    /// The diagram.
    pub diagram: BifurcationDiagram,
    /// One check per interval between consecutive events (empty when
    /// [`ContinuationOptions::verify_counts`] is off).
    pub checks: Vec<CountCheck>,
}

impl CheckedDiagram {
    /// Whether every count check agreed.
    ///
    /// See the example on [`CheckedDiagram`].
    pub fn consistent(&self) -> bool {
        self.checks.iter().all(|c| c.on_branches == c.searched)
    }
}

/// Every branch of steady motions of `family` over `range`, with its events (the contract of
/// the [`families`](super) module). Branches are seeded by global searches
/// ([`steady_motions_with`]) at [`ContinuationOptions::seeds`] values of `s`, followed by
/// pseudo-arclength continuation through folds, and switched at branch points (a pitchfork, or
/// the birth of a circle of steady motions of a symmetric body, which becomes a branch with
/// `isolated: false`). Events are located by solving their defining equation to
/// `|Δs| ≤ event_tol·max(1, |s|)`. Between consecutive events the number of steady motions on the
/// branches is compared with a global search, and missing branches are seeded there
/// ([`bifurcation_diagram_checked`] returns the comparisons).
///
/// Errors: [`RouthError::InvalidOption`] for an empty or non-finite range or invalid options;
/// [`RouthError::AtParameter`] when the family returns an invalid model (e.g. `J` not positive
/// definite) or a non-finite `p_ψ` at some `s`.
///
/// ```
/// use routh_core::{bifurcation_diagram, ContinuationOptions, EventKind};
/// # use test_models::Gyrostat;
///
/// // A Lagrange top A₁ = 1, C = 1.25, mgl = 1 (any model implementing `Routhian`; with the
/// // derive of the `routh` crate it is one struct and one attribute) over the cyclic momentum.
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// // Maievskii's bound p² = 4A₁mgl and the secular bound p² = mglC²/(C − A₁).
/// let hh = d.events.iter().find(|e| e.kind == EventKind::HamiltonianHopf).unwrap();
/// assert!((hh.s - 2.0).abs() < 1e-8);
/// let bp = d.events.iter().find(|e| e.kind == EventKind::BranchPoint).unwrap();
/// assert!((bp.s - 2.5).abs() < 1e-8);
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn bifurcation_diagram<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: F,
    range: (f64, f64),
    opts: &ContinuationOptions,
) -> Result<BifurcationDiagram, RouthError> {
    bifurcation_diagram_checked(family, range, opts).map(|c| c.diagram)
}

/// [`bifurcation_diagram`] with the count checks it made.
///
/// Errors: as [`bifurcation_diagram`].
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let c = families::bifurcation_diagram_checked(
///     |p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// for check in &c.checks {
///     println!("s = {}: {} on branches, {} searched", check.s, check.on_branches, check.searched);
/// }
/// assert!(c.consistent());
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn bifurcation_diagram_checked<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: F,
    range: (f64, f64),
    opts: &ContinuationOptions,
) -> Result<CheckedDiagram, RouthError> {
    validate(range, opts)?;
    let mut b = Builder::new(&family, range, opts);
    let n = opts.seeds.max(2);
    for k in 0..n {
        let s = range.0 + (range.1 - range.0) * k as f64 / (n - 1) as f64;
        b.seed_all(s)?;
    }
    b.switch_all()?;
    let mut checks = Vec::new();
    if opts.verify_counts {
        for round in 0..3 {
            checks = b.count_checks()?;
            let missing: Vec<f64> = checks
                .iter()
                .filter(|c| c.on_branches < c.searched)
                .map(|c| c.s)
                .collect();
            if missing.is_empty() || round == 2 {
                break;
            }
            for s in missing {
                b.seed_all(s)?;
            }
            b.switch_all()?;
        }
    }
    Ok(CheckedDiagram {
        diagram: b.finish(),
        checks,
    })
}

/// The branch through the steady motion nearest `gamma_guess` at `s0` (found by Newton on the
/// sphere from the guess), followed over `range` in both directions, with the branches that
/// split off it at its branch points.
///
/// Errors: as [`bifurcation_diagram`], plus [`RouthError::NoConvergence`] when no steady motion
/// is found from the guess and [`RouthError::InvalidOption`] when `s0` is outside the range.
///
/// ```
/// use routh_core::{continue_branch, ContinuationOptions, Vector3};
/// # use test_models::Gyrostat;
///
/// // The sleeping top γ = e₃ of a top with A₁ = 1, C = 1.25, followed over the weight mgl at
/// // p_ψ = 3: it loses secular stability at mgl = p²(C − A₁)/C² = 1.44 and gyroscopic
/// // stabilisation at Maievskii's mgl = p²/(4A₁) = 2.25.
/// let d = continue_branch(
///     |mgl| (Gyrostat::lagrange_top(1.0, 1.25, mgl), 3.0),
///     Vector3::z(), 1.0, (1.0, 3.0), &ContinuationOptions::default())?;
/// let s: Vec<f64> = d.events.iter().filter(|e| e.branch == 0).map(|e| e.s).collect();
/// assert!(s.iter().any(|s| (s - 1.44).abs() < 1e-8));
/// assert!(s.iter().any(|s| (s - 2.25).abs() < 1e-8));
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn continue_branch<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: F,
    gamma_guess: Vector3<f64>,
    s0: f64,
    range: (f64, f64),
    opts: &ContinuationOptions,
) -> Result<BifurcationDiagram, RouthError> {
    validate(range, opts)?;
    check_finite("s0", &[s0])?;
    if s0 < range.0 || s0 > range.1 {
        return Err(RouthError::InvalidOption {
            what: "s0",
            reason: format!(
                "must lie in the range [{}, {}] (got {s0})",
                range.0, range.1
            ),
        });
    }
    let (m, p) = member(&family, s0)?;
    let steady = steady_motion_near(&m, gamma_guess, p).map_err(|e| super::equations::at(s0, e))?;
    let mut b = Builder::new(&family, range, opts);
    b.start_branch(steady.gamma, s0, steady.isolated)?;
    b.switch_all()?;
    Ok(b.finish())
}

fn validate(range: (f64, f64), opts: &ContinuationOptions) -> Result<(), RouthError> {
    check_finite("range", &[range.0, range.1])?;
    let invalid = |what, reason: String| Err(RouthError::InvalidOption { what, reason });
    if range.1 <= range.0 {
        return invalid(
            "range",
            format!(
                "must be (lo, hi) with lo < hi (got ({}, {}))",
                range.0, range.1
            ),
        );
    }
    for (what, v) in [
        ("initial_step", opts.initial_step),
        ("max_step", opts.max_step),
        ("min_step", opts.min_step),
        ("newton_tol", opts.newton_tol),
        ("event_tol", opts.event_tol),
    ] {
        if !(v.is_finite() && v > 0.0 && v < 1.0) {
            return invalid(what, format!("must be in (0, 1) (got {v:e})"));
        }
    }
    if opts.min_step > opts.initial_step || opts.initial_step > opts.max_step {
        return invalid(
            "initial_step",
            "need min_step ≤ initial_step ≤ max_step".to_string(),
        );
    }
    if opts.max_steps == 0 || opts.max_branches == 0 {
        return invalid("max_steps", "budgets must be positive".to_string());
    }
    Ok(())
}

/// A branch point found on a branch, where new branches may start.
#[derive(Debug, Clone)]
struct Switch {
    node: Node,
    isolated: bool,
}

struct Traced {
    nodes: Vec<Node>,
    events: Vec<(EventKind, Node, Stability, Stability)>,
    switches: Vec<Switch>,
}

struct Builder<'a, M, F> {
    family: &'a F,
    range: (f64, f64),
    opts: &'a ContinuationOptions,
    branches: Vec<(Vec<Node>, bool)>,
    events: Vec<BranchEvent>,
    pending: Vec<Switch>,
    done_switches: Vec<(f64, Vector3<f64>)>,
    _model: std::marker::PhantomData<fn() -> M>,
}

impl<'a, M: Routhian, F: Fn(f64) -> (M, f64)> Builder<'a, M, F> {
    fn new(family: &'a F, range: (f64, f64), opts: &'a ContinuationOptions) -> Self {
        Builder {
            family,
            range,
            opts,
            branches: Vec::new(),
            events: Vec::new(),
            pending: Vec::new(),
            done_switches: Vec::new(),
            _model: std::marker::PhantomData,
        }
    }

    fn ctx(&self, isolated: bool, scale: f64) -> Ctx<'a, M, F> {
        let mut c = Ctx::new(self.family, self.range, self.opts);
        c.isolated = isolated;
        c.scale = scale;
        c
    }

    fn len(&self) -> f64 {
        self.range.1 - self.range.0
    }

    /// Seeds every steady motion at `s` that no branch covers yet.
    fn seed_all(&mut self, s: f64) -> Result<(), RouthError> {
        let (m, p) = member(self.family, s)?;
        let motions = steady_motions_with(&m, p, &self.opts.search)
            .map_err(|e| super::equations::at(s, e))?;
        for sm in motions {
            if !self.covered(s, &sm.gamma, sm.isolated)? {
                self.start_branch(sm.gamma, s, sm.isolated)?;
            }
        }
        Ok(())
    }

    fn scale_at(&self, gamma: &Vector3<f64>, s: f64) -> Result<f64, RouthError> {
        let (m, p) = member(self.family, s)?;
        let l =
            super::equations::Local::at(&m, gamma, p).map_err(|e| super::equations::at(s, e))?;
        let sc = l.restricted().norm().max(l.hess.norm());
        Ok(if sc > 0.0 { sc } else { 1.0 })
    }

    /// Starts a branch at the steady motion `(gamma, s)` and follows it both ways.
    fn start_branch(
        &mut self,
        gamma: Vector3<f64>,
        s: f64,
        isolated: bool,
    ) -> Result<(), RouthError> {
        if self.branches.len() >= self.opts.max_branches {
            return Ok(());
        }
        let ctx = self.ctx(isolated, self.scale_at(&gamma, s)?);
        let con = Constraint {
            a_g: Vector3::zeros(),
            a_s: 1.0,
            gamma_ref: gamma,
            sigma_ref: s / ctx.len,
            c: 0.0,
        };
        let Some((g, s1, it)) = ctx.correct(&gamma, s / ctx.len, &con, None)? else {
            return Ok(());
        };
        let Some(start) = ctx.node(&g, s1, None, it)? else {
            return Ok(());
        };
        // A seed at a degenerate point (a bifurcation point hit by a seed value) is not a
        // regular point of an isolated branch, and a circle needs its zero eigenvalue: the
        // branches through such a seed are found from their regular points.
        let zero = start.eig.iter().any(|e| e.abs() <= 1e-6);
        if isolated == zero {
            return Ok(());
        }
        self.follow(&ctx, start)
    }

    /// Follows the branch through `start` both ways and records it.
    fn follow(&mut self, ctx: &Ctx<'a, M, F>, start: Node) -> Result<(), RouthError> {
        let fwd = self.trace(ctx, start.clone())?;
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
            }
        } else {
            self.trace(ctx, back_start)?
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
        self.branches.push((nodes, ctx.isolated));
        Ok(())
    }

    fn push_event(
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
            });
        }
    }

    /// Follows one direction from `start` until the range ends, the branch closes, meets another
    /// branch (a branch of circles reaching its axis) or the budget is spent.
    fn trace(&self, ctx: &Ctx<'a, M, F>, start: Node) -> Result<Traced, RouthError> {
        let opts = self.opts;
        let mut out = Traced {
            nodes: vec![start.clone()],
            events: Vec::new(),
            switches: Vec::new(),
        };
        let mut h = opts.initial_step;
        let mut steps = 0;
        while steps < opts.max_steps {
            steps += 1;
            let a = out.nodes.last().unwrap().clone();
            let Some(b) = ctx.advance(&a, h)? else {
                h *= 0.5;
                if h < opts.min_step {
                    break;
                }
                continue;
            };
            let cos = a.tau_g.dot(&b.tau_g) + a.tau_s * b.tau_s;
            let ch = changes(&a, &b, ctx.isolated);
            let eigen = ch.iter().any(|c| matches!(c, Change::Eigen(_)));
            let disc = ch.contains(&Change::Discriminant);
            // Shorten the step when the tangent turns too fast, when two events share it, or
            // when the verdict changes with no test function changing sign.
            let unexplained = ch.is_empty() && a.verdict() != b.verdict();
            let two_eigen = ch.iter().filter(|c| matches!(c, Change::Eigen(_))).count() > 1;
            if (cos < 0.97 || (eigen && disc) || two_eigen || unexplained)
                && h > 4.0 * opts.min_step
            {
                h *= 0.5;
                continue;
            }
            // Leaving the range: end exactly on its boundary.
            let (lo, hi) = self.range;
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
            if eigen {
                let which = *ch.iter().find(|c| matches!(c, Change::Eigen(_))).unwrap();
                let e = ctx.locate(&a, &b, h, &|n| test_value(which, n))?;
                if ctx.is_branch_point(&e) {
                    if !ctx.isolated {
                        end = true;
                        out.nodes.push(e.clone());
                    } else {
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
                    out.events
                        .push((EventKind::Fold, e, a.verdict(), b.verdict()));
                }
            } else if turn {
                // A turning point in s with no eigenvalue changing sign: the branch passes
                // through the tip of a pitchfork on another branch.
                let e = ctx.locate(&a, &b, h, &|n| n.tau_s)?;
                if ctx.isolated {
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
                    out.events
                        .push((EventKind::HamiltonianHopf, e, a.verdict(), b.verdict()));
                }
            }
            if end {
                break;
            }
            let it = b.iterations;
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
            h = if it <= 2 {
                (1.5 * h).min(opts.max_step)
            } else if it >= 6 {
                (0.7 * h).max(opts.min_step)
            } else {
                h
            };
        }
        Ok(out)
    }

    /// Starts the branches that leave the branch points found so far.
    fn switch_all(&mut self) -> Result<(), RouthError> {
        let mut rounds = 0;
        while let Some(sw) = self.pending.pop() {
            rounds += 1;
            if rounds > 4 * self.opts.max_branches {
                break;
            }
            let n = &sw.node;
            if self
                .done_switches
                .iter()
                .any(|(s, g)| (s - n.s).abs() <= 1e-6 * self.len() && (g - n.gamma).norm() < 1e-5)
            {
                continue;
            }
            self.done_switches.push((n.s, n.gamma));
            let both_zero = n.eig[0].abs() <= 1e-6 && n.eig[1].abs() <= 1e-6;
            let basis = tangent_basis(&n.gamma);
            let eps = 1e-3;
            let mut candidates: Vec<(Vector3<f64>, f64, bool)> = Vec::new();
            if both_zero && sw.isolated {
                // The birth of a circle of steady motions (a symmetric body): any direction.
                // (A double zero without a symmetry is of codimension two in a one-parameter
                // family: not looked for.)
                candidates.push((basis * Vector2::new(1.0, 0.0), 0.0, false));
            } else {
                // At a branch point [K | F_σ] has rank one: its null space is the plane
                // orthogonal to its dominant row r, spanned by the branch's tangent t and r × t.
                let t = nalgebra::Vector3::new(
                    (basis.transpose() * n.tau_g).x,
                    (basis.transpose() * n.tau_g).y,
                    n.tau_s,
                );
                let r1: Vector3<f64> = n.jac.row(0).transpose();
                let r2: Vector3<f64> = n.jac.row(1).transpose();
                let r = if r1.norm() >= r2.norm() { r1 } else { r2 };
                let d = r.cross(&t);
                if d.norm() < 1e-9 {
                    continue;
                }
                let d = d.normalize();
                candidates.push((basis * Vector2::new(d.x, d.y), d.z, true));
            }
            for (dg, ds, isolated) in candidates {
                for sign in [1.0, -1.0] {
                    self.try_switch(n, sign * dg, sign * ds, eps, isolated)?;
                }
            }
        }
        Ok(())
    }

    /// Starts a branch from the branch point `n` in the direction `(dg, ds)` (in `(γ, σ)`) at
    /// distance `eps`, unless a branch already covers it.
    fn try_switch(
        &mut self,
        n: &Node,
        dg: Vector3<f64>,
        ds: f64,
        eps: f64,
        isolated: bool,
    ) -> Result<(), RouthError> {
        if self.branches.len() >= self.opts.max_branches {
            return Ok(());
        }
        let scale = self.scale_at(&n.gamma, n.s)?;
        let ctx = self.ctx(isolated, scale);
        let len = ctx.len;
        let g_p = (n.gamma + eps * dg).normalize();
        let s_p = n.s / len + eps * ds;
        let con = Constraint {
            a_g: dg,
            a_s: ds,
            gamma_ref: n.gamma,
            sigma_ref: n.s / len,
            c: eps,
        };
        let Some((g, s, it)) = ctx.correct(&g_p, s_p, &con, None)? else {
            return Ok(());
        };
        if s < self.range.0 || s > self.range.1 || (g - n.gamma).norm() < 0.2 * eps {
            return Ok(());
        }
        if self.covered(s, &g, isolated)? {
            return Ok(());
        }
        let Some(start) = ctx.node(&g, s, None, it)? else {
            return Ok(());
        };
        // Branches of circles need a zero eigenvalue along them; isolated ones must not be
        // circles.
        let zero = start.eig.iter().any(|e| e.abs() <= 1e-6);
        if isolated == zero {
            return Ok(());
        }
        self.follow(&ctx, start)
    }

    /// Whether a recorded branch passes through the steady motion `(gamma, s)` (for circles:
    /// has the same amended potential and ψ̇ there).
    fn covered(&self, s: f64, gamma: &Vector3<f64>, isolated: bool) -> Result<bool, RouthError> {
        let (m, p) = member(self.family, s)?;
        let u = m.amended_potential(gamma, p);
        let w = m.psi_dot(&Vector3::zeros(), gamma, p);
        for (nodes, iso) in &self.branches {
            if *iso != isolated {
                continue;
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
    fn count_checks(&self) -> Result<Vec<CountCheck>, RouthError> {
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
            let found = steady_motions_with(&m, p, &self.opts.search)
                .map_err(|e| super::equations::at(s, e))?
                .len();
            out.push(CountCheck {
                s,
                on_branches: on,
                searched: found,
            });
        }
        Ok(out)
    }

    fn finish(mut self) -> BifurcationDiagram {
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
        }
    }
}

/// Distance between two nodes in `(γ, σ)`.
fn dist(a: &Node, b: &Node, len: f64) -> f64 {
    ((a.gamma - b.gamma).norm_squared() + ((a.s - b.s) / len).powi(2)).sqrt()
}
