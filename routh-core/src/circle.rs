//! Stability of a circle of steady motions modulo the body's axis of symmetry: the doubly
//! amended potential.
//!
//! For a body whose Lagrangian is invariant under rotations about a body axis `e` (a symmetric
//! top, an ellipsoid of revolution), the steady motions `γ` off that axis come in circles, the
//! orbits of the symmetry, and the tangent of the circle is a null vector of the restricted
//! second variation `K` (62)–(63): [`classify`](crate::classify) can only say `Degenerate`. The symmetry brings a
//! second integral, the component of the body angular momentum on the axis,
//! `M_e = e·∂L/∂ω = e·∂R/∂Ω` ((18): `∂R/∂Ω = ∂L/∂ω` at `ω = Ω + ψ̇γ`), and reducing it too leaves
//! one degree of freedom, the distance `s` from the circle along the sphere. Its potential is the
//! *doubly amended potential* (Routh's method applied to the second cyclic coordinate)
//!
//! `V(γ) = U_r(γ) + (M₀ − m(γ))² / (2 eᵀA(γ)e)`,  `m(γ) = e·∂R/∂Ω(0, γ)`, `A = ∂²R/∂Ω²`,
//!
//! the minimum of the energy `½ΩᵀAΩ + U_r` of the reduced system at fixed `M_e = M₀`. At a
//! steady motion `m(γ₀) = M₀`, so along the unit tangent `n` normal to the circle
//!
//! `V'' = κ + (eᵀMn)² / (eᵀAe)`,  `κ = nᵀKn`,  `M = ∂²R/∂Ω∂γ`.
//!
//! A system of one degree of freedom has no gyroscopic stabilisation: `V'' > 0` is a strict
//! minimum, and `E_r + c(M_e − M₀)²` (`c` large enough) is a Lyapunov function for the circle
//! (stable modulo the symmetry: motions that start near the circle stay near it); `V'' < 0` is a
//! maximum, unstable.

use std::fmt;

use nalgebra::{Matrix3x2, Vector3};

use crate::error::RouthError;
use crate::model::Routhian;
use crate::solve::zero::ZeroTest;
use crate::sphere::{restricted_hessian, ROUND};
use crate::stability::{classify_evaluated, ClassifyOptions, Evaluated, StabilityReport};
use crate::steady::SteadyMotion;
use crate::validate::{check_finite, check_model_finite};

/// The verdict of [`classify_circle`] on a circle of steady motions, modulo the symmetry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum CircleStability {
    /// `V'' > 0`: the doubly amended potential has a strict minimum; motions near the circle stay
    /// near it (Lyapunov stability of the circle as a set).
    Stable,
    /// `V'' < 0`: a maximum of the potential of a system of one degree of freedom; unstable.
    Unstable,
    /// `V'' = 0` within the tolerance: the test is inconclusive (e.g. where the circle meets
    /// another family).
    Degenerate,
}

impl fmt::Display for CircleStability {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            CircleStability::Stable => "stable modulo the symmetry",
            CircleStability::Unstable => "unstable modulo the symmetry",
            CircleStability::Degenerate => "degenerate (test inconclusive)",
        })
    }
}

/// The analysis of a circle of steady motions by [`classify_circle`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CircleReport {
    /// The unit axis of symmetry `e` (as given, normalised).
    pub axis: Vector3<f64>,
    /// The conserved momentum about the axis, `M₀ = e·∂R/∂Ω(0, γ, p_ψ) = e·∂L/∂ω(ψ̇γ, γ)`.
    pub axis_momentum: f64,
    /// `κ = nᵀKn`: the restricted second variation of `U_r` across the circle (`n` the unit
    /// tangent of the sphere normal to the circle).
    pub across: f64,
    /// `(eᵀMn)² / (eᵀAe) ≥ 0`: what fixing `M_e` adds (`M = ∂²R/∂Ω∂γ`, `A = ∂²R/∂Ω²`).
    pub momentum_term: f64,
    /// `V'' = across + momentum_term`, the second derivative of the doubly amended potential
    /// across the circle (per radian²).
    pub curvature: f64,
    /// The verdict modulo the symmetry.
    pub verdict: CircleStability,
    /// [`classify`](crate::classify) of the same steady motion (its verdict is `Degenerate` on a
    /// circle: the circle's tangent is a null vector of `K`).
    pub report: StabilityReport,
}

