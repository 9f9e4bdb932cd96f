//! Stability of a steady motion: sufficient conditions (62)–(63), the degree of instability and
//! gyroscopic stabilisation (64), with the corrections of errata E4, E5 and E8.
//!
//! The method, the verdict rules and their tolerances are in docs/method.md §6; [`classify`] says
//! what it returns.

use nalgebra::Vector3;

mod options;
mod quartic;
mod report;
mod signatures;

pub use options::ClassifyOptions;
pub use quartic::f2_coefficients;
pub(crate) use quartic::f2_coefficients_scaled;
pub use report::{Stability, StabilityReport};
pub use signatures::{krein_report, KreinReport};

use quartic::{f2_parts_of, quartic_roots, F2Parts, SquareRoots};

use crate::error::RouthError;
use crate::model::{GyroscopicSystem, RouthBundle, Routhian};
use crate::sphere::Tangential;
use crate::steady::SteadyMotion;
use crate::validate::{check_finite, check_kinetic, check_model_finite, unit_gamma};

/// Classifies the steady motion `steady` at its cyclic momentum `steady.p_psi` (sections 4–5):
/// the eigenvalues of the restricted second variation `K = Pᵀ(μE − ∂²R/∂γ²)P` (62)–(63)
/// ([`StabilityReport::restricted_hessian_eigenvalues`]), the degree of instability, the roots
/// of the even quartic `f₂(λ) = det(Pᵀ(Aλ² + 2Gλ + C)P)` (errata E5; `A`, `G`, `C` from the
/// same evaluation, [`Routhian::bundle_and_system`] at `Ω = 0`, solved exactly and in scaled
/// units) and the verdict: secularly stable, unstable, gyroscopically stabilised or degenerate
/// (a zero eigenvalue of `K` relative to `‖K‖`, [`ClassifyOptions::zero_eigenvalue_tol`], unless
/// `f₂` proves an instability; or the boundary of gyroscopic stabilisation, within
/// [`ClassifyOptions::double_root_tol`]). The method, the table of verdicts and the tolerances
/// are in docs/method.md §6, "Verdicts". `steady.gamma` must be a critical point of the amended
/// potential, as returned by [`steady_motions`](crate::steady_motions) or built by
/// [`SteadyMotion::at`] (within [`ClassifyOptions::steady_tol`]); the other fields of `steady`
/// are not used.
///
/// Errors: [`RouthError::NonFinite`] for non-finite `p_psi` or γ (or non-finite derivatives of the
/// model); [`RouthError::NonUnitGamma`] when `| |γ| − 1 | >` [`UNIT_GAMMA_TOL`](crate::validate::UNIT_GAMMA_TOL);
/// [`RouthError::DegenerateVerticalInertia`] / [`RouthError::KineticNotPositiveDefinite`] when
/// `J(γ) = ∂²L/∂ω²` is not positive definite; [`RouthError::SingularReducedKinetic`] (with the
/// smallest eigenvalue of `PᵀAP`) when the model's `∂²R/∂Ω²` is not positive definite on the
/// tangent plane (errata E4: it must be, as a Schur complement of `J`);
/// [`RouthError::NotASteadyMotion`] when γ is not a critical point of `U_r` within
/// [`ClassifyOptions::steady_tol`]; [`RouthError::NonFiniteModel`] when the model returns
/// non-finite derivatives or the roots of `f₂` exceed the range of `f64`.
///
/// ```
/// # use routh_core::Vector3;
/// # use test_models::HeavyTop;
/// use routh_core::{classify, SteadyMotion, Stability};
/// // A free symmetric body (no potential, J = diag(2, 2, 1)): a top without weight, its Routh
/// // function written by hand in closed form.
/// let free = HeavyTop::lagrange(2.0, 1.0, 0.0);
/// // Spin about the axis of least inertia: U_r = ½p²/(γᵀJγ) has its maximum there, but the
/// // gyroscopic forces stabilise it (all roots of f₂ on the imaginary axis).
/// let p = 1.0;
/// let spin = SteadyMotion::at(&free, Vector3::z(), p, true)?;
/// let report = classify(&free, &spin)?;
/// assert_eq!(report.degree_of_instability, 2);
/// assert_eq!(report.verdict, Stability::GyroscopicallyStabilized);
/// assert!(report.f2_roots.iter().all(|r| r.re == 0.0));
/// println!("{report}");
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn classify<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
) -> Result<StabilityReport, RouthError> {
    classify_with(model, steady, &ClassifyOptions::default())
}

/// [`classify`] with explicit tolerances.
///
/// Errors: as [`classify`], plus [`RouthError::InvalidOption`] for a tolerance outside `(0, 1)`.
pub fn classify_with<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    opts: &ClassifyOptions,
) -> Result<StabilityReport, RouthError> {
    classify_parts(model, steady, opts).map(|(report, ..)| report)
}

/// The unit γ, the bundle and `A`, `G`, `C` at `Ω = 0` that a classification evaluated there,
/// with the tangential quantities and scales it judged them by, for analyses that read more of
/// them ([`crate::classify_circle`]).
pub(crate) struct Evaluated {
    pub gamma: Vector3<f64>,
    pub bundle: RouthBundle,
    pub system: GyroscopicSystem,
    pub tangential: Tangential,
}

