//! Nonlinear stability of a steady motion: the Birkhoff normal form of the reduced Hamiltonian
//! to order four, Arnold's determinant, the Arnold–Moser theorem and Markeev's resonance
//! criteria (docs/method.md §10).
//!
//! The linear verdict `GyroscopicallyStabilized` of [`classify`](crate::classify) says nothing
//! about Lyapunov stability. After the reduction the system has two degrees of freedom, and there
//! the answer is complete away from a few exceptional points: with `H₂ = s₁ω₁I₁ + s₂ω₂I₂`
//! indefinite, no resonance `k₁ω₁ = k₂ω₂` with `|k₁| + |k₂| ≤ 4` and Arnold's determinant
//! `D = c₂₀ω₂² − s₁s₂c₁₁ω₁ω₂ + c₀₂ω₁² ≠ 0`, the motion is Lyapunov stable (Arnold 1963, Moser
//! 1962); at a 1:2 resonance with a non-zero resonant term it is unstable, and at 1:3 Markeev's
//! inequality decides (Markeev 1978).
//!
//! The derivatives of order three and four come from evaluating the model's Routh function at
//! Taylor jets ([`Jet`], [`RouthianJet`]): no finite differences.

mod chart;
pub(crate) mod jet;
mod normal_form;
mod verdict;

use std::fmt;

use crate::error::RouthError;
use crate::model::Routhian;
use crate::stability::{classify_with, ClassifyOptions, Stability, StabilityReport};
use crate::steady::SteadyMotion;

pub use chart::RouthianJet;
/// The chart, the reduced Hamiltonian and the truncated power series behind the normal form:
/// public for the tests that check them by hand, not an API of routh.
#[doc(hidden)]
pub use chart::{chart, reduced_hamiltonian, tangent_frame};
#[doc(hidden)]
pub use jet::{monomial_index, monomials, Exponents, Jet, NCOEF, NVARS, ORDER};

/// Tolerances of [`nonlinear_stability`], all relative.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NonlinearOptions {
    /// Options of the linear classification that comes first.
    pub classify: ClassifyOptions,
    /// A resonance `ω₁ = kω₂` (`k = 1, 2, 3`) is declared when `|kω₂ − ω₁|/ω₁ ≤ resonance_tol`;
    /// the same bound marks a monomial of the normal form as resonant. Default `1e−6`.
    pub resonance_tol: f64,
    /// `D = 0` is declared when `|D| ≤ arnold_tol·(|c₂₀|ω₂² + |c₁₁|ω₁ω₂ + |c₀₂|ω₁²)`.
    /// Default `1e−8`.
    pub arnold_tol: f64,
    /// Margin of Markeev's criteria: a resonant coefficient counts as zero below
    /// `criterion_tol` times the largest cubic coefficient (1:2), and the two sides of the 1:3
    /// inequality as equal within `criterion_tol` relative. Default `1e−6`.
    pub criterion_tol: f64,
}

impl Default for NonlinearOptions {
    fn default() -> Self {
        NonlinearOptions {
            classify: ClassifyOptions::default(),
            resonance_tol: 1e-6,
            arnold_tol: 1e-8,
            criterion_tol: 1e-6,
        }
    }
}

impl NonlinearOptions {
    pub(crate) fn validate(&self) -> Result<(), RouthError> {
        for (what, v) in [
            ("resonance_tol", self.resonance_tol),
            ("arnold_tol", self.arnold_tol),
            ("criterion_tol", self.criterion_tol),
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

/// A resonance `k₁ω₁ = k₂ω₂` of order `|k₁| + |k₂| ≤ 4` between the two frequencies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Resonance {
    /// `ω₁ = ω₂` (orders 2 and 4).
    OneToOne,
    /// `ω₁ = 2ω₂` (order 3).
    OneToTwo,
    /// `ω₁ = 3ω₂` (order 4).
    OneToThree,
}

impl fmt::Display for Resonance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Resonance::OneToOne => "1:1",
            Resonance::OneToTwo => "1:2",
            Resonance::OneToThree => "1:3",
        })
    }
}

