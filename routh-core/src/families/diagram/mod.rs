//! [`bifurcation_diagram`] and [`continue_branch`]: branches seeded by global searches, followed
//! by continuation, switched at branch points, with their events, and a count check.

mod builder;
mod join;
mod smooth;
mod switch;
mod trace;

use nalgebra::Vector3;

use super::{BifurcationDiagram, ContinuationOptions, StopReason};
use crate::error::RouthError;
use crate::families::continuation::CORRECTOR_MAX_ITER;
use crate::families::equations::{at, member};
use crate::model::Routhian;
use crate::steady::steady_motion_near_with;
use crate::validate::check_finite;
use builder::{show, Builder, NotStarted};

/// One comparison of [`BifurcationDiagram::checks`]: the number of steady motions that the
/// branches give at `s` against the number that [`steady_motions`](crate::steady_motions) finds.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &ContinuationOptions::default())?;
/// let first: &families::CountCheck = &d.checks[0];
/// assert_eq!(first.on_branches, first.searched); // the hanging and the sleeping top
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CountCheck {
    /// The parameter value (the middle of an interval between consecutive events).
    pub s: f64,
    /// Steady motions on the branches at `s` (a circle counts once).
    pub on_branches: usize,
    /// Steady motions found by the global search at `s`.
    pub searched: usize,
}

/// Every branch of steady motions of `family` over `range`, with its events (the contract of
/// the [`families`](super) module). Branches are seeded by global searches
/// ([`steady_motion_search`]) at [`ContinuationOptions::seeds`] values of `s`, followed by
/// pseudo-arclength continuation through folds, and switched at branch points (a pitchfork, or
/// the birth of a circle of steady motions of a symmetric body, which becomes a branch with
/// `isolated: false`). Events are located by solving their defining equation to
/// `|Δs| ≤ event_tol·max(1, |s|)`. Between consecutive events the number of steady motions on the
/// branches is compared with a global search, and missing branches are seeded there
/// ([`BifurcationDiagram::checks`] holds the comparisons).
///
/// Seed values that fall on an event (a branch point at a round parameter value, as `p = 2` of
/// the Kovalevskaya top) are moved off it, never fatal; points of a branch next to an event are
/// classified on the corrector's word. Every branch contains its located events and turning
/// points (the tips of pitchforks, folds) as points, so [`BifurcationDiagram::count_at`] and a
/// drawing of the polylines are right away from the events.
///
/// A branch ends only where it leaves the range (exactly on its end), where it closes, or where a
/// branch of circles reaches its axis. A budget that runs out ends the computation with the
/// diagram so far and [`BifurcationDiagram::stop`] saying why ([`StopReason`](super::StopReason):
/// [`ContinuationOptions::max_steps`] on one branch, [`ContinuationOptions::max_branches`]).
/// Errors are kept for bad input:
///
/// - [`RouthError::InvalidOption`] for an empty or non-finite range or invalid options;
/// - [`RouthError::AtParameter`] at the last `s` reached, wrapping [`RouthError::NoConvergence`],
///   when the corrector fails for every step down to [`ContinuationOptions::min_step`] (the
///   branch cannot be continued: the family is not smooth there, or the branch runs into a
///   singularity that is none of the events of [`EventKind`](super::EventKind));
/// - [`RouthError::AtParameter`] when the family returns an invalid model (e.g. `J` not positive
///   definite) or a non-finite `p_ψ` at some `s`.
///
/// [`steady_motion_search`]: crate::steady::steady_motion_search
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
    validate(range, opts)?;
    let mut b = Builder::new(&family, range, opts);
    let n = opts.seeds.max(2);
    for k in 0..n {
        opts.control.report(k, n);
        if opts.control.is_cancelled() {
            b.stopped(StopReason::Interrupted);
            break;
        }
        let s = range.0 + (range.1 - range.0) * k as f64 / (n - 1) as f64;
        b.seed_all(s)?;
    }
    b.switch_all()?;
    opts.control.report(n, n);
    let mut checks = Vec::new();
    if opts.verify_counts && !opts.control.is_cancelled() {
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
    b.join_at_branch_points();
    b.smooth()?;
    let mut diagram = b.finish();
    super::nonlinear::add_to_diagram(&family, &mut diagram, opts)?;
    diagram.checks = checks;
    Ok(diagram)
}

/// The branch through the steady motion nearest `gamma_guess` at `s0` (found by Newton on the
/// sphere from the guess), followed over `range` in both directions, with the branches that
/// split off it at its branch points.
///
/// Errors: as [`bifurcation_diagram`], plus
/// - the errors of [`steady_motion_near`](crate::steady::steady_motion_near) at `s0` (e.g. [`RouthError::NoConvergence`] when
///   Newton's method does not converge from the guess), wrapped in
///   [`RouthError::AtParameter`] with `s: s0`;
/// - [`RouthError::InvalidOption`] naming `s0` when it is outside the range, or when the steady
///   motion found there is not a regular point of a branch (a fold or a branch point at `s0`:
///   a zero eigenvalue of the restricted second variation, or no tangent);
/// - [`RouthError::AtParameter`] wrapping [`RouthError::NoConvergence`] when the corrector at
///   `s0` does not converge from it.
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
    let steady =
        steady_motion_near_with(&m, gamma_guess, p, &opts.search).map_err(|e| at(s0, e))?;
    let mut b = Builder::new(&family, range, opts);
    let not_regular = |why: &str| RouthError::InvalidOption {
        what: "s0",
        reason: format!(
            "the steady motion found from gamma_guess at s0 = {s0}, γ = {}, {why}; start at a \
             regular point of the branch (another s0)",
            show(&steady.gamma)
        ),
    };
    match b.start_branch(steady.gamma, s0, steady.isolated)? {
        None => {}
        Some(NotStarted::Corrector(residual)) => {
            return Err(at(
                s0,
                RouthError::NoConvergence {
                    what: "continue_branch: the corrector at s0 from the steady motion found",
                    iterations: CORRECTOR_MAX_ITER,
                    residual,
                },
            ))
        }
        Some(NotStarted::Singular) => {
            return Err(not_regular(
                "is a bifurcation point (the Jacobian [K | F_s] has rank below 2: no tangent)",
            ))
        }
        Some(NotStarted::Degenerate) => {
            return Err(not_regular(if steady.isolated {
                "is degenerate (a zero eigenvalue of the restricted second variation: a fold or \
                 a branch point)"
            } else {
                "lies on a circle of steady motions whose restricted second variation has no \
                 zero eigenvalue"
            }))
        }
    }
    b.switch_all()?;
    b.join_at_branch_points();
    b.smooth()?;
    let mut diagram = b.finish();
    super::nonlinear::add_to_diagram(&family, &mut diagram, opts)?;
    Ok(diagram)
}

/// The largest [`ContinuationOptions::seeds`] a diagram accepts.
pub const MAX_SEEDS: usize = 100_000;

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
    if !(opts.em_turn_degrees.is_finite() && opts.em_turn_degrees >= 0.0) {
        return invalid(
            "em_turn_degrees",
            format!(
                "must be finite and ≥ 0 (got {}; 0 turns the smoothing off)",
                opts.em_turn_degrees
            ),
        );
    }
    // Each seed is a global search: a million of them is hours; 2^40 never ends.
    if opts.seeds > MAX_SEEDS {
        return invalid(
            "seeds",
            format!("at most {MAX_SEEDS} seed values (got {})", opts.seeds),
        );
    }
    if opts.max_steps == 0 || opts.max_branches == 0 {
        return invalid("max_steps", "budgets must be positive".to_string());
    }
    Ok(())
}
