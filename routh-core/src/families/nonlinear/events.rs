//! Nonlinear events along the branches of a bifurcation diagram (docs/method.md §10.7): on
//! gyroscopically stabilised stretches, the zeros of Arnold's determinant
//! ([`EventKind::ArnoldDegenerate`]) and the 1:2 and 1:3 resonances ([`EventKind::Resonance`]).
//!
//! One engine for the post-pass [`nonlinear_events`] and for
//! [`ContinuationOptions::nonlinear`](crate::ContinuationOptions::nonlinear): sign changes of
//! `D/scale`, `ω₁/ω₂ − 2` and `ω₁/ω₂ − 3` between consecutive points of a branch are bracketed and
//! located by the crate's event locator ([`crate::solve::locate`], regula falsi with the Illinois
//! modification) to `|Δs| ≤ s_tol·max(1, |s|)`, re-solving the steady motion (and its nonlinear
//! analysis) at each intermediate `s` by Newton from the interpolated γ. A sign change of D
//! through a pole (D has small divisors at a 1:2 resonance) is not a zero and is dropped: the
//! located point must have `|D| ≤ 1e−6·scale`. The same location ([`locate_crossing`]) places
//! the curves of the atlas (`nonlinear/atlas.rs`).

use nalgebra::Vector3;

use crate::error::RouthError;
use crate::families::{BifurcationDiagram, BranchEvent, ContinuationOptions, EventKind};
use crate::model::Routhian;
use crate::nonlinear::Jet;
use crate::nonlinear::{
    nonlinear_stability, nonlinear_stability_after, nonlinear_stability_from_jet, NonlinearOptions,
    NonlinearReport,
};
use crate::nonlinear::{NonlinearVerdict, Resonance, RouthianJet};
use crate::solve::locate::{locate, within, End, Stop};
use crate::stability::{classify_with, ClassifyOptions, Stability, StabilityReport};
use crate::steady::{steady_motion_near, SteadyMotion};

/// A located zero of `D` is kept only if `|D|/scale` is below this there (else it was a pole).
const POLE_CUT: f64 = 1e-6;

/// The nonlinear verdicts around a nonlinear event of a diagram: what
/// [`BranchEvent::nonlinear`] carries for [`EventKind::ArnoldDegenerate`] and
/// [`EventKind::Resonance`] (the linear verdicts `before`, `after` of the event are
/// `GyroscopicallyStabilized` on both sides).
///
/// ```
/// use routh_core::families::NonlinearEventVerdicts;
/// use routh_core::{NonlinearVerdict, Resonance};
/// let v = NonlinearEventVerdicts {
///     resonance: Some(Resonance::OneToTwo),
///     before: NonlinearVerdict::LyapunovStable,
///     at: NonlinearVerdict::Unstable,
///     after: NonlinearVerdict::LyapunovStable,
/// };
/// assert_eq!(v.to_string(), "1:2 resonance: Lyapunov stable | unstable | Lyapunov stable");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NonlinearEventVerdicts {
    /// Which resonance, for [`EventKind::Resonance`]; `None` for a zero of D.
    pub resonance: Option<Resonance>,
    /// The nonlinear verdict at the branch point just before (in the branch's point order).
    pub before: NonlinearVerdict,
    /// The verdict at the event itself (e.g. `Unstable` at a 1:2 resonance with a non-zero
    /// resonant term, `Undecided` where D = 0).
    pub at: NonlinearVerdict,
    /// The nonlinear verdict at the branch point just after.
    pub after: NonlinearVerdict,
}

impl std::fmt::Display for NonlinearEventVerdicts {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.resonance {
            Some(r) => write!(f, "{r} resonance")?,
            None => f.write_str("D = 0")?,
        }
        write!(f, ": {} | {} | {}", self.before, self.at, self.after)
    }
}

