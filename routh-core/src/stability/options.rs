//! The tolerances of a classification.

use crate::error::RouthError;

/// The tolerances of [`classify_with`](super::classify_with); [`classify`](super::classify) uses
/// the defaults.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ClassifyOptions {
    /// Relative tolerance under which an eigenvalue of the restricted second variation counts as
    /// zero (errata E8), relative to the norm of the restricted form itself, with a round-off
    /// floor (see [`classify`](super::classify)). Default `1e−8`: round-off in the eigenvalues is
    /// about `1e−15` of the scale and a converged steady motion is located to about `1e−13`.
    pub zero_eigenvalue_tol: f64,
    /// Tolerance on the residual of (33) for `steady.gamma` to count as a steady motion, as a
    /// distance on the sphere (radians): the length of the Newton step `K⁻¹g` to the nearest
    /// critical point of `U_r` (`g` the tangential gradient, `K` the restricted form, see
    /// [`classify`](super::classify)), or where `K` nearly vanishes (a branch point) the
    /// second-order estimate `√(2|g|/s)` with `s` the size of the derivatives. It compares `g`
    /// with `K`, so it does not change when the model is multiplied by a constant. Beyond it,
    /// [`classify`](super::classify) fails with [`RouthError::NotASteadyMotion`]. Default `1e−5`:
    /// loose enough for a point found by [`steady_motions`](crate::steady_motions) (`≤ 1e−10`),
    /// typed with 9 digits, or converged next to a branch point (where a gradient at round-off
    /// level still means a distance of order `√ε`), far below any distance between distinct
    /// steady motions that the analysis can resolve.
    pub steady_tol: f64,
    /// Relative tolerance on the discriminant of `f₂` in `λ²` under which its two roots in `λ²`
    /// are treated as a double root (the boundary of gyroscopic stabilisation). The discriminant
    /// is a difference of terms of size `c₂² + 4|c₄c₀|` computed to a few ulps, so the default
    /// `1e−10` is far above round-off and far below any physically meaningful distance from the
    /// boundary (0.1 % from the Maievskii bound gives a relative discriminant of order `1e−3`).
    pub double_root_tol: f64,
}

impl Default for ClassifyOptions {
    fn default() -> Self {
        ClassifyOptions {
            zero_eigenvalue_tol: 1e-8,
            double_root_tol: 1e-10,
            steady_tol: 1e-5,
        }
    }
}

impl ClassifyOptions {
    pub(super) fn validate(&self) -> Result<(), RouthError> {
        for (what, v) in [
            ("zero_eigenvalue_tol", self.zero_eigenvalue_tol),
            ("double_root_tol", self.double_root_tol),
            ("steady_tol", self.steady_tol),
        ] {
            if !(v > 0.0 && v < 1.0) {
                return Err(RouthError::InvalidOption {
                    what,
                    reason: format!("must be in (0, 1) (got {v:e})"),
                });
            }
        }
        Ok(())
    }
}
