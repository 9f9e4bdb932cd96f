//! Input validation shared by every public function: finite inputs, a unit γ (one tolerance for
//! the whole crate), a kinetic form that is positive definite.

use crate::solve::norm::stable_norm;
use nalgebra::{Matrix3, Vector3};

use crate::error::RouthError;
use crate::model::Lagrangian;

/// Tolerance on `| |γ| − 1 |` for an input γ to count as a unit vector (it is then normalised).
/// The same for simulation, steady motions and stability. Loose enough for a γ typed from a
/// closed form with 9 digits or read back from a trajectory integrated with tight tolerances,
/// tight enough that every formula is evaluated on the sphere to well below the tolerances of
/// the analysis.
pub const UNIT_GAMMA_TOL: f64 = 1e-8;

/// Checks that every value is finite; the error names the input and its first bad value.
pub(crate) fn check_finite(what: &'static str, values: &[f64]) -> Result<(), RouthError> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(&value) => Err(RouthError::NonFinite { what, value }),
        None => Ok(()),
    }
}

/// Checks that a model output is finite at γ.
#[inline]
pub(crate) fn check_model_finite(
    what: &'static str,
    values: &[f64],
    gamma: &Vector3<f64>,
) -> Result<(), RouthError> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(RouthError::NonFiniteModel {
            what,
            gamma: gamma_array(gamma),
        })
    }
}

pub(crate) fn gamma_array(gamma: &Vector3<f64>) -> [f64; 3] {
    [gamma.x, gamma.y, gamma.z]
}

/// Checks that γ is finite and `| |γ| − 1 | ≤` [`UNIT_GAMMA_TOL`] (the geometric integral (4));
/// returns `γ/|γ|`. Both errors name the input `what`.
pub(crate) fn unit_gamma(
    what: &'static str,
    gamma: &Vector3<f64>,
) -> Result<Vector3<f64>, RouthError> {
    check_finite(what, gamma.as_slice())?;
    let norm = stable_norm(gamma.as_slice());
    if (norm - 1.0).abs().is_nan() || (norm - 1.0).abs() > UNIT_GAMMA_TOL {
        return Err(RouthError::NonUnitGamma {
            what,
            norm,
            tol: UNIT_GAMMA_TOL,
        });
    }
    Ok(gamma / norm)
}

/// Checks that `J(γ) = ∂²L/∂ω²` is finite and positive definite (Cholesky of its symmetric part,
/// scaled to its diagonal so that any units work) and that `γᵀJγ > 0`.
pub(crate) fn check_kinetic<M: Lagrangian + ?Sized>(
    model: &M,
    gamma: &Vector3<f64>,
) -> Result<Matrix3<f64>, RouthError> {
    let j = model.d2l_domega2(gamma);
    check_model_finite("J(gamma) = d2l_domega2", j.as_slice(), gamma)?;
    let sym = 0.5 * (j + j.transpose());
    let vertical = gamma.dot(&(sym * gamma));
    if vertical.is_nan() || vertical <= 0.0 {
        return Err(RouthError::DegenerateVerticalInertia {
            gamma: gamma_array(gamma),
            value: vertical,
        });
    }
    if !is_positive_definite(&sym) {
        return Err(RouthError::KineticNotPositiveDefinite {
            gamma: gamma_array(gamma),
            min_eigenvalue: min_eigenvalue(&sym),
        });
    }
    Ok(sym)
}

/// Whether the symmetric matrix `m` is positive definite: Cholesky of `D^{-1/2} m D^{-1/2}`
/// (`D` its diagonal), which is invariant under the units of `m` and cheap on the hot path
/// (every start of the search of steady motions). Written out for 3×3 with the operations of
/// nalgebra's `Cholesky::new` on the lower triangle, column by column: every pivot must be
/// positive (a zero, negative or NaN pivot fails).
#[inline]
pub(crate) fn is_positive_definite(m: &Matrix3<f64>) -> bool {
    let d = [m[(0, 0)], m[(1, 1)], m[(2, 2)]];
    if !d.iter().all(|x| *x > 0.0 && x.is_finite()) {
        return false;
    }
    let s = d.map(|x| 1.0 / x.sqrt());
    let a = |i: usize, k: usize| m[(i, k)] * s[i] * s[k];
    let p0 = a(0, 0);
    if p0.is_nan() || p0 <= 0.0 {
        return false;
    }
    let r0 = p0.sqrt();
    let (l10, l20) = (a(1, 0) / r0, a(2, 0) / r0);
    let p1 = a(1, 1) - l10 * l10;
    if p1.is_nan() || p1 <= 0.0 {
        return false;
    }
    let l21 = (a(2, 1) - l10 * l20) / p1.sqrt();
    let p2 = a(2, 2) - l20 * l20 - l21 * l21;
    p2 > 0.0
}

/// The smallest eigenvalue of a symmetric matrix (NaN if it cannot be computed), for error
/// messages only.
pub(crate) fn min_eigenvalue(m: &Matrix3<f64>) -> f64 {
    if !m.iter().all(|x| x.is_finite()) {
        return f64::NAN;
    }
    nalgebra::SymmetricEigen::try_new(*m, f64::EPSILON, 1000)
        .map(|e| e.eigenvalues.min())
        .unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positive_definiteness_is_unit_free() {
        let m = Matrix3::from_diagonal(&Vector3::new(1e-200, 1.0, 1e200));
        assert!(is_positive_definite(&m));
        let mut n = Matrix3::identity();
        n[(0, 1)] = 1.0;
        n[(1, 0)] = 1.0;
        assert!(!is_positive_definite(&n));
    }

    /// The written-out Cholesky decides as nalgebra's on matrices near the boundary.
    #[test]
    fn positive_definiteness_matches_nalgebra() {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for _ in 0..2000 {
            let b = Matrix3::from_fn(|_, _| next());
            // Shifted Gram matrices: eigenvalues spread around zero.
            let m = b * b.transpose() - Matrix3::identity() * (0.3 * next().abs());
            let d = m.diagonal();
            let reference = d.iter().all(|x| *x > 0.0 && x.is_finite()) && {
                let s = d.map(|x| 1.0 / x.sqrt());
                Matrix3::from_fn(|i, k| m[(i, k)] * s[i] * s[k])
                    .cholesky()
                    .is_some()
            };
            assert_eq!(is_positive_definite(&m), reference, "{m}");
        }
        let singular = Matrix3::new(1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        assert!(!is_positive_definite(&singular));
        assert!(!is_positive_definite(&Matrix3::from_element(f64::NAN)));
    }
}