/// A nonlinear event on a branch, with the nonlinear verdicts on either side.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NonlinearEvent {
    /// [`EventKind::ArnoldDegenerate`] or [`EventKind::Resonance`].
    pub kind: EventKind,
    /// Which resonance, for [`EventKind::Resonance`].
    pub resonance: Option<Resonance>,
    /// Where, in the parameter (to `s_tol·max(1, |s|)`).
    pub s: f64,
    /// The steady motion there.
    pub gamma: Vector3<f64>,
    /// The index of the branch in [`BifurcationDiagram::branches`].
    pub branch: usize,
    /// The nonlinear verdict at the branch point just before (in the branch's point order).
    pub before: NonlinearVerdict,
    /// The verdict at the event itself (e.g. `Unstable` at a 1:2 resonance).
    pub at: NonlinearVerdict,
    /// The nonlinear verdict at the branch point just after.
    pub after: NonlinearVerdict,
}

impl NonlinearEvent {
    /// The nonlinear verdicts around the event.
    pub fn verdicts(&self) -> NonlinearEventVerdicts {
        NonlinearEventVerdicts {
            resonance: self.resonance,
            before: self.before,
            at: self.at,
            after: self.after,
        }
    }

    /// The event as a [`BranchEvent`] of the diagram: linear verdicts on both sides
    /// (`GyroscopicallyStabilized`), the nonlinear ones in [`BranchEvent::nonlinear`].
    pub fn to_branch_event(&self) -> BranchEvent {
        BranchEvent {
            kind: self.kind,
            s: self.s,
            gamma: self.gamma,
            branch: self.branch,
            before: Stability::GyroscopicallyStabilized,
            after: Stability::GyroscopicallyStabilized,
            nonlinear: Some(self.verdicts()),
        }
    }
}

/// The three functions whose zeros are the events: `D/scale`, `ω₁/ω₂ − 2`, `ω₁/ω₂ − 3` (NaN
/// off the gyroscopic stretches).
pub(crate) fn indicators(rep: &NonlinearReport) -> [f64; 3] {
    let [w1, w2] = rep.frequencies;
    let [c20, c11, c02] = rep.normal_form;
    let scale = c20.abs() * w2 * w2 + c11.abs() * w1 * w2 + c02.abs() * w1 * w1;
    [rep.arnold_determinant / scale, w1 / w2 - 2.0, w1 / w2 - 3.0]
}

/// The kind and resonance of indicator `k`.
pub(crate) fn indicator_kind(k: usize) -> (EventKind, Option<Resonance>) {
    match k {
        0 => (EventKind::ArnoldDegenerate, None),
        1 => (EventKind::Resonance, Some(Resonance::OneToTwo)),
        _ => (EventKind::Resonance, Some(Resonance::OneToThree)),
    }
}

/// A steady motion re-solved at a parameter, with its nonlinear report.
pub(crate) type Solved = (SteadyMotion, NonlinearReport);

/// Re-solves the steady motion at a parameter from a guess of γ, and analyses it: fully
/// (`true`), or only as far as the frequencies (`false`: the linear test, [`frequencies_only`]).
pub(crate) type Solve<'a> = dyn Fn(f64, &Vector3<f64>, bool) -> Result<Solved, RouthError> + 'a;

/// The report of a steady motion as far as the frequencies: its linear test (relaxed next to a
/// linear event, as [`analyse_with_tape`]) and `ω₁ ≥ ω₂` from the roots `±iω` of `f₂` where it is
/// gyroscopically stabilised (else NaN); the rest NaN or undecided. Enough for the resonance
/// indicators `ω₁/ω₂ − 2`, `ω₁/ω₂ − 3`, at the cost of the linear test, not of the Birkhoff
/// normal form.
pub(crate) fn frequencies_only<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    opts: &ClassifyOptions,
) -> Result<NonlinearReport, RouthError> {
    let linear = match classify_with(model, steady, opts) {
        Err(RouthError::NotASteadyMotion { .. }) => {
            let relaxed = ClassifyOptions {
                steady_tol: 0.5,
                ..opts.clone()
            };
            classify_with(model, steady, &relaxed)?
        }
        r => r?,
    };
    let mut frequencies = [f64::NAN; 2];
    if linear.verdict == Stability::GyroscopicallyStabilized {
        let mut w = linear.f2_roots.map(|r| r.im.abs());
        w.sort_by(|a, b| b.total_cmp(a));
        frequencies = [w[0], w[3]];
    }
    Ok(NonlinearReport::undecided(linear, frequencies))
}

