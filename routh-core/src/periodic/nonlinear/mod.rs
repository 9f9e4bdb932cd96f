//! Orbital stability of a periodic orbit beyond the linear test (docs/method.md
//! §12): the rotation number and the twist of the isoenergetic Poincaré map from
//! its Taylor expansion to order three ([`map`]), its Birkhoff normal form ([`birkhoff`]), and
//! the verdicts of Moser's twist theorem and of the resonances of order three and four.

mod birkhoff;
pub(crate) mod jet;
mod map;

use std::fmt;

pub use map::SectionChart;

use super::{OrbitStability, PeriodicOrbit};
use crate::{RouthError, Routhian, RunControl};

/// Settings of [`orbit_nonlinear_stability`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitNonlinearOptions {
    /// Relative tolerance of the integration of the orbit's jets.
    pub rtol: f64,
    /// Absolute tolerance of the same.
    pub atol: f64,
    /// A resonance of order three (four) is declared when `|k + 1/2|` (`|k|`) is at most this.
    pub resonance_tol: f64,
    /// The twist counts as zero (`Undecided`) when `|τ|` is at most `twist_tol` times the scale
    /// of the terms it is made of (the cubic terms of the map and the products of its quadratic
    /// terms): a cancellation the jets cannot resolve.
    pub twist_tol: f64,
    /// A resonant term counts as zero below `criterion_tol` times the scale of its order; the
    /// two sides of the fourth-order criterion count as equal within `criterion_tol` relative.
    pub criterion_tol: f64,
    /// Budget of integration steps per period.
    pub max_steps: usize,
    /// Cancellation and progress (not a setting: not serialised, not compared).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub control: RunControl,
}

impl Default for OrbitNonlinearOptions {
    fn default() -> Self {
        OrbitNonlinearOptions {
            rtol: 1e-11,
            atol: 1e-13,
            resonance_tol: 1e-6,
            twist_tol: 1e-6,
            criterion_tol: 1e-6,
            max_steps: 100_000,
            control: RunControl::default(),
        }
    }
}

impl OrbitNonlinearOptions {
    pub(crate) fn validate(&self) -> Result<(), RouthError> {
        for (what, v) in [("rtol", self.rtol), ("atol", self.atol)] {
            if !(super::MIN_TOL..1.0).contains(&v) {
                return Err(RouthError::InvalidOption {
                    what,
                    reason: format!("must be in [{:e}, 1) (got {v:e})", super::MIN_TOL),
                });
            }
        }
        for (what, v) in [
            ("resonance_tol", self.resonance_tol),
            ("twist_tol", self.twist_tol),
            ("criterion_tol", self.criterion_tol),
        ] {
            if !(v > 0.0 && v < 1.0) {
                return Err(RouthError::InvalidOption {
                    what,
                    reason: format!("must be in (0, 1) (got {v:e})"),
                });
            }
        }
        if self.max_steps == 0 {
            return Err(RouthError::InvalidOption {
                what: "max_steps",
                reason: "must be at least 1".into(),
            });
        }
        Ok(())
    }
}

/// A resonance of the Poincaré map's linear part: `ρ = 1/3, 2/3` (`k = −1/2`) or `ρ = 1/4, 3/4`
/// (`k = 0`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum OrbitResonance {
    /// Order three.
    Third,
    /// Order four.
    Fourth,
}

impl OrbitResonance {
    /// `"third"` or `"fourth"`.
    pub fn as_str(&self) -> &'static str {
        match self {
            OrbitResonance::Third => "third",
            OrbitResonance::Fourth => "fourth",
        }
    }
}

impl fmt::Display for OrbitResonance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The nonlinear verdict on a periodic orbit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum OrbitNonlinearVerdict {
    /// Elliptic with a non-zero twist away from the resonances of order three and four
    /// (Moser's twist theorem), or at a resonance whose criterion proves stability: invariant
    /// curves surround the fixed point of the Poincaré map arbitrarily close to it.
    OrbitallyStable,
    /// Hyperbolic or inverse hyperbolic, or a resonance whose criterion proves instability.
    Unstable,
    /// Parabolic, degenerate, a vanishing twist or a resonance its criterion cannot decide.
    Undecided,
}

impl OrbitNonlinearVerdict {
    /// `"orbitally_stable"`, `"unstable"` or `"undecided"`.
    pub fn as_str(&self) -> &'static str {
        match self {
            OrbitNonlinearVerdict::OrbitallyStable => "orbitally_stable",
            OrbitNonlinearVerdict::Unstable => "unstable",
            OrbitNonlinearVerdict::Undecided => "undecided",
        }
    }
}

