//! Stability of a steady motion: sufficient conditions (62)–(63), the degree of instability and
//! gyroscopic stabilisation (64), with the corrections of errata E4, E5 and E8.
//!
//! The method, the verdict rules and their tolerances are documented on [`classify`].

use std::fmt;

use nalgebra::{Complex, Matrix2, Vector3};

use crate::error::RouthError;
use crate::krein::krein_signatures;
use crate::model::{GyroscopicSystem, RouthBundle, Routhian};
use crate::sphere::{sym2_eigen, tangent_basis, Tangential};
use crate::steady::SteadyMotion;
use crate::validate::{check_finite, check_kinetic, check_model_finite, unit_gamma};

/// The tolerances of [`classify_with`]; [`classify`] uses the defaults.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ClassifyOptions {
    /// Relative tolerance under which an eigenvalue of the restricted second variation counts as
    /// zero (errata E8), relative to the norm of the restricted form itself, with a round-off
    /// floor (see [`classify`]). Default `1e−8`: round-off in the eigenvalues is about `1e−15` of
    /// the scale and a converged steady motion is located to about `1e−13`.
    pub zero_eigenvalue_tol: f64,
    /// Tolerance on the residual of (33) for `steady.gamma` to count as a steady motion, as a
    /// distance on the sphere (radians): the length of the Newton step `K⁻¹g` to the nearest
    /// critical point of `U_r` (`g` the tangential gradient, `K` the restricted form, see
    /// [`classify`]), or where `K` nearly vanishes (a branch point) the second-order estimate
    /// `√(2|g|/s)` with `s` the size of the derivatives. It compares `g` with `K`, so it does not
    /// change when the model is multiplied by a constant. Beyond it, [`classify`] fails with
    /// [`RouthError::NotASteadyMotion`]. Default `1e−5`: loose enough for a point found by
    /// [`steady_motions`](crate::steady_motions) (`≤ 1e−10`), typed with 9 digits, or converged
    /// next to a branch point (where a gradient at round-off level still means a distance of
    /// order `√ε`), far below any distance between distinct steady motions that the analysis can
    /// resolve.
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
    fn validate(&self) -> Result<(), RouthError> {
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

/// The stability verdict of [`classify`].
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

/// Classifies the steady motion `steady` at its cyclic momentum `steady.p_psi` (sections 4–5): the
/// eigenvalues of the restricted second variation (62)–(63), the degree of instability, the roots
/// of `f₂` (errata E5) and the verdict (rules and tolerances below). `steady.gamma` must be a
/// critical point of the amended potential, as returned by
/// [`steady_motions`](crate::steady_motions) or built by [`SteadyMotion::at`]; the other fields
/// of `steady` are not used.
///
/// # Method
///
/// Let `P` be a 3×2 orthonormal basis of the tangent plane γ^⊥ (63).
/// 1. The restricted second variation of the amended potential is the 2×2 form
///    `K = Pᵀ(μE − ∂²R/∂γ²)P` with `μ = (∂R/∂γ, γ)` at `Ω = 0` (62)–(63). Its eigenvalues are
///    [`StabilityReport::restricted_hessian_eigenvalues`]; the number of negative ones is the
///    degree of instability (section 5).
/// 2. The characteristic polynomial of the linearised reduced system (65) on the tangent plane is
///    `f₂(λ) = det(Pᵀ(Aλ² + 2Gλ + C)P)` with `A`, `G`, `C` of [`Routhian::gyroscopic_system`],
///    here from the same evaluation as step 1 ([`Routhian::bundle_and_system`] at `Ω = 0`)
///    (errata E5: the printed 3×3 `f(λ)` of (64) vanishes identically). With `a = PᵀAP`,
///    `c = PᵀCP` symmetric and `PᵀGP = [[0, g], [−g, 0]]`, it is the even quartic
///    `f₂(λ) = c₄λ⁴ + c₂λ² + c₀`, `c₄ = det a`, `c₂ = a₁₁c₂₂ + a₂₂c₁₁ − 2a₁₂c₁₂ + 4g²`,
///    `c₀ = det c`, solved exactly as a quadratic in `s = λ²` and then `λ = ±√s` (complex square
///    root). `c = PᵀCP` is `K` up to a rotation of the plane by a right angle (errata E6), so
///    `c₀ = det K`. The coefficients are of order `p_ψ⁴` and would overflow (or underflow) in
///    extreme units, so the quartic is solved in the scaled variable `μ = λ/ω`, `ω` a
///    characteristic frequency of `a`, `g`, `c`, with coefficients of order 1
///    (`f2_coefficients_scaled`); the roots and verdicts are the same in any units.
///
/// # Verdict
///
/// - `γ` must be a steady motion: the Newton step `|K⁻¹g|` to the nearest critical point (`g` the
///   tangential gradient of `U_r`; 0 when `|g| ≤ 1024 ε |∂R/∂γ|`, round-off) must not exceed
///   [`ClassifyOptions::steady_tol`] (radians, default `1e−5`), otherwise
///   [`RouthError::NotASteadyMotion`].
/// - An eigenvalue κ of `K` is zero when `|κ| ≤ max(`[`ClassifyOptions::zero_eigenvalue_tol`]` ·
///   ‖K‖_F, 1024 ε · s_raw)`, `s_raw = max(|∂R/∂γ|, ‖∂²R/∂γ²‖_F)`: relative to the restricted form
///   itself (invariant under adding `c|γ|²` to `U`, which changes `∂R/∂γ` and `∂²R/∂γ²` but not
///   `K`), with the raw scale only as a round-off floor.
/// - With a zero eigenvalue, `det K = c₀ ≈ 0` and `f₂ ≈ λ²(c₄λ² + c₂)`: if `c₂ < 0` beyond its
///   perturbation by the tolerance on `K`, `f₂` has the real root `√(−c₂/c₄) > 0` whatever the
///   sign of the zero eigenvalue, a proven instability: [`Stability::Unstable`]. Otherwise
///   [`Stability::Degenerate`] (errata E8: the parity argument then says nothing; circles of
///   steady motions of a symmetric body are in this case unless `f₂` proves an instability).
/// - Otherwise, with `d` the degree of instability: `d = 0` ⇒ [`Stability::SecularlyStable`]
///   (section 4); `d = 1` ⇒ [`Stability::Unstable`] (odd degree, section 5); `d = 2` ⇒
///   [`Stability::GyroscopicallyStabilized`] when the quadratic `c₄s² + c₂s + c₀` has two distinct
///   real negative roots (all four roots of `f₂` simple and on the imaginary axis: linear
///   stability), [`Stability::Unstable`] when a root of `f₂` leaves the imaginary axis.
/// - The boundary of gyroscopic stabilisation, where the discriminant `c₂² − 4c₄c₀` vanishes
///   within [`ClassifyOptions::double_root_tol`] times `c₂² + 4|c₄c₀|` (e.g. the sleeping top at exactly
///   `p_ψ² = 4A₁mgl`, Maievskii): the roots are snapped to the double pair `±i√(−s)`,
///   `s = −c₂/(2c₄)`. Two modes of opposite Krein signature collide there and the linearisation
///   generically has a Jordan block (secular growth `t·e^{iωt}`), so neither linear stability nor
///   instability follows: with `d = 2` and `s < 0` the verdict is [`Stability::Degenerate`]
///   (inconclusive), with `s > 0` it is [`Stability::Unstable`] (real roots).
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
/// # use routh_core::{Lagrangian, Routhian, Matrix3, Vector3};
/// use routh_core::{classify, SteadyMotion, Stability};
/// /// A free symmetric body (no potential, J = diag(2, 2, 1)), written with its Routh function.
/// struct Free;
/// # fn j() -> Matrix3<f64> { Matrix3::from_diagonal(&Vector3::new(2.0, 2.0, 1.0)) }
/// # impl Lagrangian for Free {
/// #     fn lagrangian(&self, w: &Vector3<f64>, _: &Vector3<f64>) -> f64 {
/// #         0.5 * w.dot(&(j() * w))
/// #     }
/// #     fn dl_domega(&self, w: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> { j() * w }
/// #     fn dl_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
/// #         Vector3::zeros()
/// #     }
/// #     fn d2l_domega2(&self, _: &Vector3<f64>) -> Matrix3<f64> { j() }
/// #     fn d2l_domega_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Matrix3<f64> {
/// #         Matrix3::zeros()
/// #     }
/// # }
/// # impl Routhian for Free {
/// #     fn routhian(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
/// #         let (n, q) = (g.dot(&(j() * g)), p - (j() * w).dot(g));
/// #         0.5 * w.dot(&(j() * w)) - 0.5 * q * q / n
/// #     }
/// #     fn dr_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
/// #         let (n, q) = (g.dot(&(j() * g)), p - (j() * w).dot(g));
/// #         j() * w + (q / n) * (j() * g)
/// #     }
/// #     fn dr_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
/// #         let (n, q) = (g.dot(&(j() * g)), p - (j() * w).dot(g));
/// #         (q / n) * (j() * w) + (q * q / (n * n)) * (j() * g)
/// #     }
/// #     fn d2r_domega2(&self, _: &Vector3<f64>, g: &Vector3<f64>, _: f64) -> Matrix3<f64> {
/// #         let n = g.dot(&(j() * g));
/// #         j() - (j() * g) * (j() * g).transpose() / n
/// #     }
/// #     fn d2r_domega_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
/// #         let (n, q) = (g.dot(&(j() * g)), p - (j() * w).dot(g));
/// #         let dqn = -(j() * w) / n - (2.0 * q / (n * n)) * (j() * g);
/// #         (j() * g) * dqn.transpose() + (q / n) * j()
/// #     }
/// #     fn d2r_dgamma2(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
/// #         let (n, q) = (g.dot(&(j() * g)), p - (j() * w).dot(g));
/// #         let dqn = -(j() * w) / n - (2.0 * q / (n * n)) * (j() * g);
/// #         (j() * w) * dqn.transpose() + (q * q / (n * n)) * j()
/// #             + (2.0 * q / n) * (j() * g) * dqn.transpose()
/// #     }
/// # }
/// // Spin about the axis of least inertia: U_r = ½p²/(γᵀJγ) has its maximum there, but the
/// // gyroscopic forces stabilise it (all roots of f₂ on the imaginary axis).
/// let p = 1.0;
/// let spin = SteadyMotion::at(&Free, Vector3::z(), p, true)?;
/// let report = classify(&Free, &spin)?;
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
/// for analyses that read more of them ([`crate::classify_circle`]).
pub(crate) struct Evaluated {
    pub gamma: Vector3<f64>,
    pub bundle: RouthBundle,
    pub system: GyroscopicSystem,
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
    // The one zero test (crate::zero) on the search's tangential scale: a zero eigenvalue here
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
        },
    ))
}

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

