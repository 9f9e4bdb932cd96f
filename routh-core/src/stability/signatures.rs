//! The Krein signatures of the modes of a classified steady motion.

use std::fmt;

use super::{classify_parts, ClassifyOptions, StabilityReport};
use crate::error::RouthError;
use crate::krein::krein_signatures;
use crate::model::Routhian;
use crate::steady::SteadyMotion;

/// A [`StabilityReport`] with the Krein signatures of the roots of `f₂`, from
/// [`krein_report`]. Its `Display` shows them next to the roots.
///
/// ```
/// # use routh_core::*;
/// # use test_models::Gyrostat;
/// use routh_core::stability::{krein_report, KreinReport};
/// let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
/// // The sleeping top between Maievskii's bound (p = 2) and the secular bound (p = 2.5).
/// let s = SteadyMotion::at(&top, Vector3::z(), 2.2, true)?;
/// let k: KreinReport = krein_report(&top, &s, &ClassifyOptions::default())?;
/// assert_eq!(k.report.verdict, Stability::GyroscopicallyStabilized);
/// // One mode of each energy sign for each sign of the frequency.
/// assert_eq!(k.krein_signatures.iter().map(|&x| x as i32).sum::<i32>(), 0);
/// println!("{k}");
/// # Ok::<(), routh_core::RouthError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct KreinReport {
    /// The stability analysis.
    pub report: StabilityReport,
    /// The Krein signature of each root in `report.f2_roots`: `+1` or `−1` for a root on the
    /// imaginary axis (the sign of the energy of its mode), `0` for a root off the axis.
    /// Gyroscopic stabilisation has, for each sign of the frequency, one mode of each signature;
    /// gyroscopic stability is lost where two roots of opposite signature collide (a
    /// Hamiltonian–Hopf bifurcation), while roots of equal signature pass each other harmlessly.
    pub krein_signatures: [i8; 4],
}

impl fmt::Display for KreinReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r = &self.report;
        let [k1, k2] = r.restricted_hessian_eigenvalues;
        write!(
            f,
            "{}: restricted second variation eigenvalues [{:+.6e}, {:+.6e}], degree of \
             instability {}, roots of f₂ (with Krein signatures):",
            r.verdict, k1, k2, r.degree_of_instability
        )?;
        for (i, (z, k)) in r.f2_roots.iter().zip(self.krein_signatures).enumerate() {
            let sep = if i == 0 { " " } else { ", " };
            let krein = match k {
                1 => " (+)",
                -1 => " (−)",
                _ => "",
            };
            write!(f, "{sep}{:+.6e}{:+.6e}i{krein}", z.re, z.im)?;
        }
        Ok(())
    }
}

/// [`classify_with`](super::classify_with) and the Krein signatures of the roots of `f₂` (see
/// [`KreinReport`]): on the tangent plane the linearisation is `a ẍ + 2gJẋ + cx = 0` with
/// conserved energy `½ẋᵀaẋ + ½xᵀcx`; on the mode `u` of a root `λ = iω` it is proportional to
/// `ω²uᴴau + uᴴcu`, and its sign is the root's signature. They explain a verdict: a secularly
/// stable motion has only `+1`; a gyroscopically stabilised one has one mode of each sign per
/// sign of ω.
///
/// Errors: as [`classify_with`](super::classify_with).
///
/// See the example on [`KreinReport`].
pub fn krein_report<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    opts: &ClassifyOptions,
) -> Result<KreinReport, RouthError> {
    let (report, parts, _) = classify_parts(model, steady, opts)?;
    // The signatures of f₂ scaled (`F2Parts`): the modes of λ = ωμ are those of μ and the
    // energies are multiplied by αω² > 0, so the signs are the same, without overflow.
    let mu = report.f2_roots.map(|l| l / parts.omega);
    let krein_signatures = krein_signatures(&parts.a_hat, parts.g_hat, &parts.c_hat, &mu);
    Ok(KreinReport {
        report,
        krein_signatures,
    })
}