impl fmt::Display for OrbitNonlinearVerdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The nonlinear analysis of one periodic orbit (docs/method.md §12).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitNonlinearReport {
    /// The orbit analysed.
    pub orbit: PeriodicOrbit,
    /// `ρ ∈ (0, 1)`, the turn of the Poincaré map's linear part in the fixed sense of docs/method.md §12.2
    /// (clockwise in a canonical chart), `cos 2πρ = k`; NaN unless elliptic.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float"))]
    pub rotation_number: f64,
    /// `τ = dρ/dA` at `A = 0`, `A` the symplectic area enclosed by an invariant curve; NaN
    /// unless elliptic.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float"))]
    pub twist: f64,
    /// A resonance of order three or four within `resonance_tol`.
    pub resonance: Option<OrbitResonance>,
    /// The verdict.
    pub verdict: OrbitNonlinearVerdict,
    /// Why: the theorem or criterion applied, or what left it undecided.
    pub reason: String,
    /// A check of the jets: `|Re(c/λ)|/|c/λ|` of the normal form's cubic coefficient, 0 for an
    /// exactly area-preserving map (NaN unless elliptic).
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float"))]
    pub area_defect: f64,
}

impl fmt::Display for OrbitNonlinearReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ({}); ρ = {:.10}, τ = {:+.6e}",
            self.verdict, self.reason, self.rotation_number, self.twist
        )?;
        if let Some(r) = self.resonance {
            write!(f, ", resonance of order {r}")?;
        }
        Ok(())
    }
}

/// The orbital stability of a periodic orbit beyond the linear test (docs/method.md §12): the
/// rotation number `ρ` and the twist `τ = dρ/dA` of the isoenergetic Poincaré map from its
/// Taylor expansion to order three, computed from jets of the flow on the model's own expression
/// tape (docs/method.md §12).
///
/// Elliptic orbits are `OrbitallyStable` when `τ ≠ 0` away from `k = −1/2, 0` (Moser's twist
/// theorem); at `k = −1/2` the resonant term of order three decides (`Unstable` when it is not
/// zero), at `k = 0` the resonant coefficient of order four against the twist (Markeev).
/// Hyperbolic orbits are `Unstable`; parabolic and degenerate orbits `Undecided`.
///
/// Errors: [`RouthError::InvalidModel`] for a model without a flow tape (hand-written), the
/// orbit's own checks, those of the integration, [`RouthError::Interrupted`].
pub fn orbit_nonlinear_stability<M: Routhian>(
    model: &M,
    orbit: &PeriodicOrbit,
    opts: &OrbitNonlinearOptions,
) -> Result<OrbitNonlinearReport, RouthError> {
    orbit_nonlinear_stability_in(model, orbit, &SectionChart::default(), opts)
}