/// The nonlinear analysis of a member's steady motion, with its linear report when known (a
/// branch point's, when the diagram classified it with the options of the analysis).
pub(crate) type Analyse<'a, M> =
    dyn Fn(&M, &SteadyMotion, Option<&StabilityReport>) -> Result<NonlinearReport, RouthError> + 'a;

/// One end of a bracket of an indicator: the parameter, the indicator's value and γ there.
pub(crate) type Bracketed = (f64, Vector3<f64>, f64);

/// Budget of re-solves (each a nonlinear analysis) of one crossing.
const LOCATE_BUDGET: usize = 100;

/// Locates the zero of indicator `k` between `a` and `b` (values of opposite signs) with the
/// crate's event locator ([`crate::solve::locate`]). `solve(t, guess, full)` re-solves the steady motion
/// at `t` from `guess` (γ interpolated between the bracket's ends), for a resonance (`k ≥ 1`)
/// only as far as the frequencies and fully once, at the located point if `report` asks for the
/// nonlinear report there (else the returned report is the frequencies'); the search stops once the
/// better end is within `tol(t)` of the zero (bracket width, or its secant estimate), after at
/// least one re-solve. `None` when a re-solve fails or leaves the gyroscopic stretch, or when a
/// sign change of D is a pole; else the better end and the solution there.
pub(crate) fn locate_crossing(
    solve: &Solve<'_>,
    k: usize,
    a: Bracketed,
    b: Bracketed,
    tol: &dyn Fn(f64) -> f64,
    report: bool,
) -> Option<(f64, Solved)> {
    type Point = (Vector3<f64>, Option<Solved>);
    let end = |(at, gamma, value): Bracketed| End::<Point> {
        at,
        value,
        point: (gamma, None),
    };
    let found = locate(
        end(a),
        end(b),
        LOCATE_BUDGET,
        |t, lo, hi| {
            let f = (t - lo.at) / (hi.at - lo.at);
            let guess = (lo.point.0 + f * (hi.point.0 - lo.point.0)).normalize();
            let Ok((st, rep)) = solve(t, &guess, k == 0) else {
                return Ok::<_, ()>(None);
            };
            let v = indicators(&rep)[k];
            Ok((!v.is_nan()).then_some((v, (st.gamma, Some((st, rep))))))
        },
        |lo, hi| {
            let solved = lo.point.1.is_some() || hi.point.1.is_some();
            solved && within(lo, hi, tol(lo.at.abs().max(hi.at.abs())))
        },
    )
    .ok()?;
    if found.stop == Stop::SolveFailed {
        return None;
    }
    let (gamma, solved) = (found.best.point.0, found.best.point.1?);
    let solved = if k == 0 || !report {
        solved
    } else {
        solve(found.best.at, &gamma, true).ok()?
    };
    if k == 0 && indicators(&solved.1)[0].abs() > POLE_CUT {
        return None; // a pole of D, not a zero
    }
    Some((found.best.at, solved))
}

/// A point of a gyroscopically stabilised stretch: `s`, γ and the nonlinear report.
type Probe = (f64, Vector3<f64>, NonlinearReport);

/// Fractions of a step at which a stretch's end is probed, nearest the end first.
const END_PROBES: [f64; 3] = [1e-6, 1e-4, 1e-2];