/// The nonlinear verdict.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum NonlinearVerdict {
    /// `H₂` definite (the amended potential has a strict minimum): Lyapunov stable by the
    /// energy integral.
    SecularlyStable,
    /// `H₂` indefinite, and either no resonance of order ≤ 4 and `D ≠ 0` (Arnold–Moser), or a
    /// 1:3 resonance that Markeev's criterion calls stable.
    LyapunovStable,
    /// Linearly unstable, or a resonance whose criterion proves instability (Markeev).
    Unstable,
    /// Not decided by the normal form to order four; the report says why.
    Undecided,
}

impl fmt::Display for NonlinearVerdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            NonlinearVerdict::SecularlyStable => "secularly stable",
            NonlinearVerdict::LyapunovStable => "Lyapunov stable",
            NonlinearVerdict::Unstable => "unstable",
            NonlinearVerdict::Undecided => "undecided",
        })
    }
}

/// The nonlinear stability analysis of one steady motion (docs/method.md §10).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NonlinearReport {
    /// The linear analysis (sections 4–5).
    pub linear: StabilityReport,
    /// `ω₁ ≥ ω₂ > 0`, the roots `±iω_k` of `f₂`; NaN when linearly unstable or degenerate.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float::array"))]
    pub frequencies: [f64; 2],
    /// Krein signs `s_k`: `H₂ = s₁ω₁I₁ + s₂ω₂I₂` with `I_k = (q_k² + p_k²)/2`, `H` the reduced
    /// energy; `[0, 0]` when the frequencies are NaN.
    pub krein_signs: [i8; 2],
    /// `c₂₀, c₁₁, c₀₂` of `H₄ = c₂₀I₁² + c₁₁I₁I₂ + c₀₂I₂²` (NaN where not computed).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float::array"))]
    pub normal_form: [f64; 3],
    /// Arnold's determinant `D = c₂₀ω₂² − s₁s₂c₁₁ω₁ω₂ + c₀₂ω₁²`.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float"))]
    pub arnold_determinant: f64,
    /// A resonance of order ≤ 4 within `resonance_tol`.
    pub resonance: Option<Resonance>,
    /// The resonance's relative distance `|kω₂ − ω₁|/ω₁` (NaN without one).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float"))]
    pub resonance_distance: f64,
    /// The verdict.
    pub verdict: NonlinearVerdict,
    /// Why: the theorem or criterion applied, or the reason of an `Undecided`.
    pub reason: String,
    /// A check of the normalisation: `max(|TᵀJT − J|, |H₂(T·) − Σs_kω_kI_k|/ω₁)` (NaN where not
    /// computed); round-off, about 1e−12, unless near a 1:1 resonance.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float"))]
    pub normalisation_defect: f64,
}

impl NonlinearReport {
    /// A report with the linear test and the frequencies alone: undecided, without a reason,
    /// the normal form and the rest NaN or absent (what the analysis starts from, and what a
    /// frequencies-only re-solve of the events returns).
    pub(crate) fn undecided(linear: StabilityReport, frequencies: [f64; 2]) -> Self {
        NonlinearReport {
            linear,
            frequencies,
            krein_signs: [0, 0],
            normal_form: [f64::NAN; 3],
            arnold_determinant: f64::NAN,
            resonance: None,
            resonance_distance: f64::NAN,
            verdict: NonlinearVerdict::Undecided,
            reason: String::new(),
            normalisation_defect: f64::NAN,
        }
    }
}

impl fmt::Display for NonlinearReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [w1, w2] = self.frequencies;
        let [s1, s2] = self.krein_signs;
        let [c20, c11, c02] = self.normal_form;
        write!(
            f,
            "{} ({}); linear: {}; ω = [{w1:.6e}, {w2:.6e}], Krein signs [{s1:+}, {s2:+}], \
             c₂₀ = {c20:+.6e}, c₁₁ = {c11:+.6e}, c₀₂ = {c02:+.6e}, D = {:+.6e}",
            self.verdict, self.reason, self.linear.verdict, self.arnold_determinant
        )?;
        if let Some(r) = self.resonance {
            write!(
                f,
                ", resonance {r} at distance {:.2e}",
                self.resonance_distance
            )?;
        }
        Ok(())
    }
}