/// [`classify_with`] and the Krein signatures of the roots of `f₂` (see [`KreinReport`]): on the
/// tangent plane the linearisation is `a ẍ + 2gJẋ + cx = 0` with conserved energy
/// `½ẋᵀaẋ + ½xᵀcx`; on the mode `u` of a root `λ = iω` it is proportional to `ω²uᴴau + uᴴcu`, and
/// its sign is the root's signature. They explain a verdict: a secularly stable motion has only
/// `+1`; a gyroscopically stabilised one has one mode of each sign per sign of ω.
///
/// Errors: as [`classify_with`].
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

/// The former name of [`krein_report`] (a `_with` form takes options, and nothing else).
#[deprecated(note = "renamed `krein_report` (same arguments)")]
#[doc(hidden)]
pub fn classify_with_krein<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    opts: &ClassifyOptions,
) -> Result<KreinReport, RouthError> {
    krein_report(model, steady, opts)
}

/// The coefficients `[c₄, c₂, c₀]` of `f₂(λ) = det(Pᵀ(Aλ² + 2Gλ + C)P) = c₄λ⁴ + c₂λ² + c₀`
/// (errata E5) at the unit vector γ, from [`Routhian::gyroscopic_system`]. They do not depend on
/// the choice of the orthonormal basis `P` of γ^⊥.
///
/// They are of the order of `p_ψ⁴` (for a free body, in units of the inertia) and overflow
/// for `|p_ψ|` beyond about `1e77`; [`classify`] solves the same polynomial in a scaled
/// variable, which does not.
///
/// Errors: as [`classify`], and [`RouthError::NonFiniteModel`] when a coefficient overflows.
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
/// Errors: as [`classify`].
pub(crate) fn f2_coefficients_scaled<M: Routhian>(
    model: &M,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> Result<([f64; 3], f64), RouthError> {
    let parts = f2_parts(model, gamma, p_psi)?;
    Ok((parts.scaled, parts.omega))
}

/// The linearisation on the tangent plane, `a ẍ + 2g J ẋ + c x = 0` (`a = PᵀAP`, `c = PᵀCP`,
/// `J = [[0, 1], [−1, 0]]`), and the same in the scaled variables that [`classify`] works with.
///
/// With `α` the largest entry of `a` (positive: `a` is positive definite) and the characteristic
/// frequency `ω = max(√(‖c‖_max/α), |g|/α)` (1 when `c` and `g` vanish), put `â = a/α`,
/// `ĝ = g/(αω)`, `ĉ = c/(αω²)` (entries at most 1 in magnitude, formed without overflow). Then
/// `aλ² + 2gJλ + c = αω²(âμ² + 2ĝJμ + ĉ)` with `λ = ωμ`, so
/// `f₂(λ) = α²ω⁴ f̂₂(μ)`, `f̂₂(μ) = det(âμ² + 2ĝJμ + ĉ) = ĉ₄μ⁴ + ĉ₂μ² + ĉ₀`: the roots of `f₂` are
/// `ω` times those of `f̂₂`, whose coefficients are O(1). The raw coefficients are O(p_ψ⁴) and
/// overflow, with their discriminant, long before the roots do (p_ψ = 1e150 with J = O(1e150)).
struct F2Parts {
    /// The unit γ the parts were evaluated at.
    gamma: Vector3<f64>,
    a: Matrix2<f64>,
    g: f64,
    c: Matrix2<f64>,
    alpha: f64,
    omega: f64,
    a_hat: Matrix2<f64>,
    g_hat: f64,
    c_hat: Matrix2<f64>,
    /// `[ĉ₄, ĉ₂, ĉ₀]`.
    scaled: [f64; 3],
}

/// The restricted `a`, `g`, `c` of (64) and `f₂` in scaled form (see [`F2Parts`]).
fn f2_parts<M: Routhian>(
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
fn f2_parts_of(sys: &GyroscopicSystem, gamma: Vector3<f64>) -> Result<F2Parts, RouthError> {
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
enum SquareRoots {
    /// Two distinct real negative roots: four simple imaginary roots λ.
    DistinctNegative,
    /// A double real negative root (within [`ClassifyOptions::double_root_tol`]): a double imaginary pair.
    DoubleNegative,
    /// Anything else (a non-negative real root or a complex pair).
    Other,
}

struct QuarticRoots {
    lambda: [Complex<f64>; 4],
    kind: SquareRoots,
}

/// The two square roots `±√s` of a real `s`, exactly on an axis.
fn sqrt_real(s: f64) -> [Complex<f64>; 2] {
    if s >= 0.0 {
        let r = s.sqrt();
        [Complex::new(r, 0.0), Complex::new(-r, 0.0)]
    } else {
        let r = (-s).sqrt();
        [Complex::new(0.0, r), Complex::new(0.0, -r)]
    }
}

/// Roots of the even quartic `c₄λ⁴ + c₂λ² + c₀` (`c₄ > 0`), sorted by `(re, im)`.
fn quartic_roots(c4: f64, c2: f64, c0: f64, double_root_tol: f64) -> QuarticRoots {
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