impl fmt::Display for CircleReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: V'' = {:+.6e} (κ = {:+.6e}, momentum term {:+.6e}), M_e = {:+.6e}",
            self.verdict, self.curvature, self.across, self.momentum_term, self.axis_momentum
        )
    }
}

/// Stability of the circle of steady motions through `steady` modulo the body's axis of symmetry
/// `axis`, with the default tolerances of [`ClassifyOptions`]. The momentum about the axis,
/// `M_e = e·∂R/∂Ω`, is conserved; fixing it leaves one degree of freedom across the circle, whose
/// potential, the doubly amended potential, has the second derivative
/// `V'' = nᵀKn + (eᵀMn)²/(eᵀAe)` (`n` the unit tangent normal to the circle, `M = ∂²R/∂Ω∂γ`,
/// `A = ∂²R/∂Ω²`; derivation in docs/method.md, 6a). With one degree of freedom there is no
/// gyroscopic stabilisation: `V'' > 0` is stable modulo the symmetry, `V'' < 0` unstable.
///
/// The model must be invariant under rotations about `axis` (body frame); this is checked at the
/// steady motion, where it makes the circle's tangent `τ = e × γ` a null vector of `K` and of
/// `eᵀM`. The zero test on `V''` is the one of [`classify`](crate::classify), relative to `‖K‖`
/// and the momentum term.
///
/// Errors: those of [`classify_with`](crate::classify_with) (e.g.
/// [`RouthError::NotASteadyMotion`]); [`RouthError::InvalidOption`] if `axis` is not finite,
/// zero or parallel to γ (the symmetry then fixes γ: an isolated motion, for `classify`);
/// [`RouthError::InvalidModel`] if the model is not symmetric about `axis` at γ.
///
/// ```
/// # use routh_core::Vector3;
/// # use test_models::HeavyTop;
/// use routh_core::{classify_circle, CircleStability, SteadyMotion};
/// // A free symmetric body (no potential, J = diag(2, 2, 1)): a top without weight, its Routh
/// // function written by hand in closed form.
/// let free = HeavyTop::lagrange(2.0, 1.0, 0.0);
/// // Rotation about an axis γ of the equator γ₃ = 0, the axis of largest inertia: the equator is a
/// // circle of such steady motions (the body's symmetry about e₃), U_r = ½p²/(2 − γ₃²) is least
/// // there, and so is the doubly amended potential.
/// let motion = SteadyMotion::at(&free, Vector3::x(), 1.0, false)?;
/// let circle = classify_circle(&free, &motion, &Vector3::z())?;
/// assert_eq!(circle.verdict, CircleStability::Stable);
/// // V'' = ¼ from U_r across the equator, plus ¼ from holding M_e = C ω₃ = 0 fixed.
/// assert!((circle.across - 0.25).abs() < 1e-12 && (circle.momentum_term - 0.25).abs() < 1e-12);
/// println!("{circle}");
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn classify_circle<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    axis: &Vector3<f64>,
) -> Result<CircleReport, RouthError> {
    classify_circle_with(model, steady, axis, &ClassifyOptions::default())
}