/// The reduced Hamiltonian at a steady motion and its linear symplectic normalisation
/// (docs/method.md §10.1–11.2), for analyses beyond the verdict (e.g. to set up a
/// small-amplitude simulation in normal coordinates).
#[doc(hidden)]
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LinearNormalForm {
    /// `H(x₁, x₂, y₁, y₂)` in the chart of [`chart`] (jet variables 0–3), minus its value at the
    /// steady motion.
    pub hamiltonian: Jet,
    /// `ω₁ ≥ ω₂ > 0`.
    pub frequencies: [f64; 2],
    /// Krein signs.
    pub krein_signs: [i8; 2],
    /// Symplectic `T` with `(x, y) = T(q₁, q₂, p₁, p₂)` and
    /// `H₂ = Σ s_kω_k(q_k² + p_k²)/2`.
    pub transform: nalgebra::Matrix4<f64>,
}

/// [`LinearNormalForm`] at `(γ₀, p_ψ)`; `None` unless `H₂` has two distinct real frequencies.
#[doc(hidden)]
pub fn linear_normal_form<R: RouthianJet + ?Sized>(
    r: &R,
    gamma0: &nalgebra::Vector3<f64>,
    p_psi: f64,
) -> Option<LinearNormalForm> {
    let h = chart::reduced_hamiltonian(r, gamma0, p_psi);
    let s = normal_form::quadratic_form(&h);
    let omega2 = normal_form::squared_frequencies(&s)?;
    let nf = normal_form::normalise(&s, omega2)?;
    Some(LinearNormalForm {
        hamiltonian: h,
        frequencies: nf.omega,
        krein_signs: nf.signs,
        transform: nf.t,
    })
}

/// The nonlinear stability of a steady motion, the Routh function's jets taken from the model.
///
/// Needs the model's Routh function as an expression tape; until the model provides it, this
/// returns [`RouthError::InvalidModel`]. Use [`nonlinear_stability_from_jet`] with a
/// [`RouthianJet`] to supply `R` yourself.
pub fn nonlinear_stability<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    opts: &NonlinearOptions,
) -> Result<NonlinearReport, RouthError> {
    nonlinear_stability_after(model, steady, None, opts)
}

/// [`nonlinear_stability`], the linear test taken from `linear` when given: it must be what
/// [`classify_with`] gives for `(model, steady, opts.classify)` (a bifurcation diagram's own
/// report of a branch point, classified with the same options).
pub(crate) fn nonlinear_stability_after<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    linear: Option<&StabilityReport>,
    opts: &NonlinearOptions,
) -> Result<NonlinearReport, RouthError> {
    opts.validate()?;
    let Some(tape) = model.routh_tape() else {
        return Err(RouthError::InvalidModel {
            what: "Routh function tape",
            reason:
                "the nonlinear test needs a derived or run-time model (R as an expression \
                     tape); for a hand-written model use nonlinear_stability_from_jet and a RouthianJet"
                    .into(),
        });
    };
    // R at jets from the model's own expression DAG (the tape the derive or the run-time model
    // built): its Taylor coefficients are the exact derivatives, no finite differences.
    let r = |big_omega: &[Jet; 3], gamma: &[Jet; 3], p_psi: f64| {
        tape.routhian(big_omega, gamma, Jet::constant(p_psi))
    };
    let linear = match linear {
        Some(l) => l.clone(),
        None => classify_with(model, steady, &opts.classify)?,
    };
    beyond_linear(linear, steady, &r, opts)
}

/// [`nonlinear_stability`] with the Routh function evaluated at jets by `r`, which must be the
/// model's `R(Ω, γ, p_ψ)` (14).
///
/// Errors: those of [`classify_with`], [`RouthError::InvalidOption`] for a tolerance outside
/// `(0, 1)`, [`RouthError::NonFiniteModel`] when `R`'s jets are not finite.
pub fn nonlinear_stability_from_jet<M: Routhian, R: RouthianJet + ?Sized>(
    model: &M,
    steady: &SteadyMotion,
    r: &R,
    opts: &NonlinearOptions,
) -> Result<NonlinearReport, RouthError> {
    opts.validate()?;
    let linear = classify_with(model, steady, &opts.classify)?;
    beyond_linear(linear, steady, r, opts)
}