/// [`classify_with`] and what it evaluated (one evaluation of the model).
pub(crate) fn classify_evaluated<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    opts: &ClassifyOptions,
) -> Result<(StabilityReport, Evaluated), RouthError> {
    classify_parts(model, steady, opts).map(|(report, _, evaluated)| (report, evaluated))
}

/// [`classify_with`], with the tangent-plane parts of (64) it found (for the Krein signatures)
/// and what it evaluated.
///
/// The model is evaluated once: [`Routhian::bundle_and_system`] at `Ω = 0` gives both the
/// derivatives of (62)–(63) and `A`, `G`, `C` of (64).
fn classify_parts<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    opts: &ClassifyOptions,
) -> Result<(StabilityReport, F2Parts, Evaluated), RouthError> {
    opts.validate()?;
    let p_psi = steady.p_psi;
    check_finite("steady.p_psi", &[p_psi])?;
    let gamma = unit_gamma("steady.gamma", &steady.gamma)?;
    check_kinetic(model, &gamma)?;

    // (62)–(63): the restricted second variation of the amended potential; (64) from the same
    // evaluation.
    let (bundle, system) = model.bundle_and_system(&Vector3::zeros(), &gamma, p_psi);
    check_model_finite("dr_dgamma", bundle.dr_dgamma.as_slice(), &gamma)?;
    check_model_finite("d2r_dgamma2", bundle.d2r_dgamma2.as_slice(), &gamma)?;
    let tan = Tangential::new(
        &gamma,
        &bundle.dr_dgamma,
        &bundle.d2r_dgamma2,
        opts.zero_eigenvalue_tol,
    );
    check_model_finite("restricted second variation", &[tan.knorm, tan.raw], &gamma)?;
    // (33): γ must be a critical point of U_r on the sphere.
    let residual = tan.residual;
    if residual.is_nan() || residual > opts.steady_tol {
        return Err(RouthError::NotASteadyMotion {
            gamma: [gamma.x, gamma.y, gamma.z],
            residual,
            tol: opts.steady_tol,
        });
    }
    let eigs = tan.values;
    // The one zero test (solve::zero) on the search's tangential scale: a zero eigenvalue here
    // is one the search calls zero too.
    let zero = tan.zero_test();
    let zero_tol = zero.tol;
    let any_zero = zero.count(&eigs) > 0;
    let degree = eigs.iter().filter(|&&e| e < -zero_tol).count();

    // (64) on the tangent plane (errata E5), in the scaled variable μ = λ/ω (see `F2Parts`):
    // the coefficients are O(1) whatever the units of the model, so neither they nor the
    // discriminant overflow or underflow (p_ψ = 1e±150).
    let parts = f2_parts_of(&system, gamma)?;
    let [c4, c2, c0] = parts.scaled;
    let a_norm = parts.a_hat.norm();
    let mut roots = quartic_roots(c4, c2, c0, opts.double_root_tol);
    for l in &mut roots.lambda {
        *l *= parts.omega;
    }
    // λ = ωμ can still exceed f64 when the frequencies themselves do (a kinetic form with a
    // moment of 1e−310 is positive definite but its frequencies are O(1e155)). Found by
    // tests/runtime_properties.rs.
    let root_parts = roots.lambda.map(|l| [l.re, l.im]);
    check_model_finite("roots of f2 (overflow)", root_parts.as_flattened(), &gamma)?;
    // The zero threshold of K (an eigenvalue of c = PᵀCP up to a rotation, errata E6) in the
    // units of the scaled coefficients: ĉ = c/(αω²).
    let zero_tol = zero_tol / parts.alpha / parts.omega / parts.omega;

    let verdict = if any_zero {
        // det K = c₀ is zero within the tolerance, so f₂ ≈ λ²(c₄λ² + c₂): a real root pair
        // ±√(−c₂/c₄) persists whatever the sign of the zero eigenvalue when c₂ < 0 beyond the
        // perturbation of c₂ by the tolerance on K (|Δc₂| ≤ 2‖PᵀAP‖·tol). That is a proven
        // instability; otherwise the test is inconclusive (errata E8).
        let c2_scale = 2.0 * a_norm * zero_tol;
        if c2 < -(c2_scale + 1e-12 * c2.abs()) {
            Stability::Unstable
        } else {
            Stability::Degenerate
        }
    } else {
        match degree {
            0 => Stability::SecularlyStable,
            2 => match roots.kind {
                SquareRoots::DistinctNegative => Stability::GyroscopicallyStabilized,
                SquareRoots::DoubleNegative => Stability::Degenerate,
                _ => Stability::Unstable,
            },
            _ => Stability::Unstable,
        }
    };
    let report = StabilityReport {
        restricted_hessian_eigenvalues: eigs,
        degree_of_instability: degree,
        f2_roots: roots.lambda,
        verdict,
    };
    Ok((
        report,
        parts,
        Evaluated {
            gamma,
            bundle,
            system,
            tangential: tan,
        },
    ))
}