/// [`orbit_nonlinear_stability`] on a chosen section and chart (`chart`): the twist and the
/// rotation number do not depend on them (a check for tests).
#[doc(hidden)]
pub fn orbit_nonlinear_stability_in<M: Routhian>(
    model: &M,
    orbit: &PeriodicOrbit,
    chart: &SectionChart,
    opts: &OrbitNonlinearOptions,
) -> Result<OrbitNonlinearReport, RouthError> {
    opts.validate()?;
    super::flow::check_orbit(orbit)?;
    let tape = model.flow_tape().ok_or_else(no_tape)?;
    let report = |rho: f64, tau: f64, res, verdict, reason: &str, area: f64| OrbitNonlinearReport {
        orbit: orbit.clone(),
        rotation_number: rho,
        twist: tau,
        resonance: res,
        verdict,
        reason: reason.into(),
        area_defect: area,
    };
    let nan = f64::NAN;
    if orbit.degenerate {
        return Ok(report(
            nan,
            nan,
            None,
            OrbitNonlinearVerdict::Undecided,
            "degenerate orbit of an integrable body: not isolated on its energy level",
            nan,
        ));
    }
    match orbit.stability {
        OrbitStability::Hyperbolic | OrbitStability::InverseHyperbolic => {
            return Ok(report(
                nan,
                nan,
                None,
                OrbitNonlinearVerdict::Unstable,
                "linearly unstable (|k| > 1)",
                nan,
            ))
        }
        OrbitStability::Parabolic => {
            return Ok(report(
                nan,
                nan,
                None,
                OrbitNonlinearVerdict::Undecided,
                "parabolic (k = ±1)",
                nan,
            ))
        }
        OrbitStability::Elliptic => {}
    }
    let k = orbit.stability_index;
    let third = (k + 0.5).abs() <= opts.resonance_tol;
    let fourth = k.abs() <= opts.resonance_tol;
    let Some(b) = normal_form(model, &tape, orbit, chart, opts, None, third)? else {
        return Ok(report(
            nan,
            nan,
            None,
            OrbitNonlinearVerdict::Undecided,
            "the Poincaré map's linear part is not elliptic at the accuracy of the jets",
            nan,
        ));
    };
    let (rho, tau) = (b.rotation_number, b.twist);
    let twist_zero =
        (tau * 2.0 * std::f64::consts::PI.powi(2)).abs() <= opts.twist_tol * b.twist_scale;
    let out = |res, verdict, reason: &str| report(rho, tau, res, verdict, reason, b.area_defect);
    if third {
        let scale = b.quadratic_scale.max(b.twist_scale.sqrt());
        if b.third_resonant > opts.criterion_tol * scale {
            return Ok(out(
                Some(OrbitResonance::Third),
                OrbitNonlinearVerdict::Unstable,
                "resonance of order three with a non-zero resonant term",
            ));
        }
        if twist_zero {
            return Ok(out(
                Some(OrbitResonance::Third),
                OrbitNonlinearVerdict::Undecided,
                "resonance of order three with a zero resonant term, and the twist vanishes",
            ));
        }
        return Ok(out(
            Some(OrbitResonance::Third),
            OrbitNonlinearVerdict::OrbitallyStable,
            "resonance of order three with a zero resonant term; the twist decides (Moser)",
        ));
    }
    if fourth {
        let (c, d) = b.fourth;
        let tol = opts.criterion_tol;
        let (verdict, reason) = if c > d * (1.0 + tol) {
            (
                OrbitNonlinearVerdict::OrbitallyStable,
                "resonance of order four: the twist exceeds the resonant coefficient (Markeev)",
            )
        } else if c < d * (1.0 - tol) {
            (
                OrbitNonlinearVerdict::Unstable,
                "resonance of order four: the resonant coefficient exceeds the twist (Markeev)",
            )
        } else {
            (
                OrbitNonlinearVerdict::Undecided,
                "resonance of order four: twist and resonant coefficient equal",
            )
        };
        return Ok(out(Some(OrbitResonance::Fourth), verdict, reason));
    }
    if twist_zero {
        return Ok(out(
            None,
            OrbitNonlinearVerdict::Undecided,
            "the twist vanishes (to twist_tol)",
        ));
    }
    Ok(out(
        None,
        OrbitNonlinearVerdict::OrbitallyStable,
        "elliptic with non-zero twist away from resonances of order three and four (Moser)",
    ))
}

/// The twist `τ` alone of an elliptic orbit (NaN otherwise), for the family's events.
pub(crate) fn twist_of<M: Routhian + ?Sized>(
    model: &M,
    orbit: &PeriodicOrbit,
    monodromy: &nalgebra::Matrix6<f64>,
    opts: &OrbitNonlinearOptions,
) -> Result<f64, RouthError> {
    if orbit.degenerate || orbit.stability != OrbitStability::Elliptic {
        return Ok(f64::NAN);
    }
    let tape = model.flow_tape().ok_or_else(no_tape)?;
    let chart = SectionChart::default();
    let b = normal_form(model, &tape, orbit, &chart, opts, Some(monodromy), false)?;
    Ok(b.map_or(f64::NAN, |b| b.twist))
}

/// The Birkhoff normal form of the orbit's Poincaré map on `chart` (`None` when its linear part
/// is not elliptic at the accuracy of the jets); `monodromy` the corrector's when known.
fn normal_form<M: Routhian + ?Sized>(
    model: &M,
    tape: &routh_tape::FlowTape,
    orbit: &PeriodicOrbit,
    chart: &SectionChart,
    opts: &OrbitNonlinearOptions,
    monodromy: Option<&nalgebra::Matrix6<f64>>,
    skip_third: bool,
) -> Result<Option<birkhoff::Birkhoff>, RouthError> {
    let sm = map::section_map(model, tape, orbit, chart, opts, monodromy)?;
    Ok(birkhoff::birkhoff(&sm.map, skip_third))
}

fn no_tape() -> RouthError {
    RouthError::InvalidModel {
        what: "flow tape",
        reason: "the nonlinear test of a periodic orbit needs a derived or run-time model \
                 (L and the equations (8) as an expression tape)"
            .into(),
    }
}

#[doc(hidden)]
pub use map::symplectic_form as orbit_symplectic_form;