/// The nonlinear test after the linear one (`linear`, of this steady motion): the normal form
/// where the linear verdict leaves the question open.
fn beyond_linear<R: RouthianJet + ?Sized>(
    linear: StabilityReport,
    steady: &SteadyMotion,
    r: &R,
    opts: &NonlinearOptions,
) -> Result<NonlinearReport, RouthError> {
    let mut report = NonlinearReport::undecided(linear.clone(), [f64::NAN; 2]);
    match linear.verdict {
        Stability::Unstable => {
            report.verdict = NonlinearVerdict::Unstable;
            report.reason = "linearly unstable (a root of f₂ off the imaginary axis, or an odd \
                             degree of instability)"
                .into();
            return Ok(report);
        }
        Stability::Degenerate => {
            report.reason = "the linear test is degenerate (a zero eigenvalue of the second \
                             variation, or a double pair of roots of f₂)"
                .into();
            return Ok(report);
        }
        Stability::SecularlyStable | Stability::GyroscopicallyStabilized => {}
    }
    let h = chart::reduced_hamiltonian(r, &steady.gamma, steady.p_psi);
    if h.c.iter().any(|c| !c.is_finite()) {
        return Err(RouthError::NonFiniteModel {
            what: "Taylor jet of the reduced Hamiltonian",
            gamma: steady.gamma.into(),
        });
    }
    let s = normal_form::quadratic_form(&h);
    let Some(omega2) = normal_form::squared_frequencies(&s) else {
        report.reason = "the quadratic part of the reduced Hamiltonian has no two real \
                         frequencies although the linear test found stability (round-off at a \
                         boundary)"
            .into();
        return Ok(report);
    };
    let omega = [omega2[0].sqrt(), omega2[1].sqrt()];
    report.frequencies = omega;
    let resonance = verdict::detect_resonance(omega, opts.resonance_tol);
    report.resonance = resonance.map(|r| r.0);
    report.resonance_distance = resonance.map_or(f64::NAN, |r| r.1);
    if let Some((Resonance::OneToOne, d)) = resonance {
        // Equal frequencies: the invariant planes are not separated; no normal form here.
        let secular = linear.verdict == Stability::SecularlyStable;
        report.verdict = if secular {
            NonlinearVerdict::SecularlyStable
        } else {
            NonlinearVerdict::Undecided
        };
        report.reason = if secular {
            "H₂ is definite: the energy is a Lyapunov function (Lagrange–Dirichlet)".into()
        } else {
            format!(
                "1:1 resonance (distance {d:.2e}) with opposite Krein signs: a \
                 Hamiltonian–Hopf point, not decided by the fourth-order normal form"
            )
        };
        return Ok(report);
    }
    let Some(nf) = normal_form::normalise(&s, omega2) else {
        report.reason = "the symplectic normalisation of H₂ failed (Krein sign undefined)".into();
        return Ok(report);
    };
    report.krein_signs = nf.signs;
    let bf = normal_form::birkhoff(&h, &nf, opts.resonance_tol);
    let [c20, c11, c02] = bf.coefficients;
    let [w1, w2] = omega;
    let s12 = f64::from(nf.signs[0] * nf.signs[1]);
    let d = c20 * w2 * w2 - s12 * c11 * w1 * w2 + c02 * w1 * w1;
    report.normal_form = bf.coefficients;
    report.normalisation_defect = nf.symplectic_defect.max(bf.quadratic_defect / w1);
    report.arnold_determinant = d;
    let (v, reason) = verdict::decide(
        &verdict::Inputs {
            omega,
            signs: nf.signs,
            c: bf.coefficients,
            d,
            resonance,
            resonant_cubic: bf.resonant_cubic,
            cubic_scale: bf.cubic_scale,
            resonant_quartic: bf.resonant_quartic,
        },
        opts,
    );
    // The linear test is the reference for definiteness; a disagreement is round-off at a
    // boundary and is reported as such.
    let secular = linear.verdict == Stability::SecularlyStable;
    if secular != (v == NonlinearVerdict::SecularlyStable) {
        report.reason = format!(
            "the Krein signs {:?} disagree with the linear verdict {} (round-off at a boundary)",
            nf.signs, linear.verdict
        );
        return Ok(report);
    }
    report.verdict = v;
    report.reason = reason;
    Ok(report)
}
