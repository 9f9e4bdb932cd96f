//! Steady motions together with their verdicts: the first thing most analyses print.
//!
//! [`classified_steady_motions`] runs the global search of [`steady_motions`] (33) and
//! [`classify`] (62)–(64) on each motion found; [`classify_at`] classifies the steady motion at a
//! known critical point (a spin about a principal axis, say) without any search;
//! [`stability_threshold`] the momentum where such a motion becomes stable.

use std::fmt;

use nalgebra::Vector3;

use crate::error::RouthError;
use crate::families::{continue_branch, ContinuationOptions};
use crate::model::Routhian;
use crate::stability::{classify, Stability, StabilityReport};
use crate::steady::{steady_motions, SteadyMotion};

/// A steady motion with its stability report.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Classified {
    /// The cyclic momentum `p_ψ` (9) of the motion.
    pub p_psi: f64,
    /// The steady motion, as found by [`steady_motions`].
    pub motion: SteadyMotion,
    /// Its classification by [`classify`].
    pub report: StabilityReport,
}

impl fmt::Display for Classified {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}\n{}", self.motion, self.report)
    }
}

/// Every steady motion at `p_psi` (the global search of [`steady_motions`]), each classified by
/// [`classify`].
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// // The Lagrange top A₁ = 1, C = 1.25, mgl = 1 at p_ψ = 3: the hanging top, the sleeping top
/// // (secularly stable above the secular bound p² = 2.5) and a circle of tilted precessions.
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let motions = classified_steady_motions(&top, 3.0)?;
/// assert_eq!(motions.len(), 3);
/// for m in &motions {
///     println!("{m}");
/// }
/// # Ok::<(), RouthError>(())
/// ```
pub fn classified_steady_motions<M: Routhian>(
    model: &M,
    p_psi: f64,
) -> Result<Vec<Classified>, RouthError> {
    steady_motions(model, p_psi)?
        .into_iter()
        .map(|motion| {
            let report = classify(model, &motion)?;
            Ok(Classified {
                p_psi,
                motion,
                report,
            })
        })
        .collect()
}

/// The classification of the steady motion at the known critical point `gamma` (normalised
/// here), without any search. An error
/// ([`RouthError::NotASteadyMotion`](crate::RouthError::NotASteadyMotion)) if `gamma` is not a
/// steady motion at `p_psi`.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// // The sleeping Lagrange top is unstable below Maievskii's bound p² = 4A₁mgl = 4.
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let r = classify_at(&top, Vector3::z(), 1.5)?;
/// assert_eq!(r.verdict, Stability::Unstable);
/// # Ok::<(), RouthError>(())
/// ```
pub fn classify_at<M: Routhian>(
    model: &M,
    gamma: Vector3<f64>,
    p_psi: f64,
) -> Result<StabilityReport, RouthError> {
    let motion = SteadyMotion::at(model, gamma, p_psi, true)?;
    classify(model, &motion)
}

/// The `p_ψ` in `[lo, hi]` where the steady motion through the critical point `gamma` (at `lo`)
/// stops being `Unstable`, by continuation of its branch over `p_ψ` ([`continue_branch`]): the
/// first event on the branch, within `1e−9` of `gamma`, whose verdict goes from `Unstable` to a
/// stable one. Its location is solved from the event's defining equation (a zero eigenvalue of
/// the restricted second variation, or a zero discriminant of `f₂`), not bisected. `None` when
/// the motion does not become stable in the range.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// // The sleeping Lagrange top becomes gyroscopically stable at Maievskii's bound
/// // p² = 4A₁mgl: p = 2 for A₁ = 1, mgl = 1.
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// let p = stability_threshold(&top, Vector3::z(), 0.5, 4.0)?.unwrap();
/// assert!((p - 2.0).abs() < 1e-9);
/// # Ok::<(), RouthError>(())
/// ```
pub fn stability_threshold<M: Routhian + Clone>(
    model: &M,
    gamma: Vector3<f64>,
    lo: f64,
    hi: f64,
) -> Result<Option<f64>, RouthError> {
    let d = continue_branch(
        |p| (model.clone(), p),
        gamma,
        lo,
        (lo, hi),
        &ContinuationOptions::default(),
    )?;
    Ok(d.events
        .iter()
        .filter(|e| (e.gamma - gamma).norm() < 1e-9)
        .find(|e| e.before == Stability::Unstable && e.after != Stability::Unstable)
        .map(|e| e.s))
}