/// [`classify_circle`] with explicit tolerances (those of [`classify_with`](crate::classify_with)).
pub fn classify_circle_with<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    axis: &Vector3<f64>,
    opts: &ClassifyOptions,
) -> Result<CircleReport, RouthError> {
    check_finite("axis", axis.as_slice())?;
    // Validates the options and that γ is a steady motion; the one evaluation of the model.
    let (
        report,
        Evaluated {
            gamma,
            bundle,
            system,
            tangential,
        },
    ) = classify_evaluated(model, steady, opts)?;
    // Scaled by its largest component first, so that the axis is the same axis at any scale
    // (1e160 or 1e-200 times it: its squared norm would overflow or underflow).
    let e = (axis / axis.amax().max(f64::MIN_POSITIVE))
        .try_normalize(0.0)
        .ok_or_else(|| RouthError::InvalidOption {
            what: "axis",
            reason: "must be a non-zero vector".into(),
        })?;
    // The orbit of γ under rotations about e: its tangent τ; n completes the tangent plane.
    let orbit = e.cross(&gamma);
    if orbit.norm() <= AXIS_SIN {
        return Err(RouthError::InvalidOption {
            what: "axis",
            reason: format!(
                "γ = {:?} lies on the axis (sin of the angle {:e}): the symmetry fixes it, and \
                 classify decides it",
                [gamma.x, gamma.y, gamma.z],
                orbit.norm()
            ),
        });
    }
    let tau = orbit.normalize();
    let n = gamma.cross(&tau);
    check_model_finite(
        "d2r_domega_dgamma",
        bundle.d2r_domega_dgamma.as_slice(),
        &gamma,
    )?;
    // K of (62)–(63) in the basis (τ, n).
    let mu = bundle.dr_dgamma.dot(&gamma);
    let k = restricted_hessian(&Matrix3x2::from_columns(&[tau, n]), mu, &bundle.d2r_dgamma2);
    let (k_tt, k_tn, across) = (k[(0, 0)], k[(0, 1)], k[(1, 1)]);
    let eae = e.dot(&(system.a * e));
    // eᵀM: the derivative of m(γ) = e·∂R/∂Ω(0, γ).
    let dm = bundle.d2r_domega_dgamma.transpose() * e;
    let (dm_t, dm_n) = (dm.dot(&tau), dm.dot(&n));
    check_model_finite("∂²R/∂Ω² on the axis", &[eae], &gamma)?;

    // The symmetry at γ: K τ = 0 and eᵀMτ = 0, to the zero test of `classify`, on the scales it
    // judged K by: ‖K‖ and the raw size max(|∂R/∂γ|, ‖∂²R/∂γ²‖) of the terms K is the
    // difference of (`sphere::Tangential`).
    let (knorm, raw) = (tangential.knorm, tangential.raw);
    let k_zero = ZeroTest::with_floor(opts.zero_eigenvalue_tol, knorm, ROUND * raw);
    let dm_zero = ZeroTest::with_floor(opts.zero_eigenvalue_tol, dm.norm(), ROUND * dm.norm());
    if !(k_zero.is_zero(k_tt) && k_zero.is_zero(k_tn) && dm_zero.is_zero(dm_t)) {
        return Err(RouthError::InvalidModel {
            what: "axis",
            reason: format!(
                "the model is not symmetric about the axis {:?} at γ = {:?}: along the orbit \
                 e × γ, K τ = ({k_tt:e}, {k_tn:e}) and eᵀMτ = {dm_t:e} are not zero (tolerances \
                 {:e}, {:e})",
                [e.x, e.y, e.z],
                [gamma.x, gamma.y, gamma.z],
                k_zero.tol,
                dm_zero.tol
            ),
        });
    }
    if eae <= 0.0 {
        return Err(RouthError::InvalidModel {
            what: "kinetic",
            reason: format!(
                "eᵀ(∂²R/∂Ω²)e = {eae:e} ≤ 0 at γ = {:?}",
                [gamma.x, gamma.y, gamma.z]
            ),
        });
    }
    let momentum_term = dm_n * dm_n / eae;
    let curvature = across + momentum_term;
    let zero = ZeroTest::with_floor(
        opts.zero_eigenvalue_tol,
        knorm.max(momentum_term),
        ROUND * raw.max(momentum_term),
    );
    let verdict = if zero.is_zero(curvature) {
        CircleStability::Degenerate
    } else if curvature > 0.0 {
        CircleStability::Stable
    } else {
        CircleStability::Unstable
    };
    Ok(CircleReport {
        axis: e,
        axis_momentum: e.dot(&bundle.dr_domega),
        across,
        momentum_term,
        curvature,
        verdict,
        report,
    })
}

/// γ within this sine of the angle from the axis is on it.
const AXIS_SIN: f64 = 1e-8;