/// The engine: the nonlinear events of the isolated branches of `diagram` (built from
/// `family`), the steady motions analysed by `analyse`, located to `|Δs| ≤ s_tol·max(1, |s|)`.
///
/// A stretch is scanned from its first to its last gyroscopically stabilised branch point and,
/// beyond them, to a point probed next to the linear event or verdict change that ends it (at
/// `10⁻⁶`, else `10⁻⁴`, `10⁻²` of the step from there): a resonance between a Hamiltonian–Hopf
/// point (ω₁ = ω₂) and the first point of the stretch is found too. A branch point whose
/// analysis fails with [`RouthError::NotASteadyMotion`] (next to a linear event, where the
/// diagram classified it on the corrector's word) interrupts the stretch; other errors are
/// returned. With `same_linear` the branch points' reports are those `classify` gives (the
/// diagram was built with these options), and their analyses start from them.
pub(crate) fn branch_events<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: &F,
    analyse: &Analyse<'_, M>,
    classify: &ClassifyOptions,
    same_linear: bool,
    diagram: &BifurcationDiagram,
    s_tol: f64,
) -> Result<Vec<NonlinearEvent>, RouthError> {
    let solve = |s: f64, guess: &Vector3<f64>, full: bool| -> Result<Solved, RouthError> {
        let (model, p) = family(s);
        let steady = steady_motion_near(&model, *guess, p)?;
        let rep = if full {
            analyse(&model, &steady, None)?
        } else {
            frequencies_only(&model, &steady, classify)?
        };
        Ok((steady, rep))
    };
    // A quarter of the tolerance: the secant's estimate of the distance is an estimate.
    let tol = |s: f64| 0.25 * s_tol * s.max(1.0);
    let gyroscopic = |rep: &NonlinearReport| {
        rep.linear.verdict == Stability::GyroscopicallyStabilized
            && rep.frequencies.iter().all(|w| w.is_finite())
    };
    // A point of the stretch next to the branch point `end` that bounds it, towards `(s, γ)`.
    let probe = |end: &crate::families::BranchSample, s: f64, g: &Vector3<f64>| -> Option<Probe> {
        END_PROBES.iter().find_map(|&f| {
            let at = end.s + f * (s - end.s);
            let guess = (end.steady.gamma + f * (g - end.steady.gamma)).normalize();
            let (st, rep) = solve(at, &guess, true).ok()?;
            gyroscopic(&rep).then_some((at, st.gamma, rep))
        })
    };
    // The events between two points of a stretch, in the order `a` → `b` of the branch.
    let scan = |bi: usize, a: &Probe, b: &Probe, events: &mut Vec<NonlinearEvent>| {
        let (ia, ib) = (indicators(&a.2), indicators(&b.2));
        for k in 0..3 {
            if ia[k] * ib[k] >= 0.0 || ia[k].is_nan() || ib[k].is_nan() {
                continue;
            }
            let Some((s, (st, rm))) =
                locate_crossing(&solve, k, (a.0, a.1, ia[k]), (b.0, b.1, ib[k]), &tol, true)
            else {
                continue;
            };
            let (kind, resonance) = indicator_kind(k);
            events.push(NonlinearEvent {
                kind,
                resonance,
                s,
                gamma: st.gamma,
                branch: bi,
                before: a.2.verdict,
                at: rm.verdict,
                after: b.2.verdict,
            });
        }
    };
    let mut events = Vec::new();
    for (bi, branch) in diagram.branches.iter().enumerate() {
        if !branch.isolated {
            continue;
        }
        let mut prev: Option<Probe> = None;
        let mut last: Option<&crate::families::BranchSample> = None;
        for q in &branch.points {
            if q.report.verdict != Stability::GyroscopicallyStabilized {
                // The stretch ends between `prev` and `q`: scan up to a probe next to `q`.
                if let Some(p0) = prev.take() {
                    if let Some(end) = probe(q, p0.0, &p0.1) {
                        scan(bi, &p0, &end, &mut events);
                    }
                }
                last = Some(q);
                continue;
            }
            let (model, _) = family(q.s);
            let rep = match analyse(&model, &q.steady, same_linear.then_some(&q.report)) {
                Ok(rep) => rep,
                Err(RouthError::NotASteadyMotion { .. }) => {
                    prev = None;
                    last = None;
                    continue;
                }
                Err(e) => return Err(e),
            };
            let cur = (q.s, q.steady.gamma, rep);
            if prev.is_none() {
                // The stretch starts between `last` and `q`: from a probe next to `last`.
                prev = last
                    .filter(|l| l.report.verdict != Stability::GyroscopicallyStabilized)
                    .and_then(|l| probe(l, q.s, &q.steady.gamma));
            }
            if let Some(p0) = &prev {
                scan(bi, p0, &cur, &mut events);
            }
            prev = Some(cur);
            last = Some(q);
        }
    }
    events.sort_by(|a, b| a.s.total_cmp(&b.s));
    Ok(events)
}

