//! The verdict of a classification and its report.

use std::fmt;

use nalgebra::Complex;

/// The stability verdict of [`classify`](super::classify).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Stability {
    /// The restricted second variation (62)–(63) is positive definite: the amended potential has
    /// a strict minimum, stable in the secular sense (section 4).
    SecularlyStable,
    /// Degree of instability 2 and every root of `f₂` simple and on the imaginary axis: linear
    /// stability by gyroscopic forces (section 5, errata E5).
    GyroscopicallyStabilized,
    /// Odd degree of instability, or a root of `f₂` with positive real part.
    Unstable,
    /// The test is inconclusive: a zero eigenvalue of the restricted second variation
    /// (errata E8), or degree 2 exactly on the boundary of gyroscopic stabilisation (a double
    /// imaginary pair of roots of `f₂`).
    Degenerate,
}

impl fmt::Display for Stability {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Stability::SecularlyStable => "secularly stable",
            Stability::GyroscopicallyStabilized => "gyroscopically stabilised",
            Stability::Unstable => "unstable",
            Stability::Degenerate => "degenerate (test inconclusive)",
        })
    }
}

/// The stability analysis of one steady motion (sections 4–5 with errata E5, E8).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StabilityReport {
    /// Eigenvalues, ascending, of the restricted second variation `Pᵀ(μE − ∂²R/∂γ²)P` of the
    /// amended potential (62)–(63).
    pub restricted_hessian_eigenvalues: [f64; 2],
    /// Number of negative eigenvalues among those not counted as zero (section 5).
    pub degree_of_instability: usize,
    /// The four roots of `f₂(λ) = det(Pᵀ(Aλ² + 2Gλ + C)P)` (errata E5), sorted by real part, then
    /// imaginary part. They are the non-zero eigenvalues of the linearised full system (8).
    pub f2_roots: [Complex<f64>; 4],
    /// The verdict.
    pub verdict: Stability,
}

impl fmt::Display for StabilityReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [k1, k2] = self.restricted_hessian_eigenvalues;
        write!(
            f,
            "{}: restricted second variation eigenvalues [{:+.6e}, {:+.6e}], degree of \
             instability {}, roots of f₂:",
            self.verdict, k1, k2, self.degree_of_instability
        )?;
        for (i, r) in self.f2_roots.iter().enumerate() {
            let sep = if i == 0 { " " } else { ", " };
            write!(f, "{sep}{:+.6e}{:+.6e}i", r.re, r.im)?;
        }
        Ok(())
    }
}
