//! Nonlinear events along the branches of a finished bifurcation diagram (docs/method.md
//! §10.7): on gyroscopically stabilised stretches, the zeros of Arnold's determinant
//! ([`EventKind::ArnoldDegenerate`]) and the 1:2 and 1:3 resonances ([`EventKind::Resonance`]).
//!
//! A post-pass: sign changes of `D/scale`, `ω₁/ω₂ − 2` and `ω₁/ω₂ − 3` between consecutive
//! points of a branch are bracketed and bisected to `|Δs| ≤ s_tol·max(1, |s|)`, re-solving the
//! steady motion at each intermediate `s` by Newton from the interpolated γ. A sign change of D
//! through a pole (D has small divisors at a 1:2 resonance) is not a zero and is dropped: the
//! located point must have `|D| ≤ 1e−6·scale`.

use nalgebra::Vector3;

use super::jet::Jet;
use super::{nonlinear_stability_with, NonlinearOptions, NonlinearReport, NonlinearVerdict};
use super::{Resonance, RouthianJet};
use crate::error::RouthError;
use crate::families::{BifurcationDiagram, BranchEvent, EventKind};
use crate::model::Routhian;
use crate::stability::Stability;
use crate::steady::{steady_motion_near, SteadyMotion};

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
    /// The verdict at the verdict at the event itself (e.g. `Unstable` at a 1:2 resonance).
    pub at: NonlinearVerdict,
    /// The nonlinear verdict at the branch point just after.
    pub after: NonlinearVerdict,
}

impl NonlinearEvent {
    /// The event as a [`BranchEvent`] of the diagram (linear verdicts on both sides).
    pub fn to_branch_event(&self) -> BranchEvent {
        BranchEvent {
            kind: self.kind,
            s: self.s,
            gamma: self.gamma,
            branch: self.branch,
            before: Stability::GyroscopicallyStabilized,
            after: Stability::GyroscopicallyStabilized,
        }
    }
}

/// The three functions whose zeros are the events.
fn indicators(rep: &NonlinearReport) -> [f64; 3] {
    let [w1, w2] = rep.frequencies;
    let [c20, c11, c02] = rep.normal_form;
    let scale = c20.abs() * w2 * w2 + c11.abs() * w1 * w2 + c02.abs() * w1 * w1;
    [rep.arnold_determinant / scale, w1 / w2 - 2.0, w1 / w2 - 3.0]
}

/// The nonlinear events of the branches of `diagram` (built from `family`), `r` giving the Routh
/// function of the family's model at jets. Each is located to `|Δs| ≤ s_tol·max(1, |s|)`.
///
/// Errors: those of [`nonlinear_stability_with`] at a branch point, [`RouthError::InvalidOption`]
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
    let analyse =
        |s: f64, guess: &Vector3<f64>| -> Result<(SteadyMotion, NonlinearReport), RouthError> {
            let (model, p) = family(s);
            let steady = steady_motion_near(&model, *guess, p)?;
            let jets = |w: &[Jet; 3], g: &[Jet; 3], p: f64| r(&model, w, g, p);
            let rep = nonlinear_stability_with(&model, &steady, &jets as &dyn RouthianJet, opts)?;
            Ok((steady, rep))
        };
    let mut events = Vec::new();
    for (bi, branch) in diagram.branches.iter().enumerate() {
        if !branch.isolated {
            continue;
        }
        let mut prev: Option<(f64, Vector3<f64>, NonlinearReport)> = None;
        for q in &branch.points {
            if q.report.verdict != Stability::GyroscopicallyStabilized {
                prev = None;
                continue;
            }
            let (model, _) = family(q.s);
            let jets = |w: &[Jet; 3], g: &[Jet; 3], p: f64| r(&model, w, g, p);
            let rep = nonlinear_stability_with(&model, &q.steady, &jets as &dyn RouthianJet, opts)?;
            if let Some((s0, g0, rep0)) = &prev {
                let (a, b) = (indicators(rep0), indicators(&rep));
                for k in 0..3 {
                    if a[k] * b[k] >= 0.0 || a[k].is_nan() || b[k].is_nan() {
                        continue;
                    }
                    // Bisection on s, the steady motion re-solved from the nearer end's γ.
                    let (mut lo, mut hi) = (*s0, q.s);
                    let (mut glo, mut ghi) = (*g0, q.steady.gamma);
                    let mut at = None;
                    let mut failed = false;
                    while (hi - lo).abs() > s_tol * hi.abs().max(1.0) {
                        let mid = 0.5 * (lo + hi);
                        let guess = (glo + ghi).normalize();
                        let Ok((st, rm)) = analyse(mid, &guess) else {
                            failed = true;
                            break;
                        };
                        let v = indicators(&rm)[k];
                        if v * a[k] > 0.0 {
                            lo = mid;
                            glo = st.gamma;
                        } else {
                            hi = mid;
                            ghi = st.gamma;
                        }
                        at = Some((st, rm));
                    }
                    let Some((st, rm)) = at else { continue };
                    if failed {
                        continue;
                    }
                    if k == 0 && indicators(&rm)[0].abs() > 1e-6 {
                        continue; // a pole of D, not a zero
                    }
                    events.push(NonlinearEvent {
                        kind: if k == 0 {
                            EventKind::ArnoldDegenerate
                        } else {
                            EventKind::Resonance
                        },
                        resonance: match k {
                            1 => Some(Resonance::OneToTwo),
                            2 => Some(Resonance::OneToThree),
                            _ => None,
                        },
                        s: 0.5 * (lo + hi),
                        gamma: st.gamma,
                        branch: bi,
                        before: rep0.verdict,
                        at: rm.verdict,
                        after: rep.verdict,
                    });
                }
            }
            prev = Some((q.s, q.steady.gamma, rep));
        }
    }
    events.sort_by(|a, b| a.s.total_cmp(&b.s));
    Ok(events)
}