/// The nonlinear events of the branches of `diagram` (built from `family`), `r` giving the Routh
/// function of the family's model at jets. Each is located to `|Δs| ≤ s_tol·max(1, |s|)`.
///
/// A post-pass over a finished diagram, for models without a Routh-function tape (hand-written
/// ones); for derived and run-time models [`ContinuationOptions::nonlinear`] adds the same events
/// to the diagram itself.
///
/// Errors: those of [`nonlinear_stability_from_jet`] at a branch point, [`RouthError::InvalidOption`]
/// for `s_tol` outside `(0, 1)`.
pub fn nonlinear_events<M, F, J>(
    family: F,
    r: J,
    diagram: &BifurcationDiagram,
    opts: &NonlinearOptions,
    s_tol: f64,
) -> Result<Vec<NonlinearEvent>, RouthError>
where
    M: Routhian,
    F: Fn(f64) -> (M, f64),
    J: Fn(&M, &[Jet; 3], &[Jet; 3], f64) -> Jet,
{
    if !(s_tol > 0.0 && s_tol < 1.0) {
        return Err(RouthError::InvalidOption {
            what: "s_tol",
            reason: format!("must be in (0, 1) (got {s_tol:e})"),
        });
    }
    opts.validate()?;
    // The diagram's options are not known: each analysis classifies its steady motion.
    let analyse = |model: &M, steady: &SteadyMotion, _: Option<&StabilityReport>| {
        let jets = |w: &[Jet; 3], g: &[Jet; 3], p: f64| r(model, w, g, p);
        nonlinear_stability_from_jet(model, steady, &jets as &dyn RouthianJet, opts)
    };
    branch_events(&family, &analyse, &opts.classify, false, diagram, s_tol)
}

/// [`nonlinear_stability`], and where the steady motion is next to a linear event (the diagram
/// and the atlas classify such points on their corrector's word) with the tolerance of (33)
/// relaxed as they do.
pub(crate) fn analyse_with_tape<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    opts: &NonlinearOptions,
) -> Result<NonlinearReport, RouthError> {
    match nonlinear_stability(model, steady, opts) {
        Err(RouthError::NotASteadyMotion { .. }) => {
            let relaxed = NonlinearOptions {
                classify: ClassifyOptions {
                    steady_tol: 0.5,
                    ..opts.classify.clone()
                },
                ..opts.clone()
            };
            nonlinear_stability(model, steady, &relaxed)
        }
        r => r,
    }
}

/// The error of a model without a Routh-function tape asked for the nonlinear test along a
/// family.
pub(crate) fn needs_tape<M: Routhian>(model: &M, what: &'static str) -> Result<(), RouthError> {
    if model.routh_tape().is_some() {
        return Ok(());
    }
    Err(RouthError::InvalidModel {
        what: "Routh function tape",
        reason: format!(
            "{what} needs a derived or run-time model (R as an expression tape); for a \
             hand-written model use families::nonlinear_events with a RouthianJet"
        ),
    })
}

/// What [`ContinuationOptions::nonlinear`] adds to a finished diagram: its nonlinear events as
/// [`BranchEvent`]s (the diagram's events stay sorted by `s`), located to `event_tol`. Nothing
/// when the option is off.
pub(crate) fn add_to_diagram<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: &F,
    diagram: &mut BifurcationDiagram,
    opts: &ContinuationOptions,
) -> Result<(), RouthError> {
    let Some(nl) = &opts.nonlinear else {
        return Ok(());
    };
    nl.validate()?;
    let Some(first) = diagram.branches.iter().find_map(|b| b.points.first()) else {
        return Ok(());
    };
    needs_tape(&family(first.s).0, "ContinuationOptions::nonlinear")?;
    let analyse = |model: &M, steady: &SteadyMotion, linear: Option<&StabilityReport>| match linear
    {
        Some(l) => nonlinear_stability_after(model, steady, Some(l), nl),
        None => analyse_with_tape(model, steady, nl),
    };
    // The branch points were classified with `opts.classify` (relaxed next to a linear event as
    // `analyse_with_tape` relaxes it): their reports are the analysis's own linear test when the
    // options agree.
    let same_linear = opts.classify == nl.classify;
    let events = branch_events(
        family,
        &analyse,
        &nl.classify,
        same_linear,
        diagram,
        opts.event_tol,
    )?;
    diagram
        .events
        .extend(events.iter().map(NonlinearEvent::to_branch_event));
    diagram.events.sort_by(|a, b| a.s.total_cmp(&b.s));
    Ok(())
}
