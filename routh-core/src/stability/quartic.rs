//! The characteristic polynomial `f₂` of (64) on the tangent plane (errata E5): its
//! coefficients in scaled form and its roots, a quartic in `λ` with only even powers.

use nalgebra::{Complex, Matrix2, Vector3};

use crate::error::RouthError;
use crate::model::{GyroscopicSystem, Routhian};
use crate::sphere::{sym2_eigen, tangent_basis};
use crate::validate::{check_finite, check_kinetic, check_model_finite, unit_gamma};

/// The coefficients `[c₄, c₂, c₀]` of `f₂(λ) = det(Pᵀ(Aλ² + 2Gλ + C)P) = c₄λ⁴ + c₂λ² + c₀`
/// (errata E5) at the unit vector γ, from [`Routhian::gyroscopic_system`]. They do not depend on
/// the choice of the orthonormal basis `P` of γ^⊥.
///
/// They are of the order of `p_ψ⁴` (for a free body, in units of the inertia) and overflow
/// for `|p_ψ|` beyond about `1e77`; [`classify`](super::classify) solves the same polynomial in a
/// scaled variable, which does not.
///
/// Errors: as [`classify`](super::classify), and [`RouthError::NonFiniteModel`] when a coefficient
/// overflows.
pub fn f2_coefficients<M: Routhian>(
    model: &M,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> Result<[f64; 3], RouthError> {
    let parts = f2_parts(model, gamma, p_psi)?;
    let (a, g, c) = (&parts.a, parts.g, &parts.c);
    // det(aλ² + 2gJλ + c) for symmetric a, c and J = [[0, 1], [−1, 0]]: the skew part adds
    // (2gλ)² to the determinant of the symmetric part.
    let c4 = a.determinant();
    let c2 =
        a[(0, 0)] * c[(1, 1)] + a[(1, 1)] * c[(0, 0)] - 2.0 * a[(0, 1)] * c[(0, 1)] + 4.0 * g * g;
    let c0 = c.determinant();
    check_model_finite("coefficients of f2", &[c4, c2, c0], &parts.gamma)?;
    Ok([c4, c2, c0])
}

/// `f₂` of [`f2_coefficients`] in the scaled variable `μ = λ/ω`: returns `([ĉ₄, ĉ₂, ĉ₀], ω)`
/// with `f₂(λ) = α²ω⁴ (ĉ₄μ⁴ + ĉ₂μ² + ĉ₀)`, `α` the largest entry of `PᵀAP` and `ω > 0` the
/// characteristic frequency `max(√(‖PᵀCP‖/α), |g|/α)` (entry-wise max norm). The roots of `f₂`
/// are `ω` times the roots of the scaled quartic; `0 < ĉ₄ ≤ 1`, `|ĉ₂| ≤ 8`, `|ĉ₀| ≤ 2`, so they
/// neither overflow nor underflow in any units (`p_ψ = 1e±150`), and ratios such as the relative
/// discriminant `(ĉ₂² − 4ĉ₄ĉ₀)/(ĉ₂² + 4|ĉ₄ĉ₀|)` equal those of the raw coefficients.
///
/// Errors: as [`classify`](super::classify).
pub(crate) fn f2_coefficients_scaled<M: Routhian>(
    model: &M,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> Result<([f64; 3], f64), RouthError> {
    let parts = f2_parts(model, gamma, p_psi)?;
    Ok((parts.scaled, parts.omega))
}

/// The linearisation on the tangent plane, `a ẍ + 2g J ẋ + c x = 0` (`a = PᵀAP`, `c = PᵀCP`,
/// `J = [[0, 1], [−1, 0]]`), and the same in the scaled variables that
/// [`classify`](super::classify) works with.
///
/// With `α` the largest entry of `a` (positive: `a` is positive definite) and the characteristic
/// frequency `ω = max(√(‖c‖_max/α), |g|/α)` (1 when `c` and `g` vanish), put `â = a/α`,
/// `ĝ = g/(αω)`, `ĉ = c/(αω²)` (entries at most 1 in magnitude, formed without overflow). Then
/// `aλ² + 2gJλ + c = αω²(âμ² + 2ĝJμ + ĉ)` with `λ = ωμ`, so
/// `f₂(λ) = α²ω⁴ f̂₂(μ)`, `f̂₂(μ) = det(âμ² + 2ĝJμ + ĉ) = ĉ₄μ⁴ + ĉ₂μ² + ĉ₀`: the roots of `f₂` are
/// `ω` times those of `f̂₂`, whose coefficients are O(1). The raw coefficients are O(p_ψ⁴) and
/// overflow, with their discriminant, long before the roots do (p_ψ = 1e150 with J = O(1e150)).
pub(super) struct F2Parts {
    /// The unit γ the parts were evaluated at.
    pub(super) gamma: Vector3<f64>,
    pub(super) a: Matrix2<f64>,
    pub(super) g: f64,
    pub(super) c: Matrix2<f64>,
    pub(super) alpha: f64,
    pub(super) omega: f64,
    pub(super) a_hat: Matrix2<f64>,
    pub(super) g_hat: f64,
    pub(super) c_hat: Matrix2<f64>,
    /// `[ĉ₄, ĉ₂, ĉ₀]`.
    pub(super) scaled: [f64; 3],
}

/// The restricted `a`, `g`, `c` of (64) and `f₂` in scaled form (see [`F2Parts`]).
pub(super) fn f2_parts<M: Routhian>(
    model: &M,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> Result<F2Parts, RouthError> {
    check_finite("p_psi", &[p_psi])?;
    let gamma = unit_gamma("gamma", gamma)?;
    check_kinetic(model, &gamma)?;
    f2_parts_of(&model.gyroscopic_system(&gamma, p_psi), gamma)
}

/// [`F2Parts`] of `A`, `G`, `C` of (64) at the unit vector `gamma` (checked by the caller).
pub(super) fn f2_parts_of(
    sys: &GyroscopicSystem,
    gamma: Vector3<f64>,
) -> Result<F2Parts, RouthError> {
    for m in [&sys.a, &sys.g, &sys.c] {
        check_model_finite("A, G, C of (64)", m.as_slice(), &gamma)?;
    }
    let p = tangent_basis(&gamma);
    let a = p.transpose() * sys.a * p;
    let a = 0.5 * (a + a.transpose());
    let c = p.transpose() * sys.c * p;
    let c = 0.5 * (c + c.transpose());
    let gm = p.transpose() * sys.g * p;
    let g = 0.5 * (gm[(0, 1)] - gm[(1, 0)]);
    check_model_finite(
        "restricted A, G, C of (64)",
        &[a.amax(), c.amax(), g],
        &gamma,
    )?;
    let singular = || RouthError::SingularReducedKinetic {
        gamma: [gamma.x, gamma.y, gamma.z],
        // a = PᵀAP is the gauge-fixed form ∂²R/∂Ω² + cγγᵀ of errata E4 restricted to γ^⊥ (A
        // annihilates γ), so its smallest eigenvalue is the one that failed.
        min_eigenvalue: sym2_eigen(&a).values[0],
    };
    // J positive definite makes PᵀAP (a Schur complement of J, errata E4) positive definite, so
    // its largest entry is a positive diagonal one; anything else is a defect of the model.
    // α = 0 fails here (a, g, c are finite), a negative definite or indefinite `a` below.
    let alpha = a.amax();
    if alpha == 0.0 {
        return Err(singular());
    }
    let c_max = c.amax();
    let omega_c = c_max.sqrt() / alpha.sqrt();
    let omega_g = g.abs() / alpha;
    let omega = omega_c.max(omega_g);
    let omega = if omega == 0.0 { 1.0 } else { omega };
    check_model_finite(
        "characteristic frequency of f2 (overflow)",
        &[omega],
        &gamma,
    )?;
    let a_hat = a / alpha;
    let g_hat = g / alpha / omega;
    let c_hat = if c_max > 0.0 {
        (c / c_max) * (omega_c / omega).powi(2)
    } else {
        Matrix2::zeros()
    };
    let c4 = a_hat.determinant();
    let c2 = a_hat[(0, 0)] * c_hat[(1, 1)] + a_hat[(1, 1)] * c_hat[(0, 0)]
        - 2.0 * a_hat[(0, 1)] * c_hat[(0, 1)]
        + 4.0 * g_hat * g_hat;
    let c0 = c_hat.determinant();
    // Positive definite: a positive diagonal entry and a positive determinant (a negative
    // definite `a` has a positive determinant too).
    if !(a_hat[(0, 0)] > 0.0 && c4 > 0.0) {
        return Err(singular());
    }
    Ok(F2Parts {
        gamma,
        a,
        g,
        c,
        alpha,
        omega,
        a_hat,
        g_hat,
        c_hat,
        scaled: [c4, c2, c0],
    })
}

/// How the roots in `s = λ²` of `c₄s² + c₂s + c₀` lie.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum SquareRoots {
    /// Two distinct real negative roots: four simple imaginary roots λ.
    DistinctNegative,
    /// A double real negative root (within [`ClassifyOptions::double_root_tol`]): a double imaginary pair.
    DoubleNegative,
    /// Anything else (a non-negative real root or a complex pair).
    Other,
}

pub(super) struct QuarticRoots {
    pub(super) lambda: [Complex<f64>; 4],
    pub(super) kind: SquareRoots,
}

/// The two square roots `±√s` of a real `s`, exactly on an axis.
pub(super) fn sqrt_real(s: f64) -> [Complex<f64>; 2] {
    if s >= 0.0 {
        let r = s.sqrt();
        [Complex::new(r, 0.0), Complex::new(-r, 0.0)]
    } else {
        let r = (-s).sqrt();
        [Complex::new(0.0, r), Complex::new(0.0, -r)]
    }
}

/// Roots of the even quartic `c₄λ⁴ + c₂λ² + c₀` (`c₄ > 0`), sorted by `(re, im)`.
pub(super) fn quartic_roots(c4: f64, c2: f64, c0: f64, double_root_tol: f64) -> QuarticRoots {
    let disc = c2 * c2 - 4.0 * c4 * c0;
    let disc_scale = c2 * c2 + 4.0 * (c4 * c0).abs();
    let (mut lambda, kind) = if disc.abs() <= double_root_tol * disc_scale {
        let s = -c2 / (2.0 * c4);
        let [r1, r2] = sqrt_real(s);
        let kind = if s < 0.0 {
            SquareRoots::DoubleNegative
        } else {
            SquareRoots::Other
        };
        ([r1, r2, r1, r2], kind)
    } else if disc > 0.0 {
        // Numerically stable roots of the quadratic in s.
        let q = -0.5 * (c2 + c2.signum() * disc.sqrt());
        let s1 = q / c4;
        let s2 = if q != 0.0 { c0 / q } else { -s1 };
        let [a1, a2] = sqrt_real(s1);
        let [b1, b2] = sqrt_real(s2);
        let kind = if s1 < 0.0 && s2 < 0.0 {
            SquareRoots::DistinctNegative
        } else {
            SquareRoots::Other
        };
        ([a1, a2, b1, b2], kind)
    } else {
        // A complex pair s = (−c₂ ± i√(−disc))/(2c₄): λ = ±√s, two roots in the right half-plane.
        let s = Complex::new(-c2 / (2.0 * c4), (-disc).sqrt() / (2.0 * c4));
        let r = s.sqrt();
        let rc = r.conj();
        ([r, -r, rc, -rc], SquareRoots::Other)
    };
    // Canonical zeros (−0.0 → +0.0) so that the total order agrees with the numeric one.
    for l in &mut lambda {
        *l = Complex::new(l.re + 0.0, l.im + 0.0);
    }
    lambda.sort_by(|x, y| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im)));
    QuarticRoots { lambda, kind }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f2(c4: f64, c2: f64, c0: f64, l: Complex<f64>) -> Complex<f64> {
        let l2 = l * l;
        l2 * l2 * c4 + l2 * c2 + c0
    }

    #[test]
    fn quartic_roots_are_roots() {
        for (c4, c2, c0) in [
            (1.0, 5.0, 4.0),
            (2.0, -1.0, 3.0),
            (1.0, -5.0, 4.0),
            (1.0, 2.0, 1.0),
            (3.0, 1.0, -2.0),
            (1.0, 0.0, 0.0),
            (1.0, 1e-9, 0.0),
        ] {
            let r = quartic_roots(c4, c2, c0, 1e-10);
            for l in r.lambda {
                let scale = c4 * l.norm().powi(4) + c2.abs() * l.norm_sqr() + c0.abs() + 1e-300;
                assert!(
                    f2(c4, c2, c0, l).norm() <= 1e-12 * scale,
                    "{c4} {c2} {c0}: {l}"
                );
            }
            for w in r.lambda.windows(2) {
                assert!((w[0].re, w[0].im) <= (w[1].re, w[1].im));
            }
        }
        assert_eq!(
            quartic_roots(1.0, 5.0, 4.0, 1e-10).kind,
            SquareRoots::DistinctNegative
        );
        assert_eq!(
            quartic_roots(1.0, 2.0, 1.0, 1e-10).kind,
            SquareRoots::DoubleNegative
        );
        assert_eq!(
            quartic_roots(2.0, -1.0, 3.0, 1e-10).kind,
            SquareRoots::Other
        );
        assert_eq!(
            quartic_roots(1.0, -5.0, 4.0, 1e-10).kind,
            SquareRoots::Other
        );
    }
}
